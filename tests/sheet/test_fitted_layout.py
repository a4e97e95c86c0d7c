"""Capability sheets draw their diagrams as large as the sheet allows (one sheet when they can)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from mechplan.sheet.dynamics import dynamics_panels
from mechplan.sheet.frame import make_frame
from mechplan.sheet.layout import ENLARGEMENTS, drawing_area, enlargement, pack
from mechplan.sheet.panels import Panel
from mechplan.sheet.primitives import Line, Role, Text
from mechplan.studies import solve_file

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"


def _boxes(n: int, side: float):
    """n square panels of side ``side`` × k (a panel builder for the search)."""
    def build(k: float) -> list[Panel]:
        s = side * k
        return [Panel(f"p{i}", [Line((0.0, 0.0), (s, s))]) for i in range(n)]
    return build


def test_the_largest_enlargement_that_fits_one_sheet_is_chosen():
    area = drawing_area(make_frame("A1", "iso", {}, language="en"))
    build = _boxes(8, 150.0)
    k = enlargement(build, size="A1", standard="iso", language="en", fields={})
    assert pack(build(k), area)[1] is None                    # all on one sheet
    larger = [e for e in ENLARGEMENTS if e > k]
    assert larger and all(pack(build(e), area)[1] is not None for e in larger)


def test_when_nothing_fits_one_sheet_the_fewest_sheets_win():
    # 24 squares of 300 mm × k: too large for A1 at k = 2, several sheets at k = 1
    build = _boxes(24, 300.0)
    k = enlargement(build, size="A1", standard="iso", language="en", fields={})
    area = drawing_area(make_frame("A1", "iso", {}, language="en"))

    def sheets(e: float) -> float:
        rest, count = build(e), 0
        while rest:
            offsets, failed = pack(rest, area)
            if failed == 0:
                return math.inf                  # a panel alone is larger than the sheet
            rest = rest[len(offsets):] if failed is not None else []
            count += 1
        return count

    counts = {e: sheets(e) for e in ENLARGEMENTS}
    assert counts[2.0] == math.inf and counts[1.0] > 1    # the case needs the search
    assert counts[k] == min(counts.values())
    assert k == max(e for e, n in counts.items() if n == counts[k])


def _mu_phi_on(sheet) -> float:
    texts = [p.string for p in sheet.primitives if isinstance(p, Text)]
    values = {float(v.replace(",", ".")) for t in texts for v in re.findall(r"μφ = ([0-9.,]+)", t)}
    assert len(values) == 1, values
    return values.pop()


def test_dynamics_sheet_fills_a1_and_its_json_scales_are_the_sheets():
    study = solve_file(TEMPLATES / "machine_unit.toml")
    scene = study.solution.scene
    k = study._enlargement()
    assert k > 1.0
    sheets = [s for s in study.sheets(None, None, None, "mu") if s.name.startswith("mu-dynamics")]
    assert len(sheets) == 1
    doc = study.to_json()["dynamics"]
    assert _mu_phi_on(sheets[0]) == pytest.approx(math.degrees(doc["scales"]["mu_phi"]))
    # the panels at the next larger enlargement do not fit on the scene's sheet
    area = drawing_area(make_frame(scene.drawing.sheet, scene.drawing.standard, {},
                                   language=scene.language))
    larger = [e for e in ENLARGEMENTS if e > k]
    for e in larger:
        assert pack(dynamics_panels(study.dynamics, scene.language, e), area)[1] is not None


@pytest.mark.parametrize("name", ["motorcycle_engine", "cam_cycloidal", "planetary_two_row"])
def test_capability_sheets_are_drawn_larger_on_a1_than_on_a3(name):
    study = solve_file(TEMPLATES / f"{name}.toml")

    def extent(size: str) -> float:
        sheets = study.sheets(size, "iso", "en", name)
        drawn = (Role.OUTLINE, Role.THIN, Role.DASHED, Role.CHAIN)     # not frame, not tables
        return max(math.dist(p.start, p.end) for s in sheets for p in s.primitives
                   if isinstance(p, Line) and p.role in drawn)

    # the longest line of the drawings (an axis, a plan's line) grows with the sheet
    assert extent("A1") > extent("A3")
