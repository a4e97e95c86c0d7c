"""Friction in the pairs of machines with two drivers (W = 2): the courses' iteration gives both
balancing quantities (a crank's M_b, a cylinder's F_d) with friction in every pair, and the
machine's efficiency η = P⁰/P of the drivers' input powers. Golden values: every link's
equilibrium with friction written here as one nonlinear system (all reaction components and both
driving quantities unknown, |R| and the senses of friction from finite-difference velocities of the
loop closure solved here) and solved by scipy's fsolve; the friction-free limit; η by powers."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechplan.dynamics.loading import Loading
from mechplan.scene import parse_scene
from mechplan.solve import solve

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"
PLANS = ("position", "velocity", "acceleration", "force")
#: five-bar positions: the drivers drive (P > 0) at all but 75° (the loads drive there)
ANGLES = (10.0, 75.0, 200.0, 250.0, 320.0, 340.0)
#: crank and cylinder: P > 0 at all but 140°
CC_ANGLES = (20.0, 75.0, 140.0, 300.0, 330.0, 345.0)


def _solve(text: str, at: tuple[float, ...] = ANGLES):
    scene = parse_scene(text, "scene.toml")
    return solve(scene, at_deg=list(at), plans=PLANS, loading=Loading.from_scene(scene))


def cross(u, v) -> float:
    return float(u[0] * v[1] - u[1] * v[0])


def _meet(p, r1, q, r2, left: bool):
    """The point at r1 from p and r2 from q, left (or right) of the line p→q."""
    d = np.hypot(*(q - p))
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(r1 * r1 - a * a)
    u = (q - p) / d
    n = np.array([-u[1], u[0]])
    return p + a * u + (h if left else -h) * n


def _rate(fun, t_of, h=1e-6):
    """d/dt of an angle function by five-point differences."""
    def ang(dt):
        return fun(t_of(dt))
    vals = [ang(k * h) for k in (-2, -1, 1, 2)]
    base = ang(0.0)
    vals = [base + math.remainder(v - base, math.tau) for v in vals]
    return (vals[0] - 8 * vals[1] + 8 * vals[2] - vals[3]) / (12 * h)


def _fsolve(equations, x0):
    """The root, its residual below 1e-12 of the largest unknown (fsolve may stop at xtol 1e-14
    saying it makes no progress when the root is already exact to rounding)."""
    sol, _info, ok, msg = fsolve(equations, x0, full_output=True, xtol=1e-14)
    assert np.abs(equations(sol)).max() < 1e-12 * max(1.0, np.abs(sol).max()), (ok, msg)
    return sol


def _moment(point, force) -> float:
    return cross(point, force)


# -- a five-bar with two cranks (the template): cranks 1 about A and 4 about E --------------------
A5, E5 = np.array([0.0, 0.0]), np.array([0.15, 0.0])
FIVE_LOADS = """
[[loads]]
type = "force"
point = "C"
link = "2"
vector = ["120 N", "-250 N"]

[[loads]]
type = "force"
point = "D"
link = "3"
vector = ["-60 N", "90 N"]

[[loads]]
type = "torque"
link = "2"
torque = "4 N m"

[[loads]]
type = "torque"
link = "3"
torque = "-6 N m"
"""
F_C5, F_D5, T2, T3 = np.array([120.0, -250.0]), np.array([-60.0, 90.0]), 4.0, -6.0
#: pairs: (f, r) — [friction] f = 0.12, pin_radius 15 mm, and the per-pair table below
FIVE_FRICTION = """
[friction]
f = {f0}
pin_radius = "15 mm"
[friction.pairs]
"0-1" = {{ f = {f1}, radius = "20 mm" }}
"2-3" = {{ f = {f2} }}
"0-4" = {{ f = {f3}, radius = "25 mm" }}
"""
FIVE_F = {"f0": 0.12, "f1": 0.15, "f2": 0.2, "f3": 0.1}


def _five_text(scale: float = 1.0) -> str:
    text = (TEMPLATES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    coefficients = {k: v * scale for k, v in FIVE_F.items()}
    return text + FIVE_LOADS + FIVE_FRICTION.format(**coefficients)


def _five_rho(scale: float = 1.0) -> dict[str, float]:
    f = {k: v * scale for k, v in FIVE_F.items()}
    return {"01": f["f1"] * 0.020, "12": f["f0"] * 0.015, "23": f["f2"] * 0.015,
            "34": f["f0"] * 0.015, "04": f["f3"] * 0.025}


def _five_points(phi1: float):
    b = A5 + 0.06 * np.array([math.cos(phi1), math.sin(phi1)])
    th4 = math.pi - (math.pi / 2 + phi1)         # φ4 = 90° + φ1, clockwise from −x
    d = E5 + 0.08 * np.array([math.cos(th4), math.sin(th4)])
    c = _meet(b, 0.2, d, 0.18, left=True)
    return b, c, d


def _five_omegas(phi1: float) -> dict[str, float]:
    def t_of(dt):
        return phi1 + 10.0 * dt

    def th2(p):
        b, c, _ = _five_points(p)
        return math.atan2(*(c - b)[::-1])

    def th3(p):
        _, c, d = _five_points(p)
        return math.atan2(*(c - d)[::-1])
    return {"1": 10.0, "2": _rate(th2, t_of), "3": _rate(th3, t_of), "4": -10.0}


def _five_system(phi1: float, rho: dict[str, float]):
    """Unknowns R01, R12, R23, R34, R04 (force of i on j), M1, M4; 12 equations."""
    b, c, d = _five_points(phi1)
    w = _five_omegas(phi1)

    def mf(r, key, j, i):        # friction couple on link j from the pair with link i
        rel = w[j] - (0.0 if i == "0" else w[i])
        return -rho[key] * np.hypot(*r) * np.sign(rel)

    def eq(x):
        r01, r12, r23, r34, r04 = (x[2 * k:2 * k + 2] for k in range(5))
        m1, m4 = x[10], x[11]
        out = []
        # link 1: R01 at A, −R12 at B
        out += [*(r01 - r12), _moment(A5, r01) + _moment(b, -r12) + m1
                + mf(r01, "01", "1", "0") + mf(r12, "12", "1", "2")]
        # link 2: R12 at B, −R23 at C, F_C, T2
        out += [*(r12 - r23 + F_C5), _moment(b, r12) + _moment(c, -r23 + F_C5) + T2
                + mf(r12, "12", "2", "1") + mf(r23, "23", "2", "3")]
        # link 3: R23 at C, −R34 at D, F_D, T3
        out += [*(r23 - r34 + F_D5), _moment(c, r23) + _moment(d, -r34 + F_D5) + T3
                + mf(r23, "23", "3", "2") + mf(r34, "34", "3", "4")]
        # link 4: R34 at D, R04 at E, M4
        out += [*(r34 + r04), _moment(d, r34) + _moment(E5, r04) + m4
                + mf(r34, "34", "4", "3") + mf(r04, "04", "4", "0")]
        return np.array(out)
    return eq, w


def _five_reference(phi1: float, scale: float = 1.0):
    """(M1, M4) with friction, (M1⁰, M4⁰) without, ω, the power of friction."""
    free_eq, w = _five_system(phi1, {k: 0.0 for k in _five_rho()})
    free = _fsolve(free_eq, np.zeros(12))
    rho = _five_rho(scale)
    eq, _ = _five_system(phi1, rho)
    x = _fsolve(eq, free)
    rels = {"01": w["1"], "12": w["2"] - w["1"], "23": w["3"] - w["2"], "34": w["4"] - w["3"],
            "04": w["4"]}
    rs = {"01": x[0:2], "12": x[2:4], "23": x[4:6], "34": x[6:8], "04": x[8:10]}
    lost = -sum(rho[k] * np.hypot(*rs[k]) * abs(rels[k]) for k in rho)
    return (x[10], x[11]), (free[10], free[11]), w, lost


def test_five_bar_geometry_is_the_templates():
    sol = _solve(_five_text())
    for k, phi in enumerate(ANGLES):
        b, c, d = _five_points(math.radians(phi))
        for name, p in (("B", b), ("C", c), ("D", d)):
            np.testing.assert_allclose(sol.ev[sol.construction.position(name)][k], p, atol=1e-12)


def test_five_bar_both_balancing_moments_with_friction_against_fsolve():
    fa = _solve(_five_text()).extras["forces"]
    fr = fa.friction
    assert fr is not None and fr.second is not None and fr.second.link == "4"
    assert np.all(fr.converged) and not np.any(fr.undefined)
    for k, phi in enumerate(ANGLES):
        (m1, m4), (m10, m40), w, lost = _five_reference(math.radians(phi))
        assert float(fa.balancing_moment[k]) == pytest.approx(m1, rel=1e-8, abs=1e-9)
        assert float(fa.second[1][k]) == pytest.approx(m4, rel=1e-8, abs=1e-9)
        assert float(fr.moment[k]) == pytest.approx(m1, rel=1e-8, abs=1e-9)
        assert float(fr.second.value[k]) == pytest.approx(m4, rel=1e-8, abs=1e-9)
        # the friction-free pass: both drivers' frictionless values
        assert float(fr.free_moment[k]) == pytest.approx(m10, rel=1e-9, abs=1e-10)
        assert float(fr.second.free[k]) == pytest.approx(m40, rel=1e-9, abs=1e-10)
        # the machine's efficiency: the ratio of the drivers' input powers, and by powers
        p, p0 = m1 * w["1"] + m4 * w["4"], m10 * w["1"] + m40 * w["4"]
        assert float(fr.input_power[k]) == pytest.approx(p, rel=1e-8)
        assert float(fr.free_input_power[k]) == pytest.approx(p0, rel=1e-9)
        assert (p > 0) == (phi != 75.0)
        if p > 0:
            assert float(fr.efficiency[k]) == pytest.approx(p0 / p, rel=1e-8)
            assert float(fr.efficiency_power[k]) == pytest.approx(1 + lost / p, rel=1e-8)
            assert float(fr.efficiency[k]) == pytest.approx(float(fr.efficiency_power[k]),
                                                            rel=1e-10)
            assert float(fr.efficiency[k]) <= 1.0
        else:       # the drivers together do not drive: no efficiency
            assert math.isnan(float(fr.efficiency[k]))
            assert math.isnan(float(fr.efficiency_power[k]))
        # the power of friction, pair by pair, sums to P⁰ − P
        total = sum(float(q.power[k]) for q in fr.pairs)
        assert total == pytest.approx(lost, rel=1e-8)
        assert total == pytest.approx(p0 - p, rel=1e-8)
    # Zhukovsky's lever with the second crank's M_b (with friction) gives the first's again
    np.testing.assert_allclose(fa.zhukovsky_moment, fa.balancing_moment, rtol=1e-9)


def test_five_bar_friction_free_limit():
    plain = _solve((TEMPLATES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
                   + FIVE_LOADS).extras["forces"]
    fr = _solve(_five_text()).extras["forces"].friction
    np.testing.assert_allclose(fr.free_moment, plain.balancing_moment, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(fr.second.free, plain.second[1], rtol=1e-9, atol=1e-12)
    tiny = _solve(_five_text(scale=1e-9)).extras["forces"]
    np.testing.assert_allclose(tiny.balancing_moment, plain.balancing_moment, rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose(tiny.second[1], plain.second[1], rtol=1e-9, atol=1e-9)
    eta = tiny.friction.efficiency
    assert np.isfinite(eta).sum() == len(ANGLES) - 1
    np.testing.assert_allclose(eta[np.isfinite(eta)], 1.0, atol=1e-8)
    zero = _solve(_five_text(scale=0.0)).extras["forces"]
    np.testing.assert_allclose(zero.balancing_moment, plain.balancing_moment, rtol=1e-12,
                               atol=1e-12)
    np.testing.assert_allclose(zero.second[1], plain.second[1], rtol=1e-12, atol=1e-12)


def test_five_bar_json_and_report():
    from mechplan.i18n import message
    from mechplan.report import text_report

    sol = _solve(_five_text(), at=(200.0,))
    fa = sol.extras["forces"]
    doc = json.loads(json.dumps(fa.json(0)))["friction"]
    fr = fa.friction
    assert doc["second_driver"]["link"] == "4"
    assert doc["second_driver"]["balancing_moment"] == pytest.approx(float(fr.second.value[0]))
    assert doc["second_driver"]["balancing_moment_without_friction"] == pytest.approx(
        float(fr.second.free[0]))
    assert doc["input_power"] == pytest.approx(
        float(fr.moment[0] * 10.0 + fr.second.value[0] * -10.0), rel=1e-12)
    assert doc["input_power_without_friction"] == pytest.approx(
        float(fr.free_moment[0] * 10.0 + fr.second.free[0] * -10.0), rel=1e-12)
    assert doc["efficiency"] == pytest.approx(doc["input_power_without_friction"]
                                              / doc["input_power"], rel=1e-12)
    assert doc["first_driver"]["power"] + doc["second_driver"]["power"] == pytest.approx(
        doc["input_power"])
    for lang in ("en", "ru", "vi", "zh"):
        text = text_report(sol, lang)
        head = message("frictionw2.report.efficiency", lang, eta="", power="").split("=")[0]
        assert head in text, lang
        assert message("frictionw2.report.second", lang, link="4", symbol="M_b", free="",
                       friction="").split("⁰")[0] in text, lang


# -- a crank and a cylinder: crank 1 about A, link 2 from B to C, the cylinder F–C ---------------
F_PIVOT = np.array([0.25, -0.05])
CRANK_CYLINDER = """title = "Crank and cylinder (W = 2)"
language = "en"

[ground]
A = ["0 mm", "0 mm"]
F = ["250 mm", "-50 mm"]

[links.1]
name = "crank"
lengths = {{ AB = "60 mm" }}

[links.2]
name = "coupler"
points = {{ B = ["0 mm", "0 mm"], C = ["200 mm", "0 mm"], P = ["100 mm", "40 mm"] }}

[links.3]
name = "barrel"
points = {{ F = ["0 mm", "0 mm"], K = ["100 mm", "0 mm"] }}
guides.bore = {{ through = "F", toward = "K" }}

[links.4]
name = "rod"
slides = {{ point = "C", on = "bore" }}

[[loads]]
type = "force"
point = "P"
link = "2"
vector = ["150 N", "-400 N"]

[[loads]]
type = "torque"
link = "2"
torque = "-5 N m"

[drive]
link = "1"
speed = "10 rad/s"
sense = "ccw"

[drive2]
kind = "cylinder"
link = "4"
speed = "{rate} m/s"
start = "200 mm"

[assembly]
C = "left of B->F"

[friction]
f = {f0}
pin_radius = "15 mm"
[friction.pairs]
"0-1" = {{ f = {f1}, radius = "20 mm" }}
"3-4" = {{ f = {f2} }}
"0-3" = {{ f = {f3}, radius = "25 mm" }}
"""
CC_F = {"f0": 0.1, "f1": 0.15, "f2": 0.2, "f3": 0.12}
F_P, T2C = np.array([150.0, -400.0]), -5.0
P_LOCAL = np.array([0.1, 0.04])


def _cc_text(scale: float = 1.0, rate: float = 0.05) -> str:
    return CRANK_CYLINDER.format(rate=rate, **{k: v * scale for k, v in CC_F.items()})


def _cc_points(phi1: float, rate: float = 0.05):
    b = 0.06 * np.array([math.cos(phi1), math.sin(phi1)])
    length = 0.2 + rate / 10.0 * phi1
    c = _meet(b, 0.2, F_PIVOT, length, left=True)
    u = (c - b) / 0.2
    p = b + P_LOCAL[0] * u + P_LOCAL[1] * np.array([-u[1], u[0]])
    return b, c, p


def _cc_omegas(phi1: float, rate: float = 0.05) -> dict[str, float]:
    def t_of(dt):
        return phi1 + 10.0 * dt

    def th2(ph):
        b, c, _ = _cc_points(ph, rate)
        return math.atan2(*(c - b)[::-1])

    def th3(ph):
        _, c, _ = _cc_points(ph, rate)
        return math.atan2(*(c - F_PIVOT)[::-1])
    w3 = _rate(th3, t_of)
    return {"1": 10.0, "2": _rate(th2, t_of), "3": w3, "4": w3}


def _cc_system(phi1: float, rho: dict[str, float], f34: float, rate: float = 0.05):
    """Unknowns R01, R12, R42 (force of i on j), F_d, N, M34, R03, M1; 12 equations."""
    b, c, p = _cc_points(phi1, rate)
    w = _cc_omegas(phi1, rate)
    u = (c - F_PIVOT) / np.hypot(*(c - F_PIVOT))
    n = np.array([-u[1], u[0]])

    def mf(r, key, j, i):
        rel = w[j] - (0.0 if i == "0" else w[i])
        return -rho[key] * np.hypot(*r) * np.sign(rel)

    def eq(x):
        r01, r12, r42 = x[0:2], x[2:4], x[4:6]
        fd, normal, m34 = x[6], x[7], x[8]
        r03, m1 = x[9:11], x[11]
        on_rod = fd * u + normal * n - f34 * abs(normal) * np.sign(rate) * u
        out = []
        out += [*(r01 - r12), _moment(np.zeros(2), r01) + _moment(b, -r12) + m1
                + mf(r01, "01", "1", "0") + mf(r12, "12", "1", "2")]
        out += [*(r12 + r42 + F_P), _moment(b, r12) + _moment(c, r42) + _moment(p, F_P) + T2C
                + mf(r12, "12", "2", "1") + mf(r42, "24", "2", "4")]
        # the rod: −R42 at C, the barrel's force and couple
        out += [*(-r42 + on_rod), _moment(c, -r42 + on_rod) + m34 + mf(r42, "24", "4", "2")]
        # the barrel: R03 at F, the rod's force at C and couple
        out += [*(r03 - on_rod), _moment(F_PIVOT, r03) + _moment(c, -on_rod) - m34
                + mf(r03, "03", "3", "0")]
        return np.array(out)
    return eq, w


def _cc_rho(scale: float = 1.0) -> tuple[dict[str, float], float]:
    f = {k: v * scale for k, v in CC_F.items()}
    return {"01": f["f1"] * 0.020, "12": f["f0"] * 0.015, "24": f["f0"] * 0.015,
            "03": f["f3"] * 0.025}, f["f2"]


def _cc_reference(phi1: float, rate: float = 0.05):
    rho, f34 = _cc_rho()
    free_eq, w = _cc_system(phi1, {k: 0.0 for k in rho}, 0.0, rate)
    free = _fsolve(free_eq, np.zeros(12))
    eq, _ = _cc_system(phi1, rho, f34, rate)
    x = _fsolve(eq, free)
    rels = {"01": w["1"], "12": w["2"] - w["1"], "24": w["4"] - w["2"], "03": w["3"]}
    rs = {"01": x[0:2], "12": x[2:4], "24": x[4:6], "03": x[9:11]}
    lost = -sum(rho[k] * np.hypot(*rs[k]) * abs(rels[k]) for k in rho)
    lost -= f34 * abs(x[7]) * abs(rate)
    return (x[11], x[6]), (free[11], free[6]), w, lost


def test_crank_cylinder_geometry():
    sol = _solve(_cc_text(), CC_ANGLES)
    for k, phi in enumerate(CC_ANGLES):
        b, c, p = _cc_points(math.radians(phi))
        for name, q in (("B", b), ("C", c), ("P", p)):
            np.testing.assert_allclose(sol.ev[sol.construction.position(name)][k], q, atol=1e-12)


def test_crank_moment_and_cylinder_force_with_friction_against_fsolve():
    fa = _solve(_cc_text(), CC_ANGLES).extras["forces"]
    fr = fa.friction
    assert fr is not None and fr.second is not None and fr.second.linear
    assert {q.pair for q in fr.pairs} == {"0-1", "1-2", "2-4", "0-3", "3-4"}
    assert np.all(fr.converged) and not np.any(fr.undefined)
    for k, phi in enumerate(CC_ANGLES):
        (m1, fd), (m10, fd0), _, lost = _cc_reference(math.radians(phi))
        assert float(fa.balancing_moment[k]) == pytest.approx(m1, rel=1e-8, abs=1e-9)
        assert float(fa.second[1][k]) == pytest.approx(fd, rel=1e-8, abs=1e-8)
        assert float(fr.second.value[k]) == pytest.approx(fd, rel=1e-8, abs=1e-8)
        assert float(fr.free_moment[k]) == pytest.approx(m10, rel=1e-9, abs=1e-10)
        assert float(fr.second.free[k]) == pytest.approx(fd0, rel=1e-9, abs=1e-9)
        p, p0 = m1 * 10.0 + fd * 0.05, m10 * 10.0 + fd0 * 0.05
        assert float(fr.input_power[k]) == pytest.approx(p, rel=1e-8)
        assert sum(float(q.power[k]) for q in fr.pairs) == pytest.approx(lost, rel=1e-8)
        assert (p > 0) == (phi != 140.0)
        if p > 0:
            assert float(fr.efficiency[k]) == pytest.approx(p0 / p, rel=1e-8)
            assert float(fr.efficiency_power[k]) == pytest.approx(1 + lost / p, rel=1e-8)
            assert float(fr.efficiency[k]) <= 1.0
        else:
            assert math.isnan(float(fr.efficiency[k]))
    np.testing.assert_allclose(fa.zhukovsky_moment, fa.balancing_moment, rtol=1e-9)


def test_crank_cylinder_friction_free_limit():
    plain_text = _cc_text().split("[friction]")[0]
    plain = _solve(plain_text, CC_ANGLES).extras["forces"]
    fr = _solve(_cc_text(), CC_ANGLES).extras["forces"].friction
    np.testing.assert_allclose(fr.free_moment, plain.balancing_moment, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(fr.second.free, plain.second[1], rtol=1e-9, atol=1e-10)
    tiny = _solve(_cc_text(scale=1e-9), CC_ANGLES).extras["forces"]
    np.testing.assert_allclose(tiny.balancing_moment, plain.balancing_moment, rtol=1e-8,
                               atol=1e-8)
    np.testing.assert_allclose(tiny.second[1], plain.second[1], rtol=1e-8, atol=1e-7)


# -- self-locking: crank 1 and a rotating guide (crank 4) with the block 3 pushed by the rod 2 -----
ROTATING_GUIDE = """title = "Crank and rotating guide (W = 2)"
language = "en"

[ground]
A = ["0 mm", "0 mm"]
E = ["200 mm", "0 mm"]

[links.1]
name = "crank"
lengths = {{ AB = "60 mm" }}

[links.2]
name = "rod"
lengths = {{ BC = "150 mm" }}

[links.3]
name = "block"
slides = {{ point = "C", on = "g" }}

[links.4]
name = "guide crank"
points = {{ E = ["0 mm", "0 mm"], D = ["100 mm", "0 mm"] }}
guides.g = {{ through = "E", toward = "D" }}

[[loads]]
type = "force"
point = "C"
link = "3"
along = ["E", "D"]
magnitude = "{load} N"

[drive]
link = "1"
speed = "10 rad/s"

[drive2]
link = "4"
speed = "4 rad/s"
phase = "150 deg"

[assembly]
C = "+"

[friction]
f = 0
pin_radius = "10 mm"
max_iterations = 400
[friction.pairs]
"3-4" = {{ f = {f} }}
"""


def _guide_geometry(phi1: float):
    """B, C (the root farther along the guide from E), the guide's unit u, s = |EC|."""
    b = 0.06 * np.array([math.cos(phi1), math.sin(phi1)])
    th4 = math.radians(150.0) + 0.4 * phi1
    u = np.array([math.cos(th4), math.sin(th4)])
    e = np.array([0.2, 0.0])
    # |e + s·u − b| = 0.15: s² + 2 s u·(e − b) + |e − b|² − 0.15² = 0
    half = float(u @ (e - b))
    s = -half + math.sqrt(half * half - float((e - b) @ (e - b)) + 0.15 ** 2)
    return b, e + s * u, u, s


def _guide_case(phi1: float):
    """(the sense of the block's sliding on the guide, cos α, sin α) of the rod to the guide."""
    h = 1e-6
    s = [_guide_geometry(phi1 + 10.0 * k * h)[3] for k in (-2, -1, 1, 2)]
    sliding = (s[0] - 8 * s[1] + 8 * s[2] - s[3]) / (12 * h)
    b, c, u, _ = _guide_geometry(phi1)
    along = (c - b) / 0.15
    return math.copysign(1.0, sliding), abs(float(along @ u)), abs(cross(u, along))


def _unchecked(text: str, deg: float):
    """The force analysis at one angle without the solve's refusal of a self-locked position."""
    from mechplan.dynamics.kinetostatics import analyse_forces
    from mechplan.solve import build

    scene = parse_scene(text, "scene.toml")
    loading = Loading.from_scene(scene)
    _, c = build(scene, PLANS, loading)
    ev = c.evaluate(np.radians([deg]))
    return analyse_forces(c, ev, scene.mechanism, loading)


@pytest.mark.parametrize("deg", [0.0, 100.0, 120.0, 340.0])
def test_self_locking_with_two_drivers_where_the_tilted_reaction_says_so(deg):
    """Friction only between the block and the rotating guide, a resistance P along the guide:
    the rod (a two-force member) pushes the block with T(cos α − f·sin α) = P, so T grows without
    bound as f·tan α → 1. Below (f·tan α = 0.9) the passes settle on that T and both balancing
    moments are given; above (1.1) the position is flagged, neither moment with friction nor η is
    given, and a solve at that angle is refused with the reason."""
    phi1 = math.radians(deg)
    sense, cos_a, sin_a = _guide_case(phi1)
    _, c, _, _ = _guide_geometry(phi1)
    load = -100.0 * sense                      # against the block's sliding
    f_lock = cos_a / sin_a
    settled = _solve(ROTATING_GUIDE.format(load=load, f=0.9 * f_lock), (deg,))
    np.testing.assert_allclose(settled.ev[settled.construction.position("C")][0], c,
                               atol=1e-12)
    fa = settled.extras["forces"]
    fr = fa.friction
    assert fr.converged[0] and fr.second is not None
    rod = np.hypot(*fa.reactions["23"].force[0])
    assert rod == pytest.approx(100.0 / (cos_a - 0.9 * f_lock * sin_a), rel=1e-9)
    assert math.isfinite(float(fr.moment[0])) and math.isfinite(float(fr.second.value[0]))
    fa = _unchecked(ROTATING_GUIDE.format(load=load, f=1.1 * f_lock), deg)
    fr = fa.friction
    assert not fr.converged[0]
    assert math.isnan(float(fr.moment[0])) and math.isnan(float(fr.second.value[0]))
    assert math.isnan(float(fr.efficiency[0])) and math.isnan(float(fr.input_power[0]))
    doc = fa.json(0)["friction"]
    assert doc["converged"] is False and doc["efficiency"] is None
    assert doc["second_driver"]["balancing_moment"] is None
    assert doc["second_driver"]["balancing_moment_without_friction"] is not None


def test_a_self_locked_position_with_two_drivers_is_refused(tmp_path):
    from mechplan.errors import SingularError
    from mechplan.scene import load_scene
    from mechplan.solve import solve as solve_scene

    sense, cos_a, sin_a = _guide_case(math.radians(100.0))
    text = ROTATING_GUIDE.format(load=-100.0 * sense, f=1.1 * cos_a / sin_a)
    path = tmp_path / "lock.toml"
    path.write_text(text + '\n[positions]\nat = ["100 deg"]\n', encoding="utf-8")
    with pytest.raises(SingularError, match="self-locks"):
        solve_scene(load_scene(path))


def test_a_held_cylinder_has_no_relative_motion_and_no_friction():
    """The excavator arm with its arm cylinder held (`[drive2] hold`): the arm turns with the boom,
    so the pairs at E, F, G and the arm cylinder's rod in its barrel do not move relative to each
    other; the sense of their friction is undefined (flagged) and their friction is zero, not a
    rounding-level rate's random sign. The held cylinder gives no power: η = F_d⁰/F_d."""
    text = (TEMPLATES / "excavator_arm.toml").read_text(encoding="utf-8")
    text = text.replace('speed = "0.075 m/s"\nstart = "2700 mm"', 'hold = "2700 mm"')
    text += '\n[friction]\nf = 0.1\npin_radius = "40 mm"\n'
    scene = parse_scene(text, "held.toml")
    fa = solve(scene, plans=PLANS, loading=Loading.from_scene(scene)).extras["forces"]
    fr = fa.friction
    assert np.all(fr.converged) and fr.second is not None and fr.second.link == "7"
    still = {p.pair: p for p in fr.pairs if p.pair in {"2-5", "2-6", "5-7", "6-7"}}
    assert len(still) == 4
    for p in still.values():
        assert np.all(p.undefined) and np.all(p.load == 0.0)
    assert all(fa.json(k)["friction"]["undefined_sense"] == ["2-5", "2-6", "5-7", "6-7"]
               for k in range(len(fa.phi)))
    np.testing.assert_array_equal(fr.second.rate, 0.0)
    # nothing in the arm's group rubs: the holding force is the friction-free one
    np.testing.assert_allclose(fr.second.value, fr.second.free, rtol=1e-12)
    np.testing.assert_allclose(fr.efficiency, fr.free_moment / fr.moment, rtol=1e-12)
    np.testing.assert_allclose(fr.efficiency, fr.efficiency_power, rtol=1e-10)
    assert np.all((fr.efficiency > 0.9) & (fr.efficiency < 1.0))
    doc = fa.json(0)["friction"]
    assert doc["second_driver"]["driving_force"] == pytest.approx(float(fa.second[1][0]))
    assert doc["second_driver"]["power"] == 0.0 and doc["second_driver"]["ratio"] is None
    assert doc["input_power"] == pytest.approx(doc["first_driver"]["power"])


@pytest.mark.parametrize("case", ["crank_slider", "slider_crank", "cylinder_slider",
                                  "slider_slider", "cylinder_crank"])
def test_every_order_of_driver_kinds_balances_the_power_with_friction(case):
    """The loaded machines of tests/dynamics/test_second_driver_kinds_forces.py with friction in
    every pair: the drivers' input power with friction covers the loads' and the friction's
    (η = P⁰/P equals 1 − |ΣP_f|/P), Zhukovsky's lever with the second driver's value agrees,
    and f = 0 gives each driver's frictionless value."""
    import sys

    sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
    sys.path.insert(0, str(Path(__file__).parent))
    from test_second_driver_kinds import CASES
    from test_second_driver_kinds_forces import loaded

    def run(text):
        scene = parse_scene(text, "kinds.toml")
        return solve(scene, at_deg=list(CASES[case])).extras["forces"]
    friction = '\n[friction]\nf = {f}\npin_radius = "10 mm"\n'
    fa = run(loaded(case) + friction.format(f=0.1))
    plain = run(loaded(case))
    fr = fa.friction
    assert np.all(fr.converged) and fr.second is not None
    lost = sum(p.power for p in fr.pairs)
    np.testing.assert_allclose(fr.free_input_power - fr.input_power, lost, rtol=1e-9,
                               atol=1e-9 * np.abs(fr.input_power).max())
    ok = fr.input_power > 0
    assert ok.any()
    np.testing.assert_allclose(fr.efficiency[ok], fr.efficiency_power[ok], rtol=1e-9)
    assert np.all(fr.efficiency[ok] <= 1.0) and np.all(np.isnan(fr.efficiency[~ok]))
    np.testing.assert_allclose(fa.zhukovsky_moment, fa.balancing_moment, rtol=1e-9)
    np.testing.assert_allclose(fr.free_moment, plain.balancing_moment, rtol=1e-9)
    np.testing.assert_allclose(fr.second.free, plain.second[1], rtol=1e-9)
    zero = run(loaded(case) + friction.format(f=0))
    np.testing.assert_allclose(zero.balancing_moment, plain.balancing_moment, rtol=1e-12)
    np.testing.assert_allclose(zero.second[1], plain.second[1], rtol=1e-12)
