"""The blocking contour of an external involute pair (ГОСТ 16532 / ISO 21771 limits) and the
specific sliding along its line of action.

Each limit is a function g(x1, x2) that is ≥ 0 where the pair satisfies it, evaluated on arrays:
no undercut of gear j (x_j ≥ h_a*(z_min − z_j)/z_min, the course rule), top land s_aj ≥ k·m,
contact ratio ε_α ≥ ε_min, no interference of gear j (the lowest contact point ρ_pj not below the
start of the generated involute ρ_lj, nor below the base circle). A boundary of the contour is the
zero line of one limit, found for each x1 of a grid as the sign changes of g(x1, ·) over x2 refined
by bisection; the admissible region is where every limit holds.

The recommended pair: on the line of balanced specific sliding (the largest slidings of both gears
equal), inside the contour, the point of the largest ε_α; without such a point, the admissible grid
point of the largest ε_α.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import PairSpec

LIMITS = ("undercut1", "undercut2", "tip1", "tip2", "contact", "interference1", "interference2")


def inv_inverse_array(value: np.ndarray) -> np.ndarray:
    """α with tan α − α = value, elementwise (Newton; NaN where value < 0)."""
    v = np.asarray(value, dtype=float)
    bad = ~(v >= 0)
    a = np.minimum(np.cbrt(3.0 * np.where(bad, 0.0, v)), 1.5)
    a = np.maximum(a, 1e-12)
    for _ in range(60):
        t = np.tan(a)
        a = np.clip(a - (t - a - np.where(bad, 0.0, v)) / (t * t), 1e-12, 1.5707)
    return np.where(bad, np.nan, a)


@dataclass(frozen=True)
class PairArrays:
    """Quantities of the pair at arrays of shifts (SI; shapes of x1, x2 broadcast)."""

    alpha_w: np.ndarray
    a_w: np.ndarray
    eps: np.ndarray
    g: np.ndarray               # N1N2
    s_a: tuple[np.ndarray, np.ndarray]
    rho_l: tuple[np.ndarray, np.ndarray]
    rho_p: tuple[np.ndarray, np.ndarray]
    sliding: tuple[np.ndarray, np.ndarray]   # the largest specific sliding of each gear


def pair_arrays(p: PairSpec, x1: np.ndarray | float, x2: np.ndarray | float) -> PairArrays:
    """Lay the pair out at every (x1, x2) at once (the formulas of :mod:`.involute`)."""
    x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
    m, al, ha = p.module, p.alpha, p.addendum
    inv_al = math.tan(al) - al
    inv_w = 2 * (x1 + x2) * math.tan(al) / (p.z1 + p.z2) + inv_al
    aw = inv_inverse_array(inv_w)
    a = m * (p.z1 + p.z2) / 2
    a_w = a * math.cos(al) / np.cos(aw)
    dy = x1 + x2 - (a_w - a) / m
    g = a_w * np.sin(aw)
    s_a, rho_l, tip = [], [], []
    for z, x in ((p.z1, x1), (p.z2, x2)):
        r = m * z / 2
        r_b = r * math.cos(al)
        r_a = r + m * (ha + x - dy)
        a_a = np.arccos(np.clip(r_b / r_a, -1.0, 1.0))
        s = m * (math.pi / 2 + 2 * x * math.tan(al))
        s_a.append(2 * r_a * (s / (2 * r) + inv_al - (np.tan(a_a) - a_a)))
        rho_l.append(r * math.sin(al) - (ha - x) * m / math.sin(al))
        tip.append(np.sqrt(np.maximum(r_a ** 2 - r_b ** 2, 0.0)))
    rho_p = (g - tip[1], g - tip[0])
    eps = (tip[0] + tip[1] - g) / (math.pi * m * math.cos(al))
    sliding = []
    for j, ratio in ((0, p.z1 / p.z2), (1, p.z2 / p.z1)):
        rp = rho_p[j]
        with np.errstate(divide="ignore", invalid="ignore"):
            sliding.append(np.where(rp > 0, 1 - ratio * (g - rp) / rp, np.inf))
    return PairArrays(aw, a_w, eps, g, (s_a[0], s_a[1]), (rho_l[0], rho_l[1]), rho_p,
                      (sliding[0], sliding[1]))


@dataclass(frozen=True)
class ContourSpec:
    """The limits of the contour: the least top land (in modules) and the least ε_α."""

    tip_land: float = 0.25
    eps_min: float = 1.2


def limit_values(p: PairSpec, c: ContourSpec, x1: np.ndarray | float, x2: np.ndarray | float
                 ) -> dict[str, np.ndarray]:
    """g(x1, x2) of every limit of :data:`LIMITS` (≥ 0: satisfied; dimensionless, in modules)."""
    q = pair_arrays(p, x1, x2)
    m = p.module
    x1a, x2a = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
    out = {}
    for j, (z, x) in enumerate(((p.z1, x1a), (p.z2, x2a)), start=1):
        out[f"undercut{j}"] = x - p.addendum * (p.z_min - z) / p.z_min
        out[f"tip{j}"] = q.s_a[j - 1] / m - c.tip_land
        out[f"interference{j}"] = (q.rho_p[j - 1] - np.maximum(q.rho_l[j - 1], 0.0)) / m
    out["contact"] = q.eps - c.eps_min
    return {k: out[k] for k in LIMITS}


def admissible(p: PairSpec, c: ContourSpec, x1: np.ndarray | float, x2: np.ndarray | float
               ) -> np.ndarray:
    """True where every limit holds."""
    vals = limit_values(p, c, x1, x2)
    ok = np.ones(np.broadcast(np.asarray(x1), np.asarray(x2)).shape, dtype=bool)
    for v in vals.values():
        ok &= np.nan_to_num(v, nan=-1.0) >= 0
    return ok


@dataclass(frozen=True)
class Contour:
    """The blocking contour: per limit, the boundary points (x1, x2) in order of x1 (NaN rows
    separate branches); the admissible mask on the grid; the recommended shifts."""

    spec: ContourSpec
    x1: np.ndarray
    x2: np.ndarray
    lines: dict[str, np.ndarray]
    mask: np.ndarray
    balanced: np.ndarray
    recommended: tuple[float, float]
    rule: str                      # "balanced_max_eps" or "max_eps"
    eps: float


def _scan(f, x1: np.ndarray, x2: np.ndarray, iterations: int = 52
          ) -> list[list[tuple[float, float]]]:
    """For each x1, the points (x1, x2) where f changes sign along x2 (bisection, all brackets at
    once)."""
    X1, X2 = np.meshgrid(x1, x2, indexing="ij")
    v = f(X1, X2)
    s = np.sign(v)                 # NaN (no pair there) never brackets a root
    rows, cols = np.nonzero(s[:, :-1] * s[:, 1:] < 0)
    at = x1[rows]
    lo, hi, flo = x2[cols].copy(), x2[cols + 1].copy(), v[rows, cols]
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        fm = f(at, mid)
        same = np.sign(fm) == np.sign(flo)
        lo, hi, flo = np.where(same, mid, lo), np.where(same, hi, mid), np.where(same, fm, flo)
    root = 0.5 * (lo + hi)
    good = np.isfinite(f(at, root))
    pts: list[list[tuple[float, float]]] = [[] for _ in range(x1.size)]
    for i, r, ok in zip(rows.tolist(), root.tolist(), good.tolist()):
        if ok:
            pts[i].append((float(x1[i]), r))
    return pts


def _branches(pts: list[list[tuple[float, float]]], gap: float) -> np.ndarray:
    """Join the k-th root of consecutive columns into the k-th branch (NaN rows between); a jump
    longer than ``gap`` between neighbours breaks the branch (two lines, not one joined)."""
    width = max((len(r) for r in pts), default=0)
    nan = (math.nan, math.nan)
    out = []
    for k in range(width):
        b = np.asarray([r[k] if len(r) > k else nan for r in pts] + [nan])
        jump = np.hypot(*np.diff(b, axis=0).T) > gap
        keep = np.insert(b, np.flatnonzero(jump) + 1, nan, axis=0)
        out.append(keep)
    return np.vstack(out) if out else np.empty((0, 2))


def _roots(f, x1: np.ndarray, x2: np.ndarray) -> np.ndarray:
    """The zero line of f(x1, x2) as NaN-separated polylines: scanned along x2 for each x1 and
    along x1 for each x2, keeping the scan that finds more points (a steep line is found across)."""
    along2 = _scan(f, x1, x2)
    along1 = [[(b, a) for a, b in row] for row in _scan(lambda a, b: f(b, a), x2, x1)]
    n2, n1 = sum(map(len, along2)), sum(map(len, along1))
    gap = 3 * max(float(np.ptp(x1)) / max(x1.size - 1, 1), float(np.ptp(x2)) / max(x2.size - 1, 1))
    return _branches(along2 if n2 >= n1 else along1, gap)


def blocking_contour(p: PairSpec, c: ContourSpec | None = None,
                     x1_range: tuple[float, float] | None = None,
                     x2_range: tuple[float, float] | None = None, n: int = 121) -> Contour:
    """The contour of the pair on an (x1, x2) grid of n × n (ranges default to −1 … 1.5 around
    the undercut limits); raise :class:`SceneError` when no shift pair is admissible."""
    c = c or ContourSpec()
    lo1 = min(-1.0, p.addendum * (p.z_min - p.z1) / p.z_min - 0.5)
    lo2 = min(-1.0, p.addendum * (p.z_min - p.z2) / p.z_min - 0.5)
    x1 = np.linspace(*(x1_range or (lo1, 1.5)), n)
    x2 = np.linspace(*(x2_range or (lo2, 1.5)), n)
    lines = {name: _roots(lambda a, b, name=name: limit_values(p, c, a, b)[name], x1, x2)
             for name in LIMITS}
    return contour_on_grid(
        p, c, x1, x2, lines, lambda a, b: admissible(p, c, a, b), lambda a, b: pair_arrays(p, a, b),
        lambda best, balanced, unbalance: _refine_balanced(p, c, best, balanced, unbalance))


def contour_on_grid(p: PairSpec, c: ContourSpec, x1: np.ndarray, x2: np.ndarray,
                    lines: dict[str, np.ndarray],
                    admissible_at: Callable[[np.ndarray, np.ndarray], np.ndarray],
                    arrays_at: Callable[[np.ndarray, np.ndarray], Any],
                    refine: Callable[[tuple[float, float], np.ndarray,
                                      Callable[[np.ndarray, np.ndarray], np.ndarray]],
                                     tuple[float, float]] | None = None) -> Contour:
    """The contour on the (x1, x2) grid with its limit ``lines``: the admissible mask, the line
    of balanced specific sliding, and the chosen shifts — the admissible balanced point of the
    largest ε_α (moved by ``refine`` where given), else the admissible grid point of the largest
    ε_α; raise :class:`SceneError` when no shift pair is admissible."""
    X1, X2 = np.meshgrid(x1, x2, indexing="ij")
    mask = admissible_at(X1, X2)

    def unbalance(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        q = arrays_at(a, b)
        with np.errstate(invalid="ignore"):
            d = q.sliding[0] - q.sliding[1]
        return np.where(np.isfinite(d), d, np.nan)
    balanced = _roots(unbalance, x1, x2)
    pts = balanced[np.isfinite(balanced[:, 0])]
    if pts.size:
        ok = admissible_at(pts[:, 0], pts[:, 1])
        if ok.any():
            cand = pts[ok]
            eps = arrays_at(cand[:, 0], cand[:, 1]).eps
            k = int(np.nanargmax(eps))
            best = (float(cand[k, 0]), float(cand[k, 1]))
            best_eps = float(eps[k])
            if refine is not None:
                best = refine(best, balanced, unbalance)
                best_eps = float(arrays_at(np.asarray(best[0]), np.asarray(best[1])).eps)
            return Contour(c, x1, x2, lines, mask, balanced, best, "balanced_max_eps", best_eps)
    if not mask.any():
        raise SceneError(Text("contour.error.empty", {"z1": p.z1, "z2": p.z2,
                                                      "k": c.tip_land, "eps": c.eps_min}),
                         key="pair.shift_rule")
    eps_grid = np.where(mask, arrays_at(X1, X2).eps, -np.inf)
    i, j = np.unravel_index(int(np.argmax(eps_grid)), eps_grid.shape)
    return Contour(c, x1, x2, lines, mask, balanced, (float(x1[i]), float(x2[j])), "max_eps",
                   float(eps_grid[i, j]))


def _refine_balanced(p: PairSpec, c: ContourSpec, start: tuple[float, float],
                     pts: np.ndarray, unbalance: Callable[[np.ndarray, np.ndarray], np.ndarray]
                     ) -> tuple[float, float]:
    """Move the best admissible balanced point to where the balanced line leaves the contour:
    towards its neighbour on the line (``pts``, NaN-separated branches) of larger ε_α that is not
    admissible, bisecting (60 steps) with each trial point put back on the line by Brent's
    method along the segment's normal."""
    i = int(np.nanargmin(np.hypot(pts[:, 0] - start[0], pts[:, 1] - start[1])))
    eps0 = float(pair_arrays(p, *start).eps)
    best = start
    for j in (i - 1, i + 1):
        if not 0 <= j < len(pts) or not np.isfinite(pts[j, 0]):
            continue
        q = (float(pts[j, 0]), float(pts[j, 1]))
        if bool(admissible(p, c, *q)) or not float(pair_arrays(p, *q).eps) > eps0:
            continue
        d = np.subtract(q, start)
        step = float(np.hypot(*d))
        n = np.array([-d[1], d[0]]) / step

        def on_line(t: float, d: np.ndarray = d, n: np.ndarray = n, step: float = step
                    ) -> tuple[float, float] | None:
            m = np.asarray(start) + t * d

            def g(u: float) -> float:
                x = m + u * n
                return float(unbalance(np.array(x[0]), np.array(x[1])))
            try:
                u = brentq(g, -step, step, xtol=1e-15)
            except ValueError:
                return None
            x = m + u * n
            return float(x[0]), float(x[1])
        lo, hi = 0.0, 1.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            x = on_line(mid)
            if x is not None and bool(admissible(p, c, *x)):
                lo = mid
            else:
                hi = mid
        x = on_line(lo)
        if x is not None and bool(admissible(p, c, *x)) and \
                float(pair_arrays(p, *x).eps) > float(pair_arrays(p, *best).eps):
            best = x
    return best


@dataclass(frozen=True)
class Sliding:
    """Specific sliding along N1N2: distance from N1 (m), η1, η2 (−inf at N1 for η1, at N2 for
    η2), the ends of the active part B1, B2 (distances from N1) and the length g = N1N2."""

    u: np.ndarray
    eta1: np.ndarray
    eta2: np.ndarray
    b1: float
    b2: float
    g: float


def specific_sliding(p: PairSpec, x1: float, x2: float, n: int = 101) -> Sliding:
    """η1 = 1 − (z1/z2)(g − u)/u, η2 = 1 − (z2/z1)·u/(g − u) at n points of N1N2 (ends included)."""
    q = pair_arrays(p, x1, x2)
    g = float(q.g)
    u = np.linspace(0.0, g, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        eta1 = np.where(u > 0, 1 - (p.z1 / p.z2) * (g - u) / np.where(u > 0, u, 1.0), -np.inf)
        eta2 = np.where(u < g, 1 - (p.z2 / p.z1) * u / np.where(u < g, g - u, 1.0), -np.inf)
    return Sliding(u, eta1, eta2, float(q.rho_p[0]), g - float(q.rho_p[1]), g)
