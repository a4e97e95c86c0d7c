"""A linear driver's law given by a table over time: q(t) through a cubic spline.

The table's rows (t_i, q_i) — times strictly increasing, in s; the driver's coordinate in m — are
interpolated by scipy's ``CubicSpline`` (not-a-knot ends), so q, q̇ and q̈ are continuous. The
first driver's coordinate is the independent variable of every plan: its spline must be strictly
monotonic over the table (checked on a fine grid, not only at the rows), and the time of a
position is found by inverting it (bisection in the row interval, then Newton steps). A second
driver's coordinate and rates are its own spline at that time.

The interpolation error is estimated by Richardson's rule: the spline through every other row
differs from the full one by about (2ᵖ − 1) times the full spline's error, p = 4, 3, 2 for q, q̇,
q̈ (the orders of cubic-spline interpolation and its derivatives).
"""

from __future__ import annotations

import functools
import itertools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from scipy.interpolate import CubicSpline

if TYPE_CHECKING:
    from .mechanism import Drive

#: samples per row interval where monotonicity and the interpolation error are looked at
DENSE = 64


@dataclass(frozen=True, slots=True)
class TableLaw:
    """A driver's q(t) by its rows: ``times`` (s, increasing) and ``values`` (m)."""

    times: tuple[float, ...]
    values: tuple[float, ...]
    source: str = "table"      # "table" or the CSV file's name as the scene gives it

    @property
    def span(self) -> tuple[float, float]:
        """(first, last) time of the table (s)."""
        return self.times[0], self.times[-1]

    @property
    def q_range(self) -> tuple[float, float]:
        """The coordinate at the table's first and last time (m)."""
        return self.values[0], self.values[-1]

    def mean_rate(self) -> float:
        """(q_last − q_first) / (t_last − t_first): the rate a report states for the law."""
        (t0, t1), (q0, q1) = self.span, self.q_range
        return (q1 - q0) / (t1 - t0)


@functools.lru_cache(maxsize=64)
def spline(law: TableLaw) -> CubicSpline:
    """The law's cubic spline (cached: a law is frozen)."""
    return CubicSpline(np.asarray(law.times), np.asarray(law.values))


def _dense(law: TableLaw) -> np.ndarray:
    t = np.asarray(law.times)
    steps = np.linspace(0.0, 1.0, DENSE, endpoint=False)
    return np.concatenate([(a + (b - a) * steps) for a, b in itertools.pairwise(t)]
                          + [t[-1:]])


def turning_time(law: TableLaw) -> float | None:
    """A time where the spline's q̇ changes sign or vanishes (None: strictly monotonic)."""
    t = _dense(law)
    rate = spline(law)(t, 1)
    sign = np.sign(law.values[-1] - law.values[0]) or 1.0
    bad = np.nonzero(rate * sign <= 0.0)[0]
    return float(t[bad[0]]) if bad.size else None


def time_of(law: TableLaw, q: np.ndarray) -> np.ndarray:
    """t(q) for a strictly monotonic law (NaN outside the table's range of q)."""
    s = spline(law)
    q = np.asarray(q, dtype=float)
    values = np.asarray(law.values)
    times = np.asarray(law.times)
    rising = values[-1] > values[0]
    order = values if rising else values[::-1]
    i = np.searchsorted(order, q, side="right") - 1
    i = np.clip(i, 0, len(values) - 2)
    if not rising:
        i = len(values) - 2 - i
    lo, hi = times[i].copy(), times[i + 1].copy()
    sense = 1.0 if rising else -1.0
    for _ in range(64):                  # bisection: the interval holds the one crossing
        mid = 0.5 * (lo + hi)
        above = (s(mid) - q) * sense > 0.0
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    t = 0.5 * (lo + hi)
    for _ in range(2):                   # Newton polishes the last bits
        t = t - (s(t) - q) / s(t, 1)
    outside = (q - min(law.q_range)) * (q - max(law.q_range)) > 0.0
    return np.where(outside | ~np.isfinite(q), np.nan, t)


def at_time(law: TableLaw, t: np.ndarray, order: int) -> np.ndarray:
    """q (order 0), q̇ (1) or q̈ (2) at times t (NaN outside the table's span)."""
    t = np.asarray(t, dtype=float)
    out = spline(law)(t, order)
    t0, t1 = law.span
    return np.where((t < t0) | (t > t1), np.nan, out)


def interpolation_error(law: TableLaw) -> tuple[float, float, float]:
    """Estimated largest errors of q, q̇, q̈ over the table (m, m/s, m/s²), by Richardson's rule
    against the spline through every other row (the last row always kept)."""
    times, values = np.asarray(law.times), np.asarray(law.values)
    keep = list(range(0, len(times), 2))
    if keep[-1] != len(times) - 1:
        keep.append(len(times) - 1)
    coarse = CubicSpline(times[keep], values[keep])
    fine = spline(law)
    t = _dense(law)
    return tuple(float(np.max(np.abs(fine(t, k) - coarse(t, k)))) / (2.0 ** p - 1.0)
                 for k, p in ((0, 4), (1, 3), (2, 2)))   # type: ignore[return-value]


def largest(law: TableLaw, order: int) -> float:
    """The largest |q̇| (1) or |q̈| (2) over the table: the size of its plans."""
    return float(np.max(np.abs(spline(law)(_dense(law), order))))


def finite_rows(times: list[float], values: list[float]) -> bool:
    """Tell whether every row is finite."""
    return all(math.isfinite(x) for x in (*times, *values))


def driver_time(drive: Drive, q: np.ndarray) -> np.ndarray:
    """The time (s) at which a driver's coordinate is q, from its reference: a law by a table
    inverted; at constant rates (q − q⁰)/q̇ for a linear driver (q⁰ its range's start, else 0) and
    φ/|ω| for a crank (q its φ in its own sense)."""
    q = np.asarray(q, dtype=float)
    if drive.law is not None:
        return time_of(drive.law, q)
    if not drive.linear:
        return q / abs(drive.omega)
    ref = drive.q_range[0] if drive.q_range is not None else 0.0
    return (q - ref) / drive.omega
