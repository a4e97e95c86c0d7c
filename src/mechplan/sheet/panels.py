"""Panels of a sheet: each plan drawn from its evaluated construction steps, with its tables.

A panel is built in its own millimetre coordinates; the layout moves it into place. Nothing here
computes mechanics: values come from an evaluated construction, this module only scales them by μ
and decides line kinds, labels and table cells.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.ops import Drawn, spec
from ..construct.ops import Line as LineStyle
from ..construct.protocol import mm
from ..construct.protocol import plan_title as plan_name
from ..construct.segments import SegmentKind
from ..construct.step import Kind
from ..construct.terms import pole_label
from ..drafting.fonts import font_of, text_width_mm
from ..drafting.labels import LabelPlacer
from ..drafting.primitives import (
    Arrow,
    Circle,
    HAlign,
    Line,
    Polyline,
    Primitive,
    Role,
    Table,
    Text,
    VAlign,
)
from ..i18n import message, scale_factor, unit
from ..i18n import number as format_number
from ..model.plans import Plan
from .link_outline import drawn as draw_figure
from .link_outline import link_figures

#: line style of an operation's drawing rule → layer role
ROLES = {LineStyle.DASHED: Role.DASHED, LineStyle.THIN: Role.THIN, LineStyle.OUTLINE: Role.OUTLINE}
LABEL_H = 3.5
#: points of a plan closer than this (mm) are drawn as one point with one label ("c≡d")
SAME_POINT_MM = 0.5
TITLE_H = 5.0
TABLE_H = 2.5
ROW = 5.0


@dataclass
class Panel:
    """Primitives in panel millimetres with the box they occupy.

    ``refit(width, height)``, when given, redraws the panel as one or more panels each at most
    ``width`` × ``height`` mm (a table split into column or row groups, text wrapped to the
    width); the layout calls it only for a panel larger than the sheet's drawing area.
    """

    name: str
    primitives: list[Primitive | Table] = field(default_factory=list)
    plan: Plan | None = None        # the plan a panel of plans shows (None: a diagram, a table)
    refit: Callable[[float, float], list[Panel]] | None = None
    #: ``split_off(width, height)``, when given: the panel as a first part of at most
    #: ``width`` × ``height`` mm and the rest in one panel (split again where it is placed) — how
    #: the layout fills a sheet's free room (else with ``refit``)
    split_off: Callable[[float, float], list[Panel]] | None = None
    #: index in ``primitives`` → id of the construction step that draws it (the replay's order)
    steps: dict[int, str] = field(default_factory=dict)

    def tag(self, step_id: str, *prims: Primitive) -> None:
        """Append primitives drawn by one construction step."""
        for p in prims:
            self.steps[len(self.primitives)] = step_id
            self.primitives.append(p)

    def bounds(self) -> tuple[float, float, float, float]:
        """(x0, y0, x1, y1) of everything drawn."""
        xs: list[float] = []
        ys: list[float] = []
        for p in self.primitives:
            for x, y in _points_of(p):
                xs.append(x)
                ys.append(y)
        return (min(xs), min(ys), max(xs), max(ys)) if xs else (0.0, 0.0, 0.0, 0.0)


def _points_of(p: Primitive | Table) -> list[tuple[float, float]]:
    if isinstance(p, (Line, Arrow)):
        return [p.start, p.end]
    if isinstance(p, Polyline):
        return list(p.points)
    if isinstance(p, Circle):
        (x, y), r = p.center, p.radius
        return [(x - r, y - r), (x + r, y + r)]
    if isinstance(p, Text):
        w = text_width_mm(p.string, p.height_mm, font_of(p))
        x, y = p.position
        dx = {HAlign.LEFT: 0.0, HAlign.CENTER: -w / 2, HAlign.RIGHT: -w}[p.halign]
        dy = {
            VAlign.BASELINE: 0.0,
            VAlign.BOTTOM: 0.0,
            VAlign.MIDDLE: -p.height_mm / 2,
            VAlign.TOP: -p.height_mm,
        }[p.valign]
        return [(x + dx, y + dy - 0.3 * p.height_mm), (x + dx + w, y + dy + p.height_mm)]
    if isinstance(p, Table):
        x0, y0 = p.origin
        return [(x0, y0), (x0 + sum(p.column_widths_mm), y0 - sum(p.row_heights_mm))]
    return []


def mu_text(plan: Plan, mu: float, lang: str) -> str:
    """ "μv = 0,1 (m/s)/mm" in the sheet's decimal mark; "μF = 1000 N/mm" (never "1")."""
    sym, si_unit = plan.scale_symbol, plan.scale_unit
    return f"{sym} = {scale_factor(mu, lang)} {unit(si_unit, lang)}"


def table(rows: Sequence[tuple[str, ...]], origin: tuple[float, float]) -> Table:
    """A table whose column widths fit their texts."""
    ncol = len(rows[0])
    widths = tuple(max(text_width_mm(r[c], TABLE_H) for r in rows) + 3.0 for c in range(ncol))
    return Table(origin, widths, tuple(ROW for _ in rows), tuple(rows), TABLE_H)


def _mm(v: np.ndarray, mu: float) -> tuple[float, float]:
    return (float(v[0]) / mu, float(v[1]) / mu)


def _pos(ev: Evaluation, point: str) -> str:
    return ev.construction.position(point)


def _has(ev: Evaluation, point: str) -> bool:
    """Tell whether a point's position was evaluated."""
    c = ev.construction
    return c.has_position(point) and c.position(point) in ev.values


def _finite(*pts: tuple[float, float]) -> bool:
    return all(math.isfinite(x) and math.isfinite(y) for x, y in pts)


def vector_plan(
    c: Construction,
    ev: Evaluation,
    k: int,
    plan: Plan,
    mu: float,
    lang: str,
    title: str,
    group: str | None = None,
) -> Panel:
    """A velocity, acceleration or force plan at position k: lines, arrows, labels, tables.

    ``group`` keeps one group's steps only (each force polygon has a pole of its own).
    """
    panel = Panel(f"{plan.value}-{k}" + (f"-{group}" if group else ""), plan=plan)
    prims = panel.primitives
    steps = [
        s for s in c.of_plan(plan) if s.id in ev.values and (group is None or s.group == group)
    ]
    segments = [g for g in c.segments if g.plan is plan and (group is None or g.group == group)]
    if plan is Plan.FORCE:  # force vectors and lines of action are not polygon vertices
        steps = [
            s
            for s in steps
            if s.kind is not Kind.POINT or spec(s.op).draw in (Drawn.VERTEX, Drawn.MEET)
        ]
    pts: dict[str, tuple[float, float]] = {}
    for s in steps:
        if s.kind is Kind.POINT:
            p = _mm(ev[s.id][k], mu)
            if _finite(p):
                pts[s.id] = p
    # auxiliary construction lines: from the point they pass through to (and past) their meet
    for s in steps:
        if spec(s.op).draw is not Drawn.CONSTRUCTION_LINE:
            continue
        line = ev[s.id][k]
        through = _mm(line[0], mu)
        u = (float(line[1][0]), float(line[1][1]))
        meet = next(
            (
                m
                for m in steps
                if spec(m.op).draw is Drawn.MEET and s.id in m.inputs and m.id in pts
            ),
            None,
        )
        if meet is None or not _finite(through):
            continue
        end = pts[meet.id]
        t_end = (end[0] - through[0]) * u[0] + (end[1] - through[1]) * u[1]
        t0, t1 = min(0.0, t_end) - 8.0, max(0.0, t_end) + 8.0
        panel.tag(
            s.id,
            Line(
                (through[0] + t0 * u[0], through[1] + t0 * u[1]),
                (through[0] + t1 * u[0], through[1] + t1 * u[1]),
                ROLES[spec(s.op).line],
            )
        )
    # similarity images: the image triangle of a link
    for s in steps:
        if spec(s.op).draw is Drawn.IMAGE_TRIANGLE and s.id in pts:
            for src in (s.input("a"), s.input("b")):
                if src in pts and math.dist(pts[src], pts[s.id]) > 1e-6:
                    panel.tag(s.id, Line(pts[src], pts[s.id], ROLES[spec(s.op).line]))
    # vectors: absolute ones thick, components and relative ones thin
    for seg in segments:
        if seg.start not in pts or seg.end not in pts:
            continue
        a, b = pts[seg.start], pts[seg.end]
        if math.dist(a, b) < 0.5:
            continue
        thick = seg.kind in (SegmentKind.ABSOLUTE, SegmentKind.DRIVE, SegmentKind.REACTION)
        panel.tag(
            seg.end,
            Arrow(
                a,
                b,
                Role.OUTLINE if thick else Role.THIN,
                head_length_mm=3.5 if thick else 3.0,
                head_width_mm=1.2 if thick else 1.0,
            )
        )
    # points closer than SAME_POINT_MM are one point on paper, with one label "c≡d"
    seen: list[tuple[tuple[float, float], list[str]]] = []
    first: list[str] = []           # the step that draws each labelled point first
    for s in steps:
        if s.id not in pts or s.kind is not Kind.POINT:
            continue
        here = next((names for xy, names in seen if math.dist(xy, pts[s.id]) < SAME_POINT_MM),
                    None)
        if here is None:
            seen.append((pts[s.id], here := []))
            first.append(s.id)
        here.append(pole_label(s.label, lang))
        panel.tag(s.id, Circle(pts[s.id], 0.5, Role.OUTLINE))
    placer = LabelPlacer([p for p in prims if isinstance(p, (Line, Arrow))], LABEL_H,
                         [xy for xy, _ in seen])
    owners: list[str] = []          # the step of each leader, in the order the placer drew them
    for (anchor, labels), sid in zip(seen, first, strict=True):
        panel.tag(sid, placer.place(anchor, "≡".join(dict.fromkeys(labels))))
        owners += [sid] * (len(placer.leaders) - len(owners))
    for sid, leader in zip(owners, placer.leaders, strict=False):
        panel.tag(sid, leader)
    _title_and_tables(panel, c, ev, k, plan, mu, lang, title, segments, group)
    return panel


def _title_and_tables(
    panel: Panel,
    c: Construction,
    ev: Evaluation,
    k: int,
    plan: Plan,
    mu: float,
    lang: str,
    title: str,
    segments: list,
    group: str | None,
) -> None:
    x0, y0, _x1, y1 = panel.bounds()
    prims = panel.primitives
    prims.append(Text((x0, y1 + 9.0), title, TITLE_H))
    prims.append(Text((x0, y1 + 3.0), mu_text(plan, mu, lang), LABEL_H))

    def head(key: str) -> str:
        return message(f"sheet.head.{key}", lang)

    rows: list[tuple[str, ...]] = [
        (
            head("segment"),
            f"{head('on_paper')}, {mm(lang)}",
            head("quantity"),
            f"{head('value')}, {unit(plan.unit, lang)}",
        )
    ]
    for seg in segments:
        if seg.start not in ev.values or seg.end not in ev.values:
            continue
        length = float(np.hypot(*(ev[seg.end][k] - ev[seg.start][k])))
        if not math.isfinite(length):
            continue
        rows.append(
            (
                pole_label(seg.name, lang),
                format_number(length / mu, 1, lang),
                seg.quantity,
                format_number(length, 3, lang),
            )
        )
    y = y0 - 6.0
    if len(rows) > 1:
        t = table(rows, (x0, y))
        prims.append(t)
        y -= sum(t.row_heights_mm) + 4.0
    for (p, g), (eq, terms) in c.equations.items():
        if p is not plan or (group is not None and g != group):
            continue
        prims.append(Text((x0, y - TABLE_H), f"{g}:  {eq}", TABLE_H))
        y -= TABLE_H + 2.5
        t2 = table(
            [(head("term"), head("direction"), head("magnitude"))]
            + [(term, d.text(lang), m) for term, d, m in terms],
            (x0, y),
        )
        prims.append(t2)
        y -= sum(t2.row_heights_mm) + 4.0


def position_plan(
    c: Construction,
    ev_all: Evaluation,
    ev_traj: Evaluation,
    mech,
    highlight: list[int],
    extremes: list[float],
    ev_ext: Evaluation | None,
    mu: float,
    lang: str,
    title: str,
    numbers: list[str],
) -> Panel:
    """Positions overlaid (highlighted ones thick), trajectories, extreme positions, guides."""
    panel = Panel("position", plan=Plan.POSITION)
    prims = panel.primitives
    links = [lk for lk in mech.links.values() if lk.id != "0"]
    joints = {
        lk.id: [p for p in lk.points if any(pr.point == p for pr in mech.pairs_of(lk.id))]
        for lk in links
    }

    # a link's outline (a coupler point E closes the rigid triangle B, C, E) and the line of
    # each guide it carries through the blocks sliding in it (a coulisse O3–A–B)
    figures = link_figures(mech)

    def draw_links(ev: Evaluation, k: int, role: Role) -> None:
        for lk in links:
            at = {p: _mm(ev[_pos(ev, p)][k], mu) for p in figures[lk.id].points if _has(ev, p)}
            prims.extend(draw_figure(figures[lk.id], {p: q for p, q in at.items() if _finite(q)},
                                     role))

    # trajectories of points that do not move on a circle about the frame or along a guide
    crank = mech.drive.link
    for lk in links:
        if lk.id == crank or lk.slides_on:
            continue
        for p in lk.points:
            if p in mech.links["0"].points or not _has(ev_traj, p):
                continue
            if any(p in other.points for other in links if other.slides_on):
                continue
            path = [_mm(v, mu) for v in ev_traj[_pos(ev_traj, p)]]
            path = [q for q in path if _finite(q)]
            if len(path) > 2:
                prims.append(Polyline(tuple(path), Role.CHAIN))
    centre: tuple[float, float] | None = None
    if mech.drive.linear:       # a cylinder's or slider's pin carries the positions' numbers
        tip = mech.drive.pivot
    else:
        tip = next(p for p in mech.links[crank].points if p != mech.drive.pivot)
        centre = _mm(ev_all[_pos(ev_all, mech.drive.pivot)][0], mu)
        radius = math.dist(centre, _mm(ev_all[_pos(ev_all, tip)][0], mu))
        prims.append(Circle(centre, radius, Role.CHAIN))
    # the positions' numbers at the crank's tip, outward; placed with the points' labels
    small_labels: list[tuple[tuple[float, float], str, float | None]] = []
    for k in range(ev_all.n):
        draw_links(ev_all, k, Role.OUTLINE if k in highlight else Role.THIN)
        tip_mm = _mm(ev_all[_pos(ev_all, tip)][k], mu)
        if _finite(tip_mm):
            outward = (None if centre is None else
                       math.degrees(math.atan2(tip_mm[1] - centre[1], tip_mm[0] - centre[0])))
            small_labels.append((tip_mm, numbers[k], outward))
    if ev_ext is not None:
        for k in range(ev_ext.n):
            draw_links(ev_ext, k, Role.DASHED)
    # guides of the frame, along the travel of their sliders
    for lk in links:
        if not lk.slides_on:
            continue
        g = mech.guides[lk.slides_on]
        if g.link != "0":
            continue
        p = next(iter(lk.points))
        travel = np.asarray(ev_traj[_pos(ev_traj, p)])
        travel = travel[np.isfinite(travel).all(axis=1)]
        if travel.size == 0:
            continue
        u = np.array([math.cos(g.angle), math.sin(g.angle)])
        o = np.array(g.origin)
        t = (travel - o) @ u
        a, b = o + (t.min() - 10 * mu) * u, o + (t.max() + 10 * mu) * u
        prims.append(Line(_mm(a, mu), _mm(b, mu), Role.CHAIN))
        small_labels.append((_mm(b, mu), g.name, None))
    # sliders, frame pivots and joints of the highlighted positions
    for k in highlight:
        for lk in links:
            if lk.slides_on:
                g = mech.guides[lk.slides_on]
                p = _mm(ev_all[_pos(ev_all, next(iter(lk.points)))][k], mu)
                ang = g.angle if g.link == "0" else float(ev_all[c.link_angle(lk.id)][k])
                if _finite(p):
                    prims.append(_slider(p, ang))
        for p in dict.fromkeys(q for js in joints.values() for q in js):
            if _has(ev_all, p):
                q = _mm(ev_all[_pos(ev_all, p)][k], mu)
                if _finite(q):
                    prims.append(Circle(q, 1.0, Role.OUTLINE))
    for name in mech.links["0"].points:
        if any(name in js for js in joints.values()):
            prims.extend(_pivot(_mm(ev_all[_pos(ev_all, name)][0], mu)))
    k0 = highlight[0] if highlight else 0
    names = list(dict.fromkeys(p for lk in links for p in lk.points))
    for p in names:  # points that are not joints get a small marker too
        if not any(p in js for js in joints.values()) and _has(ev_all, p):
            q = _mm(ev_all[_pos(ev_all, p)][k0], mu)
            if _finite(q):
                prims.append(Circle(q, 0.8, Role.OUTLINE))
    anchors = {p: _mm(ev_all[_pos(ev_all, p)][k0], mu) for p in names if _has(ev_all, p)}
    anchors = {p: q for p, q in anchors.items() if _finite(q)}
    marked = [p.center for p in prims if isinstance(p, Circle) and p.role is Role.OUTLINE
              and p.radius <= 1.0]
    placer = LabelPlacer([p for p in prims if isinstance(p, (Line, Polyline))], LABEL_H,
                         list(anchors.values()) + marked, _ends(prims))
    for p, q in anchors.items():
        prims.append(placer.place(q, p))
    for at, text, toward in small_labels:
        prims.append(placer.place(at, text, 2.5, toward))
    prims.extend(placer.leaders)
    x0, _y0, _x1, y1 = panel.bounds()
    prims.append(Text((x0, y1 + 9.0), title, TITLE_H))
    prims.append(Text((x0, y1 + 3.0), mu_text(Plan.POSITION, mu, lang), LABEL_H))
    return panel


def _ends(prims: list) -> list[tuple[float, float]]:
    """Unmarked points a reader can give a label to: line ends and vertices of the links of every
    drawn position (not the dash-dot trajectories and axes, which it skips)."""
    out: list[tuple[float, float]] = []
    for p in prims:
        if isinstance(p, Line) and p.role is not Role.CHAIN:
            out += [p.start, p.end]
        elif isinstance(p, Polyline) and p.role is not Role.CHAIN:
            out += list(p.points)
    return out


def _slider(p: tuple[float, float], angle: float) -> Polyline:
    c, s = math.cos(angle), math.sin(angle)
    corners = [(-6.0, -3.5), (6.0, -3.5), (6.0, 3.5), (-6.0, 3.5)]
    return Polyline(
        tuple((p[0] + c * x - s * y, p[1] + s * x + c * y) for x, y in corners),
        Role.OUTLINE,
        closed=True,
    )


def _pivot(p: tuple[float, float]) -> list[Primitive]:
    x, y = p
    out: list[Primitive] = [
        Polyline(((x, y), (x - 4.0, y - 6.0), (x + 4.0, y - 6.0)), Role.OUTLINE, closed=True),
        Line((x - 6.0, y - 6.0), (x + 6.0, y - 6.0), Role.OUTLINE),
    ]
    out += [
        Line((x - 6.0 + 2.0 * i, y - 6.0), (x - 8.0 + 2.0 * i, y - 8.5), Role.THIN)
        for i in range(7)
    ]
    return out


def plan_title(plan: Plan, lang: str, k: int, phi_deg: float | str,
               group: str | None = None) -> str:
    """ "Họa đồ vận tốc — vị trí 1, φ = 30°" (and the group of a force polygon); ``phi_deg`` a
    text: a linear driver's coordinate ("l4 = 1562.5 mm")."""
    head = plan_name(plan, lang) + (f" {group}" if group else "")
    position = message("sheet.position", lang)
    at = phi_deg if isinstance(phi_deg, str) else f"φ = {format_number(phi_deg, 1, lang)}°"
    return f"{head} — {position} {k}, {at}"
