"""Balancing moments of cranks moving by laws by tables (``law`` of ``[drive]`` / ``[drive2]``),
checked by virtual power with each crank moving alone; the real motion (for the inertia loads)
follows the tables' polynomials, the accelerations by five-point finite differences in time of
the loop closure solved by scipy. Nothing of mechplan's construction is used.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parent))
from test_two_cranks_forces import F_C, J2, J3, M2, M3, M4, TEMPLATE, G, _d, _solve, _state

A, E = np.array([0.0, 0.0]), np.array([0.150, 0.0])
L1, L2, L3, L4 = 0.060, 0.200, 0.180, 0.080
T = np.arange(0.0, 0.80001, 0.1)
P1 = np.polynomial.Polynomial([0.0, 8.0, 6.0, -1.0])      # φ1(t) ccw from +x, rad
P4 = np.polynomial.Polynomial([0.5, 9.0, -4.0, 2.0])      # φ4(t) cw from −x, rad


def rows(p) -> str:
    return ", ".join(f"[{float(t)!r}, {math.degrees(float(p(t)))!r}]" for t in T)


def _law_scene():
    """The loaded five-bar of test_two_cranks_forces, both cranks moving by tables."""
    text = TEMPLATE.read_text(encoding="utf-8")
    for link, centre, extra in (
            ('BC = "200 mm"', 'S2 = "0.5 of B C"',
             'mass = "2 kg"\ncentre = "S2"\nJ = "0.01 kg*m^2"'),
            ('DC = "180 mm"', 'S3 = "0.5 of D C"',
             'mass = "1.5 kg"\ncentre = "S3"\nJ = "0.006 kg*m^2"'),
            ('ED = "80 mm"', 'S4 = "0.5 of E D"', 'mass = "0.8 kg"\ncentre = "S4"')):
        text = text.replace(f"lengths = {{ {link} }}",
                            f"lengths = {{ {link} }}\npoints = {{ {centre} }}\n{extra}")
    text = text.replace("[assembly]", '[gravity]\ng = "9.81 m/s^2"\n\n[[loads]]\ntype = "force"\n'
                        'point = "C"\nlink = "3"\nvector = ["30 N", "-120 N"]\n\n[assembly]')
    head, _, tail = text.partition("[drive2]")
    head = head.replace('speed = "10 rad/s"\nsense = "ccw"',
                        f'sense = "ccw"\nlaw = {{ table = [{rows(P1)}] }}')
    tail = tail.replace('speed = "10 rad/s"', f'law = {{ table = [{rows(P4)}] }}').replace(
        'phase = "90 deg"\n', "")
    return parse_scene(head + "[drive2]" + tail, "five_law.toml")


def _golden(phi1: float):
    t0 = brentq(lambda t: P1(t) - phi1, 0.0, 0.8, xtol=1e-15)
    th1, th4 = P1(t0), math.pi - P4(t0)
    b, d = A + L1 * np.array([math.cos(th1), math.sin(th1)]), E + L4 * np.array(
        [math.cos(th4), math.sin(th4)])
    m, u = (b + d) / 2, (d - b) / np.linalg.norm(d - b)
    c = m + 0.15 * np.array([-u[1], u[0]])
    guess = _solve(th1, th4, np.array([math.atan2(*(c - b)[::-1]),
                                       math.atan2(*(c - d)[::-1])]))

    def motion(t):
        return _state(P1(t0 + t), math.pi - P4(t0 + t), guess)
    h = 2e-4
    x = [motion(k * h) for k in (-2, -1, 0, 1, 2)]
    acc = (-x[0] + 16 * x[1] - 30 * x[2] + 16 * x[3] - x[4]) / (12 * h * h)
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
        power = sum(float(f @ v[s]) for s, f in forces) + sum(cc * v[i] for i, cc in couples)
        moments.append(-power)
    return moments


@pytest.mark.parametrize("deg", [20.0, 110.0, 230.0, 400.0])
def test_balancing_moments_of_cranks_by_tables_equal_virtual_power(deg):
    sol = solve(_law_scene(), at_deg=[deg],
                plans=("position", "velocity", "acceleration", "force"))
    fa = sol.extras["forces"]
    mb1, mb4 = _golden(math.radians(deg))
    assert float(fa.balancing_moment[0]) == pytest.approx(mb1, rel=1e-6, abs=1e-7)
    assert fa.second is not None and fa.second[0] == "4"
    assert float(fa.second[1][0]) == pytest.approx(mb4, rel=1e-6, abs=1e-7)
    # Zhukovsky's lever with the tables' ω1, ω4 gives crank 1's moment again
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(mb1, rel=1e-6, abs=1e-7)
