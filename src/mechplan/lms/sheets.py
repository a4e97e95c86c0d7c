"""Grade files the LMS imports back: Moodle's offline grading worksheet (filled in place: same
columns, order, header, identifiers, encoding, delimiter and line ends) and a Canvas gradebook
CSV."""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..errors import CheckError
from ..i18n import trimmed
from ..userfiles import TABLE, read_bytes
from .roster import decode
from .texts import say

MOODLE_COLUMNS = ("Identifier", "Full name", "Email address", "Status", "Grade", "Maximum Grade",
                  "Grade can be changed", "Last modified (submission)", "Last modified (grade)",
                  "Feedback comments")
CANVAS_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")


@dataclass
class Filled:
    """What goes into one student's row."""

    participant_id: str
    name: str
    email: str
    grade: float | None
    comment: str


@dataclass
class Worksheet:
    """A Moodle grading worksheet as read: its rows and how it was written."""

    header: list[str]
    rows: list[list[str]]
    encoding: str = "utf-8"
    delimiter: str = ","
    newline: str = "\n"


def read_worksheet(path: Path) -> Worksheet:
    """Read a worksheet Moodle exported; refuse one without Moodle's columns."""
    text, encoding = decode(read_bytes(path, TABLE, error=CheckError))
    newline = "\r\n" if "\r\n" in text[:4096] else "\n"
    first = text.split("\n", 1)[0]
    delimiter = ";" if first.count(";") > first.count(",") else ","
    table = list(csv.reader(io.StringIO(text, newline=""), delimiter=delimiter))
    if not table or not {"Identifier", "Grade", "Feedback comments"} <= set(table[0]):
        raise CheckError(say("not_worksheet", columns=", ".join(MOODLE_COLUMNS)), file=str(path))
    return Worksheet(table[0], [r for r in table[1:] if r], encoding, delimiter, newline)


def new_worksheet(max_grade: float) -> Worksheet:
    """An empty worksheet in Moodle's own layout (when the instructor gave none)."""
    return Worksheet(list(MOODLE_COLUMNS), [])


def grade_text(grade: float | None, decimals: int) -> str:
    """A grade as Moodle reads it (a point, no thousands separator); "" when none."""
    return "" if grade is None else trimmed(grade, decimals, "en")


def fill_worksheet(sheet: Worksheet, filled: Iterable[Filled], max_grade: float,
                   decimals: int) -> tuple[bytes, list[str]]:
    """The worksheet's bytes with Grade and Feedback comments filled; also the participants
    the worksheet lacks (a new worksheet gets a row for each)."""
    col = {name: i for i, name in enumerate(sheet.header)}
    rows = [list(r) + [""] * (len(sheet.header) - len(r)) for r in sheet.rows]
    by_id = {r[col["Identifier"]].split()[-1] if r[col["Identifier"]].split() else "": r
             for r in rows}
    missing: list[str] = []
    for f in filled:
        row = by_id.get(f.participant_id)
        if row is None:
            if sheet.rows:
                missing.append(f.name)
                continue
            row = [""] * len(sheet.header)
            row[col["Identifier"]] = f"Participant {f.participant_id}"
            for name, value in (("Full name", f.name), ("Email address", f.email),
                                ("Maximum Grade", grade_text(max_grade, decimals)),
                                ("Grade can be changed", "Yes")):
                if name in col:
                    row[col[name]] = value
            rows.append(row)
        row[col["Grade"]] = grade_text(f.grade, decimals)
        row[col["Feedback comments"]] = f.comment
    buf = io.StringIO(newline="")
    writer = csv.writer(buf, delimiter=sheet.delimiter, quoting=csv.QUOTE_ALL,
                        lineterminator=sheet.newline)
    writer.writerow(sheet.header)
    writer.writerows(rows)
    # the worksheet's own encoding; a character it cannot hold (a re-saved cp1251 sheet and a
    # Vietnamese file name in a comment) becomes "?" rather than failing the class
    return buf.getvalue().encode(sheet.encoding, errors="replace"), missing


@dataclass
class CanvasRow:
    """One student of a Canvas gradebook."""

    name: str
    id: str
    sis_id: str
    login: str
    section: str
    grade: float | None


def canvas_gradebook(rows: Iterable[CanvasRow], column: str, max_grade: float,
                     decimals: int) -> bytes:
    """A Canvas gradebook CSV: the five student columns, the assignment column, the "Points
    Possible" row Canvas writes, a student per row (a grade cell left empty: not graded)."""
    from ..batch.csvsafe import csv_safe_row

    buf = io.StringIO(newline="")
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow([*CANVAS_COLUMNS, column])
    writer.writerow(["    Points Possible", "", "", "", "", grade_text(max_grade, decimals)])
    for r in rows:
        cells = {"a": r.name, "b": r.id, "c": r.sis_id, "d": r.login, "e": r.section}
        safe = csv_safe_row(cells)
        writer.writerow([safe[k] for k in "abcde"] + [grade_text(r.grade, decimals)])
    return buf.getvalue().encode("utf-8")
