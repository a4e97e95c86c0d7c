"""Operations of the force plan (kinetostatics): loads, polygons laid head to tail, moments.

Forces are vectors (N, 2) in N, couples and moments (N,) in N·m counter-clockwise positive,
polygon vertices are points of the force plan in N.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...geom import meet
from ...geom.vec import Array, cross, direction, dot, norm, perp, unit
from ..step import Step
from .spec import (
    Drawn,
    Grade,
    Hint,
    HintView,
    Line,
    OpSpec,
    Result,
    Written,
    hint,
    measured,
    on_lines,
    point_of,
)


def force_inertia(step: Step, a_centre: Array) -> Result:
    """Q = −m·a_S (``mass``)."""
    return -float(step.param("mass")) * a_centre, None, None


def moment_inertia(step: Step, eps: Array) -> Result:
    """M_q = −J_S·ε (``inertia``)."""
    return -float(step.param("inertia")) * eps, None, None


def _along_guide(value: Array, at: Array, towards: Array, angle: Array) -> Array:
    """A force of signed size ``value`` along the guide at ``angle``, in the sense at → towards."""
    u = direction(angle)
    sense = np.sign(dot(towards - at, u))
    out: Array = (value * sense)[..., None] * u
    return out


def force_load(step: Step, *operands: Array) -> Result:
    """A given force; ``mode`` says what it is and which operands it takes (in this order):

    ``vector`` (at): a constant vector; ``towards`` (at, target): ``magnitude`` towards a point;
    ``guide`` (at, towards, angle): ``value`` along a guide; ``table_phi`` (crank angle, at,
    towards, angle): a table against the crank angle; ``table_s`` (at, origin, towards, angle): a
    table against the displacement along the guide from its origin.
    """
    mode = step.param("mode")
    names = _LOAD_OPERANDS[mode]
    x = dict(zip(names, operands, strict=True))
    if mode == "vector":
        vec = np.asarray(step.param("vector"), dtype=float)
        return np.broadcast_to(vec, x["at"].shape).copy(), None, None
    if mode == "towards":
        return float(step.param("magnitude")) * unit(x["target"] - x["at"]), None, None
    if mode == "guide":
        value = np.full(x["at"].shape[:-1], float(step.param("value")))
    elif mode == "table_phi":
        xs, fs = np.asarray(step.param("xs")), np.asarray(step.param("fs"))
        phi = step.param("sense") * (x["crank"] - step.param("ref"))
        value = np.interp(xs[0] + np.mod(phi - xs[0], 2.0 * math.pi), xs, fs)
    else:
        xs, fs = np.asarray(step.param("xs")), np.asarray(step.param("fs"))
        value = np.interp(dot(x["at"] - x["origin"], direction(x["angle"])), xs, fs)
    return _along_guide(value, x["at"], x["towards"], x["angle"]), None, None


_LOAD_OPERANDS = {"vector": ("at",), "towards": ("at", "target"),
                  "guide": ("at", "towards", "angle"),
                  "table_phi": ("crank", "at", "towards", "angle"),
                  "table_s": ("at", "origin", "towards", "angle")}


def moment_sum(step: Step, centre: Array, *terms: Array) -> Result:
    """ΣM about the centre of known loads; ``layout`` lists them: ``F`` (point, force) or ``M``."""
    total = np.zeros(centre.shape[:-1])
    i = 0
    for kind in step.param("layout"):
        if kind == "F":
            total = total + cross(terms[i] - centre, terms[i + 1])
            i += 2
        else:
            total = total + terms[i]
            i += 1
    return total, None, None


def moment_arm_tangential(step: Step, centre: Array, at: Array, total: Array,
                          *angle: Array) -> Result:
    """Force at ``at`` ⊥ (at − centre), or ⊥ a guide, whose moment about centre is −total."""
    r = at - centre
    d = perp(direction(angle[0])) if angle else unit(perp(r))
    arm = cross(r, d)
    with np.errstate(invalid="ignore", divide="ignore"):
        lam = -total / arm
        sine = np.abs(arm) / norm(r) if angle else None
    return lam[..., None] * d, None, sine


def force_sum(step: Step, previous: Array, force: Array) -> Result:
    """Next vertex of a force polygon: the previous vertex plus the force."""
    return previous + force, None, None


def force_line(step: Step, through: Array, *direction_from: Array) -> Result:
    """Through a vertex, a line along a segment (two points) or an angle, turned by ``turn``."""
    if len(direction_from) == 2:
        u = unit(direction_from[1] - direction_from[0])
    else:
        u = direction(direction_from[0])
    if step.param("turn") == 90:
        u = perp(u)
    return np.stack((through, u), axis=-2), None, None


def force_close(step: Step, line1: Array, line2: Array) -> Result:
    """The two closing lines of a polygon meet."""
    return meet.line_line(line1[..., 0, :], line1[..., 1, :], line2[..., 0, :], line2[..., 1, :])


def negate(step: Step, value: Array) -> Result:
    """−value: R_ji = −R_ij, a guide's couple −ΣM, the balancing moment −ΣM_A."""
    return -value, None, None


def guide_offset(step: Step, origin: Array, at: Array, couple: Array, force: Array,
                 angle: Array) -> Result:
    """Where the line of action of a guide reaction with a couple crosses the guide."""
    u = direction(angle)
    with np.errstate(invalid="ignore", divide="ignore"):
        return dot(at - origin, u) + couple / cross(u, force), None, None


def line_of_action(step: Step, at: Array, force: Array, couple: Array) -> Result:
    """A point of the line of action of a force with a couple (the single equivalent force)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return at - (couple / dot(force, force))[..., None] * perp(force), None, None


def inertia_offset(step: Step, force: Array, couple: Array) -> Result:
    """h = M_q/|Q| of the single equivalent inertia force."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return couple / norm(force), None, None


def zhukovsky(step: Step, omega1: Array, *terms: Array) -> Result:
    """M_b from moments about the pole of forces at velocity images turned by +90°, couples M·ω.

    ``layout`` lists the terms: ``F`` (velocity image, force) or ``M`` (couple, ω of its link).
    """
    lever = np.zeros(omega1.shape)
    i = 0
    for kind in step.param("layout"):
        if kind == "F":
            lever = lever + cross(perp(terms[i]), terms[i + 1])
        else:
            lever = lever - terms[i] * terms[i + 1]
        i += 2
    return lever / omega1, None, None


@dataclass(frozen=True, slots=True)
class LeverTerm:
    """A term of Zhukovsky's lever: ``F`` (velocity image, force) or ``M`` (couple, ω)."""

    kind: str
    first: str
    second: str


def lever_terms(step: Step) -> list[LeverTerm]:
    """The terms of a ``ZHUKOVSKY`` step, read from its ``layout`` and its tail of inputs."""
    tail = step.rest()
    return [LeverTerm(kind, tail[2 * i], tail[2 * i + 1])
            for i, kind in enumerate(step.param("layout", ""))]


def difference(step: Step, start: Array, end: Array) -> Result:
    """The vector between two vertices (a reaction read off a closed polygon)."""
    return end - start, None, None


# -- check rules ----------------------------------------------------------------------------------
def force_sum_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The next vertex: the previous one plus the force, to scale (or the force left out)."""
    plan, lbl = step.plan, view.labels
    prev, force = step.input("previous"), step.input("force")
    exact_len = view.mm(plan, float(np.hypot(*point_of(view.exact(force)))))
    drawn = view.mm(plan, float(np.hypot(*(at - point_of(view.own(prev))))))
    name = view.c[force].label
    if drawn <= tol_mm < exact_len:
        return hint("rule.load_missing", name=name, prev=lbl(prev), len=exact_len)
    return measured(hint("rule.load_end", label=lbl(step.id), name=name, prev=lbl(prev),
                         len=exact_len))


def force_close_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The closing lines of a polygon: the vertex must lie on both."""
    return measured(hint("rule.closes", label=view.labels(step.id),
                         parts=on_lines(step, view, at, tol_mm)))


def direction_points(step: Step) -> tuple[str, str] | None:
    """The two points a ``FORCE_LINE``'s direction is taken from (None: from an angle)."""
    tail = step.rest()
    return (tail[0], tail[1]) if len(tail) == 2 else None


# -- the operations -------------------------------------------------------------------------------
FORCE_INERTIA = OpSpec("force_inertia", force_inertia, "protocol.op.force_inertia", Drawn.VECTOR,
                       Line.OUTLINE, Grade.VALUE)
MOMENT_INERTIA = OpSpec("moment_inertia", moment_inertia, "protocol.op.moment_inertia",
                        grade=Grade.VALUE)
INERTIA_OFFSET = OpSpec("inertia_offset", inertia_offset, "protocol.op.inertia_offset",
                        grade=Grade.VALUE, written=Written.OFFSET)
LINE_OF_ACTION = OpSpec("line_of_action", line_of_action, None)
FORCE_LOAD = OpSpec("force_load", force_load, "protocol.op.force_load", Drawn.VECTOR,
                    Line.OUTLINE)
MOMENT_SUM = OpSpec("moment_sum", moment_sum, "protocol.op.moment_sum", grade=Grade.VALUE)
MOMENT_ARM_TANGENTIAL = OpSpec("moment_arm_tangential", moment_arm_tangential,
                               "protocol.op.moment_arm_tangential", Drawn.VECTOR, Line.OUTLINE,
                               Grade.VALUE)
FORCE_SUM = OpSpec("force_sum", force_sum, "protocol.op.force_sum", Drawn.VERTEX, Line.THIN,
                   Grade.POINT, hint_rule=force_sum_hint)
FORCE_LINE = OpSpec("force_line", force_line, "protocol.op.force_line", Drawn.CONSTRUCTION_LINE,
                    Line.DASHED, Grade.DIRECTION, lever=direction_points, through="through")
FORCE_CLOSE = OpSpec("force_close", force_close, "protocol.op.force_close", Drawn.MEET,
                     Line.NONE, Grade.MEET, written=Written.MEET, hint_rule=force_close_hint)
DIFFERENCE = OpSpec("difference", difference, "protocol.op.difference", Drawn.VECTOR,
                    Line.OUTLINE, Grade.VALUE)
FORCE_REVERSE = OpSpec("force_reverse", negate, "protocol.op.force_reverse", Drawn.VECTOR,
                       Line.OUTLINE, Grade.VALUE)
MOMENT_CLOSE = OpSpec("moment_close", negate, "protocol.op.moment_close", grade=Grade.VALUE)
BALANCING_MOMENT = OpSpec("balancing_moment", negate, "protocol.op.balancing_moment",
                          grade=Grade.VALUE)
GUIDE_OFFSET = OpSpec("guide_offset", guide_offset, "protocol.op.guide_offset",
                      grade=Grade.VALUE, written=Written.OFFSET)
ZHUKOVSKY = OpSpec("zhukovsky", zhukovsky, "protocol.op.zhukovsky", Drawn.LEVER, Line.OUTLINE,
                   Grade.VALUE)

__all__ = ["BALANCING_MOMENT", "DIFFERENCE", "FORCE_CLOSE", "FORCE_INERTIA", "FORCE_LINE",
           "FORCE_LOAD", "FORCE_REVERSE", "FORCE_SUM", "GUIDE_OFFSET", "INERTIA_OFFSET",
           "LINE_OF_ACTION", "MOMENT_ARM_TANGENTIAL", "MOMENT_CLOSE", "MOMENT_INERTIA",
           "MOMENT_SUM", "ZHUKOVSKY"]
