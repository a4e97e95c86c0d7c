"""The ψ′–ψ diagram of an oscillating knife or roller follower on the cam sheet: the arm positions,
the segments l·ψ′ laid off along them, the wedges of the allowable pressure angle from their ends,
and the admissible zone of the cam centre, hatched."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from shapely.geometry import LineString, Polygon, box

from ..construct.scale import round_scale
from ..drafting.primitives import Circle, HAlign, Line, Polyline, Primitive, Role, Text, VAlign
from ..i18n import message, number
from ..model.cam import Contact, Motion, PhaseKind
from ..synthesis.cam.motion import phase_starts
from ..synthesis.cam.oscillating_zone import oscillating_zone
from .diagram import mu_number
from .fit import text_block
from .panels import Panel

if TYPE_CHECKING:
    from ..synthesis.cam import CamDesign

SIZE = 110.0           # mm, the larger side of the construction
HATCH = 3.0            # mm between hatch lines


def _positions(d: CamDesign, parts: int = 12) -> np.ndarray:
    """Indices of the dense samples at every 1/parts of each rise and return, and near 0."""
    starts = phase_starts(d.spec.phases)
    phi = d.dense.phi
    out = [0]
    for i, p in enumerate(d.spec.phases):
        if p.kind in (PhaseKind.RISE, PhaseKind.RETURN):
            for t in np.linspace(starts[i], starts[i + 1], parts + 1):
                out.append(int(np.argmin(np.abs(phi - min(t, phi[-1])))))
    return np.unique(np.array(out))


def zone_panel(d: CamDesign, lang: str, scale: float) -> Panel | None:
    """The panel (None unless the follower oscillates with a knife or a roller)."""
    f = d.spec.follower
    if f.motion is not Motion.OSCILLATING or f.contact is Contact.FLAT:
        return None
    g, lim = d.geometry, d.spec.limits
    dense = d.dense
    sig = 1.0 if g.sense > 0 else -1.0                      # drawn as the cam turns
    idx = np.arange(0, dense.phi.size, 20)
    z = oscillating_zone(g, dense.phi[idx], lim.alpha_rise, lim.alpha_return,
                         (dense.s[idx], dense.s1[idx], dense.s2[idx]))
    pos = _positions(d)
    zp = oscillating_zone(g, dense.phi[pos], lim.alpha_rise, lim.alpha_return,
                          (dense.s[pos], dense.s1[pos], dense.s2[pos]))
    pts = np.vstack([z.roller, z.k_points, [z.pivot], [[0.0, 0.0]]])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.25 * float(np.max(hi - lo))
    lo, hi = lo - pad, hi + pad
    mu = round_scale(float(np.max(hi - lo)) / (SIZE * scale))

    def mm(p: np.ndarray) -> tuple[float, float]:
        return (sig * float(p[0]) / mu, float(p[1]) / mu)

    prims: list[Primitive] = []
    window = box(*(lo / mu), *(hi / mu))
    zone = Polygon([(x / mu, y / mu) for x, y in z.zone]).intersection(window)
    if not zone.is_empty and zone.geom_type == "Polygon":
        ring = [(sig * x, y) for x, y in zone.exterior.coords[:-1]]
        prims.append(Polyline(tuple(ring), Role.OUTLINE, closed=True))
        x0, y0, x1, y1 = zone.bounds
        span = (x1 - x0) + (y1 - y0)
        for c in np.arange(x0 - (y1 - y0), x1, HATCH):      # 45° hatch lines
            cut = LineString([(c, y0), (c + span, y0 + span)]).intersection(zone)
            if cut.geom_type == "LineString" and cut.length > 0.2:
                (ax, ay), (bx, by) = cut.coords[0], cut.coords[-1]
                prims.append(Line((sig * ax, ay), (sig * bx, by), Role.THIN))
    prims.append(Polyline(tuple(mm(p) for p in z.roller), Role.OUTLINE))      # arc of B
    prims.append(Polyline(tuple(mm(p) for p in z.k_points), Role.DASHED))     # ends of l·ψ′
    ray = 0.5 * float(np.max(hi - lo))
    corners = z.zone
    for i in range(len(pos)):
        prims.append(Line(mm(zp.pivot), mm(zp.roller[i]), Role.THIN))
        prims.append(Line(mm(zp.roller[i]), mm(zp.k_points[i]), Role.OUTLINE))
    # of the twelve-part positions, the two tightest wedge edges of each side bound the zone
    if corners.size:
        for side in (0, 1):
            sgn = -1.0 if side == 0 else 1.0
            slack = []
            for i in range(len(zp.k_points)):
                edge = zp.rays[i, side]
                normal = sgn * np.array([-edge[1], edge[0]])
                slack.append(float(np.min((corners - zp.k_points[i]) @ normal)))
            for i in np.argsort(slack)[:2]:
                edge = zp.rays[i, side]
                reach = float(np.max((corners - zp.k_points[i]) @ edge))
                prims.append(Line(mm(zp.k_points[i]),
                                  mm(zp.k_points[i] + min(max(reach, 0.2 * ray), ray) * edge),
                                  Role.THIN))
    # the cam centre of the solution and its base radius
    prims.append(Circle((0.0, 0.0), 0.8, Role.OUTLINE))
    prims.append(Text((1.5, -1.5), "O", 3.5, valign=VAlign.TOP))
    prims.append(Circle(mm(z.pivot), 0.8, Role.OUTLINE))
    ax_, ay_ = mm(z.pivot)
    prims.append(Text((ax_ + 1.5, ay_ - 1.5), "A", 3.5, valign=VAlign.TOP))
    prims.append(Line((0.0, 0.0), mm(z.roller[0]), Role.DASHED))
    bx_, by_ = mm(z.roller[0])
    prims.append(Text((bx_ / 2, by_ / 2 + 1.5), f"r0 = {number(g.r0 * 1e3, 2, lang)}", 2.5,
                      halign=HAlign.CENTER))
    top = max(max(p.start[1], p.end[1]) for p in prims if isinstance(p, Line))
    left = min(min(p.start[0], p.end[0]) for p in prims if isinstance(p, Line))
    right = max(max(p.start[0], p.end[0]) for p in prims if isinstance(p, Line))
    y = top + 3.0
    for text, height, gap in (
            ([message("gearcam.cam.zone_note", lang,
                      ar=number(math.degrees(lim.alpha_rise), 1, lang),
                      ad=number(math.degrees(lim.alpha_return), 1, lang))], 2.5, 5.0),
            ([message("cam.sheet.scale", lang, mu=mu_number(mu, lang))], 2.5, 6.0),
            (message("gearcam.cam.zone_title", lang), 3.5, 0.0)):
        block = text_block((left, y), text, height, right - left, upward=True)
        prims.extend(block)
        y = block[0].position[1] + gap
    return Panel("cam-zone", list(prims))
