"""A crank or rocker moving by a law by a table over time (``[drive] law``, ``[drive2] law``).

Its ω and ε at a position are steps of their own (``CRANK_LAW``: the table's spline at the
position's time, written with their sense), inputs of the driving vectors p b (ω × AB) and π b′
(−ω²·AB + ε × AB) instead of the constant speed; every later step is built on them as usual.
The time of a position is the first driver's table inverted (or its constant-rate law), as for
the linear drivers' tables (``plans/laws.py``); a second crank's angle then comes from its own
table at that time.
"""

from __future__ import annotations

from ...model.law import largest
from ...model.mechanism import Drive
from ...model.plans import Plan
from ..builder import Builder
from ..ops import Op
from ..step import Kind, Role
from .laws import clock, first_step, motion


def _law_step(b: Builder, sid: str, drive: Drive, order: int, plan: Plan, label: str,
              group: str) -> str:
    return b.add(sid, Op.CRANK_LAW, (first_step(b),), plan, Kind.SCALAR, Role.GIVEN, label,
                 group, subject=(b.mech.drive.link, drive.link), order=order,
                 **clock(b.mech.drive), **motion(drive, order))


def angle(b: Builder, drive: Drive, group: str) -> str | None:
    """A second crank's direction θ2 at the position's time when a driver's law is a table
    (None: the affine law of constant rates, ``SECOND_CRANK_ANGLE``)."""
    if not any(d.law is not None for d in b.mech.drivers):
        return None
    if drive.law is not None:
        return _law_step(b, f"pos.phi.{drive.link}", drive, 0, Plan.POSITION,
                         f"θ{drive.link}", group)
    # at constant speed after a first driver by a table: θ2 = ref2 + s2·(phase + |ω2|·t)
    return b.add(f"pos.phi.{drive.link}", Op.CRANK_LAW, (first_step(b),), Plan.POSITION,
                 Kind.SCALAR, Role.GIVEN, f"θ{drive.link}", group,
                 subject=(b.mech.drive.link, drive.link), order=0, **clock(b.mech.drive),
                 q0=drive.ref_angle + drive.sense * drive.phase, rate=drive.omega,
                 acceleration=drive.epsilon, size=0.0)


def rate(b: Builder, drive: Drive, plan: Plan, group: str) -> str | None:
    """The crank's ω (velocity plan) or ε (acceleration plan) by its table (None: constant)."""
    if drive.law is None:
        return None
    if plan is Plan.VELOCITY:
        return _law_step(b, f"vel.omega.{drive.link}", drive, 1, plan, f"ω{drive.link}", group)
    return _law_step(b, f"acc.epsilon.{drive.link}", drive, 2, plan, f"ε{drive.link}", group)


def sizes(drive: Drive) -> tuple[float, float]:
    """(largest |ω|, largest |ε|) over the table: the driving vectors' parameters that size the
    plans (``estimate.plan_sizes``)."""
    assert drive.law is not None
    return largest(drive.law, 1), largest(drive.law, 2)
