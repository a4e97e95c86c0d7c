"""Compose the sheet a student hands in: frame, title block and every plan with its tables."""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np
from shapely.geometry.base import BaseGeometry

from ..construct.extremes import extreme_positions
from ..construct.protocol import plan_title as plan_name
from ..construct.terms import pole_label
from ..drafting.frame import make_frame
from ..drafting.primitives import Sheet, Text
from ..errors import DrawingError, MechplanError
from ..i18n import Text as Msg
from ..i18n import message, scientific, significant, unit
from ..i18n import number as format_number
from ..model.mechanism import GROUND, PairKind
from ..model.plans import Plan
from ..solve import Solution
from .friction_diagram import efficiency_diagram
from .grow import GROWTH, grow_into_room
from .kinematics_sheet import (
    balancing_diagram,
    grid,
    kinematic_diagrams,
    small_plan,
    split_tables,
    tables_of,
)
from .layout import GOAL, Groups, coverage, drawing_area, fewest_sheets, framed
from .lever import lever_title, zhukovsky_lever
from .panels import Panel, plan_title, position_plan, vector_plan
from .scales import (
    MAX_DRAWN_POSITIONS,
    Room,
    chosen_positions,
    decide_scales,
    room,
    tables_apart,
    velocity_positions,
)
from .textbook import textbook_panels

GAP = 8.0          # mm between panels
#: the lengthenings of a diagram's φ axis tried (its height kept) once it grows no more as a whole
WIDER = (1.0, 1.1, 1.25, 1.4, 1.6, 1.8, 2.0, 2.25, 2.5, 2.8)
#: and the lengths of the kinematic diagrams' ordinates tried with each (a title unwrapped on a
#: wider diagram gives back room; a stack at its widest may fill the height under it)
TALLER = (1.0, 1.1, 1.2, 1.3, 1.4, 1.5)
#: the longest ordinates tried in turn (:func:`_grown_diagrams`)
TALLER_CAPS = (1.3, 1.5)
packing_area = drawing_area      # the drawing area clear of the centring marks and title block


def plan_positions(sol: Solution) -> list[int]:
    """Positions whose acceleration and force plans (with their tables) go on the sheets."""
    return chosen_positions(sol.scene, sol.positions)


def _extreme_phis(sol: Solution) -> list[float]:
    mech = sol.scene.mechanism
    subjects: list[str] = []
    for lk in mech.links.values():
        if lk.id in (GROUND, *(d.link for d in mech.drivers)):     # W = 2: both cranks
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


def _position_panel(sol: Solution, mu: float, lang: str) -> Panel:
    """The position plan: every position (up to MAX_DRAWN_POSITIONS) with the trajectories."""
    c, scene = sol.construction, sol.scene
    points = [c.position(q) for lk in scene.mechanism.links.values() for q in lk.points]
    chosen = plan_positions(sol)
    if sol.positions > MAX_DRAWN_POSITIONS:
        drawn = chosen
        ev_all = c.evaluate(sol.phi[drawn])
        highlight = list(range(len(drawn)))
    else:
        drawn, ev_all, highlight = list(range(sol.positions)), sol.ev, chosen
    ev_traj = c.evaluate(np.linspace(0.0, 2 * math.pi, 241))
    extremes = _extreme_phis(sol)
    ev_ext = c.evaluate(np.asarray(extremes)) if extremes else None
    for q in points:
        for ev in (ev_traj, ev_all) + ((ev_ext,) if ev_ext is not None else ()):
            ev.get(q)
    # the labelled (first highlighted) position in the title, as every plan of a position has
    # it: a sheet may hold this plan beside velocity plans of other positions (the grid of all
    # positions, cut to fit), and a reader tells the plans' positions apart by their titles
    title = (plan_title(Plan.POSITION, lang, chosen[0], position_at(sol, chosen[0], lang))
             if chosen else plan_name(Plan.POSITION, lang))
    panel = position_plan(c, ev_all, ev_traj, scene.mechanism, highlight, extremes, ev_ext, mu,
                          lang, title, [str(k) for k in drawn])
    if sol.positions > MAX_DRAWN_POSITIONS:
        x0, y0, _, _ = panel.bounds()
        panel.primitives.append(Text((x0, y0 - 5.0), message(
            "layout.positions.trajectories_only", lang, count=sol.positions,
            drawn=", ".join(str(k) for k in drawn)), 3.5))
    return panel


def _kinematics_panels(sol: Solution, mu: dict[Plan, float], lang: str, r: Room) -> list[Panel]:
    """Sheet 1: position plan; velocity plans of all positions, small and in order on a grid;
    per chosen position its velocity tables and acceleration plan; kinematic diagrams."""
    c = sol.construction
    panels = [_position_panel(sol, mu[Plan.POSITION], lang)]
    chosen = plan_positions(sol)
    has = {plan: plan.value in sol.plans and any(s.plan is plan for s in c.segments)
           for plan in (Plan.VELOCITY, Plan.ACCELERATION)}
    every = velocity_positions(sol.scene, sol.positions)
    if has[Plan.VELOCITY] and len(every) > len(chosen):
        small = [small_plan(vector_plan(c, sol.ev, k, Plan.VELOCITY, mu[Plan.VELOCITY], lang,
                                        "-"), k, position_at(sol, k, lang), lang) for k in every]
        panels += grid("velocity-all", small, r.width, r.height, title=message(
            "layout.velocity_plans", lang))
    for k in chosen:
        phi_deg = position_at(sol, k, lang)
        if has[Plan.VELOCITY]:
            vp = _marked(vector_plan(c, sol.ev, k, Plan.VELOCITY, mu[Plan.VELOCITY], lang,
                                     plan_title(Plan.VELOCITY, lang, k, phi_deg)),
                         sol, k, Plan.VELOCITY, lang)
            if len(every) > len(chosen):
                t = tables_of(vp, plan_title(Plan.VELOCITY, lang, k, phi_deg))
                if t.primitives:
                    panels.append(t)
            else:
                panels += split_tables(vp, plan_title(Plan.VELOCITY, lang, k, phi_deg),
                                       tables_apart(c, Plan.VELOCITY, r), r)
        if has[Plan.ACCELERATION]:
            title = plan_title(Plan.ACCELERATION, lang, k, phi_deg)
            ap = _marked(vector_plan(c, sol.ev, k, Plan.ACCELERATION, mu[Plan.ACCELERATION],
                                     lang, title), sol, k, Plan.ACCELERATION, lang)
            panels += split_tables(ap, title, tables_apart(c, Plan.ACCELERATION, r), r)
    panels += kinematic_diagrams(sol, lang, r) + textbook_panels(sol, lang)
    if "centres" in sol.plans and chosen:      # after the plans: they keep their places
        from .centres import centres_panels

        panels += centres_panels(sol, chosen[0], mu[Plan.POSITION], lang, r)
    return panels


def _force_panels(sol: Solution, mu: dict[Plan, float], lang: str, r: Room) -> list[Panel]:
    """Sheet 2: force polygons and Zhukovsky's lever per chosen position, then M_b(φ)."""
    c = sol.construction
    if "force" not in sol.plans:
        return []
    panels: list[Panel] = []
    groups = list(dict.fromkeys(s.group for s in c.segments if s.plan is Plan.FORCE))
    for k in plan_positions(sol):
        phi_deg = position_at(sol, k, lang)
        for group in groups:
            title = plan_title(Plan.FORCE, lang, k, phi_deg, group)
            panels += split_tables(vector_plan(c, sol.ev, k, Plan.FORCE, mu[Plan.FORCE], lang,
                                               title, group), title,
                                   tables_apart(c, Plan.FORCE, r), r)
        # the lever's loads at the force plans' μF: one μF on the sheet (the checker reads the
        # μF line nearest a polygon, and the lever's may be the nearest)
        lever = zhukovsky_lever(c, sol.ev, k, mu[Plan.VELOCITY], lang,
                                lever_title(lang, phi_deg), mu[Plan.FORCE])
        if lever is not None:
            panels.append(lever)
    mb = balancing_diagram(sol, lang, r)
    eta = efficiency_diagram(sol, lang, r)
    return panels + [d for d in (mb, eta) if d is not None]


def _diagrams(sol: Solution, lang: str, r: Room, tall: float = 1.0) -> list[Panel]:
    """The diagrams over φ of the sheets (kinematic, M_b, η) drawn for a room ``r``: the panels
    the layout may redraw larger (no plan's scale factor depends on them); ``tall``: the
    kinematic ones' ordinates that many times longer."""
    out = kinematic_diagrams(sol, lang, r, tall)
    if "force" in sol.plans:
        out += [d for d in (balancing_diagram(sol, lang, r), efficiency_diagram(sol, lang, r))
                if d is not None]
    return out


def _grown_diagrams(sol: Solution, lang: str, r: Room, groups: Groups,
                    area: BaseGeometry) -> Groups:
    """The diagrams over φ (their scales are their own) grown into their sheet's free room:
    redrawn larger as a whole, then in the shapes of a longer φ axis (:data:`WIDER`) and a
    taller one (:data:`TALLER`), each taken that fits and is larger — a stack of s, v, a
    narrower than the room beside it, where no panel fits, widens into it; a later panel that
    fits the room it leaves is pulled onto its sheet (:func:`.grow.grow_into_room`). The shapes
    are tried only where a full sheet is under the goal (a search of some 60 shapes, redrawn)."""
    found, grown = grow_into_room(lambda k: _diagrams(sol, lang, Room(r.width * k,
                                                                       r.height * k)),
                                  [g for g in GROWTH if g > 1.0], groups, area)
    if _emptiest(found, area)[0] == 0:      # every full sheet meets the goal: no reshaping
        return found

    def wider_in(shapes: list[tuple[float, float]], taller: bool) -> Groups:
        def wider(step: float) -> list[Panel]:
            kw, kt = shapes[int(step)]
            out: list[Panel] = []
            for kh in sorted(set(grown.values()) | {1.0}):
                out += [p for p in _diagrams(sol, lang, Room(r.width * kh * kw,
                                                             r.height * kh * kt),
                                             kt if taller else 1.0)
                        if grown.get(p.name, 1.0) == kh]
            return out

        return grow_into_room(wider, range(len(shapes)), found, area, pull=True, onward=True)[0]

    # each panel takes the largest shape that fits in turn, which need not fill the sheet best
    # when two diagrams share it: the room's height up to 1.3 (the kinematic ordinates capped at
    # 28 mm), and up to 1.5 with the kinematic ordinates lengthened as much again, both tried;
    # the set that leaves the fewest full sheets under the goal kept (then the fuller emptiest)
    tried = [wider_in(sorted(((kw, kt) for kw, kt in itertools.product(WIDER, TALLER)
                              if kt <= cap), key=lambda wh: (wh[0] * wh[1], wh[0])), taller)
             for cap, taller in zip(TALLER_CAPS, (False, True))]
    return min(tried, key=lambda g: (len(g), _emptiest(g, area)))


def _emptiest(groups: Groups, area: BaseGeometry) -> tuple[int, float]:
    """The count of full sheets (all but the last) under the goal, and minus the emptiest one's
    coverage."""
    full = [coverage(list(zip(p, o)), area) for p, o in groups[:-1]]
    return sum(c < GOAL for c in full), -min(full, default=1.0)


def position_at(sol: Solution, k: int, lang: str) -> float | str:
    """φ of position k in degrees (:func:`crank_degrees`), or a linear driver's coordinate as
    written on its plans' titles: "l4 = 1562.5 mm"."""
    if not sol.scene.mechanism.drive.linear:
        return crank_degrees(sol, k)
    label = pole_label(sol.construction["pos.q"].label, lang)
    return f"{label} = {format_number(float(sol.phi[k]) * 1000.0, 1, lang)} {unit('mm', lang)}"


def crank_degrees(sol: Solution, k: int) -> float:
    """φ of position k in degrees, in [0, 360) (one convention on every sheet)."""
    return math.degrees(float(sol.phi[k])) % 360.0


def _marked(panel: Panel, sol: Solution, k: int, plan: Plan, lang: str) -> Panel:
    """Add a warning under a plan drawn at a position whose results have a poor error estimate."""
    worst = 0.0
    for sid in sol.targets:
        if sid in sol.estimate and sol.construction[sid].plan is plan:
            worst = max(worst, float(sol.estimate.relative(sid)[k]))
    if worst > sol.tolerance:
        x0, y0, _, _ = panel.bounds()
        estimate = scientific(worst, 2, lang) if math.isfinite(worst) else "∞"
        panel.primitives.append(Text((x0, y0 - 6.0), message("estimate.sheet_mark", lang,
                                                             estimate=estimate), 3.5))
    return panel


def _area(panel: Panel) -> float:
    x0, y0, x1, y1 = panel.bounds()
    return (x1 - x0) * (y1 - y0)


def scale_field(mu_l: float, lang: str = "en") -> str:
    """Drawing scale of the position plan as a ratio ("1:2,5" in ru and vi)."""
    r = mu_l * 1000.0

    return f"1:{significant(r, 6, lang)}" if r >= 1 else f"{significant(1 / r, 6, lang)}:1"


def compose_sheets(sol: Solution, size: str | None = None, standard: str | None = None,
                   lang: str | None = None, name: str = "sheet") -> list[Sheet]:
    """The sheets of :func:`compose`."""
    return compose(sol, size, standard, lang, name).sheets


def compose(sol: Solution, size: str | None = None, standard: str | None = None,
            lang: str | None = None, name: str = "sheet") -> Composition:
    """Lay out the course sheets of a solution: sheet 1 kinematics, sheet 2 kinetostatics.

    The scale factors are the one decision of :func:`sheet.scales.decide_scales` for this sheet
    size (the report's own when it is the scene's sheet). Panels are packed in order, top left
    first; what does not fit flows onto further sheets, each numbered with its title block.
    """
    scene = sol.scene
    lang = lang or scene.language
    size = size or scene.drawing.sheet
    standard = standard or scene.drawing.standard
    own = size == scene.drawing.sheet and standard == scene.drawing.standard and sol.scales
    mu = dict(sol.scales) if own else decide_scales(scene, sol.construction, sol.ev, sol.plans,
                                                    size, standard)
    r = room(size, standard, lang)
    panels = _kinematics_panels(sol, mu, lang, r) + _force_panels(sol, mu, lang, r)
    base = {"title": scene.title, "scale": scale_field(mu[Plan.POSITION], lang)}
    base.update({k: v for k, v in scene.drawing.title_block.items() if v})
    # one stream in reading order: kinetostatics fills the free room kinematics leaves
    area = packing_area(make_frame(size, standard, base, language=lang))
    found = fewest_sheets(panels, area, split=True, whole=True)
    if isinstance(found, Panel):
        x0, y0, x1, y1 = found.bounds()
        fixed = ", ".join(f"{k} = {significant(v, 6, 'en')}"
                          for k, v in scene.drawing.scales.items())
        raise DrawingError(
            Msg("errmsg.sheet_compose.panel_name_value", {"name": str(found.name),
                                                           "value": f'{x1 - x0:.0f}',
                                                           "value2": f'{y1 - y0:.0f}',
                                                           "size": str(size),
                                                           "value3": str(fixed or 'chosen')}),
            file=scene.path)
    found = _grown_diagrams(sol, lang, r, found, area)
    groups = [list(zip(p, o)) for p, o in found]
    sheets = framed(groups, size=size, standard=standard, language=lang, name=name, fields=base)
    return Composition(sheets, groups, mu, size, standard)


@dataclasses.dataclass(frozen=True)
class Composition:
    """Sheets, the panels placed on each (with their offsets) and the scale factors used."""

    sheets: list[Sheet]
    placements: list[list[tuple[Panel, tuple[float, float]]]]
    scales: dict[Plan, float]
    size: str = "A1"
    standard: str = "iso"

    def coverage(self) -> list[float]:
        """Share of each sheet's drawing area covered by its panels' boxes."""
        out = []
        for placed in self.placements:
            frame = make_frame(self.size, self.standard, {"title": ""})
            area = packing_area(frame).area
            used = sum(_area(p) for p, _ in placed)
            out.append(used / area)
        return out
