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
import math
import re
import string
import unicodedata
from collections.abc import Iterable
from importlib import resources
from typing import Any, Self

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
    from babel.messages.pofile import read_po  # Babel is imported when first needed

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


_UNIT_SYMBOL = re.compile(r"[A-Za-z]+")


def unit(expression: str, language: str) -> str:
    """Write a unit given in SI symbols as ``language`` writes it, symbol by symbol.

    ``unit("(m/s²)/mm", "ru")`` is "(м/с²)/мм", ``unit("kg·m²", "ru")`` "кг·м²"; each symbol
    comes from the catalogue entry ``unit.<symbol>`` (locale/<lang>/units.po); one without an
    entry stays as written. Only units go through here, never names or sentences.
    """
    table = catalogue(language)
    return _UNIT_SYMBOL.sub(lambda m: table.get(f"unit.{m.group()}", m.group()), expression)


@functools.cache
def _locale(language: str) -> Any:
    from babel import Locale

    return Locale.parse(language)


def decimal_mark(language: str) -> str:
    """Return the language's decimal mark ("," for ru and vi, "." for en and zh)."""
    return str(_locale(language).number_symbols["latn"]["decimal"])


# -- numbers: every number a sheet or a report prints is written by the functions below ----------
#: magnitudes written in decimal form by :func:`significant`; outside, the ×10ⁿ form
DECIMAL_RANGE = (1e-6, 1e9)
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number(value: float, digits: int, language: str) -> str:
    """Format a number with ``digits`` decimals and the language's decimal mark, without grouping.

    A value that rounds to zero is written without a minus sign. The one writer of decimals:
    :func:`tick`, :func:`significant` and :func:`scientific` call it.
    """
    s = f"{value:.{max(0, digits)}f}"
    if s.startswith("-") and float(s) == 0.0:
        s = s[1:]
    mark = decimal_mark(language)
    return s.replace(".", mark) if mark != "." else s


def decimals_of(step: float) -> int:
    """The fewest decimals that write ``step`` exactly (to 1e-9 of it): 2.5 → 1, 0.0025 → 4,
    20 → 0; every multiple of ``step`` then needs no more."""
    step = abs(float(step))
    if step == 0.0 or not math.isfinite(step):
        return 0
    for d in range(17):
        if abs(round(step, d) - step) <= 1e-9 * step:
            return d
    return 17


def tick(value: float, step: float, language: str) -> str:
    """A tick label: ``value`` (a multiple of ``step``) with the decimals ``step`` needs, so that
    the label equals its tick (2.5, 5.0, 7.5 for a step of 2.5; never "2, 5, 8")."""
    return number(value, decimals_of(step), language)


def trimmed(value: float, digits: int, language: str) -> str:
    """``value`` with at most ``digits`` decimals, the zeros that end its fraction dropped (never
    an integer's zeros): φ = 30.5 → "30,5", 100.0 → "100"."""
    return _trimmed(number(value, digits, language), language)


def _trimmed(text: str, language: str) -> str:
    mark = decimal_mark(language)
    if mark in text:
        text = text.rstrip("0").removesuffix(mark)
    return "0" if text in ("-0", "") else text


def significant(value: float, figures: int, language: str) -> str:
    """``value`` to ``figures`` significant figures without the zeros that end its fraction:
    1000 → "1000", 2500 → "2500", 0.00025 → "0,00025" (ru), 6.981317 → "6,9813" (5 figures).

    A magnitude outside :data:`DECIMAL_RANGE` is written by :func:`scientific`; an integer part
    longer than ``figures`` is kept whole (40000 with 2 figures is "40000").
    """
    v = float(value)
    if not math.isfinite(v):
        return "∞" if v > 0 else "-∞" if v < 0 else "?"
    if v == 0.0:
        return "0"
    if not DECIMAL_RANGE[0] <= abs(v) < DECIMAL_RANGE[1]:
        return scientific(v, figures, language)
    digits = max(0, figures - 1 - math.floor(math.log10(abs(v))))
    return _trimmed(number(v, digits, language), language)


def scale_factor(mu: float, language: str) -> str:
    """A scale factor μ with all its significant figures (six at most): "2,5", "0,00025",
    "1000", "40000" — the same on the sheet and in the report."""
    return significant(mu, 6, language)


def scientific(value: float, figures: int, language: str) -> str:
    """``value`` as mantissa × 10 to a power, the way the language writes it (Babel's
    superscripting exponent): 1.67e-14 → "1,67×10⁻¹⁴" (ru), "1.67×10⁻¹⁴" (en); never "e-14".
    Trailing zeros of the mantissa are dropped; a power of 0 is written without it."""
    v = float(value)
    if not math.isfinite(v) or v == 0.0:
        return significant(v, figures, language)
    mantissa, exponent = f"{v:.{max(0, figures - 1)}e}".split("e")
    power = int(exponent)
    text = _trimmed(number(float(mantissa), max(0, figures - 1), language), language)
    if power == 0:
        return text
    times = str(_locale(language).number_symbols["latn"].get("superscriptingExponent", "×"))
    return f"{text}{times}10{str(power).translate(_SUPERSCRIPT)}"


def grouped(value: float, digits: int, language: str) -> str:
    """Format a number with the language's decimal mark and digit grouping (Babel)."""
    from babel.numbers import format_decimal

    pattern = "#,##0" + ("." + "0" * digits if digits > 0 else "")
    return str(format_decimal(value, format=pattern, locale=_locale(language)))


# -- sentences said again in another language -----------------------------------------------------
class Text(str):
    """A message of the catalogues: its English sentence as a ``str`` (so it compares, joins and
    prints as English), which remembers its message id and arguments to be said again in another
    language with :meth:`tr`. Arguments may be texts, lists (joined) or numbers (written with the
    language's decimal mark by :func:`num`). A subclass says itself otherwise by overriding
    :meth:`say` (and :meth:`joined` for list arguments)."""

    key: str
    args: dict[str, Any]

    def __new__(cls, key: str, args: dict[str, Any] | None = None) -> Self:
        args = dict(args or {})
        obj = super().__new__(cls, cls.say(key, args, DEFAULT_LANGUAGE))
        obj.key, obj.args = key, args
        return obj

    def __reduce__(self) -> tuple[Any, ...]:
        return (type(self), (self.key, self.args))

    def tr(self, language: str) -> str:
        """The text in a language (en, ru, vi, zh)."""
        return str(self) if language == DEFAULT_LANGUAGE else self.say(self.key, self.args,
                                                                       language)

    @classmethod
    def say(cls, key: str, args: dict[str, Any], language: str) -> str:
        """Message ``key`` with its arguments in a language (an unknown language: English); the
        keys ``_join`` and ``_plan`` are a list (:func:`join`) and a plan's title
        (:func:`plan_title`)."""
        language = language if language in LANGUAGES else DEFAULT_LANGUAGE
        if key == "_join":
            return listed(args["items"], args["sep"], language)
        if key == "_plan":
            return _say_plan(args, language)
        return _Formatter(language, cls).vformat(catalogue(language)[key], (), args)

    @classmethod
    def joined(cls, items: list[Any], sep: str, language: str) -> str:
        """The items of a list argument in a language, joined by ``sep``."""
        return sep.join(tr(x, language) if isinstance(x, str) else num(x, "", language)
                        for x in items)


class _Formatter(string.Formatter):
    def __init__(self, language: str, text: type[Text]) -> None:
        super().__init__()
        self.language, self.text = language, text

    def format_field(self, value: Any, format_spec: str) -> str:
        if isinstance(value, Text):
            return format(value.tr(self.language), format_spec)
        if isinstance(value, (list, tuple)):
            return format(self.text.joined(list(value), ", ", self.language), format_spec)
        if isinstance(value, str):
            return format(value, format_spec)
        return "" if value is None else num(value, format_spec, self.language)


_DECIMAL_COMMA = re.compile(r"\d,\d")
_SEPARATORS = {", ": "comma", "; ": "semicolon", " and ": "and", " or ": "or"}


def listed(items: list[Any], sep: str, language: str) -> str:
    """Items said in a language and joined by a separator said in it (", " is "、" in Chinese;
    a comma between numbers with a decimal comma is a semicolon)."""
    said = [tr(x, language) if isinstance(x, str) else num(x, "", language) for x in items]
    if sep == ", " and language in ("ru", "vi") and any(_DECIMAL_COMMA.search(x) for x in said):
        sep = "; "          # "b 0,6 мм; c 0,9 мм", not "b 0,6 мм, c 0,9 мм"
    name = _SEPARATORS.get(sep)
    return (catalogue(language)[f"core.sep.{name}"] if name else sep).join(said)


def join(items: Iterable[Any], sep: str = ", ") -> Text:
    """Items joined by a separator said in each language (:func:`listed`)."""
    return Text("_join", {"items": list(items), "sep": sep})


def plan_title(plan: str, group: str = "", number: int = 0, table: bool = False,
               case: str = "nom") -> Text:
    """"velocity plan", "force II(2,3) plan #2", "velocity plan (table)" (``plan``: a
    ``Plan`` value); in Russian in the case the sentence needs (nom, gen, loc)."""
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


def _say_plan(args: dict[str, Any], language: str) -> str:
    messages, plan = catalogue(language), args["plan"]
    if args.get("bare"):
        return messages[f"core.plan.{plan}.word"]
    text = " ".join(messages[f"core.plan.{plan}.{args['case']}"].format(group=args["group"])
                    .split())
    if args["number"]:
        text += f" #{args['number']}"
    return text + (messages["core.plan.table"] if args["table"] else "")


def tr(x: Any, language: str) -> str:
    """Any string in a language: a :class:`Text` is said again, other strings are kept."""
    if isinstance(x, Text):
        return x.tr(language)
    return "" if x is None else str(x)


def num(value: Any, spec: str, language: str) -> str:
    """A number formatted by a format spec with the language's decimal mark; in English exactly
    ``format(value, spec)`` unless that is in e-notation, which is written as ×10ⁿ
    (:func:`scientific`) in every language. A spec starting with "~" writes a number that is not
    finite as "?"."""
    unknown = spec.startswith("~")
    spec = spec.removeprefix("~")
    if isinstance(value, bool) or not hasattr(value, "__float__"):
        return format(value, spec)
    if unknown and not math.isfinite(float(value)):
        return "?"
    if isinstance(value, int) and not spec:
        return format(value, spec)
    e = re.fullmatch(r"([<>^=]?)(\d*)(?:\.(\d+))?([eEgG])", spec)
    if e and math.isfinite(float(value)) and "e" in format(value, spec).lower():
        figures = int(e.group(3) or 6) + (e.group(4) in "eE")    # never "1.67e-14"
        text = scientific(float(value), figures, language)
        return text.ljust(int(e.group(2) or 0)) if e.group(1) == "<" else text.rjust(
            int(e.group(2) or 0))
    if language == "en":
        return format(value, spec)
    m = re.fullmatch(r"([<>^=]?)([+]?)(\d*)\.(\d+)f", spec)
    if m and math.isfinite(float(value)):
        text = number(float(value), int(m.group(4)), language)
        if m.group(2) and not text.startswith("-"):
            text = "+" + text
        width_ = int(m.group(3) or 0)
        return text.ljust(width_) if m.group(1) == "<" else text.rjust(width_)
    text = format(value, spec)
    return text.replace(".", ",") if language in ("ru", "vi") else text


def width(text: str) -> int:
    """Columns a string takes in a terminal (East Asian wide characters take two)."""
    return sum(0 if unicodedata.combining(ch) else
               2 if unicodedata.east_asian_width(ch) in ("W", "F") else 1 for ch in text)


def pad(text: str, size: int, align: str = "<") -> str:
    """A string padded to ``size`` terminal columns."""
    fill = " " * max(0, size - width(text))
    return text + fill if align == "<" else fill + text
