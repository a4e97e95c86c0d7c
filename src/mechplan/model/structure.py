"""Structural analysis: degrees of freedom, Assur groups, structure formula."""

from __future__ import annotations

import enum
import itertools
from dataclasses import dataclass

from ..errors import TopologyError
from .mechanism import GROUND, Mechanism, Pair, PairKind


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

    @property
    def dof(self) -> int:
        """W = 3n − 2p5 − p4 (Chebyshev / Grübler)."""
        return 3 * self.moving_links - 2 * self.lower_pairs - self.higher_pairs

    @property
    def formula(self) -> str:
        """Structure formula, e.g. ``I(0,1) → II(2,3) → II(4,5)``."""
        parts = [f"I({GROUND},{self.driving_link})"] + [g.name for g in self.groups]
        return " → ".join(parts)

    @property
    def mechanism_class(self) -> int:
        """Highest class among the groups (I when there is none)."""
        return 2 if self.groups else 1


def degrees_of_freedom(mech: Mechanism) -> int:
    """Return W = 3n − 2p5 for a mechanism with lower pairs only."""
    return 3 * len(mech.moving) - 2 * len(mech.pairs)


def analyse(mech: Mechanism) -> Structure:
    """Decompose a one-drive mechanism into the driving link and class II groups."""
    w = degrees_of_freedom(mech)
    if w != 1:
        raise TopologyError(
            f"the mechanism has W = 3·{len(mech.moving)} − 2·{len(mech.pairs)} = {w} degrees of "
            f"freedom but 1 drive; add or remove links or pairs so that W = 1", key="links")
    known = {GROUND, mech.drive.link}
    drive_pairs = [p for p in mech.pairs_of(mech.drive.link) if p.other(mech.drive.link) == GROUND]
    if len(drive_pairs) != 1 or drive_pairs[0].kind is not PairKind.REVOLUTE:
        raise TopologyError(f"the driving link {mech.drive.link} must turn about one frame point "
                            "(a crank)", key="drive.link")
    remaining = [k for k in mech.moving if k not in known]
    groups: list[Group] = []
    while remaining:
        group = _find_dyad(mech, remaining, known)
        if group is None:
            _raise_undecomposable(mech, remaining, known)
        groups.append(group)  # type: ignore[arg-type]
        known.update(group.links)  # type: ignore[union-attr]
        remaining = [k for k in remaining if k not in known]
    return Structure(len(mech.moving), len(mech.pairs), 0, mech.drive.link, tuple(groups))


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
