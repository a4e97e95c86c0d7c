"""Every construction operation, declared once (one :class:`OpSpec` each), by family.

To add an operation: its evaluate function and its ``OpSpec`` constant (named ``value.upper()``,
listed in the module's ``__all__``) in the family module it belongs to, and its protocol sentence
``protocol.op.<name>`` in ``locale/<lang>/protocol.po`` for the four languages. It is then
``Op.<NAME>`` and in :data:`SPECS`; without a scalar form in ``construct/kernel.py`` a construction
that needs it is evaluated by the numpy path.
"""

from __future__ import annotations

from collections.abc import Callable

from ..step import Step
from . import (
    acceleration,
    centre_velocity,
    driver_inputs,
    drivers,
    force,
    inputs,
    position,
    triad,
    velocity,
)
from . import catalog as Op
from .spec import (
    Drawn,
    Grade,
    Hint,
    HintView,
    Joined,
    Line,
    OpSpec,
    Result,
    Source,
    Written,
    registered,
)

#: the families, in the order of the plans
FAMILIES = (position, velocity, acceleration, force, drivers, triad, inputs, centre_velocity,
            driver_inputs)

#: the registry: name → spec, from the families' ``__all__``
SPECS: dict[str, OpSpec] = {spec.value: spec for family in FAMILIES
                            for spec in (getattr(family, name) for name in family.__all__)}


def spec(op: OpSpec) -> OpSpec:
    """The spec of an operation: the operation itself (kept for callers that ask for it)."""
    return op


#: operation → evaluate(step, *input values)
EVALUATORS: dict[OpSpec, Callable[..., Result]] = {
    s: s.evaluate for s in SPECS.values() if s.source is Source.INPUTS and s.evaluate}
#: operations whose value depends only on the number of positions
SOURCES: dict[OpSpec, Callable[[Step, int], Result]] = {
    s: s.evaluate for s in SPECS.values() if s.source is Source.POSITIONS and s.evaluate}

__all__ = ["EVALUATORS", "FAMILIES", "SOURCES", "SPECS", "Drawn", "Grade", "Hint", "HintView",
           "Joined", "Line", "Op", "OpSpec", "Result", "Source", "Written", "registered", "spec"]
