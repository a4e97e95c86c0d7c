"""W = 2: one balancing moment per crank, checked by virtual power with two independent virtual
velocities (each crank moving alone), computed from the loop closure and finite differences only.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

TEMPLATE = Path(__file__).parents[2] / "src/mechplan/templates/five_bar_two_cranks.toml"
A, E = np.array([0.0, 0.0]), np.array([0.150, 0.0])
L1, L2, L3, L4 = 0.060, 0.200, 0.180, 0.080
W1, W4, EPS1, EPS4 = 10.0, -10.0, 4.0, -7.0
M2, J2, M3, J3, M4, G = 2.0, 0.01, 1.5, 0.006, 0.8, 9.81
F_C = np.array([30.0, -120.0])     # a constant force at C, on link 3


def _scene():
    text = TEMPLATE.read_text(encoding="utf-8")
    text = text.replace('sense = "ccw"\n', 'sense = "ccw"\nepsilon = "4 rad/s^2"\n', 1)
    text = text.replace('phase = "90 deg"\n', 'phase = "90 deg"\nepsilon = "7 rad/s^2"\n')
    text = text.replace('lengths = { BC = "200 mm" }',
                        'lengths = { BC = "200 mm" }\npoints = { S2 = "0.5 of B C" }\n'
                        'mass = "2 kg"\ncentre = "S2"\nJ = "0.01 kg*m^2"')
    text = text.replace('lengths = { DC = "180 mm" }',
                        'lengths = { DC = "180 mm" }\npoints = { S3 = "0.5 of D C" }\n'
                        'mass = "1.5 kg"\ncentre = "S3"\nJ = "0.006 kg*m^2"')
    text = text.replace('lengths = { ED = "80 mm" }',
                        'lengths = { ED = "80 mm" }\npoints = { S4 = "0.5 of E D" }\n'
                        'mass = "0.8 kg"\ncentre = "S4"')
    text = text.replace("[assembly]", '[gravity]\ng = "9.81 m/s^2"\n\n[[loads]]\ntype = "force"\n'
                        'point = "C"\nlink = "3"\nvector = ["30 N", "-120 N"]\n\n[assembly]')
    return parse_scene(text, str(TEMPLATE))


def _e(a):
    return np.array([math.cos(a), math.sin(a)])


def _solve(th1, th4, guess):
    b, d = A + L1 * _e(th1), E + L4 * _e(th4)

    def f(x):
        return b + L2 * _e(x[0]) - d - L3 * _e(x[1])
    x = fsolve(f, guess, xtol=1e-13)
    assert np.abs(f(x)).max() < 1e-14
    return x


def _state(th1, th4, guess):
    """Centres S2, S3, S4 and the angles θ2, θ3 at the crank angles."""
    t2, t3 = _solve(th1, th4, guess)
    b, d = A + L1 * _e(th1), E + L4 * _e(th4)
    return np.concatenate([b + L2 / 2 * _e(t2), d + L3 / 2 * _e(t3), E + L4 / 2 * _e(th4),
                           b + L2 * _e(t2), [t2, t3, th4]])


def _d(fun, h):
    return (fun(-2 * h) - 8 * fun(-h) + 8 * fun(h) - fun(2 * h)) / (12 * h)


def _golden(phi1):
    th1, th4 = phi1, math.pi - (math.pi / 2 + phi1)
    b, d = A + L1 * _e(th1), E + L4 * _e(th4)
    m, u = (b + d) / 2, (d - b) / np.linalg.norm(d - b)
    c = m + 0.15 * np.array([-u[1], u[0]])
    guess = np.array([math.atan2(*(c - b)[::-1]), math.atan2(*(c - d)[::-1])])
    guess = _solve(th1, th4, guess)

    def motion(t):
        return _state(th1 + W1 * t + EPS1 * t * t / 2, th4 + W4 * t + EPS4 * t * t / 2, guess)
    h = 2e-4
    x = [motion(k * h) for k in (-2, -1, 0, 1, 2)]
    acc = (-x[0] + 16 * x[1] - 30 * x[2] + 16 * x[3] - x[4]) / (12 * h * h)
    # the loads: weights, inertia forces at the centres, inertia couples, the force at C
    forces = [(slice(0, 2), -M2 * acc[0:2] + [0, -M2 * G]),
              (slice(2, 4), -M3 * acc[2:4] + [0, -M3 * G]),
              (slice(4, 6), -M4 * acc[4:6] + [0, -M4 * G]),
              (slice(6, 8), F_C)]
    couples = [(8, -J2 * acc[8]), (9, -J3 * acc[9])]
    moments = []
    for which in (0, 1):     # each crank moving alone at 1 rad/s (virtual velocities)
        def alone(t, which=which):
            return _state(th1 + (t if which == 0 else 0.0), th4 + (t if which == 1 else 0.0),
                          guess)
        v = _d(alone, 1e-5)
        power = sum(float(f @ v[s]) for s, f in forces) + sum(c * v[i] for i, c in couples)
        moments.append(-power)
    return moments


@pytest.mark.parametrize("deg", [0.0, 70.0, 160.0, 290.0])
def test_each_crank_balancing_moment_equals_virtual_power(deg):
    sol = solve(_scene(), at_deg=[deg], plans=("position", "velocity", "acceleration", "force"))
    fa = sol.extras["forces"]
    mb1, mb4 = _golden(math.radians(deg))
    assert fa.second is not None and fa.second[0] == "4"
    assert float(fa.balancing_moment[0]) == pytest.approx(mb1, rel=1e-7, abs=1e-7)
    assert float(fa.second[1][0]) == pytest.approx(mb4, rel=1e-7, abs=1e-7)
    # Zhukovsky's lever (crank 4's moment one more couple on it) gives crank 1's again
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(mb1, rel=1e-7, abs=1e-7)
    doc = fa.json(0)["forces"]["second_balancing_moment"]
    assert doc["link"] == "4" and doc["value"] == pytest.approx(mb4, rel=1e-7, abs=1e-7)
