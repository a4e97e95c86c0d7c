"""The one scale-factor decision: μl, μv, μa, μF chosen for a sheet size.

`mechplan solve` (its segment tables and JSON), `mechplan draw` and `mechplan check` all take their
scale factors from :func:`decide_scales`, so the lengths a student copies from the report are the
lengths on the sheet. Values are round (1, 2, 2.5, 4, 5 × 10^k); a value fixed by the scene's
``[drawing.scales]`` is kept on the scene's own sheet (on another size it is kept when it fits,
else it shrinks like a free one). The free values are chosen so that every plan fits its place on
the chosen sheet: the position plan about half the drawing area, the velocity plans of all positions
(or of the chosen ones) together about a third, each other plan with its tables on a sheet alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.scale import round_scale
from ..construct.step import Kind
from ..drafting.frame import make_frame
from ..model.plans import Plan
from ..scene.spec import Scene

#: default number of positions whose acceleration (and force) plans are drawn, angles given
MAX_PLAN_POSITIONS = 2
#: up to this many positions are drawn on the position plan (beyond: trajectories only)
MAX_DRAWN_POSITIONS = 36
#: up to this many positions of a sweep each gets its (small) velocity plan on sheet 1
MAX_VELOCITY_PLANS = 12
ROW_MM = 5.0          # a table row
TITLE_MM = 16.0       # title and μ line above a plan, and margins
LINES_MM = 20.0       # construction lines past the plan's points and labels, both sides


@dataclass(frozen=True)
class Room:
    """The largest free rectangle of an empty sheet: full width above the title block (mm)."""

    width: float
    height: float


def room(size: str, standard: str, language: str = "en") -> Room:
    """Free rectangle of a framed sheet (the frame's marks and the title block kept clear)."""
    frame = make_frame(size, standard, {"title": ""}, language=language)
    f, t = frame.frame, frame.title_block
    return Room(f.width - 14.0 - 8.0, f.y1 - 7.0 - (t.y1 + 3.0) - 8.0)


def chosen_positions(scene: Scene, n: int) -> list[int]:
    """Positions whose acceleration and force plans (with tables) go on the sheets."""
    chosen = [k for k in scene.drawing.plan_positions if k < n]
    if chosen:
        return chosen
    if scene.positions.angles:
        return list(range(min(n, MAX_PLAN_POSITIONS)))
    return [1 % n]


def velocity_positions(scene: Scene, n: int) -> list[int]:
    """Positions whose velocity plans are drawn: all of them (sheet 1 of a course project) when
    the positions form a sweep of at most :data:`MAX_VELOCITY_PLANS`, else the chosen ones."""
    if not scene.positions.angles and 2 < n <= MAX_VELOCITY_PLANS:
        return list(range(n))
    return chosen_positions(scene, n)


def _extent(ev: Evaluation, ids: list[str], ks: list[int] | None) -> tuple[float, float]:
    """Largest width and height of the points ``ids`` taken together (per position if ks)."""
    arrays = [np.asarray(ev[i]) for i in ids if i in ev.values]
    if not arrays:
        return (0.0, 0.0)
    pts = np.stack(arrays, axis=1)             # (positions, points, 2)
    if ks is None:
        flat = pts.reshape(-1, 2)
        flat = flat[np.isfinite(flat).all(axis=1)]
        if flat.size == 0:
            return (0.0, 0.0)
        span = flat.max(axis=0) - flat.min(axis=0)
        return (float(span[0]), float(span[1]))
    w = h = 0.0
    for k in ks:
        p = pts[k]
        p = p[np.isfinite(p).all(axis=1)]
        if p.size:
            span = p.max(axis=0) - p.min(axis=0)
            w, h = max(w, float(span[0])), max(h, float(span[1]))
    return (w, h)


def _fit(extent: tuple[float, float], width_mm: float, height_mm: float) -> float:
    """Round μ so an extent (physical units) fits width × height mm."""
    w, h = extent
    need = max(w / max(width_mm, 1.0), h / max(height_mm, 1.0))
    return round_scale(need) if need > 0 and math.isfinite(need) else 1.0


def _rows(c: Construction, plan: Plan) -> int:
    """Table rows drawn under a plan: its segments, and each vector equation with its terms."""
    segs = sum(1 for s in c.segments if s.plan is plan) + 1
    # each equation: its caption, a heading row, its terms and a gap (about 14 mm + 5 per term)
    eqs = sum(len(terms) + 3 for (p, _g), (_eq, terms) in c.equations.items() if p is plan)
    return segs + eqs


def decide_scales(scene: Scene, c: Construction, ev: Evaluation, plans: tuple[str, ...],
                  size: str | None = None, standard: str | None = None) -> dict[Plan, float]:
    """Scale factors of every plan for a sheet size (the scene's own sheet by default)."""
    size = size or scene.drawing.sheet
    standard = standard or scene.drawing.standard
    r = room(size, standard)
    n = ev.n
    out: dict[Plan, float] = {}
    mech = scene.mechanism
    points = [c.position(p) for lk in mech.links.values() for p in lk.points]
    sweep = c.evaluate(np.linspace(0.0, 2.0 * math.pi, 73))
    for p in points:
        sweep.get(p)
    ext = _extent(sweep, points, None)
    ext_now = _extent(ev, points, None)
    ext = (max(ext[0], ext_now[0]), max(ext[1], ext_now[1]))
    # the position plan: about half the width and two thirds of the height, with its margins
    out[Plan.POSITION] = _fit(ext, 0.55 * r.width - 40.0, 0.75 * r.height - 40.0)
    chosen = chosen_positions(scene, n)
    for plan in (Plan.VELOCITY, Plan.ACCELERATION, Plan.FORCE):
        ids = [s.id for s in c.of_plan(plan) if s.kind is Kind.POINT and s.id in ev.values]
        if plan is Plan.FORCE:
            groups = {s.group for s in c.of_plan(plan)}
            extent = (0.0, 0.0)
            for g in groups:
                gid = [s.id for s in c.of_plan(plan) if s.group == g and s.kind is Kind.POINT
                       and s.id in ev.values]
                e = _extent(ev, gid, chosen)
                extent = (max(extent[0], e[0]), max(extent[1], e[1]))
        else:
            ks = velocity_positions(scene, n) if plan is Plan.VELOCITY else chosen
            extent = _extent(ev, ids, ks)
        tables = _rows(c, plan) * ROW_MM + 10.0
        # construction lines run 8 mm past their points and labels stand beside them
        side = min(0.3 * r.width, r.height - tables - TITLE_MM - LINES_MM, 0.5 * r.height)
        if plan is Plan.VELOCITY and len(velocity_positions(scene, n)) > len(chosen):
            count = len(velocity_positions(scene, n))
            cell = math.sqrt(0.3 * r.width * r.height / count) - TITLE_MM
            side = min(side, cell)
        out[plan] = _fit(extent, side, side)
    # the scene's own values hold on its own sheet; on another sheet they shrink if they must
    own = size == scene.drawing.sheet and standard == scene.drawing.standard
    for plan in Plan:
        if plan.scale_key in scene.drawing.scales:
            fixed = scene.drawing.scales[plan.scale_key]
            out[plan] = fixed if own else max(fixed, out[plan])
    return out


def drawable(c: Construction, ev: Evaluation, plan: Plan) -> bool:
    """Whether a plan has segments evaluated (and so is drawn)."""
    return any(s.plan is plan and s.start in ev.values for s in c.segments)


__all__ = ["Room", "chosen_positions", "decide_scales", "drawable", "room",
           "velocity_positions"]
