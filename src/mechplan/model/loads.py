"""Loads and masses of a mechanism: the data of the force plan (SI units, frozen)."""

from __future__ import annotations

import enum
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
