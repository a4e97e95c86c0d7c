"""Extreme (dead-centre) positions of output sliders and rockers, found exactly by bisection."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..i18n import Text
from ..model.mechanism import GROUND, Mechanism
from .graph import Construction

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, slots=True)
class ExtremePosition:
    """An extreme position: crank angle φ (rad), the subject's coordinate or angle, max/min."""

    subject: str
    phi: float
    value: float
    which: str


RateFunction = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


def _rate_and_value(c: Construction, mech: Mechanism, subject: str) -> RateFunction:
    """Return f(φ) → (rate, value): v along the guide and coordinate, or ω and link angle."""
    if subject in mech.links:
        omega_id, angle_id = c.results.get(f"omega_{subject}"), c.results.get(f"angle_{subject}")
        if omega_id is None or angle_id is None:
            raise SceneError(Text("errmsg2.extremes.no_omega", {"link": subject}))

        def link_rate(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            ev = c.evaluate(phi)
            return ev[omega_id], ev[angle_id]
        return link_rate
    owner = next((k for k, lk in mech.links.items() if subject in lk.points and lk.slides_on
                  and mech.guides[lk.slides_on].link == GROUND), None)
    if owner is None:
        raise SceneError(Text("errmsg2.extremes.not_slider", {"point": subject}))
    g = mech.guides[mech.links[owner].slides_on]  # type: ignore[index]
    d = np.array([math.cos(g.angle), math.sin(g.angle)])
    o = np.array(g.origin)
    vid, pid = c.results[f"v_{subject}"], f"pos.{subject}"

    def slider_rate(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ev = c.evaluate(phi)
        return ev[vid] @ d, (ev[pid] - o) @ d
    return slider_rate


def extreme_positions(c: Construction, mech: Mechanism, subject: str, samples: int = 720,
                      iterations: int = 64) -> list[ExtremePosition]:
    """All crank angles where the subject's rate vanishes with a sign change (max and min)."""
    f = _rate_and_value(c, mech, subject)
    # half-step offset: a root exactly on a round angle (φ = 0) falls inside a bracket
    phi = (np.arange(samples + 1) - 0.5) * (TWO_PI / samples)
    rate, _ = f(phi)
    sign = np.sign(rate)
    idx = np.nonzero((sign[:-1] * sign[1:] < 0) | ((sign[:-1] != 0) & (sign[1:] == 0)))[0]
    lo, hi = phi[idx], phi[idx + 1]
    r_lo = rate[idx]
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        r_mid, _ = f(mid)
        same = np.sign(r_mid) == np.sign(r_lo)
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
        r_lo = np.where(same, r_mid, r_lo)
    roots = np.mod(0.5 * (lo + hi), TWO_PI)
    rate_before = rate[idx]
    _, values = f(roots)
    out = []
    for phi_k, v, rb in zip(roots, values, rate_before):
        # φ grows with time in the sense of rotation, so rate > 0 before the root is a maximum
        out.append(ExtremePosition(subject, float(phi_k), float(v), "max" if rb > 0 else "min"))
    seen: list[ExtremePosition] = []
    for e in sorted(out, key=lambda e: e.phi):
        if not any(abs(e.phi - s.phi) < 1e-9 for s in seen):
            seen.append(e)
    return seen
