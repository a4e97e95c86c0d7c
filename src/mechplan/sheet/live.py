"""The data of the live page (``draw --format html``): replays of each plan step by step and an
animation over the crank angle, in every language.

Nothing here is new geometry: the replays are the primitives :func:`panels.vector_plan` draws for
the sheet, each tagged with the construction step that draws it (``Panel.steps``); the position
plan's replay draws the compass arcs and points of its evaluated steps; the animation holds the
evaluated construction at ``frames`` crank angles, in paper millimetres at the sheet's scale
factors. The page (``render/html``) only shows, hides and moves what is given here.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.ops import Drawn, spec
from ..construct.protocol import mm, sentence
from ..construct.segments import SegmentKind
from ..construct.step import Kind, Step
from ..construct.terms import pole_label
from ..drafting.primitives import Arc, Arrow, Circle, Line, Primitive, Role, Sheet, Table, Text
from ..dynamics.machine import MachineDynamics
from ..i18n import LANGUAGES, decimal_mark, message, unit
from ..i18n import number as format_number
from ..model.mechanism import GROUND
from ..model.plans import Plan
from ..solve import Solution
from .compose import _extreme_phis, crank_degrees, plan_positions
from .diagram import Axis, Curve, Diagram, diagram_panel
from .dynamics import dynamics_scales
from .link_outline import drawn as draw_figure
from .link_outline import link_figures
from .panels import LABEL_H, TABLE_H, _pivot, _slider, mu_text, plan_title, vector_plan

#: crank positions of the animation (one a degree)
FRAMES = 360
#: half the sweep of a compass arc drawn through the point it finds, degrees
ARC_HALF_DEG = 14.0
#: catalogue ids of the page's own words (``locale/*/html.po``)
UI = ("replay", "animation", "plan", "previous", "next", "play", "pause", "speed", "first",
      "last", "step", "protocol", "segments", "equation", "term", "direction", "magnitude",
      "segment", "on_paper", "quantity", "value", "angle", "dead", "unbuilt", "chosen",
      "language", "reset", "print", "keys", "values", "sheets", "sheet_only", "flagged")

Doc = dict[str, Any]


def each(fn: Any) -> dict[str, str]:
    return {lang: fn(lang) for lang in LANGUAGES}


def _replay_index(c: Construction, steps: list[Step]) -> dict[str, int]:
    """Step id → index of the replay step (a protocol sentence) that shows it: its own, or the
    first sentence after it (a step without a sentence appears with the next one)."""
    order = {s.id: i for i, s in enumerate(c)}
    said = [order[s.id] for s in steps]
    out: dict[str, int] = {}
    for s in c:
        later = [j for j, o in enumerate(said) if o >= order[s.id]]
        out[s.id] = later[0] if later else len(steps) - 1
    return out


def _said(c: Construction, ev: Evaluation, plan: Plan, group: str | None) -> list[Step]:
    """The steps of a plan (one group of a force plan) that have a protocol sentence."""
    return [s for s in c.of_plan(plan) if s.id in ev.values and s.op.message is not None
            and (group is None or s.group == group)]


def _replay_steps(sol: Solution, steps: list[Step], k: int, mu: dict[Plan, float]) -> list[Doc]:
    c, ev = sol.construction, sol.ev
    return [{"id": s.id, "group": s.group,
             "label": each(lambda lang, s=s: pole_label(s.label, lang)),
             "sentence": each(lambda lang, s=s: sentence(c, s, ev, k, lang, mu))}
            for s in steps]


def tagged(prims: Iterable[tuple[Primitive | Table, str | None]], index: dict[str, int]
            ) -> list[tuple[Primitive, int]]:
    """Drawing primitives with the replay step that draws them (-1: always shown)."""
    out = []
    for p, sid in prims:
        if isinstance(p, Table) or isinstance(p, Text) and (p.height_mm == TABLE_H or sid is None):
            continue       # tables, title and μ are the page's own, the tables filled as steps run
        out.append((p, index.get(sid, -1) if sid is not None else -1))
    return out


def _tables(sol: Solution, k: int, plan: Plan, mu: float, group: str | None,
            index: dict[str, int]) -> tuple[list[Doc], list[Doc]]:
    """Rows of the segments table (each with the step that finds it) and the vector equations
    with the step at which each term is drawn."""
    c, ev = sol.construction, sol.ev
    segs = [g for g in c.segments if g.plan is plan and (group is None or g.group == group)
            and g.start in ev.values and g.end in ev.values]
    rows = []
    found: dict[str, int] = {}
    for g in segs:
        length = float(np.hypot(*(ev[g.end][k] - ev[g.start][k])))
        if not math.isfinite(length):
            continue
        at = index.get(g.end, -1)
        found.setdefault(g.quantity, at)
        rows.append({"step": at, "name": each(lambda lang, g=g: pole_label(g.name, lang)),
                     "mm": each(lambda lang, v=length / mu: format_number(v, 1, lang)),
                     "quantity": g.quantity,
                     "value": each(lambda lang, v=length: format_number(v, 3, lang))})
    equations = []
    for (p, name), (eq, terms) in c.equations.items():
        if p is not plan or (group is not None and name != group):
            continue
        equations.append({"group": name, "eq": eq, "terms": [
            {"term": term, "magnitude": mag, "step": found.get(term, -1),
             "direction": each(lambda lang, d=d: d.text(lang))}
            for term, d, mag in terms]})
    return rows, equations


def _vector_replay(sol: Solution, k: int, plan: Plan, mu: dict[Plan, float],
                   group: str | None = None) -> Doc:
    c, ev = sol.construction, sol.ev
    steps = _said(c, ev, plan, group)
    index = _replay_index(c, steps)
    phi = crank_degrees(sol, k)
    prims: dict[str, list[tuple[Primitive, int]]] = {}
    for lang in LANGUAGES:
        panel = vector_plan(c, ev, k, plan, mu[plan], lang, plan_title(plan, lang, k, phi, group),
                            group)
        prims[lang] = tagged(((p, panel.steps.get(i)) for i, p in enumerate(panel.primitives)),
                              index)
    rows, equations = _tables(sol, k, plan, mu[plan], group, index)
    return {"id": f"{plan.value}-{k}" + (f"-{group}" if group else ""), "plan": plan.value,
            "k": k, "phi": phi, "unit": plan.unit,
            "title": each(lambda lang: plan_title(plan, lang, k, phi, group)),
            "mu": each(lambda lang: mu_text(plan, mu[plan], lang)),
            "steps": _replay_steps(sol, steps, k, mu), "prims": prims, "rows": rows,
            "equations": equations}


def _mm(v: np.ndarray, mu: float) -> tuple[float, float]:
    return (float(v[0]) / mu, float(v[1]) / mu)


def _finite(p: tuple[float, float]) -> bool:
    return math.isfinite(p[0]) and math.isfinite(p[1])


def _position_prims(sol: Solution, k: int, mu: float, lang: str) -> list[tuple[Primitive, str]]:
    """The position plan at one position as a student builds it: the frame pivots, the crank,
    each point with the compass arcs that find it, each link once its points are found."""
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    out: list[tuple[Primitive, str]] = []
    at: dict[str, tuple[float, float]] = {}
    for s in c.of_plan(Plan.POSITION):
        if s.kind is not Kind.POINT or s.id not in ev.values:
            continue
        p = _mm(ev[s.id][k], mu)
        if not _finite(p):
            continue
        at[s.id] = p
        name = s.op.value
        centres: list[tuple[str, float]] = []
        if name == "circle_circle":
            centres = [(s.input("centre1"), s.param("r1")), (s.input("centre2"), s.param("r2"))]
        elif name == "circle_line":
            centres = [(s.input("centre"), s.param("r"))]
        for cid, r in centres:
            if cid in at and r:
                q = at[cid]
                a = math.degrees(math.atan2(p[1] - q[1], p[0] - q[0]))
                out.append((Arc(q, float(r) / mu, a - ARC_HALF_DEG, a + ARC_HALF_DEG,
                                Role.THIN), s.id))
        if name == "polar_point" and s.input("centre") in at:
            out.append((Line(at[s.input("centre")], p, Role.DASHED), s.id))
        out.append((Circle(p, 0.8, Role.OUTLINE), s.id))
        out.append((Text((p[0] + 1.2, p[1] + 1.2), pole_label(s.label, lang), LABEL_H), s.id))
    order = {s.id: i for i, s in enumerate(c)}
    for fig in link_figures(mech).values():
        ids = {n: c.position(n) for n in fig.points if c.has_position(n)}
        here = {n: at[i] for n, i in ids.items() if i in at}
        if len(here) < 2:
            continue
        last = max((ids[n] for n in here), key=order.__getitem__)
        out += [(p, last) for p in draw_figure(fig, here, Role.OUTLINE)]
    return out


def _position_replay(sol: Solution, k: int, mu: dict[Plan, float]) -> Doc:
    c, ev = sol.construction, sol.ev
    steps = _said(c, ev, Plan.POSITION, None)
    index = _replay_index(c, steps)
    phi = crank_degrees(sol, k)
    prims = {lang: tagged(_position_prims(sol, k, mu[Plan.POSITION], lang), index)
             for lang in LANGUAGES}
    return {"id": f"position-{k}", "plan": "position", "k": k, "phi": phi, "unit": "m",
            "title": each(lambda lang: plan_title(Plan.POSITION, lang, k, phi)),
            "mu": each(lambda lang: mu_text(Plan.POSITION, mu[Plan.POSITION], lang)),
            "steps": _replay_steps(sol, steps, k, mu), "prims": prims, "rows": [],
            "equations": []}


def replays(sol: Solution, mu: dict[Plan, float]) -> list[Doc]:
    """Every plan of every chosen position, step by step, in the order of the sheets."""
    c = sol.construction
    out = []
    groups = list(dict.fromkeys(s.group for s in c.segments if s.plan is Plan.FORCE))
    for n, k in enumerate(plan_positions(sol)):
        out.append(_position_replay(sol, k, mu))
        if n == 0 and "centres" in sol.plans:       # as on the sheet: the first position's
            from .live_centres import centres_replay

            out.append(centres_replay(sol, k, mu[Plan.POSITION]))
        for plan in (Plan.VELOCITY, Plan.ACCELERATION):
            if plan.value in sol.plans and any(s.plan is plan for s in c.segments):
                out.append(_vector_replay(sol, k, plan, mu))
        if "force" in sol.plans:
            out += [_vector_replay(sol, k, Plan.FORCE, mu, g) for g in groups]
    return out


# -- the animation ---------------------------------------------------------------------------------

def _frames_phi(sol: Solution, frames: int) -> np.ndarray:
    """Crank angles of the animation from the first position, in the crank's sense of turning
    (a linear driver's coordinate over its range: :func:`live_diagrams.linear_frames`)."""
    if sol.scene.mechanism.drive.linear:
        from .live_diagrams import linear_frames

        return linear_frames(sol, frames)
    sense = 1.0 if sol.scene.mechanism.drive.omega >= 0 else -1.0
    return float(sol.phi[0]) + sense * np.arange(frames) * 2.0 * math.pi / frames


def _link_paths(sol: Solution, ev: Evaluation, mu: float) -> list[Doc]:
    """Each moving link's lines at every frame (the figure the position plan draws)."""
    c, mech = sol.construction, sol.scene.mechanism
    items = []
    for lid, fig in link_figures(mech).items():
        names = [n for n in fig.points if c.has_position(n)]
        if not names:
            continue
        xy = {n: np.asarray(ev[c.position(n)], dtype=float) / mu for n in names}
        frames = []
        for k in range(ev.n):
            at = {n: (float(v[k, 0]), float(v[k, 1])) for n, v in xy.items()
                  if np.isfinite(v[k]).all()}
            frames.append(draw_figure(fig, at, Role.OUTLINE))
        items.append({"kind": "link", "link": lid, "frames": frames})
    return items


def _points(steps: Iterable[Step], ev: Evaluation, mu: float) -> dict[str, np.ndarray]:
    return {s.id: np.asarray(ev[s.id], dtype=float) / mu for s in steps}


def _position_anim(sol: Solution, ev: Evaluation, mu: float) -> Doc:
    c, mech = sol.construction, sol.scene.mechanism
    names = list(dict.fromkeys(n for lk in mech.links.values() for n in lk.points))
    names = [n for n in names if c.has_position(n)]
    pts = {n: np.asarray(ev[c.position(n)], dtype=float) / mu for n in names}
    fixed = set(mech.links[GROUND].points)
    items = _link_paths(sol, ev, mu)
    frame: list[Primitive] = []          # the frame's pivots and guides, drawn once
    joints = {pr.point for pr in mech.pairs if GROUND in (pr.a, pr.b)}
    for n in fixed & joints & set(pts):
        frame += _pivot((float(pts[n][0, 0]), float(pts[n][0, 1])))
    for lk in mech.links.values():
        if not lk.slides_on or next(iter(lk.points)) not in pts:
            continue
        g = mech.guides[lk.slides_on]
        at = pts[next(iter(lk.points))]
        if g.link == GROUND:
            angle = np.full(ev.n, g.angle)
            u = np.array([math.cos(g.angle), math.sin(g.angle)])
            ok = at[np.isfinite(at).all(axis=1)]
            if ok.size:
                t = ok @ u
                o = ok[0] - (ok[0] @ u) * u
                frame.append(Line(tuple(o + (t.min() - 10.0) * u), tuple(o + (t.max() + 10.0) * u),
                                  Role.CHAIN))
        else:
            angle = np.asarray(ev[c.link_angle(lk.id)], dtype=float)
        items.append({"kind": "link", "link": f"slider-{lk.id}", "frames": [
            [_slider((float(at[k, 0]), float(at[k, 1])), float(angle[k]))]
            if np.isfinite(at[k]).all() and math.isfinite(angle[k]) else []
            for k in range(ev.n)]})
    return {"id": "position", "plan": "position",
            "title": each(lambda lang: message("protocol.plan.position", lang)),
            "mu": each(lambda lang: mu_text(Plan.POSITION, mu, lang)),
            "points": {n: {"label": each(lambda _lang, n=n: n), "xy": v,
                           "trace": n not in fixed} for n, v in pts.items()},
            "items": items, "fixed": frame}


def _vector_anim(sol: Solution, ev: Evaluation, plan: Plan, mu: float) -> Doc:
    c = sol.construction
    steps = [s for s in c.of_plan(plan) if s.id in sol.ev.values and s.kind is Kind.POINT
             and spec(s.op).draw in (Drawn.POINT, Drawn.MEET, Drawn.VERTEX, Drawn.IMAGE_TRIANGLE)]
    pts = _points(steps, ev, mu)
    items = []
    for g in c.segments:
        if g.plan is not plan or g.start not in pts or g.end not in pts:
            continue
        thick = g.kind in (SegmentKind.ABSOLUTE, SegmentKind.DRIVE, SegmentKind.REACTION)
        frames: list[list[Primitive]] = []
        a, b = pts[g.start], pts[g.end]
        for k in range(ev.n):
            p, q = (float(a[k, 0]), float(a[k, 1])), (float(b[k, 0]), float(b[k, 1]))
            ok = _finite(p) and _finite(q) and math.dist(p, q) >= 0.5
            frames.append([Arrow(p, q, Role.OUTLINE if thick else Role.THIN,
                                 head_length_mm=3.5 if thick else 3.0,
                                 head_width_mm=1.2 if thick else 1.0)] if ok else [])
        items.append({"kind": "segment", "name": g.name, "thick": thick, "frames": frames})
    return {"id": plan.value, "plan": plan.value,
            "title": each(lambda lang: message(f"protocol.plan.{plan.value}", lang)),
            "mu": each(lambda lang: mu_text(plan, mu, lang)),
            "points": {s.id: {"label": each(lambda lang, s=s: pole_label(s.label, lang)),
                              "xy": pts[s.id], "trace": False} for s in steps},
            "items": items}


def _values(sol: Solution, ev: Evaluation, mu: dict[Plan, float]) -> list[Doc]:
    """The quantities of the segments table at every frame: value (SI) and length on paper."""
    c = sol.construction
    out = []
    for g in c.segments:
        if g.plan not in (Plan.VELOCITY, Plan.ACCELERATION) or g.plan.value not in sol.plans:
            continue
        if g.start not in sol.ev.values or g.end not in sol.ev.values:
            continue
        v = np.hypot(*(np.asarray(ev[g.end]) - np.asarray(ev[g.start])).T)
        out.append({"quantity": g.quantity, "unit": each(lambda lang, g=g: unit(g.plan.unit,
                                                                                  lang)),
                    "name": each(lambda lang, g=g: pole_label(g.name, lang)),
                    "value": v, "mm": v / mu[g.plan]})
    return out


def _marks(sol: Solution, phi: np.ndarray, broken: np.ndarray) -> list[Doc]:
    """Dead centres, positions that cannot be built, and the positions of the sheets."""
    frames = phi.shape[0]
    step = 2.0 * math.pi / frames
    linear = sol.scene.mechanism.drive.linear

    def frame_of(angle: float) -> int | None:
        if linear:                      # a length within the driver's range
            from .live_diagrams import frame_of as frame_at

            return frame_at(phi, angle)
        sense = 1.0 if sol.scene.mechanism.drive.omega >= 0 else -1.0
        return round(sense * (angle - float(phi[0])) / step) % frames

    marks = [{"k": frame_of(a), "kind": "dead"} for a in ([] if linear else _extreme_phis(sol))]
    marks += [{"k": int(k), "kind": "unbuilt"} for k in np.flatnonzero(broken)]
    marks += [{"k": frame_of(float(sol.phi[k])), "kind": "chosen", "position": k}
              for k in plan_positions(sol)]
    # positions of the solution whose results the error estimate does not trust
    marks += [{"k": frame_of(float(sol.phi[k])), "kind": "flagged", "position": k}
              for k in sorted({f.k for f in sol.flags})]
    return [m for m in marks if m["k"] is not None]


def cursor_panel(pid: str, title: Any, drawn: dict[str, Diagram], x: np.ndarray,
                  y: np.ndarray, label: str) -> Doc:
    """A diagram (axes and curves in every language) and its cursor at (x, y) of every frame."""
    d = drawn[LANGUAGES[0]]
    xy = np.column_stack([d.origin[0] + x / d.mu_x, d.origin[1] + y / d.mu_y])
    _x0, y0, _x1, y1 = d.panel.bounds()
    cursor = [[Line((float(px), y0), (float(px), y1), Role.DASHED)] if math.isfinite(px) else []
              for px in xy[:, 0]]
    return {"id": pid, "plan": "diagram", "title": each(title), "mu": each(lambda _lang: ""),
            "points": {pid: {"label": each(lambda _lang: label), "xy": xy, "trace": False}},
            "items": [{"kind": "segment", "name": "cursor", "thick": False, "frames": cursor}],
            "static": {lang: [p for p in dd.panel.primitives if not isinstance(p, Table)]
                       for lang, dd in drawn.items()}}


def _dynamics_anims(dyn: MachineDynamics, phi: np.ndarray) -> list[Doc]:
    """M(φ), ΔT(φ), J_red(φ) and ω(φ) of the machine's cycle (the dynamics sheet's diagrams at its
    scale factors) with a cursor at the crank angle of every frame (the cycle's first turn when
    it lasts two)."""
    sc = dynamics_scales(dyn)
    q = np.arange(0, dyn.theta.size, max(1, dyn.theta.size // 720))
    deg = np.degrees(dyn.theta)
    theta = np.mod(phi - dyn.phi0, dyn.spec.cycle)
    x = np.degrees(theta)
    axis = Axis("φ", "°", math.degrees(dyn.spec.cycle) / math.degrees(sc.mu_phi),
                mu=math.degrees(sc.mu_phi), mu_symbol="μφ")
    Spec = tuple[str, str, list[tuple[np.ndarray, Role, str | None]], Axis, dict[str, Any]]
    specs: list[Spec] = [
             ("moments", "M_d", [(dyn.M_d, Role.OUTLINE, "M_d"), (dyn.M_c, Role.DASHED, "M_c")],
              Axis("M", "N·m", 60.0, mu=sc.mu_M, mu_symbol="μM"), {}),
             ("energy", "ΔT", [(dyn.dT, Role.OUTLINE, None)],
              Axis("ΔT", "J", 50.0, mu=sc.mu_T, mu_symbol="μT"), {}),
             ("inertia", "J", [(dyn.J_red, Role.OUTLINE, None)],
              Axis("J", "kg·m²", 60.0, mu=sc.mu_J, mu_symbol="μJ"), {}),
             ("omega", "ω", [(dyn.omega, Role.OUTLINE, None)], Axis("ω", "rad/s", 50.0),
              {"hlines": [(dyn.omega_m, "ω_m")], "y_zero": False})]
    out = []
    for key, label, curves, y_axis, extra in specs:
        def title(lang: str, key: str = key) -> str:
            return message(f"dynamics.diagram.{key}", lang)

        lines = [Curve(deg[q], v[q], role, label=lb) for v, role, lb in curves]
        drawn = {lang: diagram_panel(f"dynamics-{key}", title(lang), lines, axis, y_axis, lang,
                                     **extra) for lang in LANGUAGES}
        y = np.interp(theta, dyn.theta, curves[0][0])
        out.append(cursor_panel(f"dynamics-{key}", title, drawn, x, y, label))
    from .live_more import wittenbauer

    out.append(wittenbauer(dyn, theta))             # ΔT(J_red) with its cursor
    return out


def animation(sol: Solution, mu: dict[Plan, float], frames: int = FRAMES,
              dynamics: MachineDynamics | None = None) -> Doc:
    """The mechanism and its velocity and acceleration plans at ``frames`` crank angles."""
    c = sol.construction
    phi = _frames_phi(sol, frames)
    ev = c.evaluate(phi)
    panels = [_position_anim(sol, ev, mu[Plan.POSITION])]
    if "centres" in sol.plans:                      # the instant centres moving
        from .live_centres import centres_anim

        panels.append(centres_anim(sol, ev, panels[0], mu))
    for plan in (Plan.VELOCITY, Plan.ACCELERATION):
        if plan.value in sol.plans and any(s.plan is plan for s in c.segments):
            panels.append(_vector_anim(sol, ev, plan, mu[plan]))
    from .live_diagrams import diagram_anims

    panels += diagram_anims(sol, phi)
    if dynamics is not None:
        panels += _dynamics_anims(dynamics, phi)
    broken = np.zeros(frames, dtype=bool)
    for p in panels[0]["points"].values():
        broken |= ~np.isfinite(p["xy"]).all(axis=1)
    doc = {"frames": frames, "phi_deg": np.degrees(phi) % 360.0, "panels": panels,
           "values": _values(sol, ev, mu), "marks": _marks(sol, phi, broken)}
    if sol.scene.mechanism.drive.linear:        # "l4 = 2400.0 mm" in place of φ
        from .live_diagrams import coordinate_doc

        doc["coordinate"] = coordinate_doc(sol, phi)
    return doc


def ui_strings() -> dict[str, dict[str, str]]:
    """The page's own words and number marks in every language."""
    keep = {"n": "{n}", "total": "{total}"}         # filled in by the page
    return {lang: {**{key: message(f"html.{key}", lang, **keep) for key in UI},
                   "decimal": decimal_mark(lang), "mm": mm(lang),
                   "language_name": message("html.language_name", lang)}
            for lang in LANGUAGES}


def live_document(sol: Solution, mu: dict[Plan, float], lang: str, name: str,
                  frames: int = FRAMES, dynamics: MachineDynamics | None = None) -> Doc:
    """Everything the live page shows, for every language (``lang`` is the one it opens in)."""
    return {"name": name, "title": sol.scene.title, "lang": lang, "languages": list(LANGUAGES),
            "ui": ui_strings(), "replays": replays(sol, mu),
            "animation": animation(sol, mu, frames, dynamics)}


def sheets_document(sheets: Mapping[str, Sequence[Sheet]], lang: str, name: str, title: str
                    ) -> Doc:
    """The page of a scene kind without a replay yet: its sheets in every language."""
    return {"name": name, "title": title, "lang": lang, "languages": list(LANGUAGES),
            "ui": ui_strings(), "replays": [], "animation": None,
            "sheets": {lg: [{"name": s.name, "w": s.width_mm, "h": s.height_mm,
                             "prims": list(s.flat())} for s in each]
                       for lg, each in sheets.items()}}


__all__ = ["FRAMES", "animation", "live_document", "replays", "sheets_document", "ui_strings"]
