"""The textbook answers on the sheet: a table per position and a table over the crank's turn.

Only what the solution carries (``extras["textbook"]``, computed when the scene asks); the
numbers are the same as in the report and the JSON (:mod:`mechplan.textbook_report`).
"""

from __future__ import annotations

import math

import numpy as np

from ..construct.textbook import TextbookAnswers
from ..i18n import message, unit
from ..i18n import number as format_number
from ..model.mechanism import GROUND
from ..solve import Solution
from .fit import TableStyle, table_panel
from .panels import Panel

STYLE = TableStyle(text_h=2.5, row_h=5.0, head_h=6.0)


def _w(key: str, lang: str, **kw: object) -> str:
    return message(f"textbook.{key}", lang, **kw)


def _phi(phi_rad: float) -> float:
    d = math.degrees(phi_rad) % 360.0
    return 0.0 if d > 360.0 - 1e-9 else d


def position_table(sol: Solution, t: TextbookAnswers, lang: str) -> Panel | None:
    """φ, then v_rel (and a^k on a moving guide) of each prismatic pair, γ of each group and
    v_rub of each pin with a radius, one row per position."""
    ms, ms2 = unit("m/s", lang), unit("m/s²", lang)
    cols: list[tuple[str, np.ndarray, int]] = []
    for s in t.sliding:
        cols.append((f"v_rel {s.pair.point}, {ms}", s.v_slide, 4))
        if s.a_cor is not None and s.guide_link != GROUND:
            cols.append((f"a^k {s.pair.point}, {ms2}", np.hypot(*s.a_cor.T), 4))
    for tr in t.transmission:
        cols.append((f"γ {tr.group.name}, °", np.degrees(tr.gamma), 2))
    for r in t.rubbing:
        cols.append((f"v_rub {r.pair.point}, {ms}", r.v_rub, 4))
    for lv in t.least_velocity:
        cols.append((f"v_min {lv.link}, {ms}", lv.v_min, 4))
    if not cols:
        return None
    head = ["φ, °", *(c[0] for c in cols)]
    rows = [[format_number(_phi(float(sol.phi[k])), 1, lang),
             *(format_number(float(v[k]), d, lang) if math.isfinite(float(v[k])) else "—"
               for _, v, d in cols)] for k in range(sol.positions)]
    return table_panel("textbook-positions", _w("heading", lang), [head, *rows], STYLE)


def cycle_table(t: TextbookAnswers, lang: str) -> Panel | None:
    """Stroke or swing, the extremes, the working and return crank angles, K; γ_min."""
    mm_ = unit("mm", lang)
    rows: list[list[str]] = []
    for s in t.strokes:
        if not s.extremes:
            continue
        size = (f"ψ = {format_number(math.degrees(s.size), 2, lang)}°" if s.rocker
                else f"H = {format_number(s.size * 1000, 2, lang)} {mm_}")
        ex = ", ".join(f"{e.which} {format_number(_phi(e.phi), 2, lang)}°" for e in s.extremes)
        k_text = (f"θ_w = {format_number(math.degrees(s.theta_work or 0.0), 2, lang)}°, "
                  f"θ_r = {format_number(math.degrees(s.theta_return or 0.0), 2, lang)}°, "
                  f"K = {format_number(s.K, 4, lang)}") if s.K is not None else "—"
        # a bare "B" in a cell would be read back as a label of a plan
        rows.append([_w("row.link" if s.rocker else "row.point", lang, subject=s.subject), size,
                     ex, k_text])
    for name, least in t.least_gamma.items():
        if least is None:
            continue
        # not "φ = …": a checker reads that text as the crank angle of the sheet's plans
        where = "—" if math.isnan(least[0]) else f"{format_number(_phi(least[0]), 2, lang)}°"
        gamma = format_number(math.degrees(least[1]), 2, lang)
        rows.append([_w("row.group", lang, subject=name), f"γ_min = {gamma}°", where, ""])
    if not rows:
        return None
    head = ["", _w("col.size", lang), _w("col.extremes", lang), _w("col.ratio", lang)]
    return table_panel("textbook-cycle", _w("cycle", lang), [head, *rows], STYLE)


def textbook_panels(sol: Solution, lang: str) -> list[Panel]:
    """The textbook answers' tables, when the solution carries them."""
    t: TextbookAnswers | None = sol.extras.get("textbook")
    if t is None:
        return []
    return [p for p in (position_table(sol, t, lang), cycle_table(t, lang)) if p is not None]
