"""Specs of an internal-combustion engine for its dynamic calculation (SI units, angles in rad).

Crank angle φ is measured from the top dead centre of cylinder 1 in the sense of rotation; the cycle
is 4π for a four-stroke engine, 2π for a two-stroke one.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass


class Layout(enum.Enum):
    """How the cylinders sit on the crankshaft."""

    INLINE = "inline"               # one cylinder per throw, all axes parallel
    V = "v"                         # two banks, side-by-side rods on shared throws
    ARTICULATED = "v_articulated"   # two banks, a master and an articulated rod on every throw
    RADIAL = "radial"               # one throw, a master rod and n − 1 articulated rods


class IndicatorKind(enum.Enum):
    """Where the indicator diagram comes from."""

    THERMAL = "thermal"             # Grinevetsky–Mazing construction from the thermal calculation
    VOLUME = "volume"               # a measured table p(V) around the closed cycle
    CRANK_ANGLE = "crank_angle"     # a measured table p(φ) over the cycle


@dataclass(frozen=True, slots=True)
class ThermalSpec:
    """Thermal-calculation parameters of the indicator diagram (pressures absolute, Pa).

    ``rho`` > 1 makes a diesel (combustion at p_z from V_c to ρ·V_c). The corners are rounded
    from the ignition advance (before TDC) to the real peak ``peak_fraction``·p_z at ``peak_angle``
    after TDC, and from the exhaust-valve opening (before BDC) to BDC at (p_b + p_r)/2.
    """

    epsilon: float
    p_a: float
    p_r: float
    n1: float
    n2: float
    p_z: float
    rho: float = 1.0
    ignition_advance: float = math.radians(15.0)
    peak_angle: float = math.radians(12.0)
    peak_fraction: float = 0.85
    tdc_fraction: float = 1.2           # p_c'' = tdc_fraction · p_c (rounding point at TDC)
    exhaust_opening: float = math.radians(50.0)
    rounding: bool = True


@dataclass(frozen=True, slots=True)
class IndicatorSpec:
    """The indicator diagram: thermal parameters or a measured table.

    Tables: ``rows`` of (V [m³], p [Pa]) around the closed cycle starting at the intake TDC, or
    (φ [rad], p [Pa]) over the cycle from 0.
    """

    kind: IndicatorKind
    thermal: ThermalSpec | None = None
    rows: tuple[tuple[float, float], ...] = ()
    epsilon: float | None = None        # compression ratio (tables: for V_c when not implied)


@dataclass(frozen=True, slots=True)
class CylinderSpec:
    """One cylinder: its throw (angle of its crank behind crank 1) and bank (angle of its axis)."""

    number: int
    throw: float
    bank: float
    articulated: bool = False


@dataclass(frozen=True, slots=True)
class RodMasses:
    """A connecting rod reduced to two masses: m1 at the piston pin, m2 at the big end.

    ``J_S`` is the rod's own moment of inertia about its centre of mass if given (to report the
    two-mass error), else None.
    """

    m1: float
    m2: float
    J_S: float | None = None
    l1: float | None = None             # distance centre of mass → small end, m
    l2: float | None = None             # distance centre of mass → big end, m

    @property
    def total(self) -> float:
        """m1 + m2."""
        return self.m1 + self.m2

    @property
    def J_two_mass(self) -> float | None:
        """Moment of inertia the two masses have about the centre of mass (m1·l1² + m2·l2²)."""
        if self.l1 is None or self.l2 is None:
            return None
        return self.m1 * self.l1 ** 2 + self.m2 * self.l2 ** 2


@dataclass(frozen=True, slots=True)
class MassSpec:
    """Masses of one crank throw's moving parts (kg); crank masses reduced to the pin radius R."""

    piston: float                       # piston group
    rod: RodMasses
    rotating_extra: float = 0.0         # e.g. big-end bearing shell, rotating with the pin
    crank: float = 0.0                  # crank's unbalanced mass reduced to R (m_k)
    counterweight: float = 0.0          # counterweights reduced to R (opposite the pin)


@dataclass(frozen=True, slots=True)
class ArticulatedSpec:
    """The articulated cylinder of a master/articulated V pair.

    The lug D sits on the master rod at ``lug_radius`` from the big end B, at ``lug_angle`` from
    B→C towards the articulated bank; the articulated rod DE has ``rod_length``.
    """

    lug_radius: float
    lug_angle: float
    rod_length: float
    piston: float
    rod: RodMasses


@dataclass(frozen=True, slots=True)
class ArticulatedRod:
    """One articulated cylinder: its number, its master cylinder's and its rod's geometry.

    ``lug`` is the signed angle ∠CBD from the master rod's B→C in the sense of rotation (rad).
    """

    number: int
    master: int
    lug: float
    spec: ArticulatedSpec


@dataclass(frozen=True, slots=True)
class RodSideSpec:
    """The crank-end (rod-side) face of a double-acting cylinder.

    Gas acts on F_p − π·d²/4; its indicator diagram runs its own cycle from its own TDC, the head
    end's BDC (half a turn later).
    """

    rod_diameter: float
    indicator: IndicatorSpec | None       # None: the head end's diagram, half a turn later


@dataclass(frozen=True, slots=True)
class EngineSpec:
    """An engine for its dynamic calculation."""

    title: str
    strokes: int                        # 2 or 4
    speed: float                        # ω, rad/s (positive; the sense of rotation is positive φ)
    bore: float
    R: float
    L: float
    p0: float                           # crankcase / ambient pressure, Pa
    layout: Layout
    cylinders: tuple[CylinderSpec, ...]
    firing_order: tuple[int, ...]
    masses: MassSpec
    indicator: IndicatorSpec
    articulated: ArticulatedSpec | None = None
    rods: tuple[ArticulatedRod, ...] = ()   # every articulated cylinder
    rod_side: RodSideSpec | None = None     # double-acting cylinders
    grid: int = 720                     # points of the dense pass per cycle
    table_step: float = math.radians(15.0)
    language: str = "en"
    csv: str | None = None              # path of the per-angle CSV to write, if asked

    @property
    def lam(self) -> float:
        """λ = R/L."""
        return self.R / self.L

    @property
    def cycle(self) -> float:
        """Cycle angle: 4π (four-stroke) or 2π (two-stroke)."""
        return 2.0 * math.pi * self.strokes / 2.0

    @property
    def F_p(self) -> float:
        """Piston area πD²/4."""
        return math.pi * self.bore ** 2 / 4.0

    @property
    def V_h(self) -> float:
        """Displacement of one cylinder F_p·2R."""
        return self.F_p * 2.0 * self.R

    @property
    def F_rod_side(self) -> float:
        """Gas area of the crank-end face F_p − πd²/4 (0 for a single-acting cylinder)."""
        rs = self.rod_side
        return 0.0 if rs is None else self.F_p - math.pi * rs.rod_diameter ** 2 / 4.0


def firing_phases(cylinders: tuple[CylinderSpec, ...], order: tuple[int, ...],
                  strokes: int) -> dict[int, float]:
    """Cycle angle δ_i at which cylinder i starts its cycle, cylinder 1 at 0 (rad).

    Cylinder i's crank reaches its own axis at θ_i + ψ_i (throw + bank) after crank 1 reaches
    axis 1; a four-stroke engine takes that angle or one turn more, as the firing order says.
    Raise ValueError when the order does not fit the throws.
    """
    full = 2.0 * math.pi
    cycle = math.pi * strokes
    by_number = {c.number: c for c in cylinders}
    geo = {n: (c.throw + c.bank) % full for n, c in by_number.items()}
    start = geo[order[0]]
    phases: dict[int, float] = {order[0]: 0.0}
    prev = 0.0
    for n in order[1:]:
        g = (geo[n] - start) % full
        if g < 1e-12:
            g = full if strokes == 4 else g
        options = [g + k * full for k in range(strokes // 2) if g + k * full > prev + 1e-9]
        if not options or options[0] >= cycle - 1e-9:
            raise ValueError(
                f"the firing order {list(order)} does not fit the throws and banks: cylinder {n} "
                f"cannot fire after cylinder {order[order.index(n) - 1]} within one cycle")
        prev = options[0]
        phases[n] = prev
    shift = phases[1]
    return {n: (d - shift) % cycle for n, d in phases.items()}
