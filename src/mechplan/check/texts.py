"""Every human-readable text of the checker in en / ru / vi / zh, from the catalogues
``locale/<lang>/check.po`` (ids ``check.<key>``).

The checker builds its hints, findings, notes and sources as :class:`Text` objects (the
catalogue's :class:`mechplan.i18n.Text` with the ids of this area): a ``str`` whose value is the
English sentence, which :func:`mechplan.i18n.tr` says again in another language when the report is
written. Lists are joined by the language's separator ("、" in Chinese); plan titles take the
grammatical case the Russian sentence needs.

Symbols and labels (pb, v_B, μv, π, b′, ω, v_rel) and SI units are the same in every language;
only millimetres of paper read "мм" in Russian, as in the construction protocol. Terms follow the
project glossary (ru "план скоростей", "теорема подобия"; vi "họa đồ vận tốc", "định lý đồng
dạng"; zh "速度多边形", "影像原理").
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

from .. import i18n
from ..i18n import LANGUAGES, catalogue, has_message, tr

__all__ = ["LANGUAGES", "T", "Text", "capitalize", "has", "join", "plan_title", "plan_word",
           "tr", "with_case", "word"]

_DECIMAL_COMMA = re.compile(r"\d,\d")
_SEPARATORS = {", ": "comma", "; ": "semicolon", " and ": "and"}


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
        """The text in a language: "_join" and "_plan" are said here, the rest by the catalogue
        (an argument ``unit`` is a unit in SI symbols, written as the language writes it)."""
        lang = language if language in LANGUAGES else "en"
        if key == "_join":
            return cls.joined(args["items"], args["sep"], lang)
        if key == "_plan":
            return _say_plan(args, lang)
        if isinstance(args.get("unit"), str):
            args = {**args, "unit": i18n.unit(args["unit"], lang)}
        return super().say(_id(key), args, lang)

    @classmethod
    def joined(cls, items: list[Any], sep: str, language: str) -> str:
        """Items joined by a separator said in the language (a comma between numbers with a
        decimal comma is a semicolon)."""
        said = [tr(x, language) if isinstance(x, str) else i18n.num(x, "", language)
                for x in items]
        if sep == ", " and language in ("ru", "vi") and any(_DECIMAL_COMMA.search(x)
                                                              for x in said):
            sep = "; "          # "b 0,6 мм; c 0,9 мм", not "b 0,6 мм, c 0,9 мм"
        name = _SEPARATORS.get(sep)
        return (catalogue(language)[_id(f"sep.{name}")] if name else sep).join(said)


def T(key: str, /, **args: Any) -> Text:
    """The catalogue's message ``key`` with its arguments."""
    if not has(key):
        raise KeyError(f"no message {key!r} in the catalogue")
    return Text(key, args)


def join(items: Iterable[Any], sep: str = ", ") -> Text:
    """Items joined by a separator said in each language (", " is "、" in Chinese)."""
    return Text("_join", {"items": list(items), "sep": sep})


def plan_title(plan: str, group: str = "", number: int = 0, table: bool = False,
               case: str = "nom") -> Text:
    """"velocity plan", "force II(2,3) plan #2", "velocity plan (table)"; in Russian in the case
    the sentence needs (nom, gen, loc)."""
    return Text("_plan", {"plan": plan, "group": group, "number": number, "table": table,
                          "case": case})


def plan_word(plan: str) -> Text:
    """The kind of a plan: "velocity" in English, "план скоростей" in Russian."""
    return Text("_plan", {"plan": plan, "bare": True})


def with_case(text: Any, case: str) -> Any:
    """A plan title in another grammatical case (other texts are returned as they are)."""
    if isinstance(text, Text) and text.key == "_plan":
        return Text("_plan", {**text.args, "case": case})
    return text


def word(group: str, value: str, lang: str) -> str:
    """A verdict, cause, finding kind, error kind or note level in a language (unknown values
    are kept as they are)."""
    key = f"{group}.{value}"
    return catalogue(lang if lang in LANGUAGES else "en")[_id(key)] if has(key) else value


def capitalize(text: str) -> str:
    """First letter upper case."""
    return text[:1].upper() + text[1:]


def _say_plan(args: dict[str, Any], lang: str) -> str:
    messages, plan = catalogue(lang), args["plan"]
    if args.get("bare"):
        return messages[_id(f"plan.{plan}.word")]
    text = " ".join(messages[_id(f"plan.{plan}.{args['case']}")].format(group=args["group"])
                    .split())
    if args["number"]:
        text += f" #{args['number']}"
    return text + (messages[_id("plan.table")] if args["table"] else "")
