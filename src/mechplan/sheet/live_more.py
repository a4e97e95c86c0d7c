"""More of the live page's animation: an engine's crank train moving with the polar diagram's
cursor, and a cursor on the Wittenbauer diagram of a machine with ``[dynamics]``.

The crank train is the engine model's own slider-crank (its R, L and piston travel x(φ)); the
Wittenbauer diagram is the dynamics sheet's (the same curves at its scale factors). Nothing here
computes dynamics.
"""

from __future__ import annotations

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import Circle, Line, Polyline, Primitive, Role
from ..dynamics.machine import MachineDynamics
from ..i18n import LANGUAGES, message
from ..model.plans import Plan
from .diagram import Axis, Curve, Marker, diagram_panel
from .dynamics import dynamics_scales
from .engine import EngineData
from .live import Doc, cursor_panel, each
from .panels import mu_text

#: paper height of the crank train (crank circle to the piston at TDC), mm
TRAIN_MM = 70.0


def crank_train(study: EngineData, phi: np.ndarray) -> Doc:
    """Cylinder 1's crank, rod and piston at the crank angles ``phi`` (from its TDC; the crank
    turns counter-clockwise on the page, the cylinder's axis upward)."""
    kin = study.model.kin
    R, L = kin.R, kin.L
    mu = round_scale((2 * R + L) / TRAIN_MM)
    a = np.column_stack([-R * np.sin(phi), R * np.cos(phi)]) / mu
    b = np.column_stack([np.zeros_like(phi), R + L - kin.x(phi)]) / mu
    w = 0.45 * float(study.model.spec.bore) / mu         # half the piston's width on paper
    h = 0.6 * w
    frames: list[list[Primitive]] = []
    for (ax, ay), (bx, by) in zip(a.tolist(), b.tolist(), strict=True):
        piston = Polyline(((bx - w, by - h), (bx + w, by - h), (bx + w, by + h), (bx - w, by + h)),
                          Role.OUTLINE, closed=True)
        frames.append([Line((0.0, 0.0), (ax, ay), Role.OUTLINE),
                       Line((ax, ay), (bx, by), Role.OUTLINE), piston])
    top, bottom = (R + L) / mu + 2 * h, (L - R) / mu - 2 * h
    fixed: list[Primitive] = [Circle((0.0, 0.0), R / mu, Role.THIN),
                              Line((0.0, -R / mu - 4.0), (0.0, top + 4.0), Role.CHAIN),
                              Line((-w - 0.8, bottom), (-w - 0.8, top), Role.OUTLINE),
                              Line((w + 0.8, bottom), (w + 0.8, top), Role.OUTLINE)]
    reach = R / mu + 6.0
    return {"id": "engine-train", "plan": "train", "scale": mu,
            "box": [-max(reach, w + 6.0), -top - 6.0, max(reach, w + 6.0), R / mu + 6.0],
            "title": each(lambda lang: message("htmlmore.engine.train", lang)),
            "mu": each(lambda lang: mu_text(Plan.POSITION, mu, lang)),
            "points": {"O": {"label": each(lambda _l: "O"), "xy": np.zeros_like(a),
                             "trace": False},
                       "A": {"label": each(lambda _l: "A"), "xy": a, "trace": False},
                       "B": {"label": each(lambda _l: "B"), "xy": b, "trace": False}},
            "items": [{"kind": "segment", "name": "train", "thick": True, "frames": frames}],
            "fixed": fixed}


def wittenbauer(dyn: MachineDynamics, theta: np.ndarray) -> Doc:
    """The Wittenbauer diagram ΔT(J_red) of the dynamics sheet with a cursor at (J_red, ΔT) of
    the cycle angles ``theta``."""
    sc = dynamics_scales(dyn)
    q = np.unique(np.concatenate([np.arange(0, dyn.theta.size, max(1, dyn.theta.size // 720)),
                                  [dyn.theta.size - 1]]))
    w = dyn.witt
    j_hi = float(dyn.J_red.max()) * 1.1
    curves = [Curve(dyn.J_red[q], dyn.dT[q]),
              Curve(np.array([0.0, j_hi]), np.array([w.b_max, w.b_max + w.k_max * j_hi]),
                    Role.THIN, label="ψ_max"),
              Curve(np.array([0.0, j_hi]), np.array([w.b_min, w.b_min + w.k_min * j_hi]),
                    Role.THIN, label="ψ_min")]

    def title(lang: str) -> str:
        return message("dynamics.diagram.wittenbauer", lang)

    drawn = {lang: diagram_panel("dynamics-wittenbauer", title(lang), curves,
                                 Axis("J", "kg·m²", 60.0, mu=sc.mu_J, mu_symbol="μJ"),
                                 Axis("ΔT", "J", 50.0, mu=sc.mu_T, mu_symbol="μT"), lang,
                                 markers=[Marker(0.0, w.b_max, "k"), Marker(0.0, w.b_min, "l")])
             for lang in LANGUAGES}
    x = np.interp(theta, dyn.theta, dyn.J_red)
    y = np.interp(theta, dyn.theta, dyn.dT)
    return cursor_panel("dynamics-wittenbauer", title, drawn, x, y, "ΔT, J")


def cycle_angles(dyn: MachineDynamics, phi: np.ndarray) -> np.ndarray:
    """The cycle angle θ of the crank angles ``phi`` (the first turn of a two-turn cycle)."""
    return np.mod(phi - dyn.phi0, dyn.spec.cycle)


__all__ = ["crank_train", "cycle_angles", "wittenbauer"]
