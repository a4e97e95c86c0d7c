"""Our own sheets (drawings/*.dxf, made by `mechplan draw`) checked against their scenes.

The velocity, acceleration and force plans of a sheet pass within 0.01 mm (points the sheet labels
as one, "c≡d", excepted); position plans are left out: a sheet draws all positions of the cycle
on one plan.
"""

from __future__ import annotations

import math

import pytest
from scenes import TEMPLATES as LINKAGE_TEMPLATES

from mechplan.check import Options, check
from mechplan.check.report import WRONG

from .sheets import ROOT, TEMPLATES

LINKAGES = {t.stem for t in LINKAGE_TEMPLATES}          # sheets of linkages (kind = "mechanism")
SHEETS = sorted(p for p in (ROOT / "drawings").glob("*.dxf") if p.stem in LINKAGES)


def test_every_template_has_its_sheet() -> None:
    assert {p.stem for p in (ROOT / "drawings").glob("*.dxf")} >= {
        t.stem for t in TEMPLATES.glob("*.toml")}


def _exact(plan) -> bool:
    return all(s.verdict != WRONG for s in plan.segments)


@pytest.mark.parametrize("sheet", SHEETS, ids=[p.stem for p in SHEETS])
def test_own_sheet_passes(sheet) -> None:
    """Sheet 1 draws the velocity plans of every position: the checker, which checks one crank
    angle per sheet, must find them all exact but those of other positions; every other plan
    (acceleration, force: drawn at the chosen positions) passes."""
    scene = TEMPLATES / f"{sheet.stem}.toml"
    report = check(scene, sheet, Options())
    plans = [p for p in report.plans if p.plan in ("velocity", "acceleration", "force")]
    assert {"velocity", "acceleration"} <= {p.plan for p in plans}
    assert any(p.plan == "velocity" and _exact(p) for p in plans)
    checked = 0
    for p in plans:
        if p.plan == "velocity" and not _exact(p):
            continue                      # a velocity plan of another position
        spots = [pt.at_mm for pt in p.points]
        merged = {pt.step for pt in p.points if spots.count(pt.at_mm) > 1}   # "c≡d"
        for s in p.segments:
            assert s.verdict != WRONG, (p.name, s)
            if s.submitted_mm is not None and not {s.start, s.end} & merged:
                checked += 1
                across = (s.exact_mm or 0) * math.sin(math.radians(s.direction_deg or 0))
                assert abs(s.error_mm) < 0.01 and abs(across) < 0.01, (p.name, s)
    assert checked >= 8
    assert not any(v.verdict == WRONG for v in report.values)


@pytest.mark.parametrize("k", [0, 5, 11])
def test_every_velocity_plan_of_sheet_one_is_exact_at_its_own_position(k) -> None:
    scene = TEMPLATES / "four_bar.toml"
    from mechplan.scene import load_scene
    from mechplan.solve import solve

    phi = math.degrees(float(solve(load_scene(scene), plans=("position",)).phi[k]))
    report = check(scene, ROOT / "drawings" / "four_bar.dxf", Options(at_deg=phi))
    velocity = [p for p in report.plans if p.plan == "velocity"]
    assert len(velocity) >= 12
    exact = [p for p in velocity if _exact(p)]
    assert len(exact) == 1
    assert all(abs(s.error_mm) < 0.01 for s in exact[0].segments if s.submitted_mm is not None)
