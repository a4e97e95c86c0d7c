"""Operations of the acceleration plan: the driving vector, normal and Coriolis components, ε."""

from __future__ import annotations

from ...geom.vec import Array, cross, dot, perp
from ..step import Op, Step
from .spec import Drawn, Grade, Line, OpSpec, Result, Written, scaled


def drive_acceleration(step: Step, pivot: Array, tip: Array) -> Result:
    """π b′: the crank's normal component −ω²·AB plus its tangential component ε × AB."""
    r = tip - pivot
    omega, eps = step.param("omega"), step.param("epsilon", 0.0)
    out = perp(r)                       # eps·perp(r) − ω²·r, in place: the same values
    out *= eps
    out -= omega * omega * r
    return out, None, None


def normal(step: Step, start: Array, omega: Array, p: Array, q: Array) -> Result:
    """From the image of P, ∥ QP towards P, of length ω²·l_PQ."""
    return start - scaled(omega * omega, q - p), None, None


def coriolis(step: Step, start: Array, omega: Array, v_from: Array, v_to: Array) -> Result:
    """Coriolis component 2ω × v_rel laid off from an image."""
    return start + scaled(2.0 * omega, perp(v_to - v_from)), None, None


def epsilon(step: Step, p: Array, q: Array, normal_end: Array, aq: Array) -> Result:
    """ε of the link pq from its tangential component: (pq × a^t) / |pq|²."""
    r = q - p
    out = cross(r, aq - normal_end)
    out /= dot(r, r)
    return out, None, None


def rigid_acceleration(step: Step, origin: Array, omega: Array, eps: Array, p_origin: Array,
                       p_point: Array) -> Result:
    """a_X = a_O + ε × OX − ω² OX."""
    r = p_point - p_origin
    return origin + scaled(eps, perp(r)) - scaled(omega * omega, r), None, None


SPECS = (
    OpSpec(Op.DRIVE_ACCELERATION, drive_acceleration, "protocol.op.drive_acceleration",
           Drawn.POINT, Line.OUTLINE, Grade.POINT, "hint.drive"),
    OpSpec(Op.NORMAL, normal, "protocol.op.normal", Drawn.POINT, Line.THIN, Grade.POINT,
           "hint.normal"),
    OpSpec(Op.CORIOLIS, coriolis, "protocol.op.coriolis", Drawn.POINT, Line.THIN, Grade.POINT),
    OpSpec(Op.EPSILON, epsilon, "protocol.op.epsilon", grade=Grade.VALUE, written=Written.RATE),
    OpSpec(Op.RIGID_ACCELERATION, rigid_acceleration, "protocol.op.rigid_acceleration",
           Drawn.POINT, Line.OUTLINE, Grade.POINT, written=Written.MEET),
)
