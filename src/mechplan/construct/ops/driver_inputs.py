"""Operations of drivers added for any order of driver kinds (``[drive]``, ``[drive2]``).

``CRANK_LAW``: a crank's or rocker's ω and ε given by its law by a table over time (``law`` of a
crank), and a second crank's direction θ2 at the position's time: the spline's value or
derivatives at the time of a position (the evaluation is the linear drivers'
:func:`~mechplan.construct.ops.inputs.driver_law`, with the table in the construction's absolute
angle θ, ``model/crank_law.py``); the protocol writes ω and ε with their sense.

``SECOND_SLIDER_POSITION``: a second driver that is a slider on a frame guide, its displacement
s2 = ``offset`` + ``ratio``·q1 from the first driver's coordinate at constant rates (the second
cylinder's affine law, :func:`~mechplan.construct.ops.inputs.second_driver_length`), with its
own sentence (a displacement along the guide, not a length).

``CIRCLE_LINE_DRIVEN``: a cylinder whose group is an RRP dyad (the link it drives slides on a
guide): an arc of the driven length l(q) about the cylinder's known end cuts the line the pin
moves on (the cylinder's RRR group is ``CIRCLE_CIRCLE_DRIVEN``, ``ops/drivers.py``).
"""

from __future__ import annotations

from ...geom import meet
from ...geom.vec import Array
from ..step import Step
from .inputs import driver_law, second_driver_length
from .position import position_hint
from .spec import Drawn, Grade, Line, OpSpec, Result, Written


def circle_line_driven(step: Step, centre: Array, guide: Array, radius: Array) -> Result:
    """An arc of the driven length about ``centre`` cuts a guide line (branch ``sigma``).

    Its conditioning is the crossing's sine squared, as for two arcs of which one is driven
    (``circle_circle_driven``): the half-chord h = √(l² − w²) cancels near the tangent position,
    and every rate of the group is divided by it."""
    point, gap, sine = meet.circle_line(centre, radius, guide[..., 0, :], guide[..., 1, :],
                                        step.param("sigma"))
    return point, gap, sine * sine

CRANK_LAW = OpSpec("crank_law", driver_law, "protocol.op.crank_law", written=Written.RATE)
SECOND_SLIDER_POSITION = OpSpec("second_slider_position", second_driver_length,
                                "protocol.op.second_slider_position", written=Written.LINEAR)

CIRCLE_LINE_DRIVEN = OpSpec("circle_line_driven", circle_line_driven,
                            "protocol.op.circle_line_driven", Drawn.POINT, Line.OUTLINE,
                            Grade.POINT, hint_rule=position_hint)

__all__ = ["CIRCLE_LINE_DRIVEN", "CRANK_LAW", "SECOND_SLIDER_POSITION"]
