"""Meets of construction loci with their conditioning, vectorised over positions.

Every function returns ``(point, gap, sine)``:
- ``point``: (N, 2), NaN where the loci do not meet;
- ``gap``: (N,) metres by which the loci miss each other (> 0: no meet; ≤ 0: they meet);
- ``sine``: (N,) |sin| of the angle at which the loci cross (0 = tangent/parallel; the meet's
  condition number is 1/sine).
"""

from __future__ import annotations

import numpy as np

from .vec import Array, cross, dot, norm


def circle_circle(
    c1: Array, r1: Array | float, c2: Array, r2: Array | float, sigma: int
) -> tuple[Array, Array, Array]:
    """Intersect circles (c1, r1) and (c2, r2); sigma=+1 takes the point left of c1→c2."""
    d_vec = c2 - c1
    d = norm(d_vec)
    r1 = np.asarray(r1, dtype=d.dtype)  # the points' float type (float32 stays float32)
    r2 = np.asarray(r2, dtype=d.dtype)
    gap = np.maximum(d - (r1 + r2), np.abs(r1 - r2) - d)
    # the formulas below, evaluated in place (the same operations in the same order)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        dd = d * d
        a = r1 * r1 - r2 * r2 + dd
        a /= 2.0 * d
        # product form of r1² − a² keeps precision near tangency (Heron)
        h = (r1 + r2) ** 2 - dd
        h *= dd - (r1 - r2) ** 2
        dd *= 4.0                                   # 4·d·d: a power of two, exactly
        h /= dd
        negative = h < 0.0
        np.sqrt(h, out=h)                           # NaN where the circles miss
        if negative.any():
            h[negative & (gap <= 0.0)] = 0.0         # tangent within rounding
        ux, uy = d_vec[..., 0] / d, d_vec[..., 1] / d
        sh = h if sigma == 1 else sigma * h
        # per component: cheaper than broadcasting over a trailing axis of length 2
        point = np.empty(d.shape + (2,), d.dtype)
        x, y = point[..., 0], point[..., 1]
        np.multiply(a, ux, out=x)
        np.add(c1[..., 0], x, out=x)
        np.subtract(x, sh * uy, out=x)
        np.multiply(a, uy, out=y)
        np.add(c1[..., 1], y, out=y)
        np.add(y, sh * ux, out=y)
        sine = h * d
        sine /= r1 * r2
        np.abs(sine, out=sine)
    return point, gap, sine


def circle_line(
    c: Array, r: Array | float, p: Array, u: Array, sigma: int
) -> tuple[Array, Array, Array]:
    """Intersect circle (c, r) with the line through p along unit u.

    sigma=+1 takes the far one along u.
    """
    w = cross(u, c - p)
    r = np.asarray(r, dtype=np.result_type(w, np.float32))  # float32 points stay float32
    along = dot(c - p, u)
    ux, uy = u[..., 0], u[..., 1]
    gap = np.abs(w) - r
    with np.errstate(invalid="ignore"):
        h2 = (r - w) * (r + w)
        h = np.sqrt(np.where(h2 >= 0.0, h2, np.nan))
        h = np.where((h2 < 0.0) & (gap <= 0.0), 0.0, h)
        sh = sigma * h
        fx, fy = p[..., 0] + along * ux, p[..., 1] + along * uy
        point = np.stack((fx + sh * ux, fy + sh * uy), axis=-1)
        sine = np.abs(h / r)
    return point, gap, sine


def line_line(p1: Array, u1: Array, p2: Array, u2: Array) -> tuple[Array, Array, Array]:
    """Intersect the line through p1 along u1 with the line through p2 along u2 (u unit)."""
    s = cross(u1, u2)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        t = cross(p2 - p1, u2)
        t /= s
        parallel = s == 0.0
        if parallel.any():
            t[parallel] = np.nan
        # per component, in place: the same values as p1 + t·u1
        point = np.empty(t.shape + (2,), t.dtype)
        x, y = point[..., 0], point[..., 1]
        np.multiply(t, u1[..., 0], out=x)
        np.add(p1[..., 0], x, out=x)
        np.multiply(t, u1[..., 1], out=y)
        np.add(p1[..., 1], y, out=y)
    # two lines always meet unless parallel; parallelism is a conditioning matter, not a gap
    return point, np.full(s.shape, -np.inf), np.abs(s)
