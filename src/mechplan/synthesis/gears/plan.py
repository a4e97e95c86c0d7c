"""The velocity plan of a planetary train (Smirnov): the pitch-point velocity equations solved as a
linear system — independent of Willis' formula, so the ratio read off the plan checks it.

Radii are measured from the central axis (y), velocities are perpendicular to the section plane (v).
Each gear's velocities lie on a straight line v(y) through its instantaneous centre: the central
gears and the carrier through y = 0, the planet block through its pitch point with a held gear.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...model.gears import PlanetarySpec, Scheme
from .train import centre_distance


@dataclass(frozen=True)
class TrainPlan:
    """Angular velocities and the lines of the linear velocity plan of one tooth set."""

    names: tuple[str, ...]                   # gears, then "h"
    omega: dict[str, float]                  # absolute, rad/s (counter-clockwise seen along +axis)
    relative: dict[str, float]               # ω − ω_h
    radius: dict[str, float]                 # pitch radius of each gear, m
    a_w: float                               # radius of the planet axis, m
    pitch_points: dict[str, float]           # "A" (1–2), "B" (planet–last central): radius, m
    lines: dict[str, tuple[tuple[float, float], tuple[float, float]]]  # link: (y, v) ends
    ratio: float                             # ω_in/ω_out read off the plan


def velocity_plan(spec: PlanetarySpec, z: tuple[int, ...]) -> TrainPlan:
    """Solve the pitch-point velocity equations for the set ``z``."""
    sch = spec.scheme
    names = sch.gear_names
    m1, m2 = spec.modules
    if sch is Scheme.SINGLE_ROW:
        m2 = m1
    a_w = float(centre_distance(spec, np.asarray([z]))[0][0])
    mods = (m1, m1, m2, m2) if sch.two_row else (m1, m1, m1)
    radius = {n: mods[j] * z[j] / 2 for j, n in enumerate(names)}
    y_a, y_b = radius[names[0]], radius[names[-1]]
    # unknowns: ω_a, ω_planet block, ω_b, ω_h
    A = np.zeros((4, 4))
    rhs = np.zeros(4)
    A[0] = (y_a, -(y_a - a_w), 0.0, -a_w)        # pitch point A: gear a = planet block
    A[1] = (0.0, -(y_b - a_w), y_b, -a_w)        # pitch point B: gear b = planet block
    col = {names[0]: 0, names[-1]: 2, "h": 3}
    A[2, col[spec.fixed]] = 1.0
    A[3, col[spec.input]] = 1.0
    rhs[3] = spec.input_speed
    w_a, w_p, w_b, w_h = np.linalg.solve(A, rhs)
    omega = {names[0]: w_a, names[-1]: w_b, "h": w_h}
    for n in names[1:-1]:
        omega[n] = w_p
    omega = {n: float(omega[n]) for n in (*names, "h")}
    planet_ys = (y_a, y_b, a_w)
    lines = {names[0]: ((0.0, 0.0), (y_a, w_a * y_a)),
             names[-1]: ((0.0, 0.0), (y_b, w_b * y_b)),
             "h": ((0.0, 0.0), (a_w, w_h * a_w))}
    lo, hi = min(planet_ys), max(planet_ys)
    v = (lambda y: w_h * a_w + w_p * (y - a_w))
    for n in names[1:-1]:
        lines[n] = ((lo, float(v(lo))), (hi, float(v(hi))))
    return TrainPlan(names=(*names, "h"), omega=omega,
                     relative={n: omega[n] - omega["h"] for n in omega}, radius=radius,
                     a_w=a_w, pitch_points={"A": y_a, "B": y_b}, lines=lines,
                     ratio=omega[spec.input] / omega[spec.output])
