"""An engine prepared for evaluation: kinematics, indicator diagram, reduced masses, phases."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...model.engine import EngineSpec, IndicatorKind, IndicatorSpec, Layout, firing_phases
from ...scene.spec import Scene
from ..indicator import IndicatorDiagram, angle_table_diagram, thermal_diagram, volume_table_diagram
from .articulated import ArticulatedGroup, GroupState
from .cylinder import CylinderForces, slider_forces
from .kinematics import CrankEnd, SliderCrank

Array = np.ndarray
TURN = 2.0 * math.pi


def diagram_of(spec: EngineSpec, file: str, ind: IndicatorSpec | None = None,
               F: float | None = None, key: str = "indicator.table",
               crank_end: bool = False) -> IndicatorDiagram:
    """The indicator diagram the scene describes (``ind``/``F``/``crank_end``: another face's
    diagram, gas area and kinematics, e.g. the crank end of a double-acting cylinder)."""
    kin: Any = SliderCrank(spec.R, spec.L)
    if crank_end:
        kin = CrankEnd(kin)
    ind = ind or spec.indicator
    F = spec.F_p if F is None else F
    if ind.kind is IndicatorKind.THERMAL:
        assert ind.thermal is not None
        return thermal_diagram(ind.thermal, spec.strokes, kin, F)
    if ind.kind is IndicatorKind.VOLUME:
        return volume_table_diagram(ind.rows, spec.strokes, F * 2.0 * spec.R, file, key)
    return angle_table_diagram(ind.rows, spec.strokes, kin, F, ind.epsilon, file, key)


def rod_side_diagram(spec: EngineSpec, file: str) -> IndicatorDiagram | None:
    """The crank end's diagram of a double-acting cylinder (None: single-acting)."""
    rs = spec.rod_side
    if rs is None:
        return None
    if rs.indicator is None:
        return diagram_of(spec, file, spec.indicator, spec.F_rod_side, crank_end=True)
    return diagram_of(spec, file, rs.indicator, spec.F_rod_side, "rod_side.indicator.table",
                      crank_end=True)


@dataclass(frozen=True)
class ArticulatedCylinder:
    """Where an articulated cylinder sits: its pin, master, slot in the group, the linkage's
    crank angle offset (engine φ − offset = the linkage's angle from the master's axis)."""

    number: int
    master: int
    pin: int
    slot: int
    offset: float
    share_C: float                        # share of its rod's big end moved to the master piston


@dataclass
class EngineModel:
    """Everything that does not depend on the crank angle."""

    spec: EngineSpec
    kin: SliderCrank
    diagram: IndicatorDiagram
    phases: dict[int, float]
    m_j: dict[int, float]                 # reciprocating mass per cylinder
    m_rot: dict[int, float]               # mass rotating with the pin (rod's big end + extra)
    pins: dict[int, tuple[int, ...]]      # pin number → cylinders on it (the master first)
    group: ArticulatedGroup | None = None  # the exact linkage of one throw's rods
    articulated: dict[int, ArticulatedCylinder] = field(default_factory=dict)
    rod_diagram: IndicatorDiagram | None = None   # crank end of a double-acting cylinder
    extras: dict[str, float] = field(default_factory=dict)
    last_state: tuple[bytes, GroupState] | None = field(default=None, repr=False)

    @classmethod
    def build(cls, spec: EngineSpec, file: str, linkage: Scene | None = None) -> EngineModel:
        """Prepare an engine (and the exact linkage of its articulated rods, if any)."""
        kin = SliderCrank(spec.R, spec.L)
        diagram = diagram_of(spec, file)
        phases = firing_phases(spec.cylinders, spec.firing_order, spec.strokes)
        ms = spec.masses
        m_j = {c.number: ms.piston + ms.rod.m1 for c in spec.cylinders}
        m_rot = {c.number: ms.rod.m2 + ms.rotating_extra for c in spec.cylinders}
        group = None
        arts: dict[int, ArticulatedCylinder] = {}
        if spec.layout is Layout.RADIAL:
            pins: dict[int, tuple[int, ...]] = {1: tuple(c.number for c in spec.cylinders)}
        elif spec.layout in (Layout.V, Layout.ARTICULATED):
            n = len(spec.cylinders)
            pins = {k + 1: tuple(c for c in (2 * k + 1, 2 * k + 2) if c <= n)
                    for k in range((n + 1) // 2)}
        else:
            pins = {c.number: (c.number,) for c in spec.cylinders}
        if spec.rods:
            assert linkage is not None
            first = spec.rods[0].master
            group = ArticulatedGroup(linkage, sum(1 for r in spec.rods if r.master == first))
            by_number = {c.number: c for c in spec.cylinders}
            pin_of = {c: p for p, members in pins.items() for c in members}
            slot: dict[int, int] = {}
            for r in spec.rods:
                k = slot.get(r.master, 0)
                slot[r.master] = k + 1
                master = by_number[r.master]
                share = r.spec.lug_radius * math.cos(r.lug) / spec.L
                m2a = r.spec.rod.m2
                m_j[r.master] += m2a * share
                m_rot[r.master] += m2a * (1.0 - share)
                m_j[r.number] = r.spec.piston + r.spec.rod.m1
                m_rot[r.number] = 0.0
                arts[r.number] = ArticulatedCylinder(
                    r.number, r.master, pin_of[r.number], k, (master.throw + master.bank) % TURN,
                    share)
        rod_diagram = rod_side_diagram(spec, file)
        return cls(spec, kin, diagram, phases, m_j, m_rot, pins, group, arts, rod_diagram)

    @property
    def omega(self) -> float:
        """Crank speed ω (rad/s)."""
        return self.spec.speed

    @property
    def pair(self) -> ArticulatedGroup | None:
        """The articulated linkage of one throw (all throws have the same geometry)."""
        return self.group

    def local(self, number: int, phi: Array) -> Array:
        """Cylinder's own cycle angle at engine crank angles φ."""
        return np.mod(np.asarray(phi, float) - self.phases[number], self.spec.cycle)

    def stroke_of(self, number: int) -> float:
        """Stroke of a cylinder's piston (2R, or the articulated piston's exact stroke)."""
        art = self.articulated.get(number)
        if art is None:
            return 2.0 * self.spec.R
        assert self.group is not None
        return self.group.slaves[art.slot].stroke

    def cylinder(self, number: int, phi: Array) -> CylinderForces:
        """Forces of one cylinder at engine crank angles φ."""
        spec = self.spec
        psi = self.local(number, phi)
        if number in self.articulated:
            return self._articulated(number, psi, np.asarray(phi, float))
        return slider_forces(self.kin, self.omega, self.diagram, psi, spec.F_p, spec.p0,
                             self.m_j[number], self.rod_diagram, spec.F_rod_side)

    def dead_centres(self, number: int) -> tuple[float, float]:
        """An articulated cylinder's exact TDC and BDC less a half turn, as offsets (rad, within
        ±π) from its own cycle's nominal TDC and BDC."""
        art = self.articulated[number]
        assert self.group is not None
        sl = self.group.slaves[art.slot]
        d = self.phases[number]
        return (math.remainder(sl.phi_tdc + art.offset - d, TURN),
                math.remainder(sl.phi_bdc + art.offset - d - math.pi, TURN))

    def stroke_E(self, psi: Array, number: int = 2) -> Array:
        """Stroke index of an articulated cylinder at its own cycle angle ψ (exact dead
        centres)."""
        e_T, e_B = self.dead_centres(number)
        shifted = np.mod(psi - e_T, self.spec.cycle)
        bounds = np.array([k * math.pi + (e_B - e_T if k % 2 else 0.0)
                           for k in range(1, self.spec.strokes)])
        return np.searchsorted(bounds, shifted, side="right")

    def _articulated(self, number: int, psi: Array, phi: Array) -> CylinderForces:
        group = self.group
        assert group is not None
        art = self.articulated[number]
        sl = group.slaves[art.slot]
        spec, w = self.spec, self.omega
        st = self.group_state(phi - art.offset)
        u = sl.u
        E, D = st.E[art.slot], st.D[art.slot]
        x = sl.s_tdc - E @ u
        v = -(st.v_E[art.slot] @ u)
        a = -(st.a_E[art.slot] @ u)
        e = E - D
        e /= np.hypot(e[:, 0], e[:, 1])[:, None]
        n = np.array([-u[1], u[0]])
        beta = np.arctan2(e @ n, e @ u)
        p = self.diagram.pressure_xi(x / sl.stroke, self.stroke_E(psi, number))
        # Brix's construction drawn for this piston, from its own exact TDC
        own = psi - self.dead_centres(number)[0]
        p_brix = self.diagram.at_phi(own, sl.xi_brix(own))
        a_s = sl.a_series(phi - art.offset, w)
        m = self.m_j[number]
        Pk = (p - spec.p0) * spec.F_p
        p_rod = None
        if self.rod_diagram is not None:
            # the crank end: its own stroke fraction 1 − x/S′, its stroke one behind the head's
            # (its cycle starts at the head's exact BDC)
            j = np.mod(self.stroke_E(psi, number) - 1, spec.strokes)
            p_rod = self.rod_diagram.pressure_xi(1.0 - x / sl.stroke, j)
            Pk = Pk - (p_rod - spec.p0) * spec.F_rod_side
        Pj = -m * a
        P = Pk + Pj
        M = P * v / w
        nan = np.full_like(P, np.nan)
        return CylinderForces(psi, x, v, a, a_s, beta, p, p_brix, Pk, Pj, -m * a_s, P,
                              P * np.tan(beta), P / np.cos(beta), M / spec.R, nan, M, Pj * v / w,
                              p_rod)

    def group_state(self, theta: Array) -> GroupState:
        """The linkage at its crank angles θ; the last evaluation is kept (the articulated
        cylinders of one pin ask for the same angles in turn)."""
        assert self.group is not None
        theta = np.asarray(theta, float)
        key = theta.tobytes()
        cached = self.last_state
        if cached is not None and cached[0] == key:
            return cached[1]
        st = self.group.state(theta)
        self.last_state = (key, st)
        return st

    def group_pin_force(self, pin: int, phi: Array,
                        P: dict[int, Array]) -> tuple[Array, Array]:
        """T and Z on a crank pin carrying a master rod and its articulated rods, from the statics
        of the group (``P``: cylinder → force along its axis at the engine angles φ)."""
        group = self.group
        assert group is not None
        members = self.pins[pin]
        master = members[0]
        slaves = sorted((a for a in self.articulated.values() if a.master == master),
                        key=lambda a: a.slot)
        offset = slaves[0].offset
        return group.pin_force(np.asarray(phi, float) - offset, P[master],
                               tuple(P[a.number] for a in slaves))

    def pair_pin_force(self, phi: Array, P_C: Array, P_E: Array) -> tuple[Array, Array]:
        """T and Z on pin 1 of a master/articulated pair (see :meth:`group_pin_force`)."""
        return self.group_pin_force(1, phi, {self.pins[1][0]: P_C, self.pins[1][1]: P_E})
