"""The messages of the batch safeguards (catalogue area ``batchsafe``, ids ``batchsafe.<key>``)."""

from __future__ import annotations

from typing import Any

from ..i18n import Text


def say(msgid: str, /, **args: Any) -> Text:
    """Message ``batchsafe.<key>`` with its arguments (English as a ``str``, said again by
    ``tr``)."""
    return Text(f"batchsafe.{msgid}", args)
