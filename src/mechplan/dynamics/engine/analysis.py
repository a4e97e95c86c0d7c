"""The engine over its cycle: every cylinder, the summed torque, crank-pin and main-journal loads,
the wear diagram and the consistency checks."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .checks import Checks, consistency_checks
from .cylinder import CylinderForces, rows_of, slider_forces
from .model import EngineModel

Array = np.ndarray
WEAR_RAYS = 24
WEAR_SPREAD = math.radians(60.0)


@dataclass(frozen=True)
class PinLoad:
    """Load of the rods on one crank pin in the crank's frame (T across, Z along, towards the
    axis)."""

    T: Array
    Z: Array
    K_r: float              # −m_r·R·ω² of the rotating masses on the pin (negative: outwards)

    @property
    def Q_T(self) -> Array:
        """Component of Q across the crank (sense of rotation +)."""
        return self.T

    @property
    def Q_Z(self) -> Array:
        """Component of Q along the crank, towards the axis +: Z + K_r."""
        return self.Z + self.K_r

    @property
    def Q(self) -> Array:
        """|Q|."""
        return np.hypot(self.T, self.Z + self.K_r)


@dataclass(frozen=True)
class EngineResult:
    """The engine at crank angles φ (rad, 0 … cycle) with its cylinders, pins and journals."""

    model: EngineModel
    phi: Array
    cylinders: dict[int, CylinderForces]
    M_total: Array
    M_inertia: Array
    pins: dict[int, PinLoad]
    journals: Array                      # (J, N, 2) loads on the main journals, fixed frame

    def pin_of(self, cylinder: int) -> int:
        """The crank pin cylinder ``cylinder``'s rod turns (two cylinders share one in a V)."""
        return next(pin for pin, members in self.model.pins.items() if cylinder in members)

    @property
    def M_mean(self) -> float:
        """Mean engine torque over the cycle (trapezoids on the grid)."""
        f = self.phi
        return float(np.trapezoid(self.M_total, f) / (f[-1] - f[0]))

    @property
    def non_uniformity(self) -> float:
        """(M_max − M_min)/M_mean."""
        return float((self.M_total.max() - self.M_total.min()) / self.M_mean)


def pin_loads(model: EngineModel, phi: Array, cyl: dict[int, CylinderForces]) -> dict[int, PinLoad]:
    """T and Z summed over the cylinders on each pin, and the pin's rotating force."""
    spec = model.spec
    rw2 = spec.R * model.omega ** 2
    out = {}
    for pin, members in model.pins.items():
        K_r = -sum(model.m_rot[c] for c in members) * rw2
        if any(c in model.articulated for c in members):
            T, Z = model.group_pin_force(pin, phi, {c: cyl[c].P for c in members})
        else:
            T = np.sum([cyl[c].T for c in members], axis=0)
            Z = np.sum([cyl[c].Z for c in members], axis=0)
        out[pin] = PinLoad(np.asarray(T), np.asarray(Z), K_r)
    return out


def journal_loads(model: EngineModel, phi: Array, pins: dict[int, PinLoad]) -> Array:
    """Loads on the main journals (fixed frame: x along cylinder 1, y in the sense of rotation).

    Each throw's load (its pin load plus the centrifugal force of the crank's unbalanced mass less
    the counterweights) is shared equally by the journals on either side of it.
    """
    spec = model.spec
    numbers = sorted(pins)
    throw_of = {c.number: c.throw for c in spec.cylinders}
    W = []
    for pin in numbers:
        theta = phi - throw_of[model.pins[pin][0]]
        r = np.stack([np.cos(theta), np.sin(theta)], axis=1)
        t = np.stack([-np.sin(theta), np.cos(theta)], axis=1)
        q = pins[pin]
        outward = (-q.Q_Z + (spec.masses.crank - spec.masses.counterweight)
                   * spec.R * model.omega ** 2)
        W.append(q.Q_T[:, None] * t + outward[:, None] * r)
    zero = np.zeros_like(W[0])
    return np.stack([0.5 * ((W[j - 1] if j > 0 else zero) + (W[j] if j < len(W) else zero))
                     for j in range(len(W) + 1)])


def wear(load: PinLoad, step: int = 1) -> tuple[Array, Array]:
    """Wear diagram of a crank pin: ray angles and the summed loads on them.

    Rays at 360°/24 in the crank's frame, from the crank's outward direction in the sense of
    rotation. Each load Q presses the pin at the point opposite its direction; its magnitude is
    spread over ±60° from that point (the courses' assumption).
    """
    rays = np.arange(WEAR_RAYS) * 2.0 * math.pi / WEAR_RAYS
    qt, qz = load.Q_T[::step], load.Q_Z[::step]
    mag = np.hypot(qt, qz)
    # Q in (outward, across) components is (−Q_Z, Q_T); the pressed point is opposite: (Q_Z, −Q_T)
    contact = np.arctan2(-qt, qz)
    d = np.abs(np.angle(np.exp(1j * (rays[:, None] - contact[None, :]))))
    return rays, np.sum(np.where(d <= WEAR_SPREAD + 1e-12, mag[None, :], 0.0), axis=1)


def analyse(model: EngineModel, phi: Array) -> EngineResult:
    """All quantities at engine crank angles φ."""
    phi = np.asarray(phi, float)
    spec = model.spec
    plain = [c.number for c in spec.cylinders if c.number not in model.articulated]
    psi = np.stack([model.local(n, phi) for n in plain])
    m_j = np.array([model.m_j[n] for n in plain])[:, None]
    together = slider_forces(model.kin, model.omega, model.diagram, psi, spec.F_p, spec.p0, m_j,
                             model.rod_diagram, spec.F_rod_side)
    cyl = {n: rows_of(together, i) for i, n in enumerate(plain)}
    M = together.M.sum(axis=0)
    Mj = together.M_j.sum(axis=0)
    for n in model.articulated:
        cyl[n] = model.cylinder(n, phi)
        M = M + cyl[n].M
        Mj = Mj + cyl[n].M_j
    cyl = {c.number: cyl[c.number] for c in spec.cylinders}
    pins = pin_loads(model, phi, cyl)
    return EngineResult(model, phi, cyl, M, Mj, pins, journal_loads(model, phi, pins))


def grids(model: EngineModel) -> tuple[Array, Array]:
    """The dense grid and the table's angles over one cycle (both with the end point)."""
    spec = model.spec
    dense = np.linspace(0.0, spec.cycle, spec.grid + 1)
    n = round(spec.cycle / spec.table_step)
    return dense, np.linspace(0.0, spec.cycle, n + 1)


__all__ = ["Checks", "EngineResult", "PinLoad", "analyse", "consistency_checks", "grids", "wear"]
