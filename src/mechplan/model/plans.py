"""The plans of the graphical method: positions, velocities, accelerations, forces.

A plan is a notion of the course, not of one module: the construction draws on it, a student's
sheet is read as one, the checker grades it. Each kind carries its unit and dimension and its
scale factor's key, symbol and dimension.
"""

from __future__ import annotations

import enum
from typing import NamedTuple


class Plan(enum.Enum):
    """Which plan a step belongs to."""

    POSITION = "position"
    VELOCITY = "velocity"
    ACCELERATION = "acceleration"
    FORCE = "force"

    @property
    def unit(self) -> str:
        """SI unit of the plan's vectors: ``m``, ``m/s``, ``m/s²``, ``N``."""
        return _UNITS[self].unit

    @property
    def dimension(self) -> str:
        """The dimension of the plan's vectors (a key of ``units.DIMENSIONS``): ``length``, …"""
        return _UNITS[self].dimension

    @property
    def scale_key(self) -> str:
        """Key of the plan's scale factor in scene files and JSON: ``mu_l``, ``mu_v``, …"""
        return _UNITS[self].scale_key

    @property
    def scale_symbol(self) -> str:
        """Symbol of the plan's scale factor on sheets: ``μl``, ``μv``, ``μa``, ``μF``."""
        return _UNITS[self].scale_symbol

    @property
    def scale_dimension(self) -> str:
        """The dimension a written scale factor is read in (a key of ``units.DIMENSIONS``)."""
        return f"mu_{self.dimension}"

    @property
    def scale_unit(self) -> str:
        """Unit of the scale factor: physical units per paper millimetre (``(m/s)/mm``)."""
        return f"{self.unit}/mm" if "/" not in self.unit else f"({self.unit})/mm"


class _Units(NamedTuple):
    unit: str
    dimension: str
    scale_key: str
    scale_symbol: str


_UNITS = {Plan.POSITION: _Units("m", "length", "mu_l", "μl"),
          Plan.VELOCITY: _Units("m/s", "velocity", "mu_v", "μv"),
          Plan.ACCELERATION: _Units("m/s²", "acceleration", "mu_a", "μa"),
          Plan.FORCE: _Units("N", "force", "mu_F", "μF")}
