"""What one construction operation is: its name, inputs, evaluation, sentence, drawing and checks.

An :class:`OpSpec` is the one home of an operation, declared once as a constant of its family
module (``CIRCLE_CIRCLE = OpSpec("circle_circle", circle_circle, ...)`` in ``position.py``) and
read everywhere as ``Op.CIRCLE_CIRCLE`` (``from mechplan.construct.ops import Op``); a step holds
its spec (``step.op``), compared with ``is``. Its named inputs are the parameters of its
``evaluate`` function after ``step`` (in the order of ``Step.inputs``; a ``*name`` parameter takes
the rest); its protocol sentence is the catalogue message ``message`` (``locale/*/protocol.po``);
``draw`` and ``line`` say what a sheet draws for it; ``written`` how the protocol writes its value;
``lever`` which two input points a direction or a rate is taken from (their distance divides the
error estimate), ``rate_of`` for a link's ω or ε the two images of the relative vector it is read
from; ``grade``, ``hint`` and ``hint_rule`` how the checker grades a submitted point or
line of it and what it tells the student (as :class:`Hint` message ids of ``locale/*/check.po``),
``alias`` the letter by which textbooks also name its points (the checker reads those names),
``through`` for a construction line the input point it is drawn through.
"""

from __future__ import annotations

import enum
import inspect
import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np

from ...geom.vec import Array, as_complex, from_complex, norm
from ...model.plans import Plan
from ..step import Step

if TYPE_CHECKING:
    from ..graph import Construction

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
    LINEAR = "linear"        # a linear driver's length and its rates (m, m/s, m/s²)


class Line(enum.Enum):
    """Line style of what is drawn (the sheet maps it to its layer roles)."""

    NONE = "none"
    DASHED = "dashed"
    THIN = "thin"
    OUTLINE = "outline"


class Grade(enum.Enum):
    """How the checker grades what a student submits for a step of this operation."""

    NOT_GRADED = "not_graded"  # given data or a value never drawn
    GIVEN = "given"  # a given point: a position plan without its drive pivot is placed by it
    ORIGIN = "origin"  # a plan's pole: the plan is placed by it, segments from it are absolute
    POINT = "point"  # the submitted point against the exact one, in paper mm
    MEET = "meet"  # a point found by two lines: graded as a point, lines by direction
    DIRECTION = "direction"  # a construction line: its direction through its point
    VALUE = "value"  # a scalar written in a table: relative error
    RATE = "rate"  # a link's ω or ε, graded as a value; hints name it among a point's inputs


# -- what the checker says ------------------------------------------------------------------------
@dataclass(frozen=True, slots=True, eq=False)
class Hint:
    """A sentence of the checker's catalogue: id ``check.<key>`` and its arguments.

    An argument may itself be a :class:`Hint` or a :class:`Joined` list. ``measured``: the checker
    follows it with how far the submitted point lies from where the student's own points put it.
    """

    key: str
    args: dict[str, Any]
    measured: bool = False


@dataclass(frozen=True, slots=True, eq=False)
class Joined:
    """Items said one after another with a separator said in each language (" and ")."""

    items: tuple[Any, ...]
    sep: str = " and "


def hint(key: str, /, **args: Any) -> Hint:
    """The checker's message ``key`` with its arguments."""
    return Hint(key, args)


def measured(body: Hint) -> Hint:
    """``body`` followed by the distance of the submitted point from the student's own one."""
    return replace(body, measured=True)


class HintView(Protocol):
    """What a check rule may read at the graded position: the construction, the student's own
    values of steps (from their earlier points), the exact values, labels and paper millimetres."""

    @property
    def c(self) -> Construction: ...

    @property
    def own(self) -> Callable[[str], Array]: ...

    @property
    def exact(self) -> Callable[[str], Array]: ...

    @property
    def labels(self) -> Callable[[str], str]: ...

    def mm(self, plan: Plan, length: float) -> float:
        """A physical length on a plan in mm of paper."""
        ...

    def link_of(self, *points: str) -> str | None:
        """The moving link that holds all the named points."""
        ...


#: the checker's hint for a wrong result of a step, from the construction (labels of its inputs)
StepHint = Callable[[Step, "Construction"], Hint]
#: what a step's rule is and how a submitted point ``at`` (SI) breaks it: (step, view, at, tol_mm)
HintRule = Callable[[Step, HintView, Array, float], Hint]
#: the two input points a step's direction or rate is taken from (see :meth:`OpSpec.lever_of`)
Lever = tuple[str, str] | Callable[[Step], tuple[str, str] | None]


def step_hint(step: Step, c: Construction) -> Hint:
    """The default hint: "check step <label>: <operation>"."""
    return hint("hint.step", op=hint(f"op.{step.op.value}"), label=step.label)


def labelled(key: str) -> StepHint:
    """A hint that names only the step's label."""
    return lambda step, c: hint(key, label=step.label)


@dataclass(frozen=True, slots=True, eq=False)
class OpSpec:
    """One construction operation, declared once.

    ``value`` is its name (``"circle_circle"``, written in JSON and message ids); its constant in
    its family module is ``value.upper()``. Specs compare by identity and pickle as references to
    the registry, so ``step.op is Op.CIRCLE_CIRCLE`` holds in every process.
    """

    value: str
    evaluate: Callable[..., Result] | None
    message: str | None  # protocol sentence; None: drawn, never written
    draw: Drawn = Drawn.NOTHING
    line: Line = Line.NONE
    grade: Grade = Grade.NOT_GRADED
    source: Source = Source.INPUTS
    written: Written = Written.PLAIN     # how the protocol writes its value
    lever: Lever | None = None           # two named inputs (points), or a rule giving two ids
    rate_of: tuple[str, str] | None = None  # a link's ω or ε: the two images of its relative
    #                                         vector (over the lever's length: the rate)
    hint: StepHint = step_hint           # the checker's hint for a wrong segment ending at it
    value_hint: StepHint | None = None   # the hint for a wrong written value (None: generic)
    hint_rule: HintRule | None = None    # how a submitted point breaks its rule (None: generic)
    alias: str | None = None             # the letter of its points' textbook names (n_XY, n2, n)
    through: str | None = None           # a construction line: the input point it is drawn
    #                                      through (a meet's hint names the line by it)
    inputs: tuple[str, ...] = field(init=False)
    rest: str | None = field(init=False)  # name of a variable tail of inputs, if any
    #: its evaluator takes ``shared=``: a dict of one evaluation, for a part several steps
    #: compute alike (a link's unit normal, a similarity ratio), computed by the first of them
    shares: bool = field(init=False)

    def __post_init__(self) -> None:
        names: list[str] = []
        rest = None
        shares = False
        if self.evaluate is not None and self.source is Source.INPUTS:
            params = list(inspect.signature(self.evaluate).parameters.values())[1:]
            for p in params:
                if p.kind is inspect.Parameter.VAR_POSITIONAL:
                    rest = p.name
                elif p.kind is inspect.Parameter.KEYWORD_ONLY:
                    shares = shares or p.name == "shared"
                else:
                    names.append(p.name)
        object.__setattr__(self, "inputs", tuple(names))
        object.__setattr__(self, "rest", rest)
        object.__setattr__(self, "shares", shares)
        for pair in (self.lever, self.rate_of):
            if isinstance(pair, tuple):
                for name in pair:
                    self.index(name)
        if self.through is not None:
            self.index(self.through)

    @property
    def name(self) -> str:
        """The name of its constant: ``CIRCLE_CIRCLE``."""
        return self.value.upper()

    def __repr__(self) -> str:
        return f"Op.{self.name}"

    def __reduce__(self) -> tuple[Any, ...]:
        return (registered, (self.value,))

    def index(self, name: str) -> int:
        """Position of a named input in ``Step.inputs``."""
        try:
            return self.inputs.index(name)
        except ValueError:
            raise KeyError(
                f"{self.value} has no input {name!r} (inputs: {self.inputs})"
            ) from None

    def lever_of(self, step: Step) -> tuple[str, str] | None:
        """Ids of the two points whose distance divides the step's error (None: no lever)."""
        if self.lever is None:
            return None
        if isinstance(self.lever, tuple):
            first, second = self.lever
            return step.input(first), step.input(second)
        return self.lever(step)


def registered(value: str) -> OpSpec:
    """The registered operation of a name (``"circle_circle"`` → ``Op.CIRCLE_CIRCLE``)."""
    from . import SPECS  # the registry is built from the family modules, above this one

    try:
        return SPECS[value]
    except KeyError:
        raise KeyError(f"no operation {value!r}") from None


# -- helpers shared by the check rules ------------------------------------------------------------
def point_of(v: Array) -> Array:
    """The first point of a value (leading axis 1) as a flat (2,) float array."""
    return np.asarray(v, dtype=float).reshape(-1)[:2]


def dist_to_line(p: Array, line_value: Array) -> float:
    """Distance of a point from a line value (a point and a direction); NaN for no line."""
    line_value = np.asarray(line_value, dtype=float).reshape(2, 2)
    o, u = line_value[0], line_value[1]
    n = math.hypot(*u)
    if not n or not np.all(np.isfinite(line_value)):
        return math.nan
    d = p - o
    return float(abs(d[0] * u[1] - d[1] * u[0]) / n)


def on_lines(step: Step, view: HintView, at: Array, tol_mm: float) -> Joined:
    """For a meet: on which of its lines the submitted point lies, and how far off the others."""
    c, plan = view.c, step.plan
    parts = []
    for lid in step.inputs:
        line_step = c[lid]
        point = line_step.op.through
        through = view.labels(line_step.input(point)) if point else "?"
        d = view.mm(plan, dist_to_line(at, view.own(lid)))
        where = hint("rule.on_it") if d <= tol_mm else hint("rule.off_by", d=d)
        parts.append(hint("rule.on_line", through=through, line=line_step.label, where=where))
    return Joined(tuple(parts))


def drive_hint(step: Step, view: HintView, at: Array, how: str) -> Hint:
    """The driving vector (inputs ``pivot``, ``tip``): its length and direction against the
    submitted ones."""
    c, plan = view.c, step.plan
    pivot, tip = c[step.input("pivot")].label, c[step.input("tip")].label
    exact = point_of(view.exact(step.id))
    length = view.mm(plan, float(np.hypot(*exact)))
    drawn = view.mm(plan, float(np.hypot(*at)))
    ang = math.degrees(math.remainder(math.atan2(at[1], at[0]) - math.atan2(exact[1], exact[0]),
                                      2 * math.pi))
    return hint("rule.drive", label=view.labels(step.id), how=hint(how, pivot=pivot, tip=tip),
                len=length, drawn=drawn, ang=ang)


def rigid_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A point of a rigid link from a known image: v_X = v_O + ω × OX (a_X likewise); inputs
    ``origin`` (the image of O) and ``p_point`` (X)."""
    return measured(hint("rule.rigid", label=view.labels(step.id),
                         X=view.c[step.input("p_point")].label,
                         o=view.labels(step.input("origin"))))


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
