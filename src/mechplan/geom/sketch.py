"""Geometry of hand-drawn sketches: points that are one point, joined drawings, line crossings,
gaps between groups of points.

Vectorised over all points or segments of a drawing (numpy, shapely's STRtree, scipy's sparse
graphs); used to read a student's drawing.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import shapely
from numpy.typing import NDArray
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from shapely import STRtree
from shapely.geometry import MultiPoint

#: lines crossing at less than this angle do not define a point
MIN_CROSSING_DEG = 5.0


def cluster(points: NDArray[np.float64], snap: float) -> NDArray[np.int64]:
    """Cluster index of each point (M, 2): points closer than ``snap`` (transitively) are one
    cluster; clusters are numbered in order of their first point."""
    if not len(points):
        return np.zeros(0, dtype=np.int64)
    geoms = shapely.points(points)
    a, b = STRtree(geoms).query(geoms, predicate="dwithin", distance=snap)
    return components(len(points), a, b)


def components(n: int, a: NDArray[np.int64], b: NDArray[np.int64]) -> NDArray[np.int64]:
    """Connected component of each of ``n`` nodes joined by the edges ``a[i]``–``b[i]``,
    numbered in order of their first node."""
    edges = coo_matrix((np.ones(len(a)), (np.asarray(a), np.asarray(b))), shape=(n, n))
    _, labels = connected_components(edges, directed=False)
    _, first = np.unique(labels, return_index=True)
    order = np.argsort(np.argsort(first))
    return np.asarray(order[labels], dtype=np.int64)


def crossings(segments: NDArray[np.float64], near: tuple[float, float],
              radius: float) -> NDArray[np.float64]:
    """Points (K, 2) where two of the segments (M, 2, 2) cross within their extents, closer than
    ``radius`` to ``near``; nearly parallel pairs (< 5°) cross nowhere."""
    s = np.asarray(segments, dtype=float).reshape(-1, 2, 2)
    x, y = near
    lo, hi = s.min(axis=1), s.max(axis=1)
    s = s[(lo[:, 0] - radius <= x) & (x <= hi[:, 0] + radius)
          & (lo[:, 1] - radius <= y) & (y <= hi[:, 1] + radius)]
    i, j = np.triu_indices(len(s), k=1)
    p, r = s[i, 0], s[i, 1] - s[i, 0]
    q, u = s[j, 0], s[j, 1] - s[j, 0]
    d = r[:, 0] * u[:, 1] - r[:, 1] * u[:, 0]
    la, lb = np.hypot(*r.T), np.hypot(*u.T)
    ok = np.abs(d) >= math.sin(math.radians(MIN_CROSSING_DEG)) * la * lb
    d = np.where(ok, d, 1.0)
    w = q - p
    t = (w[:, 0] * u[:, 1] - w[:, 1] * u[:, 0]) / d
    v = (w[:, 0] * r[:, 1] - w[:, 1] * r[:, 0]) / d
    eps = 1e-6
    ok &= (t >= -eps) & (t <= 1 + eps) & (v >= -eps) & (v <= 1 + eps)
    pts = p + t[:, None] * r
    ok &= np.hypot(pts[:, 0] - x, pts[:, 1] - y) <= radius
    return np.asarray(pts[ok], dtype=np.float64)


def box_distance(points: NDArray[np.float64], centre: tuple[float, float],
                 half: tuple[float, float], rotation_deg: float = 0.0) -> NDArray[np.float64]:
    """Distance (N,) of points (N, 2) from a box of half sizes ``half`` about ``centre``, turned
    by ``rotation_deg`` (0 inside it)."""
    a = math.radians(rotation_deg)
    d = np.asarray(points, dtype=float).reshape(-1, 2) - np.asarray(centre, dtype=float)
    u = d[:, 0] * math.cos(a) + d[:, 1] * math.sin(a)
    v = -d[:, 0] * math.sin(a) + d[:, 1] * math.cos(a)
    out = np.hypot(np.maximum(np.abs(u) - half[0], 0.0), np.maximum(np.abs(v) - half[1], 0.0))
    return np.asarray(out, dtype=np.float64)


def nearest(points: NDArray[np.float64], at: tuple[float, float], within: float = math.inf,
            mask: NDArray[np.bool_] | None = None) -> int:
    """Index of the point (N, 2) nearest to ``at`` (the first of equals), only among ``mask``
    and not farther than ``within``; −1 when there is none."""
    d = np.hypot(*(np.asarray(points, dtype=float).reshape(-1, 2) - np.asarray(at)).T)
    d = np.where((d <= within) & (True if mask is None else mask), d, np.inf)
    return int(np.argmin(d)) if np.isfinite(d).any() else -1


def box_gap(a: Sequence[tuple[float, float]], b: Sequence[tuple[float, float]]) -> float:
    """Distance between the boxes around two sets of points (0 if they overlap, infinite if one
    set is empty)."""
    boxes = [MultiPoint(points).envelope for points in (a, b)]
    return math.inf if any(box.is_empty for box in boxes) else float(shapely.distance(*boxes))
