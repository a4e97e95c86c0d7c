"""How the position plan draws a link: the outline of its rigid points and, along each guide it
carries (a coulisse's slot), one line through every point on the guide — the sliding points of
the blocks in it included, so a coulisse O3–A–B is drawn whatever joins it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from ..drafting.primitives import Line, Polyline, Primitive, Role
from ..model.mechanism import GROUND, Mechanism, PairKind

#: points of a link closer than this (m) to a line of it lie on the line
ON_LINE_M = 1e-9


@dataclass(frozen=True, slots=True)
class LinkFigure:
    """The point chains that draw one link.

    ``polygon``: the rigid points around the link's outline, drawn closed (three or more points
    not on one line). ``lines``: sets of points on one line, each drawn as one segment between
    the two farthest apart (a bar, or a guide with the sliding points in it).
    """

    polygon: tuple[str, ...] = ()
    lines: tuple[tuple[str, ...], ...] = ()

    @property
    def points(self) -> tuple[str, ...]:
        """Every point the figure passes through."""
        return tuple(dict.fromkeys(self.polygon + tuple(p for ln in self.lines for p in ln)))


def _distance_to_line(p: tuple[float, float], o: tuple[float, float], angle: float) -> float:
    return abs((p[0] - o[0]) * math.sin(angle) - (p[1] - o[1]) * math.cos(angle))


def _collinear(pts: list[tuple[float, float]]) -> bool:
    a, b = max(((p, q) for p in pts for q in pts), key=lambda pq: math.dist(*pq))
    if math.dist(a, b) < ON_LINE_M:
        return True
    angle = math.atan2(b[1] - a[1], b[0] - a[0])
    return all(_distance_to_line(p, a, angle) < ON_LINE_M for p in pts)


def _around(local: Mapping[str, tuple[float, float]]) -> tuple[str, ...]:
    """The points on the convex outline, in order around it (points on an edge kept in place,
    points inside left out)."""
    names = list(local)
    cx = sum(local[n][0] for n in names) / len(names)
    cy = sum(local[n][1] for n in names) / len(names)
    ordered = sorted(names, key=lambda n: math.atan2(local[n][1] - cy, local[n][0] - cx))
    hull = _hull([local[n] for n in ordered])
    return tuple(n for n in ordered if _on_hull(local[n], hull))


def _hull(pts: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Andrew's monotone chain (counter-clockwise, no collinear vertices)."""
    ps = sorted(set(pts))

    def cross(o, a, b) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower: list[tuple[float, float]] = []
    upper: list[tuple[float, float]] = []
    for p in ps:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(ps):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _on_hull(p: tuple[float, float], hull: list[tuple[float, float]]) -> bool:
    for a, b in zip(hull, hull[1:] + hull[:1]):
        ab = math.dist(a, b)
        if ab > 0 and _distance_to_line(p, a, math.atan2(b[1] - a[1], b[0] - a[0])) < ON_LINE_M \
                and math.dist(a, p) + math.dist(p, b) <= ab + ON_LINE_M:
            return True
    return False


def link_figure(mech: Mechanism, link_id: str) -> LinkFigure:
    """The chains of points that draw link ``link_id`` on the position plan."""
    lk = mech.links[link_id]
    local = dict(lk.points)
    guide_lines: list[tuple[str, ...]] = []
    for g in mech.guides.values():
        if g.link != link_id:
            continue
        on = [n for n, p in local.items() if _distance_to_line(p, g.origin, g.angle) < ON_LINE_M]
        sliding = [pr.point for pr in mech.pairs if pr.kind is PairKind.PRISMATIC
                   and pr.b == link_id and pr.guide == g.name and pr.point not in on]
        if sliding and len(on) + len(sliding) >= 2:
            guide_lines.append(tuple(on + sliding))
    rigid: tuple[str, ...] = ()
    lines: list[tuple[str, ...]] = []
    if len(local) >= 2:
        if _collinear(list(local.values())):
            if not any(set(local) <= set(g) for g in guide_lines):
                lines.append(tuple(local))
        else:
            rigid = _around(local)
    return LinkFigure(rigid, tuple(lines + guide_lines))


def link_figures(mech: Mechanism) -> dict[str, LinkFigure]:
    """:func:`link_figure` of every moving link."""
    return {lid: link_figure(mech, lid) for lid in mech.links if lid != GROUND}


def drawn(figure: LinkFigure, at: Mapping[str, tuple[float, float]], role: Role) -> list[Primitive]:
    """The lines of a figure with its points at ``at`` (sheet mm; points missing there are
    left out)."""
    out: list[Primitive] = []
    poly = [at[n] for n in figure.polygon if n in at]
    if len(poly) > 2:
        out.append(Polyline(tuple(poly), role, closed=True))
    elif len(poly) == 2 and math.dist(*poly) > 1e-6:
        out.append(Line(poly[0], poly[1], role))
    for names in figure.lines:
        pts = [at[n] for n in names if n in at]
        if len(pts) < 2:
            continue
        a, b = max(((p, q) for p in pts for q in pts), key=lambda pq: math.dist(*pq))
        if math.dist(a, b) > 1e-6:
            out.append(Line(a, b, role))
    return out
