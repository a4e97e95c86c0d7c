"""Construction: a DAG of steps evaluated lazily, memoised and vectorised over crank positions."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field

import numpy as np

from ..geom.vec import Array
from ..model.plans import Plan
from .ops import Source
from .segments import Segment
from .step import Step
from .terms import Row


@dataclass(frozen=True, slots=True)
class DriveMap:
    """Map the scene's crank angle φ to the absolute crank direction θ = ref + sense·φ.

    A linear driver (``linear``): the coordinate is a length q (m), passed on as it is.
    """

    ref: float      # rad, direction of φ = 0, counter-clockwise from +x
    sense: int      # +1 counter-clockwise, -1 clockwise
    linear: bool = False
    #: a linear driver's range of q (m): where the mechanism's size is sampled
    span: tuple[float, float] | None = None

    def samples(self, n: int) -> Array:
        """n driver coordinates over a turn (a crank) or over the range (a linear driver)."""
        if self.linear and self.span is not None:
            return np.linspace(self.span[0], self.span[1], n)
        return np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)

    def absolute(self, phi: Array) -> Array:
        """Return θ for φ (radians)."""
        return self.ref + self.sense * np.asarray(phi, dtype=float)

    def scene(self, theta: Array) -> Array:
        """Return φ in [0, 2π) for θ (radians); a linear driver's q as it is."""
        if self.linear:
            return self.sense * (np.asarray(theta, dtype=float) - self.ref)
        return np.mod(self.sense * (np.asarray(theta, dtype=float) - self.ref), 2.0 * np.pi)


def reaction_key(i: str, j: str) -> str:
    """Key of the reaction of link i on link j: ``"12"``, or ``"10,12"`` for longer link ids."""
    return f"{i}{j}" if len(i) == 1 and len(j) == 1 else f"{i},{j}"


@dataclass
class Construction:
    """An ordered DAG of steps; steps are added after their inputs."""

    drive: DriveMap
    steps: dict[str, Step] = field(default_factory=dict)
    segments: list[Segment] = field(default_factory=list)
    #: vector equations per (plan, group): the equation and rows of (term, direction, magnitude)
    equations: dict[tuple[Plan, str], tuple[str, list[Row]]] = field(
        default_factory=dict)
    #: named results: quantity key ("v_C", "omega_2", "r_C") → step id
    results: dict[str, str] = field(default_factory=dict)
    #: constants derived once from the whole construction (e.g. its length scale)
    derived: dict[str, float] = field(default_factory=dict)
    #: W = 2: the second driver's link (its balancing moment is the result ``M_b{link}``, a
    #: second cylinder's driving force ``F_d{link}``)
    second_driver: str | None = None
    #: ancestor closures asked for so far (targets → steps in order); cleared when steps change
    _closures: dict[tuple[str, ...], tuple[str, ...]] = field(
        default_factory=dict, repr=False, compare=False)

    def add(self, step: Step) -> str:
        """Add a step whose inputs are already present; return its id."""
        if step.id in self.steps:
            raise ValueError(f"duplicate step id {step.id!r}")
        missing = [i for i in step.inputs if i not in self.steps]
        if missing:
            raise ValueError(f"step {step.id!r} needs unknown inputs {missing}")
        self.steps[step.id] = step
        self._closures.clear()
        return step.id

    def replace(self, step: Step) -> None:
        """Replace a step that nothing depends on yet (branch resolution)."""
        if any(step.id in s.inputs for s in self.steps.values()):
            raise ValueError(f"step {step.id!r} already has dependants")
        self.steps[step.id] = step
        self._closures.clear()

    def __contains__(self, step_id: str) -> bool:
        return step_id in self.steps

    def __getitem__(self, step_id: str) -> Step:
        return self.steps[step_id]

    def __iter__(self) -> Iterator[Step]:
        return iter(self.steps.values())

    # -- typed accessors: the only place outside the plan builders that knows how ids are formed --
    def position(self, point: str) -> str:
        """Return the step id of a point's position (position plan)."""
        sid = f"pos.{point}"
        if sid not in self.steps:
            raise KeyError(f"point {point!r} has no position step")
        return sid

    def velocity_image(self, point: str) -> str:
        """Return the step id of a point's image on the velocity plan."""
        return self._result("v", point)

    def acceleration_image(self, point: str) -> str:
        """Return the step id of a point's image on the acceleration plan."""
        return self._result("a", point)

    def link_angle(self, link: str) -> str:
        """Return the step id of a link's angle (rad, counter-clockwise from +x)."""
        return self._result("angle", link)

    def omega(self, link: str) -> str:
        """Return the step id of a link's angular velocity (rad/s, counter-clockwise +)."""
        return self._result("omega", link)

    def epsilon(self, link: str) -> str:
        """Return the step id of a link's angular acceleration (rad/s², counter-clockwise +)."""
        return self._result("epsilon", link)

    def has_position(self, point: str) -> bool:
        """Tell whether a point has a position step."""
        return f"pos.{point}" in self.steps

    # force plan (built with a loading); a link without mass has no inertia, weight or couple
    def inertia_force(self, link: str) -> str | None:
        """Return the step id of a link's inertia force Q = −m·a_S (N, 2), if it has one."""
        return self.results.get(f"Q_{link}")

    def inertia_couple(self, link: str) -> str | None:
        """Return the step id of a link's inertia couple M_q = −J_S·ε (N·m), if it has one."""
        return self.results.get(f"M_q{link}")

    def weight(self, link: str) -> str | None:
        """Return the step id of a link's weight (N, 2), if it has one."""
        return self.results.get(f"G_{link}")

    def load(self, index: int) -> str | None:
        """Return the step id of the ``index``-th load of the loading (force or couple)."""
        return self.results.get(f"load_{index}")

    def reaction(self, i: str, j: str) -> str:
        """Return the step id of R_ij, the force of link i on link j at their pair (N, 2)."""
        return self._named(f"R_{reaction_key(i, j)}")

    def guide_offset(self, i: str, j: str) -> str:
        """Return the step id of d_ij: where R_ij's line of action crosses the guide (m)."""
        return self._named(f"d_{reaction_key(i, j)}")

    def balancing_moment(self) -> str:
        """Return the step id of the balancing moment M_b on the driving link (N·m)."""
        return self._named("M_b")

    def second_balancing_moment(self, link: str) -> str:
        """Return the step id of the balancing moment on a second driving crank (W = 2, N·m)."""
        return self._named(f"M_b{link}")

    def second_driving_force(self, link: str) -> str:
        """Return the step id of the driving force of a second cylinder (W = 2, rod ``link``, N)."""
        return self._named(f"F_d{link}")

    def zhukovsky_moment(self) -> str:
        """Return the step id of M_b found by Zhukovsky's lever (N·m)."""
        return self._named("M_b_zhukovsky")

    def driving_force(self) -> str:
        """Return the step id of a linear driver's driving force F_d (N, + pushing q up)."""
        return self._named("F_d")

    def zhukovsky_force(self) -> str:
        """Return the step id of F_d found by Zhukovsky's lever (N)."""
        return self._named("F_d_zhukovsky")

    def link_results(self) -> list[str]:
        """Step ids of every link's angle, ω and ε, in construction order."""
        return [sid for key, sid in self.results.items()
                if key.split("_")[0] in ("angle", "omega", "epsilon")]

    def force_results(self) -> list[str]:
        """Step ids of the balancing moments (or driving forces), reactions and guide offsets."""
        return [sid for key, sid in self.results.items()
                if key in ("M_b", "M_b_zhukovsky", "F_d", "F_d_zhukovsky")
                or key.startswith(("R_", "d_"))
                or (self.second_driver is not None
                    and key in (f"M_b{self.second_driver}", f"F_d{self.second_driver}"))]

    def _named(self, key: str) -> str:
        try:
            return self.results[key]
        except KeyError:
            raise KeyError(f"the construction has no {key}") from None

    def has_result(self, quantity: str, subject: str) -> bool:
        """Tell if a result exists (``"v"``, ``"a"``, ``"angle"``, ``"omega"``, ``"epsilon"``)."""
        return f"{quantity}_{subject}" in self.results

    def quantity_of(self, step_id: str) -> tuple[str, str] | None:
        """Return (quantity, subject) of a result step — ("v", "C"), ("omega", "2"), ("r", "C") …"""
        if step_id.startswith("pos.") and step_id.count(".") == 1:
            return ("r", step_id[4:])
        for key, sid in self.results.items():
            if sid == step_id:
                quantity, _, subject = key.partition("_")
                return (quantity, subject)
        return None

    def _result(self, quantity: str, subject: str) -> str:
        try:
            return self.results[f"{quantity}_{subject}"]
        except KeyError:
            raise KeyError(f"the construction has no {quantity} of {subject!r}") from None

    def ancestors(self, targets: Iterable[str]) -> list[str]:
        """Return the targets and everything they depend on, in construction order."""
        key = tuple(targets)
        closure = self._closures.get(key)
        if closure is None:
            needed: set[str] = set()
            stack = list(key)
            while stack:
                sid = stack.pop()
                if sid in needed:
                    continue
                needed.add(sid)
                stack.extend(self.steps[sid].inputs)
            closure = self._closures[key] = tuple(sid for sid in self.steps if sid in needed)
        return list(closure)

    def of_plan(self, plan: Plan) -> list[Step]:
        """Return the steps of one plan in order."""
        return [s for s in self.steps.values() if s.plan is plan]

    def evaluate(self, phi: Array | float, dtype: type = np.float64,
                 overrides: Mapping[str, Array] | None = None) -> Evaluation:
        """Start a lazy evaluation at crank angles φ (radians, scene convention).

        ``overrides`` gives some steps their values (leading axis N, like every value) instead of
        their rule: the steps built on them are re-derived from those values (a student's points).
        """
        return Evaluation(self, np.atleast_1d(np.asarray(phi, dtype=float)), dtype, overrides)


class Evaluation:
    """Values of a construction at N positions, computed on demand and memoised by step id."""

    def __init__(self, construction: Construction, phi: Array, dtype: type = np.float64,
                 overrides: Mapping[str, Array] | None = None) -> None:
        self.construction = construction
        self.overrides = dict(overrides or {})
        self.dtype = dtype
        self.phi = phi
        self.n = phi.shape[0]
        self.values: dict[str, Array] = {}
        self.gaps: dict[str, Array] = {}
        self.sines: dict[str, Array] = {}
        #: parts several steps compute alike, by the first of them (see ``OpSpec.shares``)
        self.shared: dict[tuple[str, ...], Array] = {}

    @property
    def evaluated(self) -> int:
        """Number of steps evaluated so far."""
        return len(self.values)

    def __getitem__(self, step_id: str) -> Array:
        return self.get(step_id)

    def get(self, step_id: str) -> Array:
        """Return the value of a step, evaluating its ancestors first if needed."""
        if step_id in self.values:
            return self.values[step_id]
        for sid in self.construction.ancestors([step_id]):
            if sid not in self.values:
                self._compute(self.construction.steps[sid])
        return self.values[step_id]

    def evaluate_all(self, targets: Iterable[str]) -> None:
        """Evaluate the ancestor closure of targets."""
        for sid in self.construction.ancestors(targets):
            if sid not in self.values:
                self._compute(self.construction.steps[sid])

    def _compute(self, step: Step) -> None:
        value: Array
        op = step.op
        if step.id in self.overrides:
            value, gap, sine = np.asarray(self.overrides[step.id], dtype=self.dtype), None, None
            if value.shape[:1] != (self.n,):
                raise ValueError(f"override of {step.id!r} must have {self.n} positions "
                                 f"(got shape {value.shape})")
        elif op.source is Source.DRIVE:
            theta = self.construction.drive.absolute(self.phi)
            value, gap, sine = theta.astype(self.dtype), None, None
        elif op.source is Source.POSITIONS:
            assert op.evaluate is not None
            value, gap, sine = op.evaluate(step, self.n)
            value = value.astype(self.dtype)
        else:
            assert op.evaluate is not None
            args = [self.values[i] for i in step.inputs]
            if op.shares:
                value, gap, sine = op.evaluate(step, *args, shared=self.shared)
            else:
                value, gap, sine = op.evaluate(step, *args)
        stored: Array = np.asarray(value)
        stored.flags.writeable = False
        self.values[step.id] = stored
        if gap is not None:
            self.gaps[step.id] = gap
        if sine is not None:
            self.sines[step.id] = sine
