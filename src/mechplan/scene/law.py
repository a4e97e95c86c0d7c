"""Read a linear driver's law given by a table over time: ``law = { table = [[t, q], …] }`` or
``law = { file = "boom.csv" }`` (a CSV file inside the scene's folder, read the way every data
file a scene names is read: :func:`mechplan.userfiles.data_file`, a regular file within
``DATA_MAX_BYTES``, its content never echoed in a message).

``units = ["s", "mm"]`` (default) names the columns' units: the time (``s``, ``ms``, ``min``, or
``cycle`` — a fraction of the cycle, with ``period = "8 s"``) and the driver's length.
At least five rows, times strictly increasing, every value finite (docs/drivers.md).
"""

from __future__ import annotations

import csv
import io
from typing import Any

from ..errors import SceneError
from ..i18n import Text
from ..model.law import TableLaw, finite_rows
from .reader import Table

LAW_KEYS = ("table", "file", "units", "period")
#: the time column's units (s); "cycle": a fraction of the cycle, times ``period``
TIME_UNITS = {"s": 1.0, "ms": 1e-3, "min": 60.0, "cycle": 1.0}
#: fewest rows: the error estimate compares with the spline through every other row
MIN_ROWS = 5


def read_law(d: Table, dimension: str = "length") -> TableLaw:
    """The law of ``d.law`` (a table of rows or a CSV file): q a ``dimension`` ("length", m; or
    "angle", rad — a crank's φ, default unit deg)."""
    t = d.table("law", required=True)
    assert t is not None
    t.check_keys(LAW_KEYS)
    if t.has("table") == t.has("file"):
        raise t.error(None, Text("drives2.law.one_source"))
    units = t.raw("units", ["s", "mm" if dimension == "length" else "deg"])
    if (not isinstance(units, list) or len(units) != 2
            or not all(isinstance(u, str) for u in units) or units[0] not in TIME_UNITS):
        raise t.error("units", Text("drives2.law.units", {"value": repr(units)[:80]}))
    scale = TIME_UNITS[units[0]]
    if units[0] == "cycle":         # times as fractions of the cycle: its period in seconds
        scale = _period(t)
    elif t.has("period"):
        raise t.error("period", Text("drives2.law.period"))
    if t.has("file"):
        raw, where, source = _file_rows(t), "file", str(t.string("file"))
    else:
        raw, where, source = t.raw("table"), "table", "table"
        if not isinstance(raw, list):
            raise t.error("table", Text("drives2.law.rows"))
    times: list[float] = []
    values: list[float] = []
    for j, row in enumerate(raw):
        if not isinstance(row, list) or len(row) != 2:
            raise t.error(f"{where}[{j}]", Text("drives2.law.row"))
        times.append(_number(t, row[0], units[0], f"{where}[{j}]") * scale)
        values.append(t.value_quantity(f"{_number(t, row[1], units[1], f'{where}[{j}]')!r} "
                                       f"{units[1]}", f"{where}[{j}]", dimension))
    if len(times) < MIN_ROWS:
        raise t.error(where, Text("drives2.law.few_rows",
                                  {"count": str(len(times)), "least": str(MIN_ROWS)}))
    if not finite_rows(times, values):
        raise t.error(where, Text("drives2.law.row"))
    for j in range(1, len(times)):
        if times[j] <= times[j - 1]:
            raise t.error(f"{where}[{j}]", Text("drives2.law.times_increasing", {"row": str(j)}))
    return TableLaw(tuple(times), tuple(values), source)


def _period(t: Table) -> float:
    """The cycle's period (s) of a law over the cycle: ``period = "8 s"``."""
    raw = t.raw("period")
    text = raw.strip() if isinstance(raw, str) else ""
    number, _, unit = text.partition(" ")
    try:
        value = float(number.replace(",", ".")) * TIME_UNITS[unit.strip()]
    except (ValueError, KeyError):
        raise t.error("period", Text("drives2.law.period")) from None
    if not value > 0.0 or unit.strip() == "cycle":
        raise t.error("period", Text("drives2.law.period"))
    return value


def _number(t: Table, value: Any, unit: str, where: str) -> float:
    """A plain number of a row (a decimal comma allowed), in the column's ``unit``."""
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise t.error(where, Text("drives2.law.number", {"unit": unit}))
    text = value.strip().replace(",", ".") if isinstance(value, str) else str(value)
    try:
        return float(text)
    except (ValueError, OverflowError):
        raise t.error(where, Text("drives2.law.number", {"unit": unit})) from None


def _file_rows(t: Table) -> list[list[str]]:
    """The rows of the law's CSV file (comment lines ``#`` and a header row skipped)."""
    from ..userfiles import DATA, data_file, read_text

    name = t.string("file")
    assert name is not None
    key = t.key("file")
    scene = t.file or "<scene>"
    path = data_file(name, scene, key=key, error=SceneError)
    text = read_text(path, DATA, error=SceneError, key=key, shown=scene)
    try:
        rows = [[c.strip() for c in r] for r in csv.reader(io.StringIO(text, newline=""))
                if r and not r[0].lstrip().startswith("#")]
    except csv.Error:
        raise t.error("file", Text("drives2.law.csv")) from None
    if rows and not _numeric(rows[0][0]):
        rows = rows[1:]                      # a header row
    return rows


def _numeric(s: str) -> bool:
    try:
        float(s.replace(",", "."))
        return True
    except ValueError:
        return False
