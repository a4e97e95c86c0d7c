"""Works, kinetic-energy increment and the flywheel for a coefficient of speed fluctuation δ.

All functions take arrays over one steady cycle on a uniform grid θ_0 = 0 … θ_N = Φ (the last point
closes the cycle, values there equal those at 0 for periodic data). Three ways to the flywheel:
Wittenbauer's energy–mass diagram, Merkalov's method (both approximate: they use ω_m where the exact
equation has ω(φ)) and the exact one from ½J(φ)ω² = E0 + ΔT(φ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..geom.vec import Array
from ..model.dynamics import FlywheelShape, FlywheelSpec


def cumulative_work(theta: Array, moment: Array) -> Array:
    """Return A(θ) = ∫₀^θ M dθ by trapezoids over the given points (J)."""
    out = np.zeros_like(np.asarray(moment, dtype=float))
    out[1:] = np.cumsum(0.5 * (moment[1:] + moment[:-1]) * np.diff(theta))
    return out


@dataclass(frozen=True)
class Wittenbauer:
    """Tangents to the ΔT–J_red curve at slopes k = ω_m²(1 ± δ)/2 (J per kg·m²).

    The upper tangent is ΔT = b_max + k_max·J, the lower ΔT = b_min + k_min·J; the intercept on
    the ΔT axis is kl = b_max − b_min and the flywheel is kl/(δ·ω_m²).
    """

    J_flywheel: float
    k_max: float
    k_min: float
    b_max: float
    b_min: float
    at_max: int          # index of the point the upper tangent touches
    at_min: int


def wittenbauer(J_red: Array, dT: Array, omega_m: float, delta: float) -> Wittenbauer:
    """Return the flywheel by Wittenbauer's energy–mass diagram (ΔT against J_red)."""
    k_max = 0.5 * omega_m ** 2 * (1 + delta)
    k_min = 0.5 * omega_m ** 2 * (1 - delta)
    upper = dT - k_max * J_red
    lower = dT - k_min * J_red
    i, j = int(np.argmax(upper)), int(np.argmin(lower))
    kl = float(upper[i] - lower[j])
    return Wittenbauer(kl / (delta * omega_m ** 2), k_max, k_min, float(upper[i]),
                       float(lower[j]), i, j)


@dataclass(frozen=True)
class Merkalov:
    """ΔT_I = ΔT − J_var·ω_m²/2 and the constant inertia J_I it needs;
    flywheel = J_I − J_present; the law of motion ω ≈ ω_min + (ΔT_I − ΔT_I,min)/(J_I·ω_m)."""

    dT_I: Array
    J_I: float
    J_flywheel: float
    omega: Array


def merkalov(J_var: Array, dT: Array, omega_m: float, delta: float, J_present: float) -> Merkalov:
    """Return the flywheel and the (approximate) law of motion by Merkalov's method."""
    dT_I = dT - 0.5 * J_var * omega_m ** 2
    J_I = float(dT_I.max() - dT_I.min()) / (delta * omega_m ** 2)
    omega = omega_m * (1.0 - 0.5 * delta) + (dT_I - dT_I.min()) / (J_I * omega_m)
    return Merkalov(dT_I, J_I, J_I - J_present, omega)


def speed(J: Array, dT: Array, E0: float) -> Array:
    """ω(θ) from ½J(θ)ω² = E0 + ΔT(θ) (rad/s)."""
    return np.sqrt(2.0 * np.maximum(E0 + dT, 0.0) / J)


@dataclass(frozen=True)
class Extremes:
    """ω_max and ω_min over the cycle and the cycle angles (rad) where they occur."""

    omega_max: float
    theta_max: float
    omega_min: float
    theta_min: float


def extremes(theta: Array, omega: Array) -> Extremes:
    """Extremes of a periodic sampled ω(θ), refined by the parabola through three points."""
    y = omega[:-1]                     # the last point repeats the first
    h = float(theta[1] - theta[0])
    n = y.shape[0]

    def refine(i: int) -> tuple[float, float]:
        a, b, c = y[(i - 1) % n], y[i], y[(i + 1) % n]
        den = a - 2 * b + c
        if den == 0.0:
            return float(b), float(theta[i])
        off = 0.5 * (a - c) / den
        return float(b - 0.25 * (a - c) * off), float(theta[i] + off * h)

    (wmax, tmax), (wmin, tmin) = refine(int(np.argmax(y))), refine(int(np.argmin(y)))
    return Extremes(wmax, tmax, wmin, tmin)


def energy_for_mean(theta: Array, J: Array, dT: Array, omega_m: float) -> float:
    """E0 such that (ω_max + ω_min)/2 = ω_m for the inertia J(θ) (J)."""
    lo = -float(dT.min())

    def gap(E0: float) -> float:
        e = extremes(theta, speed(J, dT, E0))
        return 0.5 * (e.omega_max + e.omega_min) - omega_m

    if gap(lo) >= 0:        # too little inertia: the crank nearly stops; no E0 gives this mean
        return lo
    hi = max(lo, 0.0) + 0.5 * float(J.max()) * omega_m ** 2 * 4.0 + 1.0
    while gap(hi) < 0:
        hi *= 4.0
    return float(brentq(gap, lo, hi, xtol=1e-300, rtol=1e-15, maxiter=500))


def delta_of(theta: Array, J: Array, dT: Array, omega_m: float) -> tuple[float, float]:
    """(δ, E0): the fluctuation the inertia J(θ) gives at the mean speed ω_m, exactly."""
    E0 = energy_for_mean(theta, J, dT, omega_m)
    e = extremes(theta, speed(J, dT, E0))
    return (e.omega_max - e.omega_min) / omega_m, E0


def exact_flywheel(theta: Array, J_red: Array, dT: Array, omega_m: float, delta: float,
                   guess: float) -> tuple[float, float]:
    """(J_flywheel, E0) for which the exact motion has δ at the mean speed ω_m.

    ``guess``: an estimate of the flywheel (Merkalov's) to bracket the root.
    """
    lo = -0.5 * float(J_red.min())

    def gap(J_f: float) -> float:
        return delta_of(theta, J_red + J_f, dT, omega_m)[0] - delta

    if gap(lo) <= 0:
        return lo, delta_of(theta, J_red + lo, dT, omega_m)[1]
    hi = max(abs(guess), float(J_red.max()), 1e-9) * 2.0
    while gap(hi) > 0:
        hi *= 2.0
    J_f = float(brentq(gap, lo, hi, xtol=1e-300, rtol=1e-14, maxiter=500))
    return J_f, delta_of(theta, J_red + J_f, dT, omega_m)[1]


@dataclass(frozen=True)
class FlywheelSize:
    """Dimensions of a flywheel: diameter D (outer for a disc, mean for a rim), width b, rim
    height h (0 for a disc), mass (kg)."""

    shape: FlywheelShape
    diameter: float
    width: float
    height: float
    mass: float


def flywheel_size(J: float, spec: FlywheelSpec) -> FlywheelSize:
    """Size a disc (J = ρπbD⁴/32) or a thin rim (J = ρπD³bh/4, h = section_ratio·b)."""
    rho = spec.density
    if spec.shape is FlywheelShape.DISC:
        if spec.diameter is not None:
            D = spec.diameter
            b = 32.0 * J / (rho * math.pi * D ** 4)
        else:
            psi = float(spec.width_ratio or 0.0)
            D = (32.0 * J / (rho * math.pi * psi)) ** 0.2
            b = psi * D
        return FlywheelSize(spec.shape, D, b, 0.0, rho * math.pi * D ** 2 * b / 4.0)
    r = spec.section_ratio
    if spec.diameter is not None:
        D = spec.diameter
        b = math.sqrt(4.0 * J / (rho * math.pi * r * D ** 3))
    else:
        psi = float(spec.width_ratio or 0.0)
        D = (4.0 * J / (rho * math.pi * r * psi ** 2)) ** 0.2
        b = psi * D
    return FlywheelSize(spec.shape, D, b, r * b, rho * math.pi * D * b * r * b)
