"""Steps of a construction: what a student draws, one line or point at a time."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..model.plans import Plan

if TYPE_CHECKING:
    from .ops.spec import OpSpec


class Role(enum.Enum):
    """How a step is drawn: given data, an auxiliary line, or a result."""

    GIVEN = "given"
    AUXILIARY = "auxiliary"
    RESULT = "result"


class Kind(enum.Enum):
    """What a step's value is."""

    POINT = "point"      # (N, 2)
    LINE = "line"        # (N, 2, 2): a point and a unit direction
    SCALAR = "scalar"    # (N,)


@dataclass(frozen=True, slots=True)
class Step:
    """One construction step.

    ``inputs`` are ids of earlier steps; ``params`` hold constants (lengths in m, branch signs,
    local shapes); ``label`` is the name drawn on the plan (``c``, ``n_CB``, ``ω2``);
    ``subject`` names the geometric objects for the protocol text (e.g. the link segment "BC").
    ``op`` is the operation's spec (``Op.CIRCLE_CIRCLE``, see ``construct/ops/``).
    """

    id: str
    op: OpSpec
    inputs: tuple[str, ...]
    plan: Plan
    kind: Kind
    role: Role
    label: str
    group: str = ""
    params: tuple[tuple[str, Any], ...] = field(default_factory=tuple)
    subject: tuple[str, ...] = field(default_factory=tuple)

    def input(self, name: str) -> str:
        """Return the id of the named input (names: ``step.op.inputs``)."""
        return self.inputs[self.op.index(name)]

    def rest(self) -> tuple[str, ...]:
        """Return the ids of the variable tail of inputs (after the named ones)."""
        return self.inputs[len(self.op.inputs):]

    def param(self, name: str, default: Any = None) -> Any:
        """Return a parameter by name."""
        for key, value in self.params:
            if key == name:
                return value
        return default
