"""Scalar forms of the triads' operations (``ops/triad.py``) for the fused kernel.

The base link's angle calls the one-position solver ``kernel_triad._triad_angle`` (the numpy
path's algorithm, ``ops/triad_solve.py``); the first inner point is the two arcs' meet with the
second centre turned with the base link, and a leg's line its two points' direction — each the
same formulas in the same order as its vectorised evaluator. ``moment_along`` is a force step:
force steps have no kernel.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .ops import Op, OpSpec
from .ops.triad import params
from .step import Step

if TYPE_CHECKING:
    from .kernel_scalar import Gen, ScalarGen


def _lit(x: float) -> str:
    from .kernel_scalar import literal

    return literal(x)


def tuple_literal(xs: tuple[float, ...]) -> str:
    """A tuple of float literals (each reads back to the same binary value)."""
    return "(" + ", ".join(_lit(v) for v in xs) + ",)"


def emit_root(g: ScalarGen, n: str, call: str) -> str:
    """A class III group's closure solved by ``call`` (θ, gap, sine): its value ``n``, the
    position marked cannot-build where the gap is not ≤ 0 or the sine below the least."""
    g.emit(f"_t{n} = {call}", f"{n} = _t{n}[0]", f"_gap{n} = _t{n}[1]",
           f"sn{n} = _t{n}[2]", f"bad_i = bad_i | (not (_gap{n} <= 0.0)) | (sn{n} < MIN_SINE)")
    return f"sn{n}"


def _triad_angle(g: ScalarGen, s: Step, n: str) -> str:
    from .kernel_triad import CONSTANTS, window_trig

    t = params(s)
    a = [c for name in ("a1", "a2", "a3") for c in g.pt(s.input(name))]
    consts = [t.l1, t.l2, t.l3, *t.d2, *t.d3, float(t.sigma), float(t.slope), t.ref, t.size]
    counts, tols = CONSTANTS
    args = ", ".join([*a, *(_lit(v) for v in consts), repr(counts), tuple_literal(tols),
                      *(tuple_literal(v) for v in window_trig(t.ref))])
    return emit_root(g, n, f"_triad_angle({args})")


def turned(g: ScalarGen, n: str, theta: str, d: tuple[float, float]) -> tuple[str, str]:
    """R(θ)·d, a vector of the base link turned with it: the names of its components."""
    dx, dy = (_lit(v) for v in d)
    g.emit(f"_c = math.cos({theta})", f"_s = math.sin({theta})",
           f"_rx{n} = _c * {dx} - _s * {dy}", f"_ry{n} = _s * {dx} + _c * {dy}")
    return f"_rx{n}", f"_ry{n}"


def _triad_point(g: ScalarGen, s: Step, n: str) -> str:
    from .kernel_scalar import circle_meet

    t = params(s)
    a1, a2, angle = s.input("a1"), s.input("a2"), s.input("angle")
    (x2, y2), th = g.pt(a2), g.name(angle)
    rx, ry = turned(g, n, th, t.d2)
    g.emit(f"_cx{n} = {x2} - {rx}", f"_cy{n} = {y2} - {ry}")
    return circle_meet(g, s, n, _lit(t.l1), _lit(t.l2),
                       centres=(g.pt(a1), (f"_cx{n}", f"_cy{n}")))


def _line_through(g: ScalarGen, s: Step, n: str) -> None:
    (px, py), (qx, qy) = g.pt(s.input("p")), g.pt(s.input("q"))
    g.emit(f"_vx = {qx} - {px}", f"_vy = {qy} - {py}", "_nn = _hyp(_vx, _vy)",
           f"{n}px = {px}", f"{n}py = {py}", f"{n}ux = _div(_vx, _nn)", f"{n}uy = _div(_vy, _nn)")


#: the triads' scalar forms (merged into ``kernel_scalar.SCALAR_FORMS``)
TRIAD_FORMS: dict[OpSpec, Gen] = {
    Op.TRIAD_ANGLE: _triad_angle, Op.TRIAD_POINT: _triad_point, Op.LINE_THROUGH: _line_through,
}
