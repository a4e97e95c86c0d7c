"""The engine torque's largest and smallest values found exactly between the grid points.

On the dense grid ΣM(φ) has local extrema at some grid points; the true extremum lies between the
neighbours of one of them. There dΣM/dφ (a central difference of the exact ΣM, h = 1e-6 rad) changes
sign, and Brent's method finds the angle where it does: a smooth extremum, or a corner of the
indicator diagram (a table's node), where the derivative jumps through zero.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from .analysis import EngineResult
from .model import EngineModel

Array = np.ndarray
H = 1e-6             # rad, step of the central difference
CANDIDATES = 3       # local extrema of the grid refined for each of max and min


@dataclass(frozen=True)
class TorqueExtremes:
    """ΣM_max at φ_max and ΣM_min at φ_min (N·m, rad within the cycle)."""

    M_max: float
    phi_max: float
    M_min: float
    phi_min: float

    def non_uniformity(self, mean: float) -> float:
        """(M_max − M_min)/M_mean."""
        return (self.M_max - self.M_min) / mean


def total_torque(model: EngineModel, phi: Array) -> Array:
    """ΣM of every cylinder at engine crank angles φ (exact kinematics)."""
    phi = np.asarray(phi, float)
    return np.sum([model.cylinder(c.number, phi).M for c in model.spec.cylinders], axis=0)


def _refine(model: EngineModel, a: float, b: float, sign: float) -> tuple[float, float]:
    """Extremum of sign·ΣM on [a, b] (sign +1: maximum): the angle and ΣM there."""
    def f(x: float) -> float:
        return sign * float(total_torque(model, np.array([x]))[0])

    def slope(x: float) -> float:
        m = total_torque(model, np.array([x - H, x + H]))
        return sign * float(m[1] - m[0]) / (2.0 * H)

    if slope(a) > 0.0 > slope(b):
        x = float(brentq(slope, a, b, xtol=1e-13))
    else:                                       # no sign change: bounded Brent on ΣM itself
        x = float(minimize_scalar(lambda t: -f(t), bounds=(a, b), method="bounded",
                                  options={"xatol": 1e-11}).x)
    best = max((x, a, b), key=f)
    return best, f(best) * sign


def torque_extremes(model: EngineModel, dense: EngineResult) -> TorqueExtremes:
    """Largest and smallest ΣM over the cycle, refined between the points of the dense grid."""
    cycle = model.spec.cycle
    phi, M = dense.phi[:-1], dense.M_total[:-1]
    step = cycle / M.shape[0]
    out = []
    for sign in (1.0, -1.0):
        m = sign * M
        local = np.flatnonzero((m >= np.roll(m, 1)) & (m >= np.roll(m, -1)))
        top = local[np.argsort(m[local])[::-1][:CANDIDATES]]
        found = [_refine(model, float(phi[k]) - step, float(phi[k]) + step, sign) for k in top]
        x, value = max(found, key=lambda r: sign * r[1])
        out += [value, math.fmod(x + cycle, cycle)]
    return TorqueExtremes(*out)
