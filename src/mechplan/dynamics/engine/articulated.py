"""The master/articulated pair solved by mechplan's exact construction (positions, velocities,
accelerations of the pistons C and E and of the lug D).

The linkage scene comes from :func:`mechplan.scene.engine.articulated_linkage`: the master cylinder
along +x, the articulated one at the bank angle, the crank turning counter-clockwise from +x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ...construct.builder import build_construction
from ...construct.graph import Construction
from ...model.structure import analyse
from ...scene.spec import Scene

Array = np.ndarray


@dataclass(frozen=True)
class PairState:
    """Positions, velocities and accelerations (N, 2) of the pair's points at crank angles φ."""

    phi: Array
    B: Array
    C: Array
    D: Array
    E: Array
    v_C: Array
    v_E: Array
    a_C: Array
    a_E: Array


class ArticulatedPair:
    """The exact kinematics of a master and an articulated rod on one crank pin."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.construction: Construction = build_construction(
            scene.mechanism, analyse(scene.mechanism), ("position", "velocity", "acceleration"),
            scene.assembly_phi, scene.path, None)
        guides = scene.mechanism.guides
        self.u_C = np.array([math.cos(guides["Ax"].angle), math.sin(guides["Ax"].angle)])
        self.u_E = np.array([math.cos(guides["Ay"].angle), math.sin(guides["Ay"].angle)])
        s, _ = self._travel_E(np.linspace(0.0, 2.0 * math.pi, 721)[:-1])
        self.phi_tdc_E = self._dead_centre(s, int(np.argmax(s)))
        self.phi_bdc_E = self._dead_centre(s, int(np.argmin(s)))
        s_ext, _ = self._travel_E(np.array([self.phi_tdc_E, self.phi_bdc_E]))
        self.s_tdc_E, self.s_bdc_E = float(s_ext[0]), float(s_ext[1])

    @property
    def stroke_E(self) -> float:
        """Stroke of the articulated piston (m)."""
        return self.s_tdc_E - self.s_bdc_E

    def state(self, phi: Array) -> PairState:
        """Evaluate the pair at crank angles φ (rad from the master cylinder's axis)."""
        c = self.construction
        ev = c.evaluate(np.mod(np.asarray(phi, float), 2.0 * math.pi))
        return PairState(np.asarray(phi, float), ev[c.position("B")], ev[c.position("C")],
                         ev[c.position("D")], ev[c.position("E")], ev[c.velocity_image("C")],
                         ev[c.velocity_image("E")], ev[c.acceleration_image("C")],
                         ev[c.acceleration_image("E")])

    def _travel_E(self, phi: Array) -> tuple[Array, Array]:
        c = self.construction
        ev = c.evaluate(phi)
        return ev[c.position("E")] @ self.u_E, ev[c.velocity_image("E")] @ self.u_E

    def _dead_centre(self, s: Array, i: int) -> float:
        n = s.shape[0]
        lo, hi = (i - 1) * 2.0 * math.pi / n, (i + 1) * 2.0 * math.pi / n

        def v(f: float) -> float:
            return float(self._travel_E(np.array([f]))[1][0])

        return float(brentq(v, lo, hi, xtol=1e-14)) % (2.0 * math.pi)

    def phi_of_travel_E(self, x: float, lo: float, hi: float) -> float:
        """Crank angle in [lo, hi] where E has travelled x from its TDC (one stroke, monotone)."""
        def f(p: float) -> float:
            return self.s_tdc_E - float(self._travel_E(np.array([p]))[0][0]) - x
        return float(brentq(f, lo, hi, xtol=1e-14))
