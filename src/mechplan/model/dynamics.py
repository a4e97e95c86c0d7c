"""Specs of a machine's dynamics over its steady cycle: ``[dynamics]`` of a mechanism scene (SI)."""

from __future__ import annotations

import enum
from dataclasses import dataclass


class Unknown(enum.Enum):
    """Which side of the work balance is a constant moment, and whether it is found from the
    cycle."""

    RESISTING = "resisting"      # the given loads drive (engine); M_c = const
    DRIVING = "driving"          # the given loads resist (shaper, press, pump); M_d = const


class Stroke(enum.Enum):
    """Strokes of an engine cycle, in their order from the first dead centre."""

    INTAKE = "intake"
    COMPRESSION = "compression"
    EXPANSION = "expansion"
    EXHAUST = "exhaust"


FOUR_STROKE = (Stroke.INTAKE, Stroke.COMPRESSION, Stroke.EXPANSION, Stroke.EXHAUST)
TWO_STROKE = (Stroke.COMPRESSION, Stroke.EXPANSION)


@dataclass(frozen=True, slots=True)
class IndicatorSpec:
    """Gas pressure on a piston over the cycle (Pa, absolute); force (p − p_ambient)·πd²/4.

    Either ``table`` against the cycle angle from the cycle's start (rad, 0 … Φ), or ``strokes``:
    per stroke, pressure against the piston's displacement from the dead centre where the cycle
    starts (m). The force acts along the slider's guide towards the point ``towards``.
    """

    point: str
    link: str
    towards: str
    bore: float
    ambient: float = 0.0
    table: tuple[tuple[float, float], ...] = ()
    strokes: tuple[tuple[Stroke, tuple[tuple[float, float], ...]], ...] = ()
    key: str = "dynamics.indicator"


class FlywheelShape(enum.Enum):
    """Shapes of a flywheel whose dimensions follow from its moment of inertia."""

    DISC = "disc"
    RIM = "rim"


@dataclass(frozen=True, slots=True)
class FlywheelSpec:
    """Shape and material of the flywheel: outer (disc) or mean (rim) diameter or width ratio
    b/D."""

    shape: FlywheelShape
    density: float = 7800.0
    diameter: float | None = None
    width_ratio: float | None = None
    section_ratio: float = 1.0            # rim only: height h over width b of the cross-section


@dataclass(frozen=True, slots=True)
class DynamicsSpec:
    """What the dynamics of the machine unit needs beyond the linkage and its loads.

    ``constant_moment`` None: the constant moment of the ``unknown`` side is found from the cycle;
    a value (N·m, magnitude): both sides are given and the net work must be ≈ 0.
    """

    unknown: Unknown
    delta: float
    cycle: float                          # Φ, rad: 2π or 4π
    constant_moment: float | None = None
    inertia_const: float = 0.0            # kg·m², rotating parts beyond the mechanism, reduced
    indicator: IndicatorSpec | None = None
    flywheel: FlywheelSpec | None = None
    dense: int = 5760                     # dense (exact) points per crank turn
    pole_distance_mm: float | None = None  # H of the graphical integration; None: chosen
    balance_tolerance: float = 0.02       # |A_d − A_c| / max(A_d, A_c) allowed when both are given
