"""Resource limits: refuse work whose memory would exceed a budget, before doing it.

The budget is ``MECHPLAN_MEMORY_BUDGET`` (e.g. ``"4 GB"``, ``"512 MB"``, or bytes), default 2 GB.
"""

from __future__ import annotations

import math
import os
import re

import numpy as np

from .errors import MechplanError, shown
from .i18n import Text

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
        raise LimitError(Text("errors.budget.env", {"value": repr(text)}))
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
        raise LimitError(Text("errors.budget.steps", {
            "positions": shown(positions), "steps": str(steps), "need": need,
            "budget": _size(budget)}), file=file, key=key)
    return estimate


#: memory of a report (the JSON document or the text report, as Python objects and text) per
#: byte of one position's indented JSON: measured 14.5 for four_bar at 100 000 positions (3.2 GB)
REPORT_BYTES_FACTOR = 16


def ensure_report_within_budget(positions: int, json_bytes: int, *, file: str | None = None,
                                key: str | None = None) -> int:
    """Return the estimated bytes of a report of ``positions`` positions whose first position's
    JSON takes ``json_bytes``; raise :class:`LimitError` with the estimate over the budget."""
    estimate = positions * json_bytes * REPORT_BYTES_FACTOR
    budget = memory_budget()
    if estimate > budget:
        most = max(1, budget // max(1, json_bytes * REPORT_BYTES_FACTOR))
        raise LimitError(Text("errors.budget.report", {
            "positions": shown(positions), "need": _size(estimate), "budget": _size(budget),
            "most": f"{most:,}"}), file=file, key=key)
    return estimate


# -- files a user gives mechplan (mechplan.userfiles) ---------------------------------------------
# Each kind of file is read only when it is a regular file no larger than its limit: a scene of the
# course is a few kB, a drawn A1 sheet a few MB; the limits leave a hundred times that.

#: a scene file (TOML)
SCENE_MAX_BYTES = 4 * 1024**2
#: a variants file of a class (CSV or TOML): thousands of students with their keys
VARIANTS_MAX_BYTES = 16 * 1024**2
#: a data file a scene names (an engine's indicator table)
DATA_MAX_BYTES = 16 * 1024**2
#: a submitted table (CSV or TOML): a course project's answers are a few hundred rows
TABLE_MAX_BYTES = 8 * 1024**2
#: a submitted DXF sheet (ASCII or binary); 100 000 lines are about 18 MB of ASCII DXF
DXF_MAX_BYTES = 128 * 1024**2

# -- what a submission may hold -------------------------------------------------------------------
#: rows of a submitted table (a whole course project has a few hundred values)
TABLE_MAX_ROWS = 20_000
#: tables and arrays nested in a submitted TOML table (an answer table nests three or four)
TABLE_MAX_NESTING = 16
#: characters of one cell of a CSV table (Python's csv default field limit)
CSV_CELL_MAX_CHARS = 128 * 1024
#: entities of a DXF sheet, counted as read with every block INSERT expanded; a full A1 sheet
#: of the course draws a few thousand
DXF_MAX_ENTITIES = 200_000
#: blocks inserted inside blocks: deeper nesting (a block inserting itself) is refused
DXF_MAX_INSERT_DEPTH = 8


# -- limits on what a user may ask for (issue 38; docs/security.md lists every limit) ----------
#: largest crank angle asked for by its value (degrees): past it the angle within a turn is
#: uncertain (a float near 1e300 is spaced 1e284 apart)
MAX_ANGLE_DEG = 1e6
#: largest distance on paper an option may give (mm): the long side of an A0 sheet
MAX_PAPER_MM = 1189.0


def check_angle_deg(value: float, what: str | None = None) -> float:
    """Return ``value`` (degrees) if it is finite and within ±:data:`MAX_ANGLE_DEG`.

    Raise :class:`LimitError` saying how far apart floats are at that size (``what``: the name
    of the value; a crank angle when not given)."""
    if not math.isfinite(value) or abs(value) > MAX_ANGLE_DEG:
        spacing = (Text("errmsg2.limits.float_spacing", {"step": f"{math.ulp(value):.2g}"})
                   if math.isfinite(value) and math.ulp(value) > 1e-6 else "")
        raise LimitError(Text("errmsg2.limits.angle_range", {
            "what": what or Text("errmsg2.limits.crank_angle"), "max": f"{MAX_ANGLE_DEG:g}",
            "value": f"{value:g}", "spacing": spacing}))
    return value


def check_angles_deg(values: np.ndarray, what: str | None = None) -> np.ndarray:
    """Return ``values`` (degrees) if every one passes :func:`check_angle_deg`."""
    bad = values[~(np.abs(values) <= MAX_ANGLE_DEG)]
    if bad.size:
        check_angle_deg(float(bad[0]), what)
    return values
