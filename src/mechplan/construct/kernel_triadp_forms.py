"""Scalar forms of the operations of class III groups with sliding legs (``ops/triadp.py``) for the
fused kernel.

The base link's angle calls the one-position solver ``kernel_triadp._triadp_angle`` (the numpy
path's algorithm, ``ops/triadp_solve.py``); B_1 is the meet of the first two legs' loci with the
second turned back by the base link's R(θ)·d2 (two arcs, an arc and a line, two lines); a slider
leg's line for the special point the normal to its guide — each the same formulas in the same order
as its vectorised evaluator. The velocity and acceleration plans through Assur's special point
(lines ⊥ or ∥, their meets, the Coriolis terms of a turning guide) are built of operations that
have their scalar forms already. ``leg_normal_force`` is a force step: force steps have no kernel.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .kernel_triad_forms import _lit, emit_root, tuple_literal, turned
from .ops import Op, OpSpec
from .ops.triadp import params
from .step import Kind, Step

if TYPE_CHECKING:
    from .kernel_scalar import Gen, ScalarGen


def _locus(g: ScalarGen, sid: str) -> list[str]:
    """A leg's locus as the solver takes it: a line's point and direction, or a point and 0, 0."""
    if g.c[sid].kind is Kind.LINE:
        return list(g.line(sid))
    return [*g.pt(sid), "0.0", "0.0"]


def _triadp_angle(g: ScalarGen, s: Step, n: str) -> str:
    from .kernel_triadp import CONSTANTS, KIND_CODES, grid_trig, group_args

    t = params(s)
    loci = [c for name in ("one", "two", "three") for c in _locus(g, s.input(name))]
    kinds = "(" + ", ".join(str(KIND_CODES[k]) for k in t.kinds) + ",)"
    args = ", ".join(["(" + ", ".join(loci) + ",)", kinds, tuple_literal(group_args(t)),
                      repr(CONSTANTS), *(tuple_literal(v) for v in grid_trig(t.ref))])
    return emit_root(g, n, f"_triadp_angle({args})")


def _triadp_point(g: ScalarGen, s: Step, n: str) -> str:
    from .kernel_scalar import _circle_line_core, circle_meet, line_meet
    from .kernel_triadp import group_args

    t = params(s)
    one, two, angle = s.input("one"), s.input("two"), s.input("angle")
    rx, ry = turned(g, n, g.name(angle), t.d2)
    if t.kinds[0] == "R" and t.kinds[1] == "R":
        (x2, y2), squares = g.pt(two), group_args(t)[14:16]
        g.emit(f"_cx{n} = {x2} - {rx}", f"_cy{n} = {y2} - {ry}")
        return circle_meet(g, s, n, _lit(t.l[0]), _lit(t.l[1]),
                           centres=(g.pt(one), (f"_cx{n}", f"_cy{n}")),
                           squares=(_lit(squares[0]), _lit(squares[1])))
    px, py, ux, uy = g.line(two)
    g.emit(f"_px{n} = {px} - {rx}", f"_py{n} = {py} - {ry}")
    if t.kinds[0] == "R":
        (cx, cy) = g.pt(one)
        _circle_line_core(g, n, cx, cy, _lit(t.l[0]), f"_px{n}", f"_py{n}", ux, uy,
                          _lit(s.param("sigma")))
        return f"sn{n}"
    return line_meet(g, n, g.line(one), (f"_px{n}", f"_py{n}", ux, uy))


def _normal_through(g: ScalarGen, s: Step, n: str) -> None:
    (x, y), (_, _, ux, uy) = g.pt(s.input("point")), g.line(s.input("guide"))
    g.emit(f"{n}px = {x}", f"{n}py = {y}", f"{n}ux = -{uy}", f"{n}uy = {ux}")


#: the sliding triads' scalar forms (merged into ``kernel_scalar.SCALAR_FORMS``)
TRIADP_FORMS: dict[OpSpec, Gen] = {
    Op.TRIADP_ANGLE: _triadp_angle, Op.TRIADP_POINT: _triadp_point,
    Op.NORMAL_THROUGH: _normal_through,
}
