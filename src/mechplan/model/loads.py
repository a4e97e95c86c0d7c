"""Loads and masses of a mechanism: the data of the force plan (SI units, frozen)."""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass


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
    SPRING = "spring"
    CYLINDER = "cylinder"


@dataclass(frozen=True, slots=True)
class LoadSpec:
    """An external load.

    FORCE: ``vector`` (N) at ``point`` of ``link``, or ``magnitude`` along ``towards`` (a point) /
    ``angle``. PRESSURE: ``pressure`` × π·bore²/4 at ``point``, along the slider's guide towards
    ``towards``. MOMENT: ``moment`` (N·m, counter-clockwise +) on ``link``. TABLE: force values
    interpolated against crank angle φ (rad) or slider displacement (m), along the guide towards
    ``towards``. A FORCE with ``along`` = (P, Q) acts along the line P→Q turned by ``angle``
    (counter-clockwise, rad; the line turns with the links carrying P and Q).

    SPRING and CYLINDER act between ``point`` (on ``link``) and ``other`` (on ``other_link``,
    or the frame when it is ``"0"``): tension T = ``preload`` + ``stiffness``·(L − ``free_length``)
    pulls the two ends together (a compressed spring pushes them apart, T < 0); a cylinder pushes
    its ends apart with ``pressure``·πD²/4 − ``pressure_rod``·π(D² − d²)/4 (D the ``bore``, d the
    ``rod`` diameter; gauge pressures; a positive push extends the cylinder).
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
    along: tuple[str, str] | None = None
    other: str | None = None
    other_link: str | None = None
    stiffness: float | None = None                  # N/m
    free_length: float | None = None                # m
    preload: float | None = None                    # N, tension at the free length
    rod: float | None = None                        # m, rod diameter of a cylinder
    pressure_rod: float | None = None               # Pa, rod-side gauge pressure
    name: str | None = None

    def cylinder_push(self) -> float:
        """Force pushing a cylinder's ends apart (N): p·A − p_rod·(A − A_rod)."""
        area = math.pi * float(self.bore or 0.0) ** 2 / 4.0
        ring = area - math.pi * float(self.rod or 0.0) ** 2 / 4.0
        return float(self.pressure or 0.0) * area - float(self.pressure_rod or 0.0) * ring


@dataclass(frozen=True, slots=True)
class PairFriction:
    """Friction of one pair: coefficient ``f``; revolute pairs: pin radius ``radius`` (m)."""

    f: float
    radius: float = 0.0

    @property
    def rho(self) -> float:
        """Radius of the friction circle ρ = f·r (m)."""
        return self.f * self.radius

    @property
    def angle(self) -> float:
        """Friction angle φ = atan f (rad)."""
        return math.atan(self.f)


@dataclass(frozen=True, slots=True)
class FrictionSpec:
    """Friction in the pairs: a default and per-pair values (keyed by :func:`pair_id`).

    ``tolerance`` ends the iteration (relative change of the reactions), ``max_iterations``
    bounds it; ``diagram`` asks for the η(φ) diagram on the sheet.
    """

    default: PairFriction
    pairs: tuple[tuple[str, PairFriction], ...] = ()
    tolerance: float = 1e-10
    max_iterations: int = 50
    diagram: bool = False
    key: str = "friction"

    def of(self, a: str, b: str) -> PairFriction:
        """The friction of the pair between links ``a`` and ``b``."""
        return dict(self.pairs).get(pair_id(a, b), self.default)


def pair_id(a: str, b: str) -> str:
    """Key of the pair between two links, order-free: ``"0-1"``, ``"2-3"``."""
    x, y = sorted((a, b), key=lambda s: (len(s), s))
    return f"{x}-{y}"


@dataclass(frozen=True, slots=True)
class Gravity:
    """Gravity: acceleration g (m/s²) along a unit direction."""

    g: float = 9.81
    direction: tuple[float, float] = (0.0, -1.0)
    enabled: bool = False
