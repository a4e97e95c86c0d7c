"""Resource limits: refuse work whose memory would exceed a budget, before doing it.

The budget is ``MECHPLAN_MEMORY_BUDGET`` (e.g. ``"4 GB"``, ``"512 MB"``, or bytes), default 2 GB.
"""

from __future__ import annotations

import math
import os
import re

import numpy as np

from .errors import MechplanError, shown

DEFAULT_BUDGET = 2 * 1024**3
#: bytes per step and position: a (N, 2) float64 value, its gap or sine, and evaluation temporaries
BYTES_PER_STEP = 48
_UNITS = {"": 1, "b": 1, "kb": 1024, "k": 1024, "mb": 1024**2, "m": 1024**2, "gb": 1024**3,
          "g": 1024**3, "tb": 1024**4, "t": 1024**4}


class LimitError(MechplanError):
    """The work asked for would exceed a resource limit."""


def memory_budget() -> int:
    """Return the memory budget in bytes (``MECHPLAN_MEMORY_BUDGET`` or 2 GB)."""
    text = os.environ.get("MECHPLAN_MEMORY_BUDGET", "").strip()
    if not text:
        return DEFAULT_BUDGET
    m = re.fullmatch(r"(\d+(?:\.\d+)?)\s*([kKmMgGtT]?[bB]?)", text)
    if not m:
        raise LimitError(f"MECHPLAN_MEMORY_BUDGET must be a size such as '4 GB' (got {text!r})")
    return int(min(float(m.group(1)) * _UNITS[m.group(2).lower()], 2.0**62))


def _size(n: float) -> str:
    for unit, factor in (("TB", 1024**4), ("GB", 1024**3), ("MB", 1024**2), ("kB", 1024)):
        if n >= factor:
            return f"{n / factor:.1f} {unit}"
    return f"{n:.0f} B"


def ensure_within_budget(positions: int, steps: int, *, file: str | None = None,
                         key: str | None = None) -> int:
    """Return the estimated bytes of evaluating ``steps`` steps at ``positions`` positions.

    Raise :class:`LimitError` with the estimate when it exceeds :func:`memory_budget`.
    """
    estimate = positions * steps * BYTES_PER_STEP
    budget = memory_budget()
    if estimate > budget:
        need = "more than 1024 TB" if estimate >= 1024**5 else f"about {_size(estimate)}"
        raise LimitError(
            f"{shown(positions)} positions × {steps} construction steps need {need} "
            f"of memory, more than the budget of {_size(budget)}; ask for fewer positions "
            "(e.g. count = 3600) or raise MECHPLAN_MEMORY_BUDGET", file=file, key=key)
    return estimate


# -- limits on what a user may ask for (issue 38; docs/security.md lists every limit) ----------
#: largest crank angle asked for by its value (degrees): past it the angle within a turn is
#: uncertain (a float near 1e300 is spaced 1e284 apart)
MAX_ANGLE_DEG = 1e6
#: largest distance on paper an option may give (mm): the long side of an A0 sheet
MAX_PAPER_MM = 1189.0


def check_angle_deg(value: float, what: str = "a crank angle") -> float:
    """Return ``value`` (degrees) if it is finite and within ±:data:`MAX_ANGLE_DEG`.

    Raise :class:`LimitError` saying how far apart floats are at that size."""
    if not math.isfinite(value) or abs(value) > MAX_ANGLE_DEG:
        spacing = (f"; floats that large are {math.ulp(value):.2g}° apart, so the angle within "
                   "a turn is lost" if math.isfinite(value) and math.ulp(value) > 1e-6 else "")
        raise LimitError(f"{what} must be a finite number of degrees within ±{MAX_ANGLE_DEG:g} "
                         f"(got {value:g}){spacing}")
    return value


def check_angles_deg(values: np.ndarray, what: str = "a crank angle") -> np.ndarray:
    """Return ``values`` (degrees) if every one passes :func:`check_angle_deg`."""
    bad = values[~(np.abs(values) <= MAX_ANGLE_DEG)]
    if bad.size:
        check_angle_deg(float(bad[0]), what)
    return values
