"""The cam sheet: s, s′, s″ diagrams, the s′–s diagram with its admissible zone, the construction of
the profile by inversion, the results and the profile table, on framed sheets."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import (
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
from ..i18n import message, number, significant, unit
from ..model.cam import Contact, Motion
from ..synthesis.cam.profile import follower_positions
from .diagram import Axis, Curve, Marker, diagram_panel, mu_number, mu_text, scale_for
from .fit import TableStyle, table_panel, text_block, text_panel
from .layout import fitted_layout
from .panels import Panel

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet
    from ..synthesis.cam import CamDesign

DIAGRAM_W = 180.0      # mm, the φ axis of a full turn
DIAGRAM_H = 45.0       # mm
CAM_R = 110.0          # mm, largest radius of the inversion drawing
STEP = 10              # every 10th dense sample on the curves (0.1°)


@dataclass(frozen=True)
class Units:
    """How s, s′, s″, v, a are written: factor from SI and unit text."""

    f0: float
    f1: float                  # factor of s′ and s″
    u0: str
    u1: str
    u2: str
    uv: str
    ua: str


_SI = {"mm": "mm", "deg": "°", "m_s": "m/s", "m_s2": "m/s²", "rad": "rad", "rad_rad": "rad/rad",
       "per_rad": "1/rad", "rad_s": "rad/s", "rad_s2": "rad/s²"}


def units_of(d: CamDesign, lang: str) -> Units:
    """Millimetres for a translating follower, degrees and radians for an oscillating one."""
    def u(name: str) -> str:
        return unit(_SI[name], lang)
    if d.spec.follower.motion is Motion.TRANSLATING:
        return Units(1e3, 1e3, u("mm"), u("mm"), u("mm"), u("m_s"), u("m_s2"))
    return Units(180.0 / math.pi, 1.0, u("deg"), u("rad_rad"), u("per_rad"), u("rad_s"),
                 u("rad_s2"))


def table_rows(d: CamDesign, lang: str) -> tuple[list[str], list[list[str]]]:
    """Heading and rows of the profile table, formatted for ``lang``."""
    from ..synthesis.cam import profile_table

    u = units_of(d, lang)
    head = [message("cam.col.phi", lang), message("cam.col.s", lang, u=u.u0),
            message("cam.col.s1", lang, u=u.u1), message("cam.col.s2", lang, u=u.u2),
            message("cam.col.alpha", lang), message("cam.col.rho", lang),
            message("cam.col.theta", lang), message("cam.col.x", lang), message("cam.col.y", lang)]
    rows = []
    for r in profile_table(d.table):
        rows.append([number(math.degrees(r["phi"]), 1, lang), number(r["s"] * u.f0, 3, lang),
                     number(r["s1"] * u.f1, 3, lang), number(r["s2"] * u.f1, 3, lang),
                     number(math.degrees(r["alpha"]), 2, lang), number(r["rho"] * 1e3, 3, lang),
                     number(math.degrees(r["theta"]), 2, lang), number(r["x"] * 1e3, 3, lang),
                     number(r["y"] * 1e3, 3, lang)])
    return head, rows




def _motion_diagrams(d: CamDesign, lang: str, scale: float) -> list[Panel]:
    u = units_of(d, lang)
    phi_deg = np.degrees(d.dense.phi[::STEP])
    phi_deg = np.append(phi_deg, 360.0)
    def closed(v: np.ndarray, f: float) -> np.ndarray:
        return np.append(v[::STEP], v[0]) * f
    mu_deg = round_scale(360.0 / (DIAGRAM_W * scale))
    x_axis = Axis("φ", "°", 360.0 / mu_deg, mu=mu_deg)
    panels = []
    mus = []
    for name, values, u_y, f in (("s", d.dense.s, u.u0, u.f0), ("s1", d.dense.s1, u.u1, u.f1),
                                 ("s2", d.dense.s2, u.u2, u.f1)):
        y = closed(values, f)
        curves = [Curve(phi_deg, y)]
        for c in d.comparisons:        # the graphical differentiation (chords), dashed
            if name == "s1":
                curves.append(Curve(np.degrees(c.mids), c.s1_by_chords * f, Role.DASHED))
            elif name == "s2" and c.inner_nodes.size > 1:
                curves.append(Curve(np.degrees(c.inner_nodes), c.s2_by_chords * f, Role.DASHED))
        symbol = {"s": "s", "s1": "s′", "s2": "s″"}[name]
        dg = diagram_panel(f"cam-{name}", message(f"cam.sheet.{name}", lang),
                           curves, x_axis, Axis(symbol, u_y, DIAGRAM_H * scale), lang)
        panels.append(dg)
        mus.append(dg.mu_y / f)             # SI per mm
    mu_phi = math.radians(mu_deg)
    out = []
    for i, dg in enumerate(panels):
        if i > 0:
            # pole distance of the graphical differentiation from the diagram above
            H = mus[i - 1] / (mus[i] * mu_phi)
            x0, y0, x1, _ = dg.panel.bounds()
            dg.panel.primitives.extend(text_block(
                (x0, y0 - 4.0), message("cam.sheet.pole", lang, H=number(H, 1, lang)), 2.5,
                x1 - x0, valign=VAlign.TOP))
        out.append(dg.panel)
    return out


def _ss1_diagram(d: CamDesign, lang: str, scale: float) -> Panel | None:
    if d.zone is None:
        return None
    k = 1e3
    s1, s = d.dense.s1[::STEP] * k, d.dense.s[::STEP] * k
    cx, cy = d.zone.centre[0] * k, d.zone.centre[1] * k
    low = cy * 1.25 - 2.0
    curves = [Curve(np.append(s1, s1[0]), np.append(s, s[0]), Role.OUTLINE)]
    for h in d.zone.planes:
        ax, ay = h.at[0] * k, h.at[1] * k
        dx, dy = -h.n[1], h.n[0]          # along the boundary line
        if dy > 0:
            dx, dy = -dx, -dy
        t = (low - ay) / dy
        curves.append(Curve(np.array([ax, ax + t * dx]), np.array([ay, low]), Role.THIN))
    curves.append(Curve(np.array([cx, 0.0]), np.array([cy, 0.0]), Role.DASHED,
                        label=f"r0 = {number(d.zone.r0 * k, 2, lang)}"))
    span = max(float(np.ptp(np.append(s1, cx))), float(np.ptp(np.append(s, low))))
    mu = round_scale(span / (110.0 * scale))
    dg = diagram_panel("cam-ss1", message("cam.sheet.ss1", lang), curves,
                       Axis("s′", "mm", 110.0 * scale, mu=mu),
                       Axis("s", "mm", 110.0 * scale, mu=mu), lang,
                       markers=[Marker(cx, cy, "O")])
    zx, zy = dg.to_mm(cx, cy * 1.1 - 1.0)
    dg.panel.primitives.append(Text((zx, zy), message("cam.sheet.zone", lang), 2.5,
                                    halign=HAlign.CENTER, valign=VAlign.TOP))
    return dg.panel


def _inversion(d: CamDesign, lang: str, scale: float) -> tuple[Panel, float]:
    g = d.geometry
    reach = float(np.max(np.hypot(*d.dense.pitch.T)))
    if g.motion is Motion.OSCILLATING:
        reach = max(reach, g.pivot + 0.1 * g.arm)
    length = 0.35 * g.r0
    mu = round_scale((reach + length + g.roller) / (CAM_R * scale))   # m per mm
    def mm(p: np.ndarray) -> list[tuple[float, float]]:
        return [(float(x) / mu, float(y) / mu) for x, y in p]
    prims: list[Primitive | Table] = []
    prims.append(Line((-4.0, 0.0), (4.0, 0.0), Role.THIN))
    prims.append(Line((0.0, -4.0), (0.0, 4.0), Role.THIN))
    prims.append(Text((1.5, -1.5), "O", 3.5, valign=VAlign.TOP))
    prims.append(Circle((0.0, 0.0), g.r0 / mu, Role.CHAIN))
    if g.motion is Motion.TRANSLATING and abs(g.e) > 1e-9:
        prims.append(Circle((0.0, 0.0), abs(g.e) / mu, Role.DASHED))
    if g.motion is Motion.OSCILLATING:
        prims.append(Circle((0.0, 0.0), g.pivot / mu, Role.CHAIN))
    pitch = d.dense.pitch[::STEP]
    steps: dict[int, str] = {}        # the live page's replay: which ray draws what
    if d.spec.follower.contact is not Contact.FLAT:
        steps[len(prims)] = "profile"
        prims.append(Polyline(tuple(mm(pitch)), Role.DASHED, closed=True))
    steps[len(prims)] = "profile"
    prims.append(Polyline(tuple(mm(d.profile_points)), Role.OUTLINE, closed=True))
    rays = d.rays
    a, b = follower_positions(g, rays, length)
    for i in range(rays.phi.size):
        first = len(prims)
        p = rays.pitch[i] / mu
        prims.append(Line((0.0, 0.0), (float(p[0]), float(p[1])), Role.THIN))
        if d.spec.follower.contact is Contact.FLAT and g.motion is Motion.OSCILLATING:
            lo, hi = d.face or (0.0, g.pivot)             # the face from the turned pivot
            t = (b[i] - a[i]) / np.hypot(*(b[i] - a[i]))
            prims.append(Line(tuple(((a[i] + lo * t) / mu).tolist()),
                              tuple(((a[i] + hi * t) / mu).tolist()), Role.THIN))
        elif d.spec.follower.contact is Contact.FLAT:
            lo, hi = d.face or (-0.01, 0.01)
            if g.sense < 0:                  # the s′ side is mirrored with the cam
                lo, hi = -hi, -lo
            t = np.array([rays.normal[i, 1], -rays.normal[i, 0]])
            base = rays.pitch[i] - rays.s1[i] * t * (1 if g.sense > 0 else -1)
            prims.append(Line(tuple(((base + lo * t) / mu).tolist()),
                              tuple(((base + hi * t) / mu).tolist()), Role.THIN))
        else:
            prims.append(Line(tuple((a[i] / mu).tolist()), tuple((b[i] / mu).tolist()), Role.THIN))
        if g.roller > 0:
            prims.append(Circle((float(p[0]), float(p[1])), g.roller / mu, Role.THIN))
        r = math.hypot(*p)
        lbl = p * (1 + 6.0 / r) if r > 0 else p
        prims.append(Text((float(lbl[0]), float(lbl[1])), str(i), 2.5, halign=HAlign.CENTER,
                          valign=VAlign.MIDDLE))
        steps.update(dict.fromkeys(range(first, len(prims)), f"ray-{i}"))
    top = max(y for p in prims if isinstance(p, Circle) for y in (p.center[1] + p.radius,))
    left, _, right, _ = Panel("", prims).bounds()
    y = top + 3.0
    for text, height, gap in (
            (["— " + message("cam.sheet.working", lang), "- - " + message("cam.sheet.pitch", lang)],
             2.5, 5.0),
            ([message("cam.sheet.scale", lang, mu=mu_number(mu, lang)),
              message("cam.sheet.base", lang, r0=number(g.r0 * 1e3, 2, lang))], 2.5, 6.0),
            (message("cam.sheet.inversion", lang), 3.5, 0.0)):
        block = text_block((left, y), text, height, right - left, upward=True)
        prims.extend(block)
        y = block[0].position[1] + gap
    return Panel("cam-inversion", list(prims), steps=steps), mu


def _results(keep: list[str], lang: str) -> Panel:
    return text_panel("cam-results", message("cam.sheet.results", lang), keep)


def _table(head: list[str], rows: list[list[str]], lang: str) -> Panel:
    widths = (12.0, 14.0, 14.0, 16.0, 13.0, 15.0, 14.0, 15.0, 15.0)
    return table_panel("cam-table", message("cam.sheet.table", lang), [head, *rows],
                       TableStyle(text_h=1.8, row_h=4.5, head_h=6.0), widths=widths)


def cam_sheets(d: CamDesign, summary: list[str], table: tuple[list[str], list[list[str]]],
               size: str | None, standard: str | None, lang: str, name: str) -> list[Sheet]:
    """Lay the cam's panels out on framed sheets; ``summary`` are the report's result sentences."""
    spec = d.spec
    size, standard = size or spec.drawing.sheet, standard or spec.drawing.standard

    def build(scale: float) -> tuple[list[Panel], float]:
        inversion, mu = _inversion(d, lang, scale)
        panels = [inversion, *_motion_diagrams(d, lang, scale)]
        ss1 = _ss1_diagram(d, lang, scale)
        if ss1 is not None:
            panels.append(ss1)
        from .cam_dynamics import dynamics_panels
        from .cam_zone import zone_panel

        zone = zone_panel(d, lang, scale)
        if zone is not None:
            panels.append(zone)

        panels.extend(dynamics_panels(d, lang, scale, DIAGRAM_W, DIAGRAM_H))
        return panels + [_table(*table, lang), _results(summary, lang)], mu

    fields = {"title": spec.title}
    fields.update({k: v for k, v in spec.drawing.title_block.items() if v})
    lay = fitted_layout(lambda scale: build(scale)[0], size=size, standard=standard,
                        language=lang, fields=fields, grow=True)
    r = _inversion(d, lang, lay.k_of("cam-inversion"))[1] * 1000.0
    fields.setdefault("scale", f"1:{significant(r, 6, lang)}" if r >= 1
                      else f"{significant(1 / r, 6, lang)}:1")
    return lay.sheets(language=lang, name=name, fields=fields)


__all__ = ["Units", "cam_sheets", "mu_text", "scale_for", "table_rows", "units_of"]
