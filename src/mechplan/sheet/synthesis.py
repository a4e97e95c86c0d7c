"""The synthesis sheet: the K-circle construction drawn to scale, its protocol and conditions."""

from __future__ import annotations

import math

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import (
    Arc,
    Circle,
    HAlign,
    Line,
    Primitive,
    Role,
    Sheet,
    Table,
    Text,
    VAlign,
)
from ..i18n import message, significant
from ..synthesis.linkage.design import LinkageDesign, Stroke
from .diagram import Axis, Curve, diagram_panel, mu_text
from .fit import TableStyle, table_panel, text_block, text_panel
from .layout import fitted_layout
from .panels import Panel

#: the construction's larger side on paper at enlargement 1 (mm)
DRAWING_MM = 150.0
LINE_ROLES = {"given": Role.THIN, "aux": Role.DASHED, "result": Role.THIN,
              "mechanism": Role.OUTLINE, "family": Role.OUTLINE}
LABEL_MM = 3.5
DOT_MM = 0.8


def _extent(strokes: list[Stroke]) -> tuple[float, float, float, float]:
    xs: list[float] = []
    ys: list[float] = []
    for s in strokes:
        if s.kind in ("circle", "arc"):
            xs += [s.a[0] - s.r, s.a[0] + s.r]
            ys += [s.a[1] - s.r, s.a[1] + s.r]
        else:
            xs += [s.a[0], s.b[0]] if s.kind == "line" else [s.a[0]]
            ys += [s.a[1], s.b[1]] if s.kind == "line" else [s.a[1]]
    return min(xs), min(ys), max(xs), max(ys)


def construction_scale(d: LinkageDesign, enlargement: float) -> float:
    """μl (m per mm of paper) of the construction at an enlargement of the sheet."""
    x0, y0, x1, y1 = _extent(d.strokes)
    return round_scale(max(x1 - x0, y1 - y0) / (DRAWING_MM * enlargement))


def construction_panel(d: LinkageDesign, lang: str, enlargement: float) -> Panel:
    """Every stroke of the construction at μl, labelled, with its title and scale above."""
    mu = construction_scale(d, enlargement)

    def at(p: tuple[float, float]) -> tuple[float, float]:
        return p[0] / mu, p[1] / mu

    prims: list[Primitive | Table] = []
    for s in d.strokes:
        role = LINE_ROLES.get(s.role, Role.THIN)
        if s.kind == "line":
            prims.append(Line(at(s.a), at(s.b), role))
            where = at(s.b)
        elif s.kind == "arc":
            prims.append(Arc(at(s.a), s.r / mu, math.degrees(s.b[0]), math.degrees(s.b[1]),
                             role))
            where = at(s.a)
        elif s.kind == "circle":
            prims.append(Circle(at(s.a), max(s.r / mu, DOT_MM), role))
            prims.append(Circle(at(s.a), DOT_MM, Role.OUTLINE))
            where = at(s.a)
        else:
            prims.append(Circle(at(s.a), DOT_MM, Role.OUTLINE))
            where = at(s.a)
        if s.label:
            prims.append(Text((where[0] + 1.5, where[1] + 1.5), s.label, LABEL_MM,
                              halign=HAlign.LEFT, valign=VAlign.BOTTOM))
    x0, _, x1, y1 = Panel("", prims).bounds()
    title = {"function": "synth.sheet.construction_fg",
             "guidance": "synth.sheet.construction_gd",
             "path": "synth.sheet.construction_pg"}.get(d.problem,
                                                            "synth.sheet.construction")
    heading = [message(title, lang),
               mu_text("μl", mu, "m", lang)]
    prims.extend(text_block((x0, y1 + 4.0), heading, 3.5, max(x1 - x0, 60.0), upward=True))
    return Panel("synthesis-construction", prims)


def error_panel(d: LinkageDesign, lang: str, enlargement: float) -> Panel:
    """The structural error Δy(x) of a function generator (zero at the precision points)."""
    samples = np.array(d.conditions["structural_error"], dtype=float)
    dg = diagram_panel("synthesis-error", message("synth.sheet.error", lang),
                       [Curve(samples[:, 0], samples[:, 3])],
                       Axis("x", "", 120.0 * enlargement), Axis("Δy", "", 40.0 * enlargement),
                       lang, x_zero=False)
    return dg.panel


def synthesis_sheets(d: LinkageDesign, protocol: list[str], results: list[str],
                     title: str, size: str | None, standard: str | None, lang: str,
                     name: str, fields: dict[str, str],
                     conditions: list[list[str]] | None = None) -> list[Sheet]:
    """Lay the construction, its protocol, the conditions table and the sentences out on framed
    sheets."""
    size, standard = size or "A2", standard or "iso"

    def build(scale: float) -> list[Panel]:
        extra = [error_panel(d, lang, scale)] if d.problem == "function" else []
        return [construction_panel(d, lang, scale), *extra,
                text_panel("synthesis-protocol", message("synth.sheet.protocol", lang), protocol),
                *([table_panel("synthesis-conditions", message("synth.table.title", lang),
                               conditions, TableStyle(text_h=2.5, row_h=6.0, head_h=7.0))]
                  if conditions and len(conditions) > 1 else []),
                text_panel("synthesis-results", message("synth.sheet.results", lang), results)]

    all_fields = {"title": title, **{k: v for k, v in fields.items() if v}}
    lay = fitted_layout(build, size=size, standard=standard, language=lang, fields=all_fields,
                        grow=True)
    r = construction_scale(d, lay.k_of("synthesis-construction")) * 1000.0
    all_fields.setdefault("scale", f"1:{significant(r, 6, lang)}" if r >= 1
                          else f"{significant(1 / r, 6, lang)}:1")
    return lay.sheets(language=lang, name=name, fields=all_fields)


