"""W = 2 with any order of driver kinds (a slider as the second driver after a crank or a
cylinder, a crank after a slider): each driver's balancing moment or driving force against the
virtual power of the loads with each driver moving alone (the other held), the inertia loads
from the real motion (both drivers by their laws) by five-point finite differences in time of the
loop closure (tests/construct/test_second_driver_kinds.py). Nothing of mechplan's force plans is
used.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
from test_second_driver_kinds import CASES, L2, L3, _dyad, _e, laws, pins, scene_text

M2, J2, M3, J3, M4, G = 2.0, 0.01, 1.5, 0.006, 1.0, 9.81
F_D = np.array([50.0, 0.0])      # a force on the slider 4 at D


def loaded(case: str) -> str:
    text = scene_text(case)
    text = text.replace('lengths = { BC = "200 mm" }',
                        'lengths = { BC = "200 mm" }\npoints = { S2 = "0.5 of B C" }\n'
                        'mass = "2 kg"\ncentre = "S2"\nJ = "0.01 kg*m^2"')
    text = text.replace('lengths = { DC = "150 mm" }',
                        'lengths = { DC = "150 mm" }\npoints = { S3 = "0.5 of D C" }\n'
                        'mass = "1.5 kg"\ncentre = "S3"\nJ = "0.006 kg*m^2"')
    for link4 in ('slides = { point = "D", on = "g" }', 'lengths = { HD = "60 mm" }'):
        text = text.replace(link4, f'{link4}\nmass = "1 kg"\ncentre = "D"')
    return text.replace("[assembly]", '[gravity]\ng = "9.81 m/s^2"\n\n[[loads]]\n'
                        'type = "force"\npoint = "D"\nlink = "4"\nvector = ["50 N", "0 N"]\n\n'
                        "[assembly]")


def centres(case: str, q1: float, q2: float) -> np.ndarray:
    """(S2, S3, D, θ2, θ3) for the drivers' coordinates."""
    _, b, d = pins(case, q1, q2)
    t2, t3 = _dyad(b, d)
    return np.concatenate([b + L2 / 2 * _e(t2), d + L3 / 2 * _e(t3), d, [t2, t3]])


def golden(case: str, x: float) -> list[float]:
    (q1, r1, a1), (q2, r2, a2) = laws(case, x)
    h = 2e-4
    xs = [centres(case, q1 + r1 * k * h + a1 * (k * h) ** 2 / 2,
                  q2 + r2 * k * h + a2 * (k * h) ** 2 / 2) for k in (-2, -1, 0, 1, 2)]
    acc = (-xs[0] + 16 * xs[1] - 30 * xs[2] + 16 * xs[3] - xs[4]) / (12 * h * h)
    forces = [(slice(0, 2), -M2 * acc[0:2] + [0, -M2 * G]),
              (slice(2, 4), -M3 * acc[2:4] + [0, -M3 * G]),
              (slice(4, 6), -M4 * acc[4:6] + [0, -M4 * G] + F_D)]
    couples = [(6, -J2 * acc[6]), (7, -J3 * acc[7])]
    out = []
    for which in (0, 1):        # each driver moving alone at a unit rate (rad/s or m/s)
        def alone(t, which=which):
            return centres(case, q1 + (t if which == 0 else 0.0), q2 + (t if which == 1 else 0.0))
        e = 1e-6
        v = (alone(-2 * e) - 8 * alone(-e) + 8 * alone(e) - alone(2 * e)) / (12 * e)
        power = sum(float(f @ v[s]) for s, f in forces) + sum(c * v[i] for i, c in couples)
        out.append(-power)
    return out


@pytest.mark.parametrize(("case", "x"), [(c, x) for c, xs in CASES.items() for x in xs])
def test_each_driver_load_equals_virtual_power(case, x):
    sol = solve(parse_scene(loaded(case), f"{case}.toml"), at_deg=[x],
                plans=("position", "velocity", "acceleration", "force"))
    fa = sol.extras["forces"]
    first, second = golden(case, x)
    assert fa.second is not None and fa.second[0] == ("1" if case == "slider_crank" else "4")
    linear2 = case.endswith("slider")
    assert float(fa.balancing_moment[0]) == pytest.approx(first, rel=1e-6, abs=1e-6)
    assert float(fa.second[1][0]) == pytest.approx(second, rel=1e-6, abs=1e-6)
    # Zhukovsky's lever, the second driver's load one more term, gives the first's again
    assert float(fa.zhukovsky_moment[0]) == pytest.approx(first, rel=1e-6, abs=1e-6)
    assert fa.second_linear is linear2
    assert math.isfinite(float(fa.balancing_moment[0]))
