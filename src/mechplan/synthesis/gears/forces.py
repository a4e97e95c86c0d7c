"""Torques, efficiency and planet forces of a planetary train (Willis with losses per mesh).

External torques M on the three basic links balance, M_a + M_b + M_h = 0. In the motion relative to
the carrier the meshes lose power: with η^h = η(mesh 1)·η(mesh 2),
M_b·(ω_b − ω_h) = −η^h·M_a·(ω_a − ω_h) when gear a drives in that motion (M_a·(ω_a − ω_h) > 0), and
M_a·(ω_a − ω_h) = −η^h·M_b·(ω_b − ω_h) when gear b drives. The load on the output is given as the
magnitude of its resisting torque; the driving torque, the reaction of the fixed link and the
efficiency η = −P_out/P_in follow. Forces on one of k planets: F = M/(k·r_w) at each pitch point and
at the planet's axle (carrier).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from .solve import PlanetaryResult


@dataclass(frozen=True)
class TrainForces:
    """Torques (N·m, counter-clockwise positive along the axis), efficiency and planet forces."""

    torque: dict[str, float]          # external torque on each basic link
    efficiency: float                 # −P_out/P_in
    relative_efficiency: float        # η^h
    driver_in_relative: str           # the central gear that drives with the carrier held
    planet_forces: dict[str, float]   # tangential force on one planet at A, at B, at its axle, N

    def to_json(self) -> dict[str, Any]:
        """SI numbers."""
        return {"torque_N_m": self.torque, "efficiency": self.efficiency,
                "relative_efficiency": self.relative_efficiency,
                "driver_in_relative_motion": self.driver_in_relative,
                "planet_force_N": self.planet_forces}


def solve_torques(links: tuple[str, str, str], omega: dict[str, float], output: str,
                  load: float, eta_h: float) -> tuple[dict[str, float], str]:
    """External torques on a, b, h (``links``) with the resisting ``load`` on ``output``."""
    a, b, h = links
    ra, rb = omega[a] - omega[h], omega[b] - omega[h]
    m_out = -load * math.copysign(1.0, omega[output]) if omega[output] else -load
    idx = {a: 0, b: 1, h: 2}
    for driver in (a, b):
        # row 1: equilibrium; row 2: Willis with losses; row 3: the given load
        if driver == a:
            rel = [eta_h * ra, rb, 0.0]
        else:
            rel = [ra, eta_h * rb, 0.0]
        known = [0.0, 0.0, 0.0]
        known[idx[output]] = 1.0
        m = np.linalg.solve(np.array([[1.0, 1.0, 1.0], rel, known]), np.array([0.0, 0.0, m_out]))
        p_rel = m[idx[driver]] * (ra if driver == a else rb)
        if p_rel >= -1e-15 * max(1.0, abs(load)):
            return {a: float(m[0]), b: float(m[1]), h: float(m[2])}, driver
    raise ArithmeticError("no consistent direction of the power in relative motion")


def train_forces(res: PlanetaryResult) -> TrainForces | None:
    """Torques and forces of the chosen set (None without a plan or without a load)."""
    spec, plan = res.spec, res.plan
    if plan is None or spec.output_torque is None or spec.speeds is not None:
        return None
    eta_h = spec.mesh_efficiency[0] * spec.mesh_efficiency[1]
    links = spec.scheme.links
    torque, driver = solve_torques(links, plan.omega, spec.output, spec.output_torque, eta_h)
    p_in = torque[spec.input] * plan.omega[spec.input]
    p_out = torque[spec.output] * plan.omega[spec.output]
    eff = -p_out / p_in if p_in else math.nan
    a, b, h = links
    k = spec.planets
    forces = {"A": torque[a] / (k * plan.pitch_points["A"]),
              "B": torque[b] / (k * plan.pitch_points["B"]),
              "O": torque[h] / (k * plan.a_w)}
    return TrainForces(torque, eff, eta_h, driver, forces)
