"""Structural analysis: degrees of freedom, Assur groups, structure formula."""

from __future__ import annotations

import enum
import itertools
from dataclasses import dataclass, replace

from ..errors import TopologyError
from ..i18n import Text, join
from .mechanism import GROUND, Drive, DriverKind, Mechanism, Pair, PairKind


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

    @property
    def klass(self) -> int:
        """Assur class: 2."""
        return 2


@dataclass(frozen=True, slots=True)
class Triad:
    """A class III Assur group: a ternary base link joined by three binary links.

    ``legs[i]`` is binary link i; ``outer[i]`` its pair with a known link, ``inner[i]`` its pair
    with the base link. Supported: all six pairs revolute (RRR-RRR).
    """

    base: str
    legs: tuple[str, str, str]
    outer: tuple[Pair, Pair, Pair]
    inner: tuple[Pair, Pair, Pair]

    @property
    def links(self) -> tuple[str, ...]:
        """The four links: base first, then the legs."""
        return (self.base, *self.legs)

    @property
    def kind(self) -> str:
        """Outer pairs' letters, then the inner pairs', e.g. ``RRR-RRR``."""
        return ("".join(p.kind.value for p in self.outer) + "-"
                + "".join(p.kind.value for p in self.inner))

    @property
    def name(self) -> str:
        """The group as the structure formula writes it, e.g. ``III(2,3,4,5)``."""
        return f"III({','.join(sorted(self.links, key=_link_order))})"

    @property
    def pairs(self) -> tuple[Pair, ...]:
        """All six pairs: outer ones, then inner ones."""
        return (*self.outer, *self.inner)

    @property
    def klass(self) -> int:
        """Assur class: 3."""
        return 3


def _link_order(link: str) -> tuple[int, str]:
    return (int(link), link) if link.isdigit() else (10 ** 9, link)


@dataclass(frozen=True, slots=True)
class Structure:
    """Result of the structural analysis."""

    moving_links: int
    lower_pairs: int
    higher_pairs: int
    driving_link: str
    groups: tuple[Group | Triad, ...]
    #: a cylinder driver: (barrel, rod); its group lists the barrel and stands for both
    cylinder: tuple[str, str] | None = None
    #: a second driving crank (W = 2): its first-class mechanism I(0,k) follows the first
    second: str | None = None
    #: a second driving cylinder (W = 2): (barrel, rod), its group lists the barrel
    cylinder2: tuple[str, str] | None = None

    @property
    def dof(self) -> int:
        """W = 3n − 2p5 − p4 (Chebyshev / Grübler)."""
        return 3 * self.moving_links - 2 * self.lower_pairs - self.higher_pairs

    @property
    def formula(self) -> str:
        """Structure formula, e.g. ``I(0,1) → II(2,3) → III(4,5,6,7)``."""
        first = (f"I({self.cylinder[0]},{self.cylinder[1]})" if self.cylinder
                 else f"I({GROUND},{self.driving_link})")
        if self.cylinder2 is not None:
            first += f", I({self.cylinder2[0]},{self.cylinder2[1]})"
        elif self.second is not None:
            first += f", I({GROUND},{self.second})"
        parts = [first] + [g.name for g in self.groups]
        return " → ".join(parts)

    @property
    def mechanism_class(self) -> int:
        """Highest class among the groups (I when there is none)."""
        return max((g.klass for g in self.groups), default=1)


def degrees_of_freedom(mech: Mechanism) -> int:
    """Return W = 3n − 2p5 for a mechanism with lower pairs only."""
    return 3 * len(mech.moving) - 2 * len(mech.pairs)


def analyse(mech: Mechanism) -> Structure:
    """Decompose a one-driver mechanism into its first-class mechanism and class II and III groups.

    A crank or a slider on a frame guide is known once its coordinate is; a cylinder (barrel and
    rod with their driven prismatic pair) is a link of known length: its rod is merged into its
    barrel and the barrel joins the group it closes (boom + cylinder: II(boom, barrel)).
    """
    w = degrees_of_freedom(mech)
    drivers = len(mech.drivers)
    if w != drivers:
        given = join([Text("errmsg2.structure.given_driver", {"table": key, "link": d.link})
                      for key, d in zip(("drive", "drive2"), mech.drivers, strict=False)], "; ")
        raise TopologyError(
            Text("errmsg2.structure.w_drivers",
                 {"moving": str(len(mech.moving)), "pairs": str(len(mech.pairs)), "w": str(w),
                  "drivers": str(drivers),
                  "driver_word": (Text("errmsg2.structure.drivers") if drivers > 1
                                  else Text("errmsg2.structure.driver")),
                  "given": given}), key="links")
    drive = mech.drive
    view, cylinder, cylinder2 = mech, None, None
    originals: dict[Pair, Pair] = {}
    if drive.kind is DriverKind.CYLINDER:
        view, originals, cylinder = _merged_cylinder(mech, drive)
        known = {GROUND}
    else:
        _check_driving_pair(mech)
        known = {GROUND, drive.link}
    second = mech.drive2
    if second is not None and second.kind is DriverKind.CYLINDER:
        view, more, cylinder2 = _merged_cylinder(view, second, key="drive2.link")
        originals = {q: originals.get(p, p) for q, p in more.items()}
    elif second is not None:       # a crank or a slider on a frame guide: known as the first
        _check_second_crank(mech, second)
        known.add(second.link)
    remaining = [k for k in view.moving if k not in known]
    groups: list[Group | Triad] = []
    while remaining:
        group: Group | Triad | None = _find_dyad(view, remaining, known)
        if group is None:
            group = _find_triad(view, remaining, known)
        if group is None:
            _raise_undecomposable(view, remaining, known)
        assert group is not None
        if isinstance(group, Group) and originals:
            group = Group(group.links, *(originals.get(p, p) for p in group.pairs))
        groups.append(group)
        known.update(group.links)
        remaining = [k for k in remaining if k not in known]
    for cyl, key in ((cylinder, "drive.link"), (cylinder2, "drive2.link")):
        _check_cylinder_group(groups, cyl, key)
    return Structure(len(mech.moving), len(mech.pairs), 0, drive.link, tuple(groups), cylinder,
                     second.link if second is not None else None, cylinder2)


def _check_cylinder_group(groups: list[Group | Triad], cylinder: tuple[str, str] | None,
                          key: str) -> None:
    """A cylinder closes a class II group (its side of driven length: RRR or RRP); refuse it
    as a leg of a class III group, naming the driver."""
    if cylinder is None:
        return
    for g in groups:
        if isinstance(g, Triad) and cylinder[0] in g.links:
            raise TopologyError(Text("drives3.structure.cylinder_in_triad", {
                "barrel": cylinder[0], "rod": cylinder[1], "group": g.name}), key=key)


def _check_second_crank(mech: Mechanism, second: Drive) -> None:
    link = second.link
    pairs = [p for p in mech.pairs_of(link) if p.other(link) == GROUND]
    if link == mech.drive.link:
        raise TopologyError(Text(
            "errmsg2.structure.second_driver_other",
            {"link": link, "first": mech.drive.link}), key="drive2.link")
    if second.kind is DriverKind.SLIDER:
        if len(pairs) != 1 or pairs[0].kind is not PairKind.PRISMATIC or pairs[0].a != link:
            raise TopologyError(Text("errmsg2.structure.slider_one_guide",
                                     {"link": link, "count": str(len(pairs))}),
                                key="drive2.link")
        return
    if len(pairs) != 1 or pairs[0].kind is not PairKind.REVOLUTE:
        raise TopologyError(Text("errmsg2.structure.second_driver_crank", {"link": link}),
                            key="drive2.link")


def _check_driving_pair(mech: Mechanism) -> None:
    drive = mech.drive
    drive_pairs = [p for p in mech.pairs_of(drive.link) if p.other(drive.link) == GROUND]
    if drive.kind is DriverKind.SLIDER:
        if (len(drive_pairs) != 1 or drive_pairs[0].kind is not PairKind.PRISMATIC
                or drive_pairs[0].a != drive.link):
            raise TopologyError(Text(
                "errmsg2.structure.slider_one_guide",
                {"link": drive.link, "count": str(len(drive_pairs))}),
                                key="drive.link")
        return
    if len(drive_pairs) != 1 or drive_pairs[0].kind is not PairKind.REVOLUTE:
        raise TopologyError(Text("errmsg2.structure.driver_crank", {"link": drive.link}),
                            key="drive.link")


def _merged_cylinder(mech: Mechanism, drive: Drive, key: str = "drive.link"
                     ) -> tuple[Mechanism, dict[Pair, Pair], tuple[str, str]]:
    """The mechanism with the cylinder's rod merged into its barrel (their pair driven)."""
    rod, barrel = drive.link, drive.carrier
    assert barrel is not None
    driven = [p for p in mech.pairs if p.kind is PairKind.PRISMATIC and p.a == rod
              and p.b == barrel]
    if len(driven) != 1:
        raise TopologyError(Text(
            "errmsg2.structure.rod_in_barrel",
            {"rod": rod, "barrel": barrel, "count": str(len(driven))}), key=key)
    originals: dict[Pair, Pair] = {}
    pairs: list[Pair] = []
    for p in mech.pairs:
        if p is driven[0]:
            continue
        q = replace(p, a=barrel if p.a == rod else p.a, b=barrel if p.b == rod else p.b)
        if q.a == q.b:
            raise TopologyError(Text(
                "errmsg2.structure.rod_second_pair",
                {"rod": rod, "barrel": barrel, "pair": p.name}), key=key)
        originals[q] = p
        pairs.append(q)
    ends = [p for p in pairs if p.joins(barrel)]
    if len(ends) != 2 or any(p.kind is not PairKind.REVOLUTE for p in ends):
        names = ", ".join(p.name for p in ends)
        raise TopologyError(Text(
            "errmsg2.structure.cylinder_pinned",
            {"barrel": barrel, "rod": rod, "names": names}), key=key)
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
            raise TopologyError(Text("errmsg2.structure.ppp_group", {"i": i, "j": j}),
                                key=f"links.{i}")
        return g
    return None


def _letters(g: Group) -> str:
    return g.outer1.kind.value + g.inner.kind.value + g.outer2.kind.value


def _find_triad(mech: Mechanism, remaining: list[str], known: set[str]) -> Triad | None:
    """A triad of remaining links attached to known ones: a base with three inner pairs, each to a
    leg with one outer pair to a known link (raise for a triad with pairs not supported)."""
    for base in remaining:
        inner = [p for p in mech.pairs_of(base) if p.other(base) in remaining]
        if len(inner) != 3 or _outer_pairs(mech, base, known):
            continue
        legs = tuple(p.other(base) for p in inner)
        if len(set(legs)) != 3:
            continue
        outer = [_outer_pairs(mech, leg, known) for leg in legs]
        if any(len(o) != 1 for o in outer):
            continue
        if any(len([p for p in mech.pairs_of(leg) if p.other(leg) in remaining]) != 1
               for leg in legs):
            continue
        triad = Triad(base, legs, (outer[0][0], outer[1][0], outer[2][0]),  # type: ignore[arg-type]
                      (inner[0], inner[1], inner[2]))
        if triad.kind != "RRR-RRR":
            raise TopologyError(
                Text("errmsg2.structure.triad_kind",
                     {"links": ", ".join(triad.links), "base": base,
                      "pairs": ", ".join(p.name for p in triad.pairs), "kind": str(triad.kind)}),
                key=f"links.{base}")
        return triad
    return None


def _raise_undecomposable(mech: Mechanism, remaining: list[str], known: set[str]) -> None:
    for quad in itertools.combinations(remaining, 4):
        inside = [p for p in mech.pairs if p.a in quad and p.b in quad]
        outside = [p for p in mech.pairs if (p.a in quad) != (p.b in quad)
                   and (p.a in known or p.b in known)]
        if len(inside) == 4 and len(outside) == 2:
            raise TopologyError(
                Text(
                "errmsg2.structure.class_four",
                {"links": ', '.join(quad), "inside": ', '.join(p.name for p in inside),
                 "outside": ', '.join(p.name for p in outside)}), key="links")
    if len(remaining) >= 4:
        raise TopologyError(
            Text(
            "errmsg2.structure.no_group",
            {"links": ', '.join(remaining), "known": ', '.join(sorted(known))}), key="links")
    raise TopologyError(Text(
        "errmsg2.structure.not_split",
        {"links": ', '.join(remaining), "known": ', '.join(sorted(known))}),
                        key="links")
