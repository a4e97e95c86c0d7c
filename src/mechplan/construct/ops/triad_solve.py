"""The closure of an RRR-RRR triad solved for the base link's angle θ, vectorised over positions.

Legs i = 1, 2, 3 join known points A_i to the base link's points B_i (|A_i B_i| = l_i). With θ,
B_2 − B_1 = R(θ)·d2 and B_3 − B_1 = R(θ)·d3, so B_1 is where the arc (A_1, l_1) meets the arc
(A_2 − R(θ)·d2, l_2) (branch σ), and the closure is f(θ) = |B_1 − (A_3 − R(θ)·d3)| − l_3 = 0.

The root of branch σ with the sign of f′ given, nearest the assembly's angle, is bracketed on a
grid of ``GRID`` angles (first the ``WINDOW`` cells on each side of the assembly's angle, then the
whole turn) with the edges of the arcs' domain (closed form) as further nodes, and refined by a
safeguarded Newton iteration with f′ in closed form (a bisection wherever a Newton step would
leave the bracket). The fast path: where no edge of the domain falls in the window, the window's
nodes are the same angles at every position (their rotations computed once) and no sort is
needed. ``construct/kernel_triad.py`` is the same algorithm for one position.
"""

from __future__ import annotations

import math

import numpy as np

from ...geom.vec import Array
from .illinois import illinois
from .triad_closure import (  # noqa: F401  (the solver's constants and closure, re-exported)
    GRID,
    ITERATIONS,
    PURE,
    RESIDUAL_ULPS,
    SETTLE,
    STEP_TOL,
    WINDOW,
    Cells,
    Triad,
    _sloped,
    closure,
)
from .triad_newton import newton


def edges(a1: Array, a2: Array, t: Triad) -> Array:
    """The base angles (N, 4) where the arcs about A_1 and A_2 − R(θ)·d2 touch (NaN: none).

    |A_2 − A_1 − R(θ)·d2|² = |u|² + |d2|² − 2ρ·cos(θ − α) equals (l_1 ± l_2)² in closed form.
    """
    return np.stack(_edge_rows(a1[..., 0], a1[..., 1], a2[..., 0], a2[..., 1], t), axis=-1)


def _edge_rows(a1x: Array, a1y: Array, a2x: Array, a2y: Array, t: Triad) -> list[Array]:
    """:func:`edges` from the points' coordinates, one array per edge."""
    l1, l2, d2 = t.l1, t.l2, t.d2
    ux, uy = a2x - a1x, a2y - a1y
    p, q = ux * d2[0] + uy * d2[1], uy * d2[0] - ux * d2[1]
    rho, alpha = np.hypot(p, q), np.arctan2(q, p)
    base = ux * ux + uy * uy + d2[0] * d2[0] + d2[1] * d2[1]
    out = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for e in (l1 + l2, abs(l1 - l2)):
            t_ = np.arccos((base - e * e) / (2.0 * rho))
            out += [alpha + t_, alpha - t_]
    return out


def _in_turn(e: Array, lo: float) -> Array:
    out: Array = np.mod(e - lo, 2 * math.pi) + lo
    return out


def brackets(a1: Array, a2: Array, a3: Array, th: Array, t: Triad,
             sigma: int | None = None) -> tuple[Array, Array, Array, Array, Array]:
    """Grid cells (N, M) of θ with the closure's values at their ends, and the values.

    The grid ``th`` (ascending, spanning at most one turn) gets, per position, the edges of the
    arcs' domain as further nodes (:func:`edges`, put into the same turn), so that no cell
    straddles an edge where the two branches of the arcs join: a root beside an edge is
    bracketed. A cell between two edges whose inside is off the domain (f undefined at its
    midpoint) gets NaN at its start: no root is sought across it.
    """
    e = _in_turn(edges(a1, a2, t), th[0])
    e[e > th[-1]] = np.nan                                 # outside a window of less than a turn
    nodes = np.sort(np.concatenate((np.broadcast_to(th, (a1.shape[0], th.size)), e), axis=1),
                    axis=1)                                # NaN edges sort last
    p1, p2, p3 = a1[:, None, :], a2[:, None, :], a3[:, None, :]
    f = closure(p1, p2, p3, nodes, t, sigma)[0]
    mid = closure(p1, p2, p3, 0.5 * (nodes[:, :-1] + nodes[:, 1:]), t, sigma)[0]
    return nodes[:, :-1], nodes[:, 1:], np.where(np.isnan(mid), np.nan, f[:, :-1]), f[:, 1:], f


def crossing(f0: Array, f1: Array) -> Array:
    """Cells where f changes sign (or reaches zero) between finite ends."""
    out: Array = np.isfinite(f0) & np.isfinite(f1) & (f0 * f1 <= 0) & (f0 != f1)
    return out


def rising(f0: Array, f1: Array, slope: int) -> Array:
    """Cells where f crosses zero with the sign ``slope`` (NaN ends compare False)."""
    out: Array = (f0 * f1 <= 0) & ((f1 - f0) * slope > 0)
    return out


def _values(a: tuple[Array, ...], th: Array, t: Triad,
            cs: tuple[Array, Array] | None = None) -> Array:
    """f at angles ``th`` ((M,): the same at every position, or (N, M)): (N, M), as
    :func:`closure` computes it (no point, no sine). ``a``: the points' coordinates as columns
    (N, 1) — a1x, a1y, a2x, a2y, a3x, a3y; ``cs``: cos θ and sin θ when already known."""
    l1, l2, d2, d3 = t.l1, t.l2, t.d2, t.d3
    a1x, a1y, a2x, a2y, a3x, a3y = a
    c, s = (np.cos(th), np.sin(th)) if cs is None else cs
    # the formulas of closure(), in place (the same operations in the same order)
    dx = a2x - (c * d2[0] - s * d2[1])
    dx -= a1x
    dy = a2y - (s * d2[0] + c * d2[1])
    dy -= a1y
    dd = dx * dx
    dd += dy * dy
    with np.errstate(invalid="ignore", divide="ignore"):
        along = (l1 * l1 - l2 * l2) + dd
        along /= 2.0 * dd
        h = (l1 + l2) ** 2 - dd
        h *= dd - (l1 - l2) ** 2
        four = 4.0 * dd
        four *= dd
        h /= four
        np.copyto(h, 0.0, where=(h < 0.0) & (h > -1e-12))
        np.sqrt(h, out=h)
        if t.sigma != 1:
            h *= t.sigma
        out: Array = along * dx
        out += a1x
        out -= h * dy
        out -= a3x
        out += c * d3[0] - s * d3[1]                       # rx
        along *= dy
        along += a1y
        along += h * dx
        along -= a3y
        along += s * d3[0] + c * d3[1]                     # ry
        out *= out
        along *= along
        out += along
        np.sqrt(out, out=out)
        out -= t.l3
    return out


def _window(a1: Array, a2: Array, a3: Array, t: Triad) -> tuple[Cells, Array]:
    """The fast path: the window's cells at the same angles at every position, each edge of the
    arcs' domain inside splitting its cell in two (the general cells without a sort). It decides
    where no cell holds two edges and a crossing is found; returns the positions it decides.

    Laid out node by node (rows of N positions): the nearest unsplit cell with a crossing, then
    a half of a split cell where it is nearer (the halves left of each edge, then those right of
    it) — the first of equally near candidates winning, as in one list."""
    n = a1.shape[0]
    dt = 2 * math.pi / GRID
    k = np.arange(-WINDOW, WINDOW + 1)
    th = k * dt + t.ref
    a = tuple(np.ascontiguousarray(p[:, j]) for p in (a1, a2, a3) for j in (0, 1))
    f = _values(a, th[:, None], t)                        # (nodes, N)
    rows = [r for r in _edge_rows(a[0], a[1], a[2], a[3], t) if not np.isnan(r).all()]
    if not rows:                                           # the arcs meet at every angle
        rows = [np.full(n, np.nan)]
    e = _in_turn(np.stack(rows), th[0])                    # (≤ 4, N): the edges that exist
    inside = e <= th[-1]                                   # NaN compares False
    some = inside.any(axis=1)
    e, inside = e[some], inside[some]                     # the edges inside at some position
    e = np.where(inside, e, np.nan)
    cell = np.clip(np.floor((e - th[0]) / dt), 0, 2 * WINDOW - 1)
    cell = np.where(inside, cell, 0).astype(np.intp)
    split = np.zeros((2 * WINDOW, n), bool)
    twice = np.zeros(n, bool)
    r = np.arange(n)
    for m in range(e.shape[0]):
        hit = inside[m]
        twice |= hit & split[cell[m], r]
        split[cell[m, hit], r[hit]] = True
    # the unsplit cells: the nearest with a crossing, the first of equally near ones
    dist = np.abs(0.5 * (th[:-1] + th[1:]) - t.ref)
    ok = rising(f[:-1], f[1:], t.slope) & ~split
    order = np.array(sorted(range(2 * WINDOW), key=lambda j: (dist[j], j)), np.intp)
    ranked = ok[order]                                     # rows nearest first
    cj = order[np.argmax(ranked, axis=0)]                  # the first True (nearest, then first)
    has = ranked.any(axis=0)
    best = np.where(has, dist[cj], np.inf)
    lo, hi = np.where(has, th[cj], np.nan), np.where(has, th[cj + 1], np.nan)
    flo, fhi = np.where(has, f[cj, r], np.nan), np.where(has, f[cj + 1, r], np.nan)
    # then the halves left of each edge, then those right of it, where the edge is inside
    ats = [np.nonzero(inside[m])[0] for m in range(e.shape[0])]
    # where an edge is inside at every position (as often), its rows are taken whole, not gathered
    part: list[Array | slice] = [slice(None) if at.size == n else at for at in ats]
    fe = [_values(a if isinstance(sel, slice) else tuple(v[sel] for v in a), e[m, sel], t)
          for m, sel in enumerate(part)]
    for side in (0, 1):
        for m, at in enumerate(ats):
            sel = part[m]
            c, em = cell[m, sel], e[m, sel]
            if side == 0:
                c0, c1, f0, f1 = th[c], em, f[c, at], fe[m]
            else:
                c0, c1, f0, f1 = em, th[c + 1], fe[m], f[c + 1, at]
            d = np.abs(0.5 * (c0 + c1) - t.ref)
            better = rising(f0, f1, t.slope) & (d < best[sel])
            w = at[better]
            best[w], lo[w], hi[w] = d[better], c0[better], c1[better]
            flo[w], fhi[w] = f0[better], f1[better]
    found = np.isfinite(best) & ~twice
    return Cells(lo, hi, flo, fhi, found, np.full(n, np.inf)), found


def _general(a1: Array, a2: Array, a3: Array, t: Triad) -> Cells:
    """Cells with the domain's edges as nodes: the window, then the whole turn where the window
    has no root (a root inside the window is nearer than any outside, so the rule is the same)."""
    dt = 2 * math.pi / GRID
    n = a1.shape[0]
    lo, hi, flo, fhi = (np.full(n, np.nan) for _ in range(4))
    miss = np.full(n, np.inf)
    found = np.zeros(n, bool)
    todo = np.arange(n)
    for half in (WINDOW, GRID // 2):
        if not todo.size:
            break
        th = np.arange(-half, half + 1) * dt + t.ref
        c0, c1, g0, g1, g = brackets(a1[todo], a2[todo], a3[todo], th, t)
        ok = rising(g0, g1, t.slope)
        dist = np.abs(0.5 * (c0 + c1) - t.ref)
        kk = np.argmin(np.where(ok, dist, np.inf), axis=1)
        r = np.arange(todo.size)
        hit = ok[r, kk]
        lo[todo], hi[todo], flo[todo], fhi[todo] = c0[r, kk], c1[r, kk], g0[r, kk], g1[r, kk]
        found[todo] = hit
        if half == GRID // 2:
            miss[todo] = np.min(np.where(np.isfinite(g), np.abs(g), np.inf), axis=1)
        todo = todo[~hit]
    return Cells(lo, hi, flo, fhi, found, miss)


def select(a1: Array, a2: Array, a3: Array, t: Triad) -> Cells:
    """The bracket of the assembly's root at every position: the fast window, the general cells
    for the positions it leaves undecided."""
    cells, found = _window(a1, a2, a3, t)
    rest = np.nonzero(~found)[0]
    if rest.size:
        more = _general(a1[rest], a2[rest], a3[rest], t)
        for mine, theirs in zip(cells, more, strict=True):
            mine[rest] = theirs
    return cells


#: a block's temporaries stay in the cache and in memory already mapped: the memory a block
#: frees is the next one's where blocks are small enough for the allocator to keep it (measured
#: on 100 000 positions in a fresh process, glibc's default thresholds: 8 192 at a time every
#: block touched fresh pages, 9 000 in all, 530 ns a position; 6 144 at a time 700 pages and
#: 380 ns; 4 096 at a time 480 pages and 420 ns, the Python overhead of more blocks)
BLOCK = 6144


def solve(a1: Array, a2: Array, a3: Array, t: Triad) -> tuple[Array, Array, Array]:
    """θ of the base link at every position, the gap (−|f| at the root; where the group does not
    close, the least |f| over the branch) and the sine (|f′|·arcs' sine / size); ``BLOCK``
    positions at a time."""
    n = a1.shape[0]
    if n <= BLOCK:
        return _solve(a1, a2, a3, t)
    out = tuple(np.empty(n) for _ in range(3))
    for i in range(0, n, BLOCK):
        part = slice(i, i + BLOCK)
        for mine, theirs in zip(out, _solve(a1[part], a2[part], a3[part], t), strict=True):
            mine[part] = theirs
    return out[0], out[1], out[2]


def _solve(a1: Array, a2: Array, a3: Array, t: Triad) -> tuple[Array, Array, Array]:
    """:func:`solve` for one block."""
    cells = select(a1, a2, a3, t)
    theta, fb, fp, cc_sine = newton(a1, a2, a3, cells, t)
    found = cells.found & np.isfinite(theta)
    size = t.size
    with np.errstate(invalid="ignore"):
        sine = np.minimum(1.0, np.abs(fp) * cc_sine / size)
    miss = np.where(np.isfinite(cells.miss), cells.miss, size)
    gap = np.where(found, -np.abs(fb), miss)
    sine = np.where(found, np.nan_to_num(sine, nan=0.0), 0.0)
    return np.where(found, theta, np.nan), gap, sine


def refine(a1: Array, a2: Array, a3: Array, lo: Array, hi: Array, flo: Array, fhi: Array,
           t: Triad, sigma: int) -> Array:
    """Illinois secant on brackets [lo, hi] (f changes sign) to the last bit (the assembly's
    roots on branch ``sigma``, found once)."""
    return illinois(lambda x: closure(a1, a2, a3, x, t, sigma)[0], lo, hi, flo, fhi, ITERATIONS)


def roots(a1: Array, a2: Array, a3: Array, t: Triad, sigma: int) -> list[tuple[float, int]]:
    """Every root (θ, sign of f′) of branch ``sigma`` at the first position (assembly)."""
    th = np.linspace(-math.pi, math.pi, 721)
    t0, t1, f0, f1, _ = brackets(a1[:1], a2[:1], a3[:1], th, t, sigma)
    k = np.nonzero(crossing(f0[0], f1[0]))[0]
    n = k.size
    x = refine(np.repeat(a1[:1], n, 0), np.repeat(a2[:1], n, 0), np.repeat(a3[:1], n, 0),
               t0[0, k], t1[0, k], f0[0, k], f1[0, k], t, sigma)
    return [(math.remainder(float(v), 2 * math.pi), 1 if f1[0, j] > f0[0, j] else -1)
            for v, j in zip(x, k, strict=True)]


__all__ = ["GRID", "WINDOW", "Triad", "closure", "edges", "roots", "solve"]
