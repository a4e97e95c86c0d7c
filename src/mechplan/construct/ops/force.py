"""Operations of the force plan (kinetostatics): loads, polygons laid head to tail, moments.

Forces are vectors (N, 2) in N, couples and moments (N,) in N·m counter-clockwise positive,
polygon vertices are points of the force plan in N.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

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
    if mode == "along":
        u = unit(x["to"] - x["start"])
        c, s = math.cos(step.param("turn")), math.sin(step.param("turn"))
        turned = np.stack((c * u[..., 0] - s * u[..., 1], s * u[..., 0] + c * u[..., 1]), axis=-1)
        return float(step.param("magnitude")) * turned, None, None
    if mode == "pull":
        # tension T = t0 + k·(L − L0) pulls ``at`` towards ``other`` (T < 0 pushes it away)
        r = x["other"] - x["at"]
        tension = float(step.param("t0")) + float(step.param("k")) * (
            norm(r) - float(step.param("l0")))
        return tension[..., None] * unit(r), None, None
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
                  "along": ("at", "start", "to"), "pull": ("at", "other"),
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


# -- friction in the pairs ------------------------------------------------------------------------
@dataclass(eq=False)
class FrictionLoop:
    """What the friction iteration needs of its construction (held by the ``FRICTION_ITERATE``
    step): the construction, the reaction results whose magnitudes set the friction loads, the
    balancing moment's result, the tolerance and the bound on passes.
    """

    construction: object
    reactions: tuple[str, ...]
    balancing: str = "M_b"
    tolerance: float = 1e-10
    #: further drivers' balancing results (W = 2: ``M_b<link>`` or ``F_d<link>``), whose
    #: friction-free values are kept for :func:`friction_free`
    others: tuple[str, ...] = ()
    max_iterations: int = 50
    #: steps built on the friction loads (by the number of steps when found): the rest is
    #: evaluated once and kept for every next pass
    _downstream: tuple[int, frozenset[str]] = (-1, frozenset())

    def downstream(self, start: str) -> frozenset[str]:
        """The steps that depend on ``start`` (kinematics do not: they are kept between passes)."""
        c: Any = self.construction
        if self._downstream[0] != len(c.steps):
            found = {start}
            for sid, st in c.steps.items():
                if any(i in found for i in st.inputs):
                    found.add(sid)
            self._downstream = (len(c.steps), frozenset(found))
        return self._downstream[1]


def friction_iterate(step: Step, theta: Array, *, shared: dict[Any, Any]) -> Result:
    """Friction by the courses' iteration; the value is the friction-free balancing moment M_b⁰.

    Pass 0 has no friction (the friction loads are zero); each next pass takes the friction
    moments f·r·|R| and forces f·|N| from the reactions of the pass before, until the reactions
    change by less than ``tolerance`` of the largest one. The reactions' magnitudes (N, P), the
    passes made and the last relative change (N,) are left in ``shared`` for the friction steps.
    """
    loop: FrictionLoop = step.param("loop")
    c: Any = loop.construction          # a Construction (not imported: it imports the ops)
    phi = c.drive.scene(theta)
    n, p = theta.shape[0], len(loop.reactions)
    basis = np.zeros((n, p))
    residual = np.full(n, np.inf)
    mb0 = np.zeros(n)
    free: dict[str, Array] = {}
    passes = 0
    downstream = loop.downstream(step.id)
    kept: dict[str, Array] = {}
    kept_shared: dict[Any, Any] = {}
    for passes in range(1, loop.max_iterations + 1):
        inner = c.evaluate(phi, overrides={step.id: mb0})
        inner.values.update(kept)
        inner.shared.update(kept_shared)
        inner.shared[("friction", step.id)] = {"basis": basis}
        new = (np.stack([norm(inner[c.results[r]]) for r in loop.reactions], axis=-1)
               if p else basis)
        if passes == 1:
            mb0 = np.array(inner[c.results[loop.balancing]])
            free = {r: np.array(inner[c.results[r]]) for r in loop.others}
            kept = {k: v for k, v in inner.values.items() if k not in downstream}
            kept_shared = {k: v for k, v in inner.shared.items() if k[0] != "friction"}
        scale = np.maximum(np.max(new, axis=-1, initial=0.0), 1e-300)
        residual = np.max(np.abs(new - basis), axis=-1, initial=0.0) / scale
        basis = new
        if passes > 1 and not np.any(residual > loop.tolerance):
            break
    # a position where the passes did not settle (self-locking: the reactions grow without
    # bound) gets no friction loads at all: NaN, so nothing built on them passes for a result
    basis = np.where((residual <= loop.tolerance)[:, None], basis, np.nan)
    shared[("friction", step.id)] = {"basis": basis, "passes": passes, "residual": residual,
                                     "tolerance": loop.tolerance, "free": free}
    return mb0, None, None


def _basis(step: Step, shared: dict[Any, Any]) -> Array:
    """|R| of this pair from the pass before (zeros on the friction-free pass)."""
    out: Array = shared[("friction", step.input("loop"))]["basis"][:, step.param("index")]
    return out


def friction_couple(step: Step, loop: Array, *omegas: Array, shared: dict[Any, Any]) -> Result:
    """M_f = −ρ·|R|·sign(ω_j − ω_i) on link j of a revolute pair (ρ = f·r, the friction circle).

    Inputs after the loop: ω_j, then ω_i (absent when link i is the frame).
    """
    w_rel = omegas[0] - (omegas[1] if len(omegas) > 1 else 0.0)
    return -float(step.param("rho")) * _basis(step, shared) * _sense(step, w_rel), None, None


def _sense(step: Step, rel: Array) -> Array:
    """sign(rel), 0 where |rel| ≤ ``still`` (no relative motion: the sense of friction is
    undefined, its friction taken as zero — a rounding-level rate has no sign)."""
    still = float(step.param("still", 0.0))
    return np.where(np.abs(rel) <= still, 0.0, np.sign(rel))


def friction_force(step: Step, loop: Array, velocity: Array, angle: Array, *carrier: Array,
                   shared: dict[Any, Any]) -> Result:
    """F_f = −f·|N|·sign(v_rel·u)·u on a slider; v_rel = its point's velocity minus the velocity
    of the carrier's point under it (``carrier``: that image; absent for a frame guide)."""
    u = direction(angle)
    v_rel = velocity - carrier[0] if carrier else velocity
    sense = _sense(step, dot(v_rel, u))
    return (-float(step.param("f")) * _basis(step, shared) * sense)[..., None] * u, None, None


def friction_free(step: Step, loop: Array, *, shared: dict[Any, Any]) -> Result:
    """A further driver's balancing moment or driving force of the friction-free pass (W = 2:
    the second driver's M_b⁰ or F_d⁰), kept by the iteration (``result``: its result name)."""
    out: Array = shared[("friction", step.input("loop"))]["free"][step.param("result")]
    return out, None, None


FRICTION_ITERATE = OpSpec("friction_iterate", friction_iterate, "protocol.op.friction_iterate",
                          grade=Grade.VALUE)
FRICTION_COUPLE = OpSpec("friction_couple", friction_couple, "protocol.op.friction_couple",
                         grade=Grade.VALUE)
FRICTION_FORCE = OpSpec("friction_force", friction_force, "protocol.op.friction_force",
                        Drawn.VECTOR, Line.OUTLINE, Grade.VALUE)
FRICTION_FREE = OpSpec("friction_free", friction_free, "protocol.op.friction_free",
                       grade=Grade.VALUE)
__all__ += ["FRICTION_COUPLE", "FRICTION_FORCE", "FRICTION_FREE", "FRICTION_ITERATE"]
