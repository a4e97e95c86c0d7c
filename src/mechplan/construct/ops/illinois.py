"""The Illinois secant on sign-changing brackets, vectorised over positions (the assembly's roots
of the class III groups' closures, found once)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ...geom.vec import Array


def illinois(f: Callable[[Array], Array], lo: Array, hi: Array, flo: Array, fhi: Array,
             iterations: int, clamp: bool = False) -> Array:
    """The root of ``f`` in each bracket [lo, hi] (f changes sign) to the last bit; ``clamp``:
    a secant point outside its bracket is replaced by the bracket's middle."""
    side = np.zeros(lo.shape)
    x = lo.copy()
    active = np.ones(lo.shape, bool)
    for _ in range(iterations):
        if not active.any():
            break
        with np.errstate(invalid="ignore", divide="ignore"):
            x = np.where(active, hi - fhi * (hi - lo) / (fhi - flo), x)
        if clamp:
            x = np.where(active & ~((x >= lo) & (x <= hi)), 0.5 * (lo + hi), x)
        fx = f(x)
        fx = np.where(np.isfinite(fx), fx, 0.0)
        same_hi = np.sign(fx) == np.sign(fhi)
        upd_hi, upd_lo = active & same_hi, active & ~same_hi
        # halve the stale end's value when the same end moves twice
        flo = np.where(upd_hi & (side == 1), 0.5 * flo, flo)
        fhi = np.where(upd_lo & (side == -1), 0.5 * fhi, fhi)
        hi, fhi = np.where(upd_hi, x, hi), np.where(upd_hi, fx, fhi)
        lo, flo = np.where(upd_lo, x, lo), np.where(upd_lo, fx, flo)
        side = np.where(upd_hi, 1, np.where(upd_lo, -1, side))
        active &= (fx != 0) & (np.abs(hi - lo) > 4e-16 * (1 + np.abs(x)))
    return x
