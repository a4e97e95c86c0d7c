"""A machine's cycle diagram (циклограмма): scenes whose members turn with one main shaft."""

from __future__ import annotations

import enum
from dataclasses import dataclass


class Working(enum.Enum):
    """Which stroke of a linkage's output is its working stroke."""

    LONGER = "longer"      # the slower one (the longer crank angle), as the courses take it
    TO_MAX = "to_max"      # the stroke ending at the output's maximum
    TO_MIN = "to_min"      # the stroke ending at its minimum


@dataclass(frozen=True)
class MemberSpec:
    """One member on the shaft: a scene file (a linkage or a cam) and its phase offset.

    ``phase``: the member's own angle (crank angle φ of the linkage scene, cam angle from the
    start of the cam's first phase) when the main shaft is at 0, rad: φ = ψ + phase.
    """

    name: str
    scene: str
    phase: float = 0.0
    subject: str | None = None     # the linkage's output: a slider's point or a rocker's link
    working: Working = Working.LONGER
    #: a linkage whose crank is the follower lever of this cam member (its name), and the
    #: linkage's crank angle φ (its scene's convention) at the cam's near position, rad
    driven_by: str | None = None
    near: float = 0.0              # rad, or m for a driving slider (``near_length``)
    near_length: bool = False
    near_given: bool = False
    shaft: str | None = None       # the shaft it turns with (None: the first shaft, or the motor)


@dataclass(frozen=True)
class ShaftSpec:
    """A shaft turned from the motor (or from another shaft) through a gear scene's train.

    ``train``: the gear scene (a planetary stage and its ordinary stage, as solved there); the
    shaft's speed is ω_from / u with u the train's exact ratio.
    """

    name: str
    train: str
    source: str = "motor"          # "motor" or an earlier shaft's name


@dataclass(frozen=True)
class Motor:
    """The machine's motor: its speed (rad/s, signed: + counter-clockwise)."""

    omega: float


@dataclass(frozen=True)
class MachineSpec:
    """A machine file: its members and where its cycle diagram starts on the main shaft."""

    title: str
    language: str
    members: tuple[MemberSpec, ...]
    start: float | None = None     # ψ of the diagram's origin, rad (None: the first member's
                                   # first phase: its working stroke or its rise)
    file: str = "<scene>"
    motor: Motor | None = None
    shafts: tuple[ShaftSpec, ...] = ()
    cycle_shaft: str | None = None  # the shaft whose turn the diagram spans (default: the
                                    # slowest shaft)
