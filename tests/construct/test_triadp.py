"""Class III groups with slider legs (RRP-RRR): structure, exact plans, forces, singular positions.

Golden values come from the loop-closure equations of the six-bar solved with mpmath at 40 digits
(``findroot``) in the test itself, velocities and accelerations by five-point differences in time
of those solutions (h = 1e-9 s: truncation ~h⁴·x⁽⁵⁾ ≈ 1e-33, rounding ~1e-40/h² ≈ 1e-22), and the
balancing moment by virtual power with those kinematics — never from the code under test.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

import mechplan
from mechplan.construct.ops import Op
from mechplan.construct.ops.spec import line
from mechplan.construct.ops.triadp import triadp_angle
from mechplan.construct.step import Kind, Role, Step
from mechplan.errors import TopologyError, UnreachableError
from mechplan.model.mechanism import PairKind
from mechplan.model.plans import Plan
from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import solve

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "six_bar_triad_slider.toml"
#: a pressing force on the slider, added to the template's loads (the fourth: ``load_3``)
SLIDER_LOAD = """
[[loads]]
type = "force"
point = "E"
link = "5"
magnitude = "200 N"
angle = "-90 deg"
"""


def _text() -> str:
    """The template with a 1 kg slider and a pressing force on it."""
    text = TEMPLATE.read_text(encoding="utf-8").replace(
        'on = "g" }    # its mass neglected', 'on = "g" }\nmass = "1 kg"')
    assert 'mass = "1 kg"' in text
    return text + SLIDER_LOAD
mp.mp.dps = 40
MM = mp.mpf("0.001")
D = (160 * MM, 150 * MM)
L = {"OA": 40 * MM, "AB": 120 * MM, "BC": 80 * MM, "BE": 70 * MM, "CE": 75 * MM, "DC": 90 * MM}
OMEGA1 = 10
GUIDE_X = 140 * MM               # the frame guide: the vertical x = 140 mm
ALPHA = mp.radians(9)            # the crank's guide in the Coriolis scene: 9° from OA through O


def _d2(p, q):
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def _exact(phi, guess, variant=False):
    """B, C, E (6 coordinates) at crank angle φ from the closure equations, by mpmath.

    ``variant``: False, the template (E in the vertical frame guide); True, E on the crank's
    guide; a number, the frame guide turned to that angle (deg); ``"rpp"``, the rocker DC
    replaced by a slider C."""
    a = (L["OA"] * mp.cos(phi), L["OA"] * mp.sin(phi))

    def eqs(bx, by, cx, cy, ex, ey):
        b, c, e = (bx, by), (cx, cy), (ex, ey)
        if variant == "rpp":       # the rocker DC replaced by a slider C on a frame guide
            hx, hy, gamma = 175 * MM, 64 * MM, mp.radians(10)
            return [_d2(a, b) - L["AB"] ** 2, _d2(b, c) - L["BC"] ** 2, _d2(b, e) - L["BE"] ** 2,
                    _d2(c, e) - L["CE"] ** 2,
                    -mp.sin(gamma) * (cx - hx) + mp.cos(gamma) * (cy - hy), ex - GUIDE_X]
        if variant == "block":      # a block pinned at F sliding on the base link's line EB
            f = (156.3 * MM, -36.4 * MM)
            return [_d2(a, b) - L["AB"] ** 2, _d2(b, c) - L["BC"] ** 2, _d2(b, e) - L["BE"] ** 2,
                    _d2(c, e) - L["CE"] ** 2, _d2(D, c) - L["DC"] ** 2,
                    (bx - ex) * (f[1] - ey) - (by - ey) * (f[0] - ex)]
        if variant is True:
            guide = -mp.sin(phi + ALPHA) * ex + mp.cos(phi + ALPHA) * ey
        else:       # a frame guide through G = (140 mm, 0) at ``variant`` degrees (90: vertical)
            beta = mp.radians(90 if variant is False else variant)
            guide = -mp.sin(beta) * (ex - GUIDE_X) + mp.cos(beta) * ey
        return [_d2(a, b) - L["AB"] ** 2, _d2(b, c) - L["BC"] ** 2, _d2(b, e) - L["BE"] ** 2,
                _d2(c, e) - L["CE"] ** 2, _d2(D, c) - L["DC"] ** 2, guide]

    return list(mp.findroot(eqs, guess))


def _kinematics(phi, guess, variant=False):
    """Positions, d/dt and d²/dt² (ω1 = 10 rad/s) of A, B, C, E: five-point differences in t."""
    h = mp.mpf("1e-9")
    x0 = _exact(phi, guess, variant)
    rows = {}
    for m in (-2, -1, 0, 1, 2):
        f = phi + m * h * OMEGA1
        x = x0 if m == 0 else _exact(f, x0, variant)
        rows[m] = [L["OA"] * mp.cos(f), L["OA"] * mp.sin(f), *x]
    v = [(rows[-2][i] - 8 * rows[-1][i] + 8 * rows[1][i] - rows[2][i]) / (12 * h)
         for i in range(8)]
    a = [(-rows[-2][i] + 16 * rows[-1][i] - 30 * rows[0][i] + 16 * rows[1][i] - rows[2][i])
         / (12 * h * h) for i in range(8)]

    def pts(x):
        return {n: (x[2 * i], x[2 * i + 1]) for i, n in enumerate("ABCE")}
    return pts(rows[0]), pts(v), pts(a)


def _coriolis_scene() -> str:
    """The template with the slider E on a guide of the crank (through O, 9° from OA)."""
    text = _text()
    text = text.replace('lengths = { OA = "40 mm" }',
                        'lengths = { OA = "40 mm" }\nguides.h = { through = "O", angle = "9 deg" }')
    text = text.replace('slides = { point = "E", on = "g" }', 'slides = { point = "E", on = "h" }')
    return text.replace('E = ["140 mm", "22 mm"]', 'E = ["140 mm", "22.2 mm"]').replace(
        "count = 8", 'at = ["0 deg", "10 deg", "20 deg", "30 deg", "40 deg"]')


@pytest.fixture(scope="module")
def sol():
    return mechplan.loads(_text()).solve(fast=False)


def test_structure_formula_and_kind():
    scene = load_scene(TEMPLATE)
    st = analyse(scene.mechanism)
    assert st.formula == "I(0,1) → III(2,3,4,5)" and st.mechanism_class == 3
    (g,) = st.groups
    assert g.base == "3" and g.kind == "RRP-RRR" and g.sliding


def test_a_leg_carrying_the_guide_is_refused_with_its_links():
    mech = load_scene(TEMPLATE).mechanism
    pairs = tuple(replace(p, a=p.b, b=p.a) if p.kind is PairKind.PRISMATIC else p
                  for p in mech.pairs)
    with pytest.raises(TopologyError) as info:
        analyse(replace(mech, pairs=pairs))
    msg = str(info.value)
    assert "class III group" in msg and "3, 2, 4, 5" in msg and "slide on a known" in msg
    assert "a block pinned to a known link" in msg


def _compare(s, variant=False):
    worst = {"r": 0.0, "v": 0.0, "a": 0.0}
    for k, phi_deg in enumerate(s.phi_deg):
        guess = [float(x) + 0.001 for n in "BCE" for x in s.r[n][k]]
        r, v, a = _kinematics(mp.radians(phi_deg), guess, variant)
        for n in "BCE":
            for key, exact, got in (("r", r, s.r), ("v", v, s.v), ("a", a, s.a)):
                err = max(abs(float(exact[n][i]) - got[n][k][i]) for i in (0, 1))
                worst[key] = max(worst[key], err)
    return worst


def test_positions_velocities_accelerations_match_mpmath(sol):
    worst = _compare(sol)
    # metres, m/s (~0.4), m/s² (~5)
    assert worst["r"] < 1e-15 and worst["v"] < 1e-14 and worst["a"] < 1e-13, worst


def test_a_guide_on_the_crank_brings_coriolis_and_matches_mpmath():
    m = mechplan.loads(_coriolis_scene())
    s = m.solve(fast=False)
    assert len(s.phi_deg) == 5
    worst = _compare(s, variant=True)
    # the accelerations here reach ~20 m/s²
    assert worst["r"] < 1e-15 and worst["v"] < 1e-14 and worst["a"] < 5e-13, worst
    # the slider turns with its guide's link
    assert np.allclose(s.omega["5"], OMEGA1) and np.allclose(s.epsilon["5"], 0.0)
    c = solve(load_scene(TEMPLATE)).construction
    assert not any(st.op is Op.CORIOLIS for st in c.steps.values())
    cc = solve(parse_scene(_coriolis_scene(), "c.toml")).construction
    assert any(st.op is Op.CORIOLIS and st.group == "III(2,3,4,5)" for st in cc.steps.values())


def _turned(deg: int) -> str:
    return _text().replace(
        'angle = "90 deg" }', f'angle = "{deg} deg" }}').replace('E = ["140 mm", "22 mm"]\n', "")


def test_the_slider_leg_gives_the_special_point_when_its_normal_crosses_best():
    """The guide turned to 120°: S is where DC meets the normal to the guide at E; the plans
    still match mpmath and the balancing moment virtual power."""
    text = _turned(120)
    c = solve(parse_scene(text, "t.toml")).construction
    assert c["pos.line.III(2,3,4,5).E"].op is Op.NORMAL_THROUGH
    s = mechplan.loads(text).solve(fast=False)
    worst = _compare(s, variant=120)
    assert worst["r"] < 1e-15 and worst["v"] < 1e-14 and worst["a"] < 2e-13, worst
    for k, phi_deg in enumerate(s.phi_deg):
        guess = [float(x) + 0.001 for n in "BCE" for x in s.r[n][k]]
        expected = _power_balance_moment(phi_deg, guess, variant=120)
        assert s.forces.M_b[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)


def _two_sliders() -> str:
    """The rocker DC replaced by a slider C on a frame guide through H (175, 64) mm at 10°: a
    group RPP-RRR (an arc and two guide lines), its link-4 loads dropped."""
    t = _text().replace('G = ["140 mm", "0 mm"]',
                        'G = ["140 mm", "0 mm"]\nH = ["175 mm", "64 mm"]\n'
                        'guides.gc = { through = "H", angle = "10 deg" }')
    t = (t[:t.index("[links.4]")] + '[links.4]\nname = "slider C"\nslides = { point = "C", '
         'on = "gc" }\nmass = "1 kg"\n\n' + t[t.index("[links.5]"):])
    for cut in ("# the working resistance on the rocker DC", "# a spring-like pull"):
        i = t.index(cut)
        j = t.find("[[loads]]", i)
        t = t[:t.rindex("[[loads]]", 0, i)] + (t[j:] if j >= 0 else "")
    return t


def test_two_slider_legs_match_mpmath_and_virtual_power():
    text = _two_sliders()
    (g,) = analyse(parse_scene(text, "t.toml").mechanism).groups
    assert g.kind == "RPP-RRR"
    s = mechplan.loads(text).solve(np.arange(0.0, 360.0, 40.0), fast=False)
    worst = _compare(s, variant="rpp")
    assert worst["r"] < 1e-15 and worst["v"] < 1e-14 and worst["a"] < 2e-13, worst
    for k, phi_deg in enumerate(s.phi_deg):
        guess = [float(x) + 0.001 for n in "BCE" for x in s.r[n][k]]
        expected = _power_balance_moment(phi_deg, guess, variant="rpp")
        assert s.forces.M_b[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)
        assert s.forces.M_b_zhukovsky[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)


def _block() -> str:
    """The slider E replaced by a block 5 pinned to the frame at F, sliding on the base link's
    guide along EB: a group RRR-RRP (the third leg's pair with the base link prismatic)."""
    t = TEMPLATE.read_text(encoding="utf-8")
    t = t.replace('G = ["140 mm", "0 mm"]\nguides.g = { through = "G", angle = "90 deg" }',
                  'F = ["156.3 mm", "-36.4 mm"]')
    t = t.replace('side = { E = "right of B->C" }',
                  'side = { E = "right of B->C" }\nguides.h = { through = "E", toward = "B" }')
    t = t.replace('slides = { point = "E", on = "g" }    # its mass neglected',
                  'slides = { point = "F", on = "h" }')
    return t.replace('E = ["140 mm", "22 mm"]', 'E = ["140 mm", "21 mm"]')


def test_a_block_sliding_on_the_base_link_matches_mpmath_and_virtual_power():
    text = _block()
    (g,) = analyse(parse_scene(text, "t.toml").mechanism).groups
    assert g.kind == "RRR-RRP"
    s = mechplan.loads(text).solve(np.arange(0.0, 360.0, 40.0), fast=False)
    worst = _compare(s, variant="block")
    assert worst["r"] < 1e-15 and worst["v"] < 1e-14 and worst["a"] < 2e-13, worst
    # the block turns with the base link
    assert np.allclose(s.omega["5"], s.omega["3"]) and np.allclose(s.epsilon["5"], s.epsilon["3"])
    for k, phi_deg in enumerate(s.phi_deg):
        guess = [float(x) + 0.001 for n in "BCE" for x in s.r[n][k]]
        expected = _power_balance_moment(phi_deg, guess, variant="block")
        assert s.forces.M_b[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)
        assert s.forces.M_b_zhukovsky[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)
    # the massless block: the frame's pin force and the base link's guide force cancel, ⊥ EB
    sol = solve(parse_scene(text, "t.toml"))
    ev, res = sol.ev, sol.construction.results
    r05, r35 = ev[res["R_05"]], ev[res["R_35"]]
    at = mechplan.loads(text).solve(plans=("position",), fast=False)     # the same positions
    eb = at.r["B"] - at.r["E"]
    assert np.max(np.abs(r05 + r35)) < 1e-9 * max(1.0, float(np.max(np.abs(r05))))
    assert np.max(np.abs(np.sum(r35 * eb, axis=1))) < 1e-9 * float(np.max(np.abs(r35)))


def test_a_block_with_a_mass_is_refused_by_the_force_plan():
    text = _block().replace('slides = { point = "F", on = "h" }',
                            'slides = { point = "F", on = "h" }\nmass = "1 kg"')
    with pytest.raises(mechplan.errors.SceneError) as info:
        solve(parse_scene(text, "t.toml"))
    assert "block 5" in str(info.value) and "III(2,3,4,5)" in str(info.value)


def test_every_link_stays_rigid_and_e_in_its_guide():
    m = mechplan.load(TEMPLATE)
    s = m.solve(np.arange(0.0, 360.0, 1.0), plans=("position", "velocity", "acceleration"),
                fast=False)
    assert np.max(np.abs(s.r["E"][:, 0] - 0.140)) < 2e-16          # 0.140 to 4 ulp
    assert np.max(np.abs(s.v["E"][:, 0])) < 1e-15 and np.max(np.abs(s.a["E"][:, 0])) < 1e-13
    for link, names in {"2": "AB", "3": "BCE", "4": "DC"}.items():
        w = s.omega[link]
        for i, p in enumerate(names):
            for q in names[i + 1:]:
                d = s.r[q] - s.r[p]
                dv, da = s.v[q] - s.v[p], s.a[q] - s.a[p]
                assert np.max(np.abs(np.sum(dv * d, axis=1))) < 1e-15
                assert np.max(np.abs(np.sum(da * d, axis=1) + w ** 2 * np.sum(d * d, axis=1))) \
                    < 1e-14


def _power_balance_moment(phi_deg, guess, variant=False):
    """M_b from virtual power with the template's masses and loads and mpmath kinematics."""
    r, v, a = _kinematics(mp.radians(phi_deg), guess, variant)
    zero = (mp.mpf(0), mp.mpf(0))
    r["D"], v["D"], a["D"] = D, zero, zero

    def mid(x, p, q):
        return tuple((x[p][i] + x[q][i]) / 2 for i in (0, 1))

    def rate(p, q, which):
        d = (r[q][0] - r[p][0], r[q][1] - r[p][1])
        dv = (which[q][0] - which[p][0], which[q][1] - which[p][1])
        return (d[0] * dv[1] - d[1] * dv[0]) / (d[0] ** 2 + d[1] ** 2)

    power = mp.mpf(0)
    links = ((2, "0.003", "A", "B"), (3, "0.004", "B", "C"), ("1.5", "0.001", "D", "C"))
    if variant == "rpp":
        links = links[:2]
        power += -(a["C"][0] * v["C"][0] + a["C"][1] * v["C"][1])  # the slider C: 1 kg
    for m_, j_, p, q in links:
        m_, j_ = mp.mpf(m_), mp.mpf(j_)
        vs, as_ = mid(v, p, q), mid(a, p, q)
        power += -m_ * (as_[0] * vs[0] + as_[1] * vs[1]) - j_ * rate(p, q, a) * rate(p, q, v)
    if variant != "block":
        power += -(a["E"][0] * v["E"][0] + a["E"][1] * v["E"][1])  # the slider: 1 kg at E
        power += -200 * v["E"][1]                                    # 200 N at E, downwards
    power += -150 * v["C"][1]                                        # 150 N at C, downwards
    if variant != "rpp":
        power += -20 * rate("D", "C", v)                             # −20 N·m on the rocker DC
        power += 80 * mid(v, "D", "C")[0]                            # 80 N at S4 along +x
    return float(-power / OMEGA1)


def test_balancing_moment_matches_virtual_power_and_zhukovsky(sol):
    for k, phi_deg in enumerate(sol.phi_deg):
        guess = [float(x) + 0.001 for n in "BCE" for x in sol.r[n][k]]
        expected = _power_balance_moment(phi_deg, guess)
        assert sol.forces.M_b[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)
        assert sol.forces.M_b_zhukovsky[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)


def test_balancing_moment_with_a_turning_guide_matches_virtual_power():
    s = mechplan.loads(_coriolis_scene()).solve(fast=False)
    for k, phi_deg in enumerate(s.phi_deg):
        guess = [float(x) + 0.001 for n in "BCE" for x in s.r[n][k]]
        expected = _power_balance_moment(phi_deg, guess, variant=True)
        assert s.forces.M_b[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)


def test_reactions_balance_every_link_and_the_guide_reaction_is_normal():
    s = solve(parse_scene(_text(), "t.toml"))
    c, ev = s.construction, s.ev
    res = c.results

    def vec(key):
        return ev[res[key]]

    loads = {"2": [vec("Q_2")], "3": [vec("Q_3"), vec("load_1")],
             "4": [vec("Q_4"), vec("load_2")], "5": [vec("Q_5"), vec("load_3")]}
    reactions = {"2": ["R_12", "R_32"], "3": ["R_23", "R_43", "R_53"], "4": ["R_04", "R_34"],
                 "5": ["R_05", "R_35"]}
    scale = max(1.0, float(np.max(np.abs(vec("R_12")))))
    for link, applied in loads.items():
        total = sum(applied) + sum(vec(r) for r in reactions[link])
        assert np.max(np.abs(total)) < 1e-9 * scale, link
    # a frictionless vertical guide pushes horizontally
    assert np.max(np.abs(vec("R_05")[:, 1])) < 1e-12 * scale


def test_unreachable_positions_name_group_and_angle():
    text = TEMPLATE.read_text(encoding="utf-8").replace('AB = "120 mm"', 'AB = "75 mm"')
    text = text.replace('B = ["120 mm", "89 mm"]\n', "")
    with pytest.raises((UnreachableError, mechplan.errors.SceneError)) as info:
        mechplan.loads(text).solve(np.arange(0.0, 360.0, 1.0), plans=("position",), fast=False)
    msg = str(info.value)
    assert "III(2,3,4,5)" in msg


def _step(kinds, sigma, slope, ref, lengths, d2, d3):
    return Step("pos.angle.3", Op.TRIADP_ANGLE, ("one", "two", "three"), Plan.POSITION,
                Kind.SCALAR, Role.RESULT, "θ3", "III", tuple(sorted({
                    "kinds": kinds, "sigma": sigma, "slope": slope, "theta_ref": ref,
                    "l": lengths, "d2": d2, "d3": d3}.items())))


def test_singular_group_is_flagged_then_refused():
    """Legs' lines (A_1B_1, A_2B_2 and the normal to the slider's guide at B_3) through one point
    Q: the group's Jacobian is singular (a double root): there the sine is ~0 (flagged); with the
    guide moved a little past it, the group does not close (NaN, gap > 0); a regular assembly has
    a sine of order 0.1."""
    b = [np.array([0.0, 0.0]), np.array([0.08, 0.0]), np.array([0.04, 0.06])]
    q = np.array([0.04, -0.10])
    a = [bb + 0.09 * (bb - q) / np.linalg.norm(bb - q) for bb in b[:2]]
    n3 = (b[2] - q) / np.linalg.norm(b[2] - q)            # the guide ⊥ Q B_3
    u3 = np.array([-n3[1], n3[0]])
    d2, d3 = tuple(b[1] - b[0]), tuple(b[2] - b[0])

    def angle(shift, sigma, slope, ref=0.0, u=u3):
        step = _step("RRP", sigma, slope, ref, (0.09, 0.09, 0.0), d2, d3)
        guide = line((b[2] + shift * n3)[None], u[None])
        return [float(x[0]) for x in triadp_angle(step, a[0][None], a[1][None], guide)]

    # which branch holds the assembly: B_1 on the arc about A_1 and the shifted arc about A_2
    found = []
    for sigma in (1, -1):
        for slope in (1, -1):
            th, _, sine = angle(0.0, sigma, slope)
            if math.isfinite(th) and abs(th) < 1e-5:
                found.append(sine)
    assert found and min(found) < 1e-5
    # moved out along n3 (away from Q) the double root disappears, or both roots stay regular
    outs = [angle(sh, sg, sl) for sh in (2e-4, -2e-4) for sg in (1, -1) for sl in (1, -1)]
    assert any(math.isnan(t) and g > 0 and s == 0.0 for t, g, s in outs)
    # a regular group: the guide turned by 30°
    rot = np.array([[math.cos(0.5), -math.sin(0.5)], [math.sin(0.5), math.cos(0.5)]])
    regular = [angle(0.0, sg, sl, u=rot @ u3) for sg in (1, -1) for sl in (1, -1)]
    assert any(abs(t) < 1e-9 and s > 0.05 for t, _, s in regular if math.isfinite(t))


def test_the_fast_path_compiles_the_group_and_answers_the_same():
    """The group's operations have scalar forms: the fast path runs the fused kernel (numba), or
    without numba the numpy path; the answers are the same (tests/construct/test_kernel_triadp.py
    compares them over whole turns)."""
    from mechplan.fast import FastPath, numba_available
    from mechplan.solve import build

    scene = load_scene(TEMPLATE)
    _, c = build(scene, ("position", "velocity", "acceleration"))
    prepared = FastPath(scene).prepare(c, ("position", "velocity", "acceleration"))
    assert (prepared is not None) == numba_available()
    m = mechplan.load(TEMPLATE)
    slow = m.solve(np.arange(0.0, 360.0, 30.0), plans=("position", "velocity", "acceleration"),
                   fast=False)
    quick = m.solve(np.arange(0.0, 360.0, 30.0), plans=("position", "velocity", "acceleration"))
    for n in "BCE":
        assert np.max(np.abs(slow.r[n] - quick.r[n])) <= 1e-16
        assert np.max(np.abs(slow.a[n] - quick.a[n])) <= 1e-13


def test_protocol_writes_each_step_in_four_languages():
    from mechplan.construct.protocol import protocol

    s = solve(load_scene(TEMPLATE))
    ops = {Op.TRIADP_ANGLE, Op.TRIADP_POINT, Op.LEG_NORMAL_FORCE}
    assert ops <= {st.op for st in s.construction.steps.values()}
    for lang in ("en", "ru", "vi", "zh"):
        rows = protocol(s.construction, s.ev, 0, lang, {}, tuple(Plan))
        text = "\n".join(r[2] for r in rows)
        assert "θ3" in text and "{" not in text
        assert sum("S" in r[2] for r in rows) >= 3
