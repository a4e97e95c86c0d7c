"""Scalar form of the second driver's operation (``ops/inputs.py``) for the fused kernel."""

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


#: the scalar forms of the second driver's operations
INPUT_FORMS: dict[OpSpec, Gen] = {Op.SECOND_CRANK_ANGLE: _second_crank_angle,
                                  Op.SECOND_DRIVER_LENGTH: _second_driver_length,
                                  Op.SECOND_SLIDER_POSITION: _second_driver_length}
