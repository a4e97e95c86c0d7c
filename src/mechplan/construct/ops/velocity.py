"""Operations of the velocity plan (and the similarity image shared with the acceleration plan)."""

from __future__ import annotations

import numpy as np

from ...geom.vec import Array, cross, dot, perp
from ..step import Op, Step
from .spec import (
    Drawn,
    Grade,
    Line,
    OpSpec,
    Result,
    Source,
    Written,
    line,
    scaled,
    to_complex,
    to_real,
    unit,
)


def pole(step: Step, n: int) -> Result:
    """The pole p (or π): the zero vector."""
    return np.zeros((n, 2)), None, None


def drive_velocity(step: Step, pivot: Array, tip: Array) -> Result:
    """pb ⊥ AB in the sense of ω: ``omega`` · (AB turned by 90°)."""
    return step.param("omega") * perp(tip - pivot), None, None


def line_perp(step: Step, through: Array, p: Array, q: Array) -> Result:
    """Through an image, a line ⊥ the link segment pq."""
    return line(through, unit(perp(q - p))), None, None


def line_parallel(step: Step, through: Array, guide: Array) -> Result:
    """Through an image, a line ∥ a guide."""
    return line(through, guide[..., 1, :]), None, None


def omega(step: Step, p: Array, q: Array, vp: Array, vq: Array) -> Result:
    """ω of the link pq from the velocities of its two points: (pq × v_qp) / |pq|²."""
    r = q - p
    out = cross(r, vq - vp)
    out /= dot(r, r)
    return out, None, None


def rigid_velocity(
    step: Step, origin: Array, omega: Array, p_origin: Array, p_point: Array
) -> Result:
    """v_X = v_O + ω × OX."""
    return origin + scaled(omega, perp(p_point - p_origin)), None, None


def similar_image(step: Step, a: Array, b: Array, pa: Array, pb: Array, px: Array) -> Result:
    """Similarity theorem: image x on the images a, b, as X is on A, B of the position plan."""
    za, zb = to_complex(a), to_complex(b)
    zpa = to_complex(pa)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = (to_complex(px) - zpa) / (to_complex(pb) - zpa)
    return to_real(za + (zb - za) * ratio), None, None


def copy(step: Step, value: Array) -> Result:
    """A value taken over from another step (ω3 = ω2: the slider turns with its guide)."""
    return value, None, None


SPECS = (
    OpSpec(Op.POLE, pole, "protocol.op.pole", Drawn.VERTEX, source=Source.POSITIONS),
    OpSpec(Op.DRIVE_VELOCITY, drive_velocity, "protocol.op.drive_velocity", Drawn.POINT,
           Line.OUTLINE, Grade.POINT, "hint.drive"),
    OpSpec(Op.LINE_PERP, line_perp, "protocol.op.line_perp", Drawn.CONSTRUCTION_LINE,
           Line.DASHED, Grade.DIRECTION),
    OpSpec(Op.LINE_PARALLEL, line_parallel, "protocol.op.line_parallel", Drawn.CONSTRUCTION_LINE,
           Line.DASHED, Grade.DIRECTION),
    OpSpec(Op.OMEGA, omega, "protocol.op.omega", grade=Grade.VALUE, written=Written.RATE),
    OpSpec(Op.RIGID_VELOCITY, rigid_velocity, "protocol.op.rigid_velocity", Drawn.POINT,
           Line.OUTLINE, Grade.POINT, written=Written.MEET),
    OpSpec(Op.SIMILAR_IMAGE, similar_image, "protocol.op.similar_image", Drawn.IMAGE_TRIANGLE,
           Line.THIN, Grade.POINT, "hint.similar", written=Written.MEET),
    OpSpec(Op.COPY, copy, "protocol.op.copy", grade=Grade.VALUE),
)
