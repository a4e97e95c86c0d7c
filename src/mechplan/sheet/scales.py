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
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.ops import Drawn, spec
from ..construct.scale import ROUND_MANTISSAS, round_scale
from ..construct.step import Kind
from ..drafting.frame import make_frame
from ..i18n import decimal_mark, message, plan_title, tr, unit
from ..model.mechanism import GROUND
from ..model.plans import Plan
from ..scene.spec import Scene

#: default number of positions whose acceleration (and force) plans are drawn, angles given
MAX_PLAN_POSITIONS = 2
#: up to this many positions are drawn on the position plan (beyond: trajectories only)
MAX_DRAWN_POSITIONS = 36
#: up to this many positions of a sweep each gets its (small) velocity plan on sheet 1
MAX_VELOCITY_PLANS = 12
#: the sheet sizes, smallest first
SIZES = ("A4", "A3", "A2", "A1", "A0")
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
    """The smallest round μ at which an extent (physical units) fits width × height mm."""
    w, h = extent
    need = max(w / max(width_mm, 1.0), h / max(height_mm, 1.0))
    return round_scale(need) if need > 0 and math.isfinite(need) else 1.0


def _rows(c: Construction, plan: Plan, group: str | None = None) -> int:
    """Table rows drawn under one plan panel (a force polygon: one group's): its segments, and
    each vector equation with its terms."""
    def mine(p: Plan, g: str) -> bool:
        return p is plan and (group is None or g == group)

    segs = sum(1 for s in c.segments if mine(s.plan, s.group)) + 1
    # each equation: its caption, a heading row, its terms and a gap (about 14 mm + 5 per term)
    eqs = sum(len(terms) + 3 for (p, g), (_eq, terms) in c.equations.items() if mine(p, g))
    return segs + eqs


def _tables_mm(c: Construction, plan: Plan) -> float:
    """Height of the tables under the tallest panel of a plan (force: of one group's polygon)."""
    if plan is Plan.FORCE:
        groups = {s.group for s in c.segments if s.plan is plan}
        rows = max((_rows(c, plan, g) for g in groups), default=1)
    else:
        rows = _rows(c, plan)
    return rows * ROW_MM + 10.0


#: the tables of a plan go beside it, on their own panel, when under it they would leave the
#: plan less than this share of the drawing area's height
TABLES_APART = 0.4


def tables_apart(c: Construction, plan: Plan, r: Room) -> bool:
    """Whether a plan's tables go on a panel of their own (they are too tall to stand under the
    plan on this sheet: the plan would be squeezed to a strip)."""
    return r.height - _tables_mm(c, plan) - TITLE_MM - LINES_MM < TABLES_APART * r.height


@dataclass(frozen=True)
class PlanScale:
    """The scale factor of one plan and why: the panel its drawing fills, its extent.

    ``box`` is the panel (mm) the plan's points are to fill on this sheet (a velocity plan of
    every position: one cell of their grid); ``extent`` the plan's largest width and height in
    physical units; ``fixed`` the scene's own value (``[drawing.scales]``), ``kept`` whether it is
    used; ``enlarged`` when the plan got more room than its share so that its segments are
    readable, ``short`` when some labelled segment is still shorter than :data:`MIN_SEGMENT_MM`.
    """

    plan: Plan
    mu: float
    box: tuple[float, float]
    extent: tuple[float, float]
    fixed: float | None = None
    kept: bool = True
    enlarged: bool = False
    short: bool = False

    @property
    def fill(self) -> float:
        """Largest extent over its panel: the share of the panel the plan fills (0 … 1)."""
        return max(self.extent[0] / self.mu / max(self.box[0], 1.0),
                   self.extent[1] / self.mu / max(self.box[1], 1.0))


@dataclass(frozen=True)
class Decision:
    """The scale factors of every plan on one sheet size and standard, with their reasons."""

    size: str
    standard: str
    plans: dict[Plan, PlanScale]

    @property
    def scales(self) -> dict[Plan, float]:
        """μ of every plan."""
        return {p: s.mu for p, s in self.plans.items()}

    def not_kept(self) -> list[PlanScale]:
        """Plans whose value fixed in the scene could not be used on this sheet."""
        return [s for s in self.plans.values() if s.fixed is not None and not s.kept]


#: a plan's panel is never narrower than this (or the whole drawing width when it is narrower)
MIN_BOX_MM = 120.0
#: a cell of the grid of velocity plans of every position is at least this side (mm)
MIN_CELL_MM = 40.0
#: every labelled segment of a plan is drawn at least this long (mm)
MIN_SEGMENT_MM = 2.0
#: segments shorter than this share of their plan's extent cannot be made readable by any panel
#: (a vector passing through zero near a dead position): they are left out of the 2 mm rule
NEGLIGIBLE = 0.05


def _shortest(c: Construction, ev: Evaluation, plan: Plan, ks: list[int],
              extent: float) -> float:
    """The shortest segment of a plan at positions ``ks`` (physical units) that is not
    negligible against the plan's ``extent``; inf when there is none."""
    shortest = math.inf
    for s in c.segments:
        if s.plan is not plan or s.start not in ev.values or s.end not in ev.values:
            continue
        d = np.hypot(*(np.asarray(ev[s.end])[ks] - np.asarray(ev[s.start])[ks]).T)
        d = d[np.isfinite(d) & (d >= NEGLIGIBLE * extent)]
        if d.size:
            shortest = min(shortest, float(d.min()))
    return shortest


def _largest_round(per_mm: float) -> float:
    """The largest round μ ≤ per_mm."""
    mu = round_scale(per_mm)
    if mu <= per_mm * (1 + 1e-12):
        return mu
    k = math.floor(math.log10(mu) + 1e-12)
    m = mu / 10.0 ** k
    lower = [x for x in ROUND_MANTISSAS if x < m - 1e-9]
    return float(f"{(lower[-1] if lower else 0.5) * 10.0 ** k:.12g}")


@dataclass(frozen=True)
class _Place:
    """Where a plan goes on a sheet: its extent (physical), its share of the drawing area and
    the most it can get (mm), and the positions it is drawn at."""

    extent: tuple[float, float]
    box: tuple[float, float]
    room: tuple[float, float]
    positions: list[int]


def _places(scene: Scene, c: Construction, ev: Evaluation, r: Room) -> dict[Plan, _Place]:
    """The place of every plan on a sheet whose free rectangle is ``r``."""
    mech = scene.mechanism
    # the points drawn: those of the moving links (a far point of the frame that only gives a
    # force its direction is not drawn)
    points = list(dict.fromkeys(c.position(p) for lk in mech.links.values() if lk.id != GROUND
                                for p in lk.points))
    sweep = c.evaluate(np.linspace(0.0, 2.0 * math.pi, 73))
    for p in points:
        sweep.get(p)
    ext, ext_now = _extent(sweep, points, None), _extent(ev, points, None)
    wide = min(MIN_BOX_MM, r.width - LINES_MM)
    chosen = chosen_positions(scene, ev.n)
    every = velocity_positions(scene, ev.n)
    # the position plan: about half the width and three quarters of the height, with margins
    out = {Plan.POSITION: _Place((max(ext[0], ext_now[0]), max(ext[1], ext_now[1])),
                                 (max(0.55 * r.width - 40.0, wide), 0.75 * r.height - 40.0),
                                 (r.width - 40.0, r.height - 40.0), chosen)}
    for plan in (Plan.VELOCITY, Plan.ACCELERATION, Plan.FORCE):
        ks = every if plan is Plan.VELOCITY else chosen
        extent = (0.0, 0.0)
        groups = {s.group for s in c.of_plan(plan)} if plan is Plan.FORCE else {None}
        for g in groups:      # each force polygon is a panel of its own
            ids = [s.id for s in c.of_plan(plan) if s.kind is Kind.POINT and s.id in ev.values
                   and (g is None or (s.group == g
                                      and spec(s.op).draw in (Drawn.VERTEX, Drawn.MEET)))]
            e = _extent(ev, ids, ks)
            extent = (max(extent[0], e[0]), max(extent[1], e[1]))
        # the plan with its tables under it (or apart), its title and μ line, and construction
        # lines running past its points; at most the whole drawing area, its tables apart
        tables = 0.0 if tables_apart(c, plan, r) else _tables_mm(c, plan)
        tall = r.height - tables - TITLE_MM - LINES_MM
        box = (max(0.3 * r.width, wide), max(min(tall, 0.5 * r.height), 1.0))
        most = (r.width - LINES_MM, r.height - TITLE_MM - LINES_MM)
        if plan is Plan.VELOCITY and len(every) > len(chosen):
            # the velocity plans of every position share about 30 % of the drawing area
            cell = math.sqrt(0.3 * r.width * r.height / len(every)) - TITLE_MM
            cell = max(cell, min(MIN_CELL_MM, r.width - LINES_MM))
            box = (min(cell, box[0]), min(cell, box[1]))
            most = (r.width - LINES_MM, r.height - 2 * TITLE_MM - LINES_MM)
        out[plan] = _Place(extent, box, most, ks)
    return out


def _choose(plan: Plan, place: _Place, c: Construction, ev: Evaluation, fixed: float | None,
            own: bool) -> PlanScale:
    """The scale factor of one plan in its place (see :func:`decide`)."""
    extent, box = place.extent, place.box
    mu = _fit(extent, *box)
    at_room = _fit(extent, *place.room)
    enlarged = short = False
    shortest = _shortest(c, ev, plan, place.positions, max(extent))
    if math.isfinite(shortest) and shortest / mu < MIN_SEGMENT_MM:
        readable = _largest_round(shortest / MIN_SEGMENT_MM)
        if readable < mu:
            enlarged, mu = True, max(readable, at_room)
        short = shortest / mu < MIN_SEGMENT_MM
    kept = True
    if fixed is not None:
        kept = own or fixed >= at_room          # it fits the drawing area (tables apart)
        if kept:
            mu, box, enlarged = fixed, (box if fixed >= mu else place.room), False
            short = math.isfinite(shortest) and shortest / mu < MIN_SEGMENT_MM
    if enlarged:      # the plan gets the panel it needs (at most the drawing area)
        box = (max(box[0], extent[0] / mu), max(box[1], extent[1] / mu))
    return PlanScale(plan, mu, box, extent, fixed, kept, enlarged, short)


def decide(scene: Scene, c: Construction, ev: Evaluation, plans: tuple[str, ...] = (),
           size: str | None = None, standard: str | None = None) -> Decision:
    """Scale factors of every plan for a sheet size (the scene's own sheet by default).

    One rule for every plan on every size: μ is the smallest round value at which the plan's
    extent fits its panel — so the plan fills between half and all of it (the ladder 1, 2, 2.5,
    4, 5 has gaps of 2) — where a panel is the plan's share of the drawing area (never narrower
    than :data:`MIN_BOX_MM`); when a segment would be shorter than :data:`MIN_SEGMENT_MM` the plan
    gets up to the whole drawing area. A value fixed in the scene is kept on its own sheet, and on
    another wherever the plan fits the whole drawing area at it (``plans``: unused, kept for the
    callers of :func:`decide_scales`).
    """
    size = size or scene.drawing.sheet
    standard = standard or scene.drawing.standard
    own = size == scene.drawing.sheet and standard == scene.drawing.standard
    places = _places(scene, c, ev, room(size, standard))
    return Decision(size, standard, {
        plan: _choose(plan, place, c, ev, scene.drawing.scales.get(plan.scale_key), own)
        for plan, place in places.items()})


def decide_scales(scene: Scene, c: Construction, ev: Evaluation, plans: tuple[str, ...],
                  size: str | None = None, standard: str | None = None) -> dict[Plan, float]:
    """Scale factors of every plan for a sheet size (the scene's own sheet by default)."""
    return decide(scene, c, ev, plans, size, standard).scales


def mu_said(plan: Plan, mu: float, lang: str) -> str:
    """ "μa = 2,5 (m/s²)/mm": a scale factor in a sentence (every digit kept)."""
    value = f"{mu:.12g}".replace(".", decimal_mark(lang))
    return f"{plan.scale_symbol} = {value} {unit(plan.scale_unit, lang)}"


def notes(decision: Decision, lang: str, scene: Scene | None = None,
          c: Construction | None = None, ev: Evaluation | None = None) -> list[str]:
    """What the scale decision could not do as asked, in a language: values fixed in the scene
    not kept, plans given more room than their share, segments still shorter than 2 mm (with
    the smallest sheet that draws them long enough, when ``scene``, ``c`` and ``ev`` are given).
    """
    out: list[str] = []
    size, standard = decision.size, decision.standard.upper()
    for s in decision.plans.values():
        if s.fixed is None and s.extent == (0.0, 0.0):
            continue
        used = mu_said(s.plan, s.mu, lang)
        plan = tr(plan_title(s.plan.value), lang)
        if s.fixed is not None and not s.kept:
            out.append(message("scales.not_kept", lang, mu=mu_said(s.plan, s.fixed, lang),
                               plan=plan, size=size, standard=standard, used=used))
        if s.enlarged:
            out.append(message("scales.enlarged", lang, plan=plan, used=used, size=size,
                               min_mm=f"{MIN_SEGMENT_MM:g}"))
        if s.short:
            hint = message("scales.hint.none", lang)
            if scene is not None and c is not None and ev is not None:
                for bigger in SIZES[SIZES.index(size) + 1:] if size in SIZES else ():
                    other = decide(scene, c, ev, (), bigger, decision.standard).plans[s.plan]
                    if not other.short:
                        hint = message("scales.hint.sheet", lang, size=bigger)
                        break
            out.append(message("scales.short", lang, plan=tr(plan_title(s.plan.value,
                                                                        case="gen"), lang),
                               used=used, size=size, min_mm=f"{MIN_SEGMENT_MM:g}", hint=hint))
    return out


def decision_json(decision: Decision) -> dict[str, Any]:
    """The decision in ``solve --json``: the sheet, values fixed in the scene and not kept
    (scene's and used), plans enlarged for readable segments, plans with shorter segments."""
    plans = decision.plans.values()
    return {
        "sheet": decision.size, "standard": decision.standard,
        "not_kept": {s.plan.scale_key: {"scene": s.fixed, "used": s.mu}
                     for s in plans if s.fixed is not None and not s.kept},
        "enlarged": [s.plan.scale_key for s in plans if s.enlarged],
        "shorter_than_2mm": [s.plan.scale_key for s in plans if s.short],
    }


def drawable(c: Construction, ev: Evaluation, plan: Plan) -> bool:
    """Whether a plan has segments evaluated (and so is drawn)."""
    return any(s.plan is plan and s.start in ev.values for s in c.segments)


__all__ = [
    "Decision",
    "PlanScale",
    "Room",
    "chosen_positions",
    "decide",
    "decide_scales",
    "decision_json",
    "drawable",
    "mu_said",
    "notes",
    "room",
    "tables_apart",
    "velocity_positions",
]
