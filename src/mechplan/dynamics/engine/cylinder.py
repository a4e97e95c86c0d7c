"""Forces of one cylinder along its axis and on the crank pin (Kolchin–Demidov conventions).

P is positive towards the crankshaft axis; T is positive when its moment acts in the sense of
rotation; Z is positive towards the crankshaft axis; N = P tan β is the side thrust with β the rod's
angle (sin β = λ sin φ), positive on the side the crank pin moves to from TDC.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any

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
    p_rod: Array | None = None   # crank-end pressure of a double-acting cylinder

    def json_row(self, k: int) -> dict[str, float]:
        """One angle's values."""
        out = {name: float(getattr(self, name)[k]) for name in
               ("x", "v", "a", "a_series", "beta", "p", "p_brix", "Pk", "Pj", "Pj_series", "P",
                "N", "S", "T", "Z", "M")}
        if self.p_rod is not None:
            out["p_rod"] = float(self.p_rod[k])
        return out


def slider_forces(kin: SliderCrank, omega: float, diagram: IndicatorDiagram, phi: Array,
                  F_p: float, p0: float, m_j: float | Array,
                  rod_diagram: IndicatorDiagram | None = None,
                  F_rod: float = 0.0) -> CylinderForces:
    """Everything along one cylinder of a central slider-crank at local cycle angles ``phi``.

    ``phi`` may be 2-D (cylinders × angles) with ``m_j`` of shape (cylinders, 1): one pass for all.
    A double-acting cylinder (``rod_diagram``) has gas on the crank-end face too: its own cycle
    starts half a turn later (its TDC is the head end's BDC), its stroke fraction is 1 − x/S and
    it pushes the piston away from the crankshaft on the area ``F_rod``.
    """
    phi = np.asarray(phi, float)
    R, lam = kin.R, kin.lam
    S = 2.0 * R
    sf, cf = np.sin(phi), np.cos(phi)
    s = lam * sf                                  # sin β
    cb = np.sqrt(1.0 - s * s)                     # cos β
    beta = np.arcsin(s)
    spb = sf * cb + cf * s                        # sin(φ + β)
    cpb = cf * cb - sf * s                        # cos(φ + β)
    x = R * (1.0 - cf) + kin.L * (1.0 - cb)
    rw2 = R * omega * omega
    a = rw2 * (cpb / cb + lam * cf * cf / (cb * cb * cb))
    a_s = rw2 * (cf + lam * (2.0 * cf * cf - 1.0))
    x_brix = R * (1.0 - cf * np.sqrt(1.0 - s * s / 4.0) + lam / 2.0 * sf * sf)
    stroke = diagram.stroke_of(phi)
    p = diagram.pressure_xi(x / S, stroke)
    p_brix = diagram.pressure_xi(x_brix / S, stroke)
    Pk = (p - p0) * F_p
    p_rod = None
    if rod_diagram is not None:
        p_rod = rod_diagram.pressure_xi(1.0 - x / S, rod_diagram.stroke_of(phi - np.pi))
        Pk = Pk - (p_rod - p0) * F_rod
    Pj = -m_j * a
    P = Pk + Pj
    arm = spb / cb
    T = P * arm
    return CylinderForces(phi, x, omega * R * arm, a, a_s, beta, p, p_brix, Pk, Pj, -m_j * a_s, P,
                          P * s / cb, P / cb, T, P * cpb / cb, T * R, Pj * arm * R, p_rod)


def rows_of(forces: CylinderForces, i: int) -> CylinderForces:
    """Row i of forces computed for several cylinders at once."""
    values: list[Any] = [None if getattr(forces, f.name) is None else getattr(forces, f.name)[i]
                         for f in fields(forces)]
    return CylinderForces(*values)
