"""W = 2 with cylinders: the excavator arm (two cylinders) and a crank-driven boom with the arm
cylinder (crank + cylinder), against an independent loop closure.

Golden values: the closure |B(θ2) − A| = l4 (or θ2 given by the crank), |G(θ2, θ5) − F(θ2)| = l7
solved by scipy at times t = 0, ±h, ±2h with each driver moving by its own law
q(t) = q0 + q̇·t + q̈·t²/2; velocities and accelerations by five-point finite differences in time.
Nothing of mechplan's construction is used.
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.errors import SceneError
from mechplan.model.structure import analyse
from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

TEMPLATE = Path(__file__).parents[2] / "src/mechplan/templates/excavator_arm.toml"
KIN = ("position", "velocity", "acceleration")
O, A = np.array([0.0, 0.0]), np.array([0.6, -1.0])
# the boom's points in its frame (O at the origin, E on its x axis), the arm's (E, H, G)
B_2, E_2, F_2 = np.array([2.5, -0.45]), np.array([5.7, 0.0]), np.array([2.9, 0.55])
G_5, H_5 = np.array([-0.6, 0.25]), np.array([2.9, 0.0])
L4DOT, L4DDOT, L7DOT, L7DDOT = 0.1, 0.03, 0.075, -0.02


def rot(a: float, v: np.ndarray) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def cross(u: np.ndarray, v: np.ndarray) -> float:
    return float(u[0] * v[1] - u[1] * v[0])


def boom_angle(l4: float) -> float:
    """θ2 with |B − A| = l4, B right of A→O (the scene's assembly), by a bracketing root."""
    def f(t):
        return float(np.hypot(*(rot(t, B_2) - A))) - l4

    def right(t):
        return cross(O - A, rot(t, B_2) - A) < 0
    grid = np.linspace(-math.pi, math.pi, 721)
    roots = [brentq(f, a, b, xtol=1e-15) for a, b in itertools.pairwise(grid)
             if f(a) * f(b) < 0]
    return next(r for r in roots if right(r))


def arm_angle(th2: float, l7: float) -> float:
    """θ5 with |G − F| = l7, G left of F→E."""
    e, f_ = rot(th2, E_2), rot(th2, F_2)

    def g(t):
        return float(np.hypot(*(e + rot(t, G_5) - f_))) - l7

    def left(t):
        return cross(e - f_, e + rot(t, G_5) - f_) > 0
    grid = np.linspace(th2 - math.pi, th2 + math.pi, 721)
    roots = [brentq(g, a, b, xtol=1e-15) for a, b in itertools.pairwise(grid)
             if g(a) * g(b) < 0]
    return next(r for r in roots if left(r))


def state(th2: float, l7: float) -> np.ndarray:
    """θ2, θ5, the barrels' angles θ3, θ6 and the bucket pivot H."""
    th5 = arm_angle(th2, l7)
    b, e, f_ = rot(th2, B_2), rot(th2, E_2), rot(th2, F_2)
    g = e + rot(th5, G_5)
    h = e + rot(th5, H_5)
    return np.array([th2, th5, math.atan2(*(b - A)[::-1]), math.atan2(*(g - f_)[::-1]), *h])


def fd(motion, h: float = 1e-3):
    xs = [motion(k * h) for k in (-2, -1, 0, 1, 2)]
    d1 = (xs[0] - 8 * xs[1] + 8 * xs[3] - xs[4]) / (12 * h)
    d2 = (-xs[0] + 16 * xs[1] - 30 * xs[2] + 16 * xs[3] - xs[4]) / (12 * h * h)
    return xs[2], d1, d2


def two_cylinders(l4: float):
    l7 = 2.7 + L7DOT / L4DOT * (l4 - 2.2)

    def motion(t):
        th2 = boom_angle(l4 + L4DOT * t + L4DDOT * t * t / 2)
        return state(th2, l7 + L7DOT * t + L7DDOT * t * t / 2)
    return fd(motion)


def _scene(accelerations: bool = True, text: str | None = None):
    text = text or TEMPLATE.read_text(encoding="utf-8")
    if accelerations:
        text = text.replace('acceleration = "0 m/s^2"', 'acceleration = "0.03 m/s^2"')
        text = text.replace('start = "2700 mm"', 'start = "2700 mm"\nacceleration = "-0.02 m/s^2"')
    return parse_scene(text, str(TEMPLATE))


def test_structure_formula_lists_both_cylinders():
    st = analyse(_scene().mechanism)
    assert st.dof == 2
    assert st.formula == "I(3,4), I(6,7) → II(2,3) → II(5,6)"


def _check(sol, k, x, v, a, angles=True):
    c, ev = sol.construction, sol.ev
    for link, i in (("2", 0), ("5", 1), ("3", 2), ("6", 3)):
        assert math.remainder(ev[c.link_angle(link)][k] - x[i], 2 * math.pi) == pytest.approx(
            0.0, abs=1e-12), link
        assert ev[c.omega(link)][k] == pytest.approx(v[i], rel=1e-8, abs=1e-10), link
        assert ev[c.epsilon(link)][k] == pytest.approx(a[i], rel=1e-5, abs=1e-8), link
    np.testing.assert_allclose(ev[c.position("H")][k], x[4:6], atol=1e-12)
    np.testing.assert_allclose(ev[c.velocity_image("H")][k], v[4:6], rtol=0, atol=1e-10)
    np.testing.assert_allclose(ev[c.acceleration_image("H")][k], a[4:6], rtol=0, atol=1e-7)


@pytest.mark.parametrize("l4_mm", [2200.0, 2450.0, 2730.0, 3000.0])
def test_two_cylinders_equal_the_loop_closure(l4_mm):
    sol = solve(_scene(), at_deg=[l4_mm], plans=KIN)
    x, v, a = two_cylinders(l4_mm / 1000)
    assert sol.ev["pos.q2"][0] == pytest.approx(2.7 + 0.75 * (l4_mm / 1000 - 2.2), abs=1e-15)
    _check(sol, 0, x, v, a)


@pytest.mark.parametrize("scene_of", ["two_cylinders", "crank_cylinder"])
def test_the_fused_kernel_equals_the_numpy_path_and_estimates_are_tiny(scene_of):
    from mechplan.construct.estimate import estimate_errors
    from mechplan.construct.kernel import compile_kernel
    from mechplan.solve import build, targets_for

    scene = _scene() if scene_of == "two_cylinders" else _crank_scene()
    _, c = build(scene, KIN)
    targets = targets_for(scene, c, KIN)
    q = np.linspace(2.2, 3.0, 41) if scene_of == "two_cylinders" else np.linspace(0.1, 0.75, 41)
    ev = c.evaluate(q)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    values, rel, bad = compile_kernel(c, targets, jit=False)(q)
    assert not bad.any()
    for sid in targets:
        size = max(float(np.max(np.abs(ev[sid]))), est.scale[sid])
        # a few ulps of the arm's rates, carried through two groups (math.atan2 in the loop and
        # np.arctan2 outside it may differ in the last bit)
        assert np.max(np.abs(values[sid] - ev[sid])) <= 1e-14 * size, sid
        assert np.allclose(rel[sid], est.relative(sid), rtol=1e-5, atol=0), sid
    # measured against the first driver's rates (|q̇|, |q̈| + q̇²/L): the bucket pivot H moves
    # through two levers in series (rod → boom → arm), ~50× faster than the rods; the bound is
    # looser than one cylinder's 1e-11
    assert max(float(np.max(est.relative(sid))) for sid in targets) < 5e-9


# -- crank + cylinder: the boom driven as a crank about O, the arm by its cylinder --------------
W2, EPS2 = 0.08, 0.01


def _crank_scene():
    text = TEMPLATE.read_text(encoding="utf-8")
    head, _, tail = text.partition("[links.3]")
    tail = tail[tail.index("[links.5]"):]
    text = head + tail
    text = text.replace('A = ["600 mm", "-1000 mm"]\n', "")
    start, end = text.index("[drive]"), text.index("[drive2]")
    text = (text[:start] + '[drive]\nlink = "2"\nspeed = "0.08 rad/s"\nepsilon = "0.01 rad/s^2"\n\n'
            + text[end:])
    text = text.replace('start = "2700 mm"', 'start = "2700 mm"\nacceleration = "-0.02 m/s^2"')
    text = text.replace('B = "right of A->O"\n', "").replace("[positions]\ncount = 5\n", "")
    return parse_scene(text, "crank_cylinder.toml")


def test_crank_and_cylinder_structure():
    st = analyse(_crank_scene().mechanism)
    assert st.dof == 2 and st.formula == "I(0,2), I(6,7) → II(5,6)"


@pytest.mark.parametrize("deg", [5.0, 20.0, 33.0, 42.0])
def test_crank_and_cylinder_equal_the_loop_closure(deg):
    sol = solve(_crank_scene(), at_deg=[deg], plans=KIN)
    phi = math.radians(deg)
    l7 = 2.7 + L7DOT / W2 * phi            # l7 = start + l̇7/|ω2|·φ2

    def motion(t):
        return state(phi + W2 * t + EPS2 * t * t / 2, l7 + L7DOT * t + L7DDOT * t * t / 2)
    x, v, a = fd(motion)
    c, ev = sol.construction, sol.ev
    assert ev["pos.q2"][0] == pytest.approx(l7, abs=1e-15)
    for link, i in (("2", 0), ("5", 1), ("6", 3)):
        assert math.remainder(ev[c.link_angle(link)][0] - x[i], 2 * math.pi) == pytest.approx(
            0.0, abs=1e-12), link
        assert ev[c.omega(link)][0] == pytest.approx(v[i], rel=1e-8, abs=1e-10), link
        assert ev[c.epsilon(link)][0] == pytest.approx(a[i], rel=1e-5, abs=1e-8), link
    np.testing.assert_allclose(ev[c.acceleration_image("H")][0], a[4:6], rtol=0, atol=1e-7)


def test_a_second_crank_after_a_cylinder_is_refused_naming_the_key():
    text = TEMPLATE.read_text(encoding="utf-8").replace(
        '[drive2]\nkind = "cylinder"', '[drive2]\nkind = "crank"').replace(
        'speed = "0.075 m/s"\nstart = "2700 mm"', 'speed = "1 rad/s"')
    with pytest.raises(SceneError) as err:
        parse_scene(text, "arm.toml")
    assert err.value.key == "drive2.link"


def test_a_second_cylinder_needs_its_start():
    text = TEMPLATE.read_text(encoding="utf-8").replace('start = "2700 mm"\n', "")
    with pytest.raises(SceneError) as err:
        parse_scene(text, "arm.toml")
    assert err.value.key == "drive2.start"


def test_the_first_driver_needs_a_range():
    text = TEMPLATE.read_text(encoding="utf-8").replace(
        'range = ["2200 mm", "3000 mm"]\n', "").replace(
        "count = 5", 'at = ["2400 mm"]')
    with pytest.raises(SceneError) as err:
        parse_scene(text, "arm.toml")
    assert err.value.key == "drive2.start"


def test_json_names_the_second_cylinder_and_its_law():
    from mechplan.solve import to_json

    doc = to_json(solve(_scene(), at_deg=[2400.0]))
    second = doc["second_driver"]
    assert second["kind"] == "cylinder" and second["link"] == "7"
    assert second["rate"] == 0.075 and second["acceleration"] == -0.02
    assert second["start"] == pytest.approx(2.7, abs=1e-15)


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_the_protocol_writes_the_second_length_in_every_language(lang):
    from mechplan.construct.protocol import protocol
    from mechplan.model.plans import Plan

    sol = solve(_scene(), at_deg=[2400.0])
    lines = protocol(sol.construction, sol.ev, 0, lang, sol.scales, (Plan.POSITION,))
    second = [s for _, label, s in lines if label == "l7"]
    assert len(second) == 1 and "2850" in second[0].replace(" ", "").replace(",", ""), second
