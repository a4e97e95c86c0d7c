"""SVG backend (svgwrite): true scale (size in mm, viewBox in mm), one group per layer role.

Sheet coordinates have y up; SVG has y down, so every y is written as H − y (text is never
mirrored).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

import svgwrite
from svgwrite.container import Group

from mechplan.drafting.fonts import SheetFont, baseline_point, em_size_mm, families_for, font_of
from mechplan.drafting.primitives import (
    DASH_PATTERNS_MM,
    Arc,
    Arrow,
    Block,
    Circle,
    HAlign,
    Line,
    Polyline,
    Primitive,
    Role,
    Sheet,
    Text,
)
from mechplan.drafting.typography import SCRIPT_SIZE, SUB_SHIFT, SUP_SHIFT, has_scripts, runs
from mechplan.errors import DrawingError
from mechplan.render.svg_fonts import font_faces_css

#: Paint order of the role groups (text on top, thick lines over thin ones).
ROLE_ORDER: tuple[Role, ...] = (Role.FILL, Role.THIN, Role.DASHED, Role.CHAIN, Role.DIMENSION,
                                Role.TABLE, Role.OUTLINE, Role.FRAME, Role.TEXT, Role.EXACT,
                                Role.SUBMISSION, Role.ERRORS)
_ANCHOR = {HAlign.LEFT: "start", HAlign.CENTER: "middle", HAlign.RIGHT: "end"}
INK = "black"


def _n(v: float) -> float:
    r = round(v, 4)
    return 0.0 if r == 0 else r


def font_family_css(text: str, font: SheetFont | None = None) -> str:
    """Return the CSS font-family list for `text`, its own font (or `font`) first, generic last."""
    return ", ".join([*(f"'{f}'" if " " in f else f for f in families_for(text, font)),
                      "sans-serif"])


class _Writer:
    def __init__(self, sheet: Sheet) -> None:
        self.sheet = sheet
        self.h = sheet.height_mm
        w = sheet.width_mm
        self.dwg = svgwrite.Drawing(size=(f"{_n(w)}mm", f"{_n(self.h)}mm"), profile="full",
                                    debug=False, viewBox=f"0 0 {_n(w)} {_n(self.h)}")

    def p(self, pt: tuple[float, float]) -> tuple[float, float]:
        return (_n(pt[0]), _n(self.h - pt[1]))

    def role_group(self, role: Role) -> Group:
        st = role.style
        attrs: dict[str, Any] = {"class_": f"role-{role.value.lower()}"}
        if role is Role.TEXT:
            attrs.update(fill=st.ink, stroke="none")
        else:
            attrs.update(fill="none", stroke=st.ink, stroke_width=st.lineweight_mm,
                         stroke_linecap="butt", stroke_linejoin="miter")
            pattern = DASH_PATTERNS_MM[st.linetype]
            if pattern:
                attrs["stroke_dasharray"] = " ".join(str(v) for v in pattern)
        return self.dwg.g(**attrs)

    def add_all(self, parent: Group | svgwrite.Drawing, prims: Iterable[Primitive]) -> None:
        prims = list(prims)
        for role in ROLE_ORDER:
            mine = [p for p in prims if not isinstance(p, Block) and p.role is role]
            if not mine:
                continue
            g = self.role_group(role)
            for p in mine:
                self.add(g, p)
            parent.add(g)
        for blk in (p for p in prims if isinstance(p, Block)):
            g = self.dwg.g(id=blk.name)
            self.add_all(g, blk.primitives)
            parent.add(g)

    def add(self, g: Group, p: Primitive) -> None:
        d = self.dwg
        if isinstance(p, Line):
            g.add(d.line(self.p(p.start), self.p(p.end)))
        elif isinstance(p, Polyline):
            pts = [self.p(v) for v in p.points]
            if p.filled:
                g.add(d.polygon(pts, fill=INK, stroke="none"))
            elif p.closed:
                g.add(d.polygon(pts))
            else:
                g.add(d.polyline(pts))
        elif isinstance(p, Circle):
            g.add(d.circle(self.p(p.center), _n(p.radius)))
        elif isinstance(p, Arc):
            self.add_arc(g, p)
        elif isinstance(p, Arrow):
            shaft = p.shaft()
            if shaft is not None:
                g.add(d.line(self.p(shaft.start), self.p(shaft.end)))
            g.add(d.polygon([self.p(v) for v in p.head()], fill=INK, stroke="none"))
        elif isinstance(p, Text):
            self.add_text(g, p)
        else:
            raise DrawingError(f"SVG backend cannot draw {type(p).__name__}")

    def add_arc(self, g: Group, a: Arc) -> None:
        if a.sweep_deg >= 360.0:
            g.add(self.dwg.circle(self.p(a.center), _n(a.radius)))
            return
        cx, cy = a.center
        t0, t1 = math.radians(a.start_deg), math.radians(a.start_deg + a.sweep_deg)
        x0, y0 = self.p((cx + a.radius * math.cos(t0), cy + a.radius * math.sin(t0)))
        x1, y1 = self.p((cx + a.radius * math.cos(t1), cy + a.radius * math.sin(t1)))
        large = 1 if a.sweep_deg > 180.0 else 0
        # counter-clockwise with y up is sweep-flag 0 with y down
        r = _n(a.radius)
        g.add(self.dwg.path(d=f"M {x0} {y0} A {r} {r} 0 {large} 0 {x1} {y1}"))

    def add_text(self, g: Group, t: Text) -> None:
        if not t.string:
            return
        x, y = self.p(baseline_point(t))
        transform = f"translate({x} {y})"
        if t.rotation_deg:
            transform += f" rotate({_n(-t.rotation_deg)})"
        if t.width_factor != 1.0:
            transform += f" scale({_n(t.width_factor)} 1)"
        attrs: dict[str, Any] = {
            "insert": (0, 0),
            "transform": transform,
            "font_size": _n(em_size_mm(t)),
            "font_family": font_family_css(t.string, font_of(t)),
            "text_anchor": _ANCHOR[t.halign],
        }
        if t.role is not Role.TEXT:
            attrs.update(fill=t.role.style.ink, stroke="none")
        if t.tag:
            attrs["data-tag"] = t.tag
        if not has_scripts(t.string):
            g.add(self.dwg.text(t.string, **attrs))
            return
        # sub- and superscripts: smaller tspans shifted off the baseline and back
        text = self.dwg.text("", **attrs)
        em = em_size_mm(t)
        level = 0.0
        for run, shift in runs(t.string):
            target = {1: SUP_SHIFT, -1: SUB_SHIFT, 0: 0.0}[shift] * t.height_mm
            span: dict[str, Any] = {}
            if target != level:
                span["dy"] = [_n(level - target)]        # SVG y runs down
                level = target
            if shift:
                span["font_size"] = _n(em * SCRIPT_SIZE)
            text.add(self.dwg.tspan(run, **span))
        g.add(text)

    def document(self) -> svgwrite.Drawing:
        d = self.dwg
        title = self.sheet.attributes.get("title")
        if title:
            d.set_desc(title=title)
        faces = font_faces_css(self.sheet)
        if faces:
            d.defs.add(d.style(faces))
        d.add(d.rect((0, 0), (_n(self.sheet.width_mm), _n(self.h)), fill="white", stroke="none"))
        self.add_all(d, self.sheet.primitives)
        return d


def to_svg(sheet: Sheet) -> str:
    """Return the SVG document of `sheet` as a string."""
    return str(_Writer(sheet).document().tostring())
