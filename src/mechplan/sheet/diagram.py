"""Diagram panels: curves y(x) on axes with round scale factors, ticks and the μ annotations.

Every capability that plots a quantity against an angle or another quantity (kinematic diagrams,
M_red(φ), works, ΔT–J, s(φ), T(φ), the gear velocity plan) draws it through :func:`diagram_panel`,
so all diagrams of a sheet set look alike: thin axes with arrowheads, ticks at round values, curves
in the outline line, the scale factor of each axis written under the diagram.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import Arrow, HAlign, Line, Polyline, Primitive, Role, Text, VAlign
from ..i18n import scale_factor, tick, unit
from .fit import drawing_right, text_block
from .panels import Panel

TEXT_H = 2.5        # mm, axis names and annotations
TITLE_H = 3.5       # mm, diagram title
TICK = 1.5          # mm
SMALL_H = 1.8       # mm, tick labels (ISO 3098)


@dataclass(frozen=True)
class Axis:
    """One axis: its symbol and SI unit ("N·m", written in the sheet's language by
    :func:`mechplan.i18n.unit`), and its scale factor (units per mm).

    ``mu`` None: a round scale factor is chosen so the data fill ``length_mm``.
    """

    symbol: str
    unit: str
    length_mm: float
    mu: float | None = None
    mu_symbol: str = ""            # e.g. "μφ"; default "μ" + symbol

    def title(self, language: str) -> str:
        """"M, Н·м": the axis' symbol and unit as the sheet writes them."""
        return f"{self.symbol}, {unit(self.unit, language)}" if self.unit else self.symbol


@dataclass(frozen=True)
class Curve:
    """A curve to draw: x and y in physical units (NaN breaks the line)."""

    x: np.ndarray
    y: np.ndarray
    role: Role = Role.OUTLINE
    label: str | None = None       # written near the curve's end
    closed: bool = False
    tag: str | None = None         # the replay step that draws it (``Panel.steps``)


@dataclass(frozen=True)
class Marker:
    """A labelled point on a diagram (a numbered position, an extreme value)."""

    x: float
    y: float
    label: str


@dataclass
class Diagram:
    """A diagram laid out: the panel and the scale factors used (units per mm)."""

    panel: Panel
    mu_x: float
    mu_y: float
    origin: tuple[float, float] = (0.0, 0.0)
    extras: dict[str, float] = field(default_factory=dict)

    def to_mm(self, x: float, y: float) -> tuple[float, float]:
        """Paper coordinates (panel mm) of a physical point."""
        return (self.origin[0] + x / self.mu_x, self.origin[1] + y / self.mu_y)


def scale_for(values: Sequence[float] | np.ndarray, length_mm: float,
              include_zero: bool = True) -> float:
    """Round scale factor so the range of ``values`` (with 0 if asked) fits ``length_mm``."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return 1.0
    lo, hi = float(v.min()), float(v.max())
    if include_zero:
        lo, hi = min(lo, 0.0), max(hi, 0.0)
    span = hi - lo
    if span > 0:
        return round_scale(span / length_mm)
    return round_scale(max(abs(hi), 1e-300) / length_mm)


def _tick_step(mu: float, min_gap_mm: float = 12.0) -> float:
    """A round physical step whose ticks are at least ``min_gap_mm`` apart."""
    return round_scale(mu * min_gap_mm)


def mu_number(mu: float, language: str) -> str:
    """A scale factor with every significant digit ("0,00025", "2,5", "20", "2500")."""
    return scale_factor(mu, language)


def mu_text(symbol: str, mu: float, si_unit: str, language: str) -> str:
    """"μM = 2,5 N·m/mm", "μv = 0,2 (m/s)/mm", "μs = 0,25 мм/мм" in the language's decimal mark
    and unit symbols (:func:`mechplan.i18n.unit`): a compound unit in parentheses."""
    num = mu_number(mu, language)
    if "/" in si_unit:
        si_unit = f"({si_unit})"
    return f"{symbol} = {num} {unit(f'{si_unit or 1}/mm', language)}"


def _polylines(xs: np.ndarray, ys: np.ndarray, role: Role, closed: bool) -> list[Primitive]:
    """Polylines through the finite runs of (xs, ys) in mm."""
    out: list[Primitive] = []
    ok = np.isfinite(xs) & np.isfinite(ys)
    run: list[tuple[float, float]] = []
    for x, y, good in zip(xs, ys, ok):
        if good:
            run.append((float(x), float(y)))
        elif len(run) > 1:
            out.append(Polyline(tuple(run), role))
            run = []
        else:
            run = []
    if len(run) > 1:
        out.append(Polyline(tuple(run), role, closed=closed and bool(ok.all())))
    return out


def diagram_panel(name: str, title: str, curves: Sequence[Curve], x_axis: Axis, y_axis: Axis,
                  language: str, *, markers: Sequence[Marker] = (),
                  hlines: Sequence[tuple[float, str]] = (),
                  x_zero: bool = True, y_zero: bool = True) -> Diagram:
    """Draw curves on a pair of axes; return the panel and the scale factors.

    The x axis is drawn at y = 0 (or at the lowest value if 0 is outside and ``y_zero`` is False),
    the y axis at x = 0 likewise. ``hlines`` are horizontal reference lines (value, label), e.g. a
    mean value, drawn dashed.
    """
    xs_all = np.concatenate([np.asarray(c.x, float).ravel() for c in curves] or [np.zeros(1)])
    ys_all = np.concatenate([np.asarray(c.y, float).ravel() for c in curves] or [np.zeros(1)])
    ys_all = np.concatenate([ys_all, np.asarray([v for v, _ in hlines], float)])
    mu_x = x_axis.mu or scale_for(xs_all, x_axis.length_mm, x_zero)
    mu_y = y_axis.mu or scale_for(ys_all, y_axis.length_mm, y_zero)
    fx, fy = xs_all[np.isfinite(xs_all)], ys_all[np.isfinite(ys_all)]
    x_lo = min(float(fx.min()), 0.0) if x_zero else float(fx.min())
    x_hi = max(float(fx.max()), 0.0) if x_zero else float(fx.max())
    y_lo = min(float(fy.min()), 0.0) if y_zero else float(fy.min())
    y_hi = max(float(fy.max()), 0.0) if y_zero else float(fy.max())
    # axes cross at (0, 0) when it is in range, else at the low corner
    ax_x = 0.0 if x_lo <= 0.0 <= x_hi else x_lo
    ax_y = 0.0 if y_lo <= 0.0 <= y_hi else y_lo
    prims: list[Primitive] = []
    X0, X1 = x_lo / mu_x, x_hi / mu_x
    Y0, Y1 = y_lo / mu_y, y_hi / mu_y
    ox, oy = ax_x / mu_x, ax_y / mu_y
    prims.append(Arrow((X0 - 2.0, oy), (X1 + 8.0, oy), Role.THIN, 3.0, 1.0))
    prims.append(Arrow((ox, Y0 - 2.0), (ox, Y1 + 8.0), Role.THIN, 3.0, 1.0))
    prims.append(Text((X1 + 9.0, oy - 1.0), x_axis.title(language), TEXT_H, valign=VAlign.TOP))
    prims.append(Text((ox + 1.5, Y1 + 9.0), y_axis.title(language), TEXT_H, valign=VAlign.TOP))
    for lo, hi, mu, horizontal in ((x_lo, x_hi, mu_x, True), (y_lo, y_hi, mu_y, False)):
        step = _tick_step(mu)
        first = math.ceil(lo / step - 1e-9)
        last = math.floor(hi / step + 1e-9)
        for i in range(first, last + 1):
            v = i * step
            if abs(v) < step * 1e-9:
                continue
            t = v / mu
            label = tick(v, step, language)
            if horizontal:
                prims.append(Line((t, oy - TICK / 2), (t, oy + TICK / 2), Role.THIN))
                prims.append(Text((t, oy - TICK - 0.5), label, SMALL_H, halign=HAlign.CENTER,
                                  valign=VAlign.TOP))
            else:
                prims.append(Line((ox - TICK / 2, t), (ox + TICK / 2, t), Role.THIN))
                prims.append(Text((ox - TICK - 0.5, t), label, SMALL_H, halign=HAlign.RIGHT,
                                  valign=VAlign.MIDDLE))
    steps: dict[int, str] = {}
    for c in curves:
        first = len(prims)
        xs = np.asarray(c.x, float) / mu_x
        ys = np.asarray(c.y, float) / mu_y
        prims.extend(_polylines(xs, ys, c.role, c.closed))
        if c.label:
            ok = np.flatnonzero(np.isfinite(xs) & np.isfinite(ys))
            if ok.size:
                j = ok[-1]
                prims.append(Text((float(xs[j]) + 1.0, float(ys[j]) + 1.0), c.label, TEXT_H))
        if c.tag is not None:
            steps |= dict.fromkeys(range(first, len(prims)), c.tag)
    for value, label in hlines:
        y = value / mu_y
        prims.append(Line((X0, y), (X1, y), Role.DASHED))
        if label:
            prims.append(Text((X1 + 1.0, y + 0.8), label, TEXT_H))
    for m in markers:
        x, y = m.x / mu_x, m.y / mu_y
        if math.isfinite(x) and math.isfinite(y):
            prims.append(Line((x, oy), (x, y), Role.THIN))
            prims.append(Text((x, y + 1.0), m.label, SMALL_H, halign=HAlign.CENTER,
                              valign=VAlign.BOTTOM))
    mux = x_axis.mu_symbol or f"μ{x_axis.symbol}"
    muy = y_axis.mu_symbol or f"μ{y_axis.symbol}"
    y_note = min(Y0, oy) - 9.0
    width = drawing_right(prims) - X0         # title and scale factors wrap to the drawing
    prims.extend(text_block((X0, y_note), [mu_text(mux, mu_x, x_axis.unit, language),
                                           mu_text(muy, mu_y, y_axis.unit, language)],
                            TEXT_H, width, valign=VAlign.TOP))
    prims.extend(text_block((X0, Y1 + 14.0), title, TITLE_H, width, upward=True))
    return Diagram(Panel(name, list(prims), steps=steps), mu_x, mu_y)
