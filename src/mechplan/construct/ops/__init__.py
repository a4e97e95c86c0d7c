"""Every construction operation, declared once (one :class:`OpSpec` each), by family.

To add an operation: a member of :class:`~mechplan.construct.step.Op`, an ``OpSpec`` in the
family module it belongs to (its evaluate function beside it), and its protocol sentence
``protocol.op.<name>`` in ``locale/<lang>/protocol.po`` for the four languages.
"""

from __future__ import annotations

from collections.abc import Callable

from ..step import Op, Step
from . import acceleration, force, position, velocity
from .spec import Drawn, Grade, Line, OpSpec, Result, Source, Written

#: the registry: operation → its spec (built once from the family modules' ``SPECS``)
SPECS: dict[Op, OpSpec] = {s.op: s for family in (position, velocity, acceleration, force)
                           for s in family.SPECS}


def spec(op: Op) -> OpSpec:
    """Return the spec of an operation."""
    return SPECS[op]


#: operation → evaluate(step, *input values) (kept for ``check/``)
EVALUATORS: dict[Op, Callable[..., Result]] = {
    s.op: s.evaluate for s in SPECS.values() if s.source is Source.INPUTS and s.evaluate}
#: operations whose value depends only on the number of positions (kept for ``check/``)
SOURCES: dict[Op, Callable[[Step, int], Result]] = {
    s.op: s.evaluate for s in SPECS.values() if s.source is Source.POSITIONS and s.evaluate}

__all__ = ["EVALUATORS", "SOURCES", "SPECS", "Drawn", "Grade", "Line", "OpSpec", "Result",
           "Source", "Written", "spec"]
