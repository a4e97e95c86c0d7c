"""The specification of a linkage synthesis (``kind = "synthesis"``): what is asked, in SI."""

from __future__ import annotations

from dataclasses import dataclass, field

PROBLEMS = ("crank_rocker", "slider_crank", "coulisse", "shaper")
#: how a crank-rocker is picked from its family on the construction circle
CHOICES = ("frame", "frame_angle", "best")


@dataclass(frozen=True)
class SynthesisSpec:
    """A synthesis asked by a scene; lengths in m, angles in rad, speed in rad/s.

    ``None`` marks a key the scene left out. ``sense``: +1 counter-clockwise, −1 clockwise.
    """

    problem: str
    k: float
    title: str = ""
    language: str = "en"
    path: str = "<scene>"
    swing: float | None = None          # ψ of the rocker (crank_rocker)
    rocker: float | None = None         # rocker length DC (crank_rocker)
    frame: float | None = None          # AD, O1O3
    frame_angle: float | None = None    # ψ0 between the frame line and the nearer extreme rocker
    stroke: float | None = None         # H of the slider / ram / coulisse tip
    offset: float | None = None         # e of a slider-crank
    rod_ratio: float | None = None      # λ = r/l
    crank: float | None = None          # r (coulisse, shaper)
    coulisse: float | None = None       # O3B (coulisse)
    rod: float | None = None            # BC of the shaper
    gamma_limit: float | None = None    # the admissible minimum transmission angle [γ]
    speed: float = 10.0
    sense: int = 1
    positions: int = 12
    sheet: str | None = None
    standard: str | None = None
    title_block: dict[str, str] = field(default_factory=dict)
