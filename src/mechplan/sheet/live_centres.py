"""The instant centres on the live page (a linkage whose scene asks for ``centres``): Kennedy's
construction replayed centre by centre in the order found — each centre with the two lines that
find it and its chord on the circle diagram — and the centres moving with the crank angle.

The drawing is the sheet's own centre panel and circle diagram (``sheet/centres.py``, each
primitive tagged with its centre); the positions are ``construct.plans.centres`` evaluated at
the animation's angles. Nothing here finds a centre.
"""

from __future__ import annotations

import math

import numpy as np

from ..construct.graph import Evaluation
from ..construct.plans.centres import Centre, Centres, centres_at, label
from ..drafting.primitives import Table
from ..i18n import LANGUAGES, message
from ..i18n import number as format_number
from ..model.mechanism import PairKind
from ..model.plans import Plan
from ..solve import Solution
from .centres import centres_panels
from .compose import crank_degrees
from .layout import moved
from .live import Doc, each
from .scales import room

#: the circle diagram stands this far right of the centres' view (mm)
GAP = 14.0
#: the animation's view: the mechanism's box over the turn grown by this share of its size
MARGIN = 0.4


def _construction(c: Centre, cs: Centres, k: int, sym: str, lang: str) -> str:
    """How the centre is found at position k (the triangles its lines close there)."""
    name, links = label(c, sym), cs.diagram.links
    if c.pair is not None:
        key = "pin" if c.pair.kind is PairKind.REVOLUTE else "slide"
        return message(f"centres.step.{key}", lang, centre=name, point=c.pair.point,
                       guide=c.pair.guide or "", a=c.i, b=c.j)
    t = cs.values[(c.i, c.j)].triangles[k]
    k1, k2 = c.via[int(t[0])], c.via[int(t[1])]
    return message("centres.step.kennedy", lang, centre=name, p=label((c.i, k1), sym, links),
                   q=label((c.j, k1), sym, links), r=label((c.i, k2), sym, links),
                   s=label((c.j, k2), sym, links))


def _where(h: np.ndarray, length: float, lang: str) -> str:
    if not np.all(np.isfinite(h)):
        return "?"
    if h[2] == 0.0:
        return message("centres.infinite", lang,
                       angle=format_number(math.degrees(math.atan2(h[1], h[0])), 2, lang))
    return message("centres.at", lang, x=format_number(h[0] * length * 1e3, 2, lang),
                   y=format_number(h[1] * length * 1e3, 2, lang))


def centres_replay(sol: Solution, k: int, mu_l: float) -> Doc:
    """Kennedy's construction at position k, centre by centre in the solver's order."""
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    cs = centres_at(c, ev, mech)
    order = cs.diagram.centres
    index = {"base": 0} | {ctr.key: i + 1 for i, ctr in enumerate(order)}
    r = room(sol.scene.drawing.sheet, sol.scene.drawing.standard)
    prims = {}
    for lang in LANGUAGES:
        view, diagram, *_ = centres_panels(sol, k, mu_l, lang, r, velocities=False)
        _x0, y0, x1, y1 = view.bounds()
        d0, e0, _d1, e1 = diagram.bounds()
        dx, dy = x1 + GAP - d0, (y0 + y1) / 2 - (e0 + e1) / 2
        out = []
        for panel, shift in ((view, (0.0, 0.0)), (diagram, (dx, dy))):
            for j, q in enumerate(panel.primitives):
                if isinstance(q, Table):
                    continue
                at = index[panel.steps.get(j, "base")]
                out.append((moved(q, *shift) if shift != (0.0, 0.0) else q, at))
        prims[lang] = out
    phi = crank_degrees(sol, k)

    def sentence(lang: str, ctr: Centre) -> str:
        sym = message("centres.symbol", lang)
        h = cs.values[(ctr.i, ctr.j)].h[k]
        return f"{_construction(ctr, cs, k, sym, lang)}: {_where(h, cs.length, lang)}"

    steps = [{"id": "base", "group": "", "label": each(lambda _l: ""),
              "sentence": each(lambda lang: message(
                  "htmlmore.centres.base", lang, links="–".join(cs.diagram.links),
                  count=cs.diagram.count))}]
    steps += [{"id": ctr.key, "group": "",
               "label": each(lambda lang, ctr=ctr: label(ctr, message("centres.symbol", lang))),
               "sentence": each(lambda lang, ctr=ctr: sentence(lang, ctr))} for ctr in order]
    rows = []
    for ctr in order:
        h = cs.values[(ctr.i, ctr.j)].h[k]
        rows.append({"step": index[ctr.key],
                     "name": each(lambda lang, ctr=ctr: label(ctr, message("centres.symbol",
                                                                            lang))),
                     "mm": each(lambda _l: ""), "quantity": "x, y",
                     "value": each(lambda lang, h=h: _where(h, cs.length, lang))})
    return {"id": f"centres-{k}", "plan": "centres", "k": k, "phi": phi, "unit": "m",
            "title": each(lambda lang: message("centres.panel.title", lang, k=k,
                                               phi=format_number(phi, 1, lang))),
            "mu": each(lambda _l: ""), "steps": steps, "prims": prims, "rows": rows,
            "equations": [], "order": [ctr.key for ctr in order]}


def centres_anim(sol: Solution, ev: Evaluation, position: Doc, mu: dict[Plan, float]) -> Doc:
    """The mechanism (the position panel's links) with its centres at every frame, in a fixed
    view: the box of the mechanism's points over the turn, grown by ``MARGIN`` (the wheel zooms
    out to centres beyond it). A centre at infinity, or far beyond the view, is left out at that
    frame."""
    c, mech = sol.construction, sol.scene.mechanism
    cs = centres_at(c, ev, mech)
    mu_l = mu[Plan.POSITION]
    pts = np.concatenate([np.asarray(p["xy"], dtype=float) for p in position["points"].values()])
    pts = pts[np.isfinite(pts).all(axis=1)]
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    size = float(max(hi - lo)) or 1.0
    lo, hi = lo - MARGIN * size, hi + MARGIN * size
    far = 10.0 * (float(max(hi - lo)) + size)
    points: Doc = {}
    for ctr in cs.diagram.centres:
        xy = cs.point(ctr.i, ctr.j) / mu_l
        mid = (lo + hi) / 2
        xy[~(np.abs(xy - mid) <= far).all(axis=1)] = np.nan
        points[ctr.key] = {"label": each(lambda lang, ctr=ctr: label(ctr, message(
            "centres.symbol", lang))), "xy": xy, "trace": False, "centre": True}
    return {"id": "centres", "plan": "centres", "box": [float(lo[0]), float(-hi[1]),
                                                       float(hi[0]), float(-lo[1])],
            "title": each(lambda lang: message("htmlmore.centres.moving", lang)),
            "mu": position["mu"], "points": points, "items": position["items"],
            "fixed": position.get("fixed", [])}


__all__ = ["centres_anim", "centres_replay"]
