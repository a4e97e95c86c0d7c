"""What every linkage synthesis hands on: the construction, the chosen mechanism, its conditions."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

Point = tuple[float, float]


def theta_of_k(k: float) -> float:
    """The angle of overlap θ = π·(K − 1)/(K + 1) (rad) of a time ratio K ≥ 1."""
    return math.pi * (k - 1.0) / (k + 1.0)


def k_of_theta(theta: float) -> float:
    """The time ratio K = (π + θ)/(π − θ) of an angle of overlap θ (rad)."""
    return (math.pi + theta) / (math.pi - theta)


@dataclass(frozen=True, slots=True)
class Step:
    """One line of the construction protocol: a catalogue id and its values (SI: m, rad)."""

    msgid: str
    values: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class Stroke:
    """A drawn element of the construction (SI coordinates, metres).

    ``kind``: ``"point"``, ``"line"`` (a segment a→b), ``"circle"`` (centre a, radius r),
    ``"arc"`` (centre a, radius r, counter-clockwise from angle b[0] to b[1], rad), and
    ``role``: ``"given"``, ``"aux"``, ``"result"``, ``"mechanism"`` or ``"family"``.
    """

    kind: str
    a: Point
    b: Point = (0.0, 0.0)
    r: float = 0.0
    role: str = "aux"
    label: str = ""


@dataclass(frozen=True, slots=True)
class Candidate:
    """One member of the family along the construction circle: its parameter and conditions."""

    t: float              # the parameter (rad along the circle, or the offset in m)
    lengths: dict[str, float]
    gamma_min: float      # rad; NaN where the member is not a valid mechanism
    valid: bool


@dataclass(frozen=True)
class LinkageDesign:
    """A synthesised linkage: the asked and achieved values, the scene to analyse, the drawing.

    ``problem``: crank_rocker | slider_crank | coulisse | shaper. Lengths in metres, angles in
    radians. ``scene`` is a mechanism scene as a dict (written with
    :func:`mechplan.scene.writer.to_toml`); ``extremes`` name the output whose extreme positions
    give the time ratio back (a link number or a slider point).
    """

    problem: str
    k: float
    theta: float
    lengths: dict[str, float]
    strokes: list[Stroke]
    protocol: list[Step]
    conditions: dict[str, Any]
    family: list[Candidate]
    choice: Step
    scene: dict[str, Any]
    output: str             # the extreme-position subject of the produced scene
    output_kind: str        # "angle" (a rocking link: ψ) or "length" (a slider: H)
    asked_output: float     # ψ (rad) or H (m) asked
