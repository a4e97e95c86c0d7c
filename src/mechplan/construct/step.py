"""Steps of a construction: what a student draws, one line or point at a time."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import Any


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


class Op(enum.Enum):
    """Operations of the graphical method."""

    CRANK_ANGLE = "crank_angle"          # the input: absolute crank angle
    FIXED_POINT = "fixed_point"          # a point of the frame
    CONSTANT = "constant"                # a given scalar (ω1, a guide angle)
    POLAR_POINT = "polar_point"          # centre + length at an angle (crank pin)
    ANGLE_OF = "angle_of"                # direction of a segment
    ANGLE_PLUS = "angle_plus"            # an angle plus a constant (slider on a guide)
    CIRCLE_CIRCLE = "circle_circle"      # two compass arcs
    CIRCLE_LINE = "circle_line"          # compass arc across a guide line
    LINE_LINE = "line_line"              # two lines meet
    LOCUS_LINE = "locus_line"            # line a point of a sliding link must lie on
    CARRIER_ANGLE = "carrier_angle"      # coulisse direction through a slider pin
    PLACE = "place"                      # point of a link from a point and the link angle
    SIMILAR_POSITION = "similar_position"  # triangle on a known side (constant shape)
    SIMILAR_IMAGE = "similar_image"      # similarity theorem on velocity/acceleration plans
    RIGID_VELOCITY = "rigid_velocity"    # v_X = v_O + ω × OX
    RIGID_ACCELERATION = "rigid_acceleration"  # a_X = a_O + ε × OX − ω² OX
    POLE = "pole"                        # pole p or π (zero vector)
    DRIVE_VELOCITY = "drive_velocity"    # pb ⊥ AB, ω1·l_AB
    DRIVE_ACCELERATION = "drive_acceleration"  # π b′ (normal + tangential of the crank)
    LINE_PERP = "line_perp"              # through an image, ⊥ to a link segment
    LINE_PARALLEL = "line_parallel"      # through an image, ∥ to a direction (guide)
    OMEGA = "omega"                      # ω of a link from a relative velocity
    EPSILON = "epsilon"                  # ε of a link from a tangential component
    NORMAL = "normal"                    # normal component: from an image, ∥ link, ω²l
    CORIOLIS = "coriolis"                # Coriolis component 2ω × v_rel
    COPY = "copy"                        # a value taken over from another step (ω3 = ω2)
    DIFFERENCE = "difference"            # a vector between two images (relative velocity)
    # force plan (kinetostatics)
    FORCE_INERTIA = "force_inertia"      # Q = −m·a_S
    MOMENT_INERTIA = "moment_inertia"    # M_q = −J_S·ε
    FORCE_LOAD = "force_load"            # a given force: weight, constant, pressure, table
    MOMENT_ARM_TANGENTIAL = "moment_arm_tangential"  # R^t (or a guide's normal) from ΣM = 0
    FORCE_SUM = "force_sum"              # next vertex of a force polygon: previous + force
    FORCE_CLOSE = "force_close"          # two closing lines of known direction meet
    BALANCING_MOMENT = "balancing_moment"  # M_b = −ΣM_A of all loads on the driving link
    ZHUKOVSKY = "zhukovsky"              # M_b from moments about the pole of the turned plan
    MOMENT_SUM = "moment_sum"            # ΣM_P of known forces and couples on a link
    MOMENT_CLOSE = "moment_close"        # the couple of a guide reaction: −ΣM
    FORCE_LINE = "force_line"            # through a polygon vertex, ∥ or ⊥ a link or guide
    FORCE_REVERSE = "force_reverse"      # R_ji = −R_ij (action and reaction)
    GUIDE_OFFSET = "guide_offset"        # where a guide reaction's line of action crosses the guide
    LINE_OF_ACTION = "line_of_action"    # a point of the line of action of a force with a couple
    INERTIA_OFFSET = "inertia_offset"    # h = M_q/|Q| of the single equivalent inertia force


@dataclass(frozen=True, slots=True)
class Step:
    """One construction step.

    ``inputs`` are ids of earlier steps; ``params`` hold constants (lengths in m, branch signs,
    local shapes); ``label`` is the name drawn on the plan (``c``, ``n_CB``, ``ω2``);
    ``subject`` names the geometric objects for the protocol text (e.g. the link segment "BC").
    """

    id: str
    op: Op
    inputs: tuple[str, ...]
    plan: Plan
    kind: Kind
    role: Role
    label: str
    group: str = ""
    params: tuple[tuple[str, Any], ...] = field(default_factory=tuple)
    subject: tuple[str, ...] = field(default_factory=tuple)

    def input(self, name: str) -> str:
        """Return the id of the named input (names: ``construct.ops.spec(op).inputs``)."""
        from .ops import spec  # the registry is built above this module

        return self.inputs[spec(self.op).index(name)]

    def rest(self) -> tuple[str, ...]:
        """Return the ids of the variable tail of inputs (after the named ones)."""
        from .ops import spec

        return self.inputs[len(spec(self.op).inputs):]

    def param(self, name: str, default: Any = None) -> Any:
        """Return a parameter by name."""
        for key, value in self.params:
            if key == name:
                return value
        return default
