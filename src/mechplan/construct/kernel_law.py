"""Scalar helpers of the drivers' laws by a table (``driver_law``, ``crank_law``) for the fused
kernel: a cubic spline's value and derivatives (scipy's ``PPoly`` evaluation, the same operations
in the same order: bit for bit the numpy path's) and the time of a position (the first driver's
table inverted as ``model.law.time_of`` does: bisection, then two Newton steps).

A table enters the generated source as literal tuples: its times and the spline's coefficients,
interval by interval (``coefs[4·i + r]`` = ``CubicSpline.c[r, i]``, highest power first).
Compiled by numba once per machine like ``kernel_helpers``; plain Python without it.
"""

from __future__ import annotations

import math

from .kernel_helpers import _div, _jit

NAN = math.nan


@_jit
def _pp(x: float, times: tuple[float, ...], coefs: tuple[float, ...], order: int) -> float:
    """The spline (``order`` 0) or its derivative at x, extrapolated beyond the table."""
    n = len(times) - 1
    if math.isnan(x):
        return NAN
    if x >= times[n]:
        i = n - 1
    elif x < times[0]:
        i = 0
    else:
        lo, hi = 0, n
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if times[mid] <= x:
                lo = mid
            else:
                hi = mid
        i = lo
    s = x - times[i]
    res = 0.0
    z = 1.0
    for kp in range(4):
        prefactor = 1.0
        if order > 0:
            if kp < order:
                continue
            for k in range(kp, kp - order, -1):
                prefactor *= k
        res = res + coefs[4 * i + 3 - kp] * z * prefactor
        if kp < 3 and kp >= order:
            z *= s
    return res


@_jit
def _law_at(t: float, times: tuple[float, ...], coefs: tuple[float, ...], order: int) -> float:
    """q, q̇ or q̈ at time t by the table's spline (NaN outside its span)."""
    if t < times[0] or t > times[len(times) - 1]:
        return NAN
    value: float = _pp(t, times, coefs, order)
    return value


@_jit
def _law_time(q: float, times: tuple[float, ...], values: tuple[float, ...],
              coefs: tuple[float, ...]) -> float:
    """t(q) for a strictly monotonic table (NaN outside its range of q)."""
    n = len(values)
    rising = values[n - 1] > values[0]
    count = 0                            # searchsorted(order, q, side="right")
    for j in range(n):
        v = values[j] if rising else values[n - 1 - j]
        if v <= q:
            count = j + 1
    i = min(max(count - 1, 0), n - 2)
    if not rising:
        i = n - 2 - i
    lo, hi = times[i], times[i + 1]
    sense = 1.0 if rising else -1.0
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        if (_pp(mid, times, coefs, 0) - q) * sense > 0.0:
            hi = mid
        else:
            lo = mid
    t = 0.5 * (lo + hi)
    for _ in range(2):
        t = t - _div(_pp(t, times, coefs, 0) - q, _pp(t, times, coefs, 1))
    q0, q1 = values[0], values[n - 1]
    if not (abs(q) < math.inf) or (q - min(q0, q1)) * (q - max(q0, q1)) > 0.0:
        return NAN
    return t


@_jit
def _where_finite(t: float, value: float) -> float:
    """``value`` where t is finite, NaN elsewhere (a constant rate at a position's time)."""
    return value if abs(t) < math.inf else NAN
