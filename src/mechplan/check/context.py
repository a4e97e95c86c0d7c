"""What grading works with: options, the exact and re-derived values, drawn plans, row words."""

from __future__ import annotations

from collections.abc import Callable, Hashable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.segments import Segment
from ..model.plans import Plan
from ..scene.spec import Scene
from ..submission.drawn_plans import DrawnPlan, DrawnSheet
from ..submission.labels import LabelBook, PlanKey, plan_key
from ..submission.read import Submission
from .labels import segment_key
from .match import Interpretation
from .report import (
    NEW,
    SWAPPED,
    Finding,
    SegmentRow,
    Tolerance,
)
from .texts import T, join


@dataclass
class Options:
    """How to check: crank angle, tolerances and scale factors per plan, label search."""

    at_deg: float | None = None
    tolerance: dict[Plan | None, Tolerance] = field(default_factory=dict)
    mu: dict[Plan, float] = field(default_factory=dict)
    label_distance: float | None = None
    snap: float = 0.2

    def tol(self, plan: Plan | None) -> Tolerance:
        """The tolerance of a plan (or the default one)."""
        return self.tolerance.get(plan) or self.tolerance.get(None) or Tolerance()


# -- the student's own values: the construction re-evaluated from submitted points -------------
class Rederive:
    """Values of steps derived by the engine from the submitted points instead of the exact ones."""

    def __init__(self, c: Construction, ev: Evaluation, k: int,
                 overrides: dict[str, np.ndarray]) -> None:
        self.c, self.ev, self.k = c, ev, k
        self.phi = ev.phi[k:k + 1]
        self.over = {s: np.asarray(v, dtype=float).reshape(1, 2) for s, v in overrides.items()}
        self._all = c.evaluate(self.phi, overrides=self.over)
        self._but: dict[str, Evaluation] = {}

    def exact(self, sid: str) -> np.ndarray:
        """The exact value of a step (leading axis 1)."""
        return np.asarray(self.ev[sid][self.k:self.k + 1])

    def own(self, sid: str) -> np.ndarray:
        """The value the step gets from the submitted points (never its own submitted value)."""
        ev = self._all
        if sid in self.over:
            ev = self._but.get(sid) or self._but.setdefault(sid, self.c.evaluate(
                self.phi, overrides={s: v for s, v in self.over.items() if s != sid}))
        with np.errstate(all="ignore"):
            return np.asarray(ev[sid])


# -- grading at one crank position ------------------------------------------------------------
@dataclass
class Ctx:
    scene: Scene
    sub: Submission
    c: Construction
    ev: Evaluation
    book: LabelBook
    sheet: DrawnSheet | None
    interp: Interpretation
    options: Options
    scales: dict[Plan, float]          # the scene's own scale factors (paper tolerance fallback)
    #: reduced moment and inertia over all positions, computed once when a value asks for them
    reduced: dict[str, np.ndarray] = field(default_factory=dict)


@dataclass
class Drawn:
    dp: DrawnPlan
    mu: float | None
    mu_source: str
    anchor: str | None
    si: dict[str, np.ndarray]          # step → submitted value (SI, exact frame)
    reference: Segment | None = None
    status: dict[str, str] = field(default_factory=dict)      # step → cause of a wrong point
    errors: dict[str, float] = field(default_factory=dict)    # step → total error (mm)
    own_err: dict[str, float] = field(default_factory=dict)
    tol: dict[str, float] = field(default_factory=dict)
    swapped: dict[str, str] = field(default_factory=dict)


def swaps(items: list[Any], fits: Callable[[Any, Any], bool],
          group: Callable[[Any], Hashable] | None = None) -> list[tuple[Any, Any]]:
    """Pairs of items, in order, each right under the other's name (``fits(a, b)``: a is right as
    b); an item is in one pair at most. ``group(item)``: items of different groups never fit,
    so only pairs within a group are tried (a table of 10^4 values is not tried pair by pair)."""
    if group is not None:
        groups: dict[Hashable, list[int]] = {}
        for i, item in enumerate(items):
            groups.setdefault(group(item), []).append(i)
        found = [(idx[a], idx[b]) for idx in groups.values()
                 for a, b in _pairs([items[i] for i in idx], fits)]
        return [(items[i], items[j]) for i, j in sorted(found)]
    return [(items[i], items[j]) for i, j in _pairs(items, fits)]


def _pairs(items: list[Any], fits: Callable[[Any, Any], bool]) -> list[tuple[int, int]]:
    """The pairs of :func:`swaps` as indices, each item paired with the first later one that
    fits both ways."""
    out: list[tuple[int, int]] = []
    used: set[int] = set()
    for i, a in enumerate(items):
        for j in range(i + 1, len(items)):
            if not {i, j} & used and fits(a, items[j]) and fits(items[j], a):
                used |= {i, j}
                out.append((i, j))
    return out


def exact_length(ctx: Ctx, start: str, end: str, k: int) -> float:
    """The exact distance between two point steps at position k (SI)."""
    return float(np.hypot(*(ctx.ev[end][k] - ctx.ev[start][k])))


def given_mu(ctx: Ctx, plan: Plan) -> tuple[float, str] | None:
    """A plan's scale factor given on the command line, else written on the submission, and
    where it comes from (None: neither)."""
    if plan in ctx.options.mu:
        return ctx.options.mu[plan], T("mu.cli")
    return ctx.interp.scales.get(plan)


def segments_of(c: Construction, key: PlanKey) -> list[Segment]:
    """The construction's segments on one plan (a force polygon of one group)."""
    return [s for s in c.segments if segment_key(s) == key or (
        s.plan is Plan.FORCE and plan_key(s.plan, c[s.end].group) == key)]


def _off(x: float | None, tol: float | None) -> bool:
    return x is not None and tol is not None and abs(x) > tol


def row_error(r: SegmentRow) -> str:
    """"length", "direction" or "length and direction": what is off in a segment row."""
    return " and ".join(kind for kind, off in (("length", _off(r.error_mm, r.tolerance_mm)), (
        "direction", _off(r.direction_deg, r.tolerance_deg))) if off)


def row_brief(r: SegmentRow) -> str:
    """What is off in a segment row, in a few words ("pb is 3.1 mm too long")."""
    parts = []
    if _off(r.error_mm, r.tolerance_mm):
        e = float(r.error_mm or 0.0)
        parts.append(T("brief.long" if e > 0 else "brief.short", name=r.name, err=abs(e)))
    if _off(r.direction_deg, r.tolerance_deg):
        parts.append(T("brief.turned", name=r.name, dir=r.direction_deg))
    return join(parts) if parts else T("brief.off", name=r.name)


def segment_finding(plan: str, r: SegmentRow) -> Finding:
    """The finding of a wrong segment whose error is new: what is off, and the hint."""
    return Finding("wrong segment", plan, r.name, T("colon", a=row_brief(r), b=r.hint), r.step,
                   row_error(r))


def roots_of(ctx: Ctx, status: dict[str, str], sid: str, also: str | None = None) -> list[str]:
    """Wrong points with a new error (or swapped labels) that a step is built from, in
    construction order; ``also`` (a segment's own end or start) first when it is one itself."""
    built_from = [s for s in ctx.c.ancestors([sid]) if s != sid]
    candidates = built_from if also is None else [also, *built_from]
    return list(dict.fromkeys(s for s in candidates if status.get(s) in (NEW, SWAPPED)))
