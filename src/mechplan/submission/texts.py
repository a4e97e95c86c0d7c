"""The reader's sentences in en / ru / vi / zh: catalogue ``locale/<lang>/submission.po``, ids
``submission.<key>`` (errors of unreadable files, notes on what was skipped or repaired, and where
in the file something stands)."""

from __future__ import annotations

from typing import Any

from ..i18n import Text, has_message


def has(key: str) -> bool:
    """Tell whether the reader's catalogue has a message ``key``."""
    return has_message("submission." + key)


def T(key: str, /, **args: Any) -> Text:
    """The catalogue's message ``key`` with its arguments, said again in any language."""
    if not has(key):
        raise KeyError(f"no message {key!r} in the catalogue")
    return Text("submission." + key, args)
