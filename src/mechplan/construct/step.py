"""Steps of a construction: what a student draws, one line or point at a time."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .ops.spec import OpSpec


class Plan(enum.Enum):
    """Which plan a step belongs to."""

    POSITION = "position"
    VELOCITY = "velocity"
    ACCELERATION = "acceleration"
    FORCE = "force"

    @property
    def unit(self) -> str:
        """SI unit of the plan's vectors: ``m``, ``m/s``, ``m/s²``, ``N``."""
        return _PLAN_UNITS[self][0]

    @property
    def scale_key(self) -> str:
        """Key of the plan's scale factor in scene files and JSON: ``mu_l``, ``mu_v``, …"""
        return _PLAN_UNITS[self][1]

    @property
    def scale_symbol(self) -> str:
        """Symbol of the plan's scale factor on sheets: ``μl``, ``μv``, ``μa``, ``μF``."""
        return _PLAN_UNITS[self][2]

    @property
    def scale_unit(self) -> str:
        """Unit of the scale factor: physical units per paper millimetre (``(m/s)/mm``)."""
        return f"{self.unit}/mm" if "/" not in self.unit else f"({self.unit})/mm"


_PLAN_UNITS = {Plan.POSITION: ("m", "mu_l", "μl"), Plan.VELOCITY: ("m/s", "mu_v", "μv"),
               Plan.ACCELERATION: ("m/s²", "mu_a", "μa"), Plan.FORCE: ("N", "mu_F", "μF")}


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
