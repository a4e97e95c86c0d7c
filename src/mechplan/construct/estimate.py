"""Error estimates: how far each evaluated step may be from the exact value, at every position.

Every step gets an absolute error bound (in the step's own units) propagated to first order from
its inputs' bounds and its own rounding: a meet of two loci divides the error of the loci by the
sine of their crossing angle (its condition number), a direction taken from two points divides the
points' error by their distance, a similarity image by the length of the side it is built on, a
division by a length by that length. A line also carries its direction's error (rad) apart from its
point's: a meet of two lines that lies far from the lines' points (a velocity plan's meet near a
toggle, |v| ∝ 1/sin) moves by that distance times the angle, so its bound is at least the lines'
direction error × its distance over the plan's size ÷ the sine. Near a toggle the position plan's
error grows like 1/sin, the velocity plan's — built on directions taken from the position plan and
met at the same angle — like 1/sin², the acceleration plan's like 1/sin³, which is how the true
errors grow.

The relative error of a quantity is its bound divided by the quantity's scale: the size of its plan
(the largest vector drawn on it over the positions evaluated; for a link's ω or ε that size over
the mechanism's length), so a vector that passes through zero (v_C at a dead centre) keeps a
finite, meaningful relative error.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

import numpy as np

from ..geom.vec import Array, norm
from ..model.plans import Plan
from .graph import Construction, Evaluation
from .ops import Op
from .step import Kind, Step

#: relative error above which a quantity is flagged (settable per call)
DEFAULT_TOLERANCE = 1e-6
#: an estimate at or above this (100 % of the plan's scale, or no bound at all) means the value
#: carries no information: the position cannot be computed
UNBOUNDED = 1.0
#: rounding of one operation, in units of the float type's epsilon (a few roundings per step)
ROUNDINGS_PER_STEP = 2.0


@dataclass
class ErrorEstimate:
    """Relative error bounds per step id (float32, NaN/inf where no bound exists) and their
    scales.

    The bounds are propagated when first needed: one bound of all of them, computed with the
    values (:meth:`may_exceed`), usually shows that none can exceed a threshold.
    """

    relative_of: dict[str, Array] = field(default_factory=dict)
    scale: dict[str, float] = field(default_factory=dict)
    #: the values of the results, each measured against the larger of its plan's scale and its own
    #: size (a slider running far out, an acceleration blowing up near a toggle): see divisor()
    results: dict[str, Array] = field(default_factory=dict)
    dtype: type = np.float32
    _divisor: dict[str, Array] = field(default_factory=dict, repr=False)    # memo of divisor()
    _relative: dict[str, Array] = field(default_factory=dict, repr=False)   # memo of relative()
    _bound: dict[str, float] = field(default_factory=dict, repr=False)      # of may_exceed()
    #: the step ids that have a bound, a bound of all their bounds at every position (see
    #: _Propagator.run), and what fills relative_of when first needed
    _ids: frozenset[str] = field(default_factory=frozenset, repr=False)
    _all: float = field(default=math.nan, repr=False)
    _fill: Callable[[], None] | None = field(default=None, repr=False)

    def __contains__(self, step_id: str) -> bool:
        return step_id in self._ids or step_id in self.relative_of

    def _ensure(self) -> None:
        """Propagate the bounds (once)."""
        if self._fill is not None:
            fill, self._fill = self._fill, None
            fill()

    def divisor(self, step_id: str) -> Array | None:
        """max(1, |value| / scale) of a result at every position (None: not a result)."""
        if step_id not in self.results:
            return None
        if step_id not in self._divisor:
            self._divisor[step_id] = _magnitude_divisor(self.results[step_id],
                                                        self.scale[step_id], self.dtype)
        return self._divisor[step_id]

    def relative(self, step_id: str) -> Array:
        """Estimated relative error at every position (inf where it cannot be bounded).

        Relative to the larger of the plan's scale and the result's own size.
        """
        if step_id in self._relative:
            return self._relative[step_id]
        self._ensure()
        rel = self.relative_of[step_id].astype(float)
        divisor = self.divisor(step_id)
        if divisor is not None:
            with np.errstate(invalid="ignore", divide="ignore"):
                rel = rel / divisor
        rel[np.isnan(rel)] = np.inf
        rel.flags.writeable = False
        self._relative[step_id] = rel
        return rel

    def may_exceed(self, step_id: str, threshold: float) -> bool:
        """Whether :meth:`relative` can exceed ``threshold`` at some position (False: it cannot).

        Cheap: the divisor is at least 1 (or NaN, from a NaN value), so the relative error is at
        most the bound against the plan's scale alone, and is computed only when that can exceed.
        """
        value = self.results.get(step_id)
        finite = value is None or not value.size or math.isfinite(float(value.sum()))
        if finite and self._all <= threshold:
            return False        # below the bound of every step's bound (NaN: not known)
        bound = self._bound.get(step_id)
        if bound is None:
            self._ensure()
            rel = self.relative_of[step_id]
            bound = float(rel.max()) if rel.size else 0.0      # NaN when some bound is NaN
            if not finite:
                bound = math.inf      # a NaN value (or an infinite one): look position by position
            self._bound[step_id] = bound
        return not bound <= threshold

    def absolute(self, step_id: str) -> Array:
        """Estimated absolute error of a step in its own units (m, m/s, rad/s, N …)."""
        self._ensure()
        rel = self.relative_of[step_id].astype(float)
        return np.where(np.isnan(rel), np.inf, rel) * self.scale[step_id]


def length_scale(c: Construction, samples: int = 72) -> float:
    """The size of the mechanism: its position plan's largest coordinate, median over a turn (m).

    A property of the mechanism, not of the positions evaluated, so an estimate at a position does
    not depend on which other positions are evaluated with it. Computed once per construction.
    """
    if "length" not in c.derived:
        # moving points only: a frame point placed far away (to give a load its direction) does
        # not make the mechanism larger
        points = [s.id for s in c if s.plan is Plan.POSITION and s.kind is Kind.POINT
                  and s.op is not Op.FIXED_POINT] or [
            s.id for s in c if s.plan is Plan.POSITION and s.kind is Kind.POINT]
        ev = c.evaluate(c.drive.samples(samples))      # over a turn, or a linear driver's range
        ev.evaluate_all(points)
        per_sample = np.zeros(samples)
        for sid in points:
            with np.errstate(invalid="ignore"):
                per_sample = np.fmax(per_sample, np.abs(ev.values[sid]).max(axis=-1))
        # the median over a turn: a slider running out to infinity near a singular sample does
        # not make the whole mechanism large
        finite = per_sample[np.isfinite(per_sample) & (per_sample > 0.0)]
        c.derived["length"] = float(np.median(finite)) if finite.size else 1.0
    return c.derived["length"]


def plan_sizes(c: Construction, ev: Evaluation | None = None) -> dict[Plan, float]:
    """Sizes of the plans that do not depend on how close a position is to a singular one.

    The position plan: the mechanism's length scale (:func:`length_scale`); the velocity and
    acceleration plans: ω1·L and (ω1² + |ε1|)·L of the driving link (a linear driver: |q̇| and
    |q̈| + q̇²/L); the force plan (given an
    evaluation): the median over the positions of its largest vector (forces have no intrinsic
    scale).
    """
    length = length_scale(c)
    omega = epsilon = 0.0
    for step in c:
        if step.op is Op.DRIVE_ACCELERATION:
            omega = abs(float(step.param("omega")))
            epsilon = abs(float(step.param("epsilon", 0.0)))
        elif step.op is Op.DRIVE_VELOCITY:
            omega = abs(float(step.param("omega")))
    sizes = {Plan.POSITION: length, Plan.VELOCITY: omega * length,
             Plan.ACCELERATION: (omega * omega + epsilon) * length}
    rates: dict[Plan, float] = {}
    for step in c:      # the largest of the drivers' rates (W = 2: a second cylinder's too)
        if step.op is Op.DRIVER_RATE:
            rates[step.plan] = max(rates.get(step.plan, 0.0), abs(float(step.param("value"))))
        elif step.op is Op.DRIVER_LAW and step.plan is not Plan.POSITION:   # a law by a table
            rates[step.plan] = max(rates.get(step.plan, 0.0), float(step.param("size")))
    if rates:   # a linear driver: its rate q̇, and q̈ with the centripetal q̇²/L of its links
        q_dot = rates.get(Plan.VELOCITY, 0.0)
        crank = omega > 0.0         # W = 2, a crank and a cylinder: the larger of the two
        sizes[Plan.VELOCITY] = max(q_dot, sizes[Plan.VELOCITY]) if crank else q_dot
        q_acc = rates.get(Plan.ACCELERATION, 0.0) + q_dot * q_dot / length
        sizes[Plan.ACCELERATION] = max(q_acc, sizes[Plan.ACCELERATION]) if crank else q_acc
    if ev is not None:
        force_max = [np.abs(v).max(axis=-1) for sid, v in ev.values.items()
                     if c[sid].plan is Plan.FORCE and c[sid].kind is Kind.POINT and v.size]
        if force_max:
            with np.errstate(invalid="ignore"):
                per_position = np.nanmax(np.stack(force_max), axis=0)
            finite = per_position[np.isfinite(per_position)]
            sizes[Plan.FORCE] = float(np.median(finite)) if finite.size else 0.0
    return sizes


def scale_of(step: Step, sizes: dict[Plan, float]) -> float:
    """The size a step's error is measured against (its plan's size, or that over a length)."""
    size = sizes.get(step.plan, 0.0)
    length = sizes[Plan.POSITION]
    if step.kind is Kind.POINT or step.kind is Kind.LINE:
        return size
    if step.plan is Plan.POSITION:
        return 1.0                                   # angles (rad)
    if step.op in (Op.GUIDE_OFFSET, Op.INERTIA_OFFSET):
        return length
    if step.op in (Op.MOMENT_INERTIA, Op.MOMENT_SUM, Op.MOMENT_CLOSE, Op.BALANCING_MOMENT,
                   Op.ZHUKOVSKY):
        return size * length                         # moments: force × length
    return size / length                             # ω, ε: a plan's size over a length


class _Propagator:
    """Walk the evaluated steps in construction order and bound each one's relative error."""

    def __init__(self, c: Construction, ev: Evaluation, dtype: type = np.float32) -> None:
        self.c, self.ev = c, ev
        self.u = float(np.finfo(ev.dtype).eps) * ROUNDINGS_PER_STEP
        self.dtype = dtype
        self.rel: dict[str, Array] = {}
        self.plan_size = plan_sizes(c, ev)
        self.length = self.plan_size[Plan.POSITION]
        self._distances: dict[tuple[str, str], Array] = {}
        self._reach: dict[str, Array] = {}
        #: a line's direction error (rad) apart from its point's: what a far meet multiplies
        self.turn: dict[str, Array] = {}

    def scale_of(self, step: Step) -> float:
        """The size a step's error is measured against."""
        return scale_of(step, self.plan_size)

    def distance(self, a: str, b: str) -> Array:
        """|b − a| of two point steps, relative to the mechanism's length (memoised per pair)."""
        key = (a, b) if a < b else (b, a)
        if key not in self._distances:
            length = norm(self.ev.values[b] - self.ev.values[a])
            length /= self.length
            self._distances[key] = length.astype(self.dtype)
        return self._distances[key]

    def reach(self, step: Step) -> Array | None:
        """How far a meet of two lines lies from the lines' points, over its plan's size, at
        least 1 (None: not a meet of lines, or a plan with no size)."""
        if step.op is not Op.LINE_LINE:
            return None
        size = self.plan_size.get(step.plan, 0.0)
        if not size > 0.0:
            return None
        if step.id not in self._reach:
            meet = self.ev.values[step.id]
            far = np.ones(self.ev.n)
            for key in ("line1", "line2"):
                base = self.ev.values[step.input(key)][..., 0, :]
                with np.errstate(invalid="ignore"):
                    far = np.fmax(far, norm(meet - base) / size)
            with np.errstate(over="ignore"):
                self._reach[step.id] = far.astype(self.dtype)
        return self._reach[step.id]

    def _turn_of(self, step: Step, u: Array) -> Array:
        """A line's direction error (rad): from the two points of its lever (their bound over
        their distance), else from its input lines' directions and its angles."""
        pair = step.op.lever_of(step)
        if pair is not None:
            with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                turn: Array = (np.maximum(self.rel[pair[0]], self.rel[pair[1]]) + u) / \
                    self.distance(*pair)
            return turn
        out: Array = np.full(self.ev.n, u, self.dtype)
        for i in dict.fromkeys(step.inputs):
            kind = self.c[i].kind
            if kind is Kind.LINE:
                np.maximum(out, self.turn[i] + u, out=out)
            elif kind is not Kind.POINT:
                np.maximum(out, self.rel[i] + u, out=out)
        return out

    def run(self, ids: Iterable[str], targets: frozenset[str]) -> ErrorEstimate:
        """The estimate of the evaluated ``ids``: scales and results now, bounds when needed.

        A step's bound is (the largest of its inputs' bounds + u) divided by its divisors (the
        distance of its spec's lever, a meet's sine), so it is at most depth·u over the product
        of the divisors below 1 along its ancestors, and every bound at a position is at most
        steps·u / Π min(1, divisor) over all the steps. Twice that (for the roundings of float32)
        is ``_all``'s value at the position; :meth:`ErrorEstimate.may_exceed` compares its
        largest value with the threshold before propagating anything.
        """
        out = ErrorEstimate(dtype=self.dtype)
        done = [sid for sid in ids if sid in self.ev.values]
        n = self.ev.n
        product = np.ones(n)
        clipped = np.empty(n)                   # one buffer: min(1, divisor), NaN stays NaN
        with np.errstate(invalid="ignore"):
            for sid in done:
                step = self.c[sid]
                scale = self.scale_of(step)
                out.scale[sid] = scale
                if sid in targets and scale > 0.0:
                    out.results[sid] = self.ev.values[sid]
                if not step.inputs:
                    continue
                lever = step.op.lever_of(step)     # a direction or rate taken from two points
                divisors = [] if lever is None else [self.distance(*lever)]
                sine = self.ev.sines.get(sid)
                if sine is not None:
                    divisors.append(sine)
                reach = self.reach(step)
                if reach is not None:
                    divisors.append(1.0 / reach)
                for d in divisors:
                    np.minimum(d, 1.0, out=clipped)
                    product *= clipped
            with np.errstate(divide="ignore"):
                out._all = float(np.max(2.0 * len(done) * self.u / product)) if n else 0.0
        out._ids = frozenset(done)
        out._fill = lambda: self._propagate(done, out)
        return out

    def _propagate(self, ids: list[str], out: ErrorEstimate) -> None:
        """Every step's bound, in construction order."""
        n, u = self.ev.n, self.dtype(self.u)
        for sid in ids:
            step = self.c[sid]
            rel: Array
            if not step.inputs:
                rel = np.full(n, u, self.dtype)
            else:
                # max(a + u, b + u) = max(a, b) + u exactly (rounding is monotonic): one sum
                first, *rest = dict.fromkeys(step.inputs)
                if rest:
                    rel = np.maximum(self.rel[first], self.rel[rest[0]])
                    for i in rest[1:]:
                        np.maximum(rel, self.rel[i], out=rel)
                    rel += u
                else:
                    rel = self.rel[first] + u
                lever = step.op.lever_of(step)     # a direction or rate taken from two points
                with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                    if lever is not None:
                        np.divide(rel, self.distance(*lever), out=rel)
                    sine = self.ev.sines.get(sid)
                    if sine is not None:
                        np.divide(rel, sine, out=rel, casting="same_kind")
                    reach = self.reach(step)
                    if reach is not None:
                        # a direction's error moves a far meet by its distance times the angle
                        turn = np.maximum(self.turn[step.input("line1")],
                                          self.turn[step.input("line2")]) + u
                        far = turn * reach
                        if sine is not None:
                            far /= sine
                        np.maximum(rel, far.astype(self.dtype), out=rel)
            self.rel[sid] = rel
            if step.kind is Kind.LINE:
                self.turn[sid] = self._turn_of(step, u) if step.inputs else rel
            out.relative_of[sid] = rel


def _magnitude_divisor(value: Array, scale: float, dtype: type) -> Array:
    if value.ndim == 2:
        size = np.sqrt(np.einsum("ij,ij->i", value, value))
    else:
        size = np.abs(value)
    with np.errstate(invalid="ignore", over="ignore"):
        out: Array = np.maximum(size / scale, 1.0).astype(dtype)
    return out


def estimate_errors(c: Construction, ev: Evaluation,
                    targets: Iterable[str] | None = None) -> ErrorEstimate:
    """Bound the error of every evaluated step (or of ``targets`` and their ancestors).

    The results (``targets``, or every evaluated step) are measured against the larger of their
    plan's scale and their own size.
    """
    if targets is None:
        wanted = [s for s in c.steps if s in ev.values]
        return _Propagator(c, ev).run(wanted, frozenset(wanted))
    targets = list(targets)
    return _Propagator(c, ev).run(c.ancestors(targets), frozenset(targets))
