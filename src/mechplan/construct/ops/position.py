"""Operations of the position plan: frame points, the crank, compass arcs, guides, link points."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ...geom import meet
from ...geom.vec import Array, angle_of, direction, rotate
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
    line,
    measured,
    on_lines,
    to_complex,
    to_real,
)

if TYPE_CHECKING:
    from ..graph import Construction


def fixed_point(step: Step, n: int) -> Result:
    """A point of the frame: ``xy`` at every position."""
    xy = np.asarray(step.param("xy"), dtype=float)
    return np.tile(xy, (n, 1)), None, None


def constant(step: Step, n: int) -> Result:
    """A given scalar ``value`` (ω1, a guide angle)."""
    return np.full(n, float(step.param("value"))), None, None


def polar_point(step: Step, centre: Array, angle: Array) -> Result:
    """The crank pin: ``length`` from the centre at the angle (+ ``offset``)."""
    a = angle + step.param("offset", 0.0)
    if a.dtype != np.float64 or centre.dtype != np.float64:
        return centre + step.param("length") * direction(a), None, None
    # centre + length·(cos, sin), per component and in place: the same values
    length = float(step.param("length"))
    out = np.empty(np.broadcast_shapes(centre.shape[:-1], a.shape) + (2,))
    t = np.cos(a)
    t *= length
    np.add(centre[..., 0], t, out=out[..., 0])
    np.sin(a, out=t)
    t *= length
    np.add(centre[..., 1], t, out=out[..., 1])
    return out, None, None


def angle_of_segment(step: Step, start: Array, end: Array) -> Result:
    """Direction of the segment start → end, less ``minus``."""
    return angle_of(end - start) - step.param("minus", 0.0), None, None


def angle_plus(step: Step, angle: Array) -> Result:
    """An angle plus the constant ``delta`` (a slider turning with its guide)."""
    return angle + step.param("delta"), None, None


def circle_circle(step: Step, centre1: Array, centre2: Array) -> Result:
    """Two compass arcs of radii ``r1``, ``r2`` meet (branch ``sigma``)."""
    return meet.circle_circle(centre1, step.param("r1"), centre2, step.param("r2"),
                              step.param("sigma"))


def circle_line(step: Step, centre: Array, guide: Array) -> Result:
    """A compass arc of radius ``r`` cuts a guide line (branch ``sigma``)."""
    return meet.circle_line(centre, step.param("r"), guide[..., 0, :], guide[..., 1, :],
                            step.param("sigma"))


def line_line(step: Step, line1: Array, line2: Array) -> Result:
    """Two lines meet."""
    return meet.line_line(line1[..., 0, :], line1[..., 1, :], line2[..., 0, :], line2[..., 1, :])


def locus_line(step: Step, base: Array, *angle: Array) -> Result:
    """The line a point of a sliding link lies on: through base + ``offset`` at ``dir_angle``.

    Without an angle the guide belongs to the frame; with one it turns with its link.
    """
    offset = np.asarray(step.param("offset"), dtype=base.dtype)
    if not angle:
        # a guide of the frame: the same direction at every position; rotating by a zero angle
        # and taking cos/sin once give the values the per-position evaluation would
        zero = np.zeros(1, dtype=base.dtype)
        point = base + rotate(offset, zero)
        return line(point, direction(zero + step.param("dir_angle"))), None, None
    theta = angle[0]
    c, s = np.cos(theta), np.sin(theta)
    # rotate(offset, theta) with the cosine and sine computed once
    point = base + np.stack((c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]), axis=-1)
    dir_angle = step.param("dir_angle")
    u = np.stack((c, s), axis=-1) if dir_angle == 0.0 else direction(theta + dir_angle)
    return line(point, u), None, None


def carrier_angle(step: Step, pivot: Array, slider: Array) -> Result:
    """Angle of a guide carrier pivoting at ``pivot`` whose guide must pass through ``slider``."""
    rel = slider - pivot
    q0 = np.asarray(step.param("q0"), dtype=rel.dtype)
    d = direction(np.asarray(step.param("dir_angle"), dtype=rel.dtype))
    radius = np.sqrt(rel[..., 0] * rel[..., 0] + rel[..., 1] * rel[..., 1])
    # the circle's centre and the guide are the same at every position: pass them once, (1, 2),
    # and let numpy broadcast (same values as (N, 2) copies, without N-sized work on constants)
    origin = np.zeros((1, 2), dtype=rel.dtype)
    hit, gap, sine = meet.circle_line(origin, radius, q0[None, :], d[None, :], step.param("sigma"))
    return angle_of(rel) - angle_of(hit), gap, sine


def place(step: Step, origin: Array, angle: Array, *,
          shared: dict[tuple[str, ...], Array] | None = None) -> Result:
    """A point of a link: ``offset`` in link coordinates from the origin, turned by the angle
    (its cosine and sine computed once for every step that turns by it)."""
    ox, oy = np.asarray(step.param("offset"), dtype=origin.dtype)
    c, s = cos_sin(step.input("angle") if shared is not None else "", angle, shared)
    # origin + rotate(offset, angle), one component at a time in place (the same values, fewer
    # fresh arrays)
    out = np.empty(np.broadcast_shapes(origin.shape, np.shape(c) + (2,)), np.result_type(origin, c))
    x, y = out[..., 0], out[..., 1]
    np.multiply(c, ox, out=x)
    x -= s * oy
    x += origin[..., 0]
    np.multiply(s, ox, out=y)
    y += c * oy
    y += origin[..., 1]
    return out, None, None


def cos_sin(key: str, angle: Array, shared: dict[tuple[str, ...], Array] | None
            ) -> tuple[Array, Array]:
    """cos and sin of the angle the step ``key`` evaluated, kept in ``shared`` (one evaluation)
    for the other steps that turn by it."""
    name = ("cos_sin", key)
    if shared is not None and name in shared:
        c, s = shared[name]
        return c, s
    angle = np.asarray(angle)
    both = np.empty((2, *angle.shape), angle.dtype if angle.dtype.kind == "f" else float)
    np.cos(angle, out=both[0, ...])
    np.sin(angle, out=both[1, ...])
    if shared is not None:
        shared[name] = both
    return both[0], both[1]


def similar_position(step: Step, a: Array, b: Array) -> Result:
    """A point on the known side ab with the link's shape (complex ratio ``z``)."""
    za, zb = to_complex(a), to_complex(b)
    return to_real(za + (zb - za) * step.param("z")), None, None


# -- check rules ----------------------------------------------------------------------------------
def position_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A point of the position plan: where the lengths of the links put it."""
    return measured(hint("rule.position", label=view.labels(step.id)))


def line_line_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A meet of two lines: it must lie on both."""
    return measured(hint("rule.must_lie", label=view.labels(step.id),
                         parts=on_lines(step, view, at, tol_mm)))


def meet_hint(step: Step, c: Construction) -> Hint:
    """A wrong meet: which two lines it lies on."""
    return hint("hint.meet", label=step.label, a=c[step.input("line1")].label,
                b=c[step.input("line2")].label)


# -- the operations -------------------------------------------------------------------------------
CRANK_ANGLE = OpSpec("crank_angle", None, "protocol.op.crank_angle", source=Source.DRIVE,
                     written=Written.ANGLE)
FIXED_POINT = OpSpec("fixed_point", fixed_point, None, Drawn.POINT, grade=Grade.GIVEN,
                     source=Source.POSITIONS)
CONSTANT = OpSpec("constant", constant, "protocol.op.constant", source=Source.POSITIONS)
POLAR_POINT = OpSpec("polar_point", polar_point, "protocol.op.polar_point", Drawn.POINT,
                     Line.OUTLINE, Grade.POINT, hint_rule=position_hint)
ANGLE_OF = OpSpec("angle_of", angle_of_segment, "protocol.op.angle_of", written=Written.ANGLE,
                  lever=("start", "end"))
ANGLE_PLUS = OpSpec("angle_plus", angle_plus, "protocol.op.angle_plus", written=Written.ANGLE)
CIRCLE_CIRCLE = OpSpec("circle_circle", circle_circle, "protocol.op.circle_circle", Drawn.POINT,
                       Line.OUTLINE, Grade.POINT, hint_rule=position_hint)
CIRCLE_LINE = OpSpec("circle_line", circle_line, "protocol.op.circle_line", Drawn.POINT,
                     Line.OUTLINE, Grade.POINT, hint_rule=position_hint)
LINE_LINE = OpSpec("line_line", line_line, "protocol.op.line_line", Drawn.MEET, Line.NONE,
                   Grade.MEET, written=Written.MEET, hint=meet_hint, hint_rule=line_line_hint)
LOCUS_LINE = OpSpec("locus_line", locus_line, "protocol.op.locus_line", Drawn.CONSTRUCTION_LINE,
                    Line.DASHED, Grade.DIRECTION, through="base")
CARRIER_ANGLE = OpSpec("carrier_angle", carrier_angle, "protocol.op.carrier_angle",
                       written=Written.ANGLE, lever=("pivot", "slider"))
PLACE = OpSpec("place", place, "protocol.op.place", Drawn.POINT, Line.OUTLINE, Grade.POINT,
               hint_rule=position_hint)
SIMILAR_POSITION = OpSpec("similar_position", similar_position, "protocol.op.similar_position",
                          Drawn.POINT, Line.OUTLINE, Grade.POINT, hint_rule=position_hint)

__all__ = ["ANGLE_OF", "ANGLE_PLUS", "CARRIER_ANGLE", "CIRCLE_CIRCLE", "CIRCLE_LINE",
           "CONSTANT", "CRANK_ANGLE", "FIXED_POINT", "LINE_LINE", "LOCUS_LINE", "PLACE",
           "POLAR_POINT", "SIMILAR_POSITION"]
