"""The point of a link with the least velocity, from the link's absolute instant centre.

Every point of a link moves with |v| = |ω|·(its distance from the instant centre I), I = Q + k×v_Q/ω
for any point Q of the link. On the link as drawn — the segment between its two points, or the
plate (convex outline) of three or more — the slowest point is the one nearest to I: the foot of
the perpendicular from I onto the link's line when it falls between the points, else the nearer
end; I itself when it lies inside a plate. A link in instantaneous translation (ω = 0) has every
point equally fast: the point is NaN and v_min = |v_Q|.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...model.mechanism import GROUND, Mechanism, PairKind
from ..graph import Construction, Evaluation
from .motion import Array, motion

#: |ω| below which a link is taken as translating (rad/s, relative to the crank's)
TRANSLATING = 1e-12


@dataclass(frozen=True, slots=True)
class LeastVelocity:
    """Instant centre ``I``, the slowest point ``G`` (N, 2), its speed (N,) and, for a link
    drawn as a bar, its distance from the link's first point along the bar (N,)."""

    link: str
    points: tuple[str, ...]
    centre: Array
    G: Array
    v_min: Array
    along: Array | None


def _cross(u: Array, v: Array) -> Array:
    out: Array = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    return out


def _nearest_on_segment(a: Array, b: Array, p: Array) -> Array:
    d = b - a
    t = np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d)
    out: Array = a + np.clip(t, 0.0, 1.0)[:, None] * d
    return out


def _convex_hull(pts: Array) -> list[int]:
    """Indices of the convex hull (counter-clockwise) of a few points in one position (M, 2);
    two indices (the ends) when the points lie on one line."""
    order = sorted(range(len(pts)), key=lambda i: (pts[i, 0], pts[i, 1]))
    tol = 1e-12 * float(np.ptp(pts, axis=0).max()) ** 2

    def half(seq: list[int]) -> list[int]:
        h: list[int] = []
        for i in seq:
            while len(h) >= 2 and _cross(pts[h[-1]] - pts[h[-2]], pts[i] - pts[h[-2]]) <= tol:
                h.pop()
            h.append(i)
        return h

    lower, upper = half(order), half(order[::-1])
    return lower[:-1] + upper[:-1]


def least_velocity(c: Construction, ev: Evaluation, mech: Mechanism, link: str) -> LeastVelocity:
    """The slowest point of ``link`` (which must have two named, built points)."""
    lk = mech.links[link]
    names = tuple(p for p in lk.points if c.has_position(p) and c.has_result("v", p))
    m = motion(c, ev, mech, link, False)
    w = m.omega
    turning = np.abs(w) > TRANSLATING * max(1.0, abs(mech.drive.omega))
    with np.errstate(invalid="ignore", divide="ignore"):
        centre = m.r + np.stack([-m.v[:, 1], m.v[:, 0]], axis=1) / np.where(turning, w, np.nan)[
            :, None]
    pos = np.stack([ev[c.position(p)] for p in names], axis=1)     # (N, M, 2)
    hull = _convex_hull(pos[0])
    if len(hull) <= 2:              # a bar (its points on one line): the segment between its ends
        ends = hull if len(hull) == 2 else [0, 1]
        best = _nearest_on_segment(pos[:, ends[0]], pos[:, ends[1]], centre)
    else:
        best = np.full((ev.n, 2), np.nan)
        best_d = np.full(ev.n, np.inf)
        inside = np.ones(ev.n, dtype=bool)
        for i, j in zip(hull, hull[1:] + hull[:1]):
            e, f = pos[:, i], pos[:, j]
            cand = _nearest_on_segment(e, f, centre)
            dist = np.hypot(*(cand - centre).T)
            closer = dist < best_d
            best[closer], best_d[closer] = cand[closer], dist[closer]
            inside &= _cross(f - e, centre - e) >= 0
        best[inside] = centre[inside]
    v_min = np.where(turning, np.abs(w) * np.hypot(*(best - centre).T), np.hypot(*m.v.T))
    along = np.hypot(*(best - pos[:, 0]).T) if len(hull) <= 2 else None
    return LeastVelocity(link, names, centre, best, v_min, along)


def slowest_links(c: Construction, mech: Mechanism) -> list[str]:
    """Moving links drawn with at least two built points and not pivoted on the frame (the
    slowest point of a crank or rocker is its fixed pivot)."""
    return [lid for lid in mech.moving
            if sum(c.has_position(p) and c.has_result("v", p) for p in mech.links[lid].points) >= 2
            and not any(pr.kind is PairKind.REVOLUTE and pr.joins(lid) and pr.other(lid) == GROUND
                        for pr in mech.pairs)]
