"""The closure of an RRR-RRR triad, f(θ), with the solver's constants: the base of
``triad_solve`` (bracketing) and ``triad_newton`` (refinement); see ``triad_solve`` for the method.
``construct/kernel_triad.py`` computes the same for one position (the numba cache's digest reads
these files)."""

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

#: Newton steps after which a position may be settled (from a 15° cell's secant point the error
#: falls as 1e-2, 1e-4, 1e-8, 1e-16: three steps settle it where the cell is not too curved)
SETTLE = 3


class Cells(NamedTuple):
    """Per position: the bracket [lo, hi] with f at its ends, whether one was found, and (where
    none) the least |f| over the branch."""

    lo: Array
    hi: Array
    flo: Array
    fhi: Array
    found: Array
    miss: Array


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
