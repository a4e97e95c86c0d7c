"""The single-mass elastic follower: the residual vibration after an undamped cycloidal rise started
from rest against its closed form h·|sin πλ|/(πλ·|1 − λ²|), λ = T·ω_n/(2π) (Duhamel's integral of
the cycloid's acceleration), and a damped response against scipy's LSODA on the error equation with
the cycloid written here."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from mechplan.studies.cam import solve_cam

H = 0.010
BETA = math.radians(80)
OMEGA = 1000 * math.pi / 30
T = BETA / OMEGA
M = 0.3


def scene(k: float, zeta: float) -> str:
    return f"""kind = "cam"
title = "t"
[follower]
motion = "translating"
contact = "flat"
offset = "0 mm"
[motion]
stroke = "10 mm"
speed = "1000 rpm"
phases = [
    {{ kind = "rise", angle = "80 deg", law = "cycloidal" }},
    {{ kind = "far_dwell", angle = "100 deg" }},
    {{ kind = "return", angle = "80 deg", law = "cycloidal" }},
    {{ kind = "near_dwell", angle = "100 deg" }},
]
[limits]
base_radius = "60 mm"
[dynamics]
mass = "{M} kg"
stiffness = "5 N/mm"
preload = "100 N"
follower_stiffness = "{k} N/m"
damping_ratio = {zeta}
"""


@pytest.mark.parametrize("lam", [2.3, 3.7, 5.5])
def test_undamped_residual_after_a_cycloidal_rise(lam):
    wn = 2 * math.pi * lam / T
    r = solve_cam(scene(M * wn * wn, 0.0), "c.toml").design.dynamics.elastic
    assert r.natural_frequency == pytest.approx(wn, rel=1e-12)
    far = next(a for kind, _, a in r.first_residual if kind == "far_dwell")
    expected = H * abs(math.sin(math.pi * lam)) / (math.pi * lam * abs(1 - lam * lam))
    assert far == pytest.approx(expected, rel=1e-6)


def test_damped_response_against_lsoda():
    lam, zeta = 3.3, 0.08
    wn = 2 * math.pi * lam / T
    r = solve_cam(scene(M * wn * wn, zeta), "c.toml").design.dynamics.elastic

    def s2(t):
        phi = (OMEGA * t) % (2 * math.pi)
        t_ret = math.radians(180)
        if phi < BETA:
            return H * 2 * math.pi / T ** 2 * math.sin(2 * math.pi * phi / BETA)
        if t_ret <= phi < t_ret + BETA:
            return -H * 2 * math.pi / T ** 2 * math.sin(2 * math.pi * (phi - t_ret) / BETA)
        return 0.0

    period = 2 * math.pi / OMEGA
    cuts = [k * period + math.radians(a) / OMEGA for k in range(3) for a in (0, 80, 180, 260)]
    cuts.append(3 * period)
    wd = wn * math.sqrt(1 - zeta ** 2)
    near = next(a for kind, _, a in r.residual if kind == "near_dwell")
    # the near dwell starts at 260°; integrate that far independently and compare
    y = np.zeros(2)
    for t0, t1 in itertools.pairwise(cuts):
        if t0 >= 2 * period + math.radians(260) / OMEGA - 1e-12:
            break
        sol = solve_ivp(lambda t, v: [v[1], -2 * zeta * wn * v[1] - wn * wn * v[0] - s2(t)],
                        (t0, t1), y, method="LSODA", rtol=1e-10, atol=1e-15)
        y = sol.y[:, -1]
    assert near == pytest.approx(math.hypot(y[0], y[1] / wd), rel=1e-5)
