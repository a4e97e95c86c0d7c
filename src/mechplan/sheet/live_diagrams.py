"""The kinematic diagrams of the live page, and what runs its animation for a linear driver.

A crank's page draws s(φ), v(φ), a(φ) of the output link over one turn, φ in degrees. A machine
driven by a cylinder or a slider runs its animation over the driver's range (not a crank's
turn), draws its diagrams over the law's time t (the sheets' abscissa: docs/drivers.md) and
writes the driver's coordinate ("l4 = 2400.0 mm") where a crank's page writes φ.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..construct.terms import pole_label
from ..i18n import LANGUAGES, message, unit
from ..model.law import driver_time
from ..model.output import output_link
from ..solve import Solution
from .diagram import Axis, Curve, diagram_panel
from .kinematics_sheet import _series

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


def diagram_anims(sol: Solution, phi: np.ndarray) -> list[Doc]:
    """s, v, a (or ψ, ω, ε) of the output link, as on sheet 1, with a cursor at every frame:
    over φ (degrees of a crank's turn) or over a linear driver's time t (s)."""
    from .live import cursor_panel

    out = output_link(sol.scene.mechanism)
    if out is None:
        return []
    series = _series(sol, out, phi)
    if "s" not in series:
        return []
    drive = sol.scene.mechanism.drive
    if drive.linear:                # the law's time at each frame
        x = np.asarray(driver_time(drive, phi), dtype=float)
        x_axis = Axis("t", "s", 120.0)
    else:
        x = np.arange(phi.shape[0]) * 360.0 / phi.shape[0]
        x_axis = Axis("φ", "°", 120.0)
    rocker = out.point is None
    symbols = ("ψ", "ω", "ε") if rocker else ("s", "v", "a")
    units = ("°", "rad/s", "rad/s²") if rocker else ("m", "m/s", "m/s²")
    kinds = ("displacement", "velocity", "acceleration")
    panels = []
    for key, sym, si, kind in zip(("s", "v", "a"), symbols, units, kinds, strict=True):
        if key not in series:
            continue
        y = np.asarray(series[key], dtype=float)
        if key == "s":
            y = (y - float(np.nanmin(y))) * (math.degrees(1.0) if rocker else 1.0)

        def title(lang: str, sym: str = sym, kind: str = kind) -> str:
            if drive.linear:        # "… over t" as the sheets title them
                return message(f"drives2.diagram.{kind}", lang, symbol=sym, x="t",
                               link=out.link)
            return message(f"layout.diagram.{kind}", lang, symbol=sym, link=out.link)

        drawn = {lang: diagram_panel(f"diagram-{key}", title(lang), [Curve(x, y)], x_axis,
                                     Axis(sym, si, 40.0), lang)
                 for lang in LANGUAGES}
        panels.append(cursor_panel(f"diagram-{key}", title, drawn, x, y, sym))
    return panels


__all__ = ["coordinate_doc", "diagram_anims", "frame_of", "linear_frames"]
