"""Every human-readable text of the checker in en / ru / vi / zh, from the catalogues
``locale/<lang>/check.po`` (ids ``check.<key>``).

The checker builds its hints, findings, notes and sources as :class:`Text` objects (the
catalogue's :class:`mechplan.i18n.Text` with the ids of this area): a ``str`` whose value is the
English sentence, which :func:`mechplan.i18n.tr` says again in another language when the report is
written. Lists are joined by the language's separator ("、" in Chinese); plan titles take the
grammatical case the Russian sentence needs (both said by :mod:`mechplan.i18n`).

Symbols and labels (pb, v_B, μv, π, b′, ω, v_rel) and SI units are the same in every language;
only millimetres of paper read "мм" in Russian, as in the construction protocol. Terms follow the
project glossary (ru "план скоростей", "теорема подобия"; vi "họa đồ vận tốc", "định lý đồng
dạng"; zh "速度多边形", "影像原理").
"""

from __future__ import annotations

from typing import Any

from .. import i18n
from ..i18n import (
    LANGUAGES,
    catalogue,
    has_message,
    join,
    listed,
    plan_title,
    plan_word,
    tr,
    with_case,
)

__all__ = ["LANGUAGES", "T", "Text", "capitalize", "has", "join", "plan_title", "plan_word",
           "tr", "with_case", "word"]


def _id(key: str) -> str:
    return "check." + key.replace(" ", "_")


def has(key: str) -> bool:
    """Tell whether the checker's catalogue has a message ``key``."""
    return has_message(_id(key))


class Text(i18n.Text):
    """A sentence of the checker's catalogue (ids ``check.<key>``), a joined list or a plan
    title."""

    @classmethod
    def say(cls, key: str, args: dict[str, Any], language: str) -> str:
        """The text in a language: lists and plan titles are said by :mod:`mechplan.i18n`, the
        rest by the catalogue (an argument ``unit`` is a unit in SI symbols, written as the
        language writes it)."""
        lang = language if language in LANGUAGES else "en"
        if key.startswith("_"):
            return super().say(key, args, lang)
        if isinstance(args.get("unit"), str):
            args = {**args, "unit": i18n.unit(args["unit"], lang)}
        return super().say(_id(key), args, lang)

    @classmethod
    def joined(cls, items: list[Any], sep: str, language: str) -> str:
        """A list argument said in the language (:func:`mechplan.i18n.listed`)."""
        return listed(items, sep, language)


def T(key: str, /, **args: Any) -> Text:
    """The catalogue's message ``key`` with its arguments."""
    if not has(key):
        raise KeyError(f"no message {key!r} in the catalogue")
    return Text(key, args)


def word(group: str, value: str, lang: str) -> str:
    """A verdict, cause, finding kind, error kind or note level in a language (unknown values
    are kept as they are)."""
    key = f"{group}.{value}"
    return catalogue(lang if lang in LANGUAGES else "en")[_id(key)] if has(key) else value


def capitalize(text: str) -> str:
    """First letter upper case."""
    return text[:1].upper() + text[1:]
