"""The live page's animation of an engine (``draw --format html`` of ``kind = "engine"``): the
polar diagram of the load on crank pin 1 traced as φ runs, T, Z and ΣM over the cycle with a
cursor, and their values at each angle. The curves are the engine sheet's (same data, same axes);
nothing here computes dynamics.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..drafting.primitives import Role
from ..i18n import LANGUAGES, message, unit
from .diagram import Axis, Curve, Marker, diagram_panel
from .engine import EngineData, H, _phi_axis
from .live import Doc, cursor_panel, each

#: angles of the animation over the cycle (one a degree of a two-stroke cycle)
ENGINE_FRAMES = 360


def _polar(study: EngineData, idx: np.ndarray) -> Doc:
    """The polar diagram (the sheet's axes, one scale on both) with the pin load's end traced."""
    q = study.dense.pins[1]
    T, Z = q.T * 1e-3, q.Z * 1e-3
    pole = -q.K_r * 1e-3

    def title(lang: str) -> str:
        return message("engine.diagram.polar", lang)

    def drawn(lang: str, mu: float | None = None) -> Any:
        return diagram_panel("polar", title(lang), [Curve(T, Z, Role.OUTLINE, closed=True)],
                             Axis("T", "kN", 150.0 if mu is None else 110.0, mu=mu),
                             Axis("Z", "kN", 150.0 if mu is None else 110.0, mu=mu), lang,
                             markers=[Marker(0.0, pole, "Oₚ")])

    first = drawn(LANGUAGES[0])
    mu = max(first.mu_x, first.mu_y) if abs(first.mu_x - first.mu_y) > 1e-12 * first.mu_x \
        else None
    dias = {lang: drawn(lang, mu) for lang in LANGUAGES}
    d = dias[LANGUAGES[0]]
    xy = np.column_stack([d.origin[0] + T[idx] / d.mu_x, d.origin[1] + Z[idx] / d.mu_y])
    return {"id": "engine-polar", "plan": "diagram", "title": each(title),
            "mu": each(lambda _lang: ""),
            "points": {"Q": {"label": each(lambda _lang: "Q"), "xy": xy, "trace": False,
                             "grow": True}},
            "items": [], "static": {lang: list(dd.panel.primitives) for lang, dd in dias.items()}}


def engine_animation(study: EngineData, frames: int = ENGINE_FRAMES) -> Doc:
    """The engine's animation over its cycle at ``frames`` angles of the dense grid."""
    d = study.dense
    idx = np.unique(np.linspace(0, d.phi.size - 1, frames + 1).round().astype(int))[:-1]
    phi = d.phi[idx]
    x = np.degrees(phi)
    q = d.pins[1]
    from .live_more import crank_train

    panels = [_polar(study, idx), crank_train(study, phi)]     # cylinder 1 moving with the cursor
    axis = _phi_axis(study, 1.0)
    for key, curves, y_axis, label, y in (
            ("tz", [Curve(np.degrees(d.phi), q.T * 1e-3, Role.OUTLINE, "T"),
                    Curve(np.degrees(d.phi), q.Z * 1e-3, Role.DASHED, "Z")],
             Axis("T, Z", "kN", H), "T", q.T[idx] * 1e-3),
            ("torque", [Curve(np.degrees(d.phi), d.M_total, Role.OUTLINE, "ΣM")],
             Axis("M", "N·m", H), "ΣM", d.M_total[idx])):
        def title(lang: str, key: str = key) -> str:
            return message(f"engine.diagram.{key}", lang)

        dias = {lang: diagram_panel(key, title(lang), curves, axis, y_axis, lang)
                for lang in LANGUAGES}
        panels.append(cursor_panel(f"engine-{key}", title, dias, x, y, label))
    values = [{"quantity": sym, "name": each(lambda _lang, s=sym: s),
               "unit": each(lambda lang, u=u: unit(u, lang)), "value": v}
              for sym, u, v in (("T", "kN", q.T[idx] * 1e-3), ("Z", "kN", q.Z[idx] * 1e-3),
                                ("Q", "kN", q.Q[idx] * 1e-3), ("ΣM", "N·m", d.M_total[idx]))]
    return {"frames": int(idx.size), "phi_deg": x, "panels": panels, "values": values,
            "marks": []}


__all__ = ["ENGINE_FRAMES", "engine_animation"]
