"""The messages of the LMS round trip (catalogue area ``lms``, ids ``lms.<key>``)."""

from __future__ import annotations

from typing import Any

from ..i18n import Text


def say(msgid: str, /, **args: Any) -> Text:
    """Message ``lms.<key>`` with its arguments."""
    return Text(f"lms.{msgid}", args)
