"""Specs of a gear scene: a planetary train (scheme, links, target ratio), an ordinary stage after
it and an involute pair. Frozen dataclasses, SI floats (module in metres, angles in radians)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Scheme(Enum):
    """Planetary schemes. Gears: 1 and the last are central, the others are planets on
    the carrier h.

    ``SINGLE_ROW``: sun 1 – planet 2 – ring 3. Two-row (planet block 2–3 on one shaft, central 1,
    4): ``EXT_INT`` 1–2 external, 3–4 internal (the worked example); ``EXT_EXT`` both external;
    ``INT_INT`` both internal (1 and 4 are rings).
    """

    SINGLE_ROW = "single_row"
    EXT_INT = "two_row_ext_int"
    EXT_EXT = "two_row_ext_ext"
    INT_INT = "two_row_int_int"

    @property
    def two_row(self) -> bool:
        """True for the schemes with a planet block of two gears."""
        return self is not Scheme.SINGLE_ROW

    @property
    def internal(self) -> tuple[bool, bool]:
        """Whether the first mesh (1–2) and the second mesh (planet–last central) are internal."""
        return {Scheme.SINGLE_ROW: (False, True), Scheme.EXT_INT: (False, True),
                Scheme.EXT_EXT: (False, False), Scheme.INT_INT: (True, True)}[self]

    @property
    def gear_names(self) -> tuple[str, ...]:
        """Names of the gears: central a, planet(s), central b."""
        return ("1", "2", "3") if self is Scheme.SINGLE_ROW else ("1", "2", "3", "4")

    @property
    def links(self) -> tuple[str, str, str]:
        """The three basic links that can be fixed, input or output: central a, central b,
        carrier."""
        names = self.gear_names
        return (names[0], names[-1], "h")


class ShiftRule(Enum):
    """How the profile shifts x1, x2 of the involute pair are chosen."""

    GIVEN = "given"                  # x1, x2 as written in the scene (default 0, 0)
    NO_UNDERCUT = "no_undercut"      # x = h_a*(z_min − z)/z_min when z < z_min, else 0
    BALANCED = "balanced_sliding"    # x2 = −x1, maximum specific slidings of both gears equal
    CONTOUR = "contour"              # inside the blocking contour: balanced sliding, largest ε_α


@dataclass(frozen=True)
class PlanetarySpec:
    """What the planetary stage must do and the rules its tooth numbers obey."""

    scheme: Scheme
    fixed: str
    input: str
    output: str
    ratio: float                     # target u_in,out (signed: + same sense of rotation)
    deviation: float                 # allowed relative deviation of the ratio, e.g. 0.02
    planets: int                     # k, equally spaced
    modules: tuple[float, float]     # m of mesh 1–2 and of the second mesh, m
    z_range: tuple[int, int]         # every tooth number within
    z_min: int = 17                  # no-undercut rule for standard teeth
    ring_difference: int = 8         # z_ring − z_planet at least (internal-mesh interference)
    addendum: float = 1.0            # h_a*
    given: tuple[int, ...] | None = None   # check this set (z1, z2[, z3, z4]) instead of the best
    input_speed: float = 1.0         # ω of the input link, rad/s
    centre_distance: float | None = None   # working a_w of every mesh (shifted gears), m
    centre_auto: bool = False        # a_w = the larger standard centre distance of the meshes
    alpha: float = 0.3490658503988659      # pressure angle of the rack, rad
    max_shift_sum: float = 2.0       # |x_Σ| of a mesh at the working a_w at most
    mesh_efficiency: tuple[float, float] = (1.0, 1.0)   # η of mesh 1–2 and of the second mesh
    output_torque: float | None = None     # load on the output link, N·m (torques and forces)
    speeds: tuple[tuple[str, float], tuple[str, float]] | None = None
    # a differential (W = 2): the two links turning as given; ``output`` is the third, ``input``
    # the first given, ``fixed`` is "" (nothing is held)


@dataclass(frozen=True)
class OrdinarySpec:
    """An external pair after the planetary stage: given teeth, or a ratio to meet."""

    module: float
    teeth: tuple[int, int] | None = None
    ratio: float | None = None       # |u| wanted when teeth are not given


@dataclass(frozen=True)
class PairSpec:
    """An involute pair to lay out and draw."""

    module: float
    z1: int
    z2: int
    alpha: float = 0.3490658503988659    # 20°
    addendum: float = 1.0                # h_a*
    clearance: float = 0.25              # c*
    shifts: tuple[float, float] = (0.0, 0.0)
    rule: ShiftRule = ShiftRule.GIVEN
    z_min: int = 17
    contour: bool = False                # draw the blocking contour (always with rule CONTOUR)
    tip_land: float = 0.25               # the contour's least top land s_a/m
    eps_min: float = 1.2                 # the contour's least contact ratio ε_α
    internal: bool = False               # gear 2 is a ring gear (an internal pair; z2 > z1)


@dataclass(frozen=True)
class CompoundGear:
    """One gear (shift) of a compound set: the input member, the members held, two members
    locked together (or none) and the output member."""

    name: str
    input: str
    output: str
    held: tuple[str, ...] = ()
    locked: tuple[str, ...] = ()


@dataclass(frozen=True)
class CompoundSpec:
    """A Simpson or Ravigneaux set: its kind, tooth numbers by name, its gears, the input speed."""

    kind: str                          # "simpson" | "ravigneaux"
    teeth: dict[str, int]
    gears: tuple[CompoundGear, ...]
    input_speed: float = 1.0           # rad/s


@dataclass(frozen=True)
class GearScene:
    """A parsed gear scene."""

    title: str
    language: str
    planetary: PlanetarySpec | None
    ordinary: OrdinarySpec | None
    pair: PairSpec | None
    file: str = "<scene>"
    compound: CompoundSpec | None = None
