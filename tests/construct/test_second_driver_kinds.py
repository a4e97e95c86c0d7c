"""W = 2 with any order of driver kinds: a slider on a frame guide as the second driver (after a
crank, after a cylinder) and a crank as the second driver after a linear first one.

Golden values: the loop closure solved by scipy (brentq for the cylinder's lever, fsolve for the
dyad) at t, t ± h, t ± 2h with each driver moving by its own law around the position (its
coordinate, rate and acceleration there), angles' rates by five-point finite differences in
time. Nothing of mechplan's construction is used.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq, fsolve

from mechplan.errors import SceneError, TopologyError
from mechplan.model.structure import analyse
from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

KIN = ("position", "velocity", "acceleration")
A, F, H = np.array([0.0, 0.0]), np.array([0.080, -0.060]), np.array([0.200, 0.0])
L2, L3 = 0.200, 0.150

BASE = """
title = "W = 2"
language = "en"

[ground]
A = ["0 mm", "0 mm"]
F = ["80 mm", "-60 mm"]
H = ["200 mm", "0 mm"]
guides.g = { through = "H", angle = "0 deg" }

[links.1]
name = "crank"
points = { A = ["0 mm", "0 mm"], G = ["50 mm", "0 mm"], B = ["LB mm", "0 mm"] }

[links.2]
name = "coupler"
lengths = { BC = "200 mm" }

[links.3]
name = "coupler"
lengths = { DC = "150 mm" }

[links.4]
name = "slider"
slides = { point = "D", on = "g" }
"""

CYLINDER = """
[links.5]
name = "barrel"
points = { F = ["0 mm", "0 mm"], K = ["100 mm", "0 mm"] }
guides.bore = { through = "F", toward = "K" }

[links.6]
name = "rod"
slides = { point = "G", on = "bore" }
"""

CRANK = """
[DRIVE]
link = "1"
speed = "10 rad/s"
sense = "ccw"
epsilon = "3 rad/s^2"
PHASE"""

SLIDER = """
[DRIVE]
kind = "slider"
link = "4"
speed = "-0.1 m/s"
acceleration = "0.5 m/s^2"
RANGE"""

CYL = """
[drive]
kind = "cylinder"
link = "6"
speed = "0.05 m/s"
acceleration = "0.2 m/s^2"
range = ["110 mm", "145 mm"]
"""

TAIL = """
[assembly]
C = "left of B->D"
GSIDE
"""


def scene_text(case: str) -> str:
    """crank_slider (crank first), slider_crank (slider first), cylinder_slider."""
    lb = "100" if case.startswith("cylinder") else "60"
    text = BASE.replace("LB", lb)
    if case == "crank_slider":
        text += CRANK.replace("DRIVE", "drive").replace("PHASE", "")
        text += SLIDER.replace("DRIVE", "drive2").replace("RANGE", 'start = "-30 mm"\n')
        text += TAIL.replace("GSIDE", "")
    elif case == "slider_crank":
        text += SLIDER.replace("DRIVE", "drive").replace(
            "RANGE", 'range = ["-40 mm", "40 mm"]\n')
        text += CRANK.replace("DRIVE", "drive2").replace("PHASE", 'phase = "30 deg"\n')
        text += TAIL.replace("GSIDE", "")
    elif case == "slider_slider":
        text = text.replace('guides.g = {', 'guides.g1 = { through = "A", angle = "90 deg" }\n'
                            'guides.g = {').replace(
            'name = "crank"\npoints = { A = ["0 mm", "0 mm"], G = ["50 mm", "0 mm"], '
            'B = ["60 mm", "0 mm"] }', 'name = "slider 1"\nslides = { point = "B", on = "g1" }')
        text += SLIDER.replace("DRIVE", "drive").replace("link = \"4\"", "link = \"1\"").replace(
            "speed = \"-0.1 m/s\"", "speed = \"0.1 m/s\"").replace(
            "RANGE", 'range = ["-40 mm", "40 mm"]\n')
        text += SLIDER.replace("DRIVE", "drive2").replace("RANGE", 'start = "0 mm"\n')
        text += TAIL.replace("GSIDE", "")
    elif case == "cylinder_crank":
        text = text.replace('slides = { point = "D", on = "g" }', 'lengths = { HD = "60 mm" }')
        text += CYLINDER + CYL
        text += CRANK.replace("DRIVE", "drive2").replace('link = "1"', 'link = "4"').replace(
            "PHASE", 'phase = "30 deg"\n')
        text += TAIL.replace("GSIDE", 'G = "right of F->A"')
    else:
        text += CYLINDER + CYL
        text += SLIDER.replace("DRIVE", "drive2").replace("RANGE", 'start = "20 mm"\n')
        text += TAIL.replace("GSIDE", 'G = "right of F->A"')
    return text.replace("[links.1]\n", "[links.1]\n", 1).replace(
        'points = { A = ["0 mm", "0 mm"], G = ["50 mm", "0 mm"], B = ["60 mm", "0 mm"] }',
        'lengths = { AB = "60 mm" }')


def _e(a: float) -> np.ndarray:
    return np.array([math.cos(a), math.sin(a)])


def _dyad(b: np.ndarray, d: np.ndarray) -> np.ndarray:
    """θ2, θ3 with C left of B→D."""
    m, u = (b + d) / 2, (d - b) / np.linalg.norm(d - b)
    c = m + 0.12 * np.array([-u[1], u[0]])
    guess = np.array([math.atan2(*(c - b)[::-1]), math.atan2(*(c - d)[::-1])])

    def f(x):
        return b + L2 * _e(x[0]) - d - L3 * _e(x[1])

    x = fsolve(f, guess, xtol=1e-13)
    assert np.abs(f(x)).max() < 1e-14
    return x


def _lever_angle(length: float) -> float:
    """θ1 of the lever whose pin G (50 mm from A) is ``length`` from F (G right of F→A)."""
    return brentq(lambda a: np.linalg.norm(A + 0.05 * _e(a) - F) - length,
                  math.radians(20.0), math.radians(160.0), xtol=1e-15)


def pins(case: str, q1: float, q2: float) -> tuple[float, np.ndarray, np.ndarray]:
    """(θ1, B, D) for the drivers' coordinates: θ (rad, ccw) of a crank, s or l (m)."""
    if case == "slider_slider":         # B on the vertical guide through A, D on g
        return math.pi / 2, A + np.array([0.0, q1]), H + np.array([q2, 0.0])
    if case == "cylinder_crank":        # the lever by the cylinder, D on crank 4 about H
        th1 = _lever_angle(q1)
        return th1, A + 0.1 * _e(th1), H + 0.06 * _e(q2)
    if case == "crank_slider":
        th1, s = q1, q2
    elif case == "slider_crank":
        th1, s = q2, q1
    else:
        th1, s = _lever_angle(q1), q2
    lb = 0.1 if case == "cylinder_slider" else 0.06
    return th1, A + lb * _e(th1), H + np.array([s, 0.0])


def state(case: str, q1: float, q2: float) -> np.ndarray:
    """(θ1, θ2, θ3, x_D) for the drivers' coordinates."""
    th1, b, d = pins(case, q1, q2)
    t2, t3 = _dyad(b, d)
    return np.array([th1, t2, t3, d[0]])


def laws(case: str, x: float) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """Each driver's (coordinate, rate, acceleration) at the position x (deg or mm)."""
    if case == "crank_slider":
        phi = math.radians(x)
        return (phi, 10.0, 3.0), (-0.030 + (-0.1 / 10.0) * phi, -0.1, 0.5)
    if case == "slider_crank":
        s = x / 1000.0
        # φ2 = phase + |ω2|·t, t = (s1 − s1⁰)/ṡ1 the time from the range's start (ṡ1 < 0)
        return (s, -0.1, 0.5), (math.radians(30.0) + 10.0 * (s + 0.040) / -0.1, 10.0, 3.0)
    q = x / 1000.0
    if case == "slider_slider":
        return (q, 0.1, 0.5), ((-0.1 / 0.1) * (q + 0.040), -0.1, 0.5)
    if case == "cylinder_crank":
        return (q, 0.05, 0.2), (math.radians(30.0) + 10.0 * (q - 0.110) / 0.05, 10.0, 3.0)
    return (q, 0.05, 0.2), (0.020 + (-0.1 / 0.05) * (q - 0.110), -0.1, 0.5)


def golden(case: str, x: float, h: float = 1e-4):
    (q1, r1, a1), (q2, r2, a2) = laws(case, x)
    xs = {k: state(case, q1 + r1 * k * h + a1 * (k * h) ** 2 / 2,
                   q2 + r2 * k * h + a2 * (k * h) ** 2 / 2) for k in (-2, -1, 0, 1, 2)}
    d1 = (xs[-2] - 8 * xs[-1] + 8 * xs[1] - xs[2]) / (12 * h)
    d2 = (-xs[-2] + 16 * xs[-1] - 30 * xs[0] + 16 * xs[1] - xs[2]) / (12 * h * h)
    return xs[0], d1, d2


CASES = {"crank_slider": [20.0, 135.0, 250.0], "slider_crank": [-35.0, 0.0, 30.0],
         "cylinder_slider": [112.0, 125.0, 143.0], "slider_slider": [-30.0, 0.0, 35.0],
         "cylinder_crank": [112.0, 125.0, 143.0]}


@pytest.mark.parametrize(("case", "x"), [(c, x) for c, xs in CASES.items() for x in xs])
def test_kinematics_equal_the_loop_closure(case, x):
    sol = solve(parse_scene(scene_text(case), f"{case}.toml"), at_deg=[x], plans=KIN)
    c, ev = sol.construction, sol.ev
    x0, d1, d2 = golden(case, x)
    for link, i in (("1", 0), ("2", 1), ("3", 2)):
        if case == "slider_slider" and link == "1":
            continue            # a slider on its guide: θ1 is the guide's
        got = ev[c.link_angle(link)][0]
        assert math.remainder(got - x0[i], 2 * math.pi) == pytest.approx(0.0, abs=1e-12), link
        assert ev[c.omega(link)][0] == pytest.approx(d1[i], rel=1e-8, abs=1e-8), link
        assert ev[c.epsilon(link)][0] == pytest.approx(d2[i], rel=1e-5, abs=1e-5), link
    assert ev[c.position("D")][0][0] == pytest.approx(x0[3], abs=1e-14)
    assert ev[c.velocity_image("D")][0][0] == pytest.approx(d1[3], rel=1e-9, abs=1e-10)
    assert ev[c.acceleration_image("D")][0][0] == pytest.approx(d2[3], rel=1e-6, abs=1e-6)


@pytest.mark.parametrize(("case", "formula"), [
    ("crank_slider", "I(0,1), I(0,4) → II(2,3)"),
    ("slider_crank", "I(0,4), I(0,1) → II(2,3)"),
    ("cylinder_slider", "I(5,6), I(0,4) → II(1,5) → II(2,3)"),
    ("slider_slider", "I(0,1), I(0,4) → II(2,3)"),
    ("cylinder_crank", "I(5,6), I(0,4) → II(1,5) → II(2,3)")])
def test_structure_formula_lists_both_drivers(case, formula):
    st = analyse(parse_scene(scene_text(case), "w2.toml").mechanism)
    assert st.dof == 2 and st.formula == formula


@pytest.mark.parametrize("case", list(CASES))
def test_the_fused_kernel_equals_the_numpy_path(case):
    from mechplan.construct.estimate import estimate_errors
    from mechplan.construct.kernel import compile_kernel
    from mechplan.solve import build, targets_for

    scene = parse_scene(scene_text(case), f"{case}.toml")
    _, c = build(scene, KIN)
    targets = targets_for(scene, c, KIN)
    lo, hi = CASES[case][0], CASES[case][-1]
    x = np.linspace(lo, hi, 21)
    q = np.radians(x) if case == "crank_slider" else x / 1000.0      # φ1 (rad) or q1 (m)
    ev = c.evaluate(q)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    values, rel, bad = compile_kernel(c, targets, jit=False)(q)
    assert not bad.any()
    for sid in targets:
        size = max(float(np.max(np.abs(ev[sid]))), est.scale[sid])
        assert np.max(np.abs(values[sid] - ev[sid])) <= 1e-14 * size, sid
        assert np.allclose(rel[sid], est.relative(sid), rtol=1e-5, atol=0), sid


def test_a_second_slider_not_on_a_frame_guide_is_refused():
    text = scene_text("crank_slider").replace('kind = "slider"\nlink = "4"',
                                              'kind = "slider"\nlink = "3"')
    with pytest.raises((SceneError, TopologyError)) as e:
        parse_scene(text, "w2.toml")
    assert e.value.key == "drive2.link"


def test_a_crank_after_a_linear_driver_without_range_is_refused():
    text = scene_text("slider_crank").replace('range = ["-40 mm", "40 mm"]\n', "").replace(
        "[assembly]", '[positions]\nat = ["0 mm"]\n\n[assembly]')
    with pytest.raises(SceneError) as e:
        parse_scene(text, "w2.toml")
    assert e.value.key == "drive2.link"
