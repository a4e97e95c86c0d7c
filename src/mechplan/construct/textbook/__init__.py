"""Every answer a textbook asks for, computed from an evaluation only when a scene asks for it.

Relative velocities and accelerations (sliding, Coriolis, normal and tangential parts), rubbing
velocities at pins, transmission angles of the groups (with their least value over the cycle),
strokes/swings with the time ratio K, and the slowest point of each link. See docs/textbook.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...model.mechanism import Mechanism, Pair
from ...model.structure import Group, Structure
from ...model.textbook import Answer, TextbookSpec
from ..graph import Construction, Evaluation
from .least import LeastVelocity, least_velocity, slowest_links
from .relative import (
    PointPair,
    Sliding,
    Turning,
    point_pairs,
    prismatic_pairs,
    revolute_pairs,
    rubbing,
    sliding,
    turning,
)
from .stroke import Stroke, strokes
from .transmission import Transmission, least_transmission, transmission


@dataclass(frozen=True, slots=True)
class Rubbing:
    """Rubbing at a pin: radius (m), ω_a − ω_b (N,), v_rub = |ω_a − ω_b|·r (N,)."""

    pair: Pair
    radius: float
    omega_rel: np.ndarray
    v_rub: np.ndarray


@dataclass
class TextbookAnswers:
    """What was asked for; each list is empty when its family was not asked."""

    asked: frozenset[Answer]
    sliding: list[Sliding] = field(default_factory=list)
    point_pairs: list[PointPair] = field(default_factory=list)
    turning: list[Turning] = field(default_factory=list)
    rubbing: list[Rubbing] = field(default_factory=list)
    transmission: list[Transmission] = field(default_factory=list)
    least_gamma: dict[str, tuple[float, float] | None] = field(default_factory=dict)
    strokes: list[Stroke] = field(default_factory=list)
    least_velocity: list[LeastVelocity] = field(default_factory=list)


def textbook_answers(c: Construction, ev: Evaluation, mech: Mechanism, structure: Structure,
                     spec: TextbookSpec, points: tuple[str, ...] = (),
                     file: str | None = None) -> TextbookAnswers:
    """Compute the families ``spec`` asks for at the evaluation's positions (and, for the least
    transmission angle and the strokes, over the whole crank turn)."""
    out = TextbookAnswers(spec.asked)
    accel = any(s.plan.value == "acceleration" for s in c)
    if Answer.RELATIVE in spec.asked:
        out.sliding = [sliding(c, ev, mech, p, accel) for p in prismatic_pairs(mech)]
        out.point_pairs = point_pairs(c, ev, mech, points)
        out.turning = [turning(c, ev, mech, p, accel) for p in revolute_pairs(mech)]
    if Answer.RUBBING in spec.asked:
        for p in revolute_pairs(mech):
            r = spec.radius(p.point, p.a, p.b)
            if r is not None:
                dw, v = rubbing(c, ev, mech, p, r)
                out.rubbing.append(Rubbing(p, r, dw, v))
    if Answer.TRANSMISSION in spec.asked:
        for g in structure.groups:
            if not isinstance(g, Group):    # a triad's legs: no one transmission angle
                continue
            out.transmission.append(transmission(c, ev, mech, g))
            out.least_gamma[g.name] = least_transmission(c, mech, g)
    if Answer.STROKE in spec.asked:
        out.strokes = strokes(c, mech, spec.outputs, file)
    if Answer.LEAST_VELOCITY in spec.asked:
        out.least_velocity = [least_velocity(c, ev, mech, lid) for lid in slowest_links(c, mech)]
    return out


__all__ = ["LeastVelocity", "PointPair", "Rubbing", "Sliding", "Stroke", "TextbookAnswers",
           "Transmission", "Turning", "textbook_answers"]
