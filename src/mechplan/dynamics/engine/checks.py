"""Consistency checks of an engine's dynamics, computed by quadrature independent of the grid.

∫ΣM dφ over the cycle must equal the indicated work (p–V area per cylinder, scaled by each
cylinder's stroke); the inertia torque must average to zero; Brix's transfer and the λ-series are
compared with the exact kinematics; a rod whose J_S is given gets its two-mass error.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ..indicator import gauss
from .model import EngineModel

Array = np.ndarray


@dataclass(frozen=True)
class Checks:
    """Results of the checks (SI units)."""

    work_diagram: float            # ∮p dV of one cylinder of stroke 2R, J
    work_expected: float           # Σ over cylinders (stroke-scaled), J
    work_torque: float             # ∫ΣM dφ over the cycle, J
    inertia_mean: float            # mean torque of the inertia forces, N·m
    inertia_peak: float            # max |torque of the inertia forces| of one cylinder, N·m
    brix_dp_max: float             # max |p_Brix − p| over the cycle, Pa
    p_max: float
    da_max: float                  # max |a − a_series| of cylinder 1, m/s²
    a_max: float
    dPj_max: float                 # max |Pj − Pj_series|, N
    two_mass_dM_max: float | None  # max torque error of the two-mass rod, N·m (J_S given)
    pair_torque_error: float | None  # articulated pair: max |R·T_pin − ΣM| / max|ΣM|

    @property
    def work_error(self) -> float:
        """Relative difference of the two works."""
        return abs(self.work_torque - self.work_expected) / abs(self.work_expected)


def _pieces(model: EngineModel, number: int) -> list[tuple[float, float]]:
    """Intervals of a cylinder's own cycle angle on which its torque is smooth."""
    spec, dia = model.spec, model.diagram
    out = []
    if model.pair is not None and number == 2:
        pair = model.pair
        d = model.phases[2]
        e_T = math.remainder(pair.phi_tdc_E - d, 2.0 * math.pi)
        e_B = math.remainder(pair.phi_bdc_E - d - math.pi, 2.0 * math.pi)
        bounds = [k * math.pi + (e_B if k % 2 else e_T) for k in range(spec.strokes)]
        bounds.append(bounds[0] + spec.cycle)
        for k in range(spec.strokes):
            lo, hi = bounds[k], bounds[k + 1]
            cuts = [lo, hi]
            for xi in dia.knots_xi(k)[1:-1]:
                cuts.append(pair.phi_of_travel_E(float(xi) * pair.stroke_E, lo + d, hi + d) - d)
            c = sorted(cuts)
            out += list(itertools.pairwise(c))
        return out
    for k in range(spec.strokes):
        lo, hi = k * math.pi, (k + 1) * math.pi
        xs = dia.knots_xi(k)[1:-1] * 2.0 * spec.R
        knots = model.kin.phi_of_x(xs, k % 2 == 1) + 2.0 * math.pi * (k // 2)
        c = sorted([lo, hi, *knots.tolist()])
        out += list(itertools.pairwise(c))
    return out


def _integral(model: EngineModel, number: int, attr: str) -> float:
    shift = model.phases[number]

    def f(psi: Array) -> Array:
        return np.asarray(getattr(model.cylinder(number, psi + shift), attr))

    return sum(gauss(f, a, b) for a, b in _pieces(model, number) if b > a)


def consistency_checks(model: EngineModel, dense: Array) -> Checks:
    """Run the checks (``dense``: the grid of engine crank angles for the maxima)."""
    spec = model.spec
    W = model.diagram.work()
    expected, torque, inertia = 0.0, 0.0, 0.0
    for c in spec.cylinders:
        scale = model.pair.stroke_E / (2.0 * spec.R) if (model.pair is not None and c.number == 2) \
            else 1.0
        expected += W * scale
        torque += _integral(model, c.number, "M")
        inertia += _integral(model, c.number, "M_j")
    c1 = model.cylinder(1, dense)
    peak = float(np.max(np.abs(c1.M_j)))
    dM = None
    rod = spec.masses.rod
    if rod.J_S is not None and rod.J_two_mass is not None:
        dM = float(np.max(np.abs(two_mass_torque_error(model, dense))))
    pair_err = None
    if model.pair is not None:
        c2 = model.cylinder(2, dense)
        T, _ = model.pair_pin_force(dense, c1.P, c2.P)
        total = c1.M + c2.M
        pair_err = float(np.max(np.abs(T * spec.R - total)) / np.max(np.abs(total)))
    return Checks(W, expected, torque, inertia / spec.cycle, peak,
                  float(np.max(np.abs(c1.p_brix - c1.p))), float(np.max(c1.p)),
                  float(np.max(np.abs(c1.a - c1.a_series))), float(np.max(np.abs(c1.a))),
                  float(np.max(np.abs(c1.Pj - c1.Pj_series))), dM, pair_err)


def two_mass_torque_error(model: EngineModel, phi: Array) -> Array:
    """Torque the two-mass model leaves out: −ΔJ·ω²·β′·β″ with ΔJ = J_S − (m1·l1² + m2·l2²)."""
    rod, kin = model.spec.masses.rod, model.kin
    assert rod.J_S is not None and rod.J_two_mass is not None
    dJ = rod.J_S - rod.J_two_mass
    psi = model.local(1, phi)
    lam = kin.lam
    b = kin.beta(psi)
    cb = np.cos(b)
    b1 = lam * np.cos(psi) / cb
    b2 = (-lam * np.sin(psi) * cb + lam * np.cos(psi) * np.sin(b) * b1) / cb ** 2
    return -dJ * model.omega ** 2 * b1 * b2
