"""The output link of a mechanism's kinematic diagrams: the last link of the chain that slides on a
frame guide or turns about a frame pivot (not a driver, not a driving cylinder's barrel)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .mechanism import GROUND, DriverKind, Mechanism, PairKind


@dataclass(frozen=True)
class Output:
    """The output link of a diagram: a slider on a frame guide or a link turning about the frame."""

    link: str
    point: str | None              # the slider's point, None for a rocker
    direction: tuple[float, float]  # the guide's direction (slider)


def output_link(mech: Mechanism) -> Output | None:
    """The last link of the chain that slides on a frame guide or turns about a frame pivot."""
    found: Output | None = None
    given = {GROUND, *(d.link for d in mech.drivers)}                # W = 2: both drivers
    given |= {d.carrier for d in mech.drivers                         # a cylinder's barrel
              if d.kind is DriverKind.CYLINDER and d.carrier is not None}
    for lk in mech.links.values():
        if lk.id in given:
            continue
        if lk.slides_on and mech.guides[lk.slides_on].link == GROUND:
            g = mech.guides[lk.slides_on]
            found = Output(lk.id, next(iter(lk.points)), (math.cos(g.angle), math.sin(g.angle)))
        elif any(p.kind is PairKind.REVOLUTE and GROUND in (p.a, p.b)
                 for p in mech.pairs_of(lk.id)):
            found = Output(lk.id, None, (1.0, 0.0))
    return found
