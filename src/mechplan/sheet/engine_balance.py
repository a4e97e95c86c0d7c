"""Sheets of an engine's balancing: the star of cranks of the 1st and 2nd order with the force
and moment polygons of each bank, the free reciprocating force over a turn (exact and series),
the tables of the orders, the counterweights and the main-journal loads."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import Circle, HAlign, Line, Role, Text, VAlign
from ..dynamics.engine.balance import Balance, extremes, turning
from ..i18n import message, number
from .diagram import TEXT_H, Axis, Curve, diagram_panel, mu_text
from .fit import TableStyle, table_panel, text_block
from .panels import Panel

STYLE = TableStyle(text_h=1.8, row_h=4.0, head_h=6.0)


def orders_cells(b: Balance, lang: str) -> list[list[str]]:
    """Heading and rows of the orders table: amplitudes exact and by the series, free force and
    moment (maxima over the turn), the parts turning with and against the crank."""
    def n(x: float, k: int = 2) -> str:
        return number(x, k, lang)

    m = "M" if b.spacing_given else "M_a"
    head = [message(f"balance.col.{c}", lang) for c in
            ("order", "A", "A_series", "F", "F_series", "dF", m, m + "_series", "forward",
             "backward")]
    rows = [head]
    for k, o in b.orders.items():
        f, bk = turning(o.F)
        Fs = extremes(o.F_series)[0] if o.F_series is not None else None
        Ms = extremes(o.M_series)[0] if o.M_series is not None else None
        rows.append([str(k), number(o.A, 6, lang),
                     "—" if o.A_series is None else number(o.A_series, 6, lang),
                     n(o.F_max), "—" if Fs is None else n(Fs),
                     "—" if Fs is None else n(o.F_max - Fs), n(o.M_max),
                     "—" if Ms is None else n(Ms), n(abs(f)), n(abs(bk))])
    return rows


def counterweight_cells(b: Balance, lang: str) -> list[list[str]]:
    """Throw, counterweight mass reduced to R, m·r of one cheek, one cheek's mass."""
    cw = b.counterweights
    head = [message(f"balance.col.{c}", lang) for c in ("throw", "z", "reduced", "mr", "mass")]
    rows = [head]
    for p in sorted(cw.reduced):
        rows.append([str(p), number(b.positions[p] * (1e3 if b.spacing_given else 1.0),
                                    1 if b.spacing_given else 0, lang),
                     number(cw.reduced[p], 4, lang), number(cw.per_cheek[p] * 1e3, 3, lang),
                     "—" if cw.mass is None else number(cw.mass[p], 4, lang)])
    return rows


def journal_cells(b: Balance, phi: np.ndarray, lang: str) -> list[list[str]]:
    """Journal, max and mean load (kN) before and after the counterweights."""
    cw = b.counterweights
    head = [message(f"balance.col.{c}", lang) for c in
            ("journal", "max_before", "max_after", "mean_before", "mean_after")]
    rows = [head]
    span = phi[-1] - phi[0]
    for j, (J0, J1) in enumerate(zip(cw.journals_before, cw.journals_after)):
        m0, m1 = np.hypot(J0[:, 0], J0[:, 1]), np.hypot(J1[:, 0], J1[:, 1])
        rows.append([str(j + 1)] + [number(v * 1e-3, 3, lang) for v in (
            float(m0.max()), float(m1.max()), float(np.trapezoid(m0, phi) / span),
            float(np.trapezoid(m1, phi) / span))])
    return rows


def _polygon(vectors: list[tuple[int, complex]], mu: float, start: tuple[float, float],
             lang: str) -> tuple[list[Any], tuple[float, float]]:
    """Vectors head to tail from ``start`` (mm) with the closing resultant dashed; returns the
    primitives and the end point."""
    prims: list[Any] = []
    x, y = start
    for number_, v in vectors:
        dx, dy = v.real / mu, v.imag / mu
        if math.hypot(dx, dy) > 1e-6:
            prims.append(Line((x, y), (x + dx, y + dy), Role.OUTLINE))
            prims.append(Text((x + dx / 2 + 0.8, y + dy / 2 + 0.8), str(number_), 1.8))
        x, y = x + dx, y + dy
    prims.append(Circle(start, 0.5, Role.OUTLINE))
    if math.hypot(x - start[0], y - start[1]) > 1e-6:
        prims.append(Line(start, (x, y), Role.DASHED))
    return prims, (x, y)


def _extent(vectors: list[complex]) -> float:
    pts = np.cumsum([0j, *vectors])
    return max(float(np.ptp(pts.real)), float(np.ptp(pts.imag)), 0.0)


def star_panel(b: Balance, phases: dict[int, float], banks: dict[int, float], k: int, lang: str,
               scale: float = 1.0) -> Panel:
    """Star of cranks of order k (crank i at −k·δ_i) and, for every bank, the polygons of the
    cylinders' shares of the order's force m_j·c_k and moment m_j·c_k·(z − z0) at φ = 0."""
    r = 22.0 * scale
    prims: list[Any] = [Circle((0.0, 0.0), r, Role.THIN)]
    by_angle: dict[int, list[int]] = {}
    for n, d in phases.items():
        key = round(math.degrees(-k * d) % 360.0 * 1000) % 360000
        by_angle.setdefault(key, []).append(n)
    for key, members in by_angle.items():
        a = math.radians(key / 1000.0)
        ux, uy = math.cos(a), math.sin(a)
        prims.append(Line((0.0, 0.0), (r * ux, r * uy), Role.OUTLINE))
        prims.append(Text((1.18 * r * ux, 1.18 * r * uy), ",".join(map(str, sorted(members))),
                          TEXT_H, halign=HAlign.CENTER, valign=VAlign.MIDDLE))
    groups: dict[int, list[int]] = {}
    for n, g in banks.items():
        groups.setdefault(round(math.degrees(g) * 1000) % 360000, []).append(n)
    forces = [[(n, complex(b.terms[n][k])) for n in sorted(g)] for g in groups.values()]
    moments = [[(n, complex(b.terms[n][k]) * b.arms[n]) for n in sorted(g)]
               for g in groups.values()]
    size = 34.0 * scale
    mu_F = round_scale(max(max(_extent([v for _, v in f]) for f in forces), 1e-12) / size)
    ext_M = max(_extent([v for _, v in m]) for m in moments)
    mu_M = round_scale(ext_M / size) if ext_M > 1e-9 * mu_F else None
    x = r + 16.0 * scale
    notes = [mu_text("μF", mu_F, "N", lang)]
    heads: list[tuple[float, str]] = []
    for kind, polys, mu in (("force_polygon", forces, mu_F), ("moment_polygon", moments, mu_M)):
        if mu is None:
            continue
        heads.append((x, message(f"balance.label.{kind}", lang)))
        for poly in polys:
            pts = np.cumsum([0j, *[v / mu for _, v in poly]])
            start = (x - float(pts.real.min()), -float(pts.imag.mean()))
            drawn, _ = _polygon(poly, mu, start, lang)
            prims += drawn
            x += max(float(np.ptp(pts.real)), 4.0) + 10.0 * scale
    if mu_M is not None:
        unit_M = "N·m" if b.spacing_given else "N·a"
        notes.append(mu_text("μM", mu_M, unit_M, lang))
    x0, y0, x1, y1 = Panel("", prims).bounds()
    for hx, label in heads:
        prims.append(Text((hx, y1 + 3.0), label, TEXT_H))
    y = y0 - 6.0
    for note in notes:
        block = text_block((x0, y), note, TEXT_H, x1 - x0, valign=VAlign.TOP)
        prims += block
        y = block[-1].position[1] - 5.0
    title = text_block((x0, y1 + 12.0), message("balance.diagram.star", lang, order=k), 3.5,
                       max(x1 - x0, 60.0), upward=True)
    return Panel(f"star{k}", [*prims, *title])


def course_panel(b: Balance, lang: str, scale: float = 1.0) -> Panel:
    """The free reciprocating force's components over one turn, exact and by the series."""
    n = b.total_exact.shape[0]
    phi = np.degrees(np.arange(n + 1) * 2.0 * math.pi / n)

    def closed(a: np.ndarray) -> np.ndarray:
        return np.append(a, a[0]) * 1e-3

    curves = [Curve(phi, closed(b.total_exact[:, 0]), Role.OUTLINE, "Fx"),
              Curve(phi, closed(b.total_series[:, 0]), Role.DASHED)]
    if np.max(np.abs(b.total_exact[:, 1])) > 1e-9 * max(np.max(np.abs(b.total_exact)), 1e-30):
        curves += [Curve(phi, closed(b.total_exact[:, 1]), Role.THIN, "Fy"),
                   Curve(phi, closed(b.total_series[:, 1]), Role.DASHED)]
    mu = round_scale(360.0 / (144.0 * scale))
    return diagram_panel("balance_course", message("balance.diagram.course", lang), curves,
                         Axis("φ", "°", 360.0 / mu, mu=mu, mu_symbol="μφ"),
                         Axis("F", "kN", 70.0 * scale), lang).panel


def _widths(cells: list[list[str]]) -> list[float]:
    return [max(12.0, 2.0 + 1.6 * max(len(r[j]) for r in cells)) for j in range(len(cells[0]))]


def balance_panels(b: Balance, phases: dict[int, float], banks: dict[int, float],
                   phi: np.ndarray, lang: str, scale: float = 1.0) -> list[Panel]:
    """Every balancing panel."""
    out = [star_panel(b, phases, banks, k, lang, scale) for k in (1, 2)]
    out.append(course_panel(b, lang, scale))
    notes = []
    if b.shafts is not None:
        notes.append(message("balance.label.shafts", lang,
                             mr_with=number(b.shafts.mr_with * 1e3, 3, lang),
                             mr_against=number(b.shafts.mr_against * 1e3, 3, lang)))
    for name, cells, extra in (("balance_orders", orders_cells(b, lang), ()),
                               ("balance_cw", counterweight_cells(b, lang), notes),
                               ("balance_journals", journal_cells(b, phi, lang), ())):
        title = message({"balance_orders": "balance.diagram.orders",
                         "balance_cw": "balance.diagram.counterweights",
                         "balance_journals": "balance.diagram.journals"}[name], lang)
        out.append(table_panel(name, title, cells, STYLE, widths=_widths(cells), notes=extra))
    return out
