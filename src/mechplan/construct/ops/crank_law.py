"""A crank's or rocker's ω and ε given by its law by a table over time (``[drive] law`` of a
crank): the spline's first and second derivative at the time of a position (``CRANK_LAW``).

The evaluation is the linear drivers' (:func:`~mechplan.construct.ops.inputs.driver_law`), with
the table in the construction's absolute angle θ (``model/crank_law.py``); the protocol writes ω
and ε with their sense, as for a constant rate.
"""

from __future__ import annotations

from .inputs import driver_law
from .spec import OpSpec, Written

CRANK_LAW = OpSpec("crank_law", driver_law, "protocol.op.crank_law", written=Written.RATE)

__all__ = ["CRANK_LAW"]
