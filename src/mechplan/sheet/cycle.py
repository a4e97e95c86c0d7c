"""The cycle diagram of a machine as the courses draw it: rectangular (one strip per member,
stacked, phase boundaries and the output's level drawn in each strip, main-shaft angle ψ below)
and circular (one ring per member, phases as sectors, ψ counter-clockwise from the right)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..drafting.fonts import text_width_mm
from ..drafting.primitives import Arc, Circle, HAlign, Line, Polyline, Primitive, Role, Text, VAlign
from ..i18n import message, number
from .diagram import Axis, Curve, diagram_panel
from .fit import text_block
from .layout import fitted_sheets
from .panels import Panel

if TYPE_CHECKING:
    from ..construct.cycle import MemberCycle
    from ..drafting.primitives import Sheet
    from ..dynamics.cam_linkage import CamLinkage

WIDTH = 180.0       # mm for 360° of the rectangular diagram
STRIP = 14.0        # mm, the height of one member's strip
TEXT_H = 2.5
SMALL_H = 1.8       # mm, the phases' names and angles
TITLE_H = 3.5
RING = 10.0         # mm, the width of one member's ring
HUB = 15.0          # mm, the radius inside the innermost ring
STEP = 5            # every fifth degree of a cam-driven linkage's diagrams


@dataclass(frozen=True)
class CycleView:
    """What the diagrams show: the members' phases and ψ of the diagram's origin (rad)."""

    members: tuple[MemberCycle, ...]
    origin: float
    lines: tuple[str, ...] = ()             # the machine's table in words (motor, shafts, …)
    driven: tuple[CamLinkage, ...] = ()     # linkages turned by a cam's follower


def _kind(kind: str, lang: str) -> str:
    return message(f"machine_cycle.kind.{kind}", lang)


def rectangular_panel(st: CycleView, lang: str, k: float) -> Panel:
    """The rectangular diagram: strips top to bottom in the order of the machine file."""
    w, h = WIDTH * k, STRIP * k
    prims: list[Primitive] = []
    n = len(st.members)
    for row, m in enumerate(st.members):
        y0 = (n - 1 - row) * h
        prims.append(Polyline(((0, y0), (w, y0), (w, y0 + h), (0, y0 + h)), Role.OUTLINE,
                              closed=True))
        prims.append(Text((-2.0, y0 + h / 2), f"{row + 1}. {m.name}", TEXT_H,
                          halign=HAlign.RIGHT, valign=VAlign.MIDDLE))
        for s, a, b in m.on_shaft(st.origin):
            xa, xb = a / (2 * math.pi) * w, b / (2 * math.pi) * w
            prims.append(Line((xa, y0), (xa, y0 + h), Role.THIN))
            # the output's level across the span (split spans: the part of the level between)
            full = s.angle if s.angle > 0 else 1.0
            t0 = m.fraction_in(s, a, st.origin)
            t1 = t0 + (b - a) * m.turns / full
            la = s.level0 + (s.level1 - s.level0) * t0
            lb = s.level0 + (s.level1 - s.level0) * t1
            pad = 0.2 * h
            prims.append(Line((xa, y0 + pad + la * (h - 2 * pad)),
                              (xb, y0 + pad + lb * (h - 2 * pad)), Role.OUTLINE))
            # a phase's name and angle only where they fit between its boundaries
            name, angle = _kind(s.kind, lang), f"{number(math.degrees(b - a), 1, lang)}°"
            if text_width_mm(name, SMALL_H) < xb - xa - 1.0:
                prims.append(Text(((xa + xb) / 2, y0 + h - 1.0), name, SMALL_H,
                                  halign=HAlign.CENTER, valign=VAlign.TOP))
            if text_width_mm(angle, SMALL_H) < xb - xa - 1.0:
                prims.append(Text(((xa + xb) / 2, y0 + 1.0), angle, SMALL_H,
                                  halign=HAlign.CENTER, valign=VAlign.BOTTOM))
    for deg in range(0, 361, 30):
        x = deg / 360 * w
        prims.append(Line((x, -1.5), (x, 0.0), Role.THIN))
        prims.append(Text((x, -2.0), f"{deg}", 1.8, halign=HAlign.CENTER, valign=VAlign.TOP))
    prims.append(Text((w + 2.0, -2.0), "ψ, °", TEXT_H, valign=VAlign.TOP))
    title = message("machine_cycle.sheet.rectangular", lang,
                    start=number(math.degrees(st.origin), 1, lang))
    prims.extend(text_block((0.0, n * h + 4.0), title, TITLE_H, w, upward=True))
    return Panel("cycle-rectangular", list(prims))


def circular_panel(st: CycleView, lang: str, k: float) -> Panel:
    """The circular diagram: the first member on the outer ring, ψ counter-clockwise from the
    right (the shaft's sense of rotation), ψ = 0 at the diagram's origin."""
    prims: list[Primitive] = []
    n = len(st.members)
    r_in = HUB * k
    ring = RING * k
    r_out = r_in + n * ring
    prims.append(Circle((0.0, 0.0), r_in, Role.THIN))
    for row, m in enumerate(st.members):
        r1 = r_out - row * ring
        r0 = r1 - ring
        prims.append(Circle((0.0, 0.0), r1, Role.OUTLINE))
        for s, a, b in m.on_shaft(st.origin):
            prims.append(Line((r0 * math.cos(a), r0 * math.sin(a)),
                              (r1 * math.cos(a), r1 * math.sin(a)), Role.OUTLINE))
            if s.level0 == s.level1 and s.level0 > 0:       # far dwell: a thick arc outside
                prims.append(Arc((0.0, 0.0), r0 + 0.7 * ring, math.degrees(a), math.degrees(b),
                                 Role.OUTLINE))
            mid = (a + b) / 2
            angle = f"{number(math.degrees(b - a), 1, lang)}°"
            if (b - a) * (r0 + r1) / 2 > text_width_mm(angle, SMALL_H) + 2.0:
                rm = (r0 + r1) / 2
                prims.append(Text((rm * math.cos(mid), rm * math.sin(mid)), angle, SMALL_H,
                                  halign=HAlign.CENTER, valign=VAlign.MIDDLE))
        # the member's number (the legend's) just above ψ = 0 inside its ring
        prims.append(Text((r0 + ring / 2, 0.5), str(row + 1), SMALL_H, halign=HAlign.CENTER,
                          valign=VAlign.BOTTOM))
    prims.append(Line((0.0, 0.0), (r_out + 4.0, 0.0), Role.DASHED))
    prims.append(Text((r_out + 5.0, 0.0), "ψ = 0", TEXT_H, valign=VAlign.MIDDLE))
    prims.extend(text_block((-r_out, r_out + 4.0), message("machine_cycle.sheet.circular", lang),
                            TITLE_H, 2 * r_out, upward=True))
    return Panel("cycle-circular", list(prims))


def legend_panel(st: CycleView, lang: str, k: float) -> Panel:
    """Each member's phases in words (kind, angle, ψ from … to …)."""
    lines = []
    for i, m in enumerate(st.members, start=1):
        spans = "; ".join(f"{_kind(sp.kind, lang)} {number(math.degrees(a), 1, lang)}–"
                          f"{number(math.degrees(b), 1, lang)}°"
                          for sp, a, b in m.on_shaft(st.origin))
        lines.append(f"{i}. {m.name}: {spans}")
    lines.extend(st.lines)

    def drawn(width: float) -> Panel:
        return Panel("cycle-legend", list(text_block((0.0, 0.0), lines, TEXT_H, width)))

    panel = drawn(WIDTH * k)
    # into a sheet's free room narrower than it: its lines rewrapped to the room's width
    panel.split_off = lambda w, h: [drawn(min(w, WIDTH * k))]
    return panel


def cycle_sheets(st: CycleView, title: str, size: str | None, standard: str | None,
                 lang: str, name: str) -> list[Sheet]:
    """The rectangular and the circular cycle diagrams and their legend on framed sheets."""
    title = title or message("machine_cycle.sheet.title", lang)
    return fitted_sheets(lambda k: [rectangular_panel(st, lang, k), circular_panel(st, lang, k),
                                    legend_panel(st, lang, k),
                                    *(p for d in st.driven
                                      for p in driven_panels(d, lang, k, size or "A3",
                                                             standard or "iso"))],
                         size=size or "A3", standard=standard or "iso", language=lang, name=name,
                         fields={"title": title}, split=True)


def driven_panels(d: CamLinkage, lang: str, k: float, size: str = "A3",
                  standard: str = "iso") -> list[Panel]:
    """A cam-driven linkage over the cam's turn: its output, and (loaded) the contact force and
    the cam torque."""
    phi = np.append(np.degrees(d.phi[::STEP]), 360.0)

    def closed(v: np.ndarray) -> np.ndarray:
        return np.append(v[::STEP], v[0])
    x_axis = Axis("φ", "°", 120.0 * k)
    out = [diagram_panel(f"driven-{d.name}-output",
                         message("machine.sheet.output", lang, name=d.name, output=d.output),
                         [Curve(phi, closed(d.out - d.out[0]), Role.OUTLINE)], x_axis,
                         Axis("Δθ" if d.rocker else "Δs", "rad" if d.rocker else "m", 40.0 * k),
                         lang).panel]
    out += plan_panels(d, lang, k, size, standard)
    if d.contact is not None and d.torque is not None:
        out.append(diagram_panel(f"driven-{d.name}-contact",
                                 message("machine.sheet.contact", lang, name=d.name),
                                 [Curve(phi, closed(d.contact), Role.OUTLINE)], x_axis,
                                 Axis("N", "N", 40.0 * k), lang).panel)
        out.append(diagram_panel(f"driven-{d.name}-torque",
                                 message("machine.sheet.torque", lang, name=d.name),
                                 [Curve(phi, closed(d.torque), Role.OUTLINE)], x_axis,
                                 Axis("T", "N·m", 40.0 * k), lang).panel)
    return out


def plan_panels(d: CamLinkage, lang: str, k: float, size: str = "A3",
                standard: str = "iso") -> list[Panel]:
    """The linkage's velocity and acceleration plans at the cam angle where its follower is
    fastest: the scene's own construction with the driver's rates from the cam's law; each
    plan's drawing under a wrapped title, its tables on a panel of their own."""
    from ..construct.scale import choose_scale
    from ..construct.step import Kind
    from ..model.plans import Plan
    from .panels import vector_plan

    c, ev, i = d.plans()
    if c is None or ev is None:
        return []
    out: list[Panel] = []
    for plan, key in ((Plan.VELOCITY, "machine.sheet.plan_v"),
                      (Plan.ACCELERATION, "machine.sheet.plan_a")):
        steps = list(c.of_plan(plan))
        if not steps:
            continue
        ev.evaluate_all([s.id for s in steps])
        sizes = [float(np.hypot(*np.asarray(ev.values[s.id])[i])) for s in steps
                 if s.kind is Kind.POINT and np.asarray(ev.values[s.id]).ndim == 2]
        sizes = [x for x in sizes if np.isfinite(x)]
        if not sizes or max(sizes) == 0:
            continue
        mu = choose_scale(max(sizes), 60.0 * k)
        title = message(key, lang, name=d.name,
                        phi=number(float(np.degrees(d.phi[i])), 1, lang))
        panel = vector_plan(c, ev, i, plan, mu, lang, title)
        # the one-line title wrapped to the drawing's measure; a vector equation written wider
        # than the plan and its tables is left to the tables (its rows say the same)
        lo, _, hi, _ = Panel("", [q for q in panel.primitives if not isinstance(q, Text)]
                             ).bounds()
        panel.primitives[:] = [q for q in panel.primitives if not (
            isinstance(q, Text) and (q.string == title or _sticks_out(q, lo, hi)))]
        x0, _y0, _x1, y1 = panel.bounds()
        panel.primitives.extend(text_block((x0, y1 + 4.0), title, TEXT_H,
                                           max(40.0, min(hi - lo, 55.0)), upward=True,
                                           measure_min=40.0))
        out.append(panel)
    return out


def _sticks_out(t: Text, lo: float, hi: float) -> bool:
    """A text wider than 40 mm reaching past the drawing's x-extent lo … hi."""
    x0, _, x1, _ = Panel("", [t]).bounds()
    return x1 - x0 > 40.0 and (x1 > hi + 0.5 or x0 < lo - 0.5)
