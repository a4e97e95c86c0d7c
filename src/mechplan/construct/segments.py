"""Measured segments of a plan: what a student measures with a ruler and multiplies by μ."""

from __future__ import annotations

import enum
from dataclasses import dataclass

from ..model.plans import Plan


class SegmentKind(enum.Enum):
    """What a drawn segment stands for."""

    LINK = "link"                # a link drawn on the position plan (length)
    ABSOLUTE = "absolute"        # pole → image: absolute velocity / acceleration
    RELATIVE = "relative"        # image → image: relative velocity / total relative acceleration
    NORMAL = "normal"            # normal component ω²l
    TANGENTIAL = "tangential"    # tangential component εl
    CORIOLIS = "coriolis"        # Coriolis component 2ωv_rel
    SLIDING = "sliding"          # relative sliding velocity / acceleration along a guide
    DRIVE = "drive"              # the driving vector
    FORCE = "force"              # a known force laid head to tail on a force polygon
    REACTION = "reaction"        # a reaction read off a closed force polygon


@dataclass(frozen=True, slots=True)
class Segment:
    """A segment between two point-valued steps of one plan."""

    plan: Plan
    start: str          # step id
    end: str            # step id
    name: str           # as written on the plan: "pb", "bc", "π b′", "n_CB c′"
    quantity: str       # physical quantity: "v_B", "v_CB", "a^t_CB", "l_AB"
    kind: SegmentKind
    group: str = ""
