"""The frozen scene: a mechanism plus what to analyse, loads, masses and drawing settings."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from ..model.mechanism import Mechanism

PLANS = ("position", "velocity", "acceleration", "force")
#: fields of a sheet's title block that a scene may fill ([title_block])
TITLE_BLOCK_FIELDS = (
    "title", "author", "group", "instructor", "school", "department", "date", "scale",
    "sheet_number", "sheets_total", "designation", "document_type", "material", "litera",
)


@dataclass(frozen=True, slots=True)
class MassSpec:
    """Mass data of a link: mass (kg), centre (a point of the link), J_S (kg·m²)."""

    link: str
    mass: float
    centre: str
    inertia: float


class LoadKind(enum.Enum):
    """Kinds of external loads."""

    FORCE = "force"
    PRESSURE = "pressure"
    MOMENT = "moment"
    TABLE = "table"


@dataclass(frozen=True, slots=True)
class LoadSpec:
    """An external load.

    FORCE: ``vector`` (N) at ``point`` of ``link``, or ``magnitude`` along ``towards`` (a point) /
    ``angle``. PRESSURE: ``pressure`` × π·bore²/4 at ``point``, along the slider's guide towards
    ``towards``. MOMENT: ``moment`` (N·m, counter-clockwise +) on ``link``. TABLE: force values
    interpolated against crank angle φ (rad) or slider displacement (m), along the guide towards
    ``towards``.
    """

    kind: LoadKind
    link: str
    point: str | None = None
    vector: tuple[float, float] | None = None
    magnitude: float | None = None
    angle: float | None = None
    towards: str | None = None
    pressure: float | None = None
    bore: float | None = None
    moment: float | None = None
    against: str | None = None                      # "crank_angle" | "displacement"
    table: tuple[tuple[float, float], ...] = ()
    key: str = ""


@dataclass(frozen=True, slots=True)
class Gravity:
    """Gravity: acceleration g (m/s²) along a unit direction."""

    g: float = 9.81
    direction: tuple[float, float] = (0.0, -1.0)
    enabled: bool = False


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
