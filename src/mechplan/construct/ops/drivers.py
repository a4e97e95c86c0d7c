"""Operations of the linear drivers: a cylinder of driven length, a slider driven on its guide.

The driver's coordinate q (a length) is the construction's independent variable; its rate and
acceleration are given (``DRIVER_RATE``). A cylinder is a link of known length: with the link it
drives it forms a triangle built by two compass arcs (``CIRCLE_CIRCLE_DRIVEN``); on the velocity
and acceleration plans the rod's motion in the barrel is a known vector along the cylinder
(``SLIDE_VECTOR``: l̇ on the velocity plan, l̈ on the acceleration plan, after the normal and
Coriolis components). A slider's point moves along its frame guide by q (``GUIDE_POINT``), its
velocity and acceleration are q̇ and q̈ along the guide (``GUIDE_VECTOR``).
"""

from __future__ import annotations

import numpy as np

from ...geom import meet
from ...geom.vec import Array, direction
from ..step import Step
from .position import position_hint
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
    point_of,
    scaled,
    unit,
)


def driver_rate(step: Step, n: int) -> Result:
    """A given rate of the driver's coordinate (``value``: l̇, l̈ or ṡ, s̈) at every position."""
    return np.full(n, float(step.param("value"))), None, None


def circle_circle_driven(step: Step, centre1: Array, centre2: Array, radius2: Array) -> Result:
    """An arc of radius ``r1`` about centre1 and an arc of the driven length about centre2 meet.

    Its conditioning is the crossing's sine squared: near the cylinder's stretched or folded
    position the triangle's height h, which every rate of the group is divided by, carries a
    relative error ~ u/sine² (the cancellation in d² − (r1 − r2)²), and the estimates of the
    rates must cover it (found against a 60-digit reference: with the sine alone they did not).
    """
    point, gap, sine = meet.circle_circle(centre1, step.param("r1"), centre2, radius2,
                                          step.param("sigma"))
    return point, gap, sine * sine


def guide_point(step: Step, base: Array, coordinate: Array) -> Result:
    """The slider's point: ``coordinate`` along the frame guide at ``dir_angle`` from ``base``."""
    u = direction(np.asarray(step.param("dir_angle"), dtype=base.dtype))
    return base + scaled(coordinate, np.broadcast_to(u, base.shape)), None, None


def guide_vector(step: Step, start: Array, rate: Array) -> Result:
    """From an image, the driver's rate along its frame guide (``dir_angle``)."""
    u = direction(np.asarray(step.param("dir_angle"), dtype=start.dtype))
    return start + scaled(rate, np.broadcast_to(u, start.shape)), None, None


def slide_vector(step: Step, start: Array, rate: Array, p: Array, q: Array) -> Result:
    """From an image, the rod's rate in the barrel along the cylinder, from its end p towards q."""
    return start + scaled(rate, unit(q - p)), None, None


def _axis(step: Step, axis: tuple[Array, ...], like: Array) -> Array:
    """The driver's axis: unit(q − p) of two points, or the frame guide's ``dir_angle``."""
    if axis:
        return unit(axis[1] - axis[0])
    u = direction(np.asarray(step.param("dir_angle"), dtype=like.dtype))
    return np.broadcast_to(u, like.shape)


def driving_force(step: Step, force: Array, *axis: Array) -> Result:
    """The driving force: the component of the pair's whole force along the driver's axis (N)."""
    u = _axis(step, axis, force)
    return force[..., 0] * u[..., 0] + force[..., 1] * u[..., 1], None, None


def normal_force(step: Step, force: Array, *axis: Array) -> Result:
    """The pair's reaction: its whole force less the driving force along the axis (⊥ the axis)."""
    u = _axis(step, axis, force)
    along = force[..., 0] * u[..., 0] + force[..., 1] * u[..., 1]
    return force - scaled(along, u), None, None


# -- check rules ----------------------------------------------------------------------------------
def slide_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The rod's motion in the barrel: ∥ the cylinder, of the length its law gives."""
    c = view.c
    start = step.input("start")
    length = view.mm(step.plan, float(np.hypot(*(point_of(view.exact(step.id))
                                                 - point_of(view.exact(start))))))
    return measured(hint("rule.driver_slide", label=view.labels(step.id),
                         start=view.labels(start), P=c[step.input("p")].label,
                         Q=c[step.input("q")].label, len=length))


def guide_vector_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The slider's velocity or acceleration: ∥ its guide, of the length its law gives."""
    start = step.input("start")
    length = view.mm(step.plan, float(np.hypot(*(point_of(view.exact(step.id))
                                                 - point_of(view.exact(start))))))
    return measured(hint("rule.driver_guide", label=view.labels(step.id),
                         start=view.labels(start), len=length))


# -- the operations -------------------------------------------------------------------------------
DRIVER_COORDINATE = OpSpec("driver_coordinate", None, "protocol.op.driver_coordinate",
                           source=Source.DRIVE, written=Written.LINEAR)
DRIVER_RATE = OpSpec("driver_rate", driver_rate, "protocol.op.driver_rate",
                     source=Source.POSITIONS, written=Written.LINEAR)
CIRCLE_CIRCLE_DRIVEN = OpSpec("circle_circle_driven", circle_circle_driven,
                              "protocol.op.circle_circle_driven", Drawn.POINT, Line.OUTLINE,
                              Grade.POINT, hint_rule=position_hint)
GUIDE_POINT = OpSpec("guide_point", guide_point, "protocol.op.guide_point", Drawn.POINT,
                     Line.OUTLINE, Grade.POINT, hint_rule=position_hint)
GUIDE_VECTOR = OpSpec("guide_vector", guide_vector, "protocol.op.guide_vector", Drawn.POINT,
                      Line.OUTLINE, Grade.POINT, hint_rule=guide_vector_hint)
SLIDE_VECTOR = OpSpec("slide_vector", slide_vector, "protocol.op.slide_vector", Drawn.POINT,
                      Line.THIN, Grade.POINT, lever=("p", "q"), hint_rule=slide_hint)

DRIVING_FORCE = OpSpec("driving_force", driving_force, "protocol.op.driving_force",
                       grade=Grade.VALUE, written=Written.LINEAR)
NORMAL_FORCE = OpSpec("normal_force", normal_force, "protocol.op.normal_force", Drawn.VECTOR,
                      Line.OUTLINE)

__all__ = ["CIRCLE_CIRCLE_DRIVEN", "DRIVER_COORDINATE", "DRIVER_RATE", "DRIVING_FORCE",
           "GUIDE_POINT", "GUIDE_VECTOR", "NORMAL_FORCE", "SLIDE_VECTOR"]
