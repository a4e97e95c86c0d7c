"""Compose the sheet a student hands in: frame, title block and every plan with its tables."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from shapely import box
from shapely.prepared import prep

from ..construct.extremes import extreme_positions
from ..construct.protocol import plan_title as plan_name
from ..construct.scale import round_scale
from ..construct.step import Plan
from ..drafting.frame import make_frame
from ..drafting.primitives import Arc, Arrow, Circle, Line, Polyline, Primitive, Sheet, Table, Text
from ..errors import DrawingError, MechplanError
from ..i18n import message
from ..model.mechanism import GROUND, PairKind
from ..solve import Solution
from .lever import lever_title, zhukovsky_lever
from .panels import Panel, plan_title, position_plan, vector_plan

GAP = 8.0          # mm between panels
MAX_PLAN_POSITIONS = 2


def _moved(p: Primitive | Table, dx: float, dy: float) -> Primitive | Table:
    def mv(q: tuple[float, float]) -> tuple[float, float]:
        return (q[0] + dx, q[1] + dy)
    if isinstance(p, (Line, Arrow)):
        return dataclasses.replace(p, start=mv(p.start), end=mv(p.end))
    if isinstance(p, Polyline):
        return dataclasses.replace(p, points=tuple(mv(q) for q in p.points))
    if isinstance(p, (Circle, Arc)):
        return dataclasses.replace(p, center=mv(p.center))
    if isinstance(p, Text):
        return dataclasses.replace(p, position=mv(p.position))
    if isinstance(p, Table):
        return dataclasses.replace(p, origin=mv(p.origin))
    raise DrawingError(f"cannot move a {type(p).__name__}")


def plan_positions(sol: Solution) -> list[int]:
    """Positions whose velocity and acceleration plans go on the sheet."""
    chosen = [k for k in sol.scene.drawing.plan_positions if k < sol.positions]
    if chosen:
        return chosen
    if sol.scene.positions.angles:
        return list(range(min(sol.positions, MAX_PLAN_POSITIONS)))
    return [1 % sol.positions]


def _extreme_phis(sol: Solution) -> list[float]:
    mech = sol.scene.mechanism
    subjects: list[str] = []
    for lk in mech.links.values():
        if lk.id in (GROUND, mech.drive.link):
            continue
        if lk.slides_on and mech.guides[lk.slides_on].link == GROUND:
            subjects.append(next(iter(lk.points)))
        elif any(
            p.kind is PairKind.REVOLUTE and GROUND in (p.a, p.b) for p in mech.pairs_of(lk.id)
        ):
            subjects.append(lk.id)
    phis: list[float] = []
    for s in subjects:
        try:
            phis += [e.phi for e in extreme_positions(sol.construction, mech, s)]
        except MechplanError:
            continue
    return sorted({round(p, 12) for p in phis})


def _panels(sol: Solution, mu: dict[Plan, float], lang: str) -> list[Panel]:
    c, scene = sol.construction, sol.scene
    ev_all = sol.ev
    ev_traj = c.evaluate(np.linspace(0.0, 2 * math.pi, 241))
    extremes = _extreme_phis(sol)
    ev_ext = c.evaluate(np.asarray(extremes)) if extremes else None
    if ev_ext is not None:
        for p in (q for lk in scene.mechanism.links.values() for q in lk.points):
            ev_ext.get(c.position(p))
    for p in (q for lk in scene.mechanism.links.values() for q in lk.points):
        ev_traj.get(c.position(p))
        ev_all.get(c.position(p))
    highlight = plan_positions(sol)
    numbers = [str(k) for k in range(sol.positions)]
    title = plan_name(Plan.POSITION, lang)
    panels = [position_plan(c, ev_all, ev_traj, scene.mechanism, highlight, extremes, ev_ext,
                            mu[Plan.POSITION], lang, title, numbers)]
    for k in highlight:
        phi_deg = math.degrees(float(sol.phi[k]))
        for plan in (Plan.VELOCITY, Plan.ACCELERATION):
            if plan.value in sol.plans and any(s.plan is plan for s in c.segments):
                panels.append(_marked(vector_plan(c, ev_all, k, plan, mu[plan], lang,
                                                  plan_title(plan, lang, k, phi_deg)),
                                      sol, k, plan, lang))
        if "force" in sol.plans:
            groups = list(dict.fromkeys(s.group for s in c.segments if s.plan is Plan.FORCE))
            for group in groups:
                panels.append(vector_plan(c, ev_all, k, Plan.FORCE, mu[Plan.FORCE], lang,
                                          plan_title(Plan.FORCE, lang, k, phi_deg, group), group))
            lever = zhukovsky_lever(c, ev_all, k, mu[Plan.VELOCITY], lang,
                                    lever_title(lang, phi_deg))
            if lever is not None:
                panels.append(lever)
    return panels


def _marked(panel: Panel, sol: Solution, k: int, plan: Plan, lang: str) -> Panel:
    """Add a warning under a plan drawn at a position whose results have a poor error estimate."""
    worst = 0.0
    for sid in sol.targets:
        if sid in sol.estimate and sol.construction[sid].plan is plan:
            worst = max(worst, float(sol.estimate.relative(sid)[k]))
    if worst > sol.tolerance:
        x0, y0, _, _ = panel.bounds()
        estimate = f"{worst:.1e}" if math.isfinite(worst) else "∞"
        panel.primitives.append(Text((x0, y0 - 6.0), message("estimate.sheet_mark", lang,
                                                             estimate=estimate), 3.5))
    return panel


def packing_area(frame):
    """The drawing area kept clear of the frame's centring marks (6 mm) and the title block."""
    f, t = frame.frame, frame.title_block
    inner = box(f.x0 + 7.0, f.y0 + 7.0, f.x1 - 7.0, f.y1 - 7.0)
    return inner.difference(box(t.x0 - 3.0, t.y0 - 3.0, t.x1 + 3.0, t.y1 + 3.0)).intersection(
        frame.drawing_area)


def _pack(panels: list[Panel], area) -> tuple[list[tuple[float, float]], int | None]:
    """Top-left-first packing inside the drawing area; also the index of a panel not fitting."""
    inside = prep(area)
    ax0, ay0, ax1, ay1 = area.bounds
    placed: list = []
    offsets: list[tuple[float, float]] = []
    for panel in panels:
        x0, y0, x1, y1 = panel.bounds()
        w, h = x1 - x0 + GAP, y1 - y0 + GAP
        candidates = {(ax0 + GAP / 2, ay1 - GAP / 2)}
        for r in placed:
            bx0, by0, bx1, by1 = r.bounds
            candidates |= {(bx1, by1), (bx0, by0), (ax0 + GAP / 2, by0), (bx1, ay1 - GAP / 2)}
        grid = [(ax0 + i * 10.0, ay1 - j * 10.0) for j in range(int((ay1 - ay0) / 10) + 1)
                for i in range(int((ax1 - ax0) / 10) + 1)]
        best = None
        for cx, cy in sorted(candidates, key=lambda q: (-q[1], q[0])) + grid:
            rect = box(cx, cy - h, cx + w, cy)
            if inside.contains(rect) and not any(rect.intersects(r) and
                                                 rect.intersection(r).area > 1e-6 for r in placed):
                best = rect
                break
        if best is None:
            return offsets, panels.index(panel)
        placed.append(best)
        bx0, by0, _, by1 = best.bounds
        offsets.append((bx0 + GAP / 2 - x0, by1 - GAP / 2 - y1))
    return offsets, None


def _largest(sol: Solution, plan: Plan, positions: list[int]) -> float:
    """Longest segment of a plan at the drawn positions (physical units)."""
    ev, out = sol.ev, 0.0
    for seg in sol.construction.segments:
        if seg.plan is plan and seg.start in ev.values and seg.end in ev.values:
            d = np.hypot(*(ev[seg.end][positions] - ev[seg.start][positions]).T)
            if np.isfinite(d).any():
                out = max(out, float(np.nanmax(d)))
    return out or 1.0


def _plan_of(panel: Panel) -> Plan:
    if panel.plan is None:       # the linkage sheet composes only panels of plans
        raise DrawingError(f"panel {panel.name!r} shows no plan")
    return panel.plan


def _area(panel: Panel) -> float:
    x0, y0, x1, y1 = panel.bounds()
    return (x1 - x0) * (y1 - y0)


def scale_field(mu_l: float) -> str:
    """Drawing scale of the position plan as a ratio ("1:2.5")."""
    r = mu_l * 1000.0
    return f"1:{r:g}" if r >= 1 else f"{1 / r:g}:1"


def compose_sheets(sol: Solution, size: str | None = None, standard: str | None = None,
                   lang: str | None = None, name: str = "sheet") -> list[Sheet]:
    """The sheets of :func:`compose`."""
    return compose(sol, size, standard, lang, name).sheets


def compose(sol: Solution, size: str | None = None, standard: str | None = None,
            lang: str | None = None, name: str = "sheet") -> Composition:
    """Lay out the plans of a solution on framed sheets.

    Everything goes on one sheet when it fits; otherwise the force analysis gets a second sheet, as
    course projects do. Free scale factors shrink by round steps until their plans fit; scale
    factors fixed by the scene never change.
    """
    scene = sol.scene
    lang = lang or scene.language
    size = size or scene.drawing.sheet
    standard = standard or scene.drawing.standard
    frame = make_frame(size, standard, {"title": scene.title}, language=lang)
    short_side = min(frame.frame.width, frame.frame.height)
    # free scale factors start large (a vector plan about 40 % of the sheet's short side) and
    # shrink by one round step at a time until everything fits
    drawn = plan_positions(sol)
    mu0 = {plan: sol.scales.get(plan, 1.0) if key in scene.drawing.scales
           else round_scale(_largest(sol, plan, drawn) / (0.4 * short_side))
           for plan, key in FIXED.items()}
    if Plan.POSITION.scale_key not in scene.drawing.scales:
        mu0[Plan.POSITION] = round_scale(
            sol.scales.get(Plan.POSITION, 1.0) * 150.0 / (0.45 * short_side)
        )
    for split in (False, True):
        composition = _fit(sol, dict(mu0), size, standard, lang, name, split)
        if composition is not None:
            return composition
    fixed = ", ".join(f"{k} = {mu0[p]:g}" for p, k in FIXED.items() if k in scene.drawing.scales)
    raise DrawingError(f"the plans do not fit on {size} sheets at the scale factors "
                       f"{fixed or 'chosen'}; use a larger sheet (--sheet A0) or larger scale "
                       "factors in [drawing.scales]", file=scene.path)


#: plan → its scale-factor key (``mu_l``, ``mu_v``, …), which a scene may fix
FIXED = {plan: plan.scale_key for plan in Plan}


@dataclasses.dataclass(frozen=True)
class Composition:
    """Sheets, the panels placed on each (with their offsets) and the scale factors used."""

    sheets: list[Sheet]
    placements: list[list[tuple[Panel, tuple[float, float]]]]
    scales: dict[Plan, float]


def _fit(sol: Solution, mu: dict[Plan, float], size: str, standard: str, lang: str, name: str,
         split: bool) -> Composition | None:
    scene = sol.scene
    free = [p for p, key in FIXED.items() if key not in scene.drawing.scales]
    for _ in range(40):
        panels = _panels(sol, mu, lang)
        if split and any(_plan_of(p) is Plan.FORCE for p in panels):
            parts = [[p for p in panels if _plan_of(p) is not Plan.FORCE],
                     [p for p in panels if _plan_of(p) is Plan.FORCE]]
        elif split:
            return None
        else:
            parts = [panels]
        sheets: list[Sheet] = []
        placements: list[list[tuple[Panel, tuple[float, float]]]] = []
        failed_panel = None
        for i, part in enumerate(parts):
            fields = {"title": scene.title, "scale": scale_field(mu[Plan.POSITION]),
                      "sheet_number": str(i + 1), "sheets_total": str(len(parts))}
            fields.update({k: v for k, v in scene.drawing.title_block.items() if v})
            frame = make_frame(size, standard, fields, language=lang)
            offsets, failed = _pack(part, packing_area(frame))
            if failed is not None:
                failed_panel = part[failed]
                break
            placements.append(list(zip(part, offsets)))
            prims: list[Primitive] = []
            for panel, (dx, dy) in zip(part, offsets):
                for p in panel.primitives:
                    moved = _moved(p, dx, dy)
                    prims.extend(moved.expand() if isinstance(moved, Table) else (moved,))
            sheets.append(frame.sheet(prims, name if i == 0 else f"{name}-{i + 1}"))
        if failed_panel is None:
            return Composition(sheets, placements, dict(mu))
        plan = _plan_of(failed_panel)
        if plan not in free:
            in_part = {_plan_of(p) for p in parts[0 if failed_panel in parts[0] else -1]} & set(
                free
            )
            if not in_part:
                return None
            plan = max(in_part, key=lambda q: max((_area(x) for x in panels if _plan_of(x) is q),
                                                  default=0.0))
        mu[plan] = round_scale(mu[plan] * 1.0001 * 1.25)
    return None
