"""Forces of one cylinder along its axis and on the crank pin (Kolchin–Demidov conventions).

P is positive towards the crankshaft axis; T is positive when its moment acts in the sense of
rotation; Z is positive towards the crankshaft axis; N = P tan β is the side thrust with β the rod's
angle (sin β = λ sin φ), positive on the side the crank pin moves to from TDC.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..indicator import IndicatorDiagram
from .kinematics import SliderCrank

Array = np.ndarray


@dataclass(frozen=True)
class CylinderForces:
    """Per-angle quantities of one cylinder (arrays of one shape, SI units)."""

    phi: Array              # local cycle angle from the cylinder's cycle start
    x: Array                # exact travel from TDC
    v: Array
    a: Array                # exact
    a_series: Array         # λ-series
    beta: Array
    p: Array                # exact p(φ)
    p_brix: Array           # p(φ) transferred by Brix's construction
    Pk: Array
    Pj: Array               # −m_j·a (exact)
    Pj_series: Array        # −m_j·a (λ-series)
    P: Array
    N: Array
    S: Array
    T: Array
    Z: Array
    M: Array                # T·R
    M_j: Array              # torque of the inertia force alone

    def json_row(self, k: int) -> dict[str, float]:
        """One angle's values."""
        return {name: float(getattr(self, name)[k]) for name in
                ("x", "v", "a", "a_series", "beta", "p", "p_brix", "Pk", "Pj", "Pj_series", "P",
                 "N", "S", "T", "Z", "M")}


def slider_forces(kin: SliderCrank, omega: float, diagram: IndicatorDiagram, phi: Array,
                  F_p: float, p0: float, m_j: float) -> CylinderForces:
    """Everything along one cylinder of a central slider-crank at local cycle angles ``phi``."""
    phi = np.asarray(phi, float)
    S = 2.0 * kin.R
    x = kin.x(phi)
    beta = kin.beta(phi)
    cb = np.cos(beta)
    a = kin.a(phi, omega)
    a_s = kin.a_series(phi, omega)
    p = diagram.at_phi(phi, x / S)
    p_brix = diagram.at_phi(phi, kin.x_brix(phi) / S)
    Pk = (p - p0) * F_p
    Pj = -m_j * a
    P = Pk + Pj
    arm = np.sin(phi + beta) / cb
    T = P * arm
    return CylinderForces(phi, x, kin.v(phi, omega), a, a_s, beta, p, p_brix, Pk, Pj, -m_j * a_s, P,
                          P * np.tan(beta), P / cb, T, P * np.cos(phi + beta) / cb, T * kin.R,
                          Pj * arm * kin.R)
