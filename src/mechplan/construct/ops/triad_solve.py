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
from typing import NamedTuple

import numpy as np

from ...geom.vec import Array

#: grid of base-link angles on which the closure's roots are bracketed
GRID = 24
#: cells on each side of the reference angle searched first
WINDOW = 3
#: iterations of the refinement, at most (a bisection from a 15° cell reaches the last bit in 52)
ITERATIONS = 64
#: plain Newton steps tried first (from a 15° cell's secant point the error falls as 1e-2,
#: 1e-4, 1e-8, 1e-16)
PURE = 4
#: a Newton step this small (relative to 1 + |θ|) ends the refinement
STEP_TOL = 4e-16
#: …when the residual |f| is within this many roundings of the group's size
RESIDUAL_ULPS = 64.0


class Triad(NamedTuple):
    """The group's dimensions and its assembly: lengths of the legs, the base link's points B_2,
    B_3 relative to B_1 in its frame, the arcs' branch σ, the sign of f′ at the root and the
    assembly's angle."""

    l1: float
    l2: float
    l3: float
    d2: tuple[float, float]
    d3: tuple[float, float]
    sigma: int
    slope: int
    ref: float

    @property
    def size(self) -> float:
        return self.l1 + self.l2 + self.l3 + math.hypot(*self.d2) + math.hypot(*self.d3)


def closure(a1: Array, a2: Array, a3: Array, theta: Array, t: Triad, sigma: int | None = None,
            slope: bool = False) -> tuple[Array, Array, Array | None]:
    """f(θ), the arcs' sine and (``slope``) f′(θ) at base angles θ (points broadcast against θ's
    shape).

    The arcs meet by Heron's product form (exact near tangency); a square of the half-chord
    negative by rounding only (at a domain edge taken as a grid node) counts as zero. f′ is the
    closed-form derivative (infinite at a domain edge, where the half-chord is zero).
    """
    sg = t.sigma if sigma is None else sigma
    l1, l2, l3, d2, d3 = t.l1, t.l2, t.l3, t.d2, t.d3
    c, s = np.cos(theta), np.sin(theta)
    u2x, u2y = c * d2[0] - s * d2[1], s * d2[0] + c * d2[1]
    dx = a2[..., 0] - u2x - a1[..., 0]
    dy = a2[..., 1] - u2y - a1[..., 1]
    dd = dx * dx + dy * dy
    with np.errstate(invalid="ignore", divide="ignore"):
        along = (l1 * l1 - l2 * l2 + dd) / (2.0 * dd)
        big, small = (l1 + l2) ** 2 - dd, dd - (l1 - l2) ** 2
        h2 = big * small / (4.0 * dd * dd)
        h2 = np.where((h2 < 0.0) & (h2 > -1e-12), 0.0, h2)
        h = np.sqrt(h2) * sg
        bx = a1[..., 0] + along * dx - h * dy
        by = a1[..., 1] + along * dy + h * dx
        u3x, u3y = c * d3[0] - s * d3[1], s * d3[0] + c * d3[1]
        rx = bx - a3[..., 0] + u3x
        ry = by - a3[..., 1] + u3y
        rr = np.sqrt(rx * rx + ry * ry)
        f = rr - l3
        sine = np.abs(h) * dd / (l1 * l2)
        fp = None
        if slope:
            # d/dθ: dx′ = u2y, dy′ = −u2x; along, h² and h through dd
            ddp = 2.0 * (dx * u2y - dy * u2x)
            alongp = -(l1 * l1 - l2 * l2) * ddp / (2.0 * dd * dd)
            h2p = ddp * ((big - small) * dd - 2.0 * big * small) / (4.0 * dd * dd * dd)
            hp = h2p / (2.0 * h)
            bxp = alongp * dx + along * u2y - hp * dy + h * u2x
            byp = alongp * dy - along * u2x + hp * dx + h * u2y
            fp = (rx * (bxp - u3y) + ry * (byp + u3x)) / rr
    return f, sine, fp


def _sloped(a1: Array, a2: Array, a3: Array, theta: Array, t: Triad
            ) -> tuple[Array, Array, Array]:
    """f, the arcs' sine and f′ at θ (:func:`closure` with the slope)."""
    f, sine, fp = closure(a1, a2, a3, theta, t, slope=True)
    assert fp is not None
    return f, sine, fp


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


class Cells(NamedTuple):
    """Per position: the bracket [lo, hi] with f at its ends, whether one was found, and (where
    none) the least |f| over the branch."""

    lo: Array
    hi: Array
    flo: Array
    fhi: Array
    found: Array
    miss: Array


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
    e = _in_turn(np.stack(_edge_rows(a[0], a[1], a[2], a[3], t)), th[0])  # (4, N)
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
    chosen = np.full(n, -1, np.intp)
    for j in sorted(range(2 * WINDOW), key=lambda j: (dist[j], j), reverse=True):
        chosen[ok[j]] = j
    has = chosen >= 0
    cj = np.maximum(chosen, 0)
    best = np.where(has, dist[cj], np.inf)
    lo, hi = np.where(has, th[cj], np.nan), np.where(has, th[cj + 1], np.nan)
    flo, fhi = np.where(has, f[cj, r], np.nan), np.where(has, f[cj + 1, r], np.nan)
    # then the halves left of each edge, then those right of it, where the edge is inside
    ats = [np.nonzero(inside[m])[0] for m in range(e.shape[0])]
    fe = [_values(tuple(v[at] for v in a), e[m, at], t) for m, at in enumerate(ats)]
    for side in (0, 1):
        for m, at in enumerate(ats):
            c, em = cell[m, at], e[m, at]
            if side == 0:
                c0, c1, f0, f1 = th[c], em, f[c, at], fe[m]
            else:
                c0, c1, f0, f1 = em, th[c + 1], fe[m], f[c + 1, at]
            d = np.abs(0.5 * (c0 + c1) - t.ref)
            better = rising(f0, f1, t.slope) & (d < best[at])
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


def _slope_at(a: tuple[Array, ...], x: Array, t: Triad) -> tuple[Array, Array, Array]:
    """f, the arcs' sine and f′ at θ = ``x`` (``a``: the points' coordinates as rows (N,)):
    :func:`closure`'s formulas in its order of operations — the same values — with fewer
    temporaries (the Newton iteration's inner step)."""
    l1, l2, l3, sg = t.l1, t.l2, t.l3, t.sigma
    (d20, d21), (d30, d31) = t.d2, t.d3
    a1x, a1y, a2x, a2y, a3x, a3y = a
    c, s = np.cos(x), np.sin(x)
    u2x = c * d20
    u2x -= s * d21
    u2y = s * d20
    u2y += c * d21
    dx = a2x - u2x
    dx -= a1x
    dy = a2y - u2y
    dy -= a1y
    dd = dx * dx
    dd += dy * dy
    k = l1 * l1 - l2 * l2
    with np.errstate(invalid="ignore", divide="ignore"):
        two = 2.0 * dd
        along = k + dd
        along /= two
        big = (l1 + l2) ** 2 - dd
        small = dd - (l1 - l2) ** 2
        four = 4.0 * dd
        four *= dd                                         # 4·dd·dd
        h = big * small
        h /= four
        np.copyto(h, 0.0, where=(h < 0.0) & (h > -1e-12))
        np.sqrt(h, out=h)
        if sg != 1:
            h *= sg
        rx = along * dx
        rx += a1x
        rx -= h * dy                                       # B_1
        ry = along * dy
        ry += a1y
        ry += h * dx
        u3x = c * d30
        u3x -= s * d31
        u3y = s * d30
        u3y += c * d31
        rx -= a3x
        rx += u3x
        ry -= a3y
        ry += u3y
        rr = rx * rx
        rr += ry * ry
        np.sqrt(rr, out=rr)
        f = rr - l3
        sine = np.abs(h)
        sine *= dd
        sine /= l1 * l2
        ddp = dx * u2y
        ddp -= dy * u2x
        ddp *= 2.0
        two *= dd                                          # 2·dd·dd
        alongp = ddp * -k
        alongp /= two
        inner = big - small
        inner *= dd
        big *= 2.0
        big *= small
        inner -= big                                       # (big − small)·dd − 2·big·small
        four *= dd                                         # 4·dd·dd·dd
        hp = ddp * inner
        hp /= four
        hp /= 2.0 * h
        bxp = alongp * dx
        bxp += along * u2y
        bxp -= hp * dy
        bxp += h * u2x
        byp = alongp * dy
        byp -= along * u2x
        byp += hp * dx
        byp += h * u2y
        bxp -= u3y
        bxp *= rx
        byp += u3x
        byp *= ry
        bxp += byp
        bxp /= rr
    return f, sine, bxp


#: Newton steps after which a position may be settled (from a 15° cell's secant point the error
#: falls as 1e-2, 1e-4, 1e-8, 1e-16: three steps settle it where the cell is not too curved)
SETTLE = 3


def _pure(a1: Array, a2: Array, a3: Array, c: Cells, t: Triad, out: tuple[Array, ...]
          ) -> Array:
    """At most ``PURE`` steps of Newton's iteration from the secant point, for the found
    brackets (no bookkeeping between them). A position is settled, after ``SETTLE`` steps or
    any later one, where the last iterate is in its bracket and its error, C·s² with
    C = s / s_prev² estimated from the last two steps (the quadratic convergence), is below
    ``STEP_TOL``·(1 + |θ|) — or the step itself is that small with a residual within
    ``RESIDUAL_ULPS`` roundings of the group's size; the positions left go on. Fills ``out``
    (θ, and f, f′, the arcs' sine at the last point evaluated); returns the positions left for
    :func:`_guarded`."""
    theta, f_at, fp_at, sine_at = out
    idx = np.nonzero(c.found)[0]
    lo, hi, flo, fhi = c.lo[idx], c.hi[idx], c.flo[idx], c.fhi[idx]
    a = tuple(np.ascontiguousarray(p[idx, j]) for p in (a1, a2, a3) for j in (0, 1))
    small = RESIDUAL_ULPS * np.finfo(float).eps * t.size
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        x = hi - fhi * (hi - lo) / (fhi - flo)
        x = np.where((x > lo) & (x < hi), x, 0.5 * (lo + hi))
        prev = step = x
        for it in range(PURE):
            if not idx.size:
                break
            fx, sx, fp = _slope_at(a, x, t)
            prev, step = step, fx / fp
            x = x - step
            if it + 1 < SETTLE:
                continue
            tol = STEP_TOL * (1.0 + np.abs(x))
            s = np.abs(step)
            done = ((s * s * s <= tol * prev * prev) & (s <= 1e-6)) | (
                (s <= tol) & (np.abs(fx) <= small))
            done &= (x >= lo) & (x <= hi)                  # NaN compares False
            j = idx[done]
            theta[j], f_at[j], fp_at[j], sine_at[j] = x[done], fx[done], fp[done], sx[done]
            keep = ~done
            if it + 1 < PURE and not keep.all():
                idx, x, prev, step = idx[keep], x[keep], prev[keep], step[keep]
                lo, hi = lo[keep], hi[keep]
                a = tuple(v[keep] for v in a)
            elif it + 1 == PURE:
                idx = idx[keep]
    left: Array = idx
    return left


def _guarded(a1: Array, a2: Array, a3: Array, c: Cells, t: Triad, idx: Array,
             out: tuple[Array, ...]) -> None:
    """Newton's iteration kept inside the bracket (a bisection where a step would leave it, not
    move, or f′ is not finite) for the positions ``idx``, from the secant point; it ends where
    the step is below ``STEP_TOL``·(1 + |θ|) with the residual within ``RESIDUAL_ULPS``
    roundings of the group's size, or where f is zero. Fills ``out`` as :func:`_pure`."""
    theta, f_at, fp_at, sine_at = out
    lo, hi, flo, fhi = c.lo[idx], c.hi[idx], c.flo[idx], c.fhi[idx]
    p1, p2, p3 = a1[idx], a2[idx], a3[idx]
    small = RESIDUAL_ULPS * np.finfo(float).eps * t.size
    fx = fp = sx = xo = np.empty(0)
    with np.errstate(invalid="ignore", divide="ignore"):
        x = hi - fhi * (hi - lo) / (fhi - flo)
        x = np.where((x > lo) & (x < hi), x, 0.5 * (lo + hi))
        for _ in range(ITERATIONS):
            if not idx.size:
                break
            fx, sx, fp = _sloped(p1, p2, p3, x, t)
            same = np.sign(fx) == np.sign(fhi)
            hi, fhi = np.where(same, x, hi), np.where(same, fx, fhi)
            lo, flo = np.where(same, lo, x), np.where(same, flo, fx)
            step = fx / fp
            xn = x - step
            inside = np.isfinite(fp) & (xn >= lo) & (xn <= hi)
            done = (fx == 0.0) | (inside & (np.abs(step) <= STEP_TOL * (1.0 + np.abs(x)))
                                  & (np.abs(fx) <= small))
            done |= ~np.isfinite(fx)                       # left the domain: give up
            xn = np.where(fx == 0.0, x, np.where(inside & ((xn != x) | done), xn,
                                                  0.5 * (lo + hi)))
            if done.any():
                j = idx[done]
                theta[j] = np.where(np.isfinite(fx[done]), xn[done], np.nan)
                f_at[j], fp_at[j], sine_at[j] = fx[done], fp[done], sx[done]
                keep = ~done
                idx, xo, x = idx[keep], x[keep], xn[keep]
                lo, hi, flo, fhi = lo[keep], hi[keep], flo[keep], fhi[keep]
                p1, p2, p3 = p1[keep], p2[keep], p3[keep]
                fx, fp, sx = fx[keep], fp[keep], sx[keep]
            else:
                x, xo = xn, x
        # the iterations ran out: the last point evaluated
        theta[idx], f_at[idx], fp_at[idx], sine_at[idx] = xo, fx, fp, sx


def newton(a1: Array, a2: Array, a3: Array, c: Cells, t: Triad
           ) -> tuple[Array, Array, Array, Array]:
    """The root in each found bracket: θ (NaN where none) and, at the last point evaluated
    (within a rounding or C·s² of θ), f, f′ and the arcs' sine. Newton's iteration
    (:func:`_pure`), and where it does not settle in the bracket, the safeguarded one
    (:func:`_guarded`)."""
    out = tuple(np.full(c.lo.shape, np.nan) for _ in range(4))
    left = _pure(a1, a2, a3, c, t, out)
    if left.size:
        _guarded(a1, a2, a3, c, t, left, out)
    return out[0], out[1], out[2], out[3]


#: positions solved together: each position is solved alone, so blocks give the same values;
#: a block's temporaries stay in the cache and in memory already mapped (measured on 100 000
#: positions: 8 192 at a time took 0.6× the time of all at once, in an evaluation less)
BLOCK = 8192


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
    side = np.zeros(lo.shape)
    x = lo.copy()
    active = np.ones(lo.shape, bool)
    for _ in range(ITERATIONS):
        if not active.any():
            break
        with np.errstate(invalid="ignore", divide="ignore"):
            x = np.where(active, hi - fhi * (hi - lo) / (fhi - flo), x)
        fx = closure(a1, a2, a3, x, t, sigma)[0]
        fx = np.where(np.isfinite(fx), fx, 0.0)
        same_hi = np.sign(fx) == np.sign(fhi)
        upd_hi, upd_lo = active & same_hi, active & ~same_hi
        # Illinois: halve the stale end's value when the same end moves twice
        flo = np.where(upd_hi & (side == 1), 0.5 * flo, flo)
        fhi = np.where(upd_lo & (side == -1), 0.5 * fhi, fhi)
        hi, fhi = np.where(upd_hi, x, hi), np.where(upd_hi, fx, fhi)
        lo, flo = np.where(upd_lo, x, lo), np.where(upd_lo, fx, flo)
        side = np.where(upd_hi, 1, np.where(upd_lo, -1, side))
        active &= (fx != 0) & (np.abs(hi - lo) > 4e-16 * (1 + np.abs(x)))
    return x


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
