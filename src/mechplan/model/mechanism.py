"""The mechanism as the course describes it: links with points, pairs, guides and a drive.

Every link has its own frame. The frame (link ``"0"``) is the world. A link that slides on a guide
has its origin at the sliding point and its x axis along the guide; any other link has its first
two points on its x axis (the first at the origin). Coordinates are metres, angles radians.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from .law import TableLaw

GROUND = "0"


class PairKind(enum.Enum):
    """Lower pairs of class 5."""

    REVOLUTE = "R"
    PRISMATIC = "P"


@dataclass(frozen=True, slots=True)
class Guide:
    """A straight guide fixed to a link: a line through ``origin`` at ``angle`` (link frame)."""

    name: str
    link: str
    origin: tuple[float, float]
    angle: float
    through: str  # the named point the guide passes through (for texts)


@dataclass(frozen=True, slots=True)
class Pair:
    """A lower pair between links ``a`` and ``b``.

    Revolute: ``point`` is the shared point. Prismatic: ``b`` carries ``guide`` and ``a`` is the
    slider whose frame origin ``point`` lies on it.
    """

    kind: PairKind
    a: str
    b: str
    point: str
    guide: str | None = None

    def other(self, link: str) -> str:
        """Return the link at the other side of the pair."""
        return self.b if link == self.a else self.a

    def joins(self, link: str) -> bool:
        """Tell whether the pair touches a link."""
        return link in (self.a, self.b)

    @property
    def name(self) -> str:
        """Short name such as ``R(1,2)@B`` or ``P(3/0)@C``."""
        if self.kind is PairKind.REVOLUTE:
            return f"R({self.a},{self.b})@{self.point}"
        return f"P({self.a}/{self.b}:{self.guide})@{self.point}"


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link: named points in its own frame."""

    id: str
    name: str
    points: dict[str, tuple[float, float]]
    slides_on: str | None = None  # guide name when the link is a slider

    def distance(self, p: str, q: str) -> float:
        """Return the distance between two of the link's points (m)."""
        (x1, y1), (x2, y2) = self.points[p], self.points[q]
        return float(((x2 - x1) ** 2 + (y2 - y1) ** 2) ** 0.5)


class DriverKind(enum.Enum):
    """What the driver moves: a link turning about a frame pivot, or a length (linear drivers)."""

    CRANK = "crank"          # a link turning about a frame pivot; coordinate φ (rad)
    CYLINDER = "cylinder"    # a linear actuator (RPR): coordinate l, its length between pins (m)
    SLIDER = "slider"        # a slider on a frame guide: coordinate s along the guide (m)


@dataclass(frozen=True, slots=True)
class Drive:
    """The driver and its law: its coordinate q is the independent variable of every plan.

    A crank: ``link`` turns about the frame point ``pivot``; q = φ (rad) measured from
    ``ref_angle``; ``omega``/``epsilon`` are dφ/dt, d²φ/dt² (signed, + counter-clockwise).
    A cylinder: ``link`` is the rod sliding on ``guide`` of the barrel ``carrier``; ``pivot`` is the
    rod's pin; q = l, the distance between the barrel's pivot and the rod's pin (m);
    ``omega``/``epsilon`` are dl/dt (m/s, + extending) and d²l/dt² (m/s²).
    A slider: ``link`` slides on the frame guide ``guide`` with its point ``pivot``; q = s, the
    displacement of that point from the guide's ``through`` point along the guide (m), rates in
    m/s and m/s². ``q_range`` is the range of q a sweep spreads its positions over (linear drivers).
    """

    link: str
    pivot: str
    omega: float  # rad/s, signed: + counter-clockwise (linear drivers: m/s)
    epsilon: float  # rad/s², signed (linear drivers: m/s²)
    ref_angle: float  # rad, absolute direction of φ = 0 (linear drivers: 0)
    ref_name: str  # what φ is measured from ("Ax", "+x")
    kind: DriverKind = DriverKind.CRANK
    carrier: str | None = None  # cylinder: the barrel link
    guide: str | None = None    # linear drivers: the guide the rod or slider slides on
    q_range: tuple[float, float] | None = None  # linear drivers: (from, to) of a sweep (m)
    #: a second driver (``[drive2]``, W = 2): a crank's φ at the first driver's φ = 0 (rad, in its
    #: sense); a cylinder's length at the first driver's reference (φ1 = 0 or its range start, m)
    phase: float = 0.0
    #: a linear driver's law by a table over time (``law``): q(t) through a cubic spline; then
    #: ``omega`` is the table's mean rate and ``epsilon`` 0 (the rates come from the spline)
    law: TableLaw | None = None

    @property
    def sense(self) -> int:
        """+1 counter-clockwise, -1 clockwise (linear drivers: always +1, q is signed)."""
        if self.linear:
            return 1
        return 1 if self.omega >= 0 else -1

    @property
    def linear(self) -> bool:
        """Tell whether the driver's coordinate is a length (a cylinder or a slider)."""
        return self.kind is not DriverKind.CRANK


@dataclass(frozen=True, slots=True)
class Mechanism:
    """Links (the frame is link "0"), pairs, guides and the drive."""

    links: dict[str, Link]
    pairs: tuple[Pair, ...]
    guides: dict[str, Guide]
    drive: Drive
    sides: dict[str, tuple[str, str, int]] = field(
        default_factory=dict
    )  # assembly: point → (P, Q, ±1)
    sketch: dict[str, tuple[float, float]] = field(default_factory=dict)  # assembly by sketch
    #: a second driver (W = 2): a crank whose φ2 = phase + |ω2|/|ω1|·φ1 (docs/two_inputs.md) or a
    #: cylinder whose l2 = phase + l̇2/rate1·(q1 − q1⁰) (docs/drivers.md)
    drive2: Drive | None = None

    @property
    def drivers(self) -> tuple[Drive, ...]:
        """Every driver: ``drive``, then ``drive2`` when there is one."""
        return (self.drive,) if self.drive2 is None else (self.drive, self.drive2)

    @property
    def moving(self) -> list[str]:
        """Moving link ids in scene order."""
        return [k for k in self.links if k != GROUND]

    def pairs_of(self, link: str) -> list[Pair]:
        """Return the pairs touching a link."""
        return [p for p in self.pairs if p.joins(link)]
