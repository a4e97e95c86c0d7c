"""Read a submission: a hand-drawn DXF (lines, polylines, text labels) or a table of measured
values.

Nothing here knows the mechanism: the reader returns drawn lines, texts and "name = value" entries
with where each came from (file, entity handle, line number); :mod:`mechplan.check.match` gives them
meaning against a construction.
"""

from __future__ import annotations

import csv
import io
import math
import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import CheckError
from ..geom.sketch import box_distance
from ..i18n import Text
from ..limits import CSV_CELL_MAX_CHARS, TABLE_MAX_NESTING, TABLE_MAX_ROWS
from ..scene import toml
from ..userfiles import DXF, TABLE, read_bytes
from .texts import T

Point = tuple[float, float]

#: $INSUNITS → millimetres per drawing unit (0 = unitless, read as millimetres)
@dataclass(frozen=True, slots=True)
class Note:
    """A message about the submission: what could not be used, and where it is."""

    level: str          # "error" (an item could not be checked), "warning", "info"
    message: str
    where: str = ""

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message


@dataclass(frozen=True, slots=True)
class DrawnLine:
    """A straight line of the sheet in millimetres of paper."""

    start: Point
    end: Point
    where: str
    layer: str = ""

    @property
    def length(self) -> float:
        """Length in mm."""
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])


@dataclass(frozen=True, slots=True)
class SheetText:
    """A text of the sheet: plain content and the estimated centre of its box (mm)."""

    text: str
    centre: Point
    height: float
    where: str
    layer: str = ""
    anchor: Point = (0.0, 0.0)     # insertion (or alignment) point
    half: tuple[float, float] = (0.0, 0.0)   # half width and height of the text box (mm)
    rotation: float = 0.0          # degrees

    def distance(self, p: Any) -> Any:
        """Distance from points (N, 2) to the text's box (0 inside it); a float for one point."""
        d = box_distance(p, self.centre, self.half, self.rotation)
        return d if np.ndim(p) > 1 else float(d[0])


@dataclass(frozen=True, slots=True)
class Entry:
    """One "name = value" item of a table or of a text on the sheet, not yet interpreted.

    ``length`` is a drawn length ("67.0", "67,0 mm"); ``value`` a physical value with its unit
    ("6.7 m/s"); ``quantity`` the name the value is given for when it differs from ``name``
    ("pb = 67 mm → v_B = 6.7 m/s"); ``section`` the plan named by the table section or column.
    """

    name: str
    where: str
    length: str | None = None
    mu: str | None = None
    quantity: str | None = None
    value: str | None = None
    section: str | None = None
    text: str | None = None        # a single uninterpreted value ("67", "2.95 m/s")
    at: Point | None = None        # where the text stands on a sheet (mm)
    phi_deg: float | None = None   # the angle of an answer table's row (degrees)


@dataclass
class Submission:
    """What a submission holds, in millimetres of paper and raw texts."""

    path: str
    kind: str                                  # "dxf" or "table"
    lines: list[DrawnLine] = field(default_factory=list)
    markers: list[tuple[Point, str]] = field(default_factory=list)   # POINT / small CIRCLE
    heads: list[tuple[Point, Point]] = field(default_factory=list)   # arrowheads: tip, base
    texts: list[SheetText] = field(default_factory=list)
    entries: list[Entry] = field(default_factory=list)
    notes: list[Note] = field(default_factory=list)
    units: str = ""
    dimensions: list[tuple[float, SheetText]] = field(default_factory=list)  # measured, its text
    skipped: int = 0        # dash-dot lines and lines of frames and tables, not read


def submitted_file(path: str | Path) -> Path:
    """The path of a submitted file; a missing file or a folder is a :class:`CheckError`."""
    p = Path(path)
    if not p.exists():
        raise CheckError(T("error.no_file"), file=str(p))
    if p.is_dir():
        raise CheckError(T("error.is_dir"), file=str(p))
    return p


def read_submission(path: str | Path) -> Submission:
    """Read a DXF (or a PDF with a DXF attached), TOML, CSV or XLSX submission; raise
    :class:`CheckError` if it cannot be read at all."""
    p = submitted_file(path)
    suffix = p.suffix.lower()
    if suffix == ".dxf":
        from .dxf import read_dxf

        return read_dxf(p)
    if suffix == ".toml":
        return read_toml(p)
    if suffix in (".csv", ".tsv", ".txt", ".xlsx", ".xlsm"):
        return read_csv(p)
    if suffix == ".pdf":
        return read_pdf(p)
    data = read_bytes(p, DXF, error=CheckError)
    head = data[:256]
    if re.match(rb"\s*0\s*\r?\n\s*SECTION", head) or head.startswith(b"AutoCAD Binary DXF"):
        from .dxf import read_dxf

        return read_dxf(p, data)
    raise CheckError(T("error.kind", suffix=p.suffix or "—"), file=str(p))


def read_pdf(path: Path) -> Submission:
    """Read the DXF attached to a PDF (in memory: nothing is written); a note names the other
    attachments, which are not checked."""
    from .dxf import read_dxf
    from .pdf_attached import attached_dxf

    drawing, others = attached_dxf(path)
    sub = read_dxf(path, drawing.data)
    sub.notes.insert(0, Note("info", T("note.pdf_attached", name=drawing.name,
                                       others=", ".join(others) or "—")))
    return sub


# -- "name = value" texts ------------------------------------------------------------------------
_ARROW = re.compile(r"\s*(?:→|->|=>|⟶|⇒)\s*")
_ASSIGN = re.compile(r"^\s*([^=:]{1,24}?)\s*(?:=|:)\s*(.+?)\s*$")


def parse_assignments(line: str, where: str, section: str | None = None,
                      at: Point | None = None) -> list[Entry]:
    """Entries of one written line: "μv = 0,1 m/s/mm", "pb = 67 mm → v_B = 6,7 m/s"; several
    separated by ";" are allowed."""
    out: list[Entry] = []
    for part in re.split(r";|\s{3,}", line):
        if "=" not in part and ":" not in part:
            continue
        pieces = [p for p in _ARROW.split(part.strip()) if p]
        first = _ASSIGN.match(pieces[0]) if pieces else None
        if not first:
            continue
        name, text = first.group(1).strip(), first.group(2).strip()
        if not name or not text:
            continue
        entry = Entry(name=name, where=where, text=text, section=section, at=at)
        if len(pieces) > 1:
            second = _ASSIGN.match(pieces[1])
            if second:
                entry = Entry(name=name, where=where, length=text, quantity=second.group(1).strip(),
                              value=second.group(2).strip(), section=section, at=at)
            else:
                entry = Entry(name=name, where=where, length=text, value=pieces[1].strip(),
                              section=section, at=at)
        out.append(entry)
    return out


# -- TOML --------------------------------------------------------------------------------------
def read_toml(path: Path) -> Submission:
    """Read a TOML table: sections named by plan hold lengths, [values] physical values,
    [scales] scale factors; top-level keys may hold any of them."""
    sub = Submission(str(path), "table")
    data, line_of = load_toml(path)

    def walk(table: dict[str, Any], section: str | None, prefix: str) -> None:
        for key, value in table.items():
            where = line_of(key)
            if isinstance(value, dict):
                if _is_row(value):
                    sub.entries.append(_row_entry(key, value, where, section))
                else:
                    inner = key if section is None else f"{section} {key}"
                    walk(value, inner, f"{prefix}{key}.")
            elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
                for i, row in enumerate(value, start=1):
                    name = str(row.get("name") or row.get("segment") or row.get("quantity") or "")
                    if not name:
                        sub.notes.append(Note("error", T("note.row_no_name_toml"),
                                              T("where.row", where=where, n=i)))
                        continue
                    sub.entries.append(_row_entry(name, row, T("where.row", where=where, n=i),
                                                  _str(row.get("plan")) or section))
            elif isinstance(value, (str, int, float)) and not isinstance(value, bool):
                sub.entries.extend(_value_entries(key, value, where, section))
            else:
                sub.notes.append(Note("error", T("note.cannot_use", value=repr(value)), where))

    walk(data, None, "")
    if not sub.entries:
        raise CheckError(T("error.toml_empty"), file=str(path))
    return within_limits(sub)


_ROW_KEYS = {"mm", "length", "length_mm", "mu", "value", "quantity", "unit"}


def _is_row(d: dict[str, Any]) -> bool:
    return (bool(d) and set(d) <= _ROW_KEYS | {"name", "segment", "plan"}
            and bool(set(d) & _ROW_KEYS))


def _str(v: Any) -> str | None:
    if v is None:
        return None
    return str(v)


def _row_entry(name: str, row: dict[str, Any], where: str, section: str | None) -> Entry:
    length = row.get("mm", row.get("length_mm", row.get("length")))
    value = _str(row.get("value"))
    unit = _str(row.get("unit"))
    if value is not None and unit:
        value = f"{value} {unit}"
    quantity = _str(row.get("quantity"))
    if "segment" in row and quantity is None and "name" in row:
        quantity = str(row["name"])
    return Entry(name=str(row.get("segment", name)), where=where, length=_str(length),
                 mu=_str(row.get("mu")), quantity=quantity, value=value, section=section)


def _value_entries(key: str, value: Any, where: str, section: str | None) -> list[Entry]:
    if isinstance(value, str):
        entries = parse_assignments(f"{key} = {value}", where, section)
        if entries:
            return entries
    return [Entry(name=key, where=where, text=str(value), section=section)]


# -- CSV ---------------------------------------------------------------------------------------
_COLUMNS = {
    "name": ("name", "segment", "item", "label", "отрезок", "название", "đoạn", "tên", "线段",
             "名称"),
    "length": ("mm", "length", "length_mm", "length, mm", "длина", "длина, мм", "мм", "độ dài",
               "độ dài, mm", "长度", "长度/mm"),
    "mu": ("mu", "μ", "µ", "scale", "scale factor", "масштаб", "tỉ lệ", "tỉ lệ xích", "比例尺"),
    "quantity": ("quantity", "величина", "đại lượng", "物理量", "量"),
    "value": ("value", "значение", "giá trị", "值", "数值"),
    "unit": ("unit", "units", "ед.", "единица", "đơn vị", "单位"),
    "plan": ("plan", "план", "họa đồ", "图"),
}


def read_csv(path: Path) -> Submission:
    """Read a CSV table: with a header (segment, mm, mu, quantity, value, unit, plan) or rows of
    "name, value[, unit]"; the delimiter may be ",", ";" or a tab; decimal commas are accepted."""
    sub = Submission(str(path), "table")
    rows = csv_rows(path, _sniff)
    first = next((i for i, row in enumerate(rows, start=1) if any(c.strip() for c in row)
                  and not row[0].strip().startswith("#")), 0)
    header: dict[str, int] | None = None
    for lineno, row in enumerate(rows, start=1):
        cells = [c.strip() for c in row]
        if not any(cells) or cells[0].startswith("#"):
            continue
        where = T("where.line", file=path.name, n=lineno)
        if header is None and lineno == first:
            header = _header(cells)
            if header is not None:
                if "name" not in header:
                    raise CheckError(T("error.csv_header"), file=str(path),
                                     key=f"line {lineno}")
                continue
        if header is not None:
            def get(k: str, cells: list[str] = cells, header: dict[str, int] = header
                    ) -> str | None:
                i = header.get(k)
                return cells[i] if i is not None and i < len(cells) and cells[i] else None

            name = get("name")
            if not name:
                sub.notes.append(Note("error", T("note.row_no_name"), where))
                continue
            value, unit = get("value"), get("unit")
            if value is not None and unit:
                value = f"{value} {unit}"
            sub.entries.append(Entry(name=name, where=where, length=get("length"), mu=get("mu"),
                                     quantity=get("quantity"), value=value, section=get("plan")))
            continue
        cells = [c for c in cells if c != ""]
        if len(cells) < 2:
            if len(cells) == 1 and "=" in cells[0]:
                sub.entries.extend(parse_assignments(cells[0], where))
            else:
                sub.notes.append(Note("error", T("note.expected_name_value",
                                                 row=repr(','.join(row))), where))
            continue
        if len(cells) >= 4:
            sub.entries.append(Entry(name=cells[0], where=where, length=cells[1], mu=cells[2],
                                     quantity=cells[3],
                                     value=cells[4] if len(cells) > 4 else None))
        elif len(cells) == 3 and not re.search(r"\d", cells[2]):
            sub.entries.append(Entry(name=cells[0], where=where, text=f"{cells[1]} {cells[2]}"))
        elif len(cells) == 3:
            sub.entries.append(Entry(name=cells[0], where=where, length=cells[1], value=cells[2]))
        else:
            sub.entries.append(Entry(name=cells[0], where=where, text=cells[1]))
    if not sub.entries:
        raise CheckError(T("error.csv_empty"), file=str(path))
    return within_limits(sub)


def within_limits(sub: Submission) -> Submission:
    """The table ``sub``, refused when it holds more than
    :data:`~mechplan.limits.TABLE_MAX_ROWS` values (grading costs grow with them)."""
    if len(sub.entries) > TABLE_MAX_ROWS:
        raise CheckError(Text("readers.error.table_rows", {"limit": TABLE_MAX_ROWS}),
                         file=sub.path)
    return sub


class _Semicolon(csv.excel):
    delimiter = ";"


def _sniff(sample: str) -> Any:
    try:
        return csv.Sniffer().sniff(sample, delimiters=",;\t|")
    except csv.Error:
        return _Semicolon if sample.count(";") > sample.count(",") else csv.excel


def _header(cells: list[str]) -> dict[str, int] | None:
    found: dict[str, int] = {}
    for i, cell in enumerate(cells):
        low = cell.lower().strip()
        for col, names in _COLUMNS.items():
            if low in names and col not in found:
                found[col] = i
    if len(found) >= 2 or (found and not any(re.search(r"\d", c) for c in cells)):
        return found
    return None


def load_toml(path: Path) -> tuple[dict[str, Any], Callable[[str], str]]:
    """A TOML table and the function giving where a key is written (its line, or its name)."""
    text = _read_text(path)
    try:
        data = toml.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CheckError(T("error.toml", detail=str(exc)), file=str(path)) from None
    except toml.TomlLimitError as exc:
        raise CheckError(T(f"error.limit_{exc.kind}", **exc.args_), file=str(path),
                         key=exc.key) from None
    if _nesting(data) > TABLE_MAX_NESTING:
        raise CheckError(Text("readers.error.nesting", {"limit": TABLE_MAX_NESTING}),
                         file=str(path))
    lines = text.splitlines()

    def where(key: str) -> str:
        pat = re.compile(r"^\s*[\"']?" + re.escape(key) + r"[\"']?\s*=")
        n = next((i for i, ln in enumerate(lines, start=1) if pat.match(ln)), None)
        return T("where.key", file=path.name, key=key) if n is None else T(
            "where.line", file=path.name, n=n)
    return data, where


def _nesting(data: Any) -> int:
    """How deep tables and arrays are nested in parsed TOML (counted without recursion)."""
    deepest, stack = 0, [(data, 1)]
    while stack:
        item, depth = stack.pop()
        deepest = max(deepest, depth)
        if isinstance(item, dict):
            stack.extend((v, depth + 1) for v in item.values() if isinstance(v, (dict, list)))
        elif isinstance(item, list):
            stack.extend((v, depth + 1) for v in item if isinstance(v, (dict, list)))
    return deepest


def csv_rows(path: Path, dialect: Callable[[str], Any]) -> list[list[str]]:
    """The rows of a CSV file, its dialect chosen by ``dialect(first 20 lines)``; a table of more
    than :data:`~mechplan.limits.TABLE_MAX_ROWS` rows, or with a cell over
    :data:`~mechplan.limits.CSV_CELL_MAX_CHARS` characters, is refused naming the line. An Excel
    workbook's rows are its active sheet's (:mod:`.xlsx`), read the same way."""
    from .xlsx import SUFFIXES, xlsx_rows

    if path.suffix.lower() in SUFFIXES:
        return xlsx_rows(path)
    text = _read_text(path)
    if "\x00" in text:
        raise CheckError(T("error.binary"), file=str(path))
    reader = csv.reader(io.StringIO(text), dialect("\n".join(text.splitlines()[:20])))
    rows: list[list[str]] = []
    try:
        for row in reader:
            if max(map(len, row), default=0) > CSV_CELL_MAX_CHARS:
                raise _cell_too_long(path, reader.line_num)
            rows.append(row)
            if len(rows) > TABLE_MAX_ROWS:
                raise CheckError(Text("readers.error.table_rows", {"limit": TABLE_MAX_ROWS}),
                                 file=str(path))
    except csv.Error as exc:
        if "field larger than field limit" in str(exc):     # the csv module's own limit
            raise _cell_too_long(path, reader.line_num) from None
        raise CheckError(T("error.csv", detail=str(exc)), file=str(path),
                         key=f"line {reader.line_num}") from None
    return rows


def _cell_too_long(path: Path, line: int) -> CheckError:
    return CheckError(Text("readers.error.csv_cell", {"limit": CSV_CELL_MAX_CHARS}),
                      file=str(path), key=f"line {line}")


def _read_text(path: Path) -> str:
    data = read_bytes(path, TABLE, error=CheckError)
    for enc in ("utf-8-sig", "cp1251", "latin-1"):
        try:
            return data.decode(enc)
        except UnicodeDecodeError:
            continue
    return data.decode("latin-1", errors="replace")
