"""A crank-driven RRR dyad near its toggle against 60-digit references (issue 29).

A non-Grashof four-bar (AB = 0.1 m, BC = 0.12 m, DC = 0.1 m, AD = 0.3 m) cannot turn its crank past
θ₀ = arccos 0.86, where |BD| = BC + CD: the arcs about B and D touch, and ω₃ grows as 1/sine.
Every value is checked against a 60-digit closed form (``singular_refs.four_bar``). The position
is within its estimate. The rates are not: their relative error grows as 1/sine² (measured at
1e-12 rad from θ₀: v_C 7.9e-5, a_C 2.4e-4) while the velocity estimate grows as 1/sine (1.1e-9)
and the acceleration estimate not at all (1.2e-15) — neither flagged nor refused. The plans'
meets lie ~|v| ∝ 1/sine (|a| ∝ 1/sine³) from their lines' points, a lever the estimate does not
count. That test is an expected failure until the estimate counts it.
"""

from __future__ import annotations

import math

import pytest
from construct import singular_refs as ref

from mechplan.construct.estimate import DEFAULT_TOLERANCE
from mechplan.errors import SingularError
from mechplan.scene import parse_scene
from mechplan.solve import solve

KINEMATIC = ("position", "velocity", "acceleration")
NON_GRASHOF = """
title = "non-Grashof four-bar at its crank's limit: BD = BC + CD"
[ground]
A = ["0 m", "0 m"]
D = ["0.3 m", "0 m"]
[links.1]
lengths = { AB = "0.1 m" }
[links.2]
lengths = { BC = "0.12 m" }
[links.3]
lengths = { DC = "0.1 m" }
[drive]
link = "1"
speed = "10 rad/s"
sense = "ccw"
[assembly]
at = "0 deg"
C = "left of B->D"
"""
THETA0 = math.acos(0.86)


def _solve(offset):
    scene = parse_scene(NON_GRASHOF, "toggle.toml")
    try:
        sol = solve(scene, at_deg=[math.degrees(THETA0 - offset)], plans=KINEMATIC)
    except SingularError as exc:                 # too close to tell: refused, and said where
        assert "φ" in str(exc)
        return None, None
    theta = sol.construction.drive.absolute(sol.phi)[0]   # the angle solved, exactly
    return sol, ref.four_bar(0.1, 0.12, 0.1, 0.3, float(theta), 10.0)


def _check(sol, exact, checks, slack=1.0):
    """Each value within ``slack``× its estimate (the policy's 10× for the rates), or flagged."""
    c = sol.construction
    for name, (sid, col) in checks(c).items():
        value = sol.ev[sid][0]
        got = float(value[col]) if col is not None else float(value)
        scale = max(sol.estimate.scale[sid], abs(exact[name]))
        true_error = abs(got - exact[name]) / scale
        estimate = float(sol.estimate.relative(sid)[0])
        assert true_error <= slack * max(estimate, 1e-15) or estimate > DEFAULT_TOLERANCE, (
            name, true_error, estimate)


OFFSETS = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14]


@pytest.mark.parametrize("offset", OFFSETS)
def test_near_a_crank_driven_toggle_the_position_is_within_its_estimate(offset):
    sol, exact = _solve(offset)
    if sol is None:
        return
    _check(sol, exact, lambda c: {"C_x": (c.position("C"), 0), "C_y": (c.position("C"), 1)})
    assert abs(float(sol.ev[sol.construction.omega("3")][0])) > 0.1 / math.sqrt(offset)


def test_near_a_crank_driven_toggle_the_rates_are_within_their_estimates():
    for offset in OFFSETS:
        sol, exact = _solve(offset)
        if sol is None:
            continue
        _check(sol, exact, lambda c: {
            "v_C_x": (c.velocity_image("C"), 0), "v_C_y": (c.velocity_image("C"), 1),
            "omega_3": (c.omega("3"), None), "a_C_x": (c.acceleration_image("C"), 0),
            "epsilon_3": (c.epsilon("3"), None)}, slack=10.0)
