"""Structural analysis: degrees of freedom, Assur groups, structure formula."""

from __future__ import annotations

import enum
import itertools
from dataclasses import dataclass, replace

from ..errors import TopologyError
from .mechanism import GROUND, DriverKind, Mechanism, Pair, PairKind


class GroupKind(enum.StrEnum):
    """Kind of a class II Assur group: pair kinds outer1–inner–outer2 (R revolute, P prismatic)."""

    RRR = "RRR"
    RRP = "RRP"
    RPR = "RPR"
    PRP = "PRP"
    RPP = "RPP"


@dataclass(frozen=True, slots=True)
class Group:
    """A class II Assur group (dyad): links (L1, L2), outer pairs and the inner pair."""

    links: tuple[str, str]
    outer1: Pair
    inner: Pair
    outer2: Pair

    @property
    def kind(self) -> GroupKind:
        """Pair kinds in order outer1–inner–outer2, e.g. ``RRP``."""
        return GroupKind(_letters(self))

    @property
    def name(self) -> str:
        """The group as the structure formula writes it, e.g. ``II(2,3)``."""
        return f"II({self.links[0]},{self.links[1]})"

    @property
    def pairs(self) -> tuple[Pair, Pair, Pair]:
        """All three pairs."""
        return (self.outer1, self.inner, self.outer2)


@dataclass(frozen=True, slots=True)
class Structure:
    """Result of the structural analysis."""

    moving_links: int
    lower_pairs: int
    higher_pairs: int
    driving_link: str
    groups: tuple[Group, ...]
    #: a cylinder driver: (barrel, rod); its group lists the barrel and stands for both
    cylinder: tuple[str, str] | None = None

    @property
    def dof(self) -> int:
        """W = 3n − 2p5 − p4 (Chebyshev / Grübler)."""
        return 3 * self.moving_links - 2 * self.lower_pairs - self.higher_pairs

    @property
    def formula(self) -> str:
        """Structure formula, e.g. ``I(0,1) → II(2,3) → II(4,5)``."""
        first = (f"I({self.cylinder[0]},{self.cylinder[1]})" if self.cylinder
                 else f"I({GROUND},{self.driving_link})")
        parts = [first] + [g.name for g in self.groups]
        return " → ".join(parts)

    @property
    def mechanism_class(self) -> int:
        """Highest class among the groups (I when there is none)."""
        return 2 if self.groups else 1


def degrees_of_freedom(mech: Mechanism) -> int:
    """Return W = 3n − 2p5 for a mechanism with lower pairs only."""
    return 3 * len(mech.moving) - 2 * len(mech.pairs)


def analyse(mech: Mechanism) -> Structure:
    """Decompose a one-driver mechanism into its first-class mechanism and class II groups.

    A crank or a slider on a frame guide is known once its coordinate is; a cylinder (barrel and
    rod with their driven prismatic pair) is a link of known length: its rod is merged into its
    barrel and the barrel joins the group it closes (boom + cylinder: II(boom, barrel)).
    """
    w = degrees_of_freedom(mech)
    drivers = 1
    if w != drivers:
        raise TopologyError(
            f"the mechanism has W = 3·{len(mech.moving)} − 2·{len(mech.pairs)} = {w} degrees of "
            f"freedom but {drivers} driver ([drive], link {mech.drive.link}); add or remove "
            "links or pairs so that W equals the number of drivers", key="links")
    drive = mech.drive
    view, cylinder = mech, None
    originals: dict[Pair, Pair] = {}
    if drive.kind is DriverKind.CYLINDER:
        view, originals, cylinder = _merged_cylinder(mech)
        known = {GROUND}
    else:
        _check_driving_pair(mech)
        known = {GROUND, drive.link}
    remaining = [k for k in view.moving if k not in known]
    groups: list[Group] = []
    while remaining:
        group = _find_dyad(view, remaining, known)
        if group is None:
            _raise_undecomposable(view, remaining, known)
        assert group is not None
        group = Group(group.links, *(originals.get(p, p) for p in group.pairs))
        groups.append(group)
        known.update(group.links)
        remaining = [k for k in remaining if k not in known]
    return Structure(len(mech.moving), len(mech.pairs), 0, drive.link, tuple(groups), cylinder)


def _check_driving_pair(mech: Mechanism) -> None:
    drive = mech.drive
    drive_pairs = [p for p in mech.pairs_of(drive.link) if p.other(drive.link) == GROUND]
    if drive.kind is DriverKind.SLIDER:
        if (len(drive_pairs) != 1 or drive_pairs[0].kind is not PairKind.PRISMATIC
                or drive_pairs[0].a != drive.link):
            raise TopologyError(f"the driving slider {drive.link} must slide on one frame guide "
                                f"(it has {len(drive_pairs)} pair(s) with the frame)",
                                key="drive.link")
        return
    if len(drive_pairs) != 1 or drive_pairs[0].kind is not PairKind.REVOLUTE:
        raise TopologyError(f"the driving link {drive.link} must turn about one frame point "
                            "(a crank)", key="drive.link")


def _merged_cylinder(mech: Mechanism) -> tuple[Mechanism, dict[Pair, Pair], tuple[str, str]]:
    """The mechanism with the cylinder's rod merged into its barrel (their pair driven)."""
    rod, barrel = mech.drive.link, mech.drive.carrier
    assert barrel is not None
    driven = [p for p in mech.pairs if p.kind is PairKind.PRISMATIC and p.a == rod
              and p.b == barrel]
    if len(driven) != 1:
        raise TopologyError(f"the cylinder's rod {rod} must slide in its barrel {barrel} "
                            f"(found {len(driven)} such pair(s))", key="drive.link")
    originals: dict[Pair, Pair] = {}
    pairs: list[Pair] = []
    for p in mech.pairs:
        if p is driven[0]:
            continue
        q = replace(p, a=barrel if p.a == rod else p.a, b=barrel if p.b == rod else p.b)
        if q.a == q.b:
            raise TopologyError(f"the cylinder's rod {rod} and barrel {barrel} share a second "
                                f"pair {p.name}; the cylinder could not extend", key="drive.link")
        originals[q] = p
        pairs.append(q)
    ends = [p for p in pairs if p.joins(barrel)]
    if len(ends) != 2 or any(p.kind is not PairKind.REVOLUTE for p in ends):
        names = ", ".join(p.name for p in ends)
        raise TopologyError(f"the cylinder (barrel {barrel}, rod {rod}) must be pinned at both "
                            f"ends by two revolute pairs (it has {names})", key="drive.link")
    links = {k: v for k, v in mech.links.items() if k != rod}
    return replace(mech, links=links, pairs=tuple(pairs)), originals, (barrel, rod)


def _outer_pairs(mech: Mechanism, link: str, known: set[str]) -> list[Pair]:
    return [p for p in mech.pairs_of(link) if p.other(link) in known]


def _find_dyad(mech: Mechanism, remaining: list[str], known: set[str]) -> Group | None:
    for i, j in itertools.combinations(remaining, 2):
        inner = [p for p in mech.pairs_of(i) if p.other(i) == j]
        if len(inner) != 1:
            continue
        o1, o2 = _outer_pairs(mech, i, known), _outer_pairs(mech, j, known)
        if len(o1) != 1 or len(o2) != 1:
            continue
        g = Group((i, j), o1[0], inner[0], o2[0])
        if _letters(g) in ("PRR", "PPR"):   # canonical order: the revolute outer pair first
            g = Group((j, i), o2[0], inner[0], o1[0])
        if _letters(g) == "PPP":
            raise TopologyError(f"links {i} and {j} form a PPP group, which cannot be assembled "
                                "(it has no defined position)", key=f"links.{i}")
        return g
    return None


def _letters(g: Group) -> str:
    return g.outer1.kind.value + g.inner.kind.value + g.outer2.kind.value


def _raise_undecomposable(mech: Mechanism, remaining: list[str], known: set[str]) -> None:
    for quad in itertools.combinations(remaining, 4):
        inside = [p for p in mech.pairs if p.a in quad and p.b in quad]
        outside = [p for p in mech.pairs if (p.a in quad) != (p.b in quad)
                   and (p.a in known or p.b in known)]
        if len(inside) == 3 and len(outside) == 3:
            raise TopologyError(
                f"links {', '.join(quad)} form a class III group (triad) with pairs "
                f"{', '.join(p.name for p in inside + outside)}; class III groups are not "
                "supported yet", key="links")
    raise TopologyError(f"links {', '.join(remaining)} cannot be split into class II groups "
                        f"attached to links {', '.join(sorted(known))}; check the pairs",
                        key="links")
