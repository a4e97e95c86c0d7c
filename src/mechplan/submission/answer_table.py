"""Read an answer table (TOML or CSV) of a dynamics, engine, cam or gear study.

Nothing here knows the study: the reader returns ``name = text`` items with the angle of their row
(when the table has rows per angle) and the section they stand in. Accepted forms:

* TOML: top-level ``name = "value unit"`` (or a number, or ``{ value = …, unit = … }``); a section
  named by an angle (``["φ = 30°"]``, ``["30°"]``) holds that angle's values; any other section
  name is kept (``[pair]``, ``["зацепление"]``); an array of tables (``[[rows]]``) holds one row per
  angle, the angle under its own name (``φ = "30°"``).
* CSV: ``name, value[, unit]`` rows; or a wide table whose header names the angle first and then
  the quantities (``φ; p; Pг; Pj; P; N; T; Z; Mкр``), one row per angle. Units may follow a name in
  the header (``T, Н`` as ``T [N]`` or ``T (N)``). A decimal comma is accepted.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path
from typing import Any

from ..errors import CheckError
from .read import Entry, Note, Submission, csv_rows, load_toml, submitted_file, within_limits
from .texts import T

_ANGLE_TEXT = re.compile(r"^\s*(?:([^\d\s=:+−-][^=:]*?)\s*[=:]\s*)?([-+−]?\d+(?:[.,]\d+)?)\s*"
                         r"(?:°|deg|град|độ|度)?\s*$")
_UNIT_IN_NAME = re.compile(r"^(.*?)\s*[\[(]\s*([^\])]+?)\s*[\])]\s*$")


def angle_of(text: str, is_angle_name: Any) -> float | None:
    """The angle in degrees a section title or cell names ("φ = 30°", "30°", "30"), or None."""
    m = _ANGLE_TEXT.match(str(text))
    if not m:
        return None
    if m.group(1) is not None and not is_angle_name(m.group(1)):
        return None
    return float(m.group(2).replace(",", ".").replace("−", "-"))


def read_answers(path: str | Path, is_angle_name: Any) -> Submission:
    """Read a TOML or CSV answer table; ``is_angle_name(name)`` tells an angle column or key."""
    p = submitted_file(path)
    suffix = p.suffix.lower()
    if suffix == ".toml":
        table = _read_toml(p, is_angle_name)
    elif suffix in (".csv", ".tsv", ".txt", ".xlsx", ".xlsm"):   # a workbook: its rows as CSV's
        table = _read_csv(p, is_angle_name)
    else:
        raise CheckError(T("error.kind", suffix=p.suffix or "—"), file=str(p))
    if not table.entries:
        raise CheckError(T("answers.empty"), file=str(p))
    return within_limits(table)


def _value_text(value: Any) -> str | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, (int, float, str)):
        return str(value)
    if isinstance(value, dict) and "value" in value:
        unit = value.get("unit")
        return f"{value['value']} {unit}" if unit else str(value["value"])
    return None


def _read_toml(path: Path, is_angle_name: Any) -> Submission:
    data, where = load_toml(path)
    out = Submission(str(path), "table")

    def put(key: str, value: Any, phi: float | None, section: str | None, at: str) -> None:
        text_ = _value_text(value)
        if text_ is None:
            out.notes.append(Note("error", T("note.cannot_use", value=repr(value)), at))
        else:
            out.entries.append(Entry(key, at, text=text_, phi_deg=phi, section=section))

    def rows(key: str, table: list[dict[str, Any]], section: str | None) -> None:
        for i, row in enumerate(table, start=1):
            at = T("where.row", where=where(key), n=i)
            phi = next((angle_of(str(v), lambda _: True) for k, v in row.items()
                        if is_angle_name(k)), None)
            for k, v in row.items():
                if not is_angle_name(k):
                    put(k, v, phi, section, at)

    def walk(table: dict[str, Any], phi: float | None, section: str | None) -> None:
        for key, value in table.items():
            if isinstance(value, dict) and "value" not in value:
                angle = angle_of(key, is_angle_name)
                if angle is not None:
                    walk(value, angle, section)
                else:
                    walk(value, phi, key if section is None else f"{section} {key}")
            elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
                rows(key, value, section)
            elif is_angle_name(key) and phi is None and section is None:
                continue            # the angle of a whole table is not an answer
            else:
                put(key, value, phi, section, where(key))

    walk(data, None, None)
    return out


def _dialect(sample: str) -> type[csv.Dialect]:
    """";" when the sample has about as many as ",", else a tab or ","."""
    delimiter = ";" if sample.count(";") >= max(1, sample.count(",") // 2) else (
        "\t" if "\t" in sample else ",")
    return type("Dialect", (csv.excel,), {"delimiter": delimiter})


def _read_csv(path: Path, is_angle_name: Any) -> Submission:
    rows = csv_rows(path, _dialect)
    out = Submission(str(path), "table")
    header: list[tuple[str, str]] | None = None
    for n, row in enumerate(rows, start=1):
        cells = [c.strip() for c in row]
        if not any(cells) or cells[0].startswith("#"):
            continue
        at = T("where.line", file=path.name, n=n)
        if header is None and is_angle_name(_UNIT_IN_NAME.sub(r"\1", cells[0])):
            header = []
            for c in cells:
                m = _UNIT_IN_NAME.match(c)
                header.append((m.group(1), m.group(2)) if m else (c, ""))
            continue
        if header is not None:
            phi = angle_of(cells[0], lambda _: True)
            if phi is None:
                out.notes.append(Note("error", T("answers.no_angle", row=";".join(cells)), at))
                continue
            for (name, unit), cell in zip(header[1:], cells[1:]):
                if name and cell:
                    out.entries.append(Entry(name, at, text=f"{cell} {unit}".strip(), phi_deg=phi))
            continue
        cells = [c for c in cells if c]
        if len(cells) == 1 and "=" in cells[0]:
            name, _, value = cells[0].partition("=")
            cells = [name.strip(), value.strip()]
        if len(cells) < 2 or not re.search(r"\d", cells[1]):
            if n == 1:
                continue            # a header "name, value, unit"
            out.notes.append(Note("error", T("note.expected_name_value", row=repr(",".join(row))),
                                  at))
            continue
        value = cells[1] if len(cells) == 2 or re.search(r"\d", cells[2]) else (
            f"{cells[1]} {cells[2]}")
        phi = angle_of(cells[3], lambda _: True) if len(cells) > 3 else None
        out.entries.append(Entry(cells[0], at, text=value, phi_deg=phi))
    return out
