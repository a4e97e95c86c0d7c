"""Minimum base radius from the allowable pressure angles (and the best offset), exactly.

Translating follower (the courses' s′–s diagram): the follower's axis is the s axis, s′ is laid off
across it in the sense of rotation, and the cam centre O = (e, −s0) of that diagram sees every point
(s′, s) under a pressure angle tan α = (s′ − e)/(s + s0). |α| ≤ L is, for each point, two
half-planes x − y·tan L ≥ s′ − s·tan L and −x − y·tan L ≥ −s′ − s·tan L; only the largest right-hand
side of each family matters, so the admissible zone is the intersection of at most six half-planes
(a convex region bounded by the rays at the allowable angles through the critical points) and the
minimum r0 is the point of that region nearest the origin. Oscillating follower: the least r0 whose
exact pressure angles keep within the limits, by bisection on r0 for the given pivot distance and
arm. Flat-faced follower: the least r0 with ρ = r0 + s + s″ ≥ ρ_min.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...model.cam import Phase, PhaseKind
from .motion import Motion as MotionValues
from .motion import motion, phase_of
from .profile import Geometry, pressure_angle


@dataclass(frozen=True)
class HalfPlane:
    """n·(x, y) ≥ c in the s′–s diagram; ``at`` is the critical point (s′, s) it passes through."""

    n: tuple[float, float]
    c: float
    at: tuple[float, float]
    limit: float


@dataclass(frozen=True)
class Zone:
    """The admissible zone of the cam centre and the nearest point to the origin."""

    planes: tuple[HalfPlane, ...]
    centre: tuple[float, float]      # (e, −s0) chosen
    r0: float
    e: float


def limit_per_angle(phases: tuple[Phase, ...], phi: np.ndarray, alpha_rise: float,
                    alpha_return: float) -> np.ndarray:
    """The allowable pressure angle at each cam angle (a dwell takes the larger of the two)."""
    kinds = [p.kind for p in phases]
    idx = phase_of(phases, phi)
    lim = np.empty(phi.size)
    for i, k in enumerate(kinds):
        value = {PhaseKind.RISE: alpha_rise, PhaseKind.RETURN: alpha_return}.get(
            k, max(alpha_rise, alpha_return))
        lim[idx == i] = value
    return lim


def half_planes(s: np.ndarray, s1: np.ndarray, limit: np.ndarray) -> tuple[HalfPlane, ...]:
    """The binding half-planes of every distinct allowable angle."""
    out: list[HalfPlane] = []
    for L in np.unique(limit):
        m = limit == L
        t = math.tan(float(L))
        for sign in (1.0, -1.0):
            rhs = sign * s1[m] - t * s[m]
            j = int(np.argmax(rhs))
            out.append(HalfPlane((sign, -t), float(rhs[j]), (float(s1[m][j]), float(s[m][j])),
                                 float(L)))
    return tuple(out)


def _feasible(planes: tuple[HalfPlane, ...], x: float, y: float) -> bool:
    return all(p.n[0] * x + p.n[1] * y >= p.c - 1e-12 * (1 + abs(p.c)) for p in planes)


def nearest(planes: tuple[HalfPlane, ...]) -> tuple[float, float]:
    """The point of the intersection of the half-planes nearest the origin."""
    cands: list[tuple[float, float]] = [(0.0, 0.0)]
    for p in planes:
        k = p.c / (p.n[0] ** 2 + p.n[1] ** 2)
        cands.append((k * p.n[0], k * p.n[1]))
    for i, p in enumerate(planes):
        for q in planes[i + 1:]:
            det = p.n[0] * q.n[1] - p.n[1] * q.n[0]
            if abs(det) > 1e-15:
                cands.append(((p.c * q.n[1] - q.c * p.n[1]) / det,
                              (p.n[0] * q.c - q.n[0] * p.c) / det))
    ok = [c for c in cands if _feasible(planes, *c)]
    return min(ok, key=lambda c: math.hypot(*c))


def translating_zone(s: np.ndarray, s1: np.ndarray, limit: np.ndarray,
                     offset: float | None) -> Zone:
    """Minimum r0 of a translating follower; ``offset`` None chooses the best offset too."""
    planes = half_planes(s, s1, limit)
    if offset is None:
        x, y = nearest(planes)
    else:
        x = offset
        y = min((p.c - p.n[0] * x) / p.n[1] for p in planes)  # n_y = −tan L < 0
    y = min(y, 0.0)
    return Zone(planes, (x, y), math.hypot(x, y), x)


def max_ratio(g: Geometry, phi: np.ndarray, limit: np.ndarray,
              m: MotionValues | None = None) -> float:
    """max |α|/L over the cam angles (≤ 1 meets every limit); ``m`` is the motion at ``phi``."""
    m = m if m is not None else motion(g.phases, g.stroke, phi)
    return float(np.max(np.abs(pressure_angle(g, m.s, m.s1, m.s2)) / limit))


def oscillating_r0(g: Geometry, phi: np.ndarray, limit: np.ndarray) -> float | None:
    """Least pitch base radius meeting the limits for the given pivot and arm (None: none does)."""
    a, l = g.pivot, g.arm
    lo = abs(a - l) * (1 + 1e-9) + 1e-9
    hi = (a + l) * (1 - 1e-9)
    ok_gamma = g.stroke
    m = motion(g.phases, g.stroke, phi)

    def good(r0: float) -> bool:
        trial = _with_r0(g, r0)
        if trial.gamma0 + ok_gamma >= math.pi:
            return False
        return max_ratio(trial, phi, limit, m) <= 1.0

    grid = np.linspace(lo, hi, 80)
    first = next((r for r in grid if good(float(r))), None)
    if first is None:
        return None
    lo_r = float(grid[max(0, int(np.searchsorted(grid, first)) - 1)])
    hi_r = float(first)
    if good(lo_r):
        return lo_r
    while hi_r - lo_r > 1e-10 * hi_r:
        mid = 0.5 * (lo_r + hi_r)
        lo_r, hi_r = (lo_r, mid) if good(mid) else (mid, hi_r)
    return hi_r


def _with_r0(g: Geometry, r0: float) -> Geometry:
    return Geometry(g.phases, g.stroke, g.sense, g.motion, g.contact, r0, g.e, g.roller, g.arm,
                    g.pivot)


def flat_r0(s: np.ndarray, s2: np.ndarray, rho_min: float) -> float:
    """Least base radius of a flat-faced follower's cam with ρ = r0 + s + s″ ≥ ρ_min."""
    return float(np.max(rho_min - s - s2))


__all__ = ["HalfPlane", "Zone", "flat_r0", "half_planes", "limit_per_angle",
           "max_ratio", "nearest", "oscillating_r0", "translating_zone"]
