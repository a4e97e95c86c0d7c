"""Normalised motion laws y(x), y′(x), y″(x) on x ∈ [0, 1]
with y(0) = 0, y(1) = 1, y′(0) = y′(1) = 0.

Every law except 3-4-5 and the tables is a chain of acceleration segments a = a0 + b·sin(w·t + p),
integrated in closed form and scaled so y(1) = 1; the uniform law's softened ends are such
constant-acceleration blends (a fraction ``blend`` of the phase at each end), so its velocity is
continuous and its acceleration finite.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.cam import Law

PI = math.pi


@dataclass(frozen=True)
class _Seg:
    x0: float
    x1: float
    a0: float
    b: float = 0.0
    w: float = 1.0
    p: float = 0.0


def _segments(law: Law, blend: float) -> list[_Seg]:
    if law is Law.CYCLOIDAL:
        return [_Seg(0.0, 1.0, 0.0, 1.0, 2 * PI)]
    if law is Law.COSINE:
        return [_Seg(0.0, 1.0, 0.0, 1.0, PI, PI / 2)]
    if law is Law.PARABOLIC:
        return [_Seg(0.0, 0.5, 1.0), _Seg(0.5, 1.0, -1.0)]
    if law is Law.UNIFORM:
        k = blend
        return [_Seg(0.0, k, 1.0), _Seg(k, 1.0 - k, 0.0), _Seg(1.0 - k, 1.0, -1.0)]
    if law is Law.MODIFIED_TRAPEZOID:
        w = 4 * PI
        return [_Seg(0.0, 0.125, 0.0, 1.0, w), _Seg(0.125, 0.375, 1.0),
                _Seg(0.375, 0.625, 0.0, 1.0, w, PI / 2), _Seg(0.625, 0.875, -1.0),
                _Seg(0.875, 1.0, 0.0, 1.0, w, -PI / 2)]
    raise ValueError(f"law {law} is not a segment law")


def _integrate(segs: list[_Seg], x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """y, v, a of a chain of segments at x (unscaled: starts at rest at 0)."""
    y = np.zeros_like(x)
    v = np.zeros_like(x)
    a = np.zeros_like(x)
    y0 = v0 = 0.0
    for i, s in enumerate(segs):
        last = i == len(segs) - 1
        m = (x >= s.x0) & ((x <= s.x1) if last else (x < s.x1))
        t = x[m] - s.x0
        a[m], v[m], y[m] = _seg_eval(s, t, v0, y0)
        T = np.array([s.x1 - s.x0])
        _, vt, yt = _seg_eval(s, T, v0, y0)
        v0, y0 = float(vt[0]), float(yt[0])
    return y, v, a


def _seg_eval(s: _Seg, t: np.ndarray, v0: float, y0: float):
    sp, cp = math.sin(s.p), math.cos(s.p)
    arg = s.w * t + s.p
    a = s.a0 + s.b * np.sin(arg)
    v = v0 + s.a0 * t + (s.b / s.w) * (cp - np.cos(arg))
    y = y0 + v0 * t + 0.5 * s.a0 * t * t + (s.b / s.w) * (t * cp - (np.sin(arg) - sp) / s.w)
    return a, v, y


def _table_a(values: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Piecewise-linear acceleration through equally spaced values, integrated exactly."""
    n = values.size - 1
    h = 1.0 / n
    slope = np.diff(values) / h
    v_nodes = np.concatenate([[0.0], np.cumsum(values[:-1] * h + slope * h * h / 2)])
    y_nodes = np.zeros(n + 1)
    for i in range(n):
        y_nodes[i + 1] = (y_nodes[i] + v_nodes[i] * h + values[i] * h * h / 2
                          + slope[i] * h ** 3 / 6)
    i = np.clip((x / h).astype(int), 0, n - 1)
    t = x - i * h
    a = values[i] + slope[i] * t
    v = v_nodes[i] + values[i] * t + slope[i] * t * t / 2
    y = y_nodes[i] + v_nodes[i] * t + values[i] * t * t / 2 + slope[i] * t ** 3 / 6
    return y, v, a


def _clamped_spline(values: np.ndarray) -> np.ndarray:
    """Second derivatives M at equally spaced knots of the cubic spline with zero end slopes."""
    n = values.size - 1
    h = 1.0 / n
    A = np.zeros((n + 1, n + 1))
    r = np.zeros(n + 1)
    A[0, 0], A[0, 1] = h / 3, h / 6
    r[0] = (values[1] - values[0]) / h
    A[n, n - 1], A[n, n] = h / 6, h / 3
    r[n] = -(values[n] - values[n - 1]) / h
    for i in range(1, n):
        A[i, i - 1], A[i, i], A[i, i + 1] = h / 6, 2 * h / 3, h / 6
        r[i] = (values[i + 1] - 2 * values[i] + values[i - 1]) / h
    return np.linalg.solve(A, r)


def _table_s(values: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    n = values.size - 1
    h = 1.0 / n
    M = _clamped_spline(values)
    i = np.clip((x / h).astype(int), 0, n - 1)
    t0 = x - i * h              # distance from the left knot
    t1 = h - t0                 # distance to the right knot
    yl, yr, Ml, Mr = values[i], values[i + 1], M[i], M[i + 1]
    y = ((Ml * t1 ** 3 + Mr * t0 ** 3) / (6 * h) + (yl / h - Ml * h / 6) * t1
         + (yr / h - Mr * h / 6) * t0)
    v = (-Ml * t1 ** 2 + Mr * t0 ** 2) / (2 * h) - (yl / h - Ml * h / 6) + (yr / h - Mr * h / 6)
    a = (Ml * t1 + Mr * t0) / h
    return y, v, a


def normalised(law: Law, x: np.ndarray, *, blend: float = 0.1, table: tuple[float, ...] = (),
               key: str = "") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Return y, dy/dx, d²y/dx² of a law at x ∈ [0, 1] (rising from 0 to 1).

    A table of s is given in normalised form (0 … 1); a table of a is a shape, scaled here so the
    phase ends at y = 1 — it must also end at rest, or a :class:`SceneError` names ``key``.
    """
    x = np.asarray(x, dtype=float)
    if law is Law.POLY345:
        return (10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5, 30 * x ** 2 - 60 * x ** 3 + 30 * x ** 4,
                60 * x - 180 * x ** 2 + 120 * x ** 3)
    if law is Law.TABLE_S:
        return _table_s(np.asarray(table, float), x)
    if law is Law.TABLE_A:
        values = np.asarray(table, float)
        y1, v1, _ = _table_a(values, np.array([1.0]))
        vmax = float(np.abs(_table_a(values, np.linspace(0, 1, 201))[1]).max())
        if not y1[0] > 0:
            raise SceneError(
                Text("errmsg.synthesis_cam_laws.acceleration_table_move", {"y1": f"{y1[0]:.4g}"}),
                key=key,
            )
        if abs(v1[0]) > 1e-6 * max(vmax, 1e-300):
            raise SceneError(
                Text(
                    "errmsg.synthesis_cam_laws.acceleration_table_end",
                    {"value": f"{v1[0] / y1[0]:.4g}"},
                ),
                key=key,
            )
        y, v, a = _table_a(values, x)
        c = 1.0 / float(y1[0])
        return y * c, v * c, a * c
    y, v, a = _integrate(_segments(law, blend), x)
    y_end, _, _ = _integrate(_segments(law, blend), np.array([1.0]))
    c = 1.0 / float(y_end[0])
    return y * c, v * c, a * c
