"""CSV cells a spreadsheet reads as text, never as a formula (OWASP, "CSV Injection").

A text cell starting with ``=``, ``+``, ``-``, ``@``, a tab or a carriage return (student names,
file names, error messages) gets a leading apostrophe, which spreadsheets show as text. Numbers
stay numbers: a number cell, or a text cell that is a plain decimal number ("-1.5", "2e-3"), is
written as it is. Every CSV writer of batch/ (class summaries, class check reports, sweeps) writes
its cells through here.
"""

from __future__ import annotations

import re
from typing import Any

#: the first characters a spreadsheet may start a formula with (OWASP)
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_PLAIN_NUMBER = re.compile(r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?")


def csv_safe(value: Any) -> Any:
    """A cell value to write: a text starting like a formula is prefixed with an apostrophe."""
    if isinstance(value, str) and value.startswith(FORMULA_START) and not _PLAIN_NUMBER.fullmatch(
            value):
        return "'" + value
    return value


def csv_safe_row(row: dict[str, Any]) -> dict[str, Any]:
    """A row of a ``csv.DictWriter`` with every cell made safe."""
    return {k: csv_safe(v) for k, v in row.items()}


def csv_safe_table(table: Any) -> Any:
    """A pyarrow table with every text column made safe (other columns untouched)."""
    import pyarrow as pa

    for i, field in enumerate(table.schema):
        if pa.types.is_string(field.type) or pa.types.is_large_string(field.type):
            column = table.column(i).to_pylist()
            if any(isinstance(v, str) and v.startswith(FORMULA_START) for v in column):
                table = table.set_column(i, field, pa.array([csv_safe(v) for v in column],
                                                            type=field.type))
    return table
