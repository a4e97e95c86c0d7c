"""The closure of a class III group with sliding legs solved for one position: the scalar form of
``ops/triadp_solve.py``.

The same algorithm in the same order of operations — the window's cells, then the whole turn's;
a cell with one end off the loci's domain cut at the domain's edge (in closed form, stepped back
onto the domain by roundings, a bisection where that fails); a cell whose middle leaves the
domain left out; the crossing of the assembly's slope nearest its angle; the Illinois secant;
f′ by a central difference — so the fused kernel's θ, gap and sine are the numpy path's.

A leg's locus is four numbers: a point (x, y, 0, 0) for an arc or a block's pin, a line
(P, u) for a slider leg; ``kinds`` are :data:`ARC`, :data:`LINE`, :data:`BLOCK`. The solver's
counts (:data:`CONSTANTS`) and the cosines and sines of the grid's nodes as numpy computes them
(:func:`grid_trig`) are passed by every kernel, so numba's compiled copy of this file (cached on
disk, keyed by this file alone) never keeps old constants. Compiled once per machine like
``kernel_triad``; plain Python without numba.
"""

from __future__ import annotations

import math

import numpy as np

from .kernel_helpers import _div, _div_nz, _height, _jit
from .kernel_triad import _sign, _turn
from .ops.triadp_solve import EDGE_STEPS, GRID, ITERATIONS, WINDOW, Group

NAN = math.nan
INF = math.inf
TWO_PI = 2 * math.pi

#: the legs' kinds as the kernel passes them (``Group.kinds``: ``R``, ``P``, ``Q``)
ARC, LINE, BLOCK = 0, 1, 2
KIND_CODES = {"R": ARC, "P": LINE, "Q": BLOCK}
#: the solver's counts: the grid's cells over a turn, the window's cells on each side of the
#: assembly's angle, the bisections of a domain edge, the Illinois secant's iterations
CONSTANTS = (GRID, WINDOW, EDGE_STEPS, ITERATIONS)
#: an edge is stepped back onto the domain by at most this many growing steps (×4 each) of
#: EDGE_ULPS·(1 + |edge|); the Illinois secant stops at a bracket of ILLINOIS_ULPS·(1 + |x|);
#: f′ is the central difference over ±SLOPE_STEP rad (``triadp_solve._edges``, ``illinois``,
#: ``triadp_solve.solve``)
EDGE_TRIES = 12
EDGE_ULPS = 4e-16
ILLINOIS_ULPS = 4e-16
SLOPE_STEP = 1e-7


def grid_trig(ref: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """cos θ and sin θ of the grid's nodes ref + k·2π/GRID, k = −GRID/2 … GRID/2, as
    ``triadp_solve.cells`` computes them (the window's nodes are among them, the same values)."""
    half = GRID // 2
    th = ref + np.arange(-half, half + 1) * (2 * math.pi / GRID)
    return tuple(float(v) for v in np.cos(th)), tuple(float(v) for v in np.sin(th))


def group_args(g: Group) -> tuple[float, ...]:
    """The group's numbers as the solver takes them: l1, l2, l3, d2, d3, q, q_angle, σ, slope,
    the assembly's angle, the group's size, and (l1 ± l2)² as ``geom.meet.circle_circle`` squares
    them (numpy's power of a scalar, not a product: they differ in the last bit now and then)."""
    r1, r2 = np.asarray(g.l[0]), np.asarray(g.l[1])
    return (*g.l, *g.d2, *g.d3, *g.q, g.q_angle, float(g.sigma), float(g.slope), g.ref, g.size,
            float((r1 + r2) ** 2), float((r1 - r2) ** 2))


@_jit
def _hypot(x: float, y: float) -> float:
    """np.hypot (numba's math.hypot is the same function; Python's own is not)."""
    return float(np.hypot(x, y))


@_jit
def _acos(x: float) -> float:
    """np.arccos: NaN outside [−1, 1]."""
    return float(np.arccos(x)) if -1.0 <= x <= 1.0 else NAN


@_jit
def _max(a: float, b: float) -> float:
    """np.maximum (NaN wins)."""
    if math.isnan(a) or math.isnan(b):
        return NAN
    return max(a, b)


@_jit
def _min(a: float, b: float) -> float:
    """np.minimum (NaN wins)."""
    if math.isnan(a) or math.isnan(b):
        return NAN
    return min(a, b)


@_jit
def _first(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...], c: float,
           s: float) -> tuple[float, float, float]:
    """B_1 and the loci's meet sine at the base angle of cosine ``c`` and sine ``s``, as
    ``triadp_solve.first_point`` (``geom.meet``'s formulas)."""
    r1, r2, d2x, d2y, sg = p[0], p[1], p[3], p[4], p[10]
    rx, ry = c * d2x - s * d2y, s * d2x + c * d2y
    if kinds[0] == ARC and kinds[1] == ARC:       # meet.circle_circle
        ax, ay = lc[0], lc[1]
        dx, dy = (lc[4] - rx) - ax, (lc[5] - ry) - ay
        d = math.sqrt(dx * dx + dy * dy)
        gap = _max(d - (r1 + r2), abs(r1 - r2) - d)
        dd = d * d
        a = _div(r1 * r1 - r2 * r2 + dd, 2.0 * d)
        h = _height(_div((p[14] - dd) * (dd - p[15]), 4.0 * dd), gap)
        ux, uy = _div(dx, d), _div(dy, d)
        sh = h if sg == 1.0 else sg * h
        return (ax + a * ux - sh * uy, ay + a * uy + sh * ux, abs(_div(h * d, r1 * r2)))
    if kinds[0] == ARC:                           # meet.circle_line
        cx, cy = lc[0], lc[1]
        px, py, ux, uy = lc[4] - rx, lc[5] - ry, lc[6], lc[7]
        w = ux * (cy - py) - uy * (cx - px)
        along = (cx - px) * ux + (cy - py) * uy
        h = _height((r1 - w) * (r1 + w), abs(w) - r1)
        sh = sg * h
        fx, fy = px + along * ux, py + along * uy
        return fx + sh * ux, fy + sh * uy, abs(_div(h, r1))
    ux, uy, vx, vy = lc[2], lc[3], lc[6], lc[7]   # meet.line_line
    cross = ux * vy - uy * vx
    t = _div_nz(((lc[4] - rx) - lc[0]) * vy - ((lc[5] - ry) - lc[1]) * vx, cross)
    return lc[0] + t * ux, lc[1] + t * uy, abs(cross)


@_jit
def _closure_cs(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...],
                theta: float, c: float, s: float) -> tuple[float, float]:
    """f and the loci's meet sine at θ (of cosine ``c``, sine ``s``), as
    ``triadp_solve.closure``."""
    b1x, b1y, sine = _first(lc, kinds, p, c, s)
    d3x, d3y = p[5], p[6]
    bx, by = b1x + (c * d3x - s * d3y), b1y + (s * d3x + c * d3y)
    if kinds[2] == ARC:
        return _hypot(bx - lc[8], by - lc[9]) - p[2], sine
    if kinds[2] == BLOCK:
        qx, qy = p[7], p[8]
        ox, oy = c * qx - s * qy, s * qx + c * qy
        ux, uy = math.cos(theta + p[9]), math.sin(theta + p[9])
        return ux * (lc[9] - b1y - oy) - uy * (lc[8] - b1x - ox), sine
    return lc[10] * (by - lc[9]) - lc[11] * (bx - lc[8]), sine


@_jit
def _closure(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...],
             theta: float) -> float:
    """f at θ."""
    out: float = _closure_cs(lc, kinds, p, theta, math.cos(theta), math.sin(theta))[0]
    return out


@_jit
def _closed_edges(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...]
                  ) -> tuple[float, float, float, float]:
    """The base angles where loci 1 and 2 touch (NaN: none), as ``triadp_solve.closed_edges``."""
    l1, l2, d2x, d2y = p[0], p[1], p[3], p[4]
    if kinds[0] == ARC and kinds[1] == ARC:
        ux, uy = lc[4] - lc[0], lc[5] - lc[1]
        a, b = ux * d2x + uy * d2y, uy * d2x - ux * d2y
        rho, alpha = _hypot(a, b), float(np.arctan2(b, a))
        base = ux * ux + uy * uy + d2x * d2x + d2y * d2y
        e1, e2 = l1 + l2, abs(l1 - l2)
        t1 = _acos(_div(base - e1 * e1, 2.0 * rho))
        t2 = _acos(_div(base - e2 * e2, 2.0 * rho))
        return alpha + t1, alpha - t1, alpha + t2, alpha - t2
    if kinds[0] == ARC:
        px, py, ux, uy = lc[4], lc[5], lc[6], lc[7]
        w = ux * (lc[1] - py) - uy * (lc[0] - px)
        a = ux * d2y - uy * d2x
        b = ux * d2x + uy * d2y
        rho, alpha = _hypot(a, b), float(np.arctan2(b, a))
        t1 = _acos(_div(l1 - w, rho))
        t2 = _acos(_div(-l1 - w, rho))
        return alpha + t1, alpha - t1, alpha + t2, alpha - t2
    return NAN, NAN, NAN, NAN


@_jit
def _edge(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...],
          e: tuple[float, float, float, float], lo: float, hi: float, finite_lo: bool,
          edge_steps: int) -> float:
    """The domain's edge in [lo, hi], as ``triadp_solve._edges`` for one cell."""
    on, off = (lo, hi) if finite_lo else (hi, lo)
    pick, best = NAN, INF
    for k in range(4):      # the closed-form edge in the cell nearest its finite end
        x: float = _turn(e[k], lo)
        if x >= lo and x <= hi and abs(x - on) < best:
            pick, best = x, abs(x - on)
    step = _sign(on - off) * EDGE_ULPS * (1.0 + abs(pick))
    x = pick
    ok = math.isfinite(_closure(lc, kinds, p, x))
    if math.isfinite(pick):
        for _ in range(EDGE_TRIES):
            if ok:
                break
            step = step * 4.0
            x = pick + step
            ok = math.isfinite(_closure(lc, kinds, p, x))
    if ok and math.isfinite(x) and abs(x - on) <= abs(off - on):
        return x
    for _ in range(edge_steps):
        mid = 0.5 * (on + off)
        if math.isfinite(_closure(lc, kinds, p, mid)):
            on = mid
        else:
            off = mid
    return on


@_jit
def _cells(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...], half: int,
           counts: tuple[int, ...], cth: tuple[float, ...], sth: tuple[float, ...]
           ) -> tuple[float, float, float, float, bool, float]:
    """The cell of ``half`` cells each side of the assembly's angle holding the crossing of the
    assembly's slope nearest that angle, as ``triadp_solve.cells`` and ``_pick``: (lo, hi, f(lo),
    f(hi), found, least |f| at the nodes)."""
    grid, edge_steps = counts[0], counts[2]
    slope, ref = p[11], p[12]
    dt = TWO_PI / grid
    centre = grid // 2                 # the tables' index of the assembly's angle
    edges = (NAN, NAN, NAN, NAN)
    have_edges = False
    least, best = INF, INF
    blo, bhi, bflo, bfhi, found = NAN, NAN, NAN, NAN, False
    th0 = ref + float(-half) * dt
    f0 = _closure_cs(lc, kinds, p, th0, cth[centre - half], sth[centre - half])[0]
    if math.isfinite(f0):
        least = abs(f0)
    for j in range(-half, half):
        th1 = ref + float(j + 1) * dt
        f1 = _closure_cs(lc, kinds, p, th1, cth[centre + j + 1], sth[centre + j + 1])[0]
        if math.isfinite(f1) and abs(f1) < least:
            least = abs(f1)
        lo, hi, flo, fhi = th0, th1, f0, f1
        if math.isfinite(flo) != math.isfinite(fhi):
            if not have_edges:
                edges, have_edges = _closed_edges(lc, kinds, p), True
            finite_lo = math.isfinite(flo)
            e = _edge(lc, kinds, p, edges, lo, hi, finite_lo, edge_steps)
            fe = _closure(lc, kinds, p, e)
            if finite_lo:
                hi, fhi = e, fe
            else:
                lo, flo = e, fe
        # a cell whose middle leaves the domain holds no root (asked only of a candidate)
        if flo * fhi <= 0 and (fhi - flo) * slope > 0:
            dist = abs(0.5 * (lo + hi) - ref)
            if dist < best and math.isfinite(_closure(lc, kinds, p, 0.5 * (lo + hi))):
                best, blo, bhi, bflo, bfhi, found = dist, lo, hi, flo, fhi, True
        th0, f0 = th1, f1
    return blo, bhi, bflo, bfhi, found, least


@_jit
def _illinois(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...], lo: float,
              hi: float, flo: float, fhi: float, iterations: int) -> float:
    """The Illinois secant on [lo, hi] to the last bit, as ``illinois.illinois`` (clamped)."""
    side = 0
    x = lo
    for _ in range(iterations):
        x = hi - _div(fhi * (hi - lo), fhi - flo)
        if not (x >= lo and x <= hi):
            x = 0.5 * (lo + hi)
        fx = _closure(lc, kinds, p, x)
        if not math.isfinite(fx):
            fx = 0.0
        if _sign(fx) == _sign(fhi):
            if side == 1:
                flo = 0.5 * flo
            hi, fhi, side = x, fx, 1
        else:
            if side == -1:
                fhi = 0.5 * fhi
            lo, flo, side = x, fx, -1
        if not (fx != 0 and abs(hi - lo) > ILLINOIS_ULPS * (1 + abs(x))):
            break
    return x


@_jit
def _triadp_angle(lc: tuple[float, ...], kinds: tuple[int, ...], p: tuple[float, ...],
                  counts: tuple[int, ...], cth: tuple[float, ...], sth: tuple[float, ...]
                  ) -> tuple[float, float, float]:
    """θ of the base link, the gap and the sine at one position, as ``triadp_solve.solve``.

    ``lc``: the three loci (4 numbers each); ``kinds``: their codes; ``p``: :func:`group_args`;
    ``counts``: :data:`CONSTANTS`; ``cth``, ``sth``: :func:`grid_trig`."""
    grid, window, iterations = counts[0], counts[1], counts[3]
    size = p[13]
    gap = size
    lo, hi, flo, fhi, found = NAN, NAN, NAN, NAN, False
    for half in (window, grid // 2):
        lo, hi, flo, fhi, found, least = _cells(lc, kinds, p, half, counts, cth, sth)
        if half == grid // 2:
            gap = least if math.isfinite(least) else size
        if found:
            break
    if not found:
        return NAN, gap, 0.0
    x = _illinois(lc, kinds, p, lo, hi, flo, fhi, iterations)
    f, msine = _closure_cs(lc, kinds, p, x, math.cos(x), math.sin(x))
    a, b = _max(x - SLOPE_STEP, lo), _min(x + SLOPE_STEP, hi)
    fp = _div(_closure(lc, kinds, p, b) - _closure(lc, kinds, p, a), b - a)
    sine = _min(1.0, abs(fp) * msine / size)
    return x, -abs(f), (0.0 if math.isnan(sine) else sine)
