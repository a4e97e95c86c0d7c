"""Scalar forms of the linear drivers' operations (``ops/drivers.py``) for the fused kernel.

Each mirrors its vectorised evaluator, the same formulas in the same order, so the kernel's values
equal the numpy path's; a guide's direction is the numpy path's own cos/sin, taken once here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..geom.vec import direction
from .ops import Op, OpSpec
from .step import Step

if TYPE_CHECKING:
    from .kernel_scalar import Gen, ScalarGen


def _lit(x: float) -> str:
    from .kernel_scalar import literal

    return literal(x)


def _coordinate(g: ScalarGen, s: Step, n: str) -> None:
    g.emit(f"{n} = REF + SENSE * phi[i]")


def _rate(g: ScalarGen, s: Step, n: str) -> None:
    g.emit(f"{n} = {_lit(float(s.param('value')))}")


def _unit_of(s: Step) -> tuple[str, str]:
    ux, uy = direction(np.asarray(s.param("dir_angle"), dtype=float))
    return _lit(float(ux)), _lit(float(uy))


def _along_guide(g: ScalarGen, s: Step, n: str, start: str, amount: str) -> None:
    (bx, by), q = g.pt(s.input(start)), g.name(s.input(amount))
    ux, uy = _unit_of(s)
    g.emit(f"{n}x = {bx} + {q} * {ux}", f"{n}y = {by} + {q} * {uy}")


def _guide_point(g: ScalarGen, s: Step, n: str) -> None:
    _along_guide(g, s, n, "base", "coordinate")


def _guide_vector(g: ScalarGen, s: Step, n: str) -> None:
    _along_guide(g, s, n, "start", "rate")


def _slide_vector(g: ScalarGen, s: Step, n: str) -> None:
    (sx, sy), rate = g.pt(s.input("start")), g.name(s.input("rate"))
    (px, py), (qx, qy) = g.pt(s.input("p")), g.pt(s.input("q"))
    g.emit(f"_vx = {qx} - {px}", f"_vy = {qy} - {py}", "_nn = _hyp(_vx, _vy)",
           f"{n}x = {sx} + {rate} * _div(_vx, _nn)", f"{n}y = {sy} + {rate} * _div(_vy, _nn)")


def _circle_circle_driven(g: ScalarGen, s: Step, n: str) -> str:
    from .kernel_scalar import circle_meet

    # the second radius is the driven length, a step of its own; its sine is squared
    return circle_meet(g, s, n, _lit(s.param("r1")), g.name(s.input("radius2")),
                       sine_squared=True)


#: the linear drivers' scalar forms (merged into ``kernel_scalar.SCALAR_FORMS``)
DRIVER_FORMS: dict[OpSpec, Gen] = {
    Op.DRIVER_COORDINATE: _coordinate, Op.DRIVER_RATE: _rate, Op.GUIDE_POINT: _guide_point,
    Op.GUIDE_VECTOR: _guide_vector, Op.SLIDE_VECTOR: _slide_vector,
    Op.CIRCLE_CIRCLE_DRIVEN: _circle_circle_driven,
}
