"""Friction in the pairs of machines driven by a cylinder or a slider: the courses' iteration
closes on the driving force F_d. Golden values: every link's equilibrium with friction written as
one nonlinear system and solved by scipy's fsolve (positions by the loop closure written here,
the senses of friction from finite-difference velocities); the friction-free limit; η by powers."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq, fsolve

from mechplan.dynamics.loading import Loading
from mechplan.errors import SceneError
from mechplan.scene import parse_scene
from mechplan.solve import solve

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"
PLANS = ("position", "velocity", "acceleration", "force")


def _solve(text: str):
    scene = parse_scene(text, "scene.toml")
    return solve(scene, plans=PLANS, loading=Loading.from_scene(scene)).extras["forces"]


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def _fsolve(equations, x0):
    sol, _info, ok, msg = fsolve(equations, x0, full_output=True, xtol=1e-13)
    assert ok in (1, 3), msg
    assert np.abs(equations(sol)).max() < 1e-6
    return sol


# -- the excavator boom: one cylinder, barrel 3 about A, rod 4 pinned to the boom 2 at B ----------
A = np.array([0.6, -0.4])
BOOM = (TEMPLATES / "excavator_boom.toml").read_text(encoding="utf-8")
# massless links (no inertia, no weight), a load of 12 kN down at the boom's tip D
BOOM_STATIC = (BOOM.replace('mass = "800 kg"', "").replace('J = "900 kg m^2"', "")
               .replace('mass = "60 kg"', "").replace('centre = "D"', "")
               .replace('centre = "C"', "")
               .replace("[gravity]\n", '[[loads]]\ntype = "force"\npoint = "D"\n'
                        'vector = ["0 N", "-12000 N"]\n\n[gravity]\n'))
BOOM_FRICTION = """
[friction]
f = 0.12
pin_radius = "40 mm"
[friction.pairs]
"0-3" = { f = 0.1, radius = "50 mm" }
"3-4" = { f = 0.15 }
"""


def _boom_angle(length: float) -> float:
    """θ2 with |AB| = l, B = 1.5 m·(cos θ2, sin θ2) right of the line A→O."""
    def gap(t):
        return math.hypot(1.5 * math.cos(t) - A[0], 1.5 * math.sin(t) - A[1]) - length
    roots = []
    grid = np.linspace(-math.pi, math.pi, 721)
    for lo, hi in itertools.pairwise(grid):
        if gap(lo) * gap(hi) < 0:
            roots.append(brentq(gap, lo, hi, xtol=1e-15))
    right = [t for t in roots
             if cross(-A, 1.5 * np.array([math.cos(t), math.sin(t)]) - A) < 0]
    assert len(right) == 1
    return right[0]


def _boom_reference(length: float, rate: float, *coefficients: float) -> float:
    """F_d with friction; fsolve starts from the friction-free equilibrium (|N| has a kink)."""
    free = _fsolve(_boom_system(length, rate, 0, 0, 0, 0, 0), np.zeros(9))
    return float(_fsolve(_boom_system(length, rate, *coefficients), free)[8])


def _boom_system(length: float, rate: float, f_pin: float, r_pin: float, f_a: float,
                 r_a: float, f_s: float):
    """The boom's, barrel's and rod's equilibrium with friction, as equations for fsolve.

    Unknowns: R02 (2), R03 (2), R24 (2, the boom on the rod), N (the barrel on the rod ⊥ the
    axis), M34 (the guide's couple on the rod), F_d (the barrel on the rod along A→B)."""
    def state(length):
        t2 = _boom_angle(length)
        b = 1.5 * np.array([math.cos(t2), math.sin(t2)])
        return t2, math.atan2(*(b - A)[::-1]), b
    t2, t3, b = state(length)
    h = 1e-6
    w2 = rate * (state(length + h)[0] - state(length - h)[0]) / (2 * h)
    w3 = rate * (state(length + h)[1] - state(length - h)[1]) / (2 * h)
    u = np.array([math.cos(t3), math.sin(t3)])
    n = np.array([-u[1], u[0]])
    c2, s2 = math.cos(t2), math.sin(t2)
    d = np.array([4.0 * c2 - 0.6 * s2, 4.0 * s2 + 0.6 * c2])
    load = np.array([0.0, -12000.0])

    def equations(x):
        r02, r03, r24, nn, m34, fd = x[0:2], x[2:4], x[4:6], x[6], x[7], x[8]
        mf02 = -f_pin * r_pin * np.hypot(*r02) * np.sign(w2)            # on the boom
        mf03 = -f_a * r_a * np.hypot(*r03) * np.sign(w3)                # on the barrel
        mf24 = -f_pin * r_pin * np.hypot(*r24) * np.sign(w3 - w2)       # on the rod (ω4 = ω3)
        on_rod = fd * u + nn * n - f_s * abs(nn) * np.sign(rate) * u     # the barrel's force
        rod = [*(r24 + on_rod), m34 + mf24]
        barrel = [*(r03 - on_rod), cross(b - A, -on_rod) - m34 + mf03]
        boom = [*(r02 - r24 + load), cross(b, -r24) + cross(d, load) + mf02 - mf24]
        return [*rod, *barrel, *boom]

    return equations


@pytest.fixture(scope="module")
def boom():
    fa = _solve(BOOM_STATIC + BOOM_FRICTION)
    plain = _solve(BOOM_STATIC)
    return fa, plain


def test_boom_driving_force_with_friction_against_fsolve(boom):
    fa, _plain = boom
    fr = fa.friction
    assert fr is not None and fa.linear
    lengths = np.linspace(1.45, 1.9, 5)
    np.testing.assert_allclose(fa.phi, lengths, rtol=1e-12)
    for k, length in enumerate(lengths):
        expected = _boom_reference(length, 0.25, 0.12, 0.04, 0.1, 0.05, 0.15)
        free = _boom_reference(length, 0.25, 0.0, 0.0, 0.0, 0.0, 0.0)
        assert abs(fa.balancing_moment[k] - expected) < 1e-8 * abs(expected)
        assert abs(fa.zhukovsky_moment[k] - expected) < 1e-8 * abs(expected)
        assert abs(fr.free_moment[k] - free) < 1e-8 * abs(free)
        assert abs(fr.moment[k] - expected) < 1e-8 * abs(expected)
        # the cylinder pushes: η = F_d⁰/F_d, and the same by the friction loads' power
        assert fr.efficiency[k] == pytest.approx(free / expected, rel=1e-8)
        assert fr.efficiency_power[k] == pytest.approx(free / expected, rel=1e-8)
        assert 0.9 < fr.efficiency[k] < 1.0
    assert fr.passes >= 3 and np.all(fr.converged)
    # the cylinder's own sliding pair: friction against l̇ > 0, i.e. along B→A, its power < 0
    slide = next(p for p in fr.pairs if p.pair == "3-4")
    assert slide.kind == "prismatic" and np.all(slide.relative > 0) and np.all(slide.power < 0)
    assert {p.pair for p in fr.pairs} == {"0-2", "0-3", "2-4", "3-4"}


def test_boom_friction_free_limit(boom):
    fa, plain = boom
    assert fa.friction is not None
    scale = np.abs(plain.balancing_moment).max()
    np.testing.assert_allclose(fa.friction.free_moment, plain.balancing_moment, rtol=0,
                               atol=1e-9 * scale)
    zero = _solve(BOOM_STATIC + "[friction]\nf = 0\n")
    assert zero.friction is not None
    np.testing.assert_array_equal(zero.balancing_moment, plain.balancing_moment)
    tiny = _solve(BOOM_STATIC + BOOM_FRICTION.replace("0.12", "1e-12").replace("0.1,", "1e-12,")
                  .replace("0.15", "1e-12"))
    np.testing.assert_allclose(tiny.balancing_moment, plain.balancing_moment, rtol=0,
                               atol=1e-9 * scale)


def test_boom_json_and_report_name_the_driving_force(boom):
    fa, _plain = boom
    doc = fa.json(2)["friction"]
    assert doc["driving_force"] == pytest.approx(float(fa.balancing_moment[2]))
    assert doc["driving_force_without_friction"] == pytest.approx(
        float(fa.friction.free_moment[2]))
    assert "balancing_moment" not in doc and set(doc["pairs"]) == {"0-2", "0-3", "2-4", "3-4"}


# -- the slotted link driven by a slider block: block 1 on the frame guide, block 2 in the slot ----
O3 = np.array([0.1, -0.3])
COULISSE = (TEMPLATES / "slider_coulisse.toml").read_text(encoding="utf-8").replace(
    "[drive]\n", '[[loads]]\ntype = "torque"\nlink = "3"\ntorque = "150 N*m"\n\n'
    '[friction]\nf = 0.1\npin_radius = "20 mm"\n[friction.pairs]\n"0-1" = { f = 0.2 }\n'
    '"2-3" = { f = 0.15 }\n\n[drive]\n', 1)


def _coulisse_reference(q: float, rate: float, f: float) -> float:
    """F_d with friction f; fsolve starts from the friction-free equilibrium."""
    free = _fsolve(_coulisse_system(q, rate, 0.0), np.zeros(9))
    return float(free[0] if f == 0 else _fsolve(_coulisse_system(q, rate, f), free)[0])


def _coulisse_system(q: float, rate: float, f: float):
    """F_d from the three links' equilibrium with friction f (pins ρ = f·20 mm, the frame guide
    2f, the slot 1.5f). Unknowns: F_d, N01, M01 (the frame on block 1), R12 (2), N32, M32
    (the slot on block 2), R03 (2)."""
    rho, f01, f23 = f * 0.02, 2 * f, 1.5 * f
    b = np.array([q, 0.0])

    def theta(q):
        return math.atan2(0.3, q - 0.1)
    h = 1e-6
    w3 = rate * (theta(q + h) - theta(q - h)) / (2 * h)
    slide = rate * (math.hypot(q + h - 0.1, 0.3) - math.hypot(q - h - 0.1, 0.3)) / (2 * h)
    u = np.array([math.cos(theta(q)), math.sin(theta(q))])
    n = np.array([-u[1], u[0]])
    x_, y_ = np.array([1.0, 0.0]), np.array([0.0, 1.0])

    def equations(x):
        fd, n01, m01, r12, n32, m32, r03 = x[0], x[1], x[2], x[3:5], x[5], x[6], x[7:9]
        mf12 = -rho * np.hypot(*r12) * np.sign(w3 - 0.0)        # on block 2 (ω2 = ω3, ω1 = 0)
        mf03 = -rho * np.hypot(*r03) * np.sign(w3)
        on_2 = n32 * n - f23 * abs(n32) * np.sign(slide) * u    # the slot on block 2
        on_1 = fd * x_ + n01 * y_ - f01 * abs(n01) * np.sign(rate) * x_
        block2 = [*(r12 + on_2), m32 + mf12]
        link3 = [*(r03 - on_2), cross(b - O3, -on_2) - m32 + 150.0 + mf03]
        block1 = [*(on_1 - r12), m01 - mf12]
        return [*block2, *link3, *block1]

    return equations


@pytest.mark.parametrize("f", [0.1, 0.0])
def test_slider_driven_coulisse_with_friction_against_fsolve(f):
    fa = _solve(COULISSE if f else COULISSE.replace("f = 0.15", "f = 0").replace(
        "f = 0.2", "f = 0").replace("f = 0.1", "f = 0"))
    fr = fa.friction
    assert fr is not None and fa.linear
    # at q = 100 mm the pin B is right above O3: the block does not slide in the slot, the
    # sense of its friction is undefined (flagged, its friction taken as zero)
    dead = np.isclose(fa.phi, 0.1, rtol=0, atol=1e-12)
    assert dead.sum() == 1
    if f:
        assert list(fr.undefined) == list(dead)
        assert fa.json(int(np.argmax(dead)))["friction"]["undefined_sense"] == ["2-3"]
    for k, q in enumerate(fa.phi):
        if dead[k]:
            continue
        expected = _coulisse_reference(float(q), 1.0, f)
        free = _coulisse_reference(float(q), 1.0, 0.0)
        assert abs(fa.balancing_moment[k] - expected) < 1e-8 * abs(expected)
        assert abs(fa.zhukovsky_moment[k] - expected) < 1e-8 * abs(expected)
        assert abs(fr.free_moment[k] - free) < 1e-9 * abs(free)
        if expected > 0:            # the slider drives: η = F_d⁰/F_d = 1 − |P_f|/(F_d·q̇)
            assert fr.efficiency[k] == pytest.approx(free / expected, rel=1e-8)
            assert fr.efficiency_power[k] == pytest.approx(free / expected, rel=1e-8)
        else:
            assert math.isnan(fr.efficiency[k])
    if f:
        assert {p.pair for p in fr.pairs} == {"0-1", "0-3", "1-2", "2-3"}
        assert np.all(fa.balancing_moment != fr.free_moment)


def test_a_friction_pair_that_does_not_exist_is_named():
    text = BOOM_STATIC + '[friction]\nf = 0.1\n[friction.pairs]\n"2-3" = { f = 0.2 }\n'
    with pytest.raises(SceneError, match="no pair 2-3"):
        _solve(text)


@pytest.fixture(scope="module")
def boom_solution():
    friction = BOOM_FRICTION.replace("[friction.pairs]", "diagram = true\n[friction.pairs]")
    text = (BOOM_STATIC + friction).replace("count = 5", "count = 7")
    return solve(parse_scene(text, "boom.toml"))


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_report_and_protocol_write_the_driving_force_in_newtons(boom_solution, lang):
    from mechplan.construct.protocol import protocol
    from mechplan.i18n import unit
    from mechplan.model.plans import Plan
    from mechplan.report import text_report

    text = text_report(boom_solution, lang)
    assert "F_d⁰" in text and "η" in text and "M_b⁰" not in text
    line = next(s for s in text.splitlines() if "F_d⁰" in s)
    assert unit("N·m", lang) not in line and "{" not in line
    steps = protocol(boom_solution.construction, boom_solution.ev, 1, lang, {Plan.FORCE: 2.0},
                     (Plan.FORCE,))
    first = next(s for _, label, s in steps if label == "F_d⁰")
    assert unit("N·m", lang) not in first and unit("N", lang) in first
    assert {"M^f_02", "M^f_03", "F^f_34", "F^f_43"} <= {label for _, label, _ in steps}


def test_the_sheet_draws_eta_over_the_drivers_time(boom_solution):
    from mechplan.sheet.friction_diagram import efficiency_diagram
    from mechplan.sheet.scales import Room

    panel = efficiency_diagram(boom_solution, "en", Room(400.0, 250.0))
    assert panel is not None and panel.name == "force-diagram-eta"
    from mechplan.sheet.compose import compose
    comp = compose(boom_solution, "A1", "iso", "en", name="boom")
    assert "force-diagram-eta" in [p.name for placed in comp.placements for p, _ in placed]


def test_friction_only_in_the_driving_sliders_guide_closed_form():
    """Only the frame guide of the driving block rubs (f = 0.3): the slot's reaction on the block
    is ⊥ the slot, N = T/ρ from link 3's moments (T = 150 N·m, ρ = |O3B|), and the block needs
    F_d = N·(sin θ3 + f·|cos θ3|): η = 1/(1 + f·|cot θ3|), θ3 the slot's angle."""
    text = COULISSE.replace('"0-1" = { f = 0.2 }', '"0-1" = { f = 0.3 }').replace(
        '"2-3" = { f = 0.15 }', '"2-3" = { f = 0 }').replace("f = 0.1\n", "f = 0\n")
    fa = _solve(text)
    fr = fa.friction
    assert fr is not None and [p.pair for p in fr.pairs] == ["0-1"]
    q = np.asarray(fa.phi)
    theta = np.arctan2(0.3, q - 0.1)
    n = 150.0 / np.hypot(q - 0.1, 0.3)
    np.testing.assert_allclose(fr.free_moment, n * np.sin(theta), rtol=1e-12)
    needed = n * (np.sin(theta) + 0.3 * np.abs(np.cos(theta)))
    np.testing.assert_allclose(fa.balancing_moment, needed, rtol=1e-12)
    eta = 1 / (1 + 0.3 * np.abs(np.cos(theta) / np.sin(theta)))
    np.testing.assert_allclose(fr.efficiency, eta, rtol=1e-12)
    np.testing.assert_allclose(fr.efficiency_power, fr.efficiency, rtol=1e-12)
