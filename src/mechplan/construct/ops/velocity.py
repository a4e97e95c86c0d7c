"""Operations of the velocity plan (and the similarity image shared with the acceleration plan)."""

from __future__ import annotations

from typing import TYPE_CHECKING

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
    dist_to_line,
    drive_hint,
    hint,
    labelled,
    line,
    measured,
    point_of,
    rigid_hint,
    scaled,
    to_complex,
    to_real,
    unit,
)

if TYPE_CHECKING:
    from ..graph import Construction


def pole(step: Step, n: int) -> Result:
    """The pole p (or π): the zero vector."""
    return np.zeros((n, 2)), None, None


def drive_velocity(step: Step, pivot: Array, tip: Array, *omega: Array) -> Result:
    """pb ⊥ AB in the sense of ω: ``omega`` · (AB turned by 90°); ω of each position from the
    step after ``tip`` when the crank moves by a law by a table (``omega`` then its largest)."""
    if omega:
        return omega[0][:, None] * perp(tip - pivot), None, None
    return step.param("omega") * perp(tip - pivot), None, None


def line_perp(step: Step, through: Array, p: Array, q: Array, *,
              shared: dict[tuple[str, ...], Array] | None = None) -> Result:
    """Through an image, a line ⊥ the link segment pq (its unit normal computed once for the
    velocity and the acceleration plan)."""
    key = ("normal", step.input("p"), step.input("q"))
    u = None if shared is None else shared.get(key)
    if u is None:
        u = unit(perp(q - p))
        if shared is not None:
            shared[key] = u
    return line(through, u), None, None


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


def similar_image(step: Step, a: Array, b: Array, pa: Array, pb: Array, px: Array, *,
                  shared: dict[tuple[str, ...], Array] | None = None) -> Result:
    """Similarity theorem: image x on the images a, b, as X is on A, B of the position plan (the
    ratio of the triangle computed once for the velocity and the acceleration plan)."""
    za, zb = to_complex(a), to_complex(b)
    key = ("ratio", step.input("pa"), step.input("pb"), step.input("px"))
    ratio = None if shared is None else shared.get(key)
    if ratio is None:
        zpa = to_complex(pa)
        with np.errstate(invalid="ignore", divide="ignore"):
            ratio = (to_complex(px) - zpa) / (to_complex(pb) - zpa)
        if shared is not None:
            shared[key] = ratio
    return to_real(za + (zb - za) * ratio), None, None


def copy(step: Step, value: Array) -> Result:
    """A value taken over from another step (ω3 = ω2: the slider turns with its guide)."""
    return value, None, None


# -- check rules ----------------------------------------------------------------------------------
def pole_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The pole: the origin of the plan."""
    return hint("rule.pole", label=view.labels(step.id))


def drive_velocity_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """pb ⊥ AB, of length ω1·l_AB / μv."""
    return drive_hint(step, view, at, "rule.drive_v")


def similar_image_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The similarity theorem: x on a, b as X on A, B (on the line ab when A, B, X are in line)."""
    c, plan, lbl = view.c, step.plan, view.labels
    label = lbl(step.id)
    ia, ib = step.input("a"), step.input("b")
    pa, pb, px = step.input("pa"), step.input("pb"), step.input("px")
    a_l, b_l = lbl(ia), lbl(ib)
    A, B, X = c[pa].label, c[pb].label, c[px].label
    link = view.link_of(A, B, X)
    link_txt = hint("rule.of_link", link=link) if link else ""
    pts = [point_of(view.exact(s)) for s in (pa, pb, px)]
    cross_ = (pts[1] - pts[0])[0] * (pts[2] - pts[0])[1] - \
        (pts[1] - pts[0])[1] * (pts[2] - pts[0])[0]
    ab = float(np.hypot(*(pts[1] - pts[0])))
    oa, ob = point_of(view.own(ia)), point_of(view.own(ib))
    text = hint("rule.similar", label=label, link=link_txt, a=a_l, b=b_l, A=A, B=B, X=X)
    if ab and abs(cross_) <= 1e-9 * ab * ab:
        t = float(np.dot(pts[2] - pts[0], pts[1] - pts[0]) / ab ** 2)
        seg = ob - oa
        n2 = float(np.dot(seg, seg))
        if n2 > 0:
            line_value = np.array([oa, seg])
            d = view.mm(plan, dist_to_line(at, line_value))
            yours = float(np.dot(at - oa, seg) / n2)
            text = hint("rule.similar_line", link=link_txt, label=label, a=a_l, b=b_l, d=d,
                        A=A, B=B, X=X, t=t, yours=yours)
    return measured(text)


def omega_value_hint(step: Step, c: Construction) -> Hint:
    """A wrong ω: the relative velocity over the link's length."""
    p, q, vp, vq = (c[step.input(name)].label for name in ("p", "q", "vp", "vq"))
    return hint("hint.omega", label=step.label, p=p, q=q, a=vp, b=vq)


# -- the operations -------------------------------------------------------------------------------
POLE = OpSpec("pole", pole, "protocol.op.pole", Drawn.VERTEX, grade=Grade.ORIGIN,
              source=Source.POSITIONS, hint_rule=pole_hint)
DRIVE_VELOCITY = OpSpec("drive_velocity", drive_velocity, "protocol.op.drive_velocity",
                        Drawn.POINT, Line.OUTLINE, Grade.POINT, hint=labelled("hint.drive"),
                        hint_rule=drive_velocity_hint)
LINE_PERP = OpSpec("line_perp", line_perp, "protocol.op.line_perp", Drawn.CONSTRUCTION_LINE,
                   Line.DASHED, Grade.DIRECTION, lever=("p", "q"), through="through")
LINE_PARALLEL = OpSpec("line_parallel", line_parallel, "protocol.op.line_parallel",
                       Drawn.CONSTRUCTION_LINE, Line.DASHED, Grade.DIRECTION, through="through")
OMEGA = OpSpec("omega", omega, "protocol.op.omega", grade=Grade.RATE, written=Written.RATE,
               lever=("p", "q"), rate_of=("vp", "vq"), value_hint=omega_value_hint)
RIGID_VELOCITY = OpSpec("rigid_velocity", rigid_velocity, "protocol.op.rigid_velocity",
                        Drawn.POINT, Line.OUTLINE, Grade.POINT, written=Written.MEET,
                        hint_rule=rigid_hint)
SIMILAR_IMAGE = OpSpec("similar_image", similar_image, "protocol.op.similar_image",
                       Drawn.IMAGE_TRIANGLE, Line.THIN, Grade.POINT, written=Written.MEET,
                       lever=("pa", "pb"), hint=labelled("hint.similar"),
                       hint_rule=similar_image_hint)
COPY = OpSpec("copy", copy, "protocol.op.copy", grade=Grade.RATE)

__all__ = ["COPY", "DRIVE_VELOCITY", "LINE_PARALLEL", "LINE_PERP", "OMEGA", "POLE",
           "RIGID_VELOCITY", "SIMILAR_IMAGE"]
