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
"""

from __future__ import annotations

from .inputs import driver_law, second_driver_length
from .spec import OpSpec, Written

CRANK_LAW = OpSpec("crank_law", driver_law, "protocol.op.crank_law", written=Written.RATE)
SECOND_SLIDER_POSITION = OpSpec("second_slider_position", second_driver_length,
                                "protocol.op.second_slider_position", written=Written.LINEAR)

__all__ = ["CRANK_LAW", "SECOND_SLIDER_POSITION"]
