"""Our own sheets (drawings/*.dxf, made by `mechplan draw`) checked against their scenes.

The velocity, acceleration and force plans of a sheet pass within 0.05 mm (points the sheet labels
as one, "c≡d", excepted); position plans are left out: a sheet draws all positions of the cycle
on one plan.
"""

from __future__ import annotations

import math
import tomllib

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
    """Sheet 1 draws the velocity plans of every position: with no angle given, each plan is
    graded at the position it fits, so every velocity plan — each at its own position — and
    every other plan (acceleration, force: drawn at the chosen positions) passes."""
    scene = TEMPLATES / f"{sheet.stem}.toml"
    report = check(scene, sheet, Options())
    plans = [p for p in report.plans if p.plan in ("velocity", "acceleration", "force")]
    assert "velocity" in {p.plan for p in plans}
    if "acceleration" not in {p.plan for p in plans}:       # on a later sheet of the set
        later = sorted(ROOT.joinpath("drawings").glob(f"{sheet.stem}-[0-9]*.dxf"))
        more = [q for f in later for q in check(scene, f, Options()).plans]
        accel = [q for q in more if q.plan == "acceleration"]
        assert accel and all(_exact(q) for q in accel), [q.name for q in more]
    velocity = [p for p in plans if p.plan == "velocity"]
    positions = tomllib.loads(scene.read_text(encoding="utf-8")).get("positions", {})
    if "count" in positions:            # plans of several positions: each at its own angle
        assert None not in {p.phi_deg for p in plans}
        assert len({p.phi_deg for p in velocity}) > 1
    else:       # one position: its velocity plan and Zhukovsky's lever (a turned velocity plan)
        assert len({p.phi_deg for p in plans}) == 1
    misread = [p for p in velocity if not _exact(p)]
    assert not misread, [p.name for p in misread]
    checked = 0
    for p in plans:
        spots = [pt.at_mm for pt in p.points]
        merged = {pt.step for pt in p.points if spots.count(pt.at_mm) > 1}   # "c≡d"
        for s in p.segments:
            assert s.verdict != WRONG, (p.name, s)
            if s.submitted_mm is not None and not {s.start, s.end} & merged:
                checked += 1
                across = (s.exact_mm or 0) * math.sin(math.radians(s.direction_deg or 0))
                assert abs(s.error_mm) < 0.05 and abs(across) < 0.05, (p.name, s)
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


def test_a_wrong_point_on_one_plan_of_sheet_one_is_found_on_that_plan_only(tmp_path) -> None:
    """Move point c of velocity plan #4 (its line ends and its label) 8 mm to the right: that
    plan, graded at its own position (the drive's φ0 + 3 steps), has c wrong; the eleven others
    stay exact."""
    import ezdxf

    from mechplan.scene import load_scene
    from mechplan.solve import build, crank_positions

    scene_path = TEMPLATES / "four_bar.toml"
    sheet = ROOT / "drawings" / "four_bar.dxf"
    before = check(scene_path, sheet, Options())
    plan4 = next(p for p in before.plans if p.plan == "velocity" and p.name.args["number"] == 4)
    c_at = next(pt.at_mm for pt in plan4.points if pt.label == "c")
    doc = ezdxf.readfile(sheet)
    moved = 0
    for e in doc.modelspace():
        if e.dxftype() == "CIRCLE" and math.dist(tuple(e.dxf.center)[:2], c_at) < 1e-3:
            e.dxf.center = (e.dxf.center.x + 8.0, e.dxf.center.y, 0.0)
            moved += 1
        elif e.dxftype() == "SOLID":
            corners = [e.dxf.get(f"vtx{i}") for i in range(4)]
            if any(math.dist((q.x, q.y), c_at) < 1e-3 for q in corners):   # an arrowhead at c
                for i, q in enumerate(corners):
                    e.dxf.set(f"vtx{i}", (q.x + 8.0, q.y, q.z))
                moved += 1
        elif e.dxftype() == "LINE":
            for end in ("start", "end"):
                q = e.dxf.get(end)
                if math.dist((q.x, q.y), c_at) < 1e-3:
                    e.dxf.set(end, (q.x + 8.0, q.y, q.z))
                    moved += 1
        elif e.dxftype() in ("TEXT", "MTEXT") and e.plain_text().strip() == "c":
            q = e.dxf.insert
            if math.dist((q.x, q.y), c_at) < 6.0:
                e.dxf.insert = (q.x + 8.0, q.y, q.z)
                if e.dxftype() == "TEXT" and e.dxf.hasattr("align_point"):
                    a = e.dxf.align_point
                    e.dxf.align_point = (a.x + 8.0, a.y, a.z)
                moved += 1
    assert moved >= 3
    student = tmp_path / "student.dxf"
    doc.saveas(student)
    report = check(scene_path, student, Options())
    scene = load_scene(scene_path)
    phi = crank_positions(scene, build(scene, ("position",))[1])
    velocity = [p for p in report.plans if p.plan == "velocity"]
    for p in velocity:
        wrong = {pt.label for pt in p.points if pt.verdict == WRONG}
        if p.name.args["number"] == 4:
            assert p.phi_deg == pytest.approx(math.degrees(phi[3]), abs=1e-9)
            assert wrong == {"c"}
        else:
            assert not wrong, p.name
    assert not report.passed


def test_crowded_velocity_plans_of_the_shaper_are_read_right() -> None:
    report = check(TEMPLATES / "shaper.toml", ROOT / "drawings" / "shaper.dxf", Options())
    assert all(_exact(p) for p in report.plans if p.plan == "velocity")
