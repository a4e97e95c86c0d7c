"""The velocity plan of a planetary train (Smirnov): the pitch-point velocity equations solved as a
linear system — independent of Willis' formula, so the ratio read off the plan checks it.

Radii are measured from the central axis (y), velocities are perpendicular to the section plane (v).
Each gear's velocities lie on a straight line v(y) through its instantaneous centre: the central
gears and the carrier through y = 0, the planet block through its pitch point with a held gear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import PlanetarySpec
from .train import centre_distance, drawable_distance, mesh_teeth


@dataclass(frozen=True)
class TrainPlan:
    """Angular velocities and the lines of the linear velocity plan of one tooth set."""

    names: tuple[str, ...]                   # gears, then "h"
    omega: dict[str, float]                  # absolute, rad/s (counter-clockwise seen along +axis)
    relative: dict[str, float]               # ω − ω_h
    radius: dict[str, float]                 # working pitch radius of each gear (its mesh), m
    a_w: float                               # radius of the planet axis, m
    pitch_points: dict[str, float]           # "A" (1–2), "B" (planet–last central): radius, m
    lines: dict[str, tuple[tuple[float, float], tuple[float, float]]]  # link: (y, v) ends
    ratio: float                             # ω_in/ω_out read off the plan (nan: two inputs)


def _solve_exact(a: list[list[Fraction]], b: list[Fraction]) -> list[Fraction]:
    """Gaussian elimination in rationals (the plan's equations are solved exactly, so a train
    of ratio 10⁴ loses no digits to cancellation)."""
    n = len(b)
    rows = [row[:] + [rhs] for row, rhs in zip(a, b, strict=True)]
    for col in range(n):
        piv = next((r for r in range(col, n) if rows[r][col] != 0), None)
        if piv is None:
            raise ZeroDivisionError("singular")
        rows[col], rows[piv] = rows[piv], rows[col]
        for r in range(n):
            if r != col and rows[r][col] != 0:
                f = rows[r][col] / rows[col][col]
                rows[r] = [x - f * y for x, y in zip(rows[r], rows[col], strict=True)]
    return [rows[j][n] / rows[j][j] for j in range(n)]


def working_radii(spec: PlanetarySpec, z: tuple[int, ...], a_w: float
                  ) -> tuple[dict[str, Fraction], Fraction, Fraction]:
    """Working pitch radii of the gears (each mesh at ``a_w``: r_w = a_w·z/(z_c ± z_p)) and the
    radii of the pitch points A (mesh 1) and B (mesh 2) from the central axis, exact."""
    names = spec.scheme.gear_names
    aw = Fraction(a_w)
    (za, zp1, int1, _), (zb, zp2, int2, _) = mesh_teeth(spec, z)
    s1 = za - zp1 if int1 else za + zp1
    s2 = zb - zp2 if int2 else zb + zp2
    radius = {names[0]: aw * za / s1, names[1]: aw * zp1 / s1, names[-1]: aw * zb / s2}
    if spec.scheme.two_row:
        radius[names[2]] = aw * zp2 / s2
    return radius, radius[names[0]], radius[names[-1]]


def velocity_plan(spec: PlanetarySpec, z: tuple[int, ...], a_w: float | None = None,
                  speeds: dict[str, float] | None = None) -> TrainPlan:
    """Solve the pitch-point velocity equations for the set ``z`` at the working centre distance
    ``a_w`` (default: :func:`working_distance`), with the fixed link held and the input turning at
    ``input_speed`` — or, for a differential, with the two links of ``speeds`` turning as given.

    Raises SceneError when the set is not coaxial and no working centre distance makes it so: its
    plan cannot be drawn (the planet's axis would sit at two radii)."""
    sch = spec.scheme
    names = sch.gear_names
    a_w = drawable_distance(spec, z) if a_w is None else a_w
    if a_w is None:
        a12, a34 = (float(v[0]) for v in centre_distance(spec, np.asarray([z])))
        raise SceneError(
            Text(
                "errmsg.synthesis_gears_plan.set_z_not",
                {"z": str(list(z)), "value": f"{a12 * 1000:.6g}", "value2": f"{a34 * 1000:.6g}"},
            ),
            key="planetary.centre_distance",
        )
    if not a_w > 0:
        raise SceneError(Text("errmsg.synthesis_gears_plan.positive_w", {"a_w": str(a_w)}),
                         key="planetary.centre_distance")
    radius, y_a, y_b = working_radii(spec, z, a_w)
    aw = Fraction(a_w)
    # unknowns: ω_a, ω_planet block, ω_b, ω_h
    rows = [[y_a, -(y_a - aw), Fraction(0), -aw],      # pitch point A: gear a = planet block
            [Fraction(0), -(y_b - aw), y_b, -aw]]      # pitch point B: gear b = planet block
    rhs = [Fraction(0), Fraction(0)]
    col = {names[0]: 0, names[-1]: 2, "h": 3}
    known = speeds if speeds is not None else {spec.fixed: 0.0, spec.input: spec.input_speed}
    for link, w in known.items():
        row = [Fraction(0)] * 4
        row[col[link]] = Fraction(1)
        rows.append(row)
        rhs.append(Fraction(w))
    try:
        w_a, w_p, w_b, w_h = _solve_exact(rows, rhs)
    except ZeroDivisionError:
        raise SceneError(
            Text(
                "errmsg.synthesis_gears_plan.set_z_known",
                {"z": str(list(z)), "known": " and ".join(known)},
            ),
            key="planetary.given",
        ) from None
    exact = {names[0]: w_a, names[-1]: w_b, "h": w_h}
    for n in names[1:-1]:
        exact[n] = w_p
    omega = {n: float(exact[n]) for n in (*names, "h")}
    ya, yb, awf = float(y_a), float(y_b), float(a_w)
    lines = {names[0]: ((0.0, 0.0), (ya, omega[names[0]] * ya)),
             names[-1]: ((0.0, 0.0), (yb, omega[names[-1]] * yb)),
             "h": ((0.0, 0.0), (awf, omega["h"] * awf))}
    lo, hi = min(ya, yb, awf), max(ya, yb, awf)
    v = (lambda y: omega["h"] * awf + omega[names[1]] * (y - awf))
    for n in names[1:-1]:
        lines[n] = ((lo, float(v(lo))), (hi, float(v(hi))))
    if speeds is None:
        ratio = float(exact[spec.input] / exact[spec.output]) if exact[spec.output] else math.inf
    else:
        ratio = math.nan
    return TrainPlan(names=(*names, "h"), omega=omega,
                     relative={n: float(exact[n] - exact["h"]) for n in exact},
                     radius={n: float(r) for n, r in radius.items()},
                     a_w=awf, pitch_points={"A": ya, "B": yb}, lines=lines, ratio=ratio)
