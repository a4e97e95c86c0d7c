"""Relative motion at every pair and between the points of a link.

Prismatic pair (slider ``a`` on the guide of link ``b`` at point P): the sliding velocity
v_rel = v_P(a) − v_P(b), along the guide; the Coriolis acceleration a_k = 2 ω_b × v_rel; the
relative (sliding) acceleration a_rel = a_P(a) − a_P(b) − a_k, along the guide. Two points P, Q
of one link: v_PQ = v_P − v_Q = ω × QP; a_PQ = a_P − a_Q = a^n_PQ + a^t_PQ with
a^n_PQ = −ω²·QP (from P towards Q, ω²·l) and a^t_PQ = ε × QP (⊥ PQ, |ε|·l).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...model.mechanism import GROUND, Mechanism, Pair, PairKind
from ..graph import Construction, Evaluation
from .motion import Array, cross_k, guide_direction, motion, point


@dataclass(frozen=True, slots=True)
class Sliding:
    """Relative motion in a prismatic pair; scalars are signed along the guide's direction."""

    pair: Pair
    guide_link: str                 # the link carrying the guide (its ω makes the Coriolis part)
    direction: Array                # (N, 2) unit vector of the guide
    v_rel: Array                    # (N, 2)
    v_slide: Array                  # (N,)
    omega_guide: Array              # (N,)
    a_cor: Array | None = None      # (N, 2)
    a_rel: Array | None = None      # (N, 2)
    a_slide: Array | None = None    # (N,)


@dataclass(frozen=True, slots=True)
class PointPair:
    """Motion of point ``p`` relative to point ``q`` of the same link (vectors (N, 2))."""

    link: str
    p: str
    q: str
    length: float
    v: Array
    a: Array | None = None
    a_n: Array | None = None
    a_t: Array | None = None


def sliding(c: Construction, ev: Evaluation, mech: Mechanism, pair: Pair,
            accelerations: bool = True) -> Sliding:
    """The relative motion of the slider in prismatic ``pair``."""
    assert pair.kind is PairKind.PRISMATIC and pair.guide is not None
    guide_link = mech.guides[pair.guide].link
    slider_link = pair.a if guide_link == pair.b else pair.b
    mb = motion(c, ev, mech, guide_link, accelerations)
    ma = motion(c, ev, mech, slider_link, accelerations)
    rp = ev[c.position(pair.point)]
    d = guide_direction(c, ev, mech, pair.guide)
    v_rel = ma.velocity_at(rp) - mb.velocity_at(rp)
    out = Sliding(pair, guide_link, d, v_rel, np.einsum("ij,ij->i", v_rel, d), mb.omega)
    aa, ab = ma.acceleration_at(rp), mb.acceleration_at(rp)
    if aa is None or ab is None:
        return out
    a_cor = 2.0 * cross_k(mb.omega, v_rel)
    a_rel = aa - ab - a_cor
    return Sliding(pair, guide_link, d, v_rel, out.v_slide, mb.omega, a_cor, a_rel,
                   np.einsum("ij,ij->i", a_rel, d))


def point_pairs(c: Construction, ev: Evaluation, mech: Mechanism,
                only: tuple[str, ...] = ()) -> list[PointPair]:
    """Every pair of named points of each moving link (later point relative to the earlier)."""
    out = []
    for lid in mech.moving:
        lk = mech.links[lid]
        names = [p for p in lk.points if c.has_position(p) and c.has_result("v", p)
                 and (not only or p in only)]
        if len(names) < 2:
            continue
        m = motion(c, ev, mech, lid)
        for i, q in enumerate(names):
            for p in names[i + 1:]:
                rq, rp = ev[c.position(q)], ev[c.position(p)]
                rho = rp - rq
                v = point(c, ev, p, "v") - point(c, ev, q, "v")     # type: ignore[operator]
                ap, aq = point(c, ev, p, "a"), point(c, ev, q, "a")
                if ap is None or aq is None or m.epsilon is None:
                    out.append(PointPair(lid, p, q, lk.distance(p, q), v))
                    continue
                out.append(PointPair(lid, p, q, lk.distance(p, q), v, ap - aq,
                                     -(m.omega ** 2)[:, None] * rho, cross_k(m.epsilon, rho)))
    return out


def prismatic_pairs(mech: Mechanism) -> list[Pair]:
    """The prismatic pairs in scene order."""
    return [p for p in mech.pairs if p.kind is PairKind.PRISMATIC]


def revolute_pairs(mech: Mechanism) -> list[Pair]:
    """The revolute pairs in scene order."""
    return [p for p in mech.pairs if p.kind is PairKind.REVOLUTE]


@dataclass(frozen=True, slots=True)
class Turning:
    """Relative rotation in a revolute pair: ω_a − ω_b and ε_a − ε_b (N,) (links a, b)."""

    pair: Pair
    omega_rel: Array
    epsilon_rel: Array | None


def turning(c: Construction, ev: Evaluation, mech: Mechanism, pair: Pair,
            accelerations: bool = True) -> Turning:
    """The relative rotation of the links of revolute ``pair``."""
    ma, mb = (motion(c, ev, mech, lk, accelerations) for lk in (pair.a, pair.b))
    eps = (ma.epsilon - mb.epsilon if ma.epsilon is not None and mb.epsilon is not None
           else None)
    return Turning(pair, ma.omega - mb.omega, eps)


def rubbing(c: Construction, ev: Evaluation, mech: Mechanism, pair: Pair,
            radius: float) -> tuple[Array, Array]:
    """Relative angular velocity ω_a − ω_b (N,) and rubbing velocity |ω_a − ω_b|·r (N,) (m/s)."""
    wa = motion(c, ev, mech, pair.a, False).omega if pair.a != GROUND else np.zeros(ev.n)
    wb = motion(c, ev, mech, pair.b, False).omega if pair.b != GROUND else np.zeros(ev.n)
    dw = wa - wb
    return dw, np.abs(dw) * radius
