"""The triad's closure solved for one position: the scalar form of ``ops/triad_solve.py``.

The same algorithm in the same order of operations — the window's cells with the domain's edges
splitting theirs, the general cells (nodes sorted) where the window does not decide, Newton's
iteration and the safeguarded one — so the fused kernel's θ is the numpy path's. Compiled by
numba once per machine like ``kernel_helpers`` (plain Python without numba); every generated
kernel that has a triad calls :func:`_triad_angle`, passing the solver's constants
(:data:`CONSTANTS`, so a compiled copy cached on disk never keeps old ones: numba's cache knows
this file's date, not ``triad_solve``'s) and the cosines and sines of the window's nodes as the
numpy path computes them (:func:`window_trig`).
"""

from __future__ import annotations

import math

import numpy as np

from .kernel_helpers import _div, _jit
from .ops.triad_closure import GRID, ITERATIONS, PURE, RESIDUAL_ULPS, SETTLE, STEP_TOL, WINDOW

NAN = math.nan
INF = math.inf
TWO_PI = 2 * math.pi
EPS = float(np.finfo(float).eps)

#: the solver's counts (grid, window, Newton steps at most and before settling, iterations) and
#: tolerances (step, residual in roundings), passed to :func:`_triad_angle` by every kernel
CONSTANTS = ((GRID, WINDOW, PURE, SETTLE, ITERATIONS), (STEP_TOL, RESIDUAL_ULPS))


def window_trig(ref: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """cos θ and sin θ of the window's nodes about ``ref``, as ``triad_solve._window`` computes
    them (the same values)."""
    th = np.arange(-WINDOW, WINDOW + 1) * (2 * math.pi / GRID) + ref
    return tuple(float(v) for v in np.cos(th)), tuple(float(v) for v in np.sin(th))


@_jit
def _sqrt(x: float) -> float:
    """√x, NaN for x < 0 (as numpy, also in plain Python)."""
    return math.sqrt(x) if x >= 0.0 else NAN


@_jit
def _sign(x: float) -> float:
    """np.sign: −1, 0, 1, NaN for NaN."""
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    return x


@_jit
def _closure(a1x: float, a1y: float, a2x: float, a2y: float, a3x: float, a3y: float,
             theta: float, l1: float, l2: float, l3: float, d2x: float, d2y: float, d3x: float,
             d3y: float, sg: float) -> tuple[float, float, float]:
    """f(θ), f′(θ) and the arcs' sine, as ``triad_solve.closure`` computes them."""
    c, s = math.cos(theta), math.sin(theta)
    u2x, u2y = c * d2x - s * d2y, s * d2x + c * d2y
    dx = a2x - u2x - a1x
    dy = a2y - u2y - a1y
    dd = dx * dx + dy * dy
    along = _div(l1 * l1 - l2 * l2 + dd, 2.0 * dd)
    big, small = (l1 + l2) ** 2 - dd, dd - (l1 - l2) ** 2
    h2 = _div(big * small, 4.0 * dd * dd)
    if h2 < 0.0 and h2 > -1e-12:
        h2 = 0.0
    h = _sqrt(h2) * sg
    bx = a1x + along * dx - h * dy
    by = a1y + along * dy + h * dx
    u3x, u3y = c * d3x - s * d3y, s * d3x + c * d3y
    rx = bx - a3x + u3x
    ry = by - a3y + u3y
    rr = math.sqrt(rx * rx + ry * ry)
    f = rr - l3
    sine = _div(abs(h) * dd, l1 * l2)
    ddp = 2.0 * (dx * u2y - dy * u2x)
    alongp = _div(-(l1 * l1 - l2 * l2) * ddp, 2.0 * dd * dd)
    h2p = _div(ddp * ((big - small) * dd - 2.0 * big * small), 4.0 * dd * dd * dd)
    hp = _div(h2p, 2.0 * h)
    bxp = alongp * dx + along * u2y - hp * dy + h * u2x
    byp = alongp * dy - along * u2x + hp * dx + h * u2y
    fp = _div(rx * (bxp - u3y) + ry * (byp + u3x), rr)
    return f, fp, sine


@_jit
def _value(a1x: float, a1y: float, a2x: float, a2y: float, a3x: float, a3y: float,
           theta: float, l1: float, l2: float, l3: float, d2x: float, d2y: float, d3x: float,
           d3y: float, sg: float) -> float:
    """f(θ) alone, as ``triad_solve._values`` computes it."""
    out: float = _value_cs(a1x, a1y, a2x, a2y, a3x, a3y, math.cos(theta), math.sin(theta), l1, l2,
                           l3, d2x, d2y, d3x, d3y, sg)
    return out


@_jit
def _value_cs(a1x: float, a1y: float, a2x: float, a2y: float, a3x: float, a3y: float,
              c: float, s: float, l1: float, l2: float, l3: float, d2x: float, d2y: float,
              d3x: float, d3y: float, sg: float) -> float:
    """f at the angle of cosine ``c`` and sine ``s``."""
    dx = a2x - (c * d2x - s * d2y) - a1x
    dy = a2y - (s * d2x + c * d2y) - a1y
    dd = dx * dx + dy * dy
    along = _div(l1 * l1 - l2 * l2 + dd, 2.0 * dd)
    h2 = _div(((l1 + l2) ** 2 - dd) * (dd - (l1 - l2) ** 2), 4.0 * dd * dd)
    if h2 < 0.0 and h2 > -1e-12:
        h2 = 0.0
    h = _sqrt(h2) * sg
    rx = a1x + along * dx - h * dy - a3x + (c * d3x - s * d3y)
    ry = a1y + along * dy + h * dx - a3y + (s * d3x + c * d3y)
    return math.sqrt(rx * rx + ry * ry) - l3


@_jit
def _edges(a1x: float, a1y: float, a2x: float, a2y: float, l1: float, l2: float, d2x: float,
           d2y: float, lo: float) -> tuple[float, float, float, float]:
    """The 4 domain edges (NaN: none), put into the turn from ``lo``, as ``triad_solve``."""
    ux, uy = a2x - a1x, a2y - a1y
    p, q = ux * d2x + uy * d2y, uy * d2x - ux * d2y
    rho, alpha = math.hypot(p, q), math.atan2(q, p)
    base = ux * ux + uy * uy + d2x * d2x + d2y * d2y
    x1 = _div(base - (l1 + l2) * (l1 + l2), 2.0 * rho)
    x2 = _div(base - abs(l1 - l2) * abs(l1 - l2), 2.0 * rho)
    t1 = math.acos(x1) if -1.0 <= x1 <= 1.0 else NAN
    t2 = math.acos(x2) if -1.0 <= x2 <= 1.0 else NAN
    return (_turn(alpha + t1, lo), _turn(alpha - t1, lo), _turn(alpha + t2, lo),
            _turn(alpha - t2, lo))


@_jit
def _turn(v: float, lo: float) -> float:
    """v put into the turn from ``lo`` (np.mod's sign), NaN stays NaN."""
    return NAN if math.isnan(v) else (v - lo) % TWO_PI + lo


@_jit
def _cell(e: float, th0: float, thl: float, dt: float, m: int) -> int:
    """The window's cell of a domain edge (−1: not inside), as ``triad_solve._window``."""
    if not e <= thl:
        return -1
    return int(min(max(math.floor((e - th0) / dt), 0), m - 2))


@_jit
def _window(a: tuple[float, ...], p: tuple[float, ...], counts: tuple[int, ...],
            cth: tuple[float, ...], sth: tuple[float, ...]
            ) -> tuple[float, float, float, float, bool]:
    """The window's bracket (lo, hi, f(lo), f(hi), decided) as ``triad_solve._window`` (the
    nodes' cosines and sines given). No arrays: the nodes are visited once, each edge's halves
    offered at its cell; the candidates' order in the numpy path's list (unsplit cells, halves
    left of the edges, halves right of them) breaks ties of distance, so the visit's order does
    not matter."""
    l1, l2, l3, d2x, d2y, d3x, d3y, sg, slope, ref = p[0], p[1], p[2], p[3], p[4], p[5], p[6], \
        p[7], p[8], p[9]
    grid, window = counts[0], counts[1]
    dt = TWO_PI / grid
    m = 2 * window + 1
    th0 = float(-window) * dt + ref
    thl = float(window) * dt + ref
    e = _edges(a[0], a[1], a[2], a[3], l1, l2, d2x, d2y, th0)
    cs = (_cell(e[0], th0, thl, dt, m), _cell(e[1], th0, thl, dt, m),
          _cell(e[2], th0, thl, dt, m), _cell(e[3], th0, thl, dt, m))
    twice = False
    for k in range(4):
        for q in range(k + 1, 4):
            if cs[k] >= 0 and cs[k] == cs[q]:
                twice = True
    fe = (NAN, NAN, NAN, NAN)
    if cs[0] >= 0 or cs[1] >= 0 or cs[2] >= 0 or cs[3] >= 0:
        fe = (_fe(a, p, e[0], cs[0]), _fe(a, p, e[1], cs[1]), _fe(a, p, e[2], cs[2]),
              _fe(a, p, e[3], cs[3]))
    best, key, blo, bhi, bf0, bf1 = INF, 0, NAN, NAN, NAN, NAN
    lo = th0
    f0 = _value_cs(a[0], a[1], a[2], a[3], a[4], a[5], cth[0], sth[0], l1, l2, l3, d2x, d2y,
                   d3x, d3y, sg)
    for j in range(m - 1):
        hi = float(j + 1 - window) * dt + ref
        f1 = _value_cs(a[0], a[1], a[2], a[3], a[4], a[5], cth[j + 1], sth[j + 1], l1, l2, l3,
                       d2x, d2y, d3x, d3y, sg)
        split = cs[0] == j or cs[1] == j or cs[2] == j or cs[3] == j
        if not split and f0 * f1 <= 0 and (f1 - f0) * slope > 0:
            dist = abs(0.5 * (lo + hi) - ref)
            if dist < best or (dist == best and j < key):
                best, key, blo, bhi, bf0, bf1 = dist, j, lo, hi, f0, f1
        if split:
            for k in range(4):
                if cs[k] != j:
                    continue
                # the half left of edge k (after every unsplit cell), then the one right of it
                if f0 * fe[k] <= 0 and (fe[k] - f0) * slope > 0:
                    dist = abs(0.5 * (lo + e[k]) - ref)
                    kk = m + k
                    if dist < best or (dist == best and kk < key):
                        best, key, blo, bhi, bf0, bf1 = dist, kk, lo, e[k], f0, fe[k]
                if fe[k] * f1 <= 0 and (f1 - fe[k]) * slope > 0:
                    dist = abs(0.5 * (e[k] + hi) - ref)
                    kk = m + 4 + k
                    if dist < best or (dist == best and kk < key):
                        best, key, blo, bhi, bf0, bf1 = dist, kk, e[k], hi, fe[k], f1
        lo, f0 = hi, f1
    return blo, bhi, bf0, bf1, best < INF and not twice


@_jit
def _fe(a: tuple[float, ...], p: tuple[float, ...], e: float, cell: int) -> float:
    """f at a domain edge inside the window (NaN where it is not)."""
    if cell < 0:
        return NAN
    out: float = _value(a[0], a[1], a[2], a[3], a[4], a[5], e, p[0], p[1], p[2], p[3], p[4], p[5],
                        p[6], p[7])
    return out


@_jit
def _general(a: tuple[float, ...], p: tuple[float, ...], counts: tuple[int, ...]
             ) -> tuple[float, float, float, float, bool, float]:
    """The general cells (the domain's edges as nodes, sorted): the window, then the whole
    turn; (lo, hi, f(lo), f(hi), found, least |f| over the turn) as ``triad_solve._general``."""
    l1, l2, l3, d2x, d2y, d3x, d3y, sg, slope, ref = p[0], p[1], p[2], p[3], p[4], p[5], p[6], \
        p[7], p[8], p[9]
    grid, window = counts[0], counts[1]
    dt = TWO_PI / grid
    miss = INF
    for half in (window, grid // 2):
        m = 2 * half + 1
        first = float(-half) * dt + ref
        last = float(half) * dt + ref
        e = _edges(a[0], a[1], a[2], a[3], l1, l2, d2x, d2y, first)
        nodes = np.empty(m + 4)
        k = 0
        for j in range(m):
            nodes[k] = float(j - half) * dt + ref
            k += 1
        for j in range(4):
            if e[j] <= last:
                nodes[k] = e[j]
                k += 1
        nodes = np.sort(nodes[:k])
        f = np.empty(k)
        for j in range(k):
            f[j] = _value(a[0], a[1], a[2], a[3], a[4], a[5], nodes[j], l1, l2, l3, d2x, d2y,
                          d3x, d3y, sg)
        best, blo, bhi, bf0, bf1 = INF, NAN, NAN, NAN, NAN
        for j in range(k - 1):
            f0, f1 = f[j], f[j + 1]
            if f0 * f1 <= 0 and (f1 - f0) * slope > 0:
                mid = _value(a[0], a[1], a[2], a[3], a[4], a[5], 0.5 * (nodes[j] + nodes[j + 1]),
                             l1, l2, l3, d2x, d2y, d3x, d3y, sg)
                if math.isnan(mid):
                    continue                   # off the domain between two edges: no root
                dist = abs(0.5 * (nodes[j] + nodes[j + 1]) - ref)
                if dist < best:
                    best, blo, bhi, bf0, bf1 = dist, nodes[j], nodes[j + 1], f0, f1
        if half == grid // 2:
            for j in range(k):
                if abs(f[j]) < miss:       # noqa: PLR1730 - NaN never replaces it
                    miss = abs(f[j])
        if best < INF:
            return blo, bhi, bf0, bf1, True, miss
    return NAN, NAN, NAN, NAN, False, miss


@_jit
def _newton(a: tuple[float, ...], p: tuple[float, ...], lo: float, hi: float, flo: float,
            fhi: float, size: float, counts: tuple[int, ...], tols: tuple[float, float]
            ) -> tuple[float, float, float, float]:
    """θ and f, f′, the arcs' sine at the last point evaluated, as ``triad_solve.newton``."""
    l1, l2, l3, d2x, d2y, d3x, d3y, sg = p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]
    pure, settle, iterations = counts[2], counts[3], counts[4]
    step_tol = tols[0]
    small = tols[1] * EPS * size
    lo0, hi0, flo0, fhi0 = lo, hi, flo, fhi
    x = hi - _div(fhi * (hi - lo), fhi - flo)
    if not (x > lo and x < hi):
        x = 0.5 * (lo + hi)
    prev = step = fx = fp = sx = x
    for it in range(pure):
        fx, fp, sx = _closure(a[0], a[1], a[2], a[3], a[4], a[5], x, l1, l2, l3, d2x, d2y, d3x,
                              d3y, sg)
        prev, step = step, _div(fx, fp)
        x = x - step
        if it + 1 < settle:
            continue
        tol = step_tol * (1.0 + abs(x))
        s = abs(step)
        done = (s * s * s <= tol * prev * prev and s <= 1e-6) or (s <= tol and abs(fx) <= small)
        if done and x >= lo and x <= hi:
            return x, fx, fp, sx
    # the safeguarded iteration, from the secant point again
    lo, hi, flo, fhi = lo0, hi0, flo0, fhi0
    x = hi - _div(fhi * (hi - lo), fhi - flo)
    if not (x > lo and x < hi):
        x = 0.5 * (lo + hi)
    fx, fp, sx, xo = NAN, NAN, NAN, x
    for _ in range(iterations):
        xo = x
        fx, fp, sx = _closure(a[0], a[1], a[2], a[3], a[4], a[5], x, l1, l2, l3, d2x, d2y, d3x,
                              d3y, sg)
        if _sign(fx) == _sign(fhi):
            hi, fhi = x, fx
        else:
            lo, flo = x, fx
        step = _div(fx, fp)
        xn = x - step
        inside = math.isfinite(fp) and xn >= lo and xn <= hi
        done = fx == 0.0 or (inside and abs(step) <= step_tol * (1.0 + abs(x))
                             and abs(fx) <= small)
        if not math.isfinite(fx):
            return NAN, fx, fp, sx
        if fx == 0.0:
            return x, fx, fp, sx
        if done:
            return xn, fx, fp, sx
        x = xn if (inside and xn != x) else 0.5 * (lo + hi)
    return xo, fx, fp, sx


@_jit
def _triad_angle(a1x: float, a1y: float, a2x: float, a2y: float, a3x: float, a3y: float,
                 l1: float, l2: float, l3: float, d2x: float, d2y: float, d3x: float, d3y: float,
                 sigma: float, slope: float, ref: float, size: float, counts: tuple[int, ...],
                 tols: tuple[float, float], cth: tuple[float, ...], sth: tuple[float, ...]
                 ) -> tuple[float, float, float]:
    """θ of the base link, the gap and the sine at one position, as ``triad_solve.solve``
    (``counts``, ``tols``: :data:`CONSTANTS`; ``cth``, ``sth``: :func:`window_trig`)."""
    a = (a1x, a1y, a2x, a2y, a3x, a3y)
    p = (l1, l2, l3, d2x, d2y, d3x, d3y, sigma, slope, ref)
    lo, hi, flo, fhi, found = _window(a, p, counts, cth, sth)
    miss = INF
    if not found:
        lo, hi, flo, fhi, found, miss = _general(a, p, counts)
    if not found:
        return NAN, (miss if miss < INF else size), 0.0
    theta, fb, fp, cc = _newton(a, p, lo, hi, flo, fhi, size, counts, tols)
    if not math.isfinite(theta):
        return NAN, (miss if miss < INF else size), 0.0
    sine = abs(fp) * cc / size
    sine = 0.0 if math.isnan(sine) else min(1.0, sine)
    return theta, -abs(fb), sine
