"""Flywheel methods against closed forms and an independent integration of the equation of
motion."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

from mechplan.dynamics.flywheel import (
    cumulative_work,
    delta_of,
    exact_flywheel,
    flywheel_size,
    merkalov,
    speed,
    wittenbauer,
)
from mechplan.model.dynamics import FlywheelShape, FlywheelSpec


def test_constant_inertia_sinusoidal_moment_closed_form():
    """J constant, M = M0·sin θ: ΔT = M0(1 − cos θ), ΔE = 2M0, every method gives ΔE/(δω²) − J0."""
    M0, J0, w, delta = 150.0, 0.8, 40.0, 1 / 30
    theta = np.linspace(0.0, 2 * math.pi, 4001)
    dT = M0 * (1 - np.cos(theta))                      # closed form, not the code's quadrature
    J = np.full_like(theta, J0)
    golden = 2 * M0 / (delta * w ** 2) - J0
    assert wittenbauer(J, dT, w, delta).J_flywheel == pytest.approx(golden, rel=1e-12)
    assert merkalov(J - J0, dT, w, delta, J0).J_flywheel == pytest.approx(golden, rel=1e-12)
    J_f, _ = exact_flywheel(theta, J, dT, w, delta, golden)
    assert J_f == pytest.approx(golden, rel=1e-6)
    # trapezoid quadrature of M converges to the closed-form ΔT
    err = [np.abs(cumulative_work(t, M0 * np.sin(t)) - M0 * (1 - np.cos(t))).max()
           for t in (np.linspace(0, 2 * math.pi, n + 1) for n in (12, 24, 48))]
    assert err[0] > err[1] > err[2] and err[1] / err[2] == pytest.approx(4.0, rel=0.05)


def test_merkalov_law_of_motion_constant_inertia_closed_form():
    """J constant, ΔT = M0(1 − cos θ): J_I = 2M0/(δω_m²), so ω = ω_m(1 − (δ/2)·cos θ) exactly,
    within O(δ²·ω_m) of the exact ½Jω² = E0 + ΔT law."""
    M0, J0, w, delta = 150.0, 0.8, 40.0, 1 / 30
    theta = np.linspace(0.0, 2 * math.pi, 4001)
    dT = M0 * (1 - np.cos(theta))
    J = np.full_like(theta, J0)
    law = merkalov(J - J0, dT, w, delta, J0).omega
    np.testing.assert_allclose(law, w * (1 - 0.5 * delta * np.cos(theta)), rtol=1e-13)
    J_f, E0 = exact_flywheel(theta, J, dT, w, delta, 1.0)
    exact = speed(J + J_f, dT, E0)
    gap = float(np.abs(law - exact).max())
    assert 1e-6 * delta * w < gap < delta ** 2 * w


def _case():
    w_m, delta = 30.0, 0.02
    J0, a = 0.5, 0.08

    def J(t):
        return J0 + a * (1 - np.cos(2 * t))

    def dJ(t):
        return 2 * a * np.sin(2 * t)

    def M(t):
        return 120.0 * np.sin(t) + 60.0 * np.cos(3 * t) - 20.0 * np.sin(2 * t)

    def dT(t):
        return 120.0 * (1 - np.cos(t)) + 20.0 * np.sin(3 * t) + 10.0 * (np.cos(2 * t) - 1)

    return w_m, delta, J, dJ, M, dT


def test_exact_flywheel_reproduced_by_solve_ivp():
    """Integrate J ω dω/dθ + ½J′ω² = M with solve_ivp; its δ and mean speed match to 1e-6."""
    w_m, delta, J, dJ, M, dT = _case()
    theta = np.linspace(0.0, 2 * math.pi, 40001)
    J_f, E0 = exact_flywheel(theta, J(theta), dT(theta), w_m, delta, 1.0)
    w0 = math.sqrt(2 * E0 / (J(0.0) + J_f))

    def rhs(t, y):
        Jt = J(t) + J_f
        return [(M(t) - 0.5 * dJ(t) * y[0] ** 2) / (Jt * y[0])]

    sol = solve_ivp(rhs, (0.0, 2 * math.pi), [w0], method="DOP853", rtol=1e-12, atol=1e-12,
                    dense_output=True)
    grid = np.linspace(0.0, 2 * math.pi, 2001)
    om = sol.sol(grid)[0]
    assert om[-1] == pytest.approx(om[0], rel=1e-9)           # periodic
    i, j = int(np.argmax(om)), int(np.argmin(om))
    h = grid[1] - grid[0]
    wmax = -minimize_scalar(lambda t: -sol.sol(t)[0], bounds=(grid[i] - h, grid[i] + h),
                            method="bounded", options={"xatol": 1e-12}).fun
    wmin = minimize_scalar(lambda t: sol.sol(t)[0], bounds=(grid[j] - h, grid[j] + h),
                           method="bounded", options={"xatol": 1e-12}).fun
    assert (wmax - wmin) / w_m == pytest.approx(delta, rel=1e-6)
    assert 0.5 * (wmax + wmin) == pytest.approx(w_m, rel=1e-8)


def test_approximate_methods_are_close_but_not_exact_with_variable_inertia():
    w_m, delta, J, _, _, dT = _case()
    theta = np.linspace(0.0, 2 * math.pi, 20001)
    Jt, dTt = J(theta), dT(theta)
    J_f, _ = exact_flywheel(theta, Jt, dTt, w_m, delta, 1.0)
    wit = wittenbauer(Jt, dTt, w_m, delta).J_flywheel
    mer = merkalov(Jt - 0.5, dTt, w_m, delta, 0.5).J_flywheel
    for approx in (wit, mer):
        assert approx == pytest.approx(J_f, rel=0.05) and approx != pytest.approx(J_f, rel=1e-9)
    # more inertia, less fluctuation
    assert delta_of(theta, Jt + 2 * J_f, dTt, w_m)[0] < delta


def test_flywheel_sizes_give_back_their_inertia():
    J = 3.5
    disc = flywheel_size(J, FlywheelSpec(FlywheelShape.DISC, 7800.0, width_ratio=0.2))
    assert disc.width / disc.diameter == pytest.approx(0.2)
    # J of a disc = m·D²/8
    assert disc.mass * disc.diameter ** 2 / 8 == pytest.approx(J, rel=1e-12)
    disc2 = flywheel_size(J, FlywheelSpec(FlywheelShape.DISC, 7800.0, diameter=0.5))
    assert disc2.mass * 0.5 ** 2 / 8 == pytest.approx(J, rel=1e-12)
    rim = flywheel_size(J, FlywheelSpec(FlywheelShape.RIM, 7200.0, diameter=0.8, section_ratio=1.5))
    assert rim.mass * (0.8 / 2) ** 2 == pytest.approx(J, rel=1e-12)
    assert rim.height == pytest.approx(1.5 * rim.width)
    assert rim.mass == pytest.approx(7200.0 * math.pi * 0.8 * rim.width * rim.height)
