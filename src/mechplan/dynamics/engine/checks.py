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
    art = model.articulated.get(number)
    if art is not None:
        group = model.group
        assert group is not None
        d = model.phases[number] - art.offset            # own cycle angle + d = linkage angle
        e_T, e_B = model.dead_centres(number)
        bounds = [k * math.pi + (e_B if k % 2 else e_T) for k in range(spec.strokes)]
        bounds.append(bounds[0] + spec.cycle)
        stroke = group.slaves[art.slot].stroke
        for k in range(spec.strokes):
            lo, hi = bounds[k], bounds[k + 1]
            cuts = [lo, hi]
            xis = list(dia.knots_xi(k)[1:-1])
            if model.rod_diagram is not None:
                # the crank end's stroke k − 1 at ξ' = 1 − x/S′
                j = (k - 1) % spec.strokes
                xis += [1.0 - xi for xi in model.rod_diagram.knots_xi(j)[1:-1]]
            for xi in xis:
                cuts.append(group.phi_of_travel(art.slot, float(xi) * stroke, lo + d, hi + d) - d)
            out += list(itertools.pairwise(sorted(cuts)))
        return out
    rod = model.rod_diagram
    for k in range(spec.strokes):
        lo, hi = k * math.pi, (k + 1) * math.pi
        xs = dia.knots_xi(k)[1:-1] * 2.0 * spec.R
        knots = model.kin.phi_of_x(xs, k % 2 == 1) + 2.0 * math.pi * (k // 2)
        cuts = [lo, hi, *knots.tolist()]
        if rod is not None:
            # the crank end's stroke j = k − 1 (its cycle starts half a turn later), ξ' = 1 − x/S
            j = (k - 1) % spec.strokes
            xr = (1.0 - rod.knots_xi(j)[1:-1]) * 2.0 * spec.R
            cuts += (model.kin.phi_of_x(xr, k % 2 == 1) + 2.0 * math.pi * (k // 2)).tolist()
        out += list(itertools.pairwise(sorted(cuts)))
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
    W_rod = model.rod_diagram.work() if model.rod_diagram is not None else 0.0
    expected, torque, inertia = 0.0, 0.0, 0.0
    for c in spec.cylinders:
        expected += (W + W_rod) * model.stroke_of(c.number) / (2.0 * spec.R)
        torque += _integral(model, c.number, "M")
        inertia += _integral(model, c.number, "M_j")
    c1 = model.cylinder(1, dense)
    peak = float(np.max(np.abs(c1.M_j)))
    dM = None
    rod = spec.masses.rod
    if rod.J_S is not None and rod.J_two_mass is not None:
        dM = float(np.max(np.abs(two_mass_torque_error(model, dense))))
    pair_err = None
    if model.articulated:
        pair_err = 0.0
        for pin, members in model.pins.items():
            if not any(c in model.articulated for c in members):
                continue
            forces = {c: model.cylinder(c, dense) for c in members}
            T, _ = model.group_pin_force(pin, dense, {c: f.P for c, f in forces.items()})
            total = sum(f.M for f in forces.values())
            pair_err = max(pair_err,
                           float(np.max(np.abs(T * spec.R - total)) / np.max(np.abs(total))))
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
