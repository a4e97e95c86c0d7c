"""Panels of the blocking contour (the limits in the (x1, x2) plane, the admissible region hatched,
the chosen shifts) and of the specific-sliding diagram along the line of action."""

from __future__ import annotations

import math

import numpy as np

from ..drafting.primitives import Role
from ..i18n import message, number
from ..synthesis.gears.contour import LIMITS, Contour, Sliding
from ..synthesis.gears.involute import Pair
from .diagram import Axis, Curve, Marker, diagram_panel
from .panels import Panel

HATCH_EVERY = 4        # every 4th grid column of the admissible region is hatched


def limit_label(name: str, c: Contour, lang: str) -> str:
    """The short name written at the end of a limit's line ("x1 min", "s_a1 = 0,25·m")."""
    return message(f"contour.line.{name}", lang, k=number(c.spec.tip_land, 2, lang),
                   eps=number(c.spec.eps_min, 2, lang))


def chosen_line(c: Contour, lang: str) -> str:
    """The sentence saying which shifts were chosen and why."""
    return message(f"contour.chosen.{c.rule}", lang, x1=number(c.recommended[0], 4, lang),
                   x2=number(c.recommended[1], 4, lang), eps=number(c.eps, 4, lang))


def _labelled(line: np.ndarray, role: Role, label: str, at: float = 0.5) -> list[Curve]:
    """A NaN-separated line as one curve per branch, the longest one labelled at the fraction
    ``at`` of its points."""
    cut = np.flatnonzero(~np.isfinite(line[:, 0]))
    parts = [b for b in np.split(line, cut) if np.isfinite(b[:, 0]).sum() > 1]
    parts = [b[np.isfinite(b[:, 0])] for b in parts]
    if not parts:
        return []
    longest = max(range(len(parts)), key=lambda k: len(parts[k]))
    out = [Curve(b[:, 0], b[:, 1], role) for k, b in enumerate(parts) if k != longest]
    # labelled inside the longest branch (the ends crowd at the grid's edges): its first part
    # carries the label at its end, the rest continues the line
    b = parts[longest]
    mid = min(max(1, int(len(b) * at)), len(b) - 1)
    out.append(Curve(b[: mid + 1, 0], b[: mid + 1, 1], role, label))
    if len(b) - mid > 1:
        out.append(Curve(b[mid:, 0], b[mid:, 1], role))
    return out


def contour_panel(c: Contour, pair: Pair, lang: str, scale: float) -> Panel:
    """The contour diagram: one line per limit, the balanced-sliding line dashed, the admissible
    region hatched by vertical thin lines, the chosen point marked."""
    curves: list[Curve] = []
    for i, name in enumerate(LIMITS):       # labels staggered along their lines
        curves += _labelled(c.lines[name], Role.OUTLINE, limit_label(name, c, lang),
                            0.2 + 0.6 * i / (len(LIMITS) - 1))
    curves += _labelled(c.balanced, Role.DASHED, message("contour.line.balanced", lang))
    hatch_x, hatch_y = [], []
    for i in range(0, c.x1.size, HATCH_EVERY):
        col = np.where(c.mask[i], c.x2, np.nan)
        hatch_x.extend([c.x1[i]] * col.size + [math.nan])
        hatch_y.extend(list(col) + [math.nan])
    curves.append(Curve(np.asarray(hatch_x), np.asarray(hatch_y), Role.THIN))
    x1, x2 = c.recommended
    title = (message("contour.sheet.title", lang, z1=pair.spec.z1, z2=pair.spec.z2)
             + "; K: " + chosen_line(c, lang))
    dg = diagram_panel("gear-contour", title, curves, Axis("x1", "", 150.0 * scale),
                       Axis("x2", "", 150.0 * scale), lang,
                       markers=[Marker(x1, x2, "K")])
    return dg.panel


def sliding_panel(s: Sliding, pair: Pair, lang: str, scale: float) -> Panel:
    """η1 and η2 along N1N2 (u from N1, mm), clipped to −5 … 1, with B1, B2 marked."""
    u_mm = s.u * 1000.0
    lo = -5.0
    curves = [Curve(u_mm, np.where(s.eta1 >= lo, s.eta1, np.nan), Role.OUTLINE, "η1"),
              Curve(u_mm, np.where(s.eta2 >= lo, s.eta2, np.nan), Role.OUTLINE, "η2")]
    for b in (s.b1, s.b2):
        curves.append(Curve(np.array([b, b]) * 1000.0, np.array([lo, 1.0]), Role.DASHED))
    markers = [Marker(s.b1 * 1000.0, 1.0, "B1"), Marker(s.b2 * 1000.0, 1.0, "B2"),
               Marker(0.0, 1.0, "N1"), Marker(s.g * 1000.0, 1.0, "N2")]
    dg = diagram_panel("gear-sliding", message("contour.sheet.sliding", lang), curves,
                       Axis("u", "mm", 150.0 * scale), Axis("η", "", 80.0 * scale), lang,
                       markers=markers)
    return dg.panel
