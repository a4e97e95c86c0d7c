"""Labels, names, numbers and units as students write them: the text of a submission read
before it means anything (no construction here).

``label_key("b′")`` → ``"b'"`` (the comparison key of a point label); ``label_names("p≡c")`` →
``["p", "c"]`` (the names one label gives its point); ``parse_value("0,25 м/с", "velocity", …)`` →
(0.25, 0.005) with half a unit of the last written digit; ``parse_angle("60°")`` → 60.0;
``is_angle_name("φ1")`` → True.
"""

from __future__ import annotations

import math
import re

from ..errors import SceneError
from ..units import parse_quantity, si_unit
from .notation import SUBSCRIPTS, units_ascii
from .read import Note
from .texts import T

PRIMES = "′'’`´ʹ‘‛＇"
_SUP = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹ⁿᵗᵏʳ", "0123456789ntkr")


_NUMBER = re.compile(r"[-+−]?\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?")


def label_key(text: str) -> str:
    """Return the comparison key of a written label: lower case, one prime mark, no decoration.

    ``"b′"``, ``"b'"`` and ``"B’"`` → ``"b'"``; ``"n_{CB}"`` and ``"nCB"`` → ``"ncb"``;
    ``"π′"`` → ``"π'"``; ``"s₂"`` → ``"s2"``.
    """
    t = text.strip().translate(SUBSCRIPTS).translate(_SUP)
    for ch in PRIMES:
        t = t.replace(ch, "'")
    t = t.replace("″", "''")
    t = re.sub(r"[\s_{}^$\\]", "", t)
    t = t.replace("Π", "π")
    return t.lower()


_SAME_POINT = re.compile(r"\s*(?:≡|,|;)\s*")


def label_names(text: str) -> list[str]:
    """The names a label text gives its point: "c", or several for one point ("p≡c", "p, o1");
    none for a text that is no label ("μv = 0,1", "42")."""
    s = text.strip()
    if "\n" in s or "=" in s or ":" in s or s.replace(",", "").replace(".", "").isdigit():
        return []
    names = [n for n in _SAME_POINT.split(s) if n]
    return [n for n in names if 0 < len(label_key(n)) <= 9]


def parse_angle(text: str) -> float:
    """A written crank angle in degrees ("60", "60°", "1,05 rad"); a :class:`SceneError` if it is
    not one."""
    written = units_ascii(text) if any(ch.isalpha() or ch == "°" for ch in text) else (
        f"{text} deg")
    return math.degrees(parse_quantity(written, "angle"))


_PHI_NAME = re.compile(r"^(?:φ|ϕ|phi|fi|at|angle|crank[_ ]?angle)[_\s]*1?$", re.IGNORECASE)


def is_angle_name(name: str) -> bool:
    """True for the name of the crank angle of the submission ("φ", "φ1", "phi", "at")."""
    return bool(_PHI_NAME.match(name.strip()))


def case_key(text: str) -> str:
    """Like :func:`label_key` but keeping upper and lower case ("BC" ≠ "bc")."""
    low = label_key(text)
    t = "".join(ch for ch in text if not ch.isspace() and ch not in "_{}^$\\")
    if len(t) != len(low):
        return low
    return "".join(a.upper() if b.isupper() else a for a, b in zip(low, t))


def number_and_half(text: str) -> tuple[float | None, float]:
    """The first number of a text and half a unit of its last digit ("0,25" → 0.25, 0.005)."""
    m = _NUMBER.search(text)
    if not m:
        return None, 0.0
    s = m.group(0).replace("−", "-").replace(",", ".")
    mant = re.split("[eE]", s)[0]
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    exp = int(re.split("[eE]", s)[1]) if re.search("[eE]", s) else 0
    value = float(s)
    if not math.isfinite(value) or abs(exp - decimals) > 300:
        return None, 0.0
    return value, 0.5 * 10.0 ** (exp - decimals)


def is_length_text(text: str) -> bool:
    """True for a bare number or a length in millimetres of paper ("42", "42 mm", "42 мм")."""
    t = text.strip().lower()
    return bool(re.fullmatch(r"[-+−]?\d+(?:[.,]\d+)?\s*(mm|мм)?", t))


def parse_answer(text: str, dimension: str, where: str, notes: list[Note],
                 name: str) -> tuple[float, float] | None:
    """(SI value, half a unit of the last digit) of a study's written answer: a tooth number or a
    ratio ("count", "dimensionless") needs no unit, a bare angle is in degrees."""
    text = text.strip()
    dim = "dimensionless" if dimension == "count" else dimension
    if dim == "dimensionless" and re.fullmatch(r"[-+−]?\d+(?:[.,]\d+)?", text):
        value, half = number_and_half(text)
        return (value, half) if value is not None else None
    if dim == "angle" and re.fullmatch(r"[-+−]?\d+(?:[.,]\d+)?", text):
        text += " deg"
    return parse_value(text, dim, where, notes, name)


def parse_value(text: str, dimension: str, where: str, notes: list[Note],
                name: str) -> tuple[float, float] | None:
    """(SI value, half a unit of the last digit in SI) of a written value, or None with a note."""
    number, half = number_and_half(text)
    bare = bool(re.fullmatch(r"\s*[-+−]?\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?\s*", text))
    if bare and number is None:
        notes.append(Note("error", T("note.not_finite", name=name, text=text), where))
        return None
    if bare and number is not None:
        unit = si_unit(dimension) or "1"
        notes.append(Note("info", T("note.no_unit", name=name, text=text, unit=unit), where))
        return number, half
    try:
        value = parse_quantity(units_ascii(text), dimension)
    except SceneError as exc:
        notes.append(Note("error", T("note.value_error", name=name, text=text,
                                     detail=exc.detail), where))
        return None
    ratio = value / number if number else 1.0
    return value, abs(half * ratio)
