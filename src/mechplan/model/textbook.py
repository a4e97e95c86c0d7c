"""What a scene's ``[answers]`` section asks for: the quantities textbooks print as answers."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


class Answer(enum.StrEnum):
    """A family of textbook answers, each computed only when asked for."""

    RELATIVE = "relative"            # relative v, a of points and pairs; n, t, Coriolis parts
    RUBBING = "rubbing"              # rubbing velocity at each pin of known radius
    TRANSMISSION = "transmission"    # transmission angle of every group, its minimum
    STROKE = "stroke"                # stroke H / swing ψ, extremes, working/return, K
    LEAST_VELOCITY = "least_velocity"  # the point of a link with the least velocity


@dataclass(frozen=True, slots=True)
class TextbookSpec:
    """The answers asked for; pin radii (m) by the point of a revolute pair; output subjects.

    ``outputs`` names sliders (a point on a frame guide) and rockers (a link number) whose stroke
    is asked for; empty: every slider on a frame guide and every rocker pivoted on the frame.
    """

    asked: frozenset[Answer]
    pin_radius: float | None = None
    pins: dict[str, float] = field(default_factory=dict)
    outputs: tuple[str, ...] = ()

    def radius(self, point: str, a: str = "", b: str = "") -> float | None:
        """The radius of the pin joining links ``a`` and ``b`` at ``point``: its own (key
        ``"A(1,2)"``), the point's (key ``"A"``) or the default; None when none is given."""
        for key in (f"{point}({a},{b})", f"{point}({b},{a})", point):
            if key in self.pins:
                return self.pins[key]
        return self.pin_radius
