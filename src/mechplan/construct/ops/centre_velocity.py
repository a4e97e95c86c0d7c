"""Operations of the velocities found by instant centres, drawn as the courses draw them.

The *line of centres* method (Khurmi & Gupta ch. 6, Rattan): links m and j have the common centre
I_mj and the fixed centres I_0m, I_0j, all three on one line. A point A of link m with a known
velocity is carried by an arc about I_0m to that line (A′, its velocity turned with it: the same
speed at the same radius, at right angles to the line); the ray from I_0m through the tip of v_A′
meets the perpendicular at I_mj in the tip of v_Imj (similar triangles); I_mj is a point of both
links, so the ray from I_0j through that tip gives, at a point B′ of link j carried to the line by
an arc about I_0j, v_B′ — turned back to B it is v_B. The *instant centre of velocities* way
(МЦС, tâm vận tốc tức thời): ω_j = v_B / P B with P = I_0j, then v_X = ω_j · P X at right angles
to P X for every other point X of the link.

Centres are homogeneous ``(x/L, y/L, w)`` values (``ops/centres.py``; ``length`` L is a step
parameter). Where a link's absolute centre is at infinity at a position the link translates
there: every point has the velocity of the known point (ω = 0), the same rule a student applies.
These operations join the registry (``ops.FAMILIES``) but not the plans' DAG: they make a
construction of their own (``construct/plans/centre_velocity.py``), evaluated on the positions
and centres of a solved mechanism.
"""

from __future__ import annotations

import numpy as np

from ...geom.vec import Array, cross, dot, perp
from ..step import Step
from .spec import (
    Drawn,
    Grade,
    Hint,
    HintView,
    Line,
    OpSpec,
    Result,
    Source,
    Written,
    hint,
    measured,
)


def _finite(h: Array) -> Array:
    out: Array = np.asarray(h)[:, 2] != 0.0
    return out


def _xy(h: Array, length: float) -> Array:
    """The point of a finite homogeneous centre (m); NaN where it is at infinity."""
    with np.errstate(invalid="ignore", divide="ignore"):
        out: Array = h[:, :2] * length / h[:, 2:3]
    out[~_finite(h)] = np.nan
    return out


def _rate(c: Array, x: Array, v: Array) -> Array:
    """ω of a link turning about c from one of its points x and its velocity v (0 for a point
    at the centre itself: a point carried there has radius 0 and no velocity to carry)."""
    r = x - c
    rr = dot(r, r)
    with np.errstate(invalid="ignore", divide="ignore"):
        out: Array = np.where(rr == 0.0, 0.0, cross(r, v) / rr)
    return out


def given(step: Step, n: int) -> Result:
    """A value taken from the solved mechanism (always given by an override): NaN otherwise."""
    width = int(step.param("width", 2))
    return np.full((n, width) if width else (n,), np.nan), None, None


def origin(step: Step, n: int) -> Result:
    """The foot of the velocity vectors as measured values: the zero vector."""
    return np.zeros((n, 2)), None, None


def drive_velocity(step: Step, centre: Array, point: Array, omega: Array) -> Result:
    """v of a point of the driving link: ω1 · I01X, at right angles to I01X."""
    c = _xy(centre, step.param("length"))
    return np.asarray(omega)[:, None] * perp(point - c), None, None


def carry(step: Step, centre: Array, point: Array, toward: Array) -> Result:
    """The point carried by an arc about the centre to the line of centres (the ray from the
    centre to ``toward``): c + |X − c| · unit(T − c); NaN where the centre is at infinity."""
    length = step.param("length")
    c, t = _xy(centre, length), _xy(toward, length)
    d = t - c
    with np.errstate(invalid="ignore", divide="ignore"):
        u = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    r = np.hypot(*(point - c).T)
    return c + r[:, None] * u, None, None


def turned(step: Step, centre: Array, source: Array, v_source: Array, target: Array) -> Result:
    """v at ``target`` of the link turning about the centre, from ``source`` and its velocity:
    ω·perp(target − c) with ω = (source − c) × v / |source − c|² — at the same radius the arc's
    turn, along a ray the similar triangles; v_source where the centre is at infinity (the link
    translates)."""
    length = step.param("length")
    c = _xy(centre, length)
    w = _rate(c, source, v_source)
    out: Array = w[:, None] * perp(target - c)
    fin = _finite(centre)
    out[~fin] = v_source[~fin]
    return out, None, None


def arc_velocity(step: Step, centre: Array, source: Array, v_source: Array,
                 target: Array) -> Result:
    """The velocity carried with the point along its arc about the centre (same speed, at right
    angles to the new radius)."""
    return turned(step, centre, source, v_source, target)


def similar_velocity(step: Step, centre: Array, source: Array, v_source: Array,
                     target: Array) -> Result:
    """Similar triangles on the line of centres: the ray from the centre through the tip of
    v_source meets the perpendicular at ``target`` in the tip of v_target."""
    return turned(step, centre, source, v_source, target)


def pole_omega(step: Step, centre: Array, point: Array, v_point: Array) -> Result:
    """ω of a link from its instant centre P (МЦС): v_X / P X, signed (0 where P is at
    infinity: the link translates)."""
    c = _xy(centre, step.param("length"))
    w = _rate(c, point, v_point)
    w[np.all(point == c, axis=1)] = np.nan     # the point is the centre: ω is not found by it
    w[~_finite(centre)] = 0.0
    return w, None, None


def pole_velocity(step: Step, centre: Array, omega: Array, point: Array, v_ref: Array) -> Result:
    """v_X = ω · P X at right angles to P X (МЦС); where P is at infinity the link translates
    and every point moves with v_ref."""
    c = _xy(centre, step.param("length"))
    out: Array = np.asarray(omega)[:, None] * perp(point - c)
    fin = _finite(centre)
    out[~fin] = v_ref[~fin]
    return out, None, None


def same_omega(step: Step, omega: Array) -> Result:
    """ω_j = ω_m: links m and j translate relative to each other (their centre is at infinity)."""
    return np.array(omega, dtype=float), None, None


# -- check rules ----------------------------------------------------------------------------------
def radius_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A velocity of a turning link: at right angles to the radius from its centre, its length
    proportional to the radius."""
    return measured(hint("rule.ic_radius", label=view.labels(step.id)))


def line_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """Similar triangles on the line of centres."""
    return measured(hint("rule.ic_line", label=view.labels(step.id)))


# -- the operations -------------------------------------------------------------------------------
IC_GIVEN = OpSpec("ic_given", given, None, source=Source.POSITIONS)
IC_ORIGIN = OpSpec("ic_origin", origin, None, source=Source.POSITIONS)
IC_DRIVE_VELOCITY = OpSpec("ic_drive_velocity", drive_velocity, "protocol.op.ic_drive_velocity",
                           Drawn.POINT, Line.OUTLINE, Grade.POINT, written=Written.MEET,
                           hint_rule=radius_hint)
IC_CARRY = OpSpec("ic_carry", carry, "protocol.op.ic_carry", Drawn.POINT, Line.THIN,
                  Grade.POINT, lever=("centre", "toward"))
IC_ARC_VELOCITY = OpSpec("ic_arc_velocity", arc_velocity, "protocol.op.ic_arc_velocity",
                         Drawn.POINT, Line.OUTLINE, Grade.POINT, written=Written.MEET,
                         hint_rule=radius_hint)
IC_SIMILAR_VELOCITY = OpSpec("ic_similar_velocity", similar_velocity,
                             "protocol.op.ic_similar_velocity", Drawn.MEET, Line.THIN,
                             Grade.POINT, written=Written.MEET, lever=("centre", "source"),
                             hint_rule=line_hint)
IC_POLE_OMEGA = OpSpec("ic_pole_omega", pole_omega, "protocol.op.ic_pole_omega",
                       grade=Grade.VALUE, written=Written.RATE, lever=("centre", "point"))
IC_POLE_VELOCITY = OpSpec("ic_pole_velocity", pole_velocity, "protocol.op.ic_pole_velocity",
                          Drawn.POINT, Line.OUTLINE, Grade.POINT, written=Written.MEET,
                          hint_rule=radius_hint)
IC_SAME_OMEGA = OpSpec("ic_same_omega", same_omega, "protocol.op.ic_same_omega",
                       grade=Grade.VALUE, written=Written.RATE)

__all__ = ["IC_ARC_VELOCITY", "IC_CARRY", "IC_DRIVE_VELOCITY", "IC_GIVEN", "IC_ORIGIN",
           "IC_POLE_OMEGA", "IC_POLE_VELOCITY", "IC_SAME_OMEGA", "IC_SIMILAR_VELOCITY"]
