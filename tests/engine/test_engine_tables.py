"""The per-angle table of each cylinder prints the load on that cylinder's own crank pin.

An in-line 4 printed crank-pin 1's Q in every cylinder's table (16.237 kN for cylinder 2 at φ = 0
where the JSON had 11.551 kN for pin 2). Independent value: each cylinder of an in-line 4 is the
single-cylinder engine turned by its firing delay (firing order 1-3-4-2 of a four-stroke: cylinder
3 fires 180° after cylinder 1, cylinder 4 360°, cylinder 2 540°), so its pin load at φ is the
single cylinder's at φ − delay.
"""

from __future__ import annotations

import pytest
from helpers import moto

from mechplan.sheet.engine import table_cells, table_panels
from mechplan.sheet.primitives import Table
from mechplan.studies import solve_text

INLINE4 = 'layout = "inline"\ncylinders = 4\nfiring_order = [1, 3, 4, 2]\ntable_step = "15 deg"'
DELAY_DEG = {1: 0.0, 3: 180.0, 4: 360.0, 2: 540.0}


def _Q_column(rows: list[list[str]], language: str = "en") -> dict[float, float]:
    """φ (deg) → the table's last column (kN), read back from the printed cells."""
    mark = "," if language in ("ru", "vi") else "."
    return {float(r[0].replace(mark, ".")): float(r[-1].replace(mark, ".")) for r in rows[1:]}


@pytest.fixture(scope="module")
def engines():
    return (solve_text(moto(INLINE4), "inline4.toml"),
            solve_text(moto('table_step = "15 deg"'), "single.toml"))


def test_each_cylinder_table_prints_its_own_pin_load(engines):
    four, single = engines
    doc = four.to_json()
    one = {round(a["phi_deg"], 6): a["pins"]["1"]["Q"] for a in single.to_json()["angles"]}
    for cyl in (1, 2, 3, 4):
        printed = _Q_column(table_cells(four.table, "en", cyl))
        for a in doc["angles"]:
            phi = round(a["phi_deg"], 6)
            # against the JSON's load on this cylinder's pin (one cylinder per pin in-line) …
            assert printed[phi] == pytest.approx(a["pins"][str(cyl)]["Q"] * 1e-3, abs=5e-4)
            # … and against the single-cylinder engine turned by the firing delay
            local = round((phi - DELAY_DEG[cyl]) % 720.0, 6)
            assert printed[phi] == pytest.approx(one[local] * 1e-3, abs=5e-4), (cyl, phi)
    # the case of the issue: cylinder 2 at φ = 0 is not pin 1's load
    first = _Q_column(table_cells(four.table, "en", 1))
    second = _Q_column(table_cells(four.table, "en", 2))
    assert abs(second[0.0] - first[0.0]) > 1.0


def test_report_and_sheet_tables_name_the_pin(engines):
    four, _ = engines
    heads = [t.cells[0][-1] for p in table_panels(four, "ru") for t in p.primitives
             if isinstance(t, Table)]
    assert heads == ["Q (шейка 1), кН", "Q (шейка 2), кН", "Q (шейка 3), кН", "Q (шейка 4), кН"]
    report = four.report("en")
    blocks = report.split("Q (pin ")[1:]
    assert [b[0] for b in blocks] == ["1", "2", "3", "4"]
    # the report's cylinder-2 table: φ = 0 row ends with pin 2's Q
    doc = four.to_json()
    q2 = doc["angles"][0]["pins"]["2"]["Q"] * 1e-3
    row0 = blocks[1].splitlines()[1].split()
    assert float(row0[0]) == 0.0 and float(row0[-1]) == pytest.approx(q2, abs=5e-4)
