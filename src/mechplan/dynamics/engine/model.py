"""An engine prepared for evaluation: kinematics, indicator diagram, reduced masses, phases."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...model.engine import EngineSpec, IndicatorKind, Layout, firing_phases
from ...scene.spec import Scene
from ..indicator import IndicatorDiagram, angle_table_diagram, thermal_diagram, volume_table_diagram
from .articulated import ArticulatedPair
from .cylinder import CylinderForces, slider_forces
from .kinematics import SliderCrank

Array = np.ndarray


def diagram_of(spec: EngineSpec, file: str) -> IndicatorDiagram:
    """The indicator diagram the scene describes."""
    kin = SliderCrank(spec.R, spec.L)
    ind = spec.indicator
    if ind.kind is IndicatorKind.THERMAL:
        assert ind.thermal is not None
        return thermal_diagram(ind.thermal, spec.strokes, kin, spec.F_p)
    if ind.kind is IndicatorKind.VOLUME:
        return volume_table_diagram(ind.rows, spec.strokes, spec.V_h, file, "indicator.table")
    assert ind.epsilon is not None
    return angle_table_diagram(ind.rows, spec.strokes, kin, spec.F_p, ind.epsilon, file,
                               "indicator.table")


@dataclass
class EngineModel:
    """Everything that does not depend on the crank angle."""

    spec: EngineSpec
    kin: SliderCrank
    diagram: IndicatorDiagram
    phases: dict[int, float]
    m_j: dict[int, float]                 # reciprocating mass per cylinder
    m_rot: dict[int, float]               # mass rotating with the pin (rod's big end + extra)
    pins: dict[int, tuple[int, ...]]      # pin number → cylinders on it
    pair: ArticulatedPair | None = None
    lug_share_C: float = 0.0              # share of the articulated rod's big end moved to C
    extras: dict[str, float] = field(default_factory=dict)

    @classmethod
    def build(cls, spec: EngineSpec, file: str, linkage: Scene | None = None) -> EngineModel:
        """Prepare an engine (and its articulated pair's exact linkage, if any)."""
        kin = SliderCrank(spec.R, spec.L)
        diagram = diagram_of(spec, file)
        phases = firing_phases(spec.cylinders, spec.firing_order, spec.strokes)
        ms = spec.masses
        m_j = {c.number: ms.piston + ms.rod.m1 for c in spec.cylinders}
        m_rot = {c.number: ms.rod.m2 + ms.rotating_extra for c in spec.cylinders}
        pair, share = None, 0.0
        if spec.layout is Layout.ARTICULATED:
            art = spec.articulated
            assert art is not None and linkage is not None
            pair = ArticulatedPair(linkage)
            share = art.lug_radius * math.cos(art.lug_angle) / spec.L
            m2a = art.rod.m2
            m_j[1] += m2a * share
            m_rot[1] += m2a * (1.0 - share)
            m_j[2] = art.piston + art.rod.m1
            m_rot[2] = 0.0
            pins: dict[int, tuple[int, ...]] = {1: (1, 2)}
        elif spec.layout is Layout.V:
            n = len(spec.cylinders)
            pins = {k + 1: tuple(c for c in (2 * k + 1, 2 * k + 2) if c <= n)
                    for k in range((n + 1) // 2)}
        else:
            pins = {c.number: (c.number,) for c in spec.cylinders}
        return cls(spec, kin, diagram, phases, m_j, m_rot, pins, pair, share)

    @property
    def omega(self) -> float:
        """Crank speed ω (rad/s)."""
        return self.spec.speed

    def local(self, number: int, phi: Array) -> Array:
        """Cylinder's own cycle angle at engine crank angles φ."""
        return np.mod(np.asarray(phi, float) - self.phases[number], self.spec.cycle)

    def cylinder(self, number: int, phi: Array) -> CylinderForces:
        """Forces of one cylinder at engine crank angles φ."""
        spec = self.spec
        psi = self.local(number, phi)
        if self.pair is not None and number == 2:
            return self._articulated(psi, np.asarray(phi, float))
        return slider_forces(self.kin, self.omega, self.diagram, psi, spec.F_p, spec.p0,
                             self.m_j[number])

    def stroke_E(self, psi: Array) -> Array:
        """Stroke index of the articulated cylinder at its own cycle angle ψ (exact dead
        centres)."""
        pair = self.pair
        assert pair is not None
        d = self.phases[2]
        e_T = math.remainder(pair.phi_tdc_E - d, 2.0 * math.pi)
        e_B = math.remainder(pair.phi_bdc_E - d - math.pi, 2.0 * math.pi)
        shifted = np.mod(psi - e_T, self.spec.cycle)
        bounds = np.array([k * math.pi + (e_B - e_T if k % 2 else 0.0)
                           for k in range(1, self.spec.strokes)])
        return np.searchsorted(bounds, shifted, side="right")

    def _articulated(self, psi: Array, phi: Array) -> CylinderForces:
        pair = self.pair
        assert pair is not None
        spec, w = self.spec, self.omega
        st = pair.state(phi)
        u = pair.u_E
        s = st.E @ u
        x = pair.s_tdc_E - s
        v = -(st.v_E @ u)
        a = -(st.a_E @ u)
        e = st.E - st.D
        e /= np.hypot(e[:, 0], e[:, 1])[:, None]
        n = np.array([-u[1], u[0]])
        beta = np.arctan2(e @ n, e @ u)
        p = self.diagram.pressure_xi(x / pair.stroke_E, self.stroke_E(psi))
        p_brix = self.diagram.at_phi(psi, self.kin.x_brix(psi) / (2.0 * spec.R))
        m = self.m_j[2]
        Pk = (p - spec.p0) * spec.F_p
        Pj = -m * a
        P = Pk + Pj
        M = P * v / w
        nan = np.full_like(P, np.nan)
        return CylinderForces(psi, x, v, a, self.kin.a_series(psi, w), beta, p, p_brix, Pk, Pj,
                              -m * self.kin.a_series(psi, w), P, P * np.tan(beta), P / np.cos(beta),
                              M / spec.R, nan, M, Pj * v / w)

    def pair_pin_force(self, phi: Array, P_C: Array, P_E: Array) -> tuple[Array, Array]:
        """T and Z on the shared crank pin from the statics of the master/articulated group.

        Rods massless (their masses are in P and in the rotating mass); returns T (sense of
        rotation +) and Z (towards the crankshaft axis +), without the rotating force.
        """
        pair = self.pair
        assert pair is not None
        st = pair.state(phi)
        u_C, u_E = pair.u_C, pair.u_E
        e = st.E - st.D
        e /= np.hypot(e[:, 0], e[:, 1])[:, None]
        s = P_E / (e @ u_E)                              # rod DE pushes piston E with s·e
        F_D = -s[:, None] * e                            # articulated rod on the master at D
        n_C = np.array([-u_C[1], u_C[0]])
        F_C_known = -P_C[:, None] * u_C                  # piston C's force on the master at C

        def cross(a: Array, b: Array) -> Array:
            return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]

        BC, BD = st.C - st.B, st.D - st.B
        N_C = -(cross(BC, F_C_known) + cross(BD, F_D)) / cross(BC, np.broadcast_to(n_C, BC.shape))
        F_pin = F_C_known + N_C[:, None] * n_C + F_D     # master rod on the crank pin
        r = st.B / self.spec.R
        t = np.stack([-r[:, 1], r[:, 0]], axis=1)
        return np.sum(F_pin * t, axis=1), -np.sum(F_pin * r, axis=1)
