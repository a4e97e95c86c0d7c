"""The transmission angle of a class II group, and its least value over the cycle.

The force enters a group through its first outer pair (the pair with the link known first) and
reaches the second link L2 through the inner pair. Neglecting friction, gravity and inertia, the
first link L1 carries only its two pair reactions, so the force line is known from the kinds of
L1's pairs: R–R along the line joining the two pins; R–P or P–R ⊥ the guide of the prismatic
pair. The point of L2 at the inner pair moves ⊥ the line from the second outer pin (outer R) or
along the second outer guide (outer P). The pressure angle α is the acute angle between the force
line and that velocity; the transmission angle is γ = 90° − α (0° … 90°; 0° is a dead point).
For an RRR group the angle between the two links at the inner pin, μ (0° … 180°), is also given:
γ = min(μ, 180° − μ). A group whose first link has two prismatic pairs has no force line: NaN.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...model.mechanism import Mechanism, Pair, PairKind
from ...model.structure import Group
from ..graph import Construction, Evaluation
from .motion import Array, guide_direction

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, slots=True)
class Transmission:
    """γ (N,) in radians, and μ (N,) the angle between the links at the inner pin (RRR only)."""

    group: Group
    gamma: Array
    mu: Array | None


def _perp(d: Array) -> Array:
    return np.stack([-d[:, 1], d[:, 0]], axis=1)


def _point_of(pair: Pair) -> str:
    return pair.point


def transmission(c: Construction, ev: Evaluation, mech: Mechanism, g: Group) -> Transmission:
    """The transmission angle of group ``g`` at the evaluation's positions."""
    o1, inner, o2 = g.outer1, g.inner, g.outer2
    r_in = ev[c.position(_point_of(inner))]
    nan = np.full((ev.n, 2), math.nan)
    if o1.kind is PairKind.REVOLUTE and inner.kind is PairKind.REVOLUTE:
        force = r_in - ev[c.position(o1.point)]
    elif o1.kind is PairKind.REVOLUTE:
        force = _perp(guide_direction(c, ev, mech, inner.guide))    # type: ignore[arg-type]
    elif inner.kind is PairKind.REVOLUTE:
        force = _perp(guide_direction(c, ev, mech, o1.guide))       # type: ignore[arg-type]
    else:
        force = nan
    if o2.kind is PairKind.REVOLUTE:
        velocity = _perp(r_in - ev[c.position(o2.point)])
    else:
        velocity = guide_direction(c, ev, mech, o2.guide)           # type: ignore[arg-type]
    # α from atan2(|f×u|, |f·u|): exact near 0° and 90°, where arccos of a cosine is not
    cross = force[:, 0] * velocity[:, 1] - force[:, 1] * velocity[:, 0]
    dot = np.einsum("ij,ij->i", force, velocity)
    gamma = 0.5 * math.pi - np.arctan2(np.abs(cross), np.abs(dot))
    gamma = np.where(np.hypot(*force.T) * np.hypot(*velocity.T) > 0, gamma, math.nan)
    mu = None
    if g.kind.value == "RRR":
        u = ev[c.position(o1.point)] - r_in
        w = ev[c.position(o2.point)] - r_in
        mu = np.abs(np.arctan2(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0],
                               np.einsum("ij,ij->i", u, w)))
    return Transmission(g, gamma, mu)


def least_transmission(c: Construction, mech: Mechanism, g: Group, samples: int = 720,
                       iterations: int = 80) -> tuple[float, float] | None:
    """(φ, γ_min) over a crank turn: the least sample refined by golden-section search on the
    bracket around it (γ may have a corner at a dead point; the search needs no derivative).
    φ is NaN when γ is the same at every position (a centred coulisse: 90°); None when no
    position can be built."""
    phi = np.arange(samples) * (TWO_PI / samples)

    def gamma(x: Array) -> Array:
        val = transmission(c, c.evaluate(x), mech, g).gamma
        return np.where(np.isfinite(val), val, np.inf)

    values = gamma(phi)
    if not np.isfinite(values).any():
        return None
    finite = values[np.isfinite(values)]
    if float(np.ptp(finite)) < 1e-9:
        return math.nan, float(finite.min())
    k = int(np.argmin(values))
    step = TWO_PI / samples
    lo, hi = phi[k] - step, phi[k] + step
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
    f1, f2 = gamma(np.array([x1, x2]))
    for _ in range(iterations):
        if f1 <= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - ratio * (hi - lo)
            f1 = float(gamma(np.array([x1]))[0])
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + ratio * (hi - lo)
            f2 = float(gamma(np.array([x2]))[0])
    x = 0.5 * (lo + hi)
    best = float(gamma(np.array([x]))[0])
    if best > values[k]:
        x, best = float(phi[k]), float(values[k])
    return float(np.mod(x, TWO_PI)), best
