"""The plans of the graphical method: positions, velocities, accelerations, forces.

A plan is a notion of the course, not of one module: the construction draws on it, a student's
sheet is read as one, the checker grades it. Each kind carries its unit and its scale factor's
key, symbol and dimension.
"""

from __future__ import annotations

import enum


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
    def scale_dimension(self) -> str:
        """The dimension a written scale factor is read in (a key of ``units.DIMENSIONS``)."""
        return _PLAN_UNITS[self][3]

    @property
    def scale_unit(self) -> str:
        """Unit of the scale factor: physical units per paper millimetre (``(m/s)/mm``)."""
        return f"{self.unit}/mm" if "/" not in self.unit else f"({self.unit})/mm"


_PLAN_UNITS = {Plan.POSITION: ("m", "mu_l", "μl", "mu_length"),
               Plan.VELOCITY: ("m/s", "mu_v", "μv", "mu_velocity"),
               Plan.ACCELERATION: ("m/s²", "mu_a", "μa", "mu_acceleration"),
               Plan.FORCE: ("N", "mu_F", "μF", "mu_force")}
