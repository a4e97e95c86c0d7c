"""Operations of a second driver (W = 2): the second crank's angle from the common parameter.

The first driver's coordinate φ1 is the independent variable of every plan. A second crank turns
by its own law, φ2 = phase + |ω2|/|ω1|·φ1 (constant speeds, each angle in its own sense from its
own reference); with θ = ref + sense·φ for both, its absolute direction is linear in θ1:
θ2 = ``offset`` + ``ratio``·θ1. Its points, velocities (``DRIVE_VELOCITY``) and accelerations
(``DRIVE_ACCELERATION``) are then built as the first crank's.
"""

from __future__ import annotations

from ...geom.vec import Array
from ..step import Step
from .spec import OpSpec, Result, Written


def second_crank_angle(step: Step, angle: Array) -> Result:
    """θ2 = ``offset`` + ``ratio``·θ1: the second crank's direction from the first's."""
    return float(step.param("offset")) + float(step.param("ratio")) * angle, None, None


SECOND_CRANK_ANGLE = OpSpec("second_crank_angle", second_crank_angle,
                            "protocol.op.second_crank_angle", written=Written.ANGLE)

__all__ = ["SECOND_CRANK_ANGLE"]
