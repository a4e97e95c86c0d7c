"""The scalar helpers every generated kernel calls.

Compiled by numba once per machine (``cache=True``: on disk) and shared by every kernel, instead
of once in each kernel's module; plain Python functions without numba (the generated source runs
as plain Python too). The kernels' sources carry this file's digest (``kernel_load.HELPERS``), so
a kernel compiled against an older version of these helpers is never reused.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

NAN = math.nan
INF = math.inf


def _plain(f: Callable[..., Any]) -> Callable[..., Any]:
    return f


try:
    import numba

    _jit: Callable[[Callable[..., Any]], Callable[..., Any]] = numba.njit(
        cache=True, error_model="numpy")
except ImportError:                      # the fast extra is optional
    _jit = _plain


@_jit
def _div(a: float, b: float) -> float:
    """a / b with IEEE results for b = 0 (±inf, NaN for 0/0), also in plain Python."""
    if b == 0.0:
        if math.isnan(a) or a == 0.0:
            return NAN
        return INF if (a > 0.0) == (math.copysign(1.0, b) > 0.0) else -INF
    return a / b


@_jit
def _cdiv(a: complex, b: complex) -> complex:
    """a / b of complex numbers; NaN for b = 0."""
    if b == 0.0:
        return complex(NAN, NAN)
    return a / b


@_jit
def _hyp(x: float, y: float) -> float:
    """√(x² + y²), as ``geom.vec.norm`` computes it."""
    return math.sqrt(x * x + y * y)


@_jit
def _div_nz(a: float, b: float) -> float:
    """a / b, NaN for b = 0 (two parallel lines meet nowhere)."""
    return NAN if b == 0.0 else _div(a, b)


@_jit
def _height(h2: float, gap: float) -> float:
    """The half-chord of two circles or of a circle and a line from its square: 0 where they
    just touch (h² < 0 by rounding), NaN where they do not meet or a value is NaN."""
    if h2 < 0.0:
        return 0.0 if gap <= 0.0 else NAN
    return math.sqrt(h2)


@_jit
def _below1(x: float) -> float:
    """min(1, x) for the bound of the estimates (NaN stays NaN)."""
    return min(1.0, x)
