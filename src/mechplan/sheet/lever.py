"""Zhukovsky's lever on a sheet: the velocity plan turned by 90° with every load at its image."""

from __future__ import annotations

import math

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.ops import Drawn, spec
from ..construct.ops.force import lever_terms
from ..construct.segments import SegmentKind
from ..construct.terms import pole_label
from ..drafting.labels import LabelPlacer
from ..drafting.primitives import Arrow, Circle, Line, Role, Text
from ..i18n import message, unit
from ..i18n import number as format_number
from ..model.plans import Plan
from .panels import LABEL_H, SAME_POINT_MM, TABLE_H, TITLE_H, Panel, _finite, mu_text


def lever_title(lang: str, phi_deg: float | str) -> str:
    """ "Zhukovsky's lever — φ = 30.0°" with the language's decimal mark (``phi_deg`` a text: a
    linear driver's coordinate)."""
    at = phi_deg if isinstance(phi_deg, str) else f"φ = {format_number(phi_deg, 1, lang)}°"
    return f"{message('sheet.lever.title', lang)} — {at}"


def zhukovsky_lever(
    c: Construction, ev: Evaluation, k: int, mu_v: float, lang: str, title: str,
    mu_f: float | None = None
) -> Panel | None:
    """The velocity plan turned by 90° with every load at the image of its point (the loads at
    ``mu_f``, else at a scale of their own)."""
    lever = next((s for s in c.of_plan(Plan.FORCE) if spec(s.op).draw is Drawn.LEVER), None)
    if lever is None or lever.id not in ev.values:
        return None
    panel = Panel(f"force-{k}-lever", plan=Plan.FORCE)
    prims = panel.primitives

    def turned(v: np.ndarray) -> tuple[float, float]:
        return (-float(v[1]) / mu_v, float(v[0]) / mu_v)

    vertices: dict[str, tuple[float, float]] = {}
    for seg in c.segments:
        if (
            seg.plan is Plan.VELOCITY
            and (seg.kind in (SegmentKind.ABSOLUTE, SegmentKind.DRIVE)
                 # a linear driver's rate: the rod's sliding velocity laid off from the pole
                 or c.drive.linear and seg.kind is SegmentKind.SLIDING)
            and seg.start in ev.values
            and seg.end in ev.values
        ):
            a, b = turned(ev[seg.start][k]), turned(ev[seg.end][k])
            if _finite(a, b):
                vertices.update({seg.start: a, seg.end: b})
                if math.dist(a, b) > 0.5:
                    prims.append(Line(a, b, Role.THIN))
    forces: list[tuple[tuple[float, float], np.ndarray, str]] = []
    couples: list[str] = []
    for term in lever_terms(lever):
        if term.kind == "F":
            forces.append((turned(ev[term.first][k]), ev[term.second][k], c[term.second].label))
        else:
            label = c[term.first].label      # a couple, or a second cylinder's F_d (W = 2)
            couples.append(
                f"{label} = {format_number(float(ev[term.first][k]), 2, lang)} "
                f"{unit('N' if label.startswith('F_d') else 'N·m', lang)}"
            )
    largest = max((float(np.hypot(*f)) for _, f, _ in forces), default=0.0)
    if largest > 0:
        from ..construct.scale import choose_scale

        mu_f = mu_f or choose_scale(largest, 40.0)
        placer_items: list[tuple[tuple[float, float], str]] = []
        for at, f, label in forces:
            tip = (at[0] + float(f[0]) / mu_f, at[1] + float(f[1]) / mu_f)
            if _finite(at, tip) and math.dist(at, tip) > 0.5:
                prims.append(Arrow(at, tip, Role.OUTLINE, head_length_mm=3.0, head_width_mm=1.0))
                placer_items.append((tip, label))
        prims.append(Circle((0.0, 0.0), 0.8, Role.OUTLINE))
        spots = _vertex_labels(c, vertices, lang)
        placer = LabelPlacer([p for p in prims if isinstance(p, (Line, Arrow))], LABEL_H,
                             [xy for xy, _ in spots])
        for xy, label in spots:
            if xy != (0.0, 0.0):
                prims.append(Circle(xy, 0.5, Role.OUTLINE))
            prims.append(placer.place(xy, label))
        for at, label in placer_items:
            prims.append(placer.place(at, label))
        prims.extend(placer.leaders)
        x0, y0, _x1, y1 = panel.bounds()
        prims.append(Text((x0, y1 + 9.0), title, TITLE_H))
        prims.append(
            Text(
                (x0, y1 + 3.0),
                f"{mu_text(Plan.VELOCITY, mu_v, lang)};  {mu_text(Plan.FORCE, mu_f, lang)}",
                LABEL_H,
            )
        )
        y = y0 - 6.0
        for line in couples + [
            (f"{lever.label} = {format_number(float(ev[lever.id][k]), 2, lang)} "
            f"{unit('N' if lever.label == 'F_d' else 'N·m', lang)}")   # a linear driver: F_d
        ]:
            prims.append(Text((x0, y), line, TABLE_H))
            y -= 4.5
    return panel if prims else None


def _vertex_labels(c: Construction, vertices: dict[str, tuple[float, float]],
                   lang: str) -> list[tuple[tuple[float, float], str]]:
    """The lever's vertices (the turned velocity images, the pole p first), points closer than
    SAME_POINT_MM written once as "c≡d"."""
    seen: list[tuple[tuple[float, float], list[str]]] = [((0.0, 0.0), [])]
    for sid, xy in vertices.items():
        here = next((names for at, names in seen if math.dist(at, xy) < SAME_POINT_MM), None)
        if here is None:
            seen.append((xy, here := []))
        here.append(pole_label(c[sid].label, lang))
    return [(xy, "≡".join(dict.fromkeys(names or ["p"]))) for xy, names in seen]
