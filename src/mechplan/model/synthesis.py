"""The specification of a linkage synthesis (``kind = "synthesis"``): what is asked, in SI."""

from __future__ import annotations

from dataclasses import dataclass, field

PROBLEMS = ("crank_rocker", "slider_crank", "coulisse", "shaper", "function", "guidance", "path")
#: the functions a four-bar function generator may be asked for (x in radians for sin, cos, tan)
FUNCTIONS = ("log10", "ln", "exp", "sqrt", "square", "cube", "reciprocal", "sin", "cos", "tan")
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
    gamma_target: float | None = None   # a slider-crank chosen by its γmin
    function: str | None = None         # y = f(x) of a function generator
    x_range: tuple[float, float] | None = None
    points: tuple[float, ...] | None = None        # precision points x (None: Chebyshev)
    point_count: int = 3                # Chebyshev points (more than 3: least squares)
    input_start: float = 0.0            # φ at x0 (rad, from the frame line A→D)
    input_range: float | None = None    # Δφ over the x range
    output_start: float = 0.0           # ψ at x0 (rad, of DC from the frame line)
    output_range: float | None = None   # Δψ over the x range
    guide_b: tuple[tuple[float, float], ...] | None = None   # three positions of B (guidance)
    guide_c: tuple[tuple[float, float], ...] | None = None   # three positions of C
    pivot_line: tuple[tuple[float, float], float] | None = None  # two positions: (point, angle)
    path_points: tuple[tuple[float, float], ...] | None = None    # P1…Pn (path generation)
    crank_rotations: tuple[float, ...] | None = None     # β2…βn from the first position
    coupler_rotations: tuple[float, float] | None = None  # α at the second and last points
    rocker_rotations: tuple[float, float] | None = None   # γ at the second and last points
    speed: float = 10.0
    sense: int = 1
    positions: int = 12
    sheet: str | None = None
    standard: str | None = None
    title_block: dict[str, str] = field(default_factory=dict)
