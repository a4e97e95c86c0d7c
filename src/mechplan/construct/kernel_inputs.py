"""Scalar forms of the drivers' input operations (``ops/inputs.py``, ``ops/driver_inputs.py``)
for the fused kernel."""

from __future__ import annotations

from collections.abc import Sequence
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


def _tuple(values: Sequence[float]) -> str:
    from .kernel_scalar import literal

    return "(" + ", ".join(literal(v) for v in values) + ",)"


def _spline(times: Sequence[float], values: Sequence[float]) -> tuple[str, str]:
    """The literal tuples of a table: its times and its spline's coefficients, interval-major."""
    from ..model.law import TableLaw, spline

    c = spline(TableLaw(tuple(times), tuple(values))).c
    return _tuple(times), _tuple([float(c[r, i]) for i in range(c.shape[1]) for r in range(4)])


def _driver_law(g: ScalarGen, s: Step, n: str) -> None:
    """A driver's coordinate or rate at the time of a position (``ops/inputs.driver_law``)."""
    from .kernel_scalar import literal

    x = g.name(s.input("coordinate"))
    clock = s.param("clock_times", ())
    if clock:
        times, coefs = _spline(clock, s.param("clock_values"))
        g.emit(f"_t = _law_time({x}, {times}, {_tuple(s.param('clock_values'))}, {coefs})")
    else:
        a, b = literal(float(s.param("clock_a"))), literal(float(s.param("clock_b")))
        g.emit(f"_t = {a} + {b} * {x}")
    order = int(s.param("order"))
    own = s.param("times", ())
    if own:
        times, coefs = _spline(own, s.param("values"))
        g.emit(f"{n} = _law_at(_t, {times}, {coefs}, {order})")
    elif order == 0:
        q0, rate = literal(float(s.param("q0"))), literal(float(s.param("rate")))
        g.emit(f"{n} = {q0} + {rate} * _t")
    else:
        value = literal(float(s.param("rate" if order == 1 else "acceleration")))
        g.emit(f"{n} = _where_finite(_t, {value})")


#: the scalar forms of the second driver's operations
INPUT_FORMS: dict[OpSpec, Gen] = {Op.SECOND_CRANK_ANGLE: _second_crank_angle,
                                  Op.SECOND_DRIVER_LENGTH: _second_driver_length,
                                  Op.SECOND_SLIDER_POSITION: _second_driver_length,
                                  Op.CIRCLE_LINE_DRIVEN: _circle_line_driven,
                                  Op.DRIVER_LAW: _driver_law, Op.CRANK_LAW: _driver_law}
