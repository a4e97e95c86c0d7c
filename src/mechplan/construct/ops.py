"""Evaluators of construction operations: pure vectorised functions of input values.

Each evaluator returns ``(value, gap, sine)``; ``gap``/``sine`` are None unless the step is a meet
(see :mod:`mechplan.geom.meet`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..geom import meet
from ..geom.vec import (
    Array,
    angle_of,
    as_complex,
    cross,
    direction,
    dot,
    from_complex,
    norm,
    perp,
    rotate,
)
from .step import Op, Step

Result = tuple[Array, Array | None, Array | None]


def _line(point: Array, u: Array) -> Array:
    # component-wise copies: numpy's inner loop over a trailing axis of 2 is ~5x slower
    out = np.empty(np.broadcast_shapes(point.shape, u.shape)[:-1] + (2, 2),
                   np.result_type(point, u))
    out[..., 0, 0], out[..., 0, 1] = point[..., 0], point[..., 1]
    out[..., 1, 0], out[..., 1, 1] = u[..., 0], u[..., 1]
    return out


def _scaled(k: Array, v: Array) -> Array:
    """Return k[..., None] * v for k (N,) and v (N, 2), one component at a time (same values)."""
    out = np.empty(np.broadcast_shapes(k.shape + (2,), v.shape), np.result_type(k, v))
    np.multiply(k, v[..., 0], out=out[..., 0])
    np.multiply(k, v[..., 1], out=out[..., 1])
    return out


def _unit(v: Array) -> Array:
    """Return v / |v| like :func:`vec.unit`, one component at a time (same values)."""
    n = norm(v)
    out = np.empty(v.shape, np.result_type(v, n))
    with np.errstate(invalid="ignore", divide="ignore"):
        np.divide(v[..., 0], n, out=out[..., 0])
        np.divide(v[..., 1], n, out=out[..., 1])
    return out


def _complex(v: Array) -> Array:
    """View (N, 2) float vectors as complex numbers without a copy where the layout allows."""
    if v.dtype in (np.float64, np.float32) and v.flags.c_contiguous and v.shape[-1] == 2:
        return v.view(np.complex128 if v.dtype == np.float64 else np.complex64)[..., 0]
    return as_complex(v)


def _from_complex(z: Array) -> Array:
    if z.dtype in (np.complex128, np.complex64) and z.flags.c_contiguous:
        return z.view(np.float64 if z.dtype == np.complex128 else np.float32).reshape(z.shape + (2,))
    return from_complex(z)


def _fixed_point(step: Step, n: int) -> Result:
    xy = np.asarray(step.param("xy"), dtype=float)
    return np.tile(xy, (n, 1)), None, None


def _polar(step: Step, centre: Array, angle: Array) -> Result:
    return centre + step.param("length") * direction(angle + step.param("offset", 0.0)), None, None


def _angle_of(step: Step, p: Array, q: Array) -> Result:
    return angle_of(q - p) - step.param("minus", 0.0), None, None


def _angle_plus(step: Step, angle: Array) -> Result:
    return angle + step.param("delta"), None, None


def _circle_circle(step: Step, c1: Array, c2: Array) -> Result:
    return meet.circle_circle(c1, step.param("r1"), c2, step.param("r2"), step.param("sigma"))


def _circle_line(step: Step, c: Array, line: Array) -> Result:
    return meet.circle_line(c, step.param("r"), line[..., 0, :], line[..., 1, :], step.param("sigma"))


def _line_line(step: Step, l1: Array, l2: Array) -> Result:
    return meet.line_line(l1[..., 0, :], l1[..., 1, :], l2[..., 0, :], l2[..., 1, :])


def _locus_line(step: Step, base: Array, *angle: Array) -> Result:
    offset = np.asarray(step.param("offset"), dtype=base.dtype)
    if not angle:
        # a guide of the frame: the same direction at every position; rotating by a zero angle
        # and taking cos/sin once give the values the per-position evaluation would
        zero = np.zeros(1, dtype=base.dtype)
        point = base + rotate(offset, zero)
        return _line(point, direction(zero + step.param("dir_angle"))), None, None
    theta = angle[0]
    c, s = np.cos(theta), np.sin(theta)
    # rotate(offset, theta) with the cosine and sine computed once
    point = base + np.stack((c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]), axis=-1)
    dir_angle = step.param("dir_angle")
    u = np.stack((c, s), axis=-1) if dir_angle == 0.0 else direction(theta + dir_angle)
    return _line(point, u), None, None


def _carrier_angle(step: Step, pc: Array, ps: Array) -> Result:
    """Angle of a guide carrier pivoting at pc whose guide must pass through ps."""
    rel = ps - pc
    q0 = np.asarray(step.param("q0"), dtype=rel.dtype)
    d = direction(np.asarray(step.param("dir_angle"), dtype=rel.dtype))
    radius = np.hypot(rel[..., 0], rel[..., 1])
    # the circle's centre and the guide are the same at every position: pass them once, (1, 2),
    # and let numpy broadcast (same values as (N, 2) copies, without N-sized work on constants)
    origin = np.zeros((1, 2), dtype=rel.dtype)
    hit, gap, sine = meet.circle_line(origin, radius, q0[None, :], d[None, :], step.param("sigma"))
    return angle_of(rel) - angle_of(hit), gap, sine


def _place(step: Step, origin: Array, angle: Array) -> Result:
    return origin + rotate(np.asarray(step.param("offset"), dtype=origin.dtype), angle), None, None


def _similar_position(step: Step, a: Array, b: Array) -> Result:
    za, zb = _complex(a), _complex(b)
    return _from_complex(za + (zb - za) * step.param("z")), None, None


def _similar_image(step: Step, a: Array, b: Array, pa: Array, pb: Array, px: Array) -> Result:
    za, zb = _complex(a), _complex(b)
    zpa = _complex(pa)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = (_complex(px) - zpa) / (_complex(pb) - zpa)
    return _from_complex(za + (zb - za) * ratio), None, None


def _rigid_velocity(step: Step, o: Array, omega: Array, po: Array, px: Array) -> Result:
    return o + _scaled(omega, perp(px - po)), None, None


def _rigid_acceleration(step: Step, o: Array, omega: Array, eps: Array, po: Array,
                        px: Array) -> Result:
    r = px - po
    return o + _scaled(eps, perp(r)) - _scaled(omega * omega, r), None, None


def _constant(step: Step, n: int) -> Result:
    return np.full(n, float(step.param("value"))), None, None


def _pole(step: Step, n: int) -> Result:
    return np.zeros((n, 2)), None, None


def _drive_velocity(step: Step, a: Array, b: Array) -> Result:
    return step.param("omega") * perp(b - a), None, None


def _drive_acceleration(step: Step, a: Array, b: Array) -> Result:
    r = b - a
    omega, eps = step.param("omega"), step.param("epsilon", 0.0)
    return eps * perp(r) - omega * omega * r, None, None


def _line_perp(step: Step, through: Array, p: Array, q: Array) -> Result:
    return _line(through, _unit(perp(q - p))), None, None


def _line_parallel(step: Step, through: Array, line: Array) -> Result:
    return _line(through, line[..., 1, :]), None, None


def _omega(step: Step, p: Array, q: Array, vp: Array, vq: Array) -> Result:
    r = q - p
    return cross(r, vq - vp) / dot(r, r), None, None


def _epsilon(step: Step, p: Array, q: Array, n: Array, aq: Array) -> Result:
    r = q - p
    return cross(r, aq - n) / dot(r, r), None, None


def _normal(step: Step, ap: Array, omega: Array, p: Array, q: Array) -> Result:
    return ap - _scaled(omega * omega, q - p), None, None


def _coriolis(step: Step, start: Array, omega: Array, v_from: Array, v_to: Array) -> Result:
    return start + _scaled(2.0 * omega, perp(v_to - v_from)), None, None


def _copy(step: Step, x: Array) -> Result:
    return x, None, None


def _difference(step: Step, a: Array, b: Array) -> Result:
    return b - a, None, None


EVALUATORS: dict[Op, Callable[..., Result]] = {
    Op.POLAR_POINT: _polar,
    Op.ANGLE_OF: _angle_of,
    Op.ANGLE_PLUS: _angle_plus,
    Op.CIRCLE_CIRCLE: _circle_circle,
    Op.CIRCLE_LINE: _circle_line,
    Op.LINE_LINE: _line_line,
    Op.LOCUS_LINE: _locus_line,
    Op.CARRIER_ANGLE: _carrier_angle,
    Op.PLACE: _place,
    Op.SIMILAR_POSITION: _similar_position,
    Op.SIMILAR_IMAGE: _similar_image,
    Op.RIGID_VELOCITY: _rigid_velocity,
    Op.RIGID_ACCELERATION: _rigid_acceleration,
    Op.DRIVE_VELOCITY: _drive_velocity,
    Op.DRIVE_ACCELERATION: _drive_acceleration,
    Op.LINE_PERP: _line_perp,
    Op.LINE_PARALLEL: _line_parallel,
    Op.OMEGA: _omega,
    Op.EPSILON: _epsilon,
    Op.NORMAL: _normal,
    Op.CORIOLIS: _coriolis,
    Op.COPY: _copy,
    Op.DIFFERENCE: _difference,
}

#: operations whose value depends only on the number of positions
SOURCES: dict[Op, Callable[[Step, int], Result]] = {
    Op.FIXED_POINT: _fixed_point,
    Op.POLE: _pole,
    Op.CONSTANT: _constant,
}
