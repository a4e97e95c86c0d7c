"""The excavator arm template as shipped — loaded while digging — gives each cylinder's driving
force equal to the virtual power of its loads with that cylinder moving alone (the other held).

Golden values: the template's figures (masses, moments of inertia, centres, the bucket's weight at
Q, the digging resistance at the teeth T) written out here, the loop closure solved by a bracketing
root-finder (tests/construct/test_cylinder_second_driver.py), real accelerations by five-point
finite differences in time with both cylinders moving by their laws, and two virtual velocity
fields by finite differences with one cylinder's length changed, the other's held. Nothing of the
construction or its force plans is used.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.scene import load_scene
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
from test_cylinder_second_driver import (
    B_2,
    E_2,
    F_2,
    G_5,
    TEMPLATE,
    A,
    arm_angle,
    boom_angle,
    rot,
)

G = 9.81
L4DOT, L7DOT = 0.1, 0.075                  # the template's laws (no acceleration)
L4_0, L7_0 = 2.2, 2.7
D_2, S_5 = np.array([2.9, 0.25]), np.array([1.8, -0.1])
Q_5, T_5 = np.array([3.4, -0.5]), np.array([3.5, -1.3])
#: (mass kg, J kg·m² about the centre) of the boom, boom barrel, boom rod, arm, arm barrel, arm rod
BODIES = ((1800.0, 4900.0), (160.0, 0.0), (80.0, 0.0), (950.0, 700.0), (160.0, 0.0), (80.0, 0.0))
F_Q = np.array([0.0, -25020.0])            # bucket with its soil, 2550 kg
F_T = np.array([30000.0, -26460.0])        # the digging resistance at the teeth


def _state(th2: float, th5: float) -> np.ndarray:
    """Centres of the six bodies, Q, T (x, y each) and the bodies' angles."""
    b, e, f_ = rot(th2, B_2), rot(th2, E_2), rot(th2, F_2)
    g = e + rot(th5, G_5)
    u3, u6 = (b - A) / np.hypot(*(b - A)), (g - f_) / np.hypot(*(g - f_))
    th3, th6 = math.atan2(u3[1], u3[0]), math.atan2(u6[1], u6[0])
    return np.concatenate([rot(th2, D_2), A + 0.7 * u3, b, e + rot(th5, S_5), f_ + 0.75 * u6, g,
                           e + rot(th5, Q_5), e + rot(th5, T_5),
                           [th2, th3, th3, th5, th6, th6]])


def _at(l4: float, l7: float) -> np.ndarray:
    th2 = boom_angle(l4)
    return _state(th2, arm_angle(th2, l7))


def _d(fun, h):
    return (fun(-2 * h) - 8 * fun(-h) + 8 * fun(h) - fun(2 * h)) / (12 * h)


def _dd(fun, h):
    return (-fun(-2 * h) + 16 * fun(-h) - 30 * fun(0.0) + 16 * fun(h) - fun(2 * h)) / (12 * h * h)


def _power(acc: np.ndarray, v: np.ndarray) -> float:
    """The power of the weights, inertia forces and couples, F_Q and F_T at the velocities v."""
    p = 0.0
    for i, (m, j) in enumerate(BODIES):
        sl = slice(2 * i, 2 * i + 2)
        p += float((-m * acc[sl] + [0.0, -m * G]) @ v[sl])
        p += -j * acc[16 + i] * v[16 + i]
    return p + float(F_Q @ v[12:14]) + float(F_T @ v[14:16])


def golden(l4: float, l7dot: float = L7DOT) -> tuple[float, float]:
    """(F_d4, F_d7) from the virtual power, each cylinder moving alone at a unit rate (the arm
    cylinder's real rate ``l7dot``: 0 when it is held at L7_0)."""
    l7 = L7_0 + l7dot / L4DOT * (l4 - L4_0)
    acc = _dd(lambda t: _at(l4 + L4DOT * t, l7 + l7dot * t), 1e-2)
    v4 = _d(lambda dq: _at(l4 + dq, l7), 1e-4)
    v7 = _d(lambda dq: _at(l4, l7 + dq), 1e-4)
    return -_power(acc, v4), -_power(acc, v7)


@pytest.fixture(scope="module")
def shipped():
    scene = load_scene(TEMPLATE)
    return solve(scene)


def test_the_template_is_loaded(shipped):
    masses = shipped.scene.masses
    assert {lk: masses[lk].mass for lk in "234567"} == pytest.approx(
        {lk: m for lk, (m, _j) in zip("234567", BODIES, strict=True)})
    assert {lk: masses[lk].inertia for lk in "25"} == pytest.approx({"2": 4900.0, "5": 700.0})
    assert len(shipped.scene.loads) == 2
    assert "force" in shipped.plans


@pytest.mark.parametrize("k", range(5))
def test_each_cylinders_driving_force_equals_the_virtual_power(shipped, k):
    l4 = float(shipped.phi[k])
    assert l4 == pytest.approx(L4_0 + 0.2 * k, abs=1e-12)
    f4, f7 = golden(l4)
    fa = shipped.extras["forces"]
    assert float(fa.balancing_moment[k]) == pytest.approx(f4, rel=1e-6)
    assert fa.second is not None and fa.second[0] == "7"
    assert float(fa.second[1][k]) == pytest.approx(f7, rel=1e-6)
    # Zhukovsky's lever, the arm cylinder's F_d7·l̇7 one more term, gives F_d4 again
    assert float(fa.zhukovsky_moment[k]) == pytest.approx(float(fa.balancing_moment[k]),
                                                          rel=1e-9)
    # both cylinders push while digging: the boom's of the order of 3–4·10⁵ N
    assert 3.0e5 < f4 < 4.0e5 and f7 > 0


def test_the_golden_values_see_every_load():
    """The virtual power is not blind to the template's figures: the digging resistance alone
    changes F_d4 by more than 5 %, and the inertia terms are small but not zero."""
    l4 = 2.6
    f4, _ = golden(l4)
    global F_T
    kept = F_T
    try:
        F_T = np.zeros(2)
        f4_free, _ = golden(l4)
    finally:
        F_T = kept
    assert abs(f4 - f4_free) > 0.05 * abs(f4)


def test_friction_with_a_linear_first_driver_closes_on_its_driving_force():
    """Friction in every pair (the two cylinders' sliding pairs too): the iteration closes on the
    first cylinder's F_d; its friction-free pass is the template's F_d, the lever agrees."""
    from mechplan.scene.loader import parse_scene

    text = TEMPLATE.read_text(encoding="utf-8")
    friction = text.replace("[drive]\n",
                            '[friction]\nf = 0.1\npin_radius = "40 mm"\n\n[drive]\n', 1)
    plain = solve(parse_scene(text, "plain.toml")).extras["forces"]
    fa = solve(parse_scene(friction, "friction.toml")).extras["forces"]
    fr = fa.friction
    assert fr is not None and np.all(fr.converged)
    assert {"3-4", "6-7"} <= {p.pair for p in fr.pairs}          # the cylinders' own pairs
    scale = np.abs(plain.balancing_moment).max()
    np.testing.assert_allclose(fr.free_moment, plain.balancing_moment, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(fa.zhukovsky_moment, fa.balancing_moment, rtol=1e-9)
    assert np.all(fa.balancing_moment > fr.free_moment)             # friction is overcome
    assert np.all((fr.efficiency > 0.9) & (fr.efficiency < 1.0))
