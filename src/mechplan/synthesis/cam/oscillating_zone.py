"""The ψ′–ψ diagram of an oscillating follower (knife or roller): the admissible zone of the cam
centre for the allowable pressure angles.

In the follower's frame (pivot A, roller centre B(ψ) on its arc, O the cam centre at the origin),
lay off along each arm position, from B away from the pivot, the segment B K = l·ψ′ (the analogue
velocity of B, in length). Seen from K, the cam centre O makes with the normal to the arm the
pressure angle: tan α = −(KO·e)/(KO·n), e along the arm from A to B and n = J·e its quarter turn.
So |α| ≤ α_allow holds for every cam centre inside the wedge with apex K, axis n and half-angle
α_allow; the admissible zone is the intersection of these wedges (convex), hatched on the sheet.
The cam centre of the solution lies in it — on its edge when the base radius is the least one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .base_radius import limit_per_angle
from .profile import Geometry, fixed_frame


@dataclass(frozen=True)
class OscillatingZone:
    """The construction (σ = +1 frame, m): arm positions, K points, wedge rays and the zone."""

    pivot: np.ndarray                   # A
    roller: np.ndarray                  # B_i
    k_points: np.ndarray                # K_i = B_i + l·ψ′_i·e_i
    rays: np.ndarray                    # (N, 2, 2): the unit directions of each wedge's two edges
    zone: np.ndarray                    # the zone's polygon (clipped to a box around the drawing)
    margin: float                       # least (α_allow − |α|) over the angles at O, rad


def _clip(poly: np.ndarray, point: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """Keep the part of a convex polygon with normal·(x − point) ≥ 0 (Sutherland–Hodgman)."""
    if poly.size == 0:
        return poly
    d = (poly - point) @ normal
    out = []
    n = len(poly)
    for i in range(n):
        j = (i + 1) % n
        if d[i] >= 0:
            out.append(poly[i])
        if (d[i] >= 0) != (d[j] >= 0):
            t = d[i] / (d[i] - d[j])
            out.append(poly[i] + t * (poly[j] - poly[i]))
    return np.array(out) if out else np.empty((0, 2))


def oscillating_zone(g: Geometry, phi: np.ndarray, alpha_rise: float, alpha_return: float,
                     from_motion: tuple[np.ndarray, np.ndarray, np.ndarray]) -> OscillatingZone:
    """The construction at the cam angles ``phi`` with s, s′, s″ given (the σ = +1 frame)."""
    s, s1, s2 = from_motion
    b, _, _, _ = fixed_frame(g, s, s1, s2)
    a = np.array([g.pivot, 0.0])
    e = (b - a) / g.arm
    n = np.stack([-e[:, 1], e[:, 0]], axis=1)
    k = b + (g.arm * s1)[:, None] * e
    lim = limit_per_angle(g.phases, phi, alpha_rise, alpha_return)
    c, sn = np.cos(lim), np.sin(lim)
    # wedge edges: n turned by ±α_allow; inside: O − K between them
    left = np.stack([c * n[:, 0] - sn * n[:, 1], sn * n[:, 0] + c * n[:, 1]], axis=1)
    right = np.stack([c * n[:, 0] + sn * n[:, 1], -sn * n[:, 0] + c * n[:, 1]], axis=1)
    rays = np.stack([left, right], axis=1)
    w = -k                                                  # O − K with O at the origin
    alpha = -np.arctan2(np.einsum("ij,ij->i", w, e), np.einsum("ij,ij->i", w, n))
    margin = float(np.min(lim - np.abs(alpha)))
    reach = 1.6 * max(g.pivot, float(np.max(np.hypot(*k.T))))
    box = np.array([[-reach, -reach], [reach, -reach], [reach, reach], [-reach, reach]])
    zone = box
    for i in range(len(k)):
        # inside the wedge: on the inner side of both edges (normals J·left and −J·right… )
        for edge, side in ((left[i], -1.0), (right[i], 1.0)):
            normal = side * np.array([-edge[1], edge[0]])
            zone = _clip(zone, k[i], normal)
    return OscillatingZone(a, b, k, rays, zone, margin)
