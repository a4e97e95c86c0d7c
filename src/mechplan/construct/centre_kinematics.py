"""What the instant centres give: velocities (a second method), centrodes, poles, inflection circle.

Velocities by instant centres. The driver d turns about its frame pivot I_0d with ω_d. For a
link j, I_dj is the point where links d and j have the same velocity, so

    ω_j · (I_dj − I_0j) = ω_d · (I_dj − I_0d)  →  ω_j = ω_d · I_0d I_dj / I_0j I_dj

(signed distances along the line of the three centres, which Kennedy's theorem puts in line), and
a point X of link j moves with v_X = ω_j · |I_0j X| at right angles to I_0j X. In homogeneous form
(``ops/centres.py``) a link's motion is the vector t = (perp(v_O)/L, ω) — proportional to its
absolute centre — and the relation reads t_j = μ·I_0j with t_j − t_m ∥ I_mj for any link m of
known motion: μ = ((t_m × I_mj) · (I_0j × I_mj)) / |I_0j × I_mj|². One formula for every case:
a link that translates (I_0j at infinity, ω_j = 0) or a relative centre at infinity (ω_j = ω_m).

Acceleration pole Q of a link (the point of zero acceleration) from a point A with a_A, and ω, ε:

    Q = A + (ω²·a_A + ε·perp(a_A)) / (ω⁴ + ε²)

Inflection circle (the points of the link whose paths have zero curvature at this instant): the
points X with a_X · (X − P) = 0, P the velocity pole (absolute centre); as a_X = a_P + ε·perp(X−P)
− ω²(X − P), this is the circle through P on the diameter P–J with J = P + a_P/ω² (the inflection
pole): centre P + a_P/(2ω²), radius |a_P|/(2ω²).

Centrodes: the fixed centrode is the path of I_0j in the frame; the moving centrode the same points
in the link's own frame (the frame of ``model/mechanism.py``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..geom.vec import Array, perp, rotate
from ..model.mechanism import GROUND, Mechanism
from .graph import Construction
from .plans.centres import Centres


def twists(cs: Centres, driver: str, omega: Array | float,
           more: dict[str, Array] | None = None) -> dict[str, Array]:
    """Every link's motion t = (perp(v_O)/L, ω) (n, 3) from the driver's ω through the centres
    (``more``: further cranks turning about their frame pivots with their ω, W = 2)."""
    n = next(iter(cs.values.values())).h.shape[0]
    known: dict[str, Array] = {GROUND: np.zeros((n, 3))}
    for d, w in {driver: omega, **(more or {})}.items():
        known[d] = np.asarray(w, dtype=float)[..., None] * np.broadcast_to(cs.of(GROUND, d).h,
                                                                            (n, 3))
    pending = [k for k in cs.diagram.links if k not in known]
    while pending:
        done = []
        for j in pending:
            if (GROUND, j) not in cs.values and (j, GROUND) not in cs.values:
                continue
            h0 = cs.of(GROUND, j).h
            best, best_size = None, None
            for m, tm in known.items():
                if m == GROUND or _key(cs, m, j) not in cs.values:
                    continue
                hm = cs.of(m, j).h
                axis = np.cross(h0, hm)
                size = np.einsum("ij,ij->i", axis, axis)
                with np.errstate(invalid="ignore", divide="ignore"):
                    mu = np.einsum("ij,ij->i", np.cross(tm, hm), axis) / size
                t = mu[:, None] * h0
                if best is None or best_size is None:
                    best, best_size = t, size
                else:
                    take = size > best_size
                    best[take], best_size[take] = t[take], size[take]
            if best is not None:
                known[j] = best
                done.append(j)
        if not done:
            break
        pending = [j for j in pending if j not in done]
    return known


def _key(cs: Centres, a: str, b: str) -> tuple[str, str]:
    links = cs.diagram.links
    return (a, b) if links.index(a) < links.index(b) else (b, a)


def velocity(t: Array, r: Array, length: float) -> Array:
    """v of points r (n, 2) of a link moving with t (n, 3): v = v_O + ω·perp(r)."""
    out: Array = -length * perp(t[:, :2]) + t[:, 2:3] * perp(r)
    return out


@dataclass(frozen=True)
class ByCentres:
    """Velocities found by the instant centres: ω of every link, v of every named point."""

    omega: dict[str, Array]
    v: dict[str, Array]


def velocities_by_centres(cs: Centres, mech: Mechanism, omega_driver: Array | float,
                          position: Callable[[str], Array],
                          more: dict[str, Array] | None = None) -> ByCentres:
    """ω of the links and v of their named points (each through the first link that carries it;
    ``more``: the ω of a second driving crank, W = 2)."""
    t = twists(cs, mech.drive.link, omega_driver, more)
    omegas = {lid: t[lid][:, 2].copy() for lid in mech.moving if lid in t}
    v: dict[str, Array] = {}
    for lid in mech.moving:
        if lid not in t:
            continue
        for p in mech.links[lid].points:
            if p not in v:
                v[p] = velocity(t[lid], np.asarray(position(p), dtype=float), cs.length)
    return ByCentres(omegas, v)


def link_origin(mech: Mechanism, link: str, position: Callable[[str], Array],
                angle: Array) -> Array:
    """World position (n, 2) of a link's frame origin, from one of its points and its angle."""
    p, local = next(iter(mech.links[link].points.items()))
    out: Array = np.asarray(position(p), dtype=float) - rotate(np.asarray(local, dtype=float),
                                                               angle)
    return out


def centrodes(cs: Centres, mech: Mechanism, link: str, position: Callable[[str], Array],
              angle: Array) -> tuple[Array, Array]:
    """Fixed centrode (in the frame) and moving centrode (in the link's frame) of a link: (n, 2)
    each, m; NaN where the absolute centre is at infinity (the curve breaks there)."""
    fixed = cs.point(GROUND, link)
    origin = link_origin(mech, link, position, angle)
    return fixed, rotate(fixed - origin, -np.asarray(angle, dtype=float))


def centrodes_over_turn(c: Construction, mech: Mechanism, link: str,
                        count: int) -> tuple[Array, Array, Array]:
    """φ (rad, scene convention) and the fixed and moving centrodes of a link at ``count``
    positions of a turn."""
    from .plans.centres import centres_at

    phi = np.linspace(0.0, 2.0 * np.pi, count, endpoint=False)
    ev = c.evaluate(phi)
    fixed, moving = centrodes(centres_at(c, ev, mech), mech, link,
                              lambda p: ev[c.position(p)], ev[c.link_angle(link)])
    return phi, fixed, moving


def acceleration_pole(a_point: Array, r_point: Array, omega: Array, epsilon: Array) -> Array:
    """The acceleration pole Q (n, 2) of a link from one point's a and r, ω and ε (NaN when the
    link has ω = ε = 0: every point has the same acceleration)."""
    w2 = np.asarray(omega, dtype=float) ** 2
    e = np.asarray(epsilon, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        out: Array = r_point + (w2[:, None] * a_point + e[:, None] * perp(a_point)) / \
            (w2 * w2 + e * e)[:, None]
    return out


def point_acceleration(a_point: Array, r_point: Array, omega: Array, epsilon: Array,
                       r: Array) -> Array:
    """a at r (n, 2) of the link: a_A + ε·perp(r − A) − ω²·(r − A)."""
    d = r - r_point
    out: Array = a_point + np.asarray(epsilon)[:, None] * perp(d) - \
        (np.asarray(omega) ** 2)[:, None] * d
    return out


def inflection_circle(pole: Array, a_point: Array, r_point: Array, omega: Array,
                      epsilon: Array) -> tuple[Array, Array, Array]:
    """Centre (n, 2), radius (n,) and inflection pole J (n, 2) of a link's inflection circle,
    from its velocity pole P (finite) and one point's a and r (NaN when ω = 0 or P at infinity)."""
    a_p = point_acceleration(a_point, r_point, omega, epsilon, pole)
    w2 = (np.asarray(omega, dtype=float) ** 2)[:, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        diameter = a_p / w2
    return pole + diameter / 2.0, np.hypot(diameter[:, 0], diameter[:, 1]) / 2.0, pole + diameter


__all__ = ["ByCentres", "acceleration_pole", "centrodes", "centrodes_over_turn",
           "inflection_circle", "link_origin", "point_acceleration", "twists",
           "velocities_by_centres", "velocity"]
