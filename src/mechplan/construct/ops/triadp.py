"""Operations of class III groups whose legs slide on known guides (``RRP-RRR`` and the like).

A slider leg (its outer pair prismatic on a guide of a known link, pinned to the base link at its
sliding point B_i) holds B_i on the guide's line; a leg with two revolute pairs holds it on the
arc (A_i, l_i). The base link's angle solves the group's closure (:mod:`.triadp_solve`), B_1 is
the meet of the first two loci with the base link at that angle. For Assur's special point a
slider leg's line is the normal to its guide through B_i (the unknown sliding velocity of B_i
is along the guide, as the unknown v_{B_iA_i} of a revolute leg is ⊥ A_iB_i).
"""

from __future__ import annotations

import numpy as np

from ...geom.vec import Array
from ..step import Step
from . import triadp_solve
from .spec import Drawn, Grade, Hint, HintView, Line, OpSpec, Result, Written, hint, line, measured
from .triadp_solve import Group


def params(step: Step) -> Group:
    """The group's dimensions and assembly as the step carries them."""
    d2, d3 = step.param("d2"), step.param("d3")
    lengths = step.param("l")
    q = step.param("q", (0.0, 0.0))
    return Group(str(step.param("kinds")), (float(lengths[0]), float(lengths[1]),
                                            float(lengths[2])),
                 (float(d2[0]), float(d2[1])), (float(d3[0]), float(d3[1])),
                 int(step.param("sigma")), int(step.param("slope", 1)),
                 float(step.param("theta_ref", 0.0)),
                 (float(q[0]), float(q[1])), float(step.param("q_angle", 0.0)))


def roots(one: Array, two: Array, three: Array, step: Step, sigma: int
          ) -> list[tuple[float, int]]:
    """Every root (θ, sign of f′) of branch ``sigma`` at the first position (the assembly)."""
    return triadp_solve.roots((one, two, three), params(step), sigma)


def triadp_angle(step: Step, one: Array, two: Array, three: Array) -> Result:
    """The base link's angle θ: the closure's root on the assembly's branch (each input a leg's
    locus: its outer point A_i for an arc, the guide's line through B_i for a slider leg). NaN
    with gap > 0 (least |f| over the turn) where the group does not close; sine: |f′|·(the loci's
    meet sine) over the group's size."""
    return triadp_solve.solve((one, two, three), params(step))


def triadp_point(step: Step, one: Array, two: Array, angle: Array) -> Result:
    """B_1: locus 1 meets locus 2 shifted back by the base link's R(θ)·d2 (branch ``sigma``)."""
    g = params(step)
    return triadp_solve.first_point((one, two, one), angle, g)


def normal_through(step: Step, point: Array, guide: Array) -> Result:
    """The line through a point ⊥ a guide's line (a slider leg's line for the special point)."""
    u = guide[..., 1, :]
    n = np.stack((-u[..., 1], u[..., 0]), axis=-1)
    return line(point, n), None, None


def leg_normal_force(step: Step, centre: Array, at: Array, angle: Array, total: Array) -> Result:
    """Force at ``at`` ⊥ the guide at ``angle`` whose moment about the centre is −total (a slider
    leg's reaction from the moments of the whole group about the special point); sine:
    |arm| / |at − centre|."""
    r = at - centre
    u = np.stack((-np.sin(angle), np.cos(angle)), axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        arm = r[..., 0] * u[..., 1] - r[..., 1] * u[..., 0]
        lam = -total / arm
        sine = np.abs(arm) / np.sqrt(r[..., 0] * r[..., 0] + r[..., 1] * r[..., 1])
    return lam[..., None] * u, None, sine


def triadp_point_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A point of the group: where the three legs' loci close it."""
    return measured(hint("rule.triadp_point", label=view.labels(step.id)))


TRIADP_ANGLE = OpSpec("triadp_angle", triadp_angle, "protocol.op.triadp_angle",
                      written=Written.ANGLE)
TRIADP_POINT = OpSpec("triadp_point", triadp_point, "protocol.op.triadp_point", Drawn.POINT,
                      Line.OUTLINE, Grade.POINT, hint_rule=triadp_point_hint)
NORMAL_THROUGH = OpSpec("normal_through", normal_through, "protocol.op.normal_through",
                        Drawn.CONSTRUCTION_LINE, Line.DASHED, Grade.DIRECTION, through="point")
LEG_NORMAL_FORCE = OpSpec("leg_normal_force", leg_normal_force, "protocol.op.leg_normal_force",
                          Drawn.VECTOR,
                          Line.OUTLINE, Grade.VALUE)

__all__ = ["LEG_NORMAL_FORCE", "NORMAL_THROUGH", "TRIADP_ANGLE", "TRIADP_POINT"]
