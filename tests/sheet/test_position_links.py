"""Every link is drawn on the position plan at every drawn position, and Zhukovsky's lever has its
vertex labels inside its panel (checked on the drawn primitives)."""

from __future__ import annotations

import functools
import math

import pytest
from scenes import ROOT, TEMPLATES
from shapely import box
from shapely.geometry import LineString, Point

from mechplan.construct.segments import SegmentKind
from mechplan.construct.terms import pole_label
from mechplan.drafting.primitives import Circle, Line, Polyline, Role, Text
from mechplan.model.mechanism import GROUND, PairKind
from mechplan.model.plans import Plan
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose, plan_positions
from mechplan.sheet.panels import _points_of
from mechplan.solve import solve

ON_MM = 0.01


@functools.cache
def _solved(stem: str):
    return solve(load_scene(ROOT / "templates" / f"{stem}.toml"))


@functools.cache
def _composed(stem: str):
    return compose(_solved(stem))


def _segments(panel, role: Role) -> list[LineString]:
    out = []
    for p in panel.primitives:
        if isinstance(p, Line) and p.role is role:
            out.append(LineString([p.start, p.end]))
        elif isinstance(p, Polyline) and p.role is role:
            pts = list(p.points) + ([p.points[0]] if p.closed else [])
            out += [LineString(pts[i:i + 2]) for i in range(len(pts) - 1)]
    return out


def _points_of_link(mech, link_id: str) -> list[str]:
    """The link's own points and the points of the blocks sliding in its guides."""
    lk = mech.links[link_id]
    sliding = [pr.point for pr in mech.pairs
               if pr.kind is PairKind.PRISMATIC and pr.b == link_id]
    return list(dict.fromkeys(list(lk.points) + sliding))


def _connected(names: list[str], edges: set[tuple[str, str]]) -> bool:
    seen, todo = {names[0]}, [names[0]]
    while todo:
        a = todo.pop()
        for b in names:
            if b not in seen and ((a, b) in edges or (b, a) in edges):
                seen.add(b)
                todo.append(b)
    return seen == set(names)


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_every_link_is_drawn_through_its_points_at_every_position(path):
    sol = _solved(path.stem)
    comp = _composed(path.stem)
    panel = next(p for placed in comp.placements for p, _ in placed if p.name == "position")
    mu = comp.scales[Plan.POSITION]
    mech, c = sol.scene.mechanism, sol.construction
    chosen = set(plan_positions(sol))
    checked = 0
    for k in range(sol.positions):
        role = Role.OUTLINE if k in chosen else Role.THIN
        segs = _segments(panel, role)
        for lid in mech.links:
            names = _points_of_link(mech, lid)
            if lid == GROUND or len(names) < 2:
                continue
            at = {n: Point(sol.ev[c.position(n)][k] / mu) for n in names}
            edges: set[tuple[str, str]] = set()
            for s in segs:
                on = [n for n in names if s.distance(at[n]) < ON_MM]
                edges |= {(a, b) for a in on for b in on if a != b}
            assert _connected(names, edges), (path.stem, k, lid, names, sorted(edges))
            checked += 1
    assert checked >= sol.positions


def test_the_coulisse_of_the_quick_return_is_one_line_through_o3_a_and_b():
    sol = _solved("quick_return")
    comp = _composed("quick_return")
    panel = next(p for p, _ in comp.placements[0] if p.name == "position")
    mu, c = comp.scales[Plan.POSITION], sol.construction
    k = plan_positions(sol)[0]
    o3, a, b = (Point(sol.ev[c.position(n)][k] / mu) for n in ("O3", "A", "B"))
    lines = [s for s in _segments(panel, Role.OUTLINE)
             if all(s.distance(q) < ON_MM for q in (o3, a, b))]
    assert lines and math.isclose(lines[0].length, o3.distance(b), rel_tol=1e-6)


def _lever_panels():
    out = []
    for path in TEMPLATES:
        sol = _solved(path.stem)
        if "force" not in sol.plans:
            continue
        comp = _composed(path.stem)
        for placed in comp.placements:
            out += [(path.stem, sol, comp, p, o) for p, o in placed if p.name.endswith("-lever")]
    return out


def test_zhukovsky_levers_label_their_vertices_inside_their_panel():
    levers = _lever_panels()
    assert len(levers) >= 3
    for stem, sol, comp, panel, (dx, dy) in levers:
        k = int(panel.name.split("-")[1])
        mu_v, c = comp.scales[Plan.VELOCITY], sol.construction
        x0, y0, x1, y1 = panel.bounds()
        inside = box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)
        texts = [t for t in panel.primitives if isinstance(t, Text)]
        vertices = [seg for seg in c.segments if seg.plan is Plan.VELOCITY
                    and seg.kind in (SegmentKind.ABSOLUTE, SegmentKind.DRIVE)]
        names = {s for seg in vertices for s in (seg.start, seg.end) if s in sol.ev.values}
        assert names, stem
        for sid in names:
            v = sol.ev[sid][k]
            at = Point(-float(v[1]) / mu_v, float(v[0]) / mu_v)
            if not all(math.isfinite(q) for q in at.coords[0]):
                continue
            label = pole_label(c[sid].label, sol.scene.language)
            near = [t for t in texts if label in t.string.split("≡")
                    and (box(*_bounds(t)).distance(at) < 2.0 or _led(panel, at, t))]
            assert near, (stem, panel.name, label)
        for p in panel.primitives:
            for x, y in _points_of(p):
                assert inside.buffer(1e-6).contains(Point(x + dx, y + dy)), (stem, p)
        assert any(isinstance(p, Circle) for p in panel.primitives)


def _led(panel, at: Point, t: Text) -> bool:
    """A label placed farther from its point has a leader from the point to its box."""
    label = box(*_bounds(t))
    return any(isinstance(p, Line) and p.role is Role.DIMENSION
               and Point(p.start).distance(at) < 0.6 and label.distance(Point(p.end)) < 1.0
               for p in panel.primitives)


def _bounds(t: Text) -> tuple[float, float, float, float]:
    (a, b), (c, d) = _points_of(t)
    return (a, b, c, d)
