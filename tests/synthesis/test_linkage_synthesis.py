"""Linkage synthesis from the time ratio K (issue 31): closed forms, the round trip through the
analysis, a textbook answer, infeasible requests, the hand-off scene, the sheet."""

from __future__ import annotations

import math

import pytest

from mechplan.errors import SceneError
from mechplan.studies import solve_text
from mechplan.studies.synthesis import SynthesisStudy

DEG = math.pi / 180


def scene(problem: str, **keys: object) -> str:
    lines = ['kind = "synthesis"', "[synthesis]", f'problem = "{problem}"']
    lines += [f"{k} = {v!r}" if not isinstance(v, str) else f'{k} = "{v}"'
              for k, v in keys.items()]
    return "\n".join(lines) + "\n"


def study(problem: str, **keys: object) -> SynthesisStudy:
    s = solve_text(scene(problem, **keys), "t.toml")
    assert isinstance(s, SynthesisStudy)
    return s


def k_of(theta: float) -> float:
    return (math.pi + theta) / (math.pi - theta)


@pytest.mark.parametrize("k, theta_deg", [(1.2, 180 * 0.2 / 2.2), (1.4, 30.0),
                                          (1.6, 180 * 0.6 / 2.6), (2.0, 60.0)])
def test_theta_from_k_is_the_closed_form(k, theta_deg):
    s = study("coulisse", K=k, frame="100 mm", coulisse="500 mm")
    assert s.design.theta == pytest.approx(theta_deg * DEG, abs=1e-14)


CRANK_ROCKERS = [
    {'K': 1.2, 'swing': "45 deg", 'rocker': "300 mm"},
    {'K': 1.4, 'swing': "40 deg", 'rocker': "300 mm", 'frame': "250 mm"},
    {'K': 1.1, 'swing': "60 deg", 'rocker': "120 mm"},
    {'K': 1.5, 'swing': "30 deg", 'rocker': "200 mm", 'frame_angle': "20 deg"},
]


@pytest.mark.parametrize("keys", CRANK_ROCKERS)
def test_crank_rocker_closed_forms(keys):
    """Independently of the circle: in the triangles A D C at the two dead centres (AC = l ± r),
    the angle at A between them is θ and the angle at D is ψ (law of cosines)."""
    s = study("crank_rocker", **keys)
    n = s.design.lengths
    r, l_, c, d = n["r"], n["l"], n["c"], n["d"]

    def at_a(ac):
        return math.acos((d * d + ac * ac - c * c) / (2 * d * ac))

    def at_d(ac):
        return math.acos((d * d + c * c - ac * ac) / (2 * d * c))
    theta = abs(at_a(l_ + r) - at_a(l_ - r))
    assert k_of(theta) == pytest.approx(keys["K"], abs=1e-12)
    assert abs(at_d(l_ + r) - at_d(l_ - r)) == pytest.approx(
        float(keys["swing"].split()[0]) * DEG, abs=1e-12)
    assert c == pytest.approx(float(keys["rocker"].split()[0]) / 1e3, abs=1e-15)
    if "frame_angle" in keys:      # ψ0: at D between the frame line and DC1 (folded)
        assert at_d(l_ - r) == pytest.approx(float(keys["frame_angle"].split()[0]) * DEG,
                                             abs=1e-12)
    if "frame" in keys:
        assert d == pytest.approx(float(keys["frame"].split()[0]) / 1e3, abs=1e-12)
    # Grashof with the crank shortest: a crank-rocker
    v = sorted([r, l_, c, d])
    assert v[0] == r and v[0] + v[3] <= v[1] + v[2]
    # the smallest transmission angle, closed form at φ = 0 and 180°
    mus = [math.acos((l_ ** 2 + c ** 2 - bd ** 2) / (2 * l_ * c)) for bd in (d - r, d + r)]
    gamma = min(min(m, math.pi - m) for m in mus)
    assert s.design.conditions["gamma_min"] == pytest.approx(gamma, abs=1e-12)


@pytest.mark.parametrize("keys", CRANK_ROCKERS)
def test_crank_rocker_round_trip_through_the_analysis(keys):
    """The produced scene, solved by mechplan: the rocker's extremes give back K and ψ."""
    s = study("crank_rocker", **keys)
    assert s.check.k == pytest.approx(keys["K"], abs=1e-9)
    assert s.check.output == pytest.approx(float(keys["swing"].split()[0]) * DEG, abs=1e-9)
    # γ over 3600 engine positions: its minimum is the closed form's (it is at φ = 0 or 180°)
    assert s.check.gamma_min == pytest.approx(s.design.conditions["gamma_min"], abs=1e-9)
    # the dead centres of the report are the extremes the analysis finds
    assert sorted(s.check.extremes_phi) == pytest.approx(
        sorted(s.design.conditions["dead_centres_phi"]), abs=1e-9)


@pytest.mark.parametrize("problem, keys, subject", [
    ("crank_rocker", {"K": 1.3, "swing": "50 deg", "rocker": "250 mm"}, "dead_centres_phi"),
    ("slider_crank", {"K": 1.2, "stroke": "100 mm"}, "dead_centres_phi"),
    ("coulisse", {"K": 1.5, "frame": "200 mm", "coulisse": "500 mm"}, "dead_centres_phi")])
@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_reported_crank_angles_are_the_analysis_angles(problem, keys, subject, sense):
    """Dead centres and γmin's place are crank angles as `mechplan solve` counts them."""
    text = scene(problem, **keys) + f'[drive]\nsense = "{sense}"\n'
    s = solve_text(text, "t.toml")
    assert sorted(s.check.extremes_phi) == pytest.approx(
        sorted(s.design.conditions[subject]), abs=1e-9)
    assert s.check.k == pytest.approx(keys["K"], abs=1e-9)
    at = s.design.conditions.get("gamma_min_at_phi", s.design.conditions.get(
        "pressure_max_at_phi"))
    if at is not None:
        assert math.cos(s.check.gamma_phi - at) == pytest.approx(1.0, abs=1e-9)


def test_best_crank_rocker_beats_every_member_of_the_family():
    s = study("crank_rocker", K=1.2, swing="45 deg", rocker="300 mm")
    best = s.design.conditions["gamma_min"]
    family = [m.gamma_min for m in s.design.family if m.valid]
    assert len(family) > 40 and best >= max(family) - 1e-12
    # γmin falls toward zero at both ends of the arc
    assert family[0] < best / 2 and family[-1] < best / 10


SLIDERS = [{'K': 1.15, 'stroke': "160 mm"}, {'K': 1.15, 'stroke': "160 mm", 'offset': "30 mm"},
           dict(K=1.3, stroke="200 mm", **{"lambda": 0.3}), dict(K=1.0, stroke="160 mm",
                                                                **{"lambda": 0.25})]


@pytest.mark.parametrize("keys", SLIDERS)
def test_slider_crank_closed_forms_and_round_trip(keys):
    s = study("slider_crank", **keys)
    n = s.design.lengths
    r, l_, e = n["r"], n["l"], n["e"]
    h = float(keys["stroke"].split()[0]) / 1e3
    # H = √((l+r)² − e²) − √((l−r)² − e²) and θ = asin(e/(l−r)) − asin(e/(l+r))
    assert math.sqrt((l_ + r) ** 2 - e * e) - math.sqrt((l_ - r) ** 2 - e * e) == \
        pytest.approx(h, abs=1e-12)
    theta = math.asin(e / (l_ - r)) - math.asin(e / (l_ + r))
    assert k_of(theta) == pytest.approx(keys["K"], abs=1e-12)
    if "offset" in keys:
        assert e == pytest.approx(0.03, abs=1e-15)
    if "lambda" in keys:
        assert r / l_ == pytest.approx(keys["lambda"], abs=1e-12)
    if keys["K"] == 1.0:
        assert e == 0.0 and r == pytest.approx(h / 2, abs=1e-15)
    assert s.design.conditions["gamma_min"] == pytest.approx(
        math.pi / 2 - math.asin((e + r) / l_), abs=1e-12)
    assert s.check.k == pytest.approx(keys["K"], abs=1e-9)
    assert s.check.output == pytest.approx(h, abs=1e-9)
    assert s.check.gamma_min == pytest.approx(s.design.conditions["gamma_min"], abs=1e-9)


def test_best_offset_slider_crank_maximises_gamma():
    best = study("slider_crank", K=1.15, stroke="160 mm")
    g = best.design.conditions["gamma_min"]
    for e_mm in (5, 20, 40, 60, 80, 100):
        other = study("slider_crank", K=1.15, stroke="160 mm", offset=f"{e_mm} mm")
        assert other.design.conditions["gamma_min"] <= g + 1e-12


def test_coulisse_textbook_example():
    """机械设计基础 exercise 2-8 (quoted at howoman.com/ptwg71tf/482.html): a swinging-coulisse
    mechanism with frame 100 mm and K = 1.4 — printed answers θ = ψ = 30°, crank l1 = 26 mm."""
    s = study("coulisse", K=1.4, frame="100 mm", coulisse="300 mm")
    assert math.degrees(s.design.theta) == pytest.approx(30.0, abs=1e-12)
    assert s.design.lengths["r"] * 1e3 == pytest.approx(26.0, abs=0.5)
    assert s.design.lengths["r"] == pytest.approx(0.1 * math.sin(15 * DEG), abs=1e-15)
    assert s.check.k == pytest.approx(1.4, abs=1e-9)
    assert s.check.output == pytest.approx(30 * DEG, abs=1e-9)


@pytest.mark.parametrize("keys", [{'K': 1.6, 'frame': "300 mm", 'stroke': "400 mm"},
                                  {'K': 1.8, 'crank': "90 mm", 'stroke': "500 mm",
                                   'rod': "200 mm"}])
def test_shaper_round_trip_and_pressure_angle(keys):
    s = study("shaper", **keys)
    n = s.design.lengths
    psi = s.design.theta
    assert 2 * n["L"] * math.sin(psi / 2) == pytest.approx(
        float(keys["stroke"].split()[0]) / 1e3, abs=1e-12)
    assert n["r"] == pytest.approx(n["a"] * math.sin(psi / 2), abs=1e-15)
    assert s.check.k == pytest.approx(keys["K"], abs=1e-9)
    assert s.check.output == pytest.approx(float(keys["stroke"].split()[0]) / 1e3, abs=1e-9)
    # the ram line halfway: the largest deviation of B is L(1 − cos(ψ/2))/2, γ = 90° − α
    dev = n["L"] * (1 - math.cos(psi / 2)) / 2
    assert s.design.conditions["pressure_max"] == pytest.approx(math.asin(dev / n["rod"]),
                                                               abs=1e-12)
    assert s.check.gamma_min == pytest.approx(s.design.conditions["gamma_min"], abs=1e-6)


@pytest.mark.parametrize("problem, keys, key", [
    ("crank_rocker", {'K': 1.0, 'swing': "45 deg", 'rocker': "300 mm"}, "synthesis.K"),
    ("crank_rocker", {'K': 1.4, 'swing': "40 deg", 'rocker': "300 mm", 'frame': "400 mm"},
     "synthesis.frame"),
    ("crank_rocker", {'K': 1.2, 'swing': "45 deg", 'rocker': "300 mm", 'gamma_min': "50 deg"},
     "synthesis.gamma_min"),
    ("crank_rocker", {'K': 1.2, 'swing': "45 deg"}, "synthesis.rocker"),
    ("crank_rocker", {'K': 1.2, 'swing': "200 deg", 'rocker': "300 mm"}, "synthesis.swing"),
    ("slider_crank", {'K': 1.15, 'stroke': "160 mm", 'offset': "900 mm"}, "synthesis.offset"),
    ("slider_crank", {'K': 1.0, 'stroke': "160 mm"}, "synthesis.lambda"),
    ("slider_crank", dict(K=1.3, stroke="160 mm", **{"lambda": 0.01}), "synthesis.lambda"),
    ("coulisse", {'K': 1.6, 'frame': "300 mm", 'coulisse': "350 mm"}, "synthesis.coulisse"),
    ("coulisse", {'K': 1.6, 'frame': "300 mm", 'crank': "50 mm", 'coulisse': "900 mm"},
     "synthesis.crank"),
    ("shaper", {'K': 1.6, 'frame': "300 mm", 'stroke': "400 mm", 'rod': "5 mm"}, "synthesis.rod"),
    ("crank_rocker", {'K': 0.5, 'swing': "45 deg", 'rocker': "300 mm"}, "synthesis.K"),
])
def test_infeasible_requests_name_the_key(problem, keys, key):
    with pytest.raises(SceneError) as err:
        study(problem, **keys)
    assert err.value.key == key
    assert "t.toml" in str(err.value)


def test_errors_speak_every_language():
    with pytest.raises(SceneError) as err:
        study("crank_rocker", K=1.4, swing="40 deg", rocker="300 mm", frame="400 mm")
    from mechplan.cli import say_error

    texts = {lang: say_error(err.value, lang) for lang in ("en", "ru", "vi", "zh")}
    assert all("400" in t and "synthesis.frame" in t for t in texts.values())
    assert len(set(texts.values())) == 4


def test_written_scene_is_taken_by_solve_and_draw(tmp_path):
    """The hand-off: the scene file is read by the loader as it is and drawn."""
    from mechplan.studies import solve_file

    s = study("crank_rocker", K=1.2, swing="45 deg", rocker="300 mm")
    [path] = s.write_files(tmp_path, "cr")
    m = solve_file(path)
    assert m.report().strip()
    assert m.sheets(None, None, None, "cr-mechanism")


@pytest.mark.parametrize("problem, keys, lang", [
    ("crank_rocker", {"K": 1.2, "swing": "45 deg", "rocker": "300 mm"}, "en"),
    ("slider_crank", {"K": 1.15, "stroke": "160 mm", "offset": "30 mm"}, "ru"),
    ("coulisse", {"K": 1.6, "frame": "300 mm", "coulisse": "600 mm"}, "vi"),
    ("shaper", {"K": 1.6, "frame": "300 mm", "stroke": "400 mm", "rod": "150 mm"}, "zh")])
def test_produced_scene_passes_the_checker_invariant(tmp_path, problem, keys, lang):
    """mechplan's own sheet of the synthesised linkage checks clean (0 wrong, 0 missing)."""
    from mechplan.check import Options, check
    from mechplan.check.report import MISSING, WRONG
    from mechplan.errors import CheckError
    from mechplan.render.dxf import to_bytes
    from mechplan.scene import load_scene
    from mechplan.sheet.compose import compose
    from mechplan.solve import solve

    s = study(problem, **keys)
    [path] = s.write_files(tmp_path, "cr")
    sc = load_scene(path)
    comp = compose(solve(sc), "A1", "iso", lang, name="cr")
    checked = 0
    for i, sheet in enumerate(comp.sheets):
        dxf = tmp_path / f"cr-{i}.dxf"
        dxf.write_bytes(to_bytes(sheet))
        try:
            report = check(sc, dxf, Options())
        except CheckError:          # "no plan on the sheet"
            continue
        for p in report.plans:
            checked += 1
            assert not [x.name for x in p.segments if x.verdict in (WRONG, MISSING)], p.name
    assert checked


def test_report_json_and_sheet_in_every_language():
    s = study("crank_rocker", K=1.2, swing="45 deg", rocker="300 mm")
    doc = s.to_json()
    assert doc["round_trip"]["K"] == pytest.approx(1.2, abs=1e-9)
    assert doc["scene"]["links"]["1"]["lengths"]["AB"].endswith(" mm")
    for lang in ("en", "ru", "vi", "zh"):
        text = s.report(lang)
        assert "θ = 180°·(K − 1)/(K + 1)" in text
        sheets = s.sheets("A3", "iso", lang, "cr")
        assert sheets


def test_cli_synth_writes_the_scene(tmp_path, capsys):
    from mechplan.cli import main
    from mechplan.scene import load_scene

    src = tmp_path / "sc.toml"
    src.write_text(scene("slider_crank", K=1.15, stroke="160 mm", offset="30 mm"),
                   encoding="utf-8")
    assert main(["synth", str(src), "-o", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert "sc-mechanism.toml" in out
    sc = load_scene(tmp_path / "out" / "sc-mechanism.toml")
    assert sc.mechanism.links["1"].name
    four_bar = tmp_path / "m.toml"
    four_bar.write_text('[ground]\nA = ["0 mm", "0 mm"]\n', encoding="utf-8")
    assert main(["synth", str(four_bar), "-o", str(tmp_path / "out")]) == 2


FUNCTION = {"function": "log10", "x_range": [1, 2], "input_start": "30 deg",
            "input_range": "90 deg", "output_start": "270 deg", "output_range": "-60 deg",
            "frame": "100 mm"}


def fg_scene(**over: object) -> str:
    keys = {**FUNCTION, **over}
    lines = ['kind = "synthesis"', "[synthesis]", 'problem = "function"']
    for k, v in keys.items():
        lines.append(f'{k} = "{v}"' if isinstance(v, str) else f"{k} = {v!r}")
    return "\n".join(lines) + "\n"


def rocker_by_intersection(a, b, c, d, phi, psi_near):
    """ψ of DC from B = a·e^{iφ} and |BC| = b, |DC| = c: both circle meets, the nearer one."""
    bx, by = a * math.cos(phi), a * math.sin(phi)
    best = None
    # solve |D + c·e^{iψ} − B| = b: P cos ψ + Q sin ψ = R
    p, q = 2 * c * (d - bx), -2 * c * by
    r = b * b - c * c - (d - bx) ** 2 - by ** 2
    base, amp = math.atan2(q, p), math.hypot(p, q)
    for sgn in (1, -1):
        psi = base + sgn * math.acos(r / amp)
        diff = abs(math.remainder(psi - psi_near, 2 * math.pi))
        if best is None or diff < best[0]:
            best = (diff, psi)
    return best[1]


def test_function_generator_meets_the_function_at_the_precision_points():
    s = solve_text(fg_scene(), "t.toml")
    n, cond = s.design.lengths, s.design.conditions
    # Chebyshev spacing on [1, 2]
    assert cond["precision_x"] == pytest.approx(
        [1.5 - 0.5 * math.cos(math.pi / 6), 1.5, 1.5 + 0.5 * math.cos(math.pi / 6)], abs=1e-15)
    for x, phi in zip(cond["precision_x"], cond["precision_phi"]):
        want = 270 * DEG - 60 * DEG * math.log10(x) / math.log10(2)
        assert phi == pytest.approx(30 * DEG + 90 * DEG * (x - 1), abs=1e-14)
        got = rocker_by_intersection(n["a"], n["b"], n["c"], n["d"], phi, want)
        assert math.remainder(got - want, 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
    assert not cond["branch_defect"] and not cond["circuit_defect"]
    # between the points the linkage errs; the error vanishes at them
    assert 1e-4 < cond["structural_error_max"] < 0.02
    # the round trip: the engine meets ψ at the points and gives the same structural error
    assert s.check.output < 1e-9
    sampled = max(abs(e[3]) for e in cond["structural_error"])
    assert s.check.structural_max == pytest.approx(sampled, abs=1e-9)


def test_function_generator_given_points_and_errors():
    s = solve_text(fg_scene(points=[1.1, 1.5, 1.9]), "t.toml")
    assert s.design.conditions["precision_x"] == [1.1, 1.5, 1.9]
    assert s.check.output < 1e-9
    for bad, key in (({"points": [1.5, 1.1, 1.9]}, "synthesis.points"),
                     ({"x_range": [2, 1]}, "synthesis.x_range"),
                     ({"output_range": "0 deg"}, "synthesis.output_range"),
                     ({"function": "gamma"}, "synthesis.function")):
        with pytest.raises(SceneError) as err:
            solve_text(fg_scene(**bad), "t.toml")
        assert err.value.key == key


def guided_positions(b_len, thetas, bs):
    return [(x + b_len * math.cos(t), y + b_len * math.sin(t)) for (x, y), t in zip(bs, thetas)]


def guidance_scene(bs, cs) -> str:
    def pts(ps):
        return "[" + ", ".join(f'["{x * 1e3!r} mm", "{y * 1e3!r} mm"]' for x, y in ps) + "]"
    return (f'kind = "synthesis"\n[synthesis]\nproblem = "guidance"\nB = {pts(bs)}\n'
            f"C = {pts(cs)}\n")


@pytest.mark.parametrize("thetas_deg", [(20, 0, -25), (-10, 15, 40)])
def test_three_position_guidance_pivots_and_round_trip(thetas_deg):
    """A and D are equidistant from the three positions of B and of C (independently: the
    distances), and the engine carries the coupler through the three positions."""
    bs = [(0.0, 0.1), (0.06, 0.13), (0.13, 0.12)]
    cs = guided_positions(0.15, [t * DEG for t in thetas_deg], bs)
    s = solve_text(guidance_scene(bs, cs), "t.toml")
    cond, n = s.design.conditions, s.design.lengths
    a_pt, d_pt = cond["A"], cond["D"]
    for p in bs:
        assert math.dist(a_pt, p) == pytest.approx(n["a"], abs=1e-12)
    for p in cs:
        assert math.dist(d_pt, p) == pytest.approx(n["c"], abs=1e-12)
    assert n["b"] == pytest.approx(0.15, abs=1e-12)
    assert n["d"] == pytest.approx(math.dist(a_pt, d_pt), abs=1e-15)
    assert not cond["branch_defect"] and not cond["circuit_defect"]
    assert s.check.output < 1e-9


def test_guidance_reports_a_branch_defect():
    """Positions taken from one four-bar on alternating assemblies: the pivots are found again
    and the branch defect is reported."""
    a, b, c, d = 0.04, 0.12, 0.08, 0.1
    bs, cs = [], []
    for phi_deg, side in ((30, 1), (120, -1), (200, 1)):
        bx, by = a * math.cos(phi_deg * DEG), a * math.sin(phi_deg * DEG)
        e = math.hypot(d - bx, by)
        ux, uy = (d - bx) / e, -by / e
        along = (b * b - c * c + e * e) / (2 * e)
        h = math.sqrt(b * b - along * along)
        bs.append((bx, by))
        cs.append((bx + along * ux - side * h * uy, by + along * uy + side * h * ux))
    s = solve_text(guidance_scene(bs, cs), "t.toml")
    assert s.design.conditions["A"] == pytest.approx([0.0, 0.0], abs=1e-12)
    assert s.design.conditions["D"] == pytest.approx([0.1, 0.0], abs=1e-12)
    assert s.design.conditions["branch_defect"]


def test_guidance_errors():
    bs = [(0.0, 0.1), (0.05, 0.1), (0.1, 0.1)]          # collinear: no circle
    cs = guided_positions(0.15, [0.3, 0.1, -0.2], bs)
    with pytest.raises(SceneError) as err:
        solve_text(guidance_scene(bs, cs), "t.toml")
    assert err.value.key == "synthesis.B"
    bs = [(0.0, 0.1), (0.06, 0.13), (0.13, 0.12)]
    cs = guided_positions(0.15, [0.3, 0.1, -0.2], bs)
    cs[2] = (cs[2][0] + 0.01, cs[2][1])                  # not the same coupler
    with pytest.raises(SceneError) as err:
        solve_text(guidance_scene(bs, cs), "t.toml")
    assert err.value.key == "synthesis.C"


def test_two_position_guidance_pivots_on_a_given_line():
    """The pivots lie on the given line and are equidistant from both positions of B (of C);
    the pole is equidistant from B1, B2 and from C1, C2; the engine meets both positions."""
    bs = [(0.0, 0.1), (0.06, 0.13)]
    cs = guided_positions(0.15, [20 * DEG, 0.0], bs)
    text = guidance_scene(bs, cs) + (
        'pivot_line = { through = ["0 mm", "-20 mm"], angle = "10 deg" }\n')
    s = solve_text(text, "t.toml")
    cond, n = s.design.conditions, s.design.lengths
    for pt in (cond["A"], cond["D"]):     # on the line through (0, −0.02) at 10°
        assert (pt[1] + 0.02) * math.cos(10 * DEG) - pt[0] * math.sin(10 * DEG) == \
            pytest.approx(0.0, abs=1e-15)
    assert math.dist(cond["A"], bs[0]) == pytest.approx(math.dist(cond["A"], bs[1]), abs=1e-15)
    assert math.dist(cond["D"], cs[0]) == pytest.approx(math.dist(cond["D"], cs[1]), abs=1e-15)
    assert n["b"] == pytest.approx(0.15, abs=1e-12)
    assert s.check.output < 1e-9
    with pytest.raises(SceneError) as err:
        solve_text(guidance_scene(bs, cs), "t.toml")
    assert err.value.key == "synthesis.pivot_line"


def test_function_generator_by_least_squares():
    """With five Chebyshev points Freudenstein's K solve the normal equations (checked with
    numpy apart), and the engine's ψ at the points is the linkage's own (intersection)."""
    import numpy as np

    s = solve_text(fg_scene(count=5), "t.toml")
    cond, n = s.design.conditions, s.design.lengths
    assert len(cond["precision_x"]) == 5
    phi, psi = np.array(cond["precision_phi"]), np.array(cond["precision_psi"])
    m = np.column_stack([np.cos(psi), -np.cos(phi), np.ones(5)])
    k = np.array([cond["K1"], cond["K2"], cond["K3"]])
    residual = m @ k - np.cos(phi - psi)
    assert np.abs(m.T @ residual).max() < 1e-12          # the normal equations
    assert np.abs(residual).max() > 1e-9                 # 5 points: not met exactly
    misses = [abs(math.remainder(rocker_by_intersection(n["a"], n["b"], n["c"], n["d"], p, w)
                                 - w, 2 * math.pi)) for p, w in zip(phi, psi)]
    assert s.check.output == pytest.approx(max(misses), abs=1e-9)
    with pytest.raises(SceneError) as err:
        solve_text(fg_scene(count=5, points=[1.1, 1.5, 1.9]), "t.toml")
    assert err.value.key == "synthesis.count"


def test_slider_crank_chosen_by_its_gamma_min():
    s = study("slider_crank", K=1.15, stroke="160 mm", gamma="45 deg")
    n = s.design.lengths
    # γmin = 90° − asin((e + r)/l), independently
    assert 90 * DEG - math.asin((n["e"] + n["r"]) / n["l"]) == pytest.approx(45 * DEG, abs=1e-12)
    assert s.check.k == pytest.approx(1.15, abs=1e-9)
    assert s.check.output == pytest.approx(0.16, abs=1e-9)
    assert s.check.gamma_min == pytest.approx(45 * DEG, abs=1e-9)
    with pytest.raises(SceneError) as err:
        study("slider_crank", K=1.15, stroke="160 mm", gamma="80 deg")
    assert err.value.key == "synthesis.gamma"
