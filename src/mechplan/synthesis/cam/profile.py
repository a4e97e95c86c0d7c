"""Profile by inversion: pitch curve, working profile, pressure angle and radii of curvature.

Frames. The cam centre O is the origin. The computation is done for a counter-clockwise cam
(σ = +1) and mirrored in the y axis for a clockwise one. Fixed frame, σ = +1: a translating follower
moves along +y on the line x = e; an oscillating follower turns about the pivot A = (a, 0), its
roller centre at B = A + l·(−cos γ, sin γ), γ = γ0 + ψ (ψ grows as B leaves O). Inversion turns the
follower by −φ about O: a point p(φ) of the fixed frame is at P(φ) = R(−φ)·p(φ) on the cam, so
P′ = R(−φ)(p′ − J p) and P″ = R(−φ)(p″ − 2J p′ − p), J the quarter turn. Radii of curvature are
signed: positive where the curve is convex (bends toward O).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...model.cam import Contact, Motion, Phase
from .motion import motion


@dataclass(frozen=True)
class Geometry:
    """Dimensions fixed by the synthesis (m, rad)."""

    phases: tuple[Phase, ...]
    stroke: float
    sense: int
    motion: Motion
    contact: Contact
    r0: float                  # base radius of the pitch curve (the working profile's for flat)
    e: float = 0.0             # offset of a translating follower
    roller: float = 0.0
    arm: float = 0.0
    pivot: float = 0.0

    @property
    def gamma0(self) -> float:
        """Angle at the pivot between AO and AB in the nearest position (oscillating)."""
        a, l, r0 = self.pivot, self.arm, self.r0
        return math.acos(max(-1.0, min(1.0, (a * a + l * l - r0 * r0) / (2 * a * l))))


@dataclass(frozen=True)
class Sample:
    """The profile at cam angles ``phi`` (arrays (N,) or (N, 2) in the cam frame, m)."""

    phi: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    follower: np.ndarray       # roller centre (or contact point) in the fixed frame
    direction: np.ndarray      # unit direction of the follower's motion (fixed frame)
    pitch: np.ndarray          # pitch curve P (cam frame); the profile itself for a flat face
    normal: np.ndarray         # outward unit normal of the profile (cam frame)
    radius_pitch: np.ndarray   # signed radius of curvature of the pitch curve
    profile: np.ndarray        # working profile
    radius: np.ndarray         # signed radius of curvature of the working profile
    alpha: np.ndarray          # signed pressure angle (rad)


def _J(v: np.ndarray) -> np.ndarray:
    return np.stack([-v[:, 1], v[:, 0]], axis=1)


def _rot(v: np.ndarray, ang: np.ndarray) -> np.ndarray:
    c, s = np.cos(ang), np.sin(ang)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=1)


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]


def fixed_frame(g: Geometry, s: np.ndarray, s1: np.ndarray, s2: np.ndarray):
    """p, p′, p″ of the roller centre (σ = +1 frame) and the follower's unit direction."""
    n = s.size
    if g.motion is Motion.TRANSLATING:
        s0 = math.sqrt(g.r0 ** 2 - g.e ** 2)
        p = np.stack([np.full(n, g.e), s0 + s], axis=1)
        p1 = np.stack([np.zeros(n), s1], axis=1)
        p2 = np.stack([np.zeros(n), s2], axis=1)
        u = np.tile([0.0, 1.0], (n, 1))
        return p, p1, p2, u
    gam = g.gamma0 + s
    sg, cg = np.sin(gam), np.cos(gam)
    d1 = g.arm * np.stack([sg, cg], axis=1)           # dB/dψ
    d2 = g.arm * np.stack([cg, -sg], axis=1)          # d²B/dψ²
    p = np.stack([g.pivot - g.arm * cg, g.arm * sg], axis=1)
    p1 = d1 * s1[:, None]
    p2 = d2 * (s1 ** 2)[:, None] + d1 * s2[:, None]
    return p, p1, p2, d1 / g.arm


def pressure_angle(g: Geometry, s: np.ndarray, s1: np.ndarray, s2: np.ndarray) -> np.ndarray:
    """Signed pressure angle (rad) of a knife or roller follower, σ = +1 frame."""
    p, p1, _, u = fixed_frame(g, s, s1, s2)
    t_fixed = p1 - _J(p)
    n = _J(t_fixed)
    return np.arctan2(_cross(u, n), np.einsum("ij,ij->i", u, n))


def sample(g: Geometry, phi: np.ndarray | float) -> Sample:
    """Evaluate the pitch curve, profile, pressure angle and curvature at cam angles ``phi``."""
    m = motion(g.phases, g.stroke, phi)
    phi_a = m.phi
    if g.contact is Contact.FLAT:
        return _flat(g, m.phi, m.s, m.s1, m.s2)
    p, p1, p2, u = fixed_frame(g, m.s, m.s1, m.s2)
    t_fixed = p1 - _J(p)
    P = _rot(p, -phi_a)
    P1 = _rot(t_fixed, -phi_a)
    P2 = _rot(p2 - 2 * _J(p1) - p, -phi_a)
    speed = np.hypot(P1[:, 0], P1[:, 1])
    n_out = _J(P1) / speed[:, None]         # the pitch curve runs clockwise as φ grows
    with np.errstate(divide="ignore"):
        R_p = -speed ** 3 / _cross(P1, P2)  # convex → positive
    n_fixed = _J(t_fixed) / speed[:, None]
    alpha = np.arctan2(_cross(u, n_fixed), np.einsum("ij,ij->i", u, n_fixed))
    W = P - g.roller * n_out
    R_w = R_p - g.roller
    out = Sample(phi_a, m.s, m.s1, m.s2, p, u, P, n_out, R_p, W, R_w, alpha)
    return _mirrored(out) if g.sense < 0 else out


def _flat(g: Geometry, phi: np.ndarray, s: np.ndarray, s1: np.ndarray, s2: np.ndarray) -> Sample:
    """A translating flat-faced follower: contact at x = s′ on the face y = r0 + s (an oscillating
    one: :mod:`.oscillating_flat`)."""
    if g.motion is Motion.OSCILLATING:
        from .oscillating_flat import flat_oscillating

        f = flat_oscillating(g.r0, g.pivot, s, s1, s2, phi)
        out = Sample(phi, s, s1, s2, f["contact"], f["direction"], f["profile"], f["normal"],
                     f["radius"], f["profile"], f["radius"], np.zeros_like(s))
        return _mirrored(out) if g.sense < 0 else out
    c = np.stack([s1, g.r0 + s], axis=1)
    C = _rot(c, -phi)
    n_out = _rot(np.tile([0.0, 1.0], (s.size, 1)), -phi)
    rho = g.r0 + s + s2
    u = np.tile([0.0, 1.0], (s.size, 1))
    out = Sample(phi, s, s1, s2, c, u, C, n_out, rho, C, rho, np.zeros_like(s))
    return _mirrored(out) if g.sense < 0 else out


def _mirrored(x: Sample) -> Sample:
    def m(v: np.ndarray) -> np.ndarray:
        return v * np.array([-1.0, 1.0])
    return Sample(x.phi, x.s, x.s1, x.s2, m(x.follower), m(x.direction), m(x.pitch), m(x.normal),
                  x.radius_pitch, m(x.profile), x.radius, -x.alpha)


def polar(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Radius vector ρ = √(x² + y²) and polar angle θ ∈ [0, 2π) of cam-frame points."""
    return np.hypot(points[:, 0], points[:, 1]), np.mod(np.arctan2(points[:, 1], points[:, 0]),
                                                        2 * math.pi)


def follower_positions(g: Geometry, smp: Sample, length: float) -> tuple[np.ndarray, np.ndarray]:
    """The follower's successive positions in the inverted motion (cam frame): segment ends.

    Translating: from the roller centre along the follower's axis, ``length`` long. Oscillating: the
    arm from the pivot (turned by −φ about O) to the roller centre.
    """
    sigma = 1.0 if g.sense > 0 else -1.0
    if g.motion is Motion.TRANSLATING:
        d = _rot(smp.direction, -sigma * smp.phi)
        return smp.pitch, smp.pitch + length * d
    pivot = np.tile([sigma * g.pivot, 0.0], (smp.phi.size, 1))
    return _rot(pivot, -sigma * smp.phi), smp.pitch
