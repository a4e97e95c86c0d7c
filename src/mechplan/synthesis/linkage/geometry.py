"""Small plane helpers of the K-circle constructions (SI, plain floats)."""

from __future__ import annotations

import math
from collections.abc import Callable

Vec = tuple[float, float]
GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


def sub(a: Vec, b: Vec) -> Vec:
    """a − b."""
    return a[0] - b[0], a[1] - b[1]


def add(a: Vec, b: Vec) -> Vec:
    """a + b."""
    return a[0] + b[0], a[1] + b[1]


def mul(a: Vec, k: float) -> Vec:
    """k·a."""
    return a[0] * k, a[1] * k


def norm(a: Vec) -> float:
    """|a|."""
    return math.hypot(a[0], a[1])


def unit(a: Vec) -> Vec:
    """a/|a|."""
    n = norm(a)
    return a[0] / n, a[1] / n


def cross(a: Vec, b: Vec) -> float:
    """The z component of a × b."""
    return a[0] * b[1] - a[1] * b[0]


def polar(r: float, angle: float, origin: Vec = (0.0, 0.0)) -> Vec:
    """origin + r·(cos, sin)(angle)."""
    return origin[0] + r * math.cos(angle), origin[1] + r * math.sin(angle)


def angle_of(a: Vec) -> float:
    """The direction of a (rad, −π…π)."""
    return math.atan2(a[1], a[0])


def angle_between(a: Vec, b: Vec) -> float:
    """The unsigned angle between a and b (rad, 0…π)."""
    return math.atan2(abs(cross(a, b)), a[0] * b[0] + a[1] * b[1])


def rotate(a: Vec, angle: float) -> Vec:
    """a turned by angle (rad, counter-clockwise)."""
    c, s = math.cos(angle), math.sin(angle)
    return c * a[0] - s * a[1], s * a[0] + c * a[1]


def bisect(f: Callable[[float], float], lo: float, hi: float, iterations: int = 200) -> float:
    """A root of f between lo and hi where f changes sign (to the last bit)."""
    f_lo = f(lo)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        f_mid = f(mid)
        if (f_mid < 0) == (f_lo < 0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def maximise(f: Callable[[float], float], lo: float, hi: float, samples: int = 721) -> float:
    """The argument of the largest f on [lo, hi]: a dense sample, then a golden-section search."""
    ts = [lo + (hi - lo) * i / (samples - 1) for i in range(samples)]
    values = [f(t) for t in ts]
    best = max(range(samples), key=lambda i: values[i] if values[i] == values[i] else -math.inf)
    a, b = ts[max(best - 1, 0)], ts[min(best + 1, samples - 1)]
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(200):
        if abs(b - a) <= 1e-15 * max(1.0, abs(a)):
            break
        if fc > fd:
            b, d, fd = d, c, fc
            c = b - GOLDEN * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLDEN * (b - a)
            fd = f(d)
    return 0.5 * (a + b)


def roots(f: Callable[[float], float], lo: float, hi: float, samples: int = 721) -> list[float]:
    """Every root of f on [lo, hi] where it changes sign between dense samples."""
    ts = [lo + (hi - lo) * i / (samples - 1) for i in range(samples)]
    fs = [f(t) for t in ts]
    out = []
    for i in range(samples - 1):
        if fs[i] == 0.0:
            out.append(ts[i])
        elif (fs[i] < 0) != (fs[i + 1] < 0) and fs[i + 1] != 0.0:
            out.append(bisect(f, ts[i], ts[i + 1]))
    if fs[-1] == 0.0:
        out.append(ts[-1])
    return out
