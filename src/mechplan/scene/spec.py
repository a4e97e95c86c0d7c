"""The frozen scene: a mechanism plus what to analyse, loads, masses and drawing settings."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model.loads import FrictionSpec, Gravity, LoadSpec, MassSpec
from ..model.mechanism import Mechanism
from ..model.plans import Plan
from ..model.textbook import TextbookSpec
from .centres import CentresSpec

#: the plans a scene may ask for, by name
PLANS = tuple(plan.value for plan in Plan)


@dataclass(frozen=True, slots=True)
class Extreme:
    """A named extreme position: of a point along its guide or of a link's angle; max or min."""

    subject: str
    which: str  # "max" | "min"


@dataclass(frozen=True, slots=True)
class Positions:
    """Crank positions to analyse: explicit φ list (rad) or N equal steps from a start."""

    angles: tuple[float, ...] = ()
    count: int = 0
    start_angle: float = 0.0
    start_extreme: Extreme | None = None


@dataclass(frozen=True, slots=True)
class DrawingSpec:
    """Sheet settings and fixed scale factors (SI per mm of paper)."""

    sheet: str = "A1"
    standard: str = "iso"
    scales: dict[str, float] = field(default_factory=dict)
    title_block: dict[str, str] = field(default_factory=dict)
    plan_positions: tuple[int, ...] = ()     # numbers of the positions whose plans are drawn


@dataclass(frozen=True, slots=True)
class Scene:
    """A parsed scene file."""

    path: str
    title: str
    language: str
    mechanism: Mechanism
    positions: Positions
    plans: tuple[str, ...]
    points_of_interest: tuple[str, ...]
    masses: dict[str, MassSpec]
    loads: tuple[LoadSpec, ...]
    gravity: Gravity
    drawing: DrawingSpec
    assembly_phi: float = 0.0
    #: the [centres] table: centrodes, acceleration poles, inflection circles of chosen links
    centres: CentresSpec | None = None
    textbook: TextbookSpec | None = None     # the [answers] section: textbook answers asked
    friction: FrictionSpec | None = None      # [friction]: friction in the pairs (docs/forces.md)
