"""A cylinder whose group is an RRP dyad: the link it drives slides on a guide (of the frame, or
of a turning crank, W = 2). Kinematics against the loop closure in closed form (the pin K on its
guide line at the cylinder's length from the barrel's pivot: a quadratic) and an independent
dyad solved by scipy, with five-point finite differences in time; driving forces and moments
against the virtual power of the loads with each driver moving alone. Nothing of mechplan's
construction is used.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechplan.errors import TopologyError
from mechplan.model.structure import analyse
from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

KIN = ("position", "velocity", "acceleration")
ALL = (*KIN, "force")

PRESS = """
title = "A carriage pushed by a cylinder along a guide, driving a rocker"
language = "en"

[ground]
F = ["0 mm", "0 mm"]
G = ["0 mm", "100 mm"]
D = ["350 mm", "300 mm"]
guides.g = { through = "G", angle = "0 deg" }

[links.1]
name = "carriage"
points = { C = ["0 mm", "80 mm"] }
slides = { point = "K", on = "g" }
MASS1

[links.2]
name = "barrel"
points = { F = ["0 mm", "0 mm"], T = ["150 mm", "0 mm"] }
guides.bore = { through = "F", toward = "T" }
MASS2

[links.3]
name = "rod"
slides = { point = "K", on = "bore" }
MASS3

[links.4]
name = "connecting rod"
lengths = { CE = "200 mm" }
MASS4

[links.5]
name = "rocker"
lengths = { DE = "120 mm" }
MASS5

[drive]
kind = "cylinder"
link = "3"
speed = "0.1 m/s"
acceleration = "0.3 m/s^2"
range = ["250 mm", "400 mm"]

LOADS
[assembly]
K = "right of F->G"
E = "left of C->D"

[positions]
count = 6
"""

PRESS_MASSES = {
    "MASS1": 'mass = "5 kg"\ncentre = "C"\nJ = "0.02 kg*m^2"',
    "MASS2": "",
    "MASS3": 'mass = "1 kg"\ncentre = "K"',
    "MASS4": 'points = { S4 = "0.5 of C E" }\nmass = "1 kg"\ncentre = "S4"\nJ = "0.005 kg*m^2"',
    "MASS5": 'points = { S5 = "0.5 of D E" }\nmass = "2 kg"\ncentre = "S5"\nJ = "0.01 kg*m^2"',
    "LOADS": '[gravity]\ng = "9.81 m/s^2"\n\n[[loads]]\ntype = "force"\npoint = "E"\nlink = "5"\n'
             'vector = ["40 N", "-30 N"]\n',
}


def press_text(loaded: bool = False) -> str:
    text = PRESS
    for key, value in PRESS_MASSES.items():
        if key == "MASS2":      # the barrel's mass: at T, with its J
            value = 'mass = "3 kg"\ncentre = "T"\nJ = "0.03 kg*m^2"'
        text = text.replace(key, value if loaded else "")
    return text


def _e(a: float) -> np.ndarray:
    return np.array([math.cos(a), math.sin(a)])


def _circle_circle_left(c: np.ndarray, rc: float, d: np.ndarray, rd: float) -> np.ndarray:
    """The meet of two circles left of c→d, solved by scipy from a crude start."""
    u = (d - c) / np.linalg.norm(d - c)
    guess = (c + d) / 2 + 0.1 * np.array([-u[1], u[0]])
    x = fsolve(lambda p: [np.hypot(*(p - c)) - rc, np.hypot(*(p - d)) - rd], guess, xtol=1e-13)
    assert (d - c)[0] * (x - c)[1] - (d - c)[1] * (x - c)[0] > 0
    return x


def press_state(length: float) -> np.ndarray:
    """(K, C, E, S4, S5, T, θ_barrel, θ4, θ5) at the cylinder's length (m)."""
    x = math.sqrt(length * length - 0.1 * 0.1)          # K = (x, 0.1), right of F→G
    k = np.array([x, 0.1])
    c = k + np.array([0.0, 0.08])
    d = np.array([0.35, 0.30])
    e = _circle_circle_left(c, 0.2, d, 0.12)
    tb = math.atan2(k[1], k[0])
    t4, t5 = math.atan2(*(e - c)[::-1]), math.atan2(*(e - d)[::-1])
    return np.concatenate([k, c, e, (c + e) / 2, (d + e) / 2, 0.15 * _e(tb), [tb, t4, t5]])


def _fd(fun, t0: float, rate: float, acc: float, h: float = 1e-4):
    xs = [fun(t0 + rate * k * h + acc * (k * h) ** 2 / 2) for k in (-2, -1, 0, 1, 2)]
    d1 = (xs[0] - 8 * xs[1] + 8 * xs[3] - xs[4]) / (12 * h)
    d2 = (-xs[0] + 16 * xs[1] - 30 * xs[2] + 16 * xs[3] - xs[4]) / (12 * h * h)
    return xs[2], d1, d2


@pytest.mark.parametrize("l_mm", [255.0, 300.0, 360.0, 395.0])
def test_a_cylinder_pushing_a_carriage_equals_the_loop_closure(l_mm):
    sol = solve(parse_scene(press_text(), "press.toml"), at_deg=[l_mm], plans=KIN)
    c, ev = sol.construction, sol.ev
    x, v, a = _fd(press_state, l_mm / 1000, 0.1, 0.3)
    for i, p in enumerate("KCE"):
        np.testing.assert_allclose(ev[c.position(p)][0], x[2 * i:2 * i + 2], atol=1e-14)
        np.testing.assert_allclose(ev[c.velocity_image(p)][0], v[2 * i:2 * i + 2], atol=1e-9)
        np.testing.assert_allclose(ev[c.acceleration_image(p)][0], a[2 * i:2 * i + 2],
                                   atol=2e-6)
    for link, i in (("2", 12), ("3", 12), ("4", 13), ("5", 14)):
        assert ev[c.omega(link)][0] == pytest.approx(v[i], rel=1e-8, abs=1e-9), link
        assert ev[c.epsilon(link)][0] == pytest.approx(a[i], rel=1e-5, abs=1e-5), link
    assert ev[c.omega("1")][0] == 0.0


def test_structure_and_protocol_name_the_driven_rrp_group():
    from mechplan.construct.protocol import protocol
    from mechplan.model.plans import Plan

    scene = parse_scene(press_text(), "press.toml")
    st = analyse(scene.mechanism)
    assert st.formula == "I(2,3) → II(2,1) → II(4,5)"
    assert [g.kind.value for g in st.groups] == ["RRP", "RRR"]
    for lang in ("en", "ru", "vi", "zh"):
        sol = solve(scene, at_deg=[300.0], plans=KIN)
        lines = protocol(sol.construction, sol.ev, 0, lang, sol.scales, (Plan.POSITION,))
        assert any(label == "K" and "g" in text for _, label, text in lines), lang


def _virtual(fun, q: float, e: float = 1e-6) -> np.ndarray:
    return (fun(q - 2 * e) - 8 * fun(q - e) + 8 * fun(q + e) - fun(q + 2 * e)) / (12 * e)


@pytest.mark.parametrize("l_mm", [260.0, 320.0, 390.0])
def test_the_press_driving_force_equals_virtual_power(l_mm):
    sol = solve(parse_scene(press_text(loaded=True), "press.toml"), at_deg=[l_mm], plans=ALL)
    fa = sol.extras["forces"]
    q = l_mm / 1000
    _, _, acc = _fd(press_state, q, 0.1, 0.3)
    vel = _virtual(press_state, q)          # the cylinder alone at l̇ = 1 m/s
    g = 9.81
    loads = [(slice(2, 4), 5.0), (slice(0, 2), 1.0), (slice(6, 8), 1.0), (slice(8, 10), 2.0),
             (slice(10, 12), 3.0)]            # carriage at C, rod at K, S4, S5, barrel at T
    power = sum(float((-m * acc[s] + [0.0, -m * g]) @ vel[s]) for s, m in loads)
    power += float(np.array([40.0, -30.0]) @ vel[4:6])
    power += sum(-j * acc[i] * vel[i] for i, j in ((12, 0.03), (13, 0.005), (14, 0.01)))
    assert float(fa.balancing_moment[0]) == pytest.approx(-power, rel=1e-6)
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(-power, rel=1e-6)


# -- W = 2: a crank carries a guide, a slider on it pushed by a second cylinder --------------------
TWO = """
title = "A crank's slider pushed by a cylinder (W = 2)"
language = "en"

[ground]
A = ["0 mm", "0 mm"]
F = ["200 mm", "-150 mm"]

[links.1]
name = "crank with a guide"
points = { A = ["0 mm", "0 mm"], T = ["100 mm", "0 mm"] }
guides.r = { through = "A", toward = "T" }
MASS1

[links.2]
name = "slider"
slides = { point = "K", on = "r" }
MASS2

[links.3]
name = "barrel"
points = { F = ["0 mm", "0 mm"], M = ["100 mm", "0 mm"] }
guides.bore = { through = "F", toward = "M" }
MASS3

[links.4]
name = "rod"
slides = { point = "K", on = "bore" }
MASS4

[drive]
link = "1"
speed = "2 rad/s"
sense = "ccw"
epsilon = "1 rad/s^2"

[drive2]
kind = "cylinder"
link = "4"
speed = "0.05 m/s"
acceleration = "0.1 m/s^2"
start = "250 mm"

LOADS
[assembly]
K = "right of F->A"
"""

TWO_MASSES = {
    "MASS1": 'mass = "2 kg"\ncentre = "T"\nJ = "0.01 kg*m^2"',
    "MASS2": 'mass = "1.5 kg"\ncentre = "K"\nJ = "0.002 kg*m^2"',
    "MASS3": 'mass = "3 kg"\ncentre = "M"\nJ = "0.02 kg*m^2"',
    "MASS4": 'mass = "1 kg"\ncentre = "K"',
    "LOADS": '[gravity]\ng = "9.81 m/s^2"\n\n[[loads]]\ntype = "force"\npoint = "K"\nlink = "2"\n'
             'vector = ["-60 N", "20 N"]\n',
}


def two_text(loaded: bool = False) -> str:
    text = TWO
    for key, value in TWO_MASSES.items():
        text = text.replace(key, value if loaded else "")
    return text


F2 = np.array([0.2, -0.15])


def two_state(theta: float, length: float) -> np.ndarray:
    """(K, T, M, θ_barrel, ρ) for the crank's direction θ and the cylinder's length."""
    u = _e(theta)
    w = float(u @ F2)
    rho = w + math.sqrt(w * w - F2 @ F2 + length * length)     # K right of F→A: the far one
    k = rho * u
    tb = math.atan2(*(k - F2)[::-1])
    return np.concatenate([k, 0.1 * u, F2 + 0.1 * _e(tb), [tb, rho]])


def two_laws(deg: float):
    phi = math.radians(deg)
    return (phi, 2.0, 1.0), (0.25 + 0.05 / 2.0 * phi, 0.05, 0.1)


def two_fd(deg: float, h: float = 1e-4):
    (t1, w1, e1), (q2, r2, a2) = two_laws(deg)
    xs = [two_state(t1 + w1 * k * h + e1 * (k * h) ** 2 / 2,
                    q2 + r2 * k * h + a2 * (k * h) ** 2 / 2) for k in (-2, -1, 0, 1, 2)]
    d1 = (xs[0] - 8 * xs[1] + 8 * xs[3] - xs[4]) / (12 * h)
    d2 = (-xs[0] + 16 * xs[1] - 30 * xs[2] + 16 * xs[3] - xs[4]) / (12 * h * h)
    return xs[2], d1, d2


@pytest.mark.parametrize("deg", [-30.0, -10.0, 5.0, 20.0])
def test_a_cylinder_pushing_a_slider_on_a_turning_guide_equals_the_loop_closure(deg):
    sol = solve(parse_scene(two_text(), "two.toml"), at_deg=[deg], plans=KIN)
    c, ev = sol.construction, sol.ev
    x, v, a = two_fd(deg)
    np.testing.assert_allclose(ev[c.position("K")][0], x[0:2], atol=1e-14)
    np.testing.assert_allclose(ev[c.velocity_image("K")][0], v[0:2], atol=1e-9)
    np.testing.assert_allclose(ev[c.acceleration_image("K")][0], a[0:2], atol=1e-5)
    assert ev[c.omega("3")][0] == pytest.approx(v[6], rel=1e-8)
    assert ev[c.epsilon("3")][0] == pytest.approx(a[6], rel=1e-5)
    assert ev[c.omega("2")][0] == 2.0 and ev[c.epsilon("2")][0] == 1.0


@pytest.mark.parametrize("deg", [-25.0, 0.0, 15.0])
def test_the_crank_moment_and_the_cylinder_force_equal_virtual_power(deg):
    sol = solve(parse_scene(two_text(loaded=True), "two.toml"), at_deg=[deg], plans=ALL)
    fa = sol.extras["forces"]
    (t1, _, _), (q2, _, _) = two_laws(deg)
    _, _, acc = two_fd(deg, h=2e-4)
    acc_slider = acc[:2]
    eps1 = 1.0
    g = 9.81
    out = []
    for which in (0, 1):
        def alone(t, which=which):
            return two_state(t1 + (t if which == 0 else 0.0), q2 + (t if which == 1 else 0.0))
        vel = _virtual(alone, 0.0)
        w_crank = 1.0 if which == 0 else 0.0
        power = 0.0
        for s, m in ((slice(0, 2), 1.5), (slice(0, 2), 1.0), (slice(2, 4), 2.0),
                     (slice(4, 6), 3.0)):       # slider, rod at K; crank at T; barrel at M
            power += float((-m * acc[s] + [0.0, -m * g]) @ vel[s])
        power += float(np.array([-60.0, 20.0]) @ vel[0:2])
        # couples: the crank's and the slider's J·ε1 (both turn with the crank), the barrel's
        power += -(0.01 + 0.002) * eps1 * w_crank - 0.02 * acc[6] * vel[6]
        out.append(-power)
    assert acc_slider.shape == (2,)
    assert float(fa.balancing_moment[0]) == pytest.approx(out[0], rel=1e-6)
    assert fa.second is not None and fa.second[0] == "4"
    assert float(fa.second[1][0]) == pytest.approx(out[1], rel=1e-6)
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(out[0], rel=1e-6)


TRIAD = """
title = "A triad with a cylinder for a leg"
language = "en"

[ground]
A = ["0 mm", "0 mm"]
B = ["400 mm", "0 mm"]
C = ["200 mm", "-100 mm"]

[links.2]
lengths = { AP = "200 mm" }

[links.3]
lengths = { BQ = "200 mm" }

[links.5]
lengths = { PQ = "250 mm", PR = "150 mm", QR = "150 mm" }
side = { R = "right of P->Q" }

[links.6]
points = { C = ["0 mm", "0 mm"], N = ["100 mm", "0 mm"] }
guides.bore = { through = "C", toward = "N" }

[links.7]
slides = { point = "R", on = "bore" }

[drive]
kind = "cylinder"
link = "7"
speed = "0.1 m/s"
range = ["150 mm", "200 mm"]
"""


def test_a_cylinder_inside_a_class_iii_group_is_refused_naming_the_driver():
    with pytest.raises(TopologyError) as e:
        solve(parse_scene(TRIAD, "triad.toml"), at_deg=[170.0], plans=KIN)
    assert e.value.key == "drive.link"
    assert "III(" in str(e.value) and "6" in str(e.value) and "7" in str(e.value)


@pytest.mark.parametrize("which", ["press", "two"])
def test_the_fused_kernel_equals_the_numpy_path(which):
    from mechplan.construct.estimate import estimate_errors
    from mechplan.construct.kernel import compile_kernel
    from mechplan.solve import build, targets_for

    scene = parse_scene(press_text() if which == "press" else two_text(), f"{which}.toml")
    _, c = build(scene, KIN)
    targets = targets_for(scene, c, KIN)
    q = np.linspace(0.252, 0.398, 31) if which == "press" else np.radians(np.linspace(-30, 20, 31))
    ev = c.evaluate(q)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    values, rel, bad = compile_kernel(c, targets, jit=False)(q)
    assert not bad.any()
    for sid in targets:
        size = max(float(np.max(np.abs(ev[sid]))), est.scale[sid])
        assert np.max(np.abs(values[sid] - ev[sid])) <= 1e-14 * size, sid
        assert np.allclose(rel[sid], est.relative(sid), rtol=1e-5, atol=0), sid
