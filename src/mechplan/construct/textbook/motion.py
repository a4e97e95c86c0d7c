"""The world motion of a link over the positions: a reference point, frame angle, ω and ε.

Everything here is read from an evaluation (positions, velocity and acceleration images, ω, ε);
the velocity or acceleration of any point fixed to a link then follows from rigid-body kinematics
(v = v_Q + ω×QP, a = a_Q + ε×QP − ω²·QP), which is what the relative quantities are made of.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...model.mechanism import GROUND, Mechanism
from ..graph import Construction, Evaluation

Array = np.ndarray


def cross_k(w: Array, v: Array) -> Array:
    """ω k × v for ω (N,) and v (N, 2): the vector v turned 90° counter-clockwise times ω."""
    out: Array = np.asarray(w)[:, None] * np.stack([-v[:, 1], v[:, 0]], axis=1)
    return out


def unit(angle: Array) -> Array:
    """Unit vectors (N, 2) at ``angle`` (N,) radians."""
    return np.stack([np.cos(angle), np.sin(angle)], axis=1)


@dataclass(frozen=True, slots=True)
class Motion:
    """A link's motion: reference point ``r``, ``v``, ``a`` (N, 2), angles (N,); a None part was
    not asked for (no acceleration plan)."""

    link: str
    theta: Array
    r: Array
    v: Array
    omega: Array
    a: Array | None
    epsilon: Array | None

    def velocity_at(self, p: Array) -> Array:
        """Velocity (N, 2) of the point of this link at world position ``p`` (N, 2)."""
        out: Array = self.v + cross_k(self.omega, p - self.r)
        return out

    def acceleration_at(self, p: Array) -> Array | None:
        """Acceleration (N, 2) of the point of this link at world position ``p`` (N, 2)."""
        if self.a is None or self.epsilon is None:
            return None
        rho = p - self.r
        out: Array = self.a + cross_k(self.epsilon, rho) - (self.omega ** 2)[:, None] * rho
        return out


def point(c: Construction, ev: Evaluation, name: str, what: str = "r") -> Array | None:
    """Position, velocity or acceleration (N, 2) of a named point, or None when not built."""
    if what == "r":
        return ev[c.position(name)] if c.has_position(name) else None
    sym = "v" if what == "v" else "a"
    if not c.has_result(sym, name):
        return None
    return ev[c.velocity_image(name) if sym == "v" else c.acceleration_image(name)]


def _rate(c: Construction, ev: Evaluation, mech: Mechanism, link: str, key: str) -> Array | None:
    if c.has_result(key, link):
        return ev[c.omega(link) if key == "omega" else c.epsilon(link)]
    lk = mech.links[link]
    if lk.slides_on:     # a slider turns with its guide's link
        carrier = mech.guides[lk.slides_on].link
        if carrier == GROUND:
            return np.zeros(ev.n)
        return _rate(c, ev, mech, carrier, key)
    return None


def frame_angle(c: Construction, ev: Evaluation, mech: Mechanism, link: str) -> Array:
    """The angle (N,) of a link's frame x axis, measured from the world's +x."""
    if link == GROUND:
        return np.zeros(ev.n)
    lk = mech.links[link]
    named = [p for p in lk.points if c.has_position(p)]
    if len(named) >= 2:
        p, q = named[0], named[1]
        (x0, y0), (x1, y1) = lk.points[p], lk.points[q]
        d = ev[c.position(q)] - ev[c.position(p)]
        angle: Array = np.arctan2(d[:, 1], d[:, 0]) - np.arctan2(y1 - y0, x1 - x0)
        return angle
    if lk.slides_on:
        g = mech.guides[lk.slides_on]
        return frame_angle(c, ev, mech, g.link) + g.angle
    return np.asarray(ev[c.link_angle(link)])


def motion(c: Construction, ev: Evaluation, mech: Mechanism, link: str,
           accelerations: bool = True) -> Motion:
    """The motion of ``link`` (the frame: at rest)."""
    n = ev.n
    if link == GROUND:
        zero = np.zeros((n, 2))
        return Motion(link, np.zeros(n), zero, zero, np.zeros(n), zero if accelerations else None,
                      np.zeros(n) if accelerations else None)
    lk = mech.links[link]
    ref = next(p for p in lk.points if c.has_position(p) and c.has_result("v", p))
    omega = _rate(c, ev, mech, link, "omega")
    if omega is None:
        raise KeyError(f"the construction has no angular velocity of link {link}")
    a = eps = None
    if accelerations and c.has_result("a", ref):
        a, eps = point(c, ev, ref, "a"), _rate(c, ev, mech, link, "epsilon")
    return Motion(link, frame_angle(c, ev, mech, link), ev[c.position(ref)],
                  ev[c.velocity_image(ref)], omega, a, eps)


def guide_direction(c: Construction, ev: Evaluation, mech: Mechanism, guide: str) -> Array:
    """Unit direction (N, 2) of a guide in the world."""
    g = mech.guides[guide]
    return unit(frame_angle(c, ev, mech, g.link) + g.angle)
