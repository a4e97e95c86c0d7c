"""Answer tables handed in as Excel workbooks (``.xlsx``, ``.xlsm``): the rows of the workbook's
active sheet as text cells, read exactly as the rows of a CSV table (same headers, notations,
decimal commas in text cells, limits on rows and cells).

A workbook is a zip: its parts are checked against the limits of every file read inside another
(:mod:`.contained`) before openpyxl sees them, and a part declaring a DTD (no spreadsheet program
writes one; entity expansion is how XML bombs work) refuses the workbook."""

from __future__ import annotations

import datetime as dt
import io
import re
import warnings
from pathlib import Path
from typing import Any

from ..errors import CheckError
from ..i18n import Text
from ..limits import CSV_CELL_MAX_CHARS, TABLE_MAX_BYTES, TABLE_MAX_ROWS
from ..userfiles import FileKind, read_bytes
from .contained import zip_members

#: the suffixes read as workbooks
SUFFIXES = (".xlsx", ".xlsm")
#: columns read of a row (an answer table has a handful; a stray cell far right is not read)
MAX_COLUMNS = 64
#: a workbook is a zip of XML: its file may be as large as a table's text
WORKBOOK = FileKind("table", TABLE_MAX_BYTES)
_DTD = re.compile(rb"<!DOCTYPE|<!ENTITY", re.IGNORECASE)


def cell_text(value: Any) -> str:
    """A cell as the text a CSV would hold: a number as it is stored, a date in ISO form,
    nothing for an empty cell."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return repr(value)           # the stored double, shortest exact form ("6.7", "1e-07")
    if isinstance(value, dt.datetime | dt.date | dt.time):
        return value.isoformat()
    return str(value)


def xlsx_rows(path: Path) -> list[list[str]]:
    """The rows of the active sheet of a workbook (of the first sheet holding anything when the
    active one is empty), each cell as text; refuse a workbook over the limits."""
    data = read_bytes(path, WORKBOOK, error=CheckError)
    for name, body in zip_members(data, str(path)):
        if name.lower().endswith((".xml", ".rels", ".vml")) and _DTD.search(body):
            raise CheckError(Text("lms2.xlsx_dtd", {"entry": name}), file=str(path))
    from openpyxl import load_workbook
    from openpyxl.utils.exceptions import InvalidFileException

    try:
        with warnings.catch_warnings():     # "no default style", "data validation" … of a file
            warnings.simplefilter("ignore")
            book = load_workbook(io.BytesIO(data), read_only=True, data_only=True)
    # what openpyxl raises on a file that is a zip but not a workbook, or a damaged part
    except (InvalidFileException, KeyError, ValueError, TypeError, IndexError, AttributeError,
            OSError, SyntaxError) as exc:
        raise CheckError(Text("lms2.xlsx_bad", {"reason": str(exc)[:160]}),
                         file=str(path)) from None
    try:
        sheets = [book.active, *book.worksheets]
        for sheet in sheets:
            rows = _rows(sheet, path) if sheet is not None else []
            if any(any(c for c in r) for r in rows):
                return rows
        return []
    finally:
        book.close()


def _rows(sheet: Any, path: Path) -> list[list[str]]:
    rows: list[list[str]] = []
    try:
        for n, row in enumerate(sheet.iter_rows(max_col=MAX_COLUMNS, values_only=True),
                                start=1):
            cells = [cell_text(v) for v in row]
            if max(map(len, cells), default=0) > CSV_CELL_MAX_CHARS:
                raise CheckError(Text("readers.error.csv_cell", {"limit": CSV_CELL_MAX_CHARS}),
                                 file=str(path), key=f"line {n}")
            while cells and not cells[-1]:
                cells.pop()
            rows.append(cells)
            if len(rows) > TABLE_MAX_ROWS:
                raise CheckError(Text("readers.error.table_rows", {"limit": TABLE_MAX_ROWS}),
                                 file=str(path))
    except (KeyError, ValueError, TypeError, IndexError, AttributeError, SyntaxError) as exc:
        raise CheckError(Text("lms2.xlsx_bad", {"reason": str(exc)[:160]}),
                         file=str(path)) from None
    while rows and not rows[-1]:
        rows.pop()
    return rows
