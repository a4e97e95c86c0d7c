"""The triad's closure refined inside its brackets: Newton's iteration from the secant point,
safeguarded by bisection (``triad_solve`` finds the brackets)."""

from __future__ import annotations

import numpy as np

from ...geom.vec import Array
from .triad_closure import (
    ITERATIONS,
    PURE,
    RESIDUAL_ULPS,
    SETTLE,
    STEP_TOL,
    Cells,
    Triad,
    _sloped,
)


def _slope_at(a: tuple[Array, ...], x: Array, t: Triad) -> tuple[Array, Array, Array]:
    """f, the arcs' sine and f′ at θ = ``x`` (``a``: the points' coordinates as rows (N,)): f
    and the sine by :func:`closure`'s formulas in its order of operations — the same values —
    with fewer temporaries, f′ by implicit differentiation (equal to :func:`closure`'s within
    roundings; the Newton iteration's inner step)."""
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
        px = rx - a1x                                      # B_1 − A_1 (for f′ only)
        py = ry - a1y
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
        # f′ by implicit differentiation: B_1′ = λ·perp(B_1 − A_1) keeps the first arc, and the
        # second, |B_1 − C_2| = l_2 with C_2 = A_2 − R(θ)·d2, gives λ·(B_1 − A_1) × (B_1 − C_2)
        # = (B_1 − C_2)·C_2′ with C_2′ = (u2y, −u2x) and (B_1 − A_1) × (B_1 − C_2) = h·dd; then
        # f′ = r·(B_1′ + perp(R(θ)·d3)) / |r|. Fewer operations than the chain rule through the
        # half-chord; f′ only steers the steps (the root is where f is zero).
        lam = px - dx                                      # B_1 − C_2
        lam *= u2y
        qy = py - dy
        qy *= u2x
        lam -= qy
        h *= dd
        lam /= h                                           # λ (infinite at a domain edge)
        out = ry * px
        out -= rx * py                                     # r · perp(B_1 − A_1)
        out *= lam
        out += ry * u3x
        out -= rx * u3y                                    # + r · perp(R(θ)·d3)
        out /= rr
    return f, sine, out




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
    every = idx.size == c.found.size                      # as often: no gathers, the same values
    pick: Array | slice = slice(None) if every else idx
    lo, hi, flo, fhi = c.lo[pick], c.hi[pick], c.flo[pick], c.fhi[pick]
    a = tuple(np.ascontiguousarray(p[pick, j]) for p in (a1, a2, a3) for j in (0, 1))
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
