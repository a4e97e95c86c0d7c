"""The layout part of an engine study: articulated cylinders, the double-acting cylinder, the
radial engine's orders against its idealised form (report lines and JSON)."""

from __future__ import annotations

import math
from typing import Any

from ..dynamics.engine.balance import Balance
from ..dynamics.engine.layouts import deviations
from ..dynamics.engine.model import EngineModel
from ..i18n import message, number
from ..model.engine import Layout


def layout_lines(m: EngineModel, lang: str) -> list[str]:
    """What the report says of the layout beyond the engine's own line."""
    spec = m.spec
    out = []
    if spec.layout is Layout.RADIAL:
        out.append(message("layouts.report.radial", lang, n=len(spec.cylinders)))
    elif spec.layout is Layout.ARTICULATED and len(spec.cylinders) > 2:
        out.append(message("layouts.report.articulated_every", lang,
                           throws=len(spec.cylinders) // 2))
    if spec.rod_side is not None:
        out.append(message("layouts.report.double_acting", lang,
                           d=number(spec.rod_side.rod_diameter * 1e3, 1, lang),
                           F=number(spec.F_rod_side * 1e4, 3, lang),
                           W=number(m.rod_diagram.work() if m.rod_diagram else 0.0, 2, lang)))
        out.append(message("layouts.report.rod_side_same" if spec.rod_side.indicator is None
                           else "layouts.report.rod_side_own", lang))
    if not m.diagram.V_c_given:
        out.append(message("layouts.report.no_epsilon", lang))
    return out


def articulated_lines(m: EngineModel, lang: str) -> list[str]:
    """One line per articulated cylinder: its exact stroke and dead centres."""
    out = []
    for n, art in m.articulated.items():
        assert m.group is not None
        sl = m.group.slaves[art.slot]
        out.append(message("layouts.report.articulated", lang, number=n, master=art.master,
                           stroke=number(sl.stroke * 1e3, 3, lang),
                           tdc=number(math.degrees((sl.phi_tdc + art.offset) % (2 * math.pi)), 3,
                                      lang),
                           bdc=number(math.degrees((sl.phi_bdc + art.offset) % (2 * math.pi)), 3,
                                      lang),
                           share=number(art.share_C, 4, lang)))
    return out


def deviation_lines(m: EngineModel, b: Balance, lang: str) -> list[str]:
    """The orders with and against the crank, exact against the idealised engine (equal rods)."""
    if not m.articulated:
        return []
    out = ["", message("layouts.report.deviation_title", lang)]
    for d in deviations(m, b):
        out.append(message("layouts.report.deviation", lang, k=d.k,
                           f=number(d.forward, 2, lang), b=number(d.backward, 2, lang),
                           fi=number(d.forward_ideal, 2, lang),
                           bi=number(d.backward_ideal, 2, lang)))
    return out


def layout_json(m: EngineModel) -> dict[str, Any]:
    """JSON keys of the layout: ``articulated`` (per cylinder) and ``rod_side``."""
    doc: dict[str, Any] = {}
    if m.articulated:
        assert m.group is not None
        doc["articulated"] = {
            str(n): {"master": a.master, "pin": a.pin,
                     "stroke": m.group.slaves[a.slot].stroke,
                     "tdc_deg": math.degrees((m.group.slaves[a.slot].phi_tdc + a.offset)
                                             % (2 * math.pi)),
                     "bdc_deg": math.degrees((m.group.slaves[a.slot].phi_bdc + a.offset)
                                             % (2 * math.pi)),
                     "share_C": a.share_C}
            for n, a in m.articulated.items()}
    rs = m.spec.rod_side
    if rs is not None:
        doc["rod_side"] = {"rod_diameter": rs.rod_diameter, "F": m.spec.F_rod_side,
                           "work": m.rod_diagram.work() if m.rod_diagram else None,
                           "same_as_head": rs.indicator is None}
    return doc


def deviation_json(m: EngineModel, b: Balance) -> list[dict[str, float]]:
    """The orders' parts with/against the crank, exact and idealised (JSON)."""
    return [{"order": d.k, "forward": d.forward, "backward": d.backward,
             "forward_ideal": d.forward_ideal, "backward_ideal": d.backward_ideal}
            for d in deviations(m, b)]
