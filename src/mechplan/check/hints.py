"""Hints for wrong items, from the construction graph: what rule the step follows and which part
of it the submission breaks, measured from the student's own earlier points."""

from __future__ import annotations

import math
from collections.abc import Callable, Container
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..construct.graph import Construction
from ..construct.ops import Grade, Hint, Joined
from ..construct.ops.spec import hint, measured, point_of
from ..construct.step import Kind, Step
from ..model.mechanism import Mechanism
from ..model.plans import Plan
from .texts import T, Text, join

Value = Callable[[str], np.ndarray]      # the student's own value of a step (leading axis 1)


@dataclass
class HintContext:
    """What a hint may use: the construction, the student's own values, μ of each plan."""

    c: Construction
    mech: Mechanism
    own: Value                      # value of a step from the student's points (not the step's own)
    exact: Value                    # exact value of a step
    mu: dict[Plan, float]

    def labels(self, sid: str) -> str:
        """The label of a step as written on the plans."""
        return self.c[sid].label

    def mm(self, plan: Plan, length: float) -> float:
        """A physical length on a plan in mm of paper."""
        return length / self.mu.get(plan, 1.0)

    def link_of(self, *points: str) -> str | None:
        """The moving link that holds all the named points."""
        links = self.mech.links
        return next((k for k in self.mech.moving if all(p in links[k].points for p in points)),
                    None)


def text_of(h: Any) -> Any:
    """A construction operation's :class:`Hint` (or :class:`Joined` list) as the checker's text."""
    if isinstance(h, Hint):
        return T(h.key, **{k: text_of(v) for k, v in h.args.items()})
    if isinstance(h, Joined):
        return join([text_of(x) for x in h.items], h.sep)
    return h


def rule(ctx: HintContext, step: Step, at: np.ndarray, tol_mm: float) -> Text:
    """What the step's rule is and how the submitted point ``at`` (SI) breaks it: the rule of its
    operation (``OpSpec.hint_rule``), measured from the student's own earlier points."""
    own_here = point_of(ctx.own(step.id))
    off = (ctx.mm(step.plan, float(np.hypot(*(at - own_here))))
           if np.all(np.isfinite(own_here)) else math.nan)
    op = step.op
    if op.hint_rule is None:
        said = measured(hint("rule.op", label=ctx.labels(step.id), op=hint(f"op.{op.value}")))
    else:
        said = op.hint_rule(step, ctx, at, tol_mm)
    body = text_of(said)
    return T("rule.tail", body=body, off=off) if said.measured else body


def depends_on(c: Construction, sid: str, present: Container[str]) -> list[str]:
    """Labels of the earlier points (present on the submission), poles and ω/ε a step is built
    from."""
    out: list[str] = []
    seen: set[str] = set()
    stack = list(c[sid].inputs)
    while stack:
        x = stack.pop(0)
        if x in seen:
            continue
        seen.add(x)
        st = c[x]
        if x in present or st.op.grade in (Grade.RATE, Grade.ORIGIN):
            out.append(st.label)
        elif not (st.plan is Plan.POSITION and st.kind is Kind.POINT):   # given to the plans
            stack.extend(st.inputs)
    return list(dict.fromkeys(out))
