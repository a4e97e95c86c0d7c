"""W = 2 with cylinders: one driving force per cylinder (and a crank's balancing moment with a
cylinder), each checked by virtual power with two independent virtual velocities — each driver
moving alone at a unit rate, the other held — computed from the loop closure and finite
differences only (tests/construct/test_cylinder_second_driver.py), never from the construction.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.dynamics.loading import Loading
from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
from test_cylinder_second_driver import (
    B_2,
    E_2,
    F_2,
    G_5,
    L4DDOT,
    L4DOT,
    L7DDOT,
    L7DOT,
    TEMPLATE,
    A,
    arm_angle,
    boom_angle,
    rot,
)

G = 9.81
D_2, S_5 = np.array([2.9, 0.25]), np.array([1.8, -0.1])
M2, J2, M3, M5, J5, M6 = 1500.0, 4000.0, 120.0, 1400.0, 1200.0, 110.0
F_H = np.array([-20000.0, 5000.0])          # the digging resistance at the bucket pivot H
FORCES = ("position", "velocity", "acceleration", "force")


def unloaded(text: str) -> str:
    """The template without its own masses, gravity and loads (the kinematic arm)."""
    text = re.sub(r"(?m)^(mass|J|centre) = .*\n", "", text)
    return re.sub(r"(?ms)^(\[gravity\]|\[\[loads\]\])\n.*?\n\n", "", text)


def _loaded(text: str) -> str:
    """The template with masses (boom, arm with its bucket, barrels) and gravity instead of its
    own (these tests' figures, not the template's)."""
    text = unloaded(text)
    for link, lines in (("2", 'mass = "1500 kg"\nJ = "4000 kg m^2"\ncentre = "D"\n'),
                        ("3", 'mass = "120 kg"\ncentre = "C"\n'),
                        ("5", 'mass = "1400 kg"\nJ = "1200 kg m^2"\ncentre = "S"\n'),
                        ("6", 'mass = "110 kg"\ncentre = "K"\n')):
        head = f"[links.{link}]\n"
        at = text.index(head) + len(head)
        at = text.index("\n", at) + 1          # after its name
        text = text[:at] + lines + text[at:]
    return text.replace("[drive]\n", '[gravity]\ng = "9.81 m/s^2"\n\n[drive]\n', 1)


def _text() -> str:
    text = _loaded(TEMPLATE.read_text(encoding="utf-8"))
    text = text.replace('acceleration = "0 m/s^2"', 'acceleration = "0.03 m/s^2"')
    text = text.replace('start = "2700 mm"', 'start = "2700 mm"\nacceleration = "-0.02 m/s^2"')
    return text.replace("[drive]\n", '[[loads]]\ntype = "force"\npoint = "H"\nlink = "5"\n'
                        'vector = ["-20 kN", "5 kN"]\n\n[drive]\n', 1)


def _solve(text: str, at: float):
    scene = parse_scene(text, str(TEMPLATE))
    return solve(scene, at_deg=[at], plans=FORCES, loading=Loading.from_scene(scene))


def centres(th2: float, th5: float) -> np.ndarray:
    """D, C (barrel 3), S, K (barrel 6), H and the angles θ2, θ3, θ5, θ6."""
    b, e, f_ = rot(th2, B_2), rot(th2, E_2), rot(th2, F_2)
    g = e + rot(th5, G_5)
    u3, u6 = (b - A) / np.hypot(*(b - A)), (g - f_) / np.hypot(*(g - f_))
    return np.concatenate([rot(th2, D_2), A + 0.7 * u3, e + rot(th5, S_5), f_ + 0.75 * u6,
                           e + rot(th5, np.array([2.9, 0.0])),
                           [th2, math.atan2(u3[1], u3[0]), th5, math.atan2(u6[1], u6[0])]])


def _d(fun, h):
    return (fun(-2 * h) - 8 * fun(-h) + 8 * fun(h) - fun(2 * h)) / (12 * h)


def _dd(fun, h):
    return (-fun(-2 * h) + 16 * fun(-h) - 30 * fun(0.0) + 16 * fun(h) - fun(2 * h)) / (12 * h * h)


def _loads_power(acc: np.ndarray, v: np.ndarray, boom_cylinder: bool) -> float:
    """Power of the weights, inertia forces and couples and the force at H at velocities v."""
    p = 0.0
    m3 = M3 if boom_cylinder else 0.0
    for m, sl in ((M2, slice(0, 2)), (m3, slice(2, 4)), (M5, slice(4, 6)), (M6, slice(6, 8))):
        p += float((-m * acc[sl] + [0.0, -m * G]) @ v[sl])
    p += float(F_H @ v[8:10])
    p += -J2 * acc[10] * v[10] - J5 * acc[12] * v[12]
    return p


def _golden(th2_of, l7: float, rate1: float, eps1: float, boom_cylinder: bool = True):
    """(first, second): −P/rate of the loads when each driver moves alone (the other held)."""
    def motion(t):
        th2 = th2_of(t * rate1 + eps1 * t * t / 2)
        return centres(th2, arm_angle(th2, l7 + L7DOT * t + L7DDOT * t * t / 2))
    acc = _dd(motion, 1e-3)

    def first_alone(dq):
        th2 = th2_of(dq)
        return centres(th2, arm_angle(th2, l7))

    def second_alone(dq):
        th2 = th2_of(0.0)
        return centres(th2, arm_angle(th2, l7 + dq))
    return (-_loads_power(acc, _d(first_alone, 1e-4), boom_cylinder),
            -_loads_power(acc, _d(second_alone, 1e-4), boom_cylinder))


@pytest.mark.parametrize("l4_mm", [2200.0, 2500.0, 2800.0, 3000.0])
def test_each_cylinder_driving_force_equals_virtual_power(l4_mm):
    sol = _solve(_text(), l4_mm)
    fa = sol.extras["forces"]
    l4 = l4_mm / 1000
    f4, f7 = _golden(lambda dq: boom_angle(l4 + dq), 2.7 + 0.75 * (l4 - 2.2), L4DOT, L4DDOT)
    assert fa.linear and fa.second is not None and fa.second[0] == "7" and fa.second_linear
    assert float(fa.balancing_moment[0]) == pytest.approx(f4, rel=1e-6)
    assert float(fa.second[1][0]) == pytest.approx(f7, rel=1e-6)
    # Zhukovsky's lever (the arm cylinder's F_d7·l̇7 one more term) gives F_d4 again
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(float(fa.balancing_moment[0]), rel=1e-9)
    doc = fa.json(0)["forces"]
    assert doc["second_driving_force"]["link"] == "7"
    assert doc["second_driving_force"]["value"] == pytest.approx(f7, rel=1e-6)
    assert f4 > 0       # the boom cylinder holds the boom up


def test_crank_balancing_moment_and_cylinder_force_equal_virtual_power():
    from test_cylinder_second_driver import EPS2, W2

    # the loaded template with the boom driven as a crank (the boom cylinder removed)
    scene = parse_scene(_crank_text(_text()), "crank_cylinder.toml")
    phi = math.radians(30.0)
    sol = solve(scene, at_deg=[30.0], plans=FORCES, loading=Loading.from_scene(scene))
    fa = sol.extras["forces"]
    mb, f7 = _golden(lambda dq: phi + dq, 2.7 + L7DOT / W2 * phi, W2, EPS2, boom_cylinder=False)
    assert not fa.linear and fa.second_linear and fa.second[0] == "7"
    assert float(fa.balancing_moment[0]) == pytest.approx(mb, rel=1e-6)
    assert float(fa.second[1][0]) == pytest.approx(f7, rel=1e-6)
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(float(fa.balancing_moment[0]), rel=1e-9)


def _crank_text(text: str) -> str:
    """The loaded template with the boom driven as a crank about O (ω 0.08 rad/s, ε 0.01)."""
    head, _, tail = text.partition("[links.3]")
    text = head + tail[tail.index("[links.5]"):]
    text = text.replace('A = ["600 mm", "-1000 mm"]\n', "")
    start, end = text.index("[drive]"), text.index("[drive2]")
    text = (text[:start] + '[drive]\nlink = "2"\nspeed = "0.08 rad/s"\nepsilon = "0.01 rad/s^2"\n\n'
            + text[end:])
    return text.replace('B = "right of A->O"\n', "").replace("[positions]\ncount = 5\n", "")


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_the_report_writes_both_driving_forces(lang):
    from mechplan.i18n import message
    from mechplan.i18n import number as format_number
    from mechplan.report import text_report

    sol = _solve(_text(), 2600.0)
    text = text_report(sol, lang)
    fa = sol.extras["forces"]
    for link, value in (("4", fa.balancing_moment[0]), ("7", fa.second[1][0])):
        line = message("drivers.force", lang, link=link, F=format_number(float(value), 3, lang),
                       unit="", role="")
        assert line.split(" (")[0].split("（")[0].rstrip() in text, (lang, link)
    assert fa.second is not None and float(fa.second[1][0]) < 0    # the arm cylinder pulls
