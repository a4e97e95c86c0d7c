"""Specs of a cam mechanism: the follower, the motion program (phases and laws) and the limits.

SI units: lengths in m, angles in rad, speeds in rad/s. The follower's displacement s is a length
for a translating follower and an angle (the swing ψ) for an oscillating one.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


class Motion(enum.Enum):
    """How the follower moves."""

    TRANSLATING = "translating"
    OSCILLATING = "oscillating"


class Contact(enum.Enum):
    """The follower's tip."""

    KNIFE = "knife"
    ROLLER = "roller"
    FLAT = "flat"


class PhaseKind(enum.Enum):
    """A phase of the motion program."""

    RISE = "rise"
    FAR_DWELL = "far_dwell"
    RETURN = "return"
    NEAR_DWELL = "near_dwell"


class Law(enum.Enum):
    """Motion law of a rise or a return."""

    UNIFORM = "uniform"                 # constant velocity with constant-acceleration blends
    PARABOLIC = "parabolic"             # constant acceleration
    COSINE = "cosine"                   # harmonic
    CYCLOIDAL = "cycloidal"             # sine acceleration
    POLY345 = "poly345"                 # 3-4-5 polynomial
    MODIFIED_TRAPEZOID = "modified_trapezoid"
    TABLE_S = "table_s"                 # user table of s(φ), equally spaced over the phase
    TABLE_A = "table_a"                 # user table of the acceleration shape a(φ)


@dataclass(frozen=True, slots=True)
class Phase:
    """One phase: its kind, cam angle and (rise/return) law.

    ``blend`` is the fraction of the phase taken by each constant-acceleration blend of the uniform
    law; ``table`` holds the equally spaced values of a table law (s in m or rad, a in any unit).
    """

    kind: PhaseKind
    angle: float
    law: Law | None = None
    blend: float = 0.1
    table: tuple[float, ...] = ()
    key: str = ""


@dataclass(frozen=True, slots=True)
class Follower:
    """The follower: motion, tip and its dimensions (m).

    ``offset`` is the signed eccentricity e of a translating follower (positive on the side that
    lowers the pressure angle on the rise); ``None`` asks for the best offset.
    """

    motion: Motion
    contact: Contact
    offset: float | None = 0.0
    roller_radius: float = 0.0
    arm: float = 0.0                    # oscillating: arm length l (pivot to roller centre)
    pivot_distance: float = 0.0         # oscillating: distance a from the cam centre to the pivot
    face_margin: float = 0.005          # flat face: margin beyond the contact points, each side


@dataclass(frozen=True, slots=True)
class Limits:
    """Allowable pressure angles (rad), a given base radius (m) and the least radius of
    curvature."""

    alpha_rise: float
    alpha_return: float
    base_radius: float | None = None
    min_curvature: float = 0.0          # flat-faced follower: ρ ≥ this
    key: str = "limits"


@dataclass(frozen=True, slots=True)
class CamDrawing:
    """Sheet settings of a cam scene."""

    sheet: str = "A1"
    standard: str = "iso"
    ray_step: float = 0.5235987755982988        # rad between the inversion rays (30°)
    table_step: float = 0.17453292519943295     # rad between rows of the profile table (10°)
    chord_error: float = 1e-6                   # m, the profile DXF's chord error bound
    title_block: dict[str, str] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class FollowerDynamics:
    """The follower's dynamics: its mass (or moment of inertia about the pivot), the closing
    spring, an optional damper and a constant load, all along the follower's motion.

    Translating: N, N/m, kg, N·s/m; oscillating: N·m, N·m/rad, kg·m², N·m·s/rad. ``stiffness`` or
    ``preload`` None: chosen so that the follower stays on the cam up to ``speed_max``.
    """

    mass: float
    stiffness: float | None = None
    preload: float | None = None        # spring force at the near position (s = 0)
    damping: float = 0.0
    load: float = 0.0                   # constant force pressing the follower onto the cam
    speed_max: float | None = None      # rad/s; None: the cam speed
    margin: float = 0.0                 # least contact force kept at every speed up to speed_max
    follower_stiffness: float | None = None   # the elastic single-mass model: k of the follower
    damping_ratio: float = 0.0          # ζ of the elastic model


@dataclass(frozen=True, slots=True)
class CamSpec:
    """A cam scene."""

    title: str
    language: str
    follower: Follower
    phases: tuple[Phase, ...]
    stroke: float                       # h (m) or the swing ψ_max (rad)
    omega: float                        # cam speed, rad/s (> 0)
    sense: int                          # +1 counter-clockwise, -1 clockwise
    limits: Limits
    drawing: CamDrawing = field(default_factory=CamDrawing)
    path: str = ""
    dynamics: FollowerDynamics | None = None
