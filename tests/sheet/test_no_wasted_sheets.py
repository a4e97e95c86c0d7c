"""No wasted sheets: no panel on a later sheet of a set would have fitted the free room an earlier
sheet of the set leaves (checked on a 1 mm raster of the drawing area, independently of the
packer), so no set uses a sheet more than it needs; and the packer's spots are exact."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
import shapely
from framed_sets import framed_sets
from scenes import ALL_TEMPLATES
from shapely import box

from mechplan.drafting.primitives import Line
from mechplan.sheet.layout import GAP, Sheetful, chain, paginate, sequence
from mechplan.sheet.panels import Panel
from mechplan.studies import solve_file

SIZES = ("A4", "A3", "A2", "A1", "A0")


@functools.cache
def _study(path):
    return solve_file(str(path))




class Raster:
    """The free room of a sheet on a 1 mm grid: a cell is free when it lies in the drawing area
    and off every placed panel's box grown by half the gap."""

    def __init__(self, area, placed) -> None:
        x0, y0, x1, y1 = area.bounds
        self.x0, self.y0 = x0, y0
        nx, ny = math.ceil(x1 - x0), math.ceil(y1 - y0)
        gx, gy = np.meshgrid(x0 + np.arange(nx + 1), y0 + np.arange(ny + 1), indexing="ij")
        inside = shapely.contains_xy(area.buffer(1e-6), gx, gy)
        free = inside[:-1, :-1] & inside[1:, :-1] & inside[:-1, 1:] & inside[1:, 1:]
        for panel, (dx, dy) in placed:
            a, b, c, d = panel.bounds()
            a, b, c, d = a + dx - GAP / 2, b + dy - GAP / 2, c + dx + GAP / 2, d + dy + GAP / 2
            i0, i1 = max(0, math.floor(a - x0)), max(0, math.ceil(c - x0))
            j0, j1 = max(0, math.floor(b - y0)), max(0, math.ceil(d - y0))
            free[i0:i1, j0:j1] = False
        blocked = (~free).astype(np.int64)
        self.sums = np.pad(blocked.cumsum(0).cumsum(1), ((1, 0), (1, 0)))

    def fits(self, w: float, h: float) -> bool:
        """Tell whether a w × h rectangle fits in whole free cells."""
        a, b = math.ceil(w), math.ceil(h)
        s = self.sums
        if a > s.shape[0] - 1 or b > s.shape[1] - 1:
            return False
        window = s[a:, b:] - s[:-a, b:] - s[a:, :-b] + s[:-a, :-b]
        return bool((window == 0).any())


def _footprint(panel: Panel) -> tuple[float, float]:
    x0, y0, x1, y1 = panel.bounds()
    return x1 - x0 + GAP, y1 - y0 + GAP


@pytest.mark.parametrize("path", ALL_TEMPLATES, ids=lambda p: p.stem)
def test_no_panel_of_a_later_sheet_fits_an_earlier_sheets_free_room(path, monkeypatch):
    late = []
    for size in SIZES:
        for placements, area in framed_sets(_study(path), path.stem, size, monkeypatch):
            rasters = [Raster(area, placed) for placed in placements]
            sheet_of = {id(q): n for n, placed in enumerate(placements) for q, _ in placed}
            for j, placed in enumerate(placements[1:], start=1):
                for panel, _ in placed:
                    # the parts of one sequence keep their order: a part cannot go on a sheet
                    # before the one that holds the part before it (a plan's tables: their plan)
                    before = [q for s in placements for q, _ in s
                              if sequence(q.name) == sequence(panel.name)]
                    k = before.index(panel)
                    first = sheet_of[id(before[k - 1])] if k else 0
                    w, h = _footprint(panel)
                    late += [(size, panel.name, j + 1, i + 1) for i in range(first, j)
                             if rasters[i].fits(w, h)]
    assert not late, late


def test_a_small_late_panel_goes_into_the_first_sheets_free_room():
    area = box(0.0, 0.0, 400.0, 300.0)

    def square(name: str, side: float) -> Panel:
        return Panel(name, [Line((0.0, 0.0), (side, side))])

    # a tall one and a wide one leave a corner; the third does not fit beside them, the fourth
    # (small) does: it goes on sheet 1, not after the third on sheet 2
    panels = [Panel("tall", [Line((0, 0), (150, 280))]), Panel("wide", [Line((0, 0), (230, 150))]),
              square("big", 200.0), square("small", 100.0)]
    groups = paginate(panels, area)
    assert [[p.name for p in g] for g, _ in groups] == [["tall", "wide", "small"], ["big"]]


def test_parts_of_one_sequence_keep_their_order():
    area = box(0.0, 0.0, 400.0, 300.0)
    panels = [Panel("position", [Line((0, 0), (250, 280))]),
              Panel("grid-1", [Line((0, 0), (250, 150))]),
              Panel("grid-2", [Line((0, 0), (100, 100))])]
    groups = paginate(panels, area)
    names = [[p.name for p in g] for g, _ in groups]
    # grid-2 would fit beside the position plan, but not before grid-1
    assert names == [["position"], ["grid-1", "grid-2"]]
    assert chain("velocity-all-2-1") == chain("velocity-all-1") == "velocity-all"
    assert sequence("acceleration-1-tables.2.1") == sequence("acceleration-1") == "acceleration"


def test_the_packer_finds_every_spot_the_raster_finds():
    rng = np.random.default_rng(7)
    area = box(0.0, 0.0, 300.0, 200.0).difference(box(180.0, 0.0, 300.0, 60.0))
    for _ in range(30):
        room = Sheetful(area)
        placed = []
        for k in range(rng.integers(1, 6)):
            side = rng.uniform(20.0, 90.0, 2)
            panel = Panel(f"p{k}", [Line((0.0, 0.0), tuple(side))])
            at = room.put(panel)
            if at is not None:
                placed.append((panel, at))
        raster = Raster(area, placed)
        for w, h in rng.uniform(15.0, 160.0, (10, 2)):
            if raster.fits(w, h):
                assert room.spot(w, h) is not None, (w, h)
