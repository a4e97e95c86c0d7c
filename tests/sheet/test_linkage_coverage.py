"""No wasted sheets on the linkage sheets (issue 28, item 7): a plan's tables set apart flow by
rows into the free room a sheet leaves, and they never come before their plan.

Coverage is computed here with shapely from the laid-out panels (each panel's box moved to its
place, clipped to the drawing area, their union measured), not from a number the layout
reports about itself.
"""

from __future__ import annotations

import re

import pytest
from framed_sets import covered, framed_sets
from scenes import ROOT

from mechplan.drafting.primitives import Table, Text
from mechplan.sheet.layout import GOAL
from mechplan.sheet.panels import TABLE_H, Panel
from mechplan.sheet.table_rows import MIN_ROWS, splittable
from mechplan.studies import solve_file


# full A4 sheets at 46–54 % on main (a plan alone on a sheet, its tables on the next; a table
# part alone; a cycle's legend on a sheet of its own): with the tables' rows flowing into the
# room the plans leave (and the legend rewrapped into it), every full sheet of these sets reaches
# the goal
@pytest.mark.parametrize("stem", ["slider_crank", "shaper", "five_bar_two_cranks",
                                  "slider_coulisse", "machine_course"])
def test_every_full_a4_sheet_of_these_sets_reaches_the_goal(stem, monkeypatch):
    for placements, area in framed_sets(_study(stem), stem, "A4", monkeypatch):
        full = [covered(p, area) for p in placements[:-1]]
        assert full and all(c >= GOAL for c in full), [round(c, 3) for c in full]


@pytest.mark.parametrize("stem", ["six_bar_triad", "shaper_flywheel", "v_engine", "four_bar"])
def test_a_plans_tables_never_come_before_the_plan(stem, monkeypatch):
    """Reading order: the tables of a plan set apart (or their first rows) are on the sheet of
    the plan or a later one, in order of their parts."""
    seen = 0
    for placements, _area in framed_sets(_study(stem), stem, "A4", monkeypatch):
        sheet_of: dict[str, int] = {}
        parts: dict[str, list[str]] = {}
        for i, placed in enumerate(placements):
            for panel, _ in placed:
                sheet_of[panel.name] = i
                m = re.match(r"(.*)-tables([-.]\d+)*$", panel.name)
                if m:
                    parts.setdefault(m.group(1), []).append(panel.name)
        seen += len(parts)
        for plan, names in parts.items():
            if plan in sheet_of:                # a velocity plan of the grid: its cell
                assert all(sheet_of[n] >= sheet_of[plan] for n in names), (plan, names)
            assert [sheet_of[n] for n in names] == sorted(sheet_of[n] for n in names)
    assert seen                                 # (a dynamics set has no plan tables)


def _tables(rows_per_table: list[int]) -> list:
    """Captions and tables as a plan panel draws them (one under the other)."""
    prims: list = []
    y = 0.0
    for t, n in enumerate(rows_per_table):
        prims.append(Text((0.0, y - TABLE_H), f"eq {t}", TABLE_H))
        y -= TABLE_H + 2.5
        cells = [("term", "dir", "value")] + [(f"r{t}.{i}", "⊥ AB", f"{i}.5") for i in range(n)]
        prims.append(Table((0.0, y), (20.0, 15.0, 15.0), tuple(5.0 for _ in cells),
                           tuple(cells), TABLE_H))
        y -= 5.0 * len(cells) + 4.0
    return prims


def _rows(panels: list[Panel]) -> list[tuple[str, ...]]:
    return [r for p in panels for t in p.primitives if isinstance(t, Table) for r in t.cells[1:]]


def test_tables_split_by_rows_into_a_room_keep_every_row_once_and_the_heading():
    prims = _tables([4, 12, 3])
    panel = splittable(prims, "acceleration-1-tables", "Plan of accelerations")
    x0, _y0, x1, _y1 = panel.bounds()
    rows = _rows([panel])
    assert len(rows) == 19
    # a room for the first table and part of the second
    room_h = 90.0
    parts = panel.split_off(x1 - x0 + 1.0, room_h)
    assert len(parts) == 2 and parts[1].split_off is not None
    first = parts[0].bounds()
    assert first[3] - first[1] <= room_h + 1e-9                  # it fits the room
    tables = [t for t in parts[0].primitives if isinstance(t, Table)]
    assert len(tables) == 2 and MIN_ROWS <= len(tables[1].cells) - 1 <= 12 - MIN_ROWS
    assert _rows(parts) == rows                                   # every row once, in order
    heads = [t.cells[0] for p in parts for t in p.primitives if isinstance(t, Table)]
    assert all(h == ("term", "dir", "value") for h in heads)      # the heading repeated
    captions = [t.string for p in parts for t in p.primitives
                if isinstance(t, Text) and t.height_mm == TABLE_H]
    assert captions == ["eq 0", "eq 1", "eq 2"]                   # a caption once, with its rows
    assert all(any(isinstance(t, Text) and t.string == "Plan of accelerations"
                   for t in p.primitives) for p in parts)         # each part under the title
    # the rest split again, and all of it in parts no taller than a room
    again = parts[1].refit(x1 - x0 + 1.0, 40.0)
    assert _rows([parts[0], *again]) == rows
    assert all(p.bounds()[3] - p.bounds()[1] <= 40.0 + 1e-9 for p in again)


def test_tables_too_small_to_cut_stay_whole():
    panel = splittable(_tables([3]), "velocity-1-tables", "Plan of velocities")
    assert panel.split_off is None                  # 3 rows: no cut leaves two on each side
    x0, _y0, x1, _y1 = splittable(_tables([3, 3]), "t", "T").bounds()
    whole = splittable(_tables([3, 3]), "t", "T").split_off(x1 - x0, 10.0)
    assert len(whole) == 1                          # nothing fits 10 mm: the layout looks on


def _study(stem: str):
    return solve_file(str(ROOT / "templates" / f"{stem}.toml"))
