"""Reduced (equivalent) moment of forces and moment of inertia on the driving link.

M_red = Σ(F_i·v_i + M_i·ω_i)/ω1 over the given loads (external forces and moments, weights — not
the inertia loads, which the reduced moment of inertia accounts for) and
J_red = Σ(m_i·v_Si² + J_Si·ω_i²)/ω1², both vectorised over positions (first axis).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..geom.vec import Array, dot
from ..model.mechanism import GROUND, Mechanism


def reduced_moment(forces: Sequence[Array], velocities: Sequence[Array], moments: Sequence[Array],
                   omegas: Sequence[Array], omega1: Array) -> Array:
    """Return M_red = (Σ F_i·v_i + Σ M_k·ω_k)/ω1 (N·m).

    ``forces``/``velocities``: (N, 2) arrays pairwise (N, m/s); ``moments``/``omegas``: (N,)
    arrays pairwise (N·m counter-clockwise +, rad/s); ``omega1``: (N,) or scalar, rad/s.
    """
    omega1 = np.asarray(omega1, dtype=float)
    power = np.zeros(np.broadcast_shapes(omega1.shape, *(np.shape(f)[:-1] for f in forces)))
    for f, v in zip(forces, velocities, strict=True):
        power = power + dot(np.asarray(f), np.asarray(v))
    for m, w in zip(moments, omegas, strict=True):
        power = power + np.asarray(m) * np.asarray(w)
    return power / omega1


def reduced_inertia(masses: Sequence[float], centre_velocities: Sequence[Array],
                    inertias: Sequence[float], omegas: Sequence[Array], omega1: Array) -> Array:
    """Return J_red = (Σ m_i·v_Si² + Σ J_Si·ω_i²)/ω1² (kg·m²).

    ``centre_velocities``: (N, 2) arrays, one per mass; ``omegas``: (N,) arrays, one per J_S.
    """
    omega1 = np.asarray(omega1, dtype=float)
    energy = np.zeros(np.broadcast_shapes(omega1.shape,
                                          *(np.shape(v)[:-1] for v in centre_velocities)))
    for m, v in zip(masses, centre_velocities, strict=True):
        v = np.asarray(v)
        energy = energy + m * dot(v, v)
    for j, w in zip(inertias, omegas, strict=True):
        energy = energy + j * np.asarray(w) ** 2
    return energy / (omega1 * omega1)


def point_velocity(c: Construction, ev: Evaluation, mech: Mechanism, point: str) -> Array:
    """Velocity (N, 2) of a named point from the velocity plan (zero for a frame point)."""
    if point in mech.links[GROUND].points:
        return np.zeros((ev.n, 2))
    return ev[c.velocity_image(point)]


def link_omega(c: Construction, ev: Evaluation, link: str) -> Array:
    """Angular velocity (N,) of a link from the velocity plan."""
    return ev[c.omega(link)]


def reduced_of(
    c: Construction, ev: Evaluation, mech: Mechanism, loading: Any
) -> tuple[Array, Array]:
    """Return (M_red, J_red) at the evaluated positions.

    J_red needs the velocity plan only; M_red needs the loads of the force plan (a construction
    built with ``loading``).
    """
    omega1 = link_omega(c, ev, mech.drive.link)
    forces: list[Array] = []
    velocities: list[Array] = []
    moments: list[Array] = []
    omegas: list[Array] = []
    for link, ms in loading.masses.items():
        weight = c.weight(link)
        if weight is not None:
            forces.append(ev[weight])
            velocities.append(point_velocity(c, ev, mech, ms.centre))
    for j, spec in enumerate(loading.loads):
        step = c.load(j)
        if step is None:
            continue
        if spec.point is None:
            moments.append(ev[step])
            omegas.append(link_omega(c, ev, spec.link))
        else:
            forces.append(ev[step])
            velocities.append(point_velocity(c, ev, mech, spec.point))
        other = c.results.get(f"load_{j}_other")     # the far end of a spring or cylinder
        if other is not None:
            forces.append(ev[other])
            velocities.append(point_velocity(c, ev, mech, spec.other))
    m_red = reduced_moment(forces, velocities, moments, omegas, omega1)
    massive = [ms for ms in loading.masses.values() if ms.mass > 0]
    turning = [ms for ms in loading.masses.values() if ms.inertia > 0]
    j_red = reduced_inertia([ms.mass for ms in massive],
                            [point_velocity(c, ev, mech, ms.centre) for ms in massive],
                            [ms.inertia for ms in turning],
                            [link_omega(c, ev, ms.link) for ms in turning], omega1)
    return m_red, j_red
