"""The reader's sentences in en / ru / vi / zh: catalogue ``locale/<lang>/submission.po``, ids
``submission.<key>`` (errors of unreadable files, notes on what was skipped or repaired, and where
in the file something stands)."""

from __future__ import annotations

import functools
from typing import Any

from ..i18n import DEFAULT_LANGUAGE, Text, catalogue, has_message


@functools.cache
def has(key: str) -> bool:
    """Tell whether the reader's catalogue has a message ``key``."""
    return has_message("submission." + key)


def T(key: str, /, **args: Any) -> Text:
    """The catalogue's message ``key`` with its arguments, said again in any language."""
    if not has(key):
        raise KeyError(f"no message {key!r} in the catalogue")
    return Text("submission." + key, args)


class _Place(Text):
    """Where something stands ("LINE #2A on layer 'V'"): one for every entity of a sheet, so its
    English is filled in directly when every argument is a string (no numbers to write in the
    language's way); said in another language like any text."""

    @classmethod
    def say(cls, key: str, args: dict[str, Any], language: str) -> str:
        if language == DEFAULT_LANGUAGE and all(isinstance(v, str) for v in args.values()):
            return catalogue(language)[key].format_map(args)
        return Text.say(key, args, language)


def where(key: str, /, **args: Any) -> Text:
    """The ``where.<key>`` message of a place in a file (see :class:`_Place`)."""
    if not has("where." + key):
        raise KeyError(f"no message 'where.{key}' in the catalogue")
    return _Place("submission.where." + key, args)
