"""Message catalogues and number formatting per language.

Every user-visible sentence, label, heading and title is a message id looked up here. The catalogues
are gettext ``.po`` files, one folder per language (``locale/<lang>/``) and one file per area
(``core.po``, ``cam.po``, …): a translator edits them without reading Python, and each capability
adds its own file without touching the others. Ids are symbolic (``cam.law.cycloidal``); the English
text lives in ``locale/en/`` like every other language. Placeholders are ``str.format`` fields
(``{value}``); numbers are formatted by :func:`number` (Babel) so that ru/vi get a decimal comma.
"""

from __future__ import annotations

import functools
import string
from importlib import resources
from typing import Any

from babel import Locale
from babel.messages.pofile import read_po
from babel.numbers import format_decimal

LANGUAGES: tuple[str, ...] = ("en", "ru", "vi", "zh")
"""The languages of protocols, sheets and reports (ISO 639-1)."""

DEFAULT_LANGUAGE = "en"


class MissingMessage(KeyError):
    """A message id is absent from a catalogue: a programming error, not a user error."""


@functools.cache
def catalogue(language: str) -> dict[str, str]:
    """Return every message of one language: id → text, merged over all its ``.po`` files."""
    if language not in LANGUAGES:
        raise ValueError(f"language must be one of {LANGUAGES} (got {language!r})")
    messages: dict[str, str] = {}
    folder = resources.files("mechplan") / "locale" / language
    for entry in sorted(folder.iterdir(), key=lambda e: e.name):
        if not entry.name.endswith(".po"):
            continue
        with entry.open("rb") as fh:
            for msg in read_po(fh, locale=language, domain=entry.name[:-3]):
                if msg.id and isinstance(msg.id, str):
                    text = msg.string if isinstance(msg.string, str) else ""
                    if msg.id in messages:
                        raise ValueError(f"message id {msg.id!r} is defined twice "
                                         f"in locale/{language}")
                    messages[msg.id] = text
    return messages


def placeholders(text: str) -> frozenset[str]:
    """Return the names of the ``{fields}`` a message text uses."""
    return frozenset(name for _, name, _, _ in string.Formatter().parse(text) if name)


def message(msgid: str, language: str, /, **values: Any) -> str:
    """Return the sentence ``msgid`` in ``language`` with its placeholders filled."""
    try:
        text = catalogue(language)[msgid]
    except KeyError:
        raise MissingMessage(f"message id {msgid!r} is not in the {language} catalogue") from None
    return text.format(**values) if values or "{" in text else text


def has_message(msgid: str, language: str = DEFAULT_LANGUAGE) -> bool:
    """Tell whether a message id exists."""
    return msgid in catalogue(language)


@functools.cache
def _locale(language: str) -> Locale:
    return Locale.parse(language)


def decimal_mark(language: str) -> str:
    """Return the language's decimal mark ("," for ru and vi, "." for en and zh)."""
    return str(_locale(language).number_symbols["latn"]["decimal"])


def number(value: float, digits: int, language: str) -> str:
    """Format a number with ``digits`` decimals and the language's decimal mark, without grouping.

    A value that rounds to zero is written without a minus sign.
    """
    s = f"{value:.{digits}f}"
    if s.startswith("-") and float(s) == 0.0:
        s = s[1:]
    mark = decimal_mark(language)
    return s.replace(".", mark) if mark != "." else s


def grouped(value: float, digits: int, language: str) -> str:
    """Format a number with the language's decimal mark and digit grouping (Babel)."""
    pattern = "#,##0" + ("." + "0" * digits if digits > 0 else "")
    return str(format_decimal(value, format=pattern, locale=_locale(language)))
