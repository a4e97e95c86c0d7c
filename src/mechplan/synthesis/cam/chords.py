"""Points of the working profile whose chords stay within a given distance of the exact curve.

The chord of length c on an arc of radius ρ departs from it by ρ − √(ρ² − c²/4) ≈ c²/(8ρ), so the
local chord may be √(8·|ρ|·δ) long. The cam angles are placed by the cumulative count of such chords
along the curve, then every chord is measured against the exact curve at intermediate angles and
split where it still departs by more than δ.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .profile import Geometry, sample


def chord_deviation(curve: Callable[[np.ndarray], np.ndarray], phi: np.ndarray,
                    inner: int = 16) -> np.ndarray:
    """Largest distance from the exact curve to each chord phi[i] → phi[i+1] (probed ``inner``
    times)."""
    pts = curve(phi)
    a, b = pts[:-1], pts[1:]
    t = (np.arange(1, inner + 1) / (inner + 1))
    probe_phi = phi[:-1, None] + (phi[1:] - phi[:-1])[:, None] * t[None, :]
    q = curve(probe_phi.ravel()).reshape(probe_phi.shape + (2,))
    ab = b - a
    length = np.hypot(ab[:, 0], ab[:, 1])
    rel = q - a[:, None, :]
    cross = np.abs(ab[:, None, 0] * rel[..., 1] - ab[:, None, 1] * rel[..., 0])
    return np.max(cross / length[:, None], axis=1)


def profile_angles(g: Geometry, tol: float, dense: int = 36000) -> tuple[np.ndarray, float]:
    """Cam angles (one turn, the first not repeated) of a closed polyline within ``tol`` of the
    profile.

    Return the angles and the largest chord deviation measured.
    """
    def curve(phi: np.ndarray) -> np.ndarray:
        return sample(g, phi).profile

    phi = np.linspace(0.0, 2 * math.pi, dense + 1)
    smp = sample(g, phi)
    pts = smp.profile
    arc = np.hypot(*np.diff(pts, axis=0).T)
    rho = np.abs(0.5 * (smp.radius[1:] + smp.radius[:-1]))
    rho = np.where(np.isfinite(rho), rho, 1e9)
    allowed = 0.8 * np.sqrt(8.0 * np.maximum(rho, 1e-12) * tol)
    count = np.concatenate([[0.0], np.cumsum(arc / allowed)])
    n = max(16, math.ceil(count[-1]))
    chosen = np.interp(np.linspace(0.0, count[-1], n + 1), count, phi)
    for _ in range(20):
        dev = chord_deviation(curve, chosen)
        bad = np.flatnonzero(dev > tol)
        if bad.size == 0:
            return chosen[:-1], float(dev.max())
        mids = 0.5 * (chosen[bad] + chosen[bad + 1])
        chosen = np.sort(np.concatenate([chosen, mids]))
    dev = chord_deviation(curve, chosen)
    return chosen[:-1], float(dev.max())
