"""Class III groups (triads): structure, exact plans against mpmath, virtual power, closure.

Golden values come from the loop-closure equations of the six-bar solved with mpmath at 40
digits (``findroot``), velocities and accelerations by central differences of those solutions
(h = 1e-12 rad at 40 digits: error ~1e-24), and the balancing moment from the power balance with
those kinematics — never from the code under test.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

import mechplan
from mechplan.construct.ops import Op
from mechplan.construct.ops.triad import triad_angle
from mechplan.construct.step import Kind, Role, Step
from mechplan.errors import UnreachableError
from mechplan.model.plans import Plan
from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import solve

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "six_bar_triad.toml"
mp.mp.dps = 40
MM = mp.mpf("0.001")
O, D, F = (mp.mpf(0), mp.mpf(0)), (160 * MM, 150 * MM), (230 * MM, -20 * MM)
L = {"OA": 40 * MM, "AB": 120 * MM, "BC": 80 * MM, "BE": 70 * MM, "CE": 75 * MM, "DC": 90 * MM,
     "FE": 100 * MM}
OMEGA1 = 10


def _d2(p, q):
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def _exact(phi, guess):
    """B, C, E (6 coordinates) at crank angle φ from the closure equations, by mpmath."""
    a = (L["OA"] * mp.cos(phi), L["OA"] * mp.sin(phi))

    def eqs(bx, by, cx, cy, ex, ey):
        b, c, e = (bx, by), (cx, cy), (ex, ey)
        return [_d2(a, b) - L["AB"] ** 2, _d2(b, c) - L["BC"] ** 2, _d2(b, e) - L["BE"] ** 2,
                _d2(c, e) - L["CE"] ** 2, _d2(D, c) - L["DC"] ** 2, _d2(F, e) - L["FE"] ** 2]

    return list(mp.findroot(eqs, guess))


def _kinematics(phi, guess):
    """Positions, d/dt and d²/dt² (ω1 = 10 rad/s constant) of A, B, C, E, by differences."""
    h = mp.mpf("1e-12")
    x0 = _exact(phi, guess)
    xp, xm = _exact(phi + h, x0), _exact(phi - h, x0)

    def with_a(x, f):
        return [L["OA"] * mp.cos(f), L["OA"] * mp.sin(f), *x]

    r0, rp, rm = with_a(x0, phi), with_a(xp, phi + h), with_a(xm, phi - h)
    v = [(p - m) / (2 * h) * OMEGA1 for p, m in zip(rp, rm, strict=True)]
    a = [(p - 2 * z + m) / h ** 2 * OMEGA1 ** 2 for p, z, m in zip(rp, r0, rm, strict=True)]

    def pts(x):
        return {n: (x[2 * i], x[2 * i + 1]) for i, n in enumerate("ABCE")}
    return pts(r0), pts(v), pts(a)


@pytest.fixture(scope="module")
def sol():
    return mechplan.load(TEMPLATE).solve(fast=False)


def test_structure_formula_and_class():
    scene = load_scene(TEMPLATE)
    st = analyse(scene.mechanism)
    assert st.formula == "I(0,1) → III(2,3,4,5)"
    assert st.mechanism_class == 3
    (g,) = st.groups
    assert g.base == "3" and sorted(g.legs) == ["2", "4", "5"] and g.kind == "RRR-RRR"


def test_json_names_the_group_class():
    from mechplan.solve import to_json as solution_json

    data = solution_json(solve(load_scene(TEMPLATE), plans=("position",)))
    assert data["structure"] == "I(0,1) → III(2,3,4,5)"
    assert data["groups"] == [{"class": 3, "kind": "RRR-RRR", "links": ["3", "2", "4", "5"]}]


def test_positions_velocities_accelerations_match_mpmath(sol):
    worst = {"r": 0.0, "v": 0.0, "a": 0.0}
    for k, phi_deg in enumerate(sol.phi_deg):
        guess = [float(x) + 0.002 for n in "BCE" for x in sol.r[n][k]]
        r, v, a = _kinematics(mp.radians(phi_deg), guess)
        for n in "BCE":
            for key, exact, got in (("r", r, sol.r), ("v", v, sol.v), ("a", a, sol.a)):
                err = max(abs(float(exact[n][i]) - got[n][k][i]) for i in (0, 1))
                worst[key] = max(worst[key], err)
    # metres, m/s, m/s²: the velocities are ~0.4 m/s and the accelerations ~4 m/s²
    assert worst["r"] < 1e-15 and worst["v"] < 1e-14 and worst["a"] < 1e-13, worst


def test_the_sketch_fixes_the_assembly(sol):
    # position 0 is φ = 0, where the scene sketches B and E
    assert np.hypot(*(sol.r["B"][0] - (0.120, 0.089))) < 1e-3
    assert np.hypot(*(sol.r["E"][0] - (0.139, 0.022))) < 1e-3


def test_the_other_assembly_from_another_sketch():
    text = TEMPLATE.read_text(encoding="utf-8")
    sol0 = mechplan.load(TEMPLATE).solve(0.0, plans=("position",), fast=False)
    # the second closure root at φ = 0 (θ3 ≈ 125°, found by the closure's grid of 720 angles)
    moved = text.replace('B = ["120 mm", "89 mm"]', 'B = ["160 mm", "7 mm"]').replace(
        'E = ["139 mm", "22 mm"]\n', "")
    other = mechplan.loads(moved).solve(0.0, plans=("position",), fast=False)
    assert np.hypot(*(other.r["B"][0] - sol0.r["B"][0])) > 0.01
    for s in (sol0, other):
        r = {n: s.r[n][0] for n in "ABCDEF"}
        assert abs(np.hypot(*(r["B"] - r["A"])) - 0.120) < 1e-15
        assert abs(np.hypot(*(r["C"] - r["D"])) - 0.090) < 1e-15
        assert abs(np.hypot(*(r["E"] - r["F"])) - 0.100) < 1e-15


def test_every_plan_closes_at_many_positions():
    """Rigid links and legs: (v_X − v_Y)·XY = 0 and (a_X − a_Y)·XY = −ω²|XY|² for every pair of
    points of a link, at 360 positions; every force balance of every link closes."""
    m = mechplan.load(TEMPLATE)
    s = m.solve(np.arange(0.0, 360.0, 1.0), fast=False)
    links = {"2": "AB", "3": "BCE", "4": "DC", "5": "FE"}
    for link, names in links.items():
        w, e = s.omega[link], s.epsilon[link]
        for i, p in enumerate(names):
            for q in names[i + 1:]:
                d = s.r[q] - s.r[p]
                dv, da = s.v[q] - s.v[p], s.a[q] - s.a[p]
                assert np.max(np.abs(np.sum(dv * d, axis=1))) < 1e-15
                assert np.max(np.abs(np.sum(da * d, axis=1) + w ** 2 * np.sum(d * d, axis=1))) \
                    < 1e-14
                # the angular rates from the cross products agree with ω, ε
                cross_v = d[:, 0] * dv[:, 1] - d[:, 1] * dv[:, 0]
                assert np.allclose(cross_v / np.sum(d * d, axis=1), w, atol=1e-12)
                cross_a = d[:, 0] * da[:, 1] - d[:, 1] * da[:, 0]
                assert np.allclose(cross_a / np.sum(d * d, axis=1), e, atol=1e-10)


def _power_balance_moment(phi_deg, guess):
    """M_b from the power balance, with the template's masses and loads and mpmath kinematics."""
    phi = mp.radians(phi_deg)
    r, v, a = _kinematics(phi, guess)
    r["D"], r["F"] = D, F
    zero = (mp.mpf(0), mp.mpf(0))
    v["D"] = v["F"] = a["D"] = a["F"] = zero

    def mid(x, p, q):
        return tuple((x[p][i] + x[q][i]) / 2 for i in (0, 1))

    def rate(p, q, which):
        d = (r[q][0] - r[p][0], r[q][1] - r[p][1])
        dv = (which[q][0] - which[p][0], which[q][1] - which[p][1])
        return (d[0] * dv[1] - d[1] * dv[0]) / (d[0] ** 2 + d[1] ** 2)

    def eps(p, q):
        # ε = d ω/dt: (d × Δa)/|d|² holds for a rigid segment
        return rate(p, q, a)

    masses = {"2": (2, "0.003", "A", "B"), "3": (3, "0.004", "B", "C"),
              "4": ("1.5", "0.001", "D", "C"), "5": ("1.5", "0.0015", "F", "E")}
    power = mp.mpf(0)
    for m_, j_, p, q in masses.values():
        m_, j_ = mp.mpf(m_), mp.mpf(j_)
        vs, as_ = mid(v, p, q), mid(a, p, q)
        power += -m_ * (as_[0] * vs[0] + as_[1] * vs[1]) - j_ * eps(p, q) * rate(p, q, v)
    power += -20 * rate("F", "E", v)                       # the moment on link 5
    power += -150 * v["C"][1]                              # 150 N at C, downwards
    power += 80 * mid(v, "D", "C")[0]                      # 80 N at S4 along +x
    return float(-power / OMEGA1)


def test_balancing_moment_matches_virtual_power_and_zhukovsky(sol):
    for k, phi_deg in enumerate(sol.phi_deg):
        guess = [float(x) + 0.002 for n in "BCE" for x in sol.r[n][k]]
        expected = _power_balance_moment(phi_deg, guess)
        assert sol.forces.M_b[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)
        assert sol.forces.M_b_zhukovsky[k] == pytest.approx(expected, rel=1e-11, abs=1e-12)


def test_reactions_balance_every_link(sol):
    """Σ forces on each link of the triad (reactions + loads + inertia) = 0."""
    s = solve(load_scene(TEMPLATE))
    c, ev = s.construction, s.ev
    res = c.results

    def vec(key):
        return ev[res[key]]

    loads = {"2": [vec("Q_2")], "3": [vec("Q_3"), vec("load_1")], "4": [vec("Q_4"), vec("load_2")],
             "5": [vec("Q_5")]}
    reactions = {"2": ["R_12", "R_32"], "3": ["R_23", "R_43", "R_53"], "4": ["R_04", "R_34"],
                 "5": ["R_05", "R_35"]}
    for link, applied in loads.items():
        total = sum(applied) + sum(vec(r) for r in reactions[link])
        assert np.max(np.abs(total)) < 1e-9 * max(1.0, float(np.max(np.abs(vec("R_12")))))


def test_fast_path_uses_the_kernel_and_agrees():
    """The triad's operations have scalar forms: the fused kernel (numba) solves the six-bar, and
    its plans are the numpy path's to rounding (1e-13 of the accelerations' ~4 m/s²)."""
    pytest.importorskip("numba", reason="the fast extra (numba) is optional")
    from mechplan.fast import FastPath
    from mechplan.solve import build

    scene = load_scene(TEMPLATE)
    _, c = build(scene, ("position", "velocity", "acceleration"))
    assert FastPath(scene).prepare(c, ("position", "velocity", "acceleration")) is not None
    m = mechplan.load(TEMPLATE)
    slow = m.solve(np.arange(0.0, 360.0, 15.0), plans=("position", "velocity", "acceleration"),
                   fast=False)
    quick = m.solve(np.arange(0.0, 360.0, 15.0), plans=("position", "velocity", "acceleration"))
    for n in "BCE":
        assert np.max(np.abs(slow.r[n] - quick.r[n])) < 1e-16
        assert np.max(np.abs(slow.v[n] - quick.v[n])) < 1e-15
        assert np.max(np.abs(slow.a[n] - quick.a[n])) < 1e-13


def test_unreachable_positions_name_group_and_angle():
    text = TEMPLATE.read_text(encoding="utf-8").replace('FE = "100 mm"', 'FE = "75 mm"')
    text = text.replace('E = ["139 mm", "22 mm"]\n', "")
    m = mechplan.loads(text)
    with pytest.raises(UnreachableError) as info:
        m.solve(np.arange(0.0, 360.0, 1.0), plans=("position",), fast=False)
    msg = str(info.value)
    assert "III(2,3,4,5)" in msg and "φ" in msg


def _triad_step(sigma, slope, ref, l, d2, d3):
    return Step("pos.angle.3", Op.TRIAD_ANGLE, ("a1", "a2", "a3"), Plan.POSITION, Kind.SCALAR,
                Role.RESULT, "θ3", "III", tuple(sorted({
                    "sigma": sigma, "slope": slope, "theta_ref": ref, "l1": l[0], "l2": l[1],
                    "l3": l[2], "d2": d2, "d3": d3}.items())))


def test_singular_triad_is_flagged_or_refused():
    """Legs whose lines meet in one point (the triad's Jacobian is singular, a double root of the
    closure): there the root comes with a zero sine (flagged); a little past it the assembly no
    longer exists and the position is refused (NaN, gap > 0); a regular root has a sine ~0.2."""
    b = [np.array([0.0, 0.0]), np.array([0.08, 0.0]), np.array([0.04, 0.06])]
    centre = np.array([0.04, -0.10])                   # the three leg lines pass through it
    lengths = (0.05, 0.06, 0.07)
    legs = [bi + length * (bi - centre) / np.linalg.norm(bi - centre)
            for bi, length in zip(b, lengths, strict=True)]
    d2, d3 = tuple(b[1] - b[0]), tuple(b[2] - b[0])

    def angle(shift, sigma, slope, ref):
        step = _triad_step(sigma, slope, ref, lengths, d2, d3)
        a3 = (legs[2] + np.array([shift, 0.0]))[None]
        return [float(x[0]) for x in triad_angle(step, legs[0][None], legs[1][None], a3)]

    for slope in (1, -1):
        th, gap, sine = angle(0.0, -1, slope, 0.0)
        assert math.isnan(th) or (abs(th) < 1e-6 and sine < 1e-6)
        th, gap, sine = angle(1e-4, -1, slope, 0.0)
        assert math.isnan(th) and gap > 0 and sine == 0.0
    th, gap, sine = angle(0.0, 1, 1, math.radians(66.0))
    assert abs(math.degrees(th) - 66.08) < 0.01 and sine > 0.1 and gap <= 0


def test_class_three_with_a_slider_leg_is_taken():
    """A leg sliding on a frame guide (RRP-RRR) is built by construct/plans/triadp.py (its own
    tests: tests/construct/test_triadp.py)."""
    text = TEMPLATE.read_text(encoding="utf-8")
    text = text.replace('F = ["230 mm", "-20 mm"]', 'F = ["230 mm", "-20 mm"]\n'
                        'guides.g = { through = "F", angle = "90 deg" }')
    text = text.replace('[links.5]\nname = "rocker FE"\nlengths = { FE = "100 mm" }\n'
                        'points = { S5 = "0.5 of F E" }',
                        '[links.5]\nname = "slider"\nslides = { point = "E", on = "g" }')
    text = text.replace('centre = "S5"\n', "")
    (g,) = analyse(parse_scene(text, "p.toml").mechanism).groups
    assert g.kind == "RRP-RRR" and g.sliding


def test_a_cell_off_the_arcs_domain_is_not_taken_for_a_root():
    """Between two edges of the arcs' domain f is undefined, yet finite (and of opposite signs) at
    the edges: no root lies there (the solver once returned one, f undefined at it). The root
    found instead closes the group: the legs' lengths, recomputed at 40 digits from the base
    link's angle and the arcs' meet, are the given ones."""
    l = (0.09045508246086377, 0.07994228694915462, 0.12809433166258827)
    d2, d3 = (0.06797485850911097, 0.02111897436632973), (-0.04067649958658648, 0.08946206686398323)
    a1 = np.array([[0.012023065270584797, 0.08354146973878265]])
    a2 = np.array([[0.037996112435555604, 0.1390244910569591]])
    a3 = np.array([[-0.01437421444377763, 0.03137504688072909]])
    step = _triad_step(1, -1, 2.0448277433160262, l, d2, d3)
    theta, gap, sine = (float(x[0]) for x in triad_angle(step, a1, a2, a3))
    assert math.isfinite(theta) and gap <= 0 and sine > 0
    th = mp.mpf(theta)
    c, s = mp.cos(th), mp.sin(th)
    # B1 on the arc (A1, l1) and on the arc (A2 − R(θ)d2, l2), on the left of A1 → centre
    cx = mp.mpf(a2[0, 0]) - (c * d2[0] - s * d2[1])
    cy = mp.mpf(a2[0, 1]) - (s * d2[0] + c * d2[1])
    dx, dy = cx - mp.mpf(a1[0, 0]), cy - mp.mpf(a1[0, 1])
    dd = dx * dx + dy * dy
    along = (mp.mpf(l[0]) ** 2 - mp.mpf(l[1]) ** 2 + dd) / (2 * dd)
    h = mp.sqrt(mp.mpf(l[0]) ** 2 / dd - along ** 2)
    bx, by = mp.mpf(a1[0, 0]) + along * dx - h * dy, mp.mpf(a1[0, 1]) + along * dy + h * dx
    b3x, b3y = bx + (c * d3[0] - s * d3[1]), by + (s * d3[0] + c * d3[1])
    leg3 = mp.sqrt((b3x - mp.mpf(a3[0, 0])) ** 2 + (b3y - mp.mpf(a3[0, 1])) ** 2)
    assert abs(leg3 - mp.mpf(l[2])) < 1e-15
