"""Vector helpers on arrays of shape (..., 2)."""

from __future__ import annotations

from typing import cast

import numpy as np

Array = np.ndarray


def perp(v: Array) -> Array:
    """Rotate vectors by +90° (counter-clockwise)."""
    v = np.asarray(v)
    if v.dtype.kind != "f":
        return np.stack((-v[..., 1], v[..., 0]), axis=-1)
    out = np.empty_like(v)              # component-wise: no temporaries, the same values
    np.negative(v[..., 1], out=out[..., 0])
    out[..., 1] = v[..., 0]
    return out


def cross(a: Array, b: Array) -> Array:
    """Return the z component of a × b."""
    out = a[..., 0] * b[..., 1]
    if isinstance(out, np.ndarray) and out.base is None:
        np.subtract(out, a[..., 1] * b[..., 0], out=out)     # in place: the same values
        return out
    return cast(Array, out - a[..., 1] * b[..., 0])


def dot(a: Array, b: Array) -> Array:
    """Return a · b along the last axis."""
    out = a[..., 0] * b[..., 0]
    if isinstance(out, np.ndarray) and out.base is None:
        np.add(out, a[..., 1] * b[..., 1], out=out)          # in place: the same values
        return out
    return cast(Array, out + a[..., 1] * b[..., 1])


def norm(v: Array) -> Array:
    """Return the Euclidean length along the last axis.

    √(x² + y²) rather than hypot: a third of the time, and the same value to within a rounding
    for any length a mechanism has (hypot only guards against squares beyond the float range).
    """
    x, y = v[..., 0], v[..., 1]
    out = x * x
    out += y * y
    if isinstance(out, np.ndarray):
        return np.sqrt(out, out=out)
    return cast(Array, np.sqrt(out))


def unit(v: Array) -> Array:
    """Return v / |v| (NaN where |v| = 0)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return cast(Array, v / norm(v)[..., None])


def direction(angle: Array) -> Array:
    """Return unit vectors at the given angles (radians, counter-clockwise from +x)."""
    angle = np.asarray(angle)
    if angle.dtype.kind != "f":     # keep float32 evaluations in float32
        angle = angle.astype(float)
    return np.stack((np.cos(angle), np.sin(angle)), axis=-1)


def angle_of(v: Array) -> Array:
    """Return the direction angle of vectors in (-π, π]."""
    return cast(Array, np.arctan2(v[..., 1], v[..., 0]))


def rotate(v: Array, angle: Array) -> Array:
    """Rotate vectors counter-clockwise by angle (radians), broadcasting over positions."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack((c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]), axis=-1)


def as_complex(v: Array) -> Array:
    """View (..., 2) vectors as complex numbers."""
    return v[..., 0] + 1j * v[..., 1]


def from_complex(z: Array) -> Array:
    """Turn complex numbers back into (..., 2) vectors."""
    return np.stack((z.real, z.imag), axis=-1)
