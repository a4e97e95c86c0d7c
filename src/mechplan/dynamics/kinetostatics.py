"""Results of the force plan, vectorised over positions: JSON-ready dicts and a text summary.

Build the construction with the ``"force"`` plan and a :class:`~mechplan.dynamics.loading.Loading`,
evaluate it at the positions wanted, then :func:`analyse_forces` gathers every reaction, the
balancing moment (group by group and by Zhukovsky's lever) and the reduced moment and inertia.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation, reaction_key
from ..geom.vec import Array, cross, norm, perp
from ..model.mechanism import Mechanism, PairKind
from .friction import FrictionAnalysis, analyse_friction
from .reduced import link_omega, reduced_of


@dataclass(frozen=True, slots=True)
class Reaction:
    """R_ij, the force of link i on link j at their pair, over N positions.

    Prismatic pairs: ``guide`` names the guide and ``offset`` (N,) is where the line of action
    crosses the guide, in metres along the guide from the pair's point ``point`` (NaN where the
    force is zero and the reaction is a pure couple).
    """

    key: str
    i: str
    j: str
    point: str
    force: Array
    guide: str | None = None
    offset: Array | None = None


@dataclass(frozen=True, slots=True)
class ForceAnalysis:
    """Kinetostatics of a mechanism at N positions (SI units, moments counter-clockwise +)."""

    phi: Array                                  # (N,) crank angle, scene convention, rad
    omega1: Array                               # (N,) angular velocity of the driving link
    inertia: dict[str, tuple[Array, Array]]     # link → (Q (N, 2), M_q (N,))
    reactions: dict[str, Reaction]              # revolute pairs, key "ij" (i before j)
    guide_reactions: dict[str, Reaction]        # prismatic pairs
    balancing_moment: Array                     # (N,) from the force polygons
    zhukovsky_moment: Array                     # (N,) from Zhukovsky's lever
    reduced_moment: Array                       # (N,)
    reduced_inertia: Array                      # (N,)
    friction: FrictionAnalysis | None = None    # with [friction]: M_b⁰, η, the iteration
    #: a linear driver (cylinder, slider): the two "moments" are its driving force F_d (N) by the
    #: polygons and by Zhukovsky's lever, omega1 its rate q̇ (m/s), the reduced ones a force
    #: (N) and a mass (kg)
    linear: bool = False
    #: a second driver (W = 2): its link and its balancing moment M_b (N·m) from its own
    #: polygon, or (``second_linear``) a second cylinder's driving force F_d (N);
    #: ``balancing_moment`` is the first driver's
    second: tuple[str, Array] | None = None
    second_linear: bool = False

    @property
    def difference_percent(self) -> Array:
        """(M_b − M_b,Zhukovsky)/max(|M_b|, |M_b,Zhukovsky|)·100 (0 where both vanish)."""
        a, b = self.balancing_moment, self.zhukovsky_moment
        scale = np.maximum(np.abs(a), np.abs(b))
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(scale > 0, (a - b) / np.where(scale > 0, scale, 1.0) * 100.0, 0.0)

    def driving(self, i: int) -> bool:
        """True if the balancing moment drives (M_b·ω1 > 0) at position i."""
        return bool(self.balancing_moment[i] * self.omega1[i] > 0)

    def json(self, i: int) -> dict[str, Any]:
        """The ``forces`` and ``reduced`` entries of position i, ready for ``json.dumps``."""
        return {
            "forces": {
                "inertia": {link: {"force": _vec(q[i]), "moment": _num(m[i])}
                            for link, (q, m) in self.inertia.items()},
                "reactions": {k: _vec(r.force[i]) for k, r in self.reactions.items()},
                "guide_reactions": {
                    k: {"force": _vec(r.force[i]),
                        "offset": _num(r.offset[i]) if r.offset is not None else None}
                    for k, r in self.guide_reactions.items()},
                **({"driving_force": _num(self.balancing_moment[i]),
                    "zhukovsky_driving_force": _num(self.zhukovsky_moment[i])} if self.linear
                   else {"balancing_moment": _num(self.balancing_moment[i]),
                         "zhukovsky_balancing_moment": _num(self.zhukovsky_moment[i])}),
                **({} if self.second is None else {
                    "second_driving_force" if self.second_linear else "second_balancing_moment": {
                        "link": self.second[0], "value": _num(self.second[1][i])}}),
            },
            "reduced": {"moment": _num(self.reduced_moment[i]),
                        "inertia": _num(self.reduced_inertia[i])},
        } | ({} if self.friction is None else {"friction": self.friction.json(i)})


def _num(x: Any) -> float | None:
    x = float(x)
    if not math.isfinite(x):
        return None
    return x + 0.0    # no negative zero in the output


def _vec(v: Array) -> list[float | None]:
    return [_num(v[0]), _num(v[1])]


def _order(mech: Mechanism) -> dict[str, int]:
    return {link: n for n, link in enumerate(mech.links)}


def analyse_forces(c: Construction, ev: Evaluation, mech: Mechanism, loading: Any) -> ForceAnalysis:
    """Gather the force plan's results at the evaluated positions (one vectorised pass)."""
    order = _order(mech)
    inertia: dict[str, tuple[Array, Array]] = {}
    zero_v, zero_s = np.zeros((ev.n, 2)), np.zeros(ev.n)
    for link, ms in loading.masses.items():
        if ms.mass > 0 or ms.inertia > 0:
            q_id, m_id = c.inertia_force(link), c.inertia_couple(link)
            q = ev[q_id] if q_id is not None else zero_v
            m = ev[m_id] if m_id is not None else zero_s
            inertia[link] = (q, m)
    reactions: dict[str, Reaction] = {}
    guides: dict[str, Reaction] = {}
    for pair in mech.pairs:
        i, j = sorted((pair.a, pair.b), key=order.__getitem__)
        key = reaction_key(i, j)
        force = ev[c.reaction(i, j)]
        if pair.kind is PairKind.REVOLUTE:
            reactions[key] = Reaction(key, i, j, pair.point, force)
        else:
            guides[key] = Reaction(key, i, j, pair.point, force, pair.guide,
                                   ev[c.guide_offset(i, j)])
    reactions = dict(sorted(reactions.items(), key=lambda kv: (order[kv[1].i], order[kv[1].j])))
    guides = dict(sorted(guides.items(), key=lambda kv: (order[kv[1].i], order[kv[1].j])))
    m_red, j_red = reduced_of(c, ev, mech, loading)
    second, second_linear = None, False
    if mech.drive2 is not None:     # W = 2: the second driver's own M_b or F_d
        link2, second_linear = mech.drive2.link, mech.drive2.linear
        second = (link2, ev[c.second_driving_force(link2) if second_linear
                            else c.second_balancing_moment(link2)])
    if mech.drive.linear:       # the driving force of a cylinder or slider
        return ForceAnalysis(
            phi=ev.phi, omega1=ev["vel.rate"], inertia=inertia, reactions=reactions,
            guide_reactions=guides, balancing_moment=ev[c.driving_force()],
            zhukovsky_moment=ev[c.zhukovsky_force()], reduced_moment=m_red,
            reduced_inertia=j_red, linear=True, friction=analyse_friction(c, ev, mech),
            second=second, second_linear=second_linear)
    return ForceAnalysis(
        phi=ev.phi, omega1=link_omega(c, ev, mech.drive.link), inertia=inertia,
        reactions=reactions, guide_reactions=guides,
        balancing_moment=ev[c.balancing_moment()], zhukovsky_moment=ev[c.zhukovsky_moment()],
        reduced_moment=m_red, reduced_inertia=j_red, friction=analyse_friction(c, ev, mech),
        second=second, second_linear=second_linear)


def balancing_force(c: Construction, ev: Evaluation, mech: Mechanism, point: str,
                    angle: float | None = None) -> Array:
    """The balancing force (N, 2) at a point of the driving link, equivalent to M_b.

    Its line of action is ⊥ to the crank line from the pivot to ``point`` (the textbook case,
    F_b = M_b/l) or, given ``angle`` (rad, counter-clockwise from +x), along that fixed direction;
    NaN where that line passes through the pivot.
    """
    drive = mech.drive
    if point not in mech.links[drive.link].points or point == drive.pivot:
        raise ValueError(f"point {point!r} is not a point of the driving link {drive.link} other "
                         f"than its pivot {drive.pivot}")
    r = ev[c.position(point)] - ev[c.position(drive.pivot)]
    if angle is None:
        d = perp(r) / norm(r)[:, None]
    else:
        d = np.broadcast_to(np.array([math.cos(angle), math.sin(angle)]), r.shape)
    with np.errstate(invalid="ignore", divide="ignore"):
        magnitude = ev[c.balancing_moment()] / cross(r, d)
    return magnitude[:, None] * d


__all__ = ["ForceAnalysis", "Reaction", "analyse_forces", "balancing_force"]
