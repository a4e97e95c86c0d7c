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

from ...geom.vec import Array
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


SECOND_CRANK_ANGLE = OpSpec("second_crank_angle", second_crank_angle,
                            "protocol.op.second_crank_angle", written=Written.ANGLE)
SECOND_DRIVER_LENGTH = OpSpec("second_driver_length", second_driver_length,
                              "protocol.op.second_driver_length", written=Written.LINEAR)

__all__ = ["SECOND_CRANK_ANGLE", "SECOND_DRIVER_LENGTH"]
