"""New loads (force along a turning line, spring, double-acting cylinder, torque) and friction in
the pairs, against independent computations: virtual power with finite-difference velocities of
the loop-closure solution, each link's equilibrium with friction solved by scipy's fsolve, the
friction-free limit and a closed form of the efficiency."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechplan.construct.builder import build_construction
from mechplan.dynamics import Loading
from mechplan.dynamics.kinetostatics import analyse_forces
from mechplan.errors import SceneError
from mechplan.model.structure import analyse
from mechplan.scene import parse_scene

PLANS = ("position", "velocity", "acceleration", "force")
R, L, E_OFF = 0.1, 0.4, 0.02           # crank, rod, offset of the guide (m)
W1 = 1500 * math.pi / 30               # rad/s

BASE = """
title = "t"
[ground]
O = ["0 mm", "0 mm"]
D = ["150 mm", "200 mm"]
guides.x = { through = "G", angle = "0 deg" }
G = ["0 mm", "-20 mm"]
[links.1]
lengths = { OA = "100 mm" }
[links.2]
lengths = { AB = "400 mm" }
points = { S2 = "0.3 of A B", E = "0.5 of A B" }
%(rod_mass)s
[links.3]
slides = { point = "B", on = "x" }
%(slider_mass)s
[drive]
link = "1"
speed = "1500 rpm"
sense = "ccw"
from = "+x"
[positions]
count = 12
"""

LOADS = """
[[loads]]
type = "spring"
between = ["E", "D"]
stiffness = "20 N/mm"
free_length = "100 mm"
preload = "50 N"
[[loads]]
type = "cylinder"
between = ["A", "B"]
links = ["2", "3"]
bore = "80 mm"
rod = "40 mm"
pressure = "1 MPa"
pressure_rod = "0.3 MPa"
[[loads]]
type = "force"
point = "S2"
along = ["A", "B"]
angle = "30 deg"
magnitude = "500 N"
[[loads]]
type = "torque"
link = "2"
torque = "20 N*m"
[[loads]]
type = "force"
point = "B"
vector = ["-1500 N", "0 N"]
"""

MASSES = {"rod_mass": 'mass = "4 kg"\ncentre = "S2"\nJ = "0.06 kg*m^2"',
          "slider_mass": 'mass = "3 kg"'}
NO_MASSES = {"rod_mass": "", "slider_mass": ""}


def scene(text: str):
    return parse_scene(text, "t.toml")


def solve(sc, phi):
    loading = Loading.from_scene(sc)
    c = build_construction(sc.mechanism, analyse(sc.mechanism), PLANS, sc.assembly_phi,
                           sc.path, loading)
    ev = c.evaluate(np.asarray(phi, dtype=float))
    return c, ev, analyse_forces(c, ev, sc.mechanism, loading)


# -- the loop closure of the offset slider-crank, solved here (outer assembly, B to the right) -----
def points(phi):
    a = np.stack((R * np.cos(phi), R * np.sin(phi)), axis=-1)
    yb = -E_OFF
    xb = a[..., 0] + np.sqrt(L ** 2 - (a[..., 1] - yb) ** 2)
    b = np.stack((xb, np.full_like(xb, yb)), axis=-1)
    return {"A": a, "B": b, "S2": a + 0.3 * (b - a), "E": a + 0.5 * (b - a)}


def rod_angle(phi):
    p = points(phi)
    d = p["B"] - p["A"]
    return np.arctan2(d[..., 1], d[..., 0])


def d_dphi(f, phi, h=1e-6):
    return (f(phi + h) - f(phi - h)) / (2 * h)


def d2_dphi2(f, phi, h=1e-4):
    return (f(phi + h) - 2 * f(phi) + f(phi - h)) / h ** 2


def velocity(name, phi):
    return W1 * d_dphi(lambda x: points(x)[name], phi)


def acceleration(name, phi):
    return W1 ** 2 * d2_dphi2(lambda x: points(x)[name], phi)


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


ANGLES = np.radians([10.0, 35.0, 80.0, 100.0, 150.0, 200.0, 250.0, 290.0, 330.0])


def test_balancing_moment_of_the_new_loads_by_virtual_power():
    """Σ(power of every load and inertia force) + M_b·ω1 = 0, velocities by finite differences."""
    _, _, fa = solve(scene(BASE % MASSES + LOADS), ANGLES)
    p = points(ANGLES)
    power = np.zeros_like(ANGLES)
    # spring E–D: tension 50 N + 20 000 N/m·(|ED| − 0.1 m) pulls E towards D
    d = np.array([0.15, 0.2])
    length = np.linalg.norm(d - p["E"], axis=-1)
    tension = 50.0 + 20_000.0 * (length - 0.1)
    power += np.sum(tension[:, None] * unit(d - p["E"]) * velocity("E", ANGLES), axis=-1)
    # cylinder A–B pushes its ends apart: 1 MPa·π·0.08²/4 − 0.3 MPa·π(0.08² − 0.04²)/4
    push = 1e6 * math.pi * 0.08 ** 2 / 4 - 0.3e6 * math.pi * (0.08 ** 2 - 0.04 ** 2) / 4
    e_ab = unit(p["B"] - p["A"])
    power += push * np.sum(e_ab * (velocity("B", ANGLES) - velocity("A", ANGLES)), axis=-1)
    # 500 N at S2 along A→B turned by 30°
    c30, s30 = math.cos(math.radians(30)), math.sin(math.radians(30))
    f_s2 = 500.0 * np.stack((c30 * e_ab[:, 0] - s30 * e_ab[:, 1],
                             s30 * e_ab[:, 0] + c30 * e_ab[:, 1]), axis=-1)
    power += np.sum(f_s2 * velocity("S2", ANGLES), axis=-1)
    # torque 20 N·m on the rod, −1500 N along x on the slider
    w2 = W1 * d_dphi(rod_angle, ANGLES)
    power += 20.0 * w2
    power += -1500.0 * velocity("B", ANGLES)[:, 0]
    # inertia: −m·a_S, −J·ε
    power += np.sum(-4.0 * acceleration("S2", ANGLES) * velocity("S2", ANGLES), axis=-1)
    power += np.sum(-3.0 * acceleration("B", ANGLES) * velocity("B", ANGLES), axis=-1)
    eps2 = W1 ** 2 * d2_dphi2(rod_angle, ANGLES)
    power += -0.06 * eps2 * w2
    expected = -power / W1
    scale = np.abs(expected).max()
    assert scale > 100.0
    np.testing.assert_allclose(fa.balancing_moment, expected, atol=1e-6 * scale)
    np.testing.assert_allclose(fa.zhukovsky_moment, expected, atol=1e-6 * scale)
    np.testing.assert_allclose(fa.reduced_moment, -expected - _inertia_part(ANGLES),
                               atol=1e-6 * scale)


def _inertia_part(phi):
    """The inertia forces' share of −M_b (M_red excludes inertia): their power over ω1."""
    w2 = W1 * d_dphi(rod_angle, phi)
    eps2 = W1 ** 2 * d2_dphi2(rod_angle, phi)
    p = (np.sum(-4.0 * acceleration("S2", phi) * velocity("S2", phi), axis=-1)
         + np.sum(-3.0 * acceleration("B", phi) * velocity("B", phi), axis=-1) - 0.06 * eps2 * w2)
    return p / W1


FRICTION = """
[friction]
f = %(f)s
pin_radius = "15 mm"
[friction.pairs]
"0-1" = { f = 0.08, radius = "25 mm" }
"0-3" = { f = 0.12 }
"""


def test_friction_free_limit_equals_todays_result():
    plain = solve(scene(BASE % MASSES + LOADS), ANGLES)[2]
    zero = solve(scene(BASE % MASSES + LOADS + (FRICTION % {"f": 0}).replace(
        '{ f = 0.08, radius = "25 mm" }', '{ f = 0.0 }').replace("{ f = 0.12 }", "{ f = 0.0 }")),
        ANGLES)[2]
    np.testing.assert_array_equal(zero.balancing_moment, plain.balancing_moment)
    tiny = solve(scene(BASE % MASSES + LOADS + (FRICTION % {"f": 1e-9}).replace(
        "0.08", "1e-9").replace("0.12", "1e-9")), ANGLES)[2]
    scale = np.abs(plain.balancing_moment).max()
    np.testing.assert_allclose(tiny.balancing_moment, plain.balancing_moment, atol=1e-6 * scale)
    assert tiny.friction is not None
    np.testing.assert_allclose(tiny.friction.free_moment, plain.balancing_moment, rtol=1e-12,
                               atol=1e-9 * scale)


def _fsolve_reference(phi: float, f_pin: float, r_pin: float, f_o: float, r_o: float,
                      f_guide: float) -> float:
    """M_b with friction from every link's equilibrium written as one nonlinear system.

    Massless links; loads on the rod: 500 N at S2 along A→B turned 30°, a 20 N·m torque; on the
    slider −1500 N along x. Unknowns: R12 (2), R23 (2), N03, R01 (2), M_b.
    """
    p = points(np.array([phi]))
    a, b, s2 = p["A"][0], p["B"][0], p["S2"][0]
    e_ab = unit(b - a)
    c30, s30 = math.cos(math.radians(30)), math.sin(math.radians(30))
    f_s2 = 500.0 * np.array([c30 * e_ab[0] - s30 * e_ab[1], s30 * e_ab[0] + c30 * e_ab[1]])
    w2 = float(W1 * d_dphi(rod_angle, np.array([phi]))[0])
    vb = float(velocity("B", np.array([phi]))[0, 0])

    def cross(u, v):
        return u[0] * v[1] - u[1] * v[0]

    def equations(x):
        r12, r23, n03, r01, mb = x[0:2], x[2:4], x[4], x[5:7], x[7]
        # friction couples: on link j from link i, against ω_j − ω_i
        m12_on2 = -f_pin * r_pin * np.hypot(*r12) * np.sign(w2 - W1)
        m32_on2 = -f_pin * r_pin * np.hypot(*r23) * np.sign(w2 - 0.0)
        m01_on1 = -f_o * r_o * np.hypot(*r01) * np.sign(W1)
        friction_3 = -f_guide * abs(n03) * np.sign(vb)
        # slider: R23 + N + friction + load = 0
        eq3 = r23 + np.array([friction_3 - 1500.0, n03])
        # rod: R12 + R32 + F_S2 = 0; moments about A
        eq2 = r12 - r23 + f_s2
        m2 = cross(b - a, -r23) + cross(s2 - a, f_s2) + 20.0 + m12_on2 + m32_on2
        # crank: R01 + R21 = 0; moments about O: M_b + A × R21 + couples
        eq1 = r01 - r12
        m1 = mb + cross(a, -r12) + m01_on1 - m12_on2
        return [*eq3, *eq2, m2, *eq1, m1]

    x0 = np.zeros(8)
    x0[2:4] = [1500.0, 0.0]
    sol, _info, ok, msg = fsolve(equations, x0, full_output=True, xtol=1e-13)
    # "no further improvement" at the last digits is fine when the equations hold
    assert ok in (1, 3), msg
    assert np.abs(equations(sol)).max() < 1e-8
    return float(sol[7])


FSOLVE_SCENE = BASE % NO_MASSES + LOADS.split("[[loads]]\ntype = \"spring\"")[0] + """
[[loads]]
type = "force"
point = "S2"
along = ["A", "B"]
angle = "30 deg"
magnitude = "500 N"
[[loads]]
type = "torque"
link = "2"
torque = "20 N*m"
[[loads]]
type = "force"
point = "B"
vector = ["-1500 N", "0 N"]
[friction]
f = 0.1
pin_radius = "15 mm"
[friction.pairs]
"0-1" = { f = 0.08, radius = "25 mm" }
"0-3" = { f = 0.12 }
"""


@pytest.mark.parametrize("deg", [20.0, 60.0, 120.0, 160.0, 210.0, 300.0])
def test_friction_against_fsolve_of_each_links_equilibrium(deg):
    phi = math.radians(deg)
    _, _, fa = solve(scene(FSOLVE_SCENE), [phi])
    expected = _fsolve_reference(phi, 0.1, 0.015, 0.08, 0.025, 0.12)
    assert fa.friction is not None
    assert fa.friction.passes >= 3 and fa.friction.residual[0] < 1e-10
    assert abs(fa.balancing_moment[0] - expected) < 1e-8 * abs(expected)
    # the friction-free limit of the same reference is the friction-free moment
    free = _fsolve_reference(phi, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert abs(fa.friction.free_moment[0] - free) < 1e-8 * abs(free)
    assert abs(fa.zhukovsky_moment[0] - expected) < 1e-8 * abs(expected)


CLOSED = """
title = "t"
[ground]
O = ["0 mm", "0 mm"]
guides.x = { through = "O", angle = "0 deg" }
[links.1]
lengths = { OA = "100 mm" }
[links.2]
lengths = { AB = "400 mm" }
[links.3]
slides = { point = "B", on = "x" }
[drive]
link = "1"
speed = "100 rpm"
sense = "ccw"
from = "+x"
[[loads]]
type = "force"
point = "B"
vector = ["1000 N", "0 N"]
[friction]
f = 0
[friction.pairs]
"0-3" = { f = 0.15 }
"""


def test_efficiency_of_the_tilted_guide_reaction_closed_form():
    """Central slider-crank at φ = 90°, friction only in the guide, a resistance P along the
    guide: the slider's reaction is tilted by φ_f = atan f, so T(cos β − f sin β) = P and
    η = 1 − f·tan β = cos(β + φ_f)/(cos β·cos φ_f), sin β = r/l."""
    _, _, fa = solve(scene(CLOSED), [math.pi / 2])
    beta, phi_f = math.asin(0.1 / 0.4), math.atan(0.15)
    expected = math.cos(beta + phi_f) / (math.cos(beta) * math.cos(phi_f))
    assert abs(expected - (1 - 0.15 * math.tan(beta))) < 1e-15
    assert fa.friction is not None
    assert abs(fa.friction.efficiency[0] - expected) < 1e-12
    assert abs(fa.friction.efficiency_power[0] - expected) < 1e-12
    assert abs(fa.friction.free_moment[0] - 0.1 * 1000.0) < 1e-9


def test_undefined_sense_of_friction_is_flagged_at_the_dead_centre():
    _, _, fa = solve(scene(CLOSED), [0.0, math.pi / 2])
    assert fa.friction is not None
    assert list(fa.friction.undefined) == [True, False]
    assert fa.json(0)["friction"]["undefined_sense"] == ["0-3"]
    assert math.isnan(fa.friction.efficiency[0])


SPRING = '[[loads]]\ntype = "spring"\nbetween = %s\nstiffness = "1 N/mm"\nfree_length = "1 mm"\n'


@pytest.mark.parametrize(("extra", "words"), [
    (SPRING % '["E", "Q"]', "unknown point 'Q'"),
    ('[[loads]]\ntype = "cylinder"\nbetween = ["A", "B"]\nlinks = ["2", "3"]\n'
     + 'bore = "40 mm"\nrod = "40 mm"\n', "smaller than the bore"),
    (SPRING % '["A", "B"]', "say which one"),
])
def test_load_errors_name_the_key(extra, words):
    with pytest.raises(SceneError, match=words):
        scene(BASE % NO_MASSES + extra)


def test_friction_pair_must_exist():
    text = BASE % NO_MASSES + LOADS + '[friction]\nf = 0.1\n[friction.pairs]\n"1-3" = { f = 0.2 }\n'
    with pytest.raises(SceneError, match="no pair 1-3"):
        solve(scene(text), [0.3])


QUICK_RETURN = """
title = "qr"
[ground]
O1 = ["0 mm", "0 mm"]
O3 = ["0 mm", "-300 mm"]
[links.1]
lengths = { O1A = "100 mm" }
[links.2]
slides = { point = "A", on = "slot" }
[links.3]
lengths = { O3B = "600 mm" }
guides.slot = { through = "O3", toward = "B" }
[drive]
link = "1"
speed = "10 rad/s"
sense = "ccw"
from = "+x"
[[loads]]
type = "force"
point = "B"
vector = ["-500 N", "0 N"]
[friction]
f = 0.1
pin_radius = "20 mm"
[friction.pairs]
"2-3" = { f = 0.15 }
"""


def _quick_return_solve(phi: float, f: float, x0: np.ndarray) -> np.ndarray:
    """The unknowns (R12, N, M32, R03, R01, M_b) of the crank-coulisse mechanism with friction
    in its four pairs, from the three links' equilibrium (the block's slot reaction N ⊥ the slot
    with a couple, the slot's friction f_s·|N| against the block's sliding relative to the
    coulisse). f = 0: no friction at all."""
    w1, rho, f_s = 10.0, f * 0.02, 1.5 * f
    o3 = np.array([0.0, -0.3])

    def geometry(x):
        a = 0.1 * np.array([math.cos(x), math.sin(x)])
        return a, math.atan2(a[1] - o3[1], a[0] - o3[0])

    a, th3 = geometry(phi)
    h = 1e-6
    w3 = w1 * (geometry(phi + h)[1] - geometry(phi - h)[1]) / (2 * h)
    u = np.array([math.cos(th3), math.sin(th3)])
    n = np.array([-u[1], u[0]])
    b = o3 + 0.6 * u
    v_rel = w1 * np.array([-a[1], a[0]]) - w3 * np.array([-(a - o3)[1], (a - o3)[0]])
    sense = np.sign(v_rel @ u)

    def cross(p, q):
        return p[0] * q[1] - p[1] * q[0]

    def equations(x):
        r12, nn, m32, r03, r01, mb = x[0:2], x[2], x[3], x[4:6], x[6:8], x[8]
        f32 = nn * n - f_s * abs(nn) * sense * u          # force of 3 on 2 at A
        mf12_on2 = -rho * np.hypot(*r12) * np.sign(w3 - w1)
        mf03_on3 = -rho * np.hypot(*r03) * np.sign(w3)
        mf01_on1 = -rho * np.hypot(*r01) * np.sign(w1)
        eq2 = r12 + f32
        m2 = m32 + mf12_on2
        eq3 = r03 - f32 + np.array([-500.0, 0.0])
        m3 = cross(a - o3, -f32) - m32 + cross(b - o3, np.array([-500.0, 0.0])) + mf03_on3
        eq1 = r01 - r12
        m1 = mb + cross(a, -r12) + mf01_on1 - mf12_on2
        return [*eq2, m2, *eq3, m3, *eq1, m1]

    sol, _info, ok, msg = fsolve(equations, x0, full_output=True, xtol=1e-13)
    assert ok in (1, 3), msg
    assert np.abs(equations(sol)).max() < 1e-8
    return sol


def _quick_return_reference(phi: float, f: float) -> float:
    """M_b with friction f; fsolve starts from the friction-free equilibrium (|N| has a kink)."""
    x0 = np.zeros(9)
    x0[2] = 500.0
    free = _quick_return_solve(phi, 0.0, x0)
    return float((free if f == 0 else _quick_return_solve(phi, f, free))[8])


@pytest.mark.parametrize("deg", [15.0, 70.0, 130.0, 200.0, 260.0, 320.0])
def test_coulisse_friction_against_fsolve(deg):
    """Friction in a prismatic pair between two moving links (block in the coulisse's slot)."""
    phi = math.radians(deg)
    _, _, fa = solve(scene(QUICK_RETURN), [phi])
    expected = _quick_return_reference(phi, 0.1)
    assert abs(fa.balancing_moment[0] - expected) < 1e-8 * abs(expected)
    assert abs(fa.zhukovsky_moment[0] - expected) < 1e-8 * abs(expected)
    assert fa.friction is not None
    free = _quick_return_reference(phi, 0.0)
    assert abs(fa.friction.free_moment[0] - free) < 1e-8 * abs(free)


def test_self_locking_where_the_tilted_reaction_says_so():
    """Central slider-crank, friction only in the guide (f = 1.5), a resistance along the guide:
    T(cos β − f sin β) = P has a positive T only while f·tan β < 1 (η = 1 − f tan β > 0). Beyond,
    the iteration cannot settle: the position is flagged, M_b with friction not given, and a
    solve at that angle is refused with the reason."""
    text = CLOSED.replace('"0-3" = { f = 0.15 }', '"0-3" = { f = 1.5 }').replace(
        '"400 mm"', '"150 mm"')
    phi = np.radians([20.0, 30.0, 60.0, 90.0, 120.0, 150.0, 160.0])
    _, _, fa = solve(scene(text), phi)
    beta = np.arcsin(0.1 * np.sin(phi) / 0.15)
    locks = 1.5 * np.tan(beta) >= 1.0
    assert locks.any() and (~locks).any()
    assert fa.friction is not None
    assert list(~fa.friction.converged) == list(locks)
    assert np.all(np.isnan(fa.friction.moment[locks]))
    ok = ~locks
    np.testing.assert_allclose(fa.friction.efficiency[ok], 1 - 1.5 * np.tan(beta[ok]),
                               rtol=1e-10)
    assert fa.json(int(np.argmax(locks)))["friction"]["converged"] is False


def test_a_self_locked_position_is_refused_with_its_reason(tmp_path):
    from mechplan.errors import SingularError
    from mechplan.scene import load_scene
    from mechplan.solve import solve as solve_scene

    text = CLOSED.replace('"0-3" = { f = 0.15 }', '"0-3" = { f = 1.5 }').replace(
        '"400 mm"', '"150 mm"') + "[positions]\nat = [\"90 deg\"]\n"
    path = tmp_path / "lock.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(SingularError, match="self-locks"):
        solve_scene(load_scene(path))
