"""Quantity parsing at the edges: "80 mm", "800 rpm", "1 MPa" → SI floats."""

from __future__ import annotations

import functools
import math
import re
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:      # pint costs ~0.15 s to import: only when a quantity is read
    import pint

from .errors import SceneError, shown
from .i18n import Text, join

#: dimension name → (pint dimensionality string, SI unit to convert to)
DIMENSIONS: dict[str, tuple[str, str]] = {
    "length": ("[length]", "m"),
    "angle": ("", "rad"),
    "angular_velocity": ("1/[time]", "rad/s"),
    "angular_acceleration": ("1/[time]**2", "rad/s**2"),
    "velocity": ("[length]/[time]", "m/s"),
    "acceleration": ("[length]/[time]**2", "m/s**2"),
    "mass": ("[mass]", "kg"),
    "inertia": ("[mass]*[length]**2", "kg*m**2"),
    "force": ("[mass]*[length]/[time]**2", "N"),
    "moment": ("[mass]*[length]**2/[time]**2", "N*m"),
    "pressure": ("[mass]/[length]/[time]**2", "Pa"),
    "area": ("[length]**2", "m**2"),
    "dimensionless": ("", ""),
    "density": ("[mass]/[length]**3", "kg/m**3"),
    "stiffness": ("[mass]/[time]**2", "N/m"),
    "damping": ("[mass]/[time]", "N*s/m"),
    "torsional_damping": ("[mass]*[length]**2/[time]", "N*m*s"),
    # scale factors: physical unit per mm of paper
    "mu_length": ("", "m/mm"),
    "mu_velocity": ("1/[time]", "m/s/mm"),
    "mu_acceleration": ("1/[time]**2", "m/s**2/mm"),
    "mu_force": ("[mass]/[time]**2", "N/mm"),
    "mu_moment": ("[mass]*[length]/[time]**2", "N*m/mm"),
}

def example(dimension: str) -> str:
    """How a value of a dimension may be written (``'"0.1 (m/s)/mm"'``), for messages."""
    return _EXAMPLES[dimension]


def si_unit(dimension: str) -> str:
    """The SI unit of a dimension as a reader writes it ("m/s²", "kg·m²"; "" for none)."""
    return DIMENSIONS.get(dimension, ("", ""))[1].replace("**2", "²").replace("*", "·")


_EXAMPLES = {
    "length": '"80 mm" or "0.08 m"',
    "angle": '"60 deg" or "1.047 rad"',
    "angular_velocity": '"800 rpm" or "83.8 rad/s"',
    "angular_acceleration": '"0 rad/s^2"',
    "velocity": '"6.7 m/s"',
    "acceleration": '"9.81 m/s^2"',
    "mass": '"3.1 kg" or "170 g"',
    "inertia": '"0.1 kg*m^2"',
    "force": '"7850 N" or "7.85 kN"',
    "moment": '"100 N*m"',
    "stiffness": '"2 N/mm" or "2000 N/m"',
    "damping": '"5 N*s/m"',
    "torsional_damping": '"0.01 N*m*s/rad"',
    "pressure": '"1 MPa" or "85 kPa"',
    "area": '"78.5 cm^2"',
    "dimensionless": '"0.35"',
    "density": '"7800 kg/m^3"',
    "mu_length": '"0.0025 m/mm"',
    "mu_velocity": '"0.1 (m/s)/mm"',
    "mu_acceleration": '"2 (m/s^2)/mm"',
    "mu_force": '"100 N/mm"',
    "mu_moment": '"10 N*m/mm"',
}


@functools.lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """Return the project's own explicit unit registry (angles are dimensionless radians)."""
    import pint

    ureg: pint.UnitRegistry = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    if "rpm" not in ureg:
        ureg.define("rpm = revolution / minute")
    return ureg


_DECIMAL_COMMA = re.compile(r"(?<=\d),(?=\d)")
#: characters of a quantity's text ("0,1 (m/s^2)/mm" is 14): pint's parser is slow on long text
MAX_QUANTITY_CHARS = 100
#: what may follow "**": a plain exponent below 100 ("m/s^2", "m**-2", "(1/2)" is not one); pint
#: computes "10^10^10" or "10^(99*99*99*99)" as integers, without end
_EXPONENT = re.compile(r"\s*(?:\(\s*[-+]?\s*\d{1,2}(?:\.\d+)?\s*\)|[-+]?\s*\d{1,2}(?:\.\d+)?)"
                       r"(?![\d.]|\s*\*\*)")
_TWO_MARKS = re.compile(r"\d[.,]\d*[.,]\d")


def _noun(dimension: str) -> Text:
    """"a length", "длина": the kind of quantity a key wants, said in any language."""
    return Text(f"errors.noun.{dimension}")


def _example(dimension: str) -> Text:
    """'"80 mm" or "0.08 m"' with "or" said in any language."""
    return join(_EXAMPLES[dimension].split(" or "), " or ")


def _error(message: str, file: str | None, key: str | None, **args: Any) -> SceneError:
    return SceneError(Text(f"errors.units.{message}", args), file=file, key=key)


def parse_quantity(text: object, dimension: str, *, file: str | None = None,
                   key: str | None = None) -> float:
    """Parse a quantity as people write it and return its SI value as a float.

    Plain numbers are accepted only for ``dimensionless``; a decimal comma ("0,1") is accepted.
    Angles come back in radians, angular speeds in rad/s, scale factors per millimetre of paper.
    """
    example, noun = _example(dimension), _noun(dimension)
    if isinstance(text, bool):
        raise _error("expected", file, key, noun=noun, example=example, value=repr(text))
    if isinstance(text, (int, float)):
        if dimension == "dimensionless" or dimension.startswith("mu_"):
            try:
                return float(text)
            except OverflowError:
                raise _error("too_large", file, key, value=shown(text)) from None
        raise _error("needs_unit", file, key, noun=noun, example=example, value=repr(text))
    if not isinstance(text, str) or not text.strip():
        raise _error("expected", file, key, noun=noun, example=example, value=repr(text))
    if len(text) > MAX_QUANTITY_CHARS:
        raise _error("too_long", file, key, value=shown(text), noun=noun,
                     length=f"{len(text):,}", most=str(MAX_QUANTITY_CHARS), example=example)
    if _TWO_MARKS.search(text):
        raise _error("two_marks", file, key, value=repr(text), noun=noun, example=example)
    cleaned = _DECIMAL_COMMA.sub(".", text.strip()).replace("·", "*").replace("²", "^2")
    cleaned = cleaned.replace("°", " deg").replace("^", "**")
    if any(not _EXPONENT.match(cleaned, m.end()) for m in re.finditer(r"\*\*", cleaned)):
        raise _error("exponent", file, key, value=shown(text), noun=noun, example=example)
    try:
        return _convert(cleaned, text, dimension, file, key)
    except OverflowError:       # "1e200 km^2": beyond a float while converting
        raise _error("too_large", file, key, value=shown(text)) from None


#: the units scenes write most, with their dimension and SI factor: "80 mm" is read without
#: loading pint (about 0.3 s of a command's start). Each factor is pint's own, and a value read
#: here equals pint's to the last bit (tests/scene/test_units_fast.py compares them); anything
#: else — another unit, a compound one, a unit of another dimension — goes to pint.
FAST_UNITS: dict[str, tuple[str, float]] = {
    "mm": ("length", 0.001), "cm": ("length", 0.01), "m": ("length", 1.0),
    "km": ("length", 1000.0), "deg": ("angle", math.pi / 180.0), "rad": ("angle", 1.0),
    "rpm": ("angular_velocity", 2.0 * math.pi / 60.0), "rad/s": ("angular_velocity", 1.0),
    "rad/s**2": ("angular_acceleration", 1.0), "m/s": ("velocity", 1.0),
    "m/s**2": ("acceleration", 1.0), "kg": ("mass", 1.0), "N": ("force", 1.0),
    "kN": ("force", 1000.0), "N*m": ("moment", 1.0), "kg*m**2": ("inertia", 1.0),
    "Pa": ("pressure", 1.0), "kPa": ("pressure", 1000.0), "MPa": ("pressure", 1000000.0),
    "bar": ("pressure", 100000.0), "N/m": ("stiffness", 1.0), "N/mm": ("stiffness", 1000.0),
    "mm**2": ("area", 1e-06), "cm**2": ("area", 0.0001), "m**2": ("area", 1.0),
    "kg/m**3": ("density", 1.0),
}
_FAST = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z/*0-9]+)\s*")


def _fast(cleaned: str, dimension: str) -> float | None:
    """The SI value of a plain "number unit" of a common unit of ``dimension``, or None."""
    m = _FAST.fullmatch(cleaned)
    if m is None:
        return None
    unit = FAST_UNITS.get(m.group(2))
    if unit is None or unit[0] != dimension:
        return None
    value = float(m.group(1)) * unit[1]
    return value if math.isfinite(value) else None


def _convert(cleaned: str, text: str, dimension: str, file: str | None, key: str | None) -> float:
    quick = _fast(cleaned, dimension)
    if quick is not None:
        return quick
    _dim, si_unit = DIMENSIONS[dimension]
    example, noun = _example(dimension), _noun(dimension)
    ureg = registry()
    try:
        q: Any = ureg.Quantity(cleaned)
    except OverflowError:
        raise
    except Exception as exc:  # noqa: BLE001 - pint raises many unrelated types for bad text
        raise _error("unreadable", file, key, value=repr(text), noun=noun, example=example,
                     reason=exc.__class__.__name__) from None
    if not isinstance(q, ureg.Quantity):
        q = ureg.Quantity(float(q), "")
    target = ureg.Quantity(1.0, si_unit) if si_unit else ureg.Quantity(1.0, "")
    if q.unitless and dimension.startswith("mu_"):
        return float(q.magnitude)  # a bare scale factor is in SI units per mm of paper
    if q.unitless and dimension != "dimensionless":
        raise _error("needs_unit", file, key, noun=noun, example=example, value=repr(text))
    if q.dimensionality != target.dimensionality:
        raise _error("wrong_dimension", file, key, value=repr(text), noun=noun,
                     unit=f"{q.units:~}", dimensionality=str(q.dimensionality), example=example)
    value = float(q.to(si_unit).magnitude) if si_unit else float(q.to("").magnitude)
    if not math.isfinite(value):
        raise _error("not_finite", file, key, value=repr(text))
    return value


def format_number(value: float, digits: int, language: str) -> str:
    """Format a number with a fixed number of decimals and the language's decimal mark."""
    from .i18n import number

    return number(value, digits, language)
