"""An oscillating flat-faced follower: the face is a straight line through the pivot A = (a, 0).

In the σ = +1 frame the face leaves A in the direction d = (−cos δ, sin δ), δ = δ0 + ψ, and O
sees it at the distance p = a·sin δ along its normal n = (sin δ, cos δ); at the near position it
touches the base circle, so sin δ0 = r0/a. Turned by −φ onto the cam, the face is the line
n_c·x = p with n_c at the polar angle β = π/2 − δ − φ; the profile is its envelope, the point
p·n_c + (dp/dβ)·t_c (t_c = dn_c/dβ), with the radius of curvature ρ = p + d²p/dβ². With
ψ′ = dψ/dφ, ψ″: dβ/dφ = −(1 + ψ′), dp/dβ = −a·cos δ·ψ′/(1 + ψ′) and
ρ = a·sin δ + a·(cos δ·ψ″ − sin δ·ψ′²·(1 + ψ′))/(1 + ψ′)³.
The contact point lies on the face at L = a·cos δ/(1 + ψ′) from the pivot; its velocity on the
follower is along the normal, so the pressure angle is zero. An envelope needs 1 + ψ′ > 0 (the
face turns one way on the cam) and a convex profile ρ > 0.
"""

from __future__ import annotations

import math

import numpy as np


def flat_oscillating(r0: float, pivot: float, s: np.ndarray, s1: np.ndarray, s2: np.ndarray,
                     phi: np.ndarray) -> dict[str, np.ndarray]:
    """Contact point (fixed and cam frame), outward normal (cam frame), ρ and L, σ = +1."""
    a = pivot
    delta = math.asin(r0 / a) + s
    sd, cd = np.sin(delta), np.cos(delta)
    k = 1.0 + s1
    p = a * sd
    q = -a * cd * s1 / k                              # dp/dβ
    n = np.stack([sd, cd], axis=1)                    # fixed frame
    d = np.stack([-cd, sd], axis=1)                   # = dn/dβ in the fixed frame
    contact = p[:, None] * n + q[:, None] * d
    c, sn = np.cos(-phi), np.sin(-phi)

    def rot(v: np.ndarray) -> np.ndarray:
        return np.stack([c * v[:, 0] - sn * v[:, 1], sn * v[:, 0] + c * v[:, 1]], axis=1)

    rho = a * sd + a * (cd * s2 - sd * s1 ** 2 * k) / k ** 3
    return {"contact": contact, "profile": rot(contact), "normal": rot(n), "radius": rho,
            "along": a * cd / k, "direction": d}


def least_r0(pivot: float, s: np.ndarray, s1: np.ndarray, s2: np.ndarray, rho_min: float
             ) -> float | None:
    """The least r0 < a with ρ ≥ ρ_min everywhere (None: no r0 below the pivot distance)."""
    phi = np.zeros_like(s)

    def margin(r0: float) -> float:
        return float(np.min(flat_oscillating(r0, pivot, s, s1, s2, phi)["radius"])) - rho_min

    grid = np.linspace(1e-4, 0.999, 400) * pivot
    ok = [r for r in grid if margin(r) >= 0]
    if not ok:
        return None
    hi = ok[0]
    j = int(np.searchsorted(grid, hi))
    if j == 0:
        return float(hi)
    lo = float(grid[j - 1])
    while hi - lo > 1e-12 * pivot:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if margin(mid) >= 0 else (mid, hi)
    return float(hi)
