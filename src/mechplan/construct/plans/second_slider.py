"""A second driver that is a slider on a frame guide (W = 2, ``[drive2] kind = "slider"``).

Its first-class mechanism I(0,k) is built as the first slider's (``plans/drivers.py``): its point
at s2 along the guide from the guide's ``through`` point (``GUIDE_POINT``), its velocity ṡ2 and
acceleration s̈2 laid along the guide from the pole (``GUIDE_VECTOR``). s2, ṡ2, s̈2 are the
second driver's steps ``pos.q2``, ``vel.rate2``, ``acc.rate2`` (its law, ``plans/second_crank.py``).
"""

from __future__ import annotations

from ...model.mechanism import GROUND
from ...model.plans import Plan
from ..builder import Builder, alabel, vlabel
from ..ops import Op
from ..step import Kind, Role
from ..terms import parallel
from . import images, position


def emit(b: Builder, plan: Plan, group: str) -> None:
    """The second slider's point (position plan) or its image (velocity, acceleration plan)."""
    drive = b.mech.drive2
    assert drive is not None and drive.guide is not None
    guide = b.mech.guides[drive.guide]
    x = drive.pivot
    if plan is Plan.POSITION:
        pair = next(p for p in b.mech.pairs_of(drive.link) if p.other(drive.link) == GROUND)
        b.pos[x] = b.add(f"pos.{x}", Op.GUIDE_POINT, (b.pos[guide.through], "pos.q2"), plan,
                         Kind.POINT, Role.RESULT, x, group, subject=(guide.through, x),
                         dir_angle=guide.angle)
        position.angle_from_pair(b, drive.link, pair, GROUND, group)
        b.bodies[drive.link].anchor = x
        position.complete(b, drive.link, group)
        return
    table = b.vel if plan is Plan.VELOCITY else b.acc
    prefix, what = ("vel", "v") if plan is Plan.VELOCITY else ("acc", "a")
    rate = f"{prefix}.rate2"
    label = vlabel(x) if plan is Plan.VELOCITY else alabel(x)
    table[x] = b.add(f"{prefix}.{x}", Op.GUIDE_VECTOR, (images.pole(plan), rate), plan,
                     Kind.POINT, Role.RESULT, label, group, subject=(guide.name, x),
                     dir_angle=guide.angle)
    images.link_scalar(b, drive.link, GROUND, plan, group)
    images.absolute(b, x, plan, group)
    b.c.equations[(plan, group)] = (f"{what}_{x} = {b.c[rate].label}",
                                    [(f"{what}_{x}", parallel(guide.name), b.c[rate].label)])
    images.complete(b, drive.link, plan, group)
