"""Hand-written vectorised numpy (float64) closed forms: slider-crank and four-bar.

This is the "hand-written numpy closed form" baseline: analytic position, velocity and
acceleration formulas evaluated for a whole array of crank angles at once (no Python loop over
positions).  It does NOT import ``mechplan``.

Conventions (same as :mod:`mpref`): SI units, ``theta`` absolute crank angle counter-clockwise
from +x, ``omega`` signed (+ = counter-clockwise), constant crank speed.  Each function returns
``dict[str, np.ndarray]``: point name -> array ``theta.shape + (6,)`` holding
``(x, y, vx, vy, ax, ay)``; link name -> array ``theta.shape + (3,)`` holding
``(angle, omega, epsilon)`` with ``angle = atan2`` of the link's named point pair, in (-pi, pi].
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["PRESETS", "four_bar", "preset", "rpm", "slider_crank"]

F64 = NDArray[np.float64]


def rpm(n: float) -> float:
    """Revolutions per minute -> rad/s (sign preserved)."""
    return n * 2.0 * math.pi / 60.0


def _point(x: F64, y: F64, vx: F64, vy: F64, ax: F64, ay: F64, shape: tuple[int, ...]) -> F64:
    return np.stack([np.broadcast_to(c, shape) for c in (x, y, vx, vy, ax, ay)], axis=-1)


def _link(angle: F64, om: F64, eps: F64, shape: tuple[int, ...]) -> F64:
    return np.stack([np.broadcast_to(c, shape) for c in (angle, om, eps)], axis=-1)


def slider_crank(
    r: float,
    l: float,
    e: float,
    omega: float,
    theta: ArrayLike,
    guide_angle: float = 0.0,
    frac_S2: float = 0.5,
) -> dict[str, F64]:
    """Slider-crank (same geometry as ``mpref.slider_crank``), closed form.

    Guide frame u = (cos g, sin g), n = (-sin g, cos g); alpha = theta - g.  Rod angle relative
    to the guide: ``sin(phi) = (e - r sin alpha) / l`` with ``cos(phi) > 0`` (B further along +u).
    Points O, A, B, S2; links "1" (O->A), "2" (A->B).
    """
    th = np.asarray(theta, dtype=np.float64)
    shape = th.shape
    g = float(guide_angle)
    ux, uy = math.cos(g), math.sin(g)
    nx, ny = -uy, ux
    w = float(omega)

    c1, s1 = np.cos(th), np.sin(th)
    alpha = th - g
    ca, sa = np.cos(alpha), np.sin(alpha)
    sp = (e - r * sa) / l
    cp = np.sqrt(1.0 - sp * sp)
    phi = np.arctan2(sp, cp)

    # rod angular velocity / acceleration (from l sin(phi) = e - r sin(alpha))
    w2 = -r * w * ca / (l * cp)
    e2 = (r * w * w * sa + l * sp * w2 * w2) / (l * cp)

    # slider coordinate along the guide and its derivatives
    t = r * ca + l * cp
    t_d = -r * w * sa - l * sp * w2
    t_dd = -r * w * w * ca - l * cp * w2 * w2 - l * sp * e2

    Ax, Ay = r * c1, r * s1
    Avx, Avy = -r * w * s1, r * w * c1
    Aax, Aay = -r * w * w * c1, -r * w * w * s1

    Bx, By = e * nx + t * ux, e * ny + t * uy
    Bvx, Bvy = t_d * ux, t_d * uy
    Bax, Bay = t_dd * ux, t_dd * uy

    f = frac_S2
    zero = np.zeros(shape)
    out = {
        "O": _point(zero, zero, zero, zero, zero, zero, shape),
        "A": _point(Ax, Ay, Avx, Avy, Aax, Aay, shape),
        "B": _point(Bx, By, Bvx, Bvy, Bax, Bay, shape),
        "S2": _point(
            Ax + f * (Bx - Ax), Ay + f * (By - Ay),
            Avx + f * (Bvx - Avx), Avy + f * (Bvy - Avy),
            Aax + f * (Bax - Aax), Aay + f * (Bay - Aay), shape,
        ),
        "1": _link(np.arctan2(s1, c1), np.full(shape, w), zero, shape),
        "2": _link(np.arctan2(np.sin(phi + g), np.cos(phi + g)), w2, e2, shape),
    }
    return out


def four_bar(
    A: Sequence[float],
    D: Sequence[float],
    lAB: float,
    lBC: float,
    lCD: float,
    omega: float,
    theta: ArrayLike,
    branch: int = 1,
    lBE: float | None = None,
    lCE: float | None = None,
) -> dict[str, F64]:
    """Four-bar (same geometry as ``mpref.four_bar``), closed form.

    C by circle intersection (left of B->D for branch=+1); omega/epsilon of coupler and rocker
    from the vector velocity/acceleration loops solved with cross products.
    Points A, B, C, D[, E]; links "1" (A->B), "2" (B->C), "3" (D->C).
    """
    th = np.asarray(theta, dtype=np.float64)
    shape = th.shape
    w = float(omega)
    ax_, ay_ = float(A[0]), float(A[1])
    dx_, dy_ = float(D[0]), float(D[1])

    c1, s1 = np.cos(th), np.sin(th)
    Bx, By = ax_ + lAB * c1, ay_ + lAB * s1
    Bvx, Bvy = -lAB * w * s1, lAB * w * c1
    Bax, Bay = -lAB * w * w * c1, -lAB * w * w * s1

    # position: circle(B, lBC) ∩ circle(D, lCD)
    vx, vy = dx_ - Bx, dy_ - By
    L = np.hypot(vx, vy)
    ex, ey = vx / L, vy / L
    a = (lBC * lBC - lCD * lCD + L * L) / (2.0 * L)
    h = np.sqrt(lBC * lBC - a * a)
    Cx = Bx + a * ex - branch * h * ey
    Cy = By + a * ey + branch * h * ex

    # velocity loop: vB + w2 k x rBC = w3 k x rDC
    rbx, rby = Cx - Bx, Cy - By
    rdx, rdy = Cx - dx_, Cy - dy_
    cr = rbx * rdy - rby * rdx  # cross(rBC, rDC)
    w2 = -(Bvx * rdx + Bvy * rdy) / cr
    w3 = -(Bvx * rbx + Bvy * rby) / cr

    # acceleration loop: e2 k x rBC - e3 k x rDC = -aB + w2^2 rBC - w3^2 rDC
    Rx = -Bax + w2 * w2 * rbx - w3 * w3 * rdx
    Ry = -Bay + w2 * w2 * rby - w3 * w3 * rdy
    e2 = (Rx * rdx + Ry * rdy) / cr
    e3 = (Rx * rbx + Ry * rby) / cr

    Cvx, Cvy = Bvx - w2 * rby, Bvy + w2 * rbx
    Cax = Bax - e2 * rby - w2 * w2 * rbx
    Cay = Bay + e2 * rbx - w2 * w2 * rby

    zero = np.zeros(shape)
    out = {
        "A": _point(np.full(shape, ax_), np.full(shape, ay_), zero, zero, zero, zero, shape),
        "B": _point(Bx, By, Bvx, Bvy, Bax, Bay, shape),
        "C": _point(Cx, Cy, Cvx, Cvy, Cax, Cay, shape),
        "D": _point(np.full(shape, dx_), np.full(shape, dy_), zero, zero, zero, zero, shape),
    }
    if lBE is not None and lCE is not None:
        beta = math.acos((lBE * lBE + lBC * lBC - lCE * lCE) / (2.0 * lBE * lBC))
        cb, sb = math.cos(beta), math.sin(beta)
        k = lBE / lBC
        # rBE = rotate(rBC, +beta) * lBE / lBC
        qx = k * (cb * rbx - sb * rby)
        qy = k * (sb * rbx + cb * rby)
        out["E"] = _point(
            Bx + qx, By + qy,
            Bvx - w2 * qy, Bvy + w2 * qx,
            Bax - e2 * qy - w2 * w2 * qx, Bay + e2 * qx - w2 * w2 * qy, shape,
        )
    out["1"] = _link(np.arctan2(s1, c1), np.full(shape, w), zero, shape)
    out["2"] = _link(np.arctan2(rby, rbx), w2, e2, shape)
    out["3"] = _link(np.arctan2(rdy, rdx), w3, e3, shape)
    return out


PRESETS: dict[str, Callable[[ArrayLike], dict[str, F64]]] = {
    "slider_crank": lambda th: slider_crank(0.1, 0.4, 0.0, rpm(1500), th, 0.0, 0.3),
    "offset_slider_crank": lambda th: slider_crank(0.08, 0.3, 0.03, rpm(-600), th, 0.0, 0.35),
    "machine_unit": lambda th: slider_crank(0.075, 0.383, 0.0, rpm(300), th, 0.0, 0.35),
    "four_bar": lambda th: four_bar((0.0, 0.0), (0.25, 0.0), 0.08, 0.26, 0.18, 10.0, th, 1,
                                    0.15, 0.18),
}


def preset(name: str, theta: ArrayLike) -> dict[str, F64]:
    """Closed-form evaluation of a shared preset (same names/parameters as ``mpref``)."""
    return PRESETS[name](theta)
