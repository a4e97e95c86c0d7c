"""Scalar forms of the drivers' input operations (``ops/inputs.py``, ``ops/driver_inputs.py``)
for the fused kernel."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .ops import Op, OpSpec
from .step import Step

if TYPE_CHECKING:
    from .kernel_scalar import Gen, ScalarGen


def _second_crank_angle(g: ScalarGen, s: Step, n: str) -> None:
    from .kernel_scalar import literal

    offset, ratio = literal(float(s.param("offset"))), literal(float(s.param("ratio")))
    g.emit(f"{n} = {offset} + {ratio} * {g.name(s.input('angle'))}")


def _second_driver_length(g: ScalarGen, s: Step, n: str) -> None:
    from .kernel_scalar import literal

    offset, ratio = literal(float(s.param("offset"))), literal(float(s.param("ratio")))
    g.emit(f"{n} = {offset} + {ratio} * {g.name(s.input('coordinate'))}")


def _circle_line_driven(g: ScalarGen, s: Step, n: str) -> str:
    """An arc of the driven length cuts a guide line (``ops/driver_inputs.py``): its sine
    squared, as for two arcs of which one is driven."""
    from .kernel_scalar import _circle_line_core, literal

    (cx, cy), (px, py, ux, uy) = g.pt(s.input("centre")), g.line(s.input("guide"))
    _circle_line_core(g, n, cx, cy, g.name(s.input("radius")), px, py, ux, uy,
                      literal(s.param("sigma")))
    g.emit(f"sn{n} = sn{n} * sn{n}", f"bad_i = bad_i | (sn{n} < MIN_SINE)")
    return f"sn{n}"


#: the scalar forms of the second driver's operations
INPUT_FORMS: dict[OpSpec, Gen] = {Op.SECOND_CRANK_ANGLE: _second_crank_angle,
                                  Op.SECOND_DRIVER_LENGTH: _second_driver_length,
                                  Op.SECOND_SLIDER_POSITION: _second_driver_length,
                                  Op.CIRCLE_LINE_DRIVEN: _circle_line_driven}
