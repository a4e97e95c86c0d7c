"""An internal pair's blocking contour on the gear sheet and in the report: the limits in the
(x1, x2) plane (the ring's own lines: its involute above the base circle, tip and trimming
interference), the admissible region hatched, the chosen shifts and each limit's value there."""

from __future__ import annotations

import math

import numpy as np

from ..drafting.primitives import Role
from ..i18n import message, number
from ..synthesis.gears.contour_internal import LIMITS_INTERNAL, InternalPair
from .diagram import Axis, Curve, Marker, diagram_panel
from .gear_contour import HATCH_EVERY, _labelled, chosen_line, limit_label
from .panels import Panel


def internal_lines(ip: InternalPair, lang: str) -> list[str]:
    """The report's sentences: the pair at its shifts, each limit's value, the verdict."""
    q, p = ip.arrays, ip.spec
    c = ip.contour
    out = [message("internal.report.pair", lang, z1=p.z1, z2=p.z2, x1=number(ip.x1, 4, lang),
                   x2=number(ip.x2, 4, lang),
                   alpha_w=number(math.degrees(float(q.alpha_w)), 4, lang),
                   a_w=number(float(q.a_w) * 1e3, 4, lang), eps=number(float(q.eps), 4, lang),
                   ra1=number(float(q.r_a[0]) * 2e3, 3, lang),
                   ra2=number(float(q.r_a[1]) * 2e3, 3, lang)),
           message("internal.report.limits", lang, k=number(c.spec.tip_land, 2, lang),
                   eps=number(c.spec.eps_min, 2, lang)),
           message("internal.report.extra", lang),
           chosen_line(c, lang)]
    for name in LIMITS_INTERNAL:
        v = ip.limits[name]
        ok = math.isfinite(v) and v >= 0
        out.append("  " + message("internal.report.limit", lang, name=limit_label(name, c, lang),
                                  value=number(v, 4, lang) if math.isfinite(v) else "—",
                                  verdict=message("internal.ok" if ok else "internal.fails",
                                                  lang)))
    return out


def internal_panel(ip: InternalPair, lang: str, scale: float) -> Panel:
    """The internal pair's contour: one line per limit, the balanced-sliding line dashed, the
    admissible region hatched, the shifts marked K."""
    c = ip.contour
    curves: list[Curve] = []
    for i, name in enumerate(LIMITS_INTERNAL):
        curves += _labelled(c.lines[name], Role.OUTLINE, limit_label(name, c, lang),
                            0.2 + 0.6 * i / (len(LIMITS_INTERNAL) - 1))
    curves += _labelled(c.balanced, Role.DASHED, message("contour.line.balanced", lang))
    hatch_x: list[float] = []
    hatch_y: list[float] = []
    for i in range(0, c.x1.size, HATCH_EVERY):
        col = np.where(c.mask[i], c.x2, np.nan)
        hatch_x.extend([float(c.x1[i])] * col.size + [math.nan])
        hatch_y.extend([float(v) for v in col] + [math.nan])
    curves.append(Curve(np.asarray(hatch_x), np.asarray(hatch_y), Role.THIN))
    title = message("internal.sheet.title", lang, z1=ip.spec.z1, z2=ip.spec.z2) + "; K: " + \
        chosen_line(c, lang)
    return diagram_panel("gear-contour-internal", title, curves, Axis("x1", "", 150.0 * scale),
                         Axis("x2", "", 150.0 * scale), lang,
                         markers=[Marker(ip.x1, ip.x2, "K")]).panel
