"""Canvas's exported gradebook filled in place: the assignment's column gets the grades of the
students matched, and every other byte — the other columns and rows, the "Points Possible" and
"Muted" rows, quoting, the byte-order mark, the line ends — stays as Canvas wrote it, so that
*Grades → Import* takes the file back and changes only that column.

The CSV is scanned by hand (RFC 4180: fields, quotes, doubled quotes, line breaks inside quotes)
keeping where each field stands, so only the cells written are touched."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import CheckError
from ..i18n import Text, significant
from ..userfiles import TABLE, read_bytes
from .roster import decode, norm
from .sheets import CANVAS_COLUMNS, grade_text

#: the rows Canvas writes under the header that are no student (their first cell, stripped)
SPECIAL_ROWS = ("points possible", "muted")


@dataclass
class Record:
    """One row of the CSV: each field's text and where it stands in the file's text."""

    cells: list[str]
    spans: list[tuple[int, int]]
    quoted: list[bool]


def scan(text: str, delimiter: str = ",") -> list[Record]:
    """The records of a CSV text with the span of every field (quotes included)."""
    out: list[Record] = []
    i, n = 0, len(text)
    while i < n:
        rec = Record([], [], [])
        while True:
            start = i
            if i < n and text[i] == '"':
                i += 1
                buf = []
                while i < n:
                    if text[i] == '"':
                        if i + 1 < n and text[i + 1] == '"':
                            buf.append('"')
                            i += 2
                            continue
                        i += 1
                        break
                    buf.append(text[i])
                    i += 1
                while i < n and text[i] not in (delimiter, "\r", "\n"):   # "a"b: kept as is
                    buf.append(text[i])
                    i += 1
                rec.cells.append("".join(buf))
                rec.quoted.append(True)
            else:
                while i < n and text[i] not in (delimiter, "\r", "\n"):
                    i += 1
                rec.cells.append(text[start:i])
                rec.quoted.append(False)
            rec.spans.append((start, i))
            if i < n and text[i] == delimiter:
                i += 1
                continue
            if i < n and text[i] == "\r":
                i += 1
            if i < n and text[i] == "\n":
                i += 1
            break
        if rec.cells != [""] or rec.spans[0][0] < rec.spans[0][1]:
            out.append(rec)
    return out


@dataclass
class Gradebook:
    """A Canvas gradebook as exported: its text, how it was written, its records."""

    path: str
    text: str
    encoding: str
    delimiter: str
    records: list[Record] = field(default_factory=list)

    @property
    def header(self) -> list[str]:
        """The column names."""
        return self.records[0].cells if self.records else []


def read_gradebook(path: Path) -> Gradebook:
    """Read Canvas's gradebook export; refuse a file without Canvas's student columns."""
    text, encoding = decode(read_bytes(path, TABLE, error=CheckError))
    first = text.split("\n", 1)[0]
    delimiter = ";" if first.count(";") > first.count(",") else ","
    book = Gradebook(str(path), text, encoding, delimiter, scan(text, delimiter))
    if not book.records or not {"Student", "ID"} <= {c.strip() for c in book.header}:
        raise CheckError(Text("lms2.not_gradebook", {"columns": ", ".join(CANVAS_COLUMNS)}),
                         file=str(path))
    return book


def assignment_column(book: Gradebook, name: str, ident: str) -> int:
    """The assignment's column: ``<name> (<id>)`` by its id, else by its name."""
    header = [c.strip() for c in book.header]
    if ident:
        hits = [i for i, c in enumerate(header) if c.endswith(f"({ident})")]
    else:
        hits = [i for i, c in enumerate(header) if c == name]
        if not hits:
            hits = [i for i, c in enumerate(header)
                    if re.fullmatch(re.escape(name) + r"\s*\(\d+\)", c)]
    if len(hits) != 1:
        shown = f"{name} ({ident})" if ident else name
        found = ", ".join(c for c in header[len(CANVAS_COLUMNS):] if c)[:400] or "—"
        raise CheckError(Text("lms2.no_assignment", {"assignment": shown, "columns": found}),
                         file=book.path)
    return hits[0]


@dataclass
class Graded:
    """A student to write: what may match a row (Canvas user id, SIS ids, name) and the grade."""

    who: str
    grade: float | None
    ids: tuple[str, ...] = ()            # Canvas user ids (the "ID" column)
    sis: tuple[str, ...] = ()            # SIS User ID
    logins: tuple[str, ...] = ()         # SIS Login ID
    names: tuple[str, ...] = ()


def _name_key(text: str) -> tuple[str, ...]:
    return tuple(sorted(norm(text.replace(",", " ")).split()))


def _quote(text: str, delimiter: str, quoted: bool) -> str:
    if quoted or any(c in text for c in (delimiter, '"', "\r", "\n")):
        return '"' + text.replace('"', '""') + '"'
    return text


def fill_gradebook(book: Gradebook, graded: Iterable[Graded], column: int, max_grade: float,
                   decimals: int) -> tuple[bytes, list[str], float | None]:
    """The gradebook's bytes with the assignment's cells of the matched students written (a
    student without a grade leaves the cell as it was); also who was not found in it, and the
    column's Points Possible when the grades were scaled to it from ``max_grade``."""
    header = [c.strip() for c in book.header]
    col = {name: header.index(name) for name in CANVAS_COLUMNS if name in header}
    rows = book.records[1:]
    possible: float | None = None
    students: list[Record] = []
    for r in rows:
        first = r.cells[0].strip().casefold() if r.cells else ""
        if first in SPECIAL_ROWS:
            if first == "points possible" and len(r.cells) > column:
                possible = _number(r.cells[column])
            continue
        students.append(r)

    def cell(r: Record, name: str) -> str:
        i = col.get(name)
        return r.cells[i].strip() if i is not None and i < len(r.cells) else ""

    scale = possible / max_grade if possible and max_grade and possible != max_grade else 1.0
    edits: list[tuple[int, int, str]] = []
    missing: list[str] = []
    for g in graded:
        hit = None
        for name, keys in (("ID", g.ids), ("SIS User ID", g.sis), ("SIS Login ID", g.logins)):
            found = [r for r in students if keys and cell(r, name) and cell(r, name) in keys]
            if len(found) == 1:
                hit = found[0]
                break
        if hit is None and g.names:
            names = {_name_key(n) for n in g.names}
            found = [r for r in students if _name_key(cell(r, "Student")) in names]
            hit = found[0] if len(found) == 1 else None
        if hit is None:
            missing.append(g.who)
            continue
        if g.grade is None or column >= len(hit.cells):
            continue
        start, end = hit.spans[column]
        value = grade_text(round(g.grade * scale, max(decimals, 2)) if scale != 1.0 else g.grade,
                           max(decimals, 2) if scale != 1.0 else decimals)
        edits.append((start, end, _quote(value, book.delimiter, hit.quoted[column])))
    text = book.text
    for start, end, new in sorted(edits, reverse=True):
        text = text[:start] + new + text[end:]
    data = text.encode(book.encoding, errors="replace")
    return data, missing, possible if scale != 1.0 else None


def _number(text: str) -> float | None:
    try:
        return float(text.strip().replace(",", "."))
    except ValueError:
        return None


def scaled_note(possible: float, max_grade: float, lang: str) -> Text:
    """The problem line saying the grades were scaled to the column's Points Possible."""
    return Text("lms2.gradebook_scaled", {"possible": significant(possible, 6, lang),
                                          "max": significant(max_grade, 6, lang)})
