"""The instant-centre panel: the mechanism at one position with every centre labelled, the lines
of Kennedy's constructions, the circle diagram and the table of centres.

Centres within the view (the mechanism's box grown by half its size) are drawn as small circles
with their names; a centre beyond it, or at infinity, is an arrow at the edge of the view pointing
to it, named, and given in the table (coordinates, or its direction for one at infinity).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import partial

import numpy as np

from ..construct.centre_kinematics import centrodes_over_turn
from ..construct.plans.centres import Centre, Centres, centres_at, label
from ..drafting.labels import LabelPlacer
from ..drafting.primitives import Arrow, Circle, Line, Polyline, Role, Text
from ..geom.vec import rotate
from ..i18n import message, number, significant
from ..model.mechanism import Mechanism
from ..solve import Solution
from .centre_velocity import draw_velocities, pole_marks, velocity_table
from .link_outline import drawn as draw_figure
from .link_outline import link_figures
from .panels import LABEL_H, TITLE_H, Panel, table
from .scales import Room

#: the view of the panel: the mechanism's box grown by this share of its size on each side
MARGIN = 0.75
#: the circle diagram's radius (mm)
DIAGRAM_R = 18.0
CENTRE_R = 1.2


def centres_panels(sol: Solution, k: int, mu_l: float, lang: str, r: Room,
                   velocities: bool = True) -> list[Panel]:
    """The panel of the centres at position k, the circle diagram and the table of centres;
    with ``velocities`` the velocities by centres drawn on the panel and their table."""
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    cs = centres_at(c, ev, mech)
    sym = message("centres.symbol", lang)
    phi = number(math.degrees(float(sol.phi[k])) % 360.0, 1, lang)
    title = message("centres.panel.title", lang, k=k, phi=phi)
    pts = {p: ev[c.position(p)][k] for lk in mech.links.values() for p in lk.points
           if c.has_position(p)}
    xy = np.array([v for v in pts.values() if np.all(np.isfinite(v))])
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    size = float(max(hi - lo)) or 1.0
    lo, hi = lo - MARGIN * size, hi + MARGIN * size
    # the view takes a fifth of the room's width and a quarter of its height (at least
    # 100 × 80 mm, on a small sheet most of it), at the position plan's scale when it can; the
    # names and arrows around it are shrunk into the room too
    width = min(0.9 * r.width, max(0.2 * r.width, 100.0))
    height = min(0.8 * r.height, max(0.25 * r.height, 80.0))
    mu = max(mu_l, float((hi - lo)[0]) / width, float((hi - lo)[1]) / height)
    curves = _centrode_curves(sol, k)
    for _ in range(4):
        drawn: dict[str, float | None] = {}
        panel = _view(cs, k, pts, mech, lo, hi, mu, sym, title, lang,
                      partial(_extras, sol=sol, k=k, curves=curves, box=(lo, hi), mu=mu,
                              lang=lang, velocities=velocities, drawn=drawn))
        mu_v = drawn.get("mu_v")
        x0, y0, x1, y1 = panel.bounds()
        grow = max((x1 - x0) / (0.95 * r.width), (y1 - y0) / (0.9 * r.height))
        if grow <= 1.0:
            break
        mu *= grow * 1.05
    out = [panel, circle_diagram_panel(cs, sym, lang), centres_table(cs, k, sym, lang)]
    extra = velocity_table(sol, k, mu_v, lang) if mu_v is not None else None
    return out + ([extra] if extra is not None else [])


def _extras(panel: Panel, *, sol: Solution, k: int, curves: list[np.ndarray],
            box: tuple[np.ndarray, np.ndarray], mu: float, lang: str, velocities: bool,
            drawn: dict[str, float | None]) -> dict[str, tuple[float, float]]:
    """The centrodes and (``velocities``) the velocities by centres, drawn before the names
    are placed clear of their lines; the arrows' μv in ``drawn["mu_v"]``. Returns the
    acceleration poles Q_j of the ``[centres] links`` inside the view (named ``Q2``)."""
    for curve in curves:
        _clipped_curve(panel, curve, box[0], box[1], mu)
    if not velocities:
        return {}
    drawn["mu_v"] = draw_velocities(panel, sol, k, _scaled(mu), mu, lang)
    return pole_marks(sol, k, box, _scaled(mu))


def _scaled(mu: float) -> Callable[[np.ndarray], tuple[float, float]]:
    """World (m) → panel mm at μ."""
    return lambda v: (float(v[0]) / mu, float(v[1]) / mu)


def _centrode_curves(sol: Solution, k: int) -> list[np.ndarray]:
    """The fixed centrodes of the links the scene asks for, and their moving centrodes where the
    link is at position k (world coordinates, m)."""
    spec = sol.scene.centres
    if spec is None:
        return []
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    out = []
    cs = centres_at(c, ev, mech)
    for lid in spec.links:
        if ("0", lid) not in cs.values:      # W = 2: Kennedy's theorem does not find I0j
            continue
        _phi, fixed, moving = centrodes_over_turn(c, mech, lid, spec.positions)
        angle = np.full(len(moving), float(ev[c.link_angle(lid)][k]))
        first, local = next(iter(mech.links[lid].points.items()))
        at_k = np.broadcast_to(ev[c.position(first)][k], moving.shape)
        origin = at_k - rotate(np.asarray(local, dtype=float), angle)
        out += [fixed, origin + rotate(moving, angle)]
    return out


def _clipped_curve(panel: Panel, curve: np.ndarray, lo: np.ndarray, hi: np.ndarray,
                   mu: float) -> None:
    """A dash-dot polyline of the curve's runs inside the view."""
    inside = np.all(np.isfinite(curve), axis=1) & np.all(curve >= lo, axis=1) & \
        np.all(curve <= hi, axis=1)
    run: list[tuple[float, float]] = []
    for ok, p in zip(inside, curve, strict=True):
        if ok:
            run.append((float(p[0]) / mu, float(p[1]) / mu))
            continue
        if len(run) > 2:
            panel.primitives.append(Polyline(tuple(run), Role.CHAIN))
        run = []
    if len(run) > 2:
        panel.primitives.append(Polyline(tuple(run), Role.CHAIN))


def _view(cs: Centres, k: int, pts: dict[str, np.ndarray], mech: Mechanism, lo: np.ndarray,
          hi: np.ndarray, mu: float, sym: str, title: str, lang: str,
          extra: Callable[[Panel], dict[str, tuple[float, float]] | None] | None = None
          ) -> Panel:
    """The mechanism and its centres at position k, drawn at μ (m per paper mm); ``extra``
    draws more (centrodes, velocities) before the names are placed clear of it."""
    panel = Panel("centres", plan=None)
    prims = panel.primitives

    def mm(v: np.ndarray) -> tuple[float, float]:
        return (float(v[0]) / mu, float(v[1]) / mu)

    figures = link_figures(mech)
    for lk in mech.links.values():
        if lk.id == "0":
            continue
        at = {p: mm(pts[p]) for p in figures[lk.id].points if p in pts}
        prims.extend(draw_figure(figures[lk.id], at, Role.OUTLINE))
    inside = {}
    for ctr in cs.diagram.centres:
        h = cs.values[(ctr.i, ctr.j)].h[k]
        if np.all(np.isfinite(h)) and h[2] == 1.0:
            p = h[:2] * cs.length
            if np.all(p >= lo) and np.all(p <= hi):
                inside[(ctr.i, ctr.j)] = p
    for ctr in cs.diagram.centres:       # each primitive tagged with its centre (``Panel.steps``)
        if not ctr.primary:
            panel.tag(ctr.key, *_kennedy_lines(cs, ctr, k, lo, hi, mm))
    marked: dict[str, tuple[float, float]] = {}
    keys: dict[str, str] = {}
    for ctr in cs.diagram.centres:
        name = label(ctr, sym)
        h = cs.values[(ctr.i, ctr.j)].h[k]
        if not np.all(np.isfinite(h)):
            continue
        if (ctr.i, ctr.j) in inside:
            marked[name] = mm(inside[(ctr.i, ctr.j)])
            keys[name] = ctr.key
            panel.tag(ctr.key, Circle(marked[name], CENTRE_R, Role.OUTLINE))
        else:
            panel.tag(ctr.key, *_far(h, cs.length, lo, hi, mm, name, lang))
    if extra is not None:           # more points to name (an acceleration pole): key "pole"
        for name, q in (extra(panel) or {}).items():
            marked[name], keys[name] = q, "pole"
            panel.tag("pole", Circle(q, CENTRE_R, Role.OUTLINE))
    # the names placed clear of the lines, the other names and each other
    placer = LabelPlacer([p for p in prims if isinstance(p, (Line, Polyline, Arrow, Text))],
                         LABEL_H, list(marked.values()))
    for name, q in marked.items():
        drawn = len(placer.leaders)
        panel.tag(keys[name], placer.place(q, name))
        panel.tag(keys[name], *placer.leaders[drawn:])     # its leader, if it needs one
    x0, _y0, _x1, y1 = panel.bounds()
    prims.append(Text((x0, y1 + 9.0), title, TITLE_H))
    ratio = significant(mu * 1000.0, 4, lang)
    prims.append(Text((x0, y1 + 3.0), message("centres.panel.scale", lang, ratio=ratio), LABEL_H))
    return panel


def _clip(p: np.ndarray, u: np.ndarray, lo: np.ndarray,
          hi: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """The part of the line p + t·u inside the box (None if it misses it)."""
    t0, t1 = -math.inf, math.inf
    for a in range(2):
        if abs(u[a]) < 1e-15:
            if not lo[a] <= p[a] <= hi[a]:
                return None
            continue
        ta, tb = (lo[a] - p[a]) / u[a], (hi[a] - p[a]) / u[a]
        t0, t1 = max(t0, min(ta, tb)), min(t1, max(ta, tb))
    if t0 > t1:
        return None
    return p + t0 * u, p + t1 * u


def _kennedy_lines(cs: Centres, ctr: Centre, k: int, lo: np.ndarray, hi: np.ndarray,
                   mm) -> list:  # type: ignore[no-untyped-def]
    """The two lines whose meet is the centre, dashed across the view."""
    out = []
    tri = cs.values[(ctr.i, ctr.j)].triangles[k]
    for t in tri:
        kk = ctr.via[int(t)]
        a, b = cs.of(ctr.i, kk).h[k], cs.of(ctr.j, kk).h[k]
        fin = [h for h in (a, b) if h[2] == 1.0]
        if not fin or not np.all(np.isfinite(a)) or not np.all(np.isfinite(b)):
            continue
        p = fin[0][:2] * cs.length
        if a[2] == 1.0 and b[2] == 1.0:
            u = (b[:2] - a[:2]) * cs.length
        else:
            u = (b if a[2] == 1.0 else a)[:2]
        if not np.hypot(*u) > 0:
            continue
        seg = _clip(p, u / np.hypot(*u), lo, hi)
        if seg is not None:
            out.append(Line(mm(seg[0]), mm(seg[1]), Role.DASHED))
    return out


def _far(h: np.ndarray, length: float, lo: np.ndarray, hi: np.ndarray, mm, name: str,
         lang: str) -> list:  # type: ignore[no-untyped-def]
    """An arrow from the view's centre to its edge, toward a centre far away or at infinity."""
    mid = (lo + hi) / 2
    u = h[:2] if h[2] == 0.0 else h[:2] * length - mid
    n = float(np.hypot(*u))
    if not n > 0:
        return []
    u = u / n
    seg = _clip(mid, u, lo, hi)
    if seg is None:
        return []
    end = seg[1] if float(np.dot(seg[1] - mid, u)) > 0 else seg[0]
    start = mid + 0.85 * (end - mid)
    text = message("centres.panel.far", lang, centre=name) if h[2] == 1.0 else \
        message("centres.panel.infinite", lang, centre=name)
    q = mm(end)
    return [Arrow(mm(start), q, Role.THIN), Text((q[0] + 1.0, q[1] + 1.5), text, 2.5)]


def circle_diagram_panel(cs: Centres, sym: str, lang: str) -> Panel:
    """The links on a circle; each centre a side or a diagonal (pairs solid, Kennedy's dashed),
    numbered in the order found."""
    panel = Panel("centres-diagram", plan=None)
    prims = panel.primitives
    links = cs.diagram.links
    n = len(links)
    at = {lk: (DIAGRAM_R * math.cos(math.pi / 2 - 2 * math.pi * i / n),
               DIAGRAM_R * math.sin(math.pi / 2 - 2 * math.pi * i / n))
          for i, lk in enumerate(links)}
    for ctr in cs.diagram.centres:
        a, b = at[ctr.i], at[ctr.j]
        m = (a[0] + 0.4 * (b[0] - a[0]), a[1] + 0.4 * (b[1] - a[1]))
        panel.tag(ctr.key, Line(a, b, Role.OUTLINE if ctr.primary else Role.DASHED),
                  Text(m, str(ctr.order + 1), 2.5))
    for lk, p in at.items():
        prims.append(Circle(p, 1.0, Role.OUTLINE))
        prims.append(Text((p[0] * 1.15 - 1.0, p[1] * 1.15 - 1.0), lk, LABEL_H))
    x0, _y0, _x1, y1 = panel.bounds()
    prims.append(Text((x0, y1 + 4.0), message("centres.panel.diagram", lang), TITLE_H))
    names = [f"{ctr.order + 1}: {label(ctr, sym)}" for ctr in cs.diagram.centres]
    _x0, y0, _x1, _y1 = panel.bounds()
    for row in range(0, len(names), 4):
        prims.append(Text((x0, y0 - 5.0 - 1.6 * row), ", ".join(names[row:row + 4]), 2.5))
    return panel


def centres_table(cs: Centres, k: int, sym: str, lang: str) -> Panel:
    """The table of centres: name, x and y in mm (or ∞ and the direction)."""
    rows = [(message("centres.table.centre", lang), message("centres.table.x", lang),
             message("centres.table.y", lang))]
    for ctr in cs.diagram.centres:
        h = cs.values[(ctr.i, ctr.j)].h[k]
        if not np.all(np.isfinite(h)):
            rows.append((label(ctr, sym), "?", "?"))
        elif h[2] == 0.0:
            ang = number(math.degrees(math.atan2(h[1], h[0])), 1, lang)
            rows.append((label(ctr, sym), "∞", message("centres.table.direction", lang,
                                                        angle=ang)))
        else:
            rows.append((label(ctr, sym), number(h[0] * cs.length * 1000.0, 1, lang),
                         number(h[1] * cs.length * 1000.0, 1, lang)))
    panel = Panel("centres-table", [table(rows, (0.0, 0.0))], plan=None)
    x0, _y0, _x1, y1 = panel.bounds()
    panel.primitives.append(Text((x0, y1 + 3.0), message("centres.table.title", lang), TITLE_H))
    return panel
