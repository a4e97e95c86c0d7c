"""Operations of a second driver (W = 2): the second crank's angle from the common parameter.

The first driver's coordinate φ1 is the independent variable of every plan. A second crank turns
by its own law, φ2 = phase + |ω2|/|ω1|·φ1 (constant speeds, each angle in its own sense from its
own reference); with θ = ref + sense·φ for both, its absolute direction is linear in θ1:
θ2 = ``offset`` + ``ratio``·θ1. Its points, velocities (``DRIVE_VELOCITY``) and accelerations
(``DRIVE_ACCELERATION``) are then built as the first crank's. A second cylinder's length follows
the first driver's coordinate by the same affine law (``SECOND_DRIVER_LENGTH``), l2 = ``offset`` +
``ratio``·q1; its group is then built as the first cylinder's (compass arcs of driven length).
"""

from __future__ import annotations

import numpy as np

from ...geom.vec import Array
from ...model.law import TableLaw, at_time, time_of
from ..step import Step
from .spec import OpSpec, Result, Written


def second_crank_angle(step: Step, angle: Array) -> Result:
    """θ2 = ``offset`` + ``ratio``·θ1: the second crank's direction from the first's."""
    return float(step.param("offset")) + float(step.param("ratio")) * angle, None, None


def second_driver_length(step: Step, coordinate: Array) -> Result:
    """l2 = ``offset`` + ``ratio``·q1: a second cylinder's length from the first's coordinate.

    q1 is the first crank's direction θ1 (rad) or the first linear driver's length (m).
    """
    return float(step.param("offset")) + float(step.param("ratio")) * coordinate, None, None


def law_time(step: Step, x: Array) -> Array:
    """The time of a position from the first driver's step value x: its law's table inverted
    (``clock_times``/``clock_values``), or t = ``clock_a`` + ``clock_b``·x at constant rates."""
    times = step.param("clock_times", ())
    if times:
        return time_of(TableLaw(times, step.param("clock_values")), x)
    return float(step.param("clock_a")) + float(step.param("clock_b")) * np.asarray(x)


def driver_law(step: Step, coordinate: Array) -> Result:
    """A driver's coordinate (``order`` 0), rate (1) or acceleration (2) at the time of a position.

    By its table (``times``/``values``: its cubic spline and derivatives) or at constant rates
    (``q0`` + ``rate``·t, ``rate``, ``acceleration``). NaN where the time is outside the table.
    """
    t = law_time(step, coordinate)
    order = int(step.param("order"))
    times = step.param("times", ())
    if times:
        return at_time(TableLaw(times, step.param("values")), t, order), None, None
    if order == 0:
        return float(step.param("q0")) + float(step.param("rate")) * t, None, None
    value = float(step.param("rate" if order == 1 else "acceleration"))
    return np.where(np.isfinite(t), value, np.nan), None, None


SECOND_CRANK_ANGLE = OpSpec("second_crank_angle", second_crank_angle,
                            "protocol.op.second_crank_angle", written=Written.ANGLE)
SECOND_DRIVER_LENGTH = OpSpec("second_driver_length", second_driver_length,
                              "protocol.op.second_driver_length", written=Written.LINEAR)

DRIVER_LAW = OpSpec("driver_law", driver_law, "protocol.op.driver_law", written=Written.LINEAR)

__all__ = ["DRIVER_LAW", "SECOND_CRANK_ANGLE", "SECOND_DRIVER_LENGTH"]
