"""The live page of a machine driven by a cylinder or a slider: its animation runs over the
driver's range (not a crank's turn), its diagrams are drawn over the law's time t, and the page
writes the driver's coordinate ("l4 = 2400.0 mm") where a crank's page writes φ."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..construct.terms import pole_label
from ..i18n import LANGUAGES, message, unit
from ..model.law import driver_time
from ..model.output import Output
from ..solve import Solution
from .diagram import Axis, Curve, diagram_panel

Doc = dict[str, Any]


def linear_frames(sol: Solution, frames: int) -> np.ndarray:
    """The driver's coordinate (m) at each frame: evenly over its range, both ends included
    (over the positions' span when no range is given), in the order the law runs it (a
    retracting cylinder from the range's end)."""
    drive = sol.scene.mechanism.drive
    if drive.q_range is not None:
        lo, hi = drive.q_range
    else:
        lo, hi = float(np.min(sol.phi)), float(np.max(sol.phi))
    q = np.linspace(lo, hi, max(frames, 2))
    t = driver_time(drive, q[[0, -1]])
    return q[::-1].copy() if float(t[-1]) < float(t[0]) else q


def frame_of(q_frames: np.ndarray, q: float) -> int | None:
    """The frame nearest to the coordinate q, or None outside the frames' span."""
    first, last = float(q_frames[0]), float(q_frames[-1])
    span = last - first
    if span == 0.0:
        return 0
    u = (q - first) / span
    if not -1e-9 <= u <= 1.0 + 1e-9:
        return None
    return round(u * (len(q_frames) - 1))


def coordinate_doc(sol: Solution, q_frames: np.ndarray) -> Doc:
    """What the page writes beside its slider: the driver's symbol, the value (mm) and unit."""
    label = sol.construction["pos.q"].label
    return {"symbol": {lang: pole_label(label, lang) for lang in LANGUAGES},
            "unit": {lang: unit("mm", lang) for lang in LANGUAGES},
            "values": np.asarray(q_frames, dtype=float) * 1000.0}


def linear_diagram_specs(sol: Solution, out: Output, series: dict[str, np.ndarray],
                         q_frames: np.ndarray) -> tuple[np.ndarray, Axis, list[Doc]]:
    """The abscissa of the diagrams (the law's time t, s, at each frame: the sheets' abscissa),
    its axis, and for each of s, v, a: key, symbol, unit, title in every language, ordinates."""
    drive = sol.scene.mechanism.drive
    t = np.asarray(driver_time(drive, q_frames), dtype=float)
    rocker = out.point is None
    symbols = ("ψ", "ω", "ε") if rocker else ("s", "v", "a")
    units = ("°", "rad/s", "rad/s²") if rocker else ("m", "m/s", "m/s²")
    kinds = ("displacement", "velocity", "acceleration")
    specs: list[Doc] = []
    for key, sym, si, kind in zip(("s", "v", "a"), symbols, units, kinds, strict=True):
        if key not in series:
            continue
        y = np.asarray(series[key], dtype=float)
        if key == "s":
            y = (y - float(np.nanmin(y))) * (math.degrees(1.0) if rocker else 1.0)
        title = {lang: message(f"drives2.diagram.{kind}", lang, symbol=sym, x="t",
                               link=out.link) for lang in LANGUAGES}
        specs.append({"key": key, "symbol": sym, "unit": si, "title": title, "y": y})
    return t, Axis("t", "s", 120.0), specs


def draw_linear_diagrams(specs: list[Doc], x: np.ndarray, axis: Axis
                         ) -> list[tuple[Doc, dict[str, Any]]]:
    """Each diagram drawn in every language (its spec, language → :class:`Diagram`)."""
    out = []
    for sp in specs:
        drawn = {lang: diagram_panel(f"diagram-{sp['key']}", sp["title"][lang],
                                     [Curve(x, sp["y"])], axis,
                                     Axis(sp["symbol"], sp["unit"], 40.0), lang)
                 for lang in LANGUAGES}
        out.append((sp, drawn))
    return out


__all__ = ["coordinate_doc", "draw_linear_diagrams", "frame_of", "linear_diagram_specs",
           "linear_frames"]
