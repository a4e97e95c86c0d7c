"""Path generation with prescribed timing (issue 31): a known four-bar's coupler point computed
here independently (circle intersections) is given back to the synthesis, which must recover the
linkage exactly from three points and pass the points by least squares from more; the produced
scene analysed by mechplan passes through the points."""

from __future__ import annotations

import math

import pytest

from mechplan.errors import SceneError
from mechplan.studies import solve_text
from mechplan.studies.synthesis import SynthesisStudy

DEG = math.pi / 180
# the known linkage (templates/four_bar.toml, moved and turned): A, D, AB, BC, DC, BE, CE
A, D = (20.0, -10.0), (255.0, 75.0)
AB, BC, DC, BE, CE = 80.0, 260.0, 180.0, 150.0, 180.0


def _circles(p, r1, q, r2, left):
    """The meet of circle(p, r1) and circle(q, r2) left (or right) of p→q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    e = math.hypot(dx, dy)
    along = (r1 * r1 - r2 * r2 + e * e) / (2 * e)
    h = math.sqrt(r1 * r1 - along * along) * (1 if left else -1)
    return (p[0] + (along * dx - h * dy) / e, p[1] + (along * dy + h * dx) / e)


def known(phi):
    """B, C, E and the coupler and rocker angles of the known linkage at the crank angle φ."""
    b = (A[0] + AB * math.cos(phi), A[1] + AB * math.sin(phi))
    c = _circles(b, BC, D, DC, left=True)
    e = _circles(b, BE, c, CE, left=True)
    return b, c, e, math.atan2(c[1] - b[1], c[0] - b[0]), math.atan2(c[1] - D[1], c[0] - D[0])


def path_scene(phis_deg, coupler=None, rocker=None, shift=None):
    ks = [known(p * DEG) for p in phis_deg]
    dx = [0.0] * len(ks)
    if shift:
        dx[shift[0]] = shift[1]
    pts = ", ".join(f'["{k[2][0] + s!r} mm", "{k[2][1]!r} mm"]' for k, s in zip(ks, dx))
    beta = ", ".join(f'"{p - phis_deg[0]!r} deg"' for p in phis_deg[1:])
    js = (1, len(ks) - 1) if len(ks) == 3 else (len(ks) // 2, len(ks) - 1)
    alpha = coupler or [math.degrees(ks[j][3] - ks[0][3]) for j in js]
    gamma = rocker or [math.degrees(ks[j][4] - ks[0][4]) for j in js]
    return (f'kind = "synthesis"\n[synthesis]\nproblem = "path"\npoints = [{pts}]\n'
            f"crank_rotations = [{beta}]\n"
            f"coupler_rotations = [{', '.join(repr(f'{v!r} deg') for v in alpha)}]\n"
            f"rocker_rotations = [{', '.join(repr(f'{v!r} deg') for v in gamma)}]\n"
            ).replace("'", '"')


def study(text: str) -> SynthesisStudy:
    s = solve_text(text, "t.toml")
    assert isinstance(s, SynthesisStudy)
    return s


@pytest.mark.parametrize("phis", [(10.0, 70.0, 150.0), (200.0, 230.0, 300.0),
                                  (0.0, 120.0, 240.0)])
def test_three_points_recover_the_known_linkage(phis):
    s = study(path_scene(phis))
    n, c = s.design.lengths, s.design.conditions
    assert n["a"] * 1e3 == pytest.approx(AB, abs=1e-9)
    assert n["b"] * 1e3 == pytest.approx(BC, abs=1e-9)
    assert n["c"] * 1e3 == pytest.approx(DC, abs=1e-9)
    assert n["d"] * 1e3 == pytest.approx(math.dist(A, D), abs=1e-9)
    assert c["A"][0] * 1e3 == pytest.approx(A[0], abs=1e-9)
    assert c["D"][1] * 1e3 == pytest.approx(D[1], abs=1e-9)
    assert c["coupler_point"]["BE"] * 1e3 == pytest.approx(BE, abs=1e-9)
    assert c["coupler_point"]["CE"] * 1e3 == pytest.approx(CE, abs=1e-9)
    assert c["coupler_point"]["left"]
    # the crank angles the engine counts (from +x, ccw) are the known ones
    for got, want in zip(c["precision_phi"], phis):
        assert math.remainder(got - want * DEG, 2 * math.pi) == pytest.approx(0, abs=1e-12)
    assert not c["branch_defect"] and not c["order_defect"] and not c["circuit_defect"]
    assert c["crank"] and c["exact"]
    assert c["path_miss"] < 1e-12
    assert s.check.output < 1e-9                 # mechplan's own analysis passes the points


def test_three_points_other_rotations_still_pass_the_points():
    """Other free choices of α, γ give another linkage, still exact through the points."""
    s = study(path_scene((10.0, 70.0, 150.0), coupler=[5.0, 20.0], rocker=[-15.0, -35.0]))
    assert s.design.lengths["a"] * 1e3 != pytest.approx(AB, abs=1e-3)
    if not s.design.conditions["branch_defect"]:
        assert s.check.output < 1e-9
    assert s.check.output == pytest.approx(s.design.conditions["path_miss"], abs=1e-9)


def test_least_squares_through_points_of_a_coupler_curve():
    """Eight points of the known coupler curve: a linkage through them exists, so the least
    squares must find one (the miss is reported and equals the engine's round trip)."""
    phis = tuple(10.0 + 40.0 * j for j in range(8))
    s = study(path_scene(phis))
    c = s.design.conditions
    assert not c["exact"]
    assert c["path_miss"] < 1e-9
    assert s.check.output == pytest.approx(c["path_miss"], abs=1e-9)
    assert s.design.lengths["a"] * 1e3 == pytest.approx(AB, abs=1e-6)


def test_least_squares_reports_its_residual_for_points_off_any_curve():
    # the fourth point moved by 5 mm: no four-bar with this timing passes all six exactly
    s = study(path_scene(tuple(10.0 + 40.0 * j for j in range(6)), shift=(3, 5.0)))
    c = s.design.conditions
    assert 1e-3 < c["path_miss"] * 1e3 < 5.0
    assert s.check.output == pytest.approx(c["path_miss"], abs=1e-9)


def test_path_errors_name_the_key():
    text = path_scene((10.0, 70.0, 150.0))
    bad = text.replace("crank_rotations = [", 'crank_rotations = ["5 deg", ')
    with pytest.raises(SceneError, match="crank_rotations"):
        solve_text(bad, "t.toml")
    bad = text.replace("coupler_rotations", "coupler_rotationz")
    with pytest.raises(SceneError, match="coupler_rotation"):
        solve_text(bad, "t.toml")
    bad = 'kind = "synthesis"\n[synthesis]\nproblem = "path"\npoints = [["0 mm", "0 mm"]]\n'
    with pytest.raises(SceneError, match="points"):
        solve_text(bad, "t.toml")


def test_path_report_json_and_scene_in_every_language():
    s = study(path_scene((10.0, 70.0, 150.0)))
    for lang in ("en", "ru", "vi", "zh"):
        assert "E" in s.report(lang)
    j = s.to_json()
    assert j["problem"] == "path" and j["round_trip"]["output_kind"] == "path"
    assert "BE" in j["scene"]["links"]["2"]["lengths"]
    s2 = solve_text(s.scene_text(), "m.toml")
    assert not isinstance(s2, SynthesisStudy)


@pytest.mark.parametrize("name, lang", [("synth_path", "vi"), ("synth_central_rocker", "zh")])
def test_produced_scene_sheet_checks_clean(tmp_path, name, lang):
    """The produced scene (the path generator with its coupler point E, the central crank-rocker)
    is loaded, drawn, and mechplan's checker finds its own plans 0 wrong, 0 missing."""
    from scenes import ROOT

    from mechplan.check import Options, check
    from mechplan.check.report import MISSING, WRONG
    from mechplan.errors import CheckError
    from mechplan.render.dxf import to_bytes
    from mechplan.scene import load_scene
    from mechplan.sheet.compose import compose
    from mechplan.solve import solve
    from mechplan.studies import solve_file

    s = solve_file(ROOT / "templates" / f"{name}.toml")
    [path] = s.write_files(tmp_path, "pg")
    sc = load_scene(path)
    comp = compose(solve(sc), "A1", "iso", lang, name="pg")
    checked = 0
    for i, sheet in enumerate(comp.sheets):
        dxf = tmp_path / f"pg-{i}.dxf"
        dxf.write_bytes(to_bytes(sheet))
        try:
            report = check(sc, dxf, Options())
        except CheckError:
            continue
        for p in report.plans:
            checked += 1
            assert not [x.name for x in p.segments if x.verdict in (WRONG, MISSING)], p.name
    assert checked
