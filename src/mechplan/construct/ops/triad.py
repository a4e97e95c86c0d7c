"""Operations of class III groups (triads): the base link's angle solved on the group's closure,
its first inner point, and the line of a leg on the position plan (for Assur's special point).

A triad RRR-RRR: legs i = 1, 2, 3 join known points A_i to the base link's points B_i
(|A_i B_i| = l_i). With the base link's angle θ, B_2 − B_1 = R(θ)·d2 and B_3 − B_1 = R(θ)·d3 (d2,
d3 in the base link's frame), so B_1 is where the arc (A_1, l_1) meets the arc (A_2 − R(θ)·d2, l_2)
(branch ``sigma``), and the closure is f(θ) = |B_1 − (A_3 − R(θ)·d3)| − l_3 = 0. It has up to six
roots; the assembly is the root of branch ``sigma`` where f crosses zero with the sign ``slope``,
nearest (circularly) to the angle ``theta_ref`` of the assembly position — a rule that needs no
neighbouring position, so any position is evaluated alone.
"""

from __future__ import annotations

import numpy as np

from ...geom import meet
from ...geom.vec import Array
from ..step import Step
from . import triad_solve
from .position import cos_sin
from .spec import Drawn, Grade, Hint, HintView, Line, OpSpec, Result, Written, hint, measured
from .triad_solve import Triad


def params(step: Step) -> Triad:
    """The group's dimensions and assembly as the step carries them."""
    d2, d3 = step.param("d2"), step.param("d3")
    return Triad(float(step.param("l1")), float(step.param("l2")), float(step.param("l3")),
                 (float(d2[0]), float(d2[1])), (float(d3[0]), float(d3[1])),
                 int(step.param("sigma")), int(step.param("slope", 1)),
                 float(step.param("theta_ref", 0.0)))


def roots(a1: Array, a2: Array, a3: Array, step: Step, sigma: int) -> list[tuple[float, int]]:
    """Every root (θ, sign of f′) of branch ``sigma`` at the first position (assembly)."""
    return triad_solve.roots(a1, a2, a3, params(step), sigma)


def triad_angle(step: Step, a1: Array, a2: Array, a3: Array) -> Result:
    """The base link's angle θ: the root of the closure f(θ) on the assembly's branch
    (:func:`triad_solve.solve`: bracketed on a grid centred on the assembly's angle, refined by a
    safeguarded Newton iteration, vectorised over positions). NaN with gap > 0 (min |f| over the
    branch) where the group does not close; the sine is |f′|·(the arcs' sine) over the group's
    size (0: the triad's Jacobian is singular)."""
    return triad_solve.solve(a1, a2, a3, params(step))


def triad_point(step: Step, a1: Array, a2: Array, angle: Array, *,
                shared: dict[tuple[str, ...], Array] | None = None) -> Result:
    """B_1: the arc (A_1, l_1) meets the arc (A_2 − R(θ)·d2, l_2), branch ``sigma``;
    ``triad_solve.BLOCK`` positions at a time (each alone: the same values), so that the
    temporaries stay in the cache and in memory already mapped; cos θ and sin θ computed once
    for every step that turns by θ."""
    t = params(step)
    c, s = cos_sin(step.input("angle") if shared is not None else "", angle, shared)
    n = angle.shape[0] if angle.ndim == 1 else 0
    if n <= triad_solve.BLOCK or a1.shape != (n, 2) or a2.shape != (n, 2):
        return _triad_point(t, a1, a2, c, s)
    point = np.empty((n, 2), np.result_type(a1, a2, angle))
    gap, sine = np.empty(n, point.dtype), np.empty(n, point.dtype)
    for i in range(0, n, triad_solve.BLOCK):
        part = slice(i, i + triad_solve.BLOCK)
        point[part], gap[part], sine[part] = _triad_point(t, a1[part], a2[part], c[part],
                                                          s[part])
    return point, gap, sine


def _triad_point(t: Triad, a1: Array, a2: Array, c: Array, s: Array
                 ) -> tuple[Array, Array, Array]:
    """:func:`triad_point` at once, from cos θ and sin θ."""
    d2 = t.d2
    centre = np.empty(np.broadcast_shapes(a2.shape, np.shape(c) + (2,)), np.result_type(a2, c))
    x, y = centre[..., 0], centre[..., 1]                 # component-wise, in place
    np.multiply(c, d2[0], out=x)
    x -= s * d2[1]
    np.subtract(a2[..., 0], x, out=x)                      # a2x − (c·d2x − s·d2y)
    np.multiply(s, d2[0], out=y)
    y += c * d2[1]
    np.subtract(a2[..., 1], y, out=y)                      # a2y − (s·d2x + c·d2y)
    return meet.circle_circle(a1, t.l1, centre, t.l2, t.sigma)


def line_through(step: Step, p: Array, q: Array) -> Result:
    """The line of a leg on the position plan: through P and Q."""
    out = np.empty(np.broadcast_shapes(p.shape, q.shape)[:-1] + (2, 2), np.result_type(p, q))
    out[..., 0, 0], out[..., 0, 1] = p[..., 0], p[..., 1]
    dx, dy = out[..., 1, 0], out[..., 1, 1]               # the direction, in place: fewer fresh
    np.subtract(q[..., 0], p[..., 0], out=dx)              # arrays (each one's pages are touched
    np.subtract(q[..., 1], p[..., 1], out=dy)              # for the first time in one run)
    n = dx * dx
    n += dy * dy
    np.sqrt(n, out=n)
    with np.errstate(invalid="ignore", divide="ignore"):
        dx /= n
        dy /= n
    return out, None, None


def moment_along(step: Step, centre: Array, at: Array, toward: Array, total: Array) -> Result:
    """Force at ``at`` along (toward − at) whose moment about the centre is −total (a leg's R^n
    from the moments of the whole triad about its special point); sine: |arm| / |at − centre|."""
    r = at - centre
    u = toward - at
    n = np.sqrt(u[..., 0] * u[..., 0] + u[..., 1] * u[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        u = u / n[..., None]
        arm = r[..., 0] * u[..., 1] - r[..., 1] * u[..., 0]
        lam = -total / arm
        sine = np.abs(arm) / np.sqrt(r[..., 0] * r[..., 0] + r[..., 1] * r[..., 1])
    return lam[..., None] * u, None, sine


# -- check rules ----------------------------------------------------------------------------------
def triad_point_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A point of a triad: where the three legs close the group."""
    return measured(hint("rule.triad_point", label=view.labels(step.id)))


# -- the operations -------------------------------------------------------------------------------
TRIAD_ANGLE = OpSpec("triad_angle", triad_angle, "protocol.op.triad_angle",
                     written=Written.ANGLE)
TRIAD_POINT = OpSpec("triad_point", triad_point, "protocol.op.triad_point", Drawn.POINT,
                     Line.OUTLINE, Grade.POINT, hint_rule=triad_point_hint)
LINE_THROUGH = OpSpec("line_through", line_through, "protocol.op.line_through",
                      Drawn.CONSTRUCTION_LINE, Line.DASHED, Grade.DIRECTION, lever=("p", "q"),
                      through="p")

MOMENT_ALONG = OpSpec("moment_along", moment_along, "protocol.op.moment_along", Drawn.VECTOR,
                      Line.OUTLINE, Grade.VALUE)

__all__ = ["LINE_THROUGH", "MOMENT_ALONG", "TRIAD_ANGLE", "TRIAD_POINT"]
