"""Operations of the instant-centre construction, in homogeneous coordinates (vectorised).

A centre is a homogeneous point ``(x/L, y/L, w)`` of shape ``(N, 3)``, L the mechanism's length
scale: ``w = 1`` for a centre at ``(x, y)``, ``w = 0`` for a centre at infinity in the direction
``(x, y)`` (unit). A line is the homogeneous vector ``(a, b, c)`` of ``a·x + b·y + c·w = 0``,
scaled to unit norm. The line through two centres is their cross product and the meet of two lines
is theirs, so a centre at infinity takes part in Kennedy's construction like any other (the line
through a pin and a centre at infinity is the line through the pin in that direction) and is never
a huge number.

These operations do not join the step DAG of the plans (``ops.FAMILIES``): the centres are a
construction of their own, evaluated on the positions of an evaluated construction only when a
scene asks for them (``construct/plans/centres.py``).
"""

from __future__ import annotations

import numpy as np

from ...geom.vec import Array

#: a homogeneous vector shorter than this (relative, unit inputs) has no direction: the two
#: centres (or lines) it joins coincide
DEGENERATE = 1e-13
#: a centre whose w is below this fraction of its (x, y) is at infinity (beyond 10¹⁴ L)
AT_INFINITY = 1e-14


def finite(p: Array, length: float) -> Array:
    """The homogeneous centre of points ``p`` (N, 2) in metres: ``(x/L, y/L, 1)``."""
    out = np.empty((p.shape[0], 3))
    out[:, :2] = p / length
    out[:, 2] = 1.0
    return out


def infinite(u: Array) -> Array:
    """The homogeneous centre at infinity in the directions ``u`` (N, 2), made unit."""
    out = np.zeros((u.shape[0], 3))
    out[:, :2] = u / np.hypot(u[:, 0], u[:, 1])[:, None]
    return out


def _unit_rows(h: Array) -> tuple[Array, Array]:
    n = np.linalg.norm(h, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return h / n[:, None], n


def join(p: Array, q: Array) -> tuple[Array, Array]:
    """The line through two centres and its conditioning ``|p̂ × q̂|`` (0: they coincide).

    The line is unit (NaN where the centres coincide)."""
    pu, _ = _unit_rows(p)
    qu, _ = _unit_rows(q)
    line, size = _unit_rows(np.cross(pu, qu))
    line[size < DEGENERATE] = np.nan
    return line, size


def meet(l1: Array, l2: Array) -> tuple[Array, Array, Array]:
    """The meet of two unit lines: the centre (normalised), ``|l1 × l2|`` and the sine of the
    lines' crossing angle on the plane.

    ``|l1 × l2|`` → 0 when the lines coincide (the centre is indeterminate: NaN); the sine → 0
    when they are parallel (the centre goes to infinity — not an error)."""
    m = np.cross(l1, l2)
    size = np.linalg.norm(m, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        sine = m[:, 2] / (np.hypot(l1[:, 0], l1[:, 1]) * np.hypot(l2[:, 0], l2[:, 1]))
    centre = normalised(m)
    centre[~(size >= DEGENERATE)] = np.nan
    return centre, size, np.abs(sine)


def normalised(h: Array) -> Array:
    """Centres in normal form: ``w = 1`` for finite ones, ``w = 0`` and ``(x, y)`` unit for those
    at infinity (the sign of the direction chosen so its angle is in (−90°, 90°])."""
    out = np.array(h, dtype=float)
    xy = np.hypot(out[:, 0], out[:, 1])
    inf = np.abs(out[:, 2]) <= AT_INFINITY * xy
    with np.errstate(invalid="ignore", divide="ignore"):
        fin = ~inf
        out[fin] /= out[fin, 2:3]
        d = out[inf, :2] / xy[inf, None]
        flip = (d[:, 0] < 0) | ((d[:, 0] == 0) & (d[:, 1] < 0))
        d[flip] *= -1.0
        out[inf, :2] = d
        out[inf, 2] = 0.0
    return out


def is_infinite(h: Array) -> Array:
    """Which centres (normal form) are at infinity."""
    out: Array = h[:, 2] == 0.0
    return out


def point(h: Array, length: float) -> Array:
    """The (N, 2) positions in metres of centres in normal form (NaN for those at infinity)."""
    out = h[:, :2] * length
    out[is_infinite(h)] = np.nan
    return out


def direction(h: Array) -> Array:
    """The (N, 2) unit directions of centres at infinity (NaN for finite ones)."""
    out = np.array(h[:, :2])
    out[~is_infinite(h)] = np.nan
    return out
