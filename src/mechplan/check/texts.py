"""Every human-readable text of the checker in en / ru / vi / zh, from the catalogues
``locale/<lang>/check.po`` (ids ``check.<key>``).

The checker builds its hints, findings, notes and sources as :class:`Text` objects: a ``str`` whose
value is the English sentence (so the report's fields, ``==`` and ``in`` read as before) and which
remembers its message id and arguments, so :func:`tr` can say it again in another language when
the report is written. Arguments may themselves be texts, lists (joined), or numbers (formatted
with the language's decimal mark: a comma in ru and vi, a point in en and zh).

Symbols and labels (pb, v_B, μv, π, b′, ω, v_rel) and SI units are the same in every language;
only millimetres of paper read "мм" in Russian, as in the construction protocol. Terms follow the
project glossary (ru "план скоростей", "теорема подобия"; vi "họa đồ vận tốc", "định lý đồng
dạng"; zh "速度多边形", "影像原理").
"""

from __future__ import annotations

import math
import re
import string
import unicodedata
from collections.abc import Iterable
from typing import Any, Self

from ..i18n import LANGUAGES, catalogue, has_message
from ..units import format_number


def _template(key: str, lang: str) -> str:
    return catalogue(lang)[_ID_PREFIX + key.replace(" ", "_")]


def has(key: str) -> bool:
    """Tell whether the checker's catalogue has a message ``key``."""
    return has_message(_ID_PREFIX + key.replace(" ", "_"))


_ID_PREFIX = "check."
_DECIMAL_COMMA = re.compile(r"\d,\d")
_SEPARATORS = {", ": "comma", "; ": "semicolon", " and ": "and"}
_PLANS = ("position", "velocity", "acceleration", "force")


# -- texts -----------------------------------------------------------------------------------------
class Text(str):
    """A sentence of the catalogue: its English wording as a ``str``, plus its message id and
    arguments, to say it in another language with :meth:`tr`."""

    key: str
    args: dict[str, Any]

    def __new__(cls, key: str, args: dict[str, Any] | None = None) -> Self:
        args = dict(args or {})
        obj = super().__new__(cls, _render(key, args, "en"))
        obj.key = key
        obj.args = args
        return obj

    def __reduce__(self) -> tuple[Any, ...]:
        return (Text, (self.key, self.args))

    def tr(self, lang: str) -> str:
        """The text in a language (en, ru, vi, zh)."""
        return str(self) if lang == "en" else _render(self.key, self.args, lang)


def T(key: str, /, **args: Any) -> Text:
    """The catalogue's message ``key`` with its arguments."""
    if key not in _SPECIAL and not has(key):
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
                          "case": case, "bare": False})


def plan_word(plan: str) -> Text:
    """The kind of a plan: "velocity" in English, "план скоростей" in Russian."""
    return Text("_plan", {"plan": plan, "group": "", "number": 0, "table": False,
                          "case": "nom", "bare": True})


def with_case(text: Any, case: str) -> Any:
    """A plan title in another grammatical case (other texts are returned as they are)."""
    if isinstance(text, Text) and text.key == "_plan":
        return Text("_plan", {**text.args, "case": case})
    return text


def tr(x: Any, lang: str) -> str:
    """Any report string in a language: a :class:`Text` is said again, other strings are kept."""
    if isinstance(x, Text):
        return x.tr(lang)
    return "" if x is None else str(x)


def word(group: str, value: str, lang: str) -> str:
    """A verdict, cause, finding kind, error kind or note level in a language (unknown values
    are kept as they are)."""
    key = f"{group}.{value}"
    return _template(key, lang if lang in LANGUAGES else "en") if has(key) else value


def capitalize(text: str) -> str:
    """First letter upper case."""
    return text[:1].upper() + text[1:]


# -- numbers ---------------------------------------------------------------------------------------
def num(value: Any, spec: str, lang: str) -> str:
    """A number formatted by a format spec with the language's decimal mark; in English exactly
    ``format(value, spec)``. A spec starting with "~" writes a number that is not finite as "?"."""
    unknown = spec.startswith("~")
    if unknown:
        spec = spec[1:]
    if isinstance(value, bool) or not hasattr(value, "__float__"):
        return format(value, spec)
    if unknown and not math.isfinite(float(value)):
        return "?"
    if lang == "en" or isinstance(value, int) and not spec:
        return format(value, spec)
    m = re.fullmatch(r"([<>^=]?)([+]?)(\d*)\.(\d+)f", spec)
    if m and math.isfinite(float(value)):
        text = format_number(float(value), int(m.group(4)), lang)
        if m.group(2) and not text.startswith("-"):
            text = "+" + text
        width = int(m.group(3) or 0)
        return text.ljust(width) if m.group(1) == "<" else text.rjust(width)
    text = format(value, spec)
    return text.replace(".", ",") if lang in ("ru", "vi") else text


def width(text: str) -> int:
    """Columns a string takes in a terminal (East Asian wide characters take two)."""
    return sum(0 if unicodedata.combining(ch) else
               2 if unicodedata.east_asian_width(ch) in ("W", "F") else 1 for ch in text)


def pad(text: str, size: int, align: str = "<") -> str:
    """A string padded to ``size`` terminal columns."""
    fill = " " * max(0, size - width(text))
    return text + fill if align == "<" else fill + text


# -- rendering -------------------------------------------------------------------------------------
class _Formatter(string.Formatter):
    def __init__(self, lang: str) -> None:
        super().__init__()
        self.lang = lang

    def format_field(self, value: Any, format_spec: str) -> str:
        lang = self.lang
        if isinstance(value, Text):
            return format(value.tr(lang), format_spec)
        if isinstance(value, (list, tuple)):
            return format(_render("_join", {"items": list(value), "sep": ", "}, lang),
                          format_spec)
        if isinstance(value, str):
            return format(value, format_spec)
        if value is None:
            return ""
        return num(value, format_spec, lang)


def _render(key: str, args: dict[str, Any], lang: str) -> str:
    if lang not in LANGUAGES:
        lang = "en"
    special = _SPECIAL.get(key)
    if special is not None:
        return special(args, lang)
    return _Formatter(lang).vformat(_template(key, lang), (), args)


def _render_join(args: dict[str, Any], lang: str) -> str:
    sep = args.get("sep", ", ")
    items = [tr(x, lang) if isinstance(x, str) else num(x, "", lang) for x in args["items"]]
    if sep == ", " and lang in ("ru", "vi") and any(_DECIMAL_COMMA.search(x) for x in items):
        sep = "; "          # "b 0,6 мм; c 0,9 мм", not "b 0,6 мм, c 0,9 мм"
    name = _SEPARATORS.get(sep)
    return (_template(f"sep.{name}", lang) if name else sep).join(items)


def _render_plan(args: dict[str, Any], lang: str) -> str:
    plan, group, number = args["plan"], args.get("group", ""), args.get("number", 0)
    if plan not in _PLANS:
        return plan
    if args.get("bare"):
        return _template(f"plan.{plan}.word", lang)
    text = " ".join(_template(f"plan.{plan}.{args.get('case', 'nom')}", lang)
                    .format(group=group).split())
    if number:
        text += f" #{number}"
    return text + (_template("plan.table", lang) if args.get("table") else "")


_SPECIAL = {"_join": _render_join, "_plan": _render_plan}
