"""What one construction operation is: its inputs, evaluation, sentence, drawing and grading.

An :class:`OpSpec` is the one home of an operation. Its named inputs are the parameters of its
``evaluate`` function after ``step`` (in the order of ``Step.inputs``; a ``*name`` parameter takes
the rest); its protocol sentence is the catalogue message ``message`` (``locale/*/protocol.po``);
``draw`` and ``line`` say what a sheet draws for it; ``grade`` and ``hint`` say how the checker
grades a submitted point or line of it and which hint it gives; ``written`` how the protocol writes
its value.
"""

from __future__ import annotations

import enum
import inspect
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ...geom.vec import Array, as_complex, from_complex, norm
from ..step import Op

#: an evaluation: the value, and for a meet its gap and the sine of its crossing angle
Result = tuple[Array, Array | None, Array | None]


class Source(enum.Enum):
    """Where an operation's value comes from."""

    INPUTS = "inputs"  # evaluate(step, *input values)
    POSITIONS = "positions"  # evaluate(step, n): depends only on the number of positions
    DRIVE = "drive"  # the crank angle, from the construction's drive map


class Drawn(enum.Enum):
    """What a sheet draws for a step of this operation."""

    NOTHING = "nothing"  # a scalar or a value only written
    POINT = "point"  # a labelled point (an image)
    VERTEX = "vertex"  # a labelled vertex of a force polygon (or a pole)
    MEET = "meet"  # a labelled point where two construction lines meet
    CONSTRUCTION_LINE = "construction_line"  # a line from its point to (and past) its meet
    IMAGE_TRIANGLE = "image_triangle"  # a point joined to the two images it is similar to
    VECTOR = "vector"  # a force laid on a polygon, not a vertex of its own
    LEVER = "lever"  # Zhukovsky's lever: the turned plan with the loads


class Written(enum.Enum):
    """How the protocol writes a step's scalar value and its measured segments."""

    PLAIN = "plain"          # the value in its plan's unit (rad/s, rad/s², N·m)
    ANGLE = "angle"          # degrees
    RATE = "rate"            # ω or ε with its sense (counter-clockwise / clockwise)
    OFFSET = "offset"        # a distance of the force plan, in millimetres
    MEET = "meet"            # a point found by a construction: its segments after a colon


class Line(enum.Enum):
    """Line style of what is drawn (the sheet maps it to its layer roles)."""

    NONE = "none"
    DASHED = "dashed"
    THIN = "thin"
    OUTLINE = "outline"


class Grade(enum.Enum):
    """How the checker grades what a student submits for a step of this operation."""

    NOT_GRADED = "not_graded"  # given data or a value never drawn
    POINT = "point"  # the submitted point against the exact one, in paper mm
    MEET = "meet"  # a point found by two lines: graded as a point, lines by direction
    DIRECTION = "direction"  # a construction line: its direction through its point
    VALUE = "value"  # a scalar written in a table: relative error


@dataclass(frozen=True, slots=True)
class OpSpec:
    """One construction operation, declared once."""

    op: Op
    evaluate: Callable[..., Result] | None
    message: str | None  # protocol sentence; None: drawn, never written
    draw: Drawn = Drawn.NOTHING
    line: Line = Line.NONE
    grade: Grade = Grade.NOT_GRADED
    hint: str = "hint.step"  # key of the checker's hint for a wrong result
    source: Source = Source.INPUTS
    written: Written = Written.PLAIN     # how the protocol writes its value
    inputs: tuple[str, ...] = field(init=False)
    rest: str | None = field(init=False)  # name of a variable tail of inputs, if any

    def __post_init__(self) -> None:
        names: list[str] = []
        rest = None
        if self.evaluate is not None and self.source is Source.INPUTS:
            params = list(inspect.signature(self.evaluate).parameters.values())[1:]
            for p in params:
                if p.kind is inspect.Parameter.VAR_POSITIONAL:
                    rest = p.name
                else:
                    names.append(p.name)
        object.__setattr__(self, "inputs", tuple(names))
        object.__setattr__(self, "rest", rest)

    def index(self, name: str) -> int:
        """Position of a named input in ``Step.inputs``."""
        try:
            return self.inputs.index(name)
        except ValueError:
            raise KeyError(
                f"{self.op.value} has no input {name!r} (inputs: {self.inputs})"
            ) from None


# -- helpers shared by the evaluators -----------------------------------------------------------
def line(point: Array, u: Array) -> Array:
    """A line value (N, 2, 2): a point and a unit direction."""
    # component-wise copies: numpy's inner loop over a trailing axis of 2 is ~5x slower
    out = np.empty(
        np.broadcast_shapes(point.shape, u.shape)[:-1] + (2, 2), np.result_type(point, u)
    )
    out[..., 0, 0], out[..., 0, 1] = point[..., 0], point[..., 1]
    out[..., 1, 0], out[..., 1, 1] = u[..., 0], u[..., 1]
    return out


def scaled(k: Array, v: Array) -> Array:
    """Return k[..., None] * v for k (N,) and v (N, 2), one component at a time (same values)."""
    out = np.empty(np.broadcast_shapes(k.shape + (2,), v.shape), np.result_type(k, v))
    np.multiply(k, v[..., 0], out=out[..., 0])
    np.multiply(k, v[..., 1], out=out[..., 1])
    return out


def unit(v: Array) -> Array:
    """Return v / |v| like :func:`vec.unit`, one component at a time (same values)."""
    n = norm(v)
    out = np.empty(v.shape, np.result_type(v, n))
    with np.errstate(invalid="ignore", divide="ignore"):
        np.divide(v[..., 0], n, out=out[..., 0])
        np.divide(v[..., 1], n, out=out[..., 1])
    return out


def to_complex(v: Array) -> Array:
    """View (N, 2) float vectors as complex numbers without a copy where the layout allows."""
    if v.dtype in (np.float64, np.float32) and v.flags.c_contiguous and v.shape[-1] == 2:
        return v.view(np.complex128 if v.dtype == np.float64 else np.complex64)[..., 0]
    return as_complex(v)


def to_real(z: Array) -> Array:
    """(N,) complex numbers as (N, 2) vectors without a copy where the layout allows."""
    if z.dtype in (np.complex128, np.complex64) and z.flags.c_contiguous:
        return z.view(np.float64 if z.dtype == np.complex128 else np.float32).reshape(
            z.shape + (2,)
        )
    return from_complex(z)
