"""Force polygons drawn on a sheet, matched like the other plans (vertices a, b, c … per group)."""

from __future__ import annotations

import pytest

from mechplan.check import Options, check
from mechplan.check.report import CARRIED, NEW, OK, REFERENCE, WRONG
from mechplan.dynamics import Loading
from mechplan.model.plans import Plan
from mechplan.scene import load_scene
from mechplan.solve import solve

from .sheets import TEMPLATES, PlanSpec, exact_sheet, move, write_dxf

F, V = Plan.FORCE, Plan.VELOCITY
GROUP = "II(2,3)"



@pytest.fixture
def slider_crank():
    scene = load_scene(TEMPLATES / "slider_crank.toml")
    sol = solve(scene, at_deg=[60], plans=("position", "velocity", "acceleration", "force"),
                loading=Loading.from_scene(scene))
    return scene, sol


def _specs(sol):
    return {V: PlanSpec(sol.scales[V], (60, 60), f"μv = {sol.scales[V]:g} m/s/mm"),
            F: PlanSpec(sol.scales[F], (320, 80), f"μF = {sol.scales[F]:g} N/mm", GROUP)}


def test_force_polygon_round_trip(tmp_path, slider_crank) -> None:
    scene, sol = slider_crank
    specs = _specs(sol)
    path = write_dxf(tmp_path / "f.dxf", sol, specs, exact_sheet(sol, specs), arrows=True)
    report = check(scene, path, Options(at_deg=60))
    assert report.passed, report.text()
    force = next(p for p in report.plans if p.plan == "force")
    assert force.group == GROUP and force.mu == pytest.approx(sol.scales[F])
    names = {s.name for s in force.segments if s.in_construction}
    assert names == {s.name for s in sol.construction.segments
                     if s.plan is F and s.group == GROUP}
    assert all(s.verdict in (OK, REFERENCE) and abs(s.error_mm) < 0.01 for s in force.segments)
    velocity = next(p for p in report.plans if p.plan == "velocity")
    assert {pt.label for pt in velocity.points} == {"p", "a", "b", "s2"}


def test_force_polygon_with_a_wrong_load(tmp_path, slider_crank) -> None:
    """Q3 drawn too long: the closing point e is then built right from it (carried)."""
    scene, sol = slider_crank
    specs = _specs(sol)
    st = exact_sheet(sol, specs)
    d = st.points[(F, "d")] - st.points[(F, "c")]
    move(st, F, "d", 0.15 * d)
    path = write_dxf(tmp_path / "f.dxf", sol, specs, st)
    report = check(scene, path, Options(at_deg=60))
    assert [(f.plan, f.subject) for f in report.findings] == [(f"force {GROUP} plan", "d")]
    force = next(p for p in report.plans if p.plan == "force")
    rows = {s.name: (s.verdict, s.cause) for s in force.segments}
    assert rows["cd"] == (WRONG, NEW)
    assert any(v == (WRONG, CARRIED) or v[0] == OK for k, v in rows.items() if k != "cd")


def test_force_polygon_missing_a_load(tmp_path, slider_crank) -> None:
    """Q2 left out: c drawn on b and the rest of the chain moved back by Q2."""
    scene, sol = slider_crank
    specs = _specs(sol)
    st = exact_sheet(sol, specs)
    q2 = st.points[(F, "c")] - st.points[(F, "b")]
    for label in ("c", "d"):
        move(st, F, label, -q2)
    path = write_dxf(tmp_path / "f.dxf", sol, specs, st)
    report = check(scene, path, Options(at_deg=60))
    force = next(p for p in report.plans if p.plan == "force")
    rows = {s.name: s for s in force.segments}
    assert rows["bc"].verdict == WRONG and rows["bc"].submitted_mm == pytest.approx(0, abs=1e-9)
    assert "the load Q2 is missing from this force polygon" in rows["bc"].hint
    assert rows["cd"].verdict == OK          # Q3 itself is drawn right, from the wrong c
    assert "c" in {f.subject for f in report.findings}
