"""Ruler mode: the construction evaluated with every placed point rounded to the drawing's
precision."""

from __future__ import annotations

from typing import Any

import numpy as np

from mechplan.construct.graph import Construction, Evaluation
from mechplan.construct.ops import Op
from mechplan.construct.step import Kind
from mechplan.model.plans import Plan


class RulerEvaluation(Evaluation):
    """The construction as a student draws it: each point placed to the ruler's precision.

    Every point-valued step of a plan (a crank pin, a compass meet, an image on the velocity or
    acceleration plan, the end of a normal or Coriolis component) is measured from the point its
    segment starts at (the previous image, the pole, the link's other end) and put back at that
    length rounded to ``delta`` (the ruler's precision in mm times the plan's scale factor μ), with
    its direction rounded so that the end moves by at most half of ``delta`` sideways too.
    Everything after it — lines through it, meets, ω and ε from measured segments — is built from
    the rounded point, so errors are carried on as on paper. Frame points and poles are exact.
    """

    def __init__(self, construction: Construction, phi: np.ndarray,
                 delta: dict[Plan, float]) -> None:
        super().__init__(construction, np.atleast_1d(np.asarray(phi, dtype=float)))
        self.delta = delta
        starts: dict[str, str] = {}
        for s in construction.segments:
            starts.setdefault(s.end, s.start)
        self.starts = starts

    def _compute(self, step: Any) -> None:
        Evaluation._compute(self, step)
        if step.kind is not Kind.POINT or step.op in (Op.FIXED_POINT, Op.POLE):
            return
        delta = self.delta.get(step.plan)
        start = self.starts.get(step.id)
        if start is None or start not in self.values:
            start = next((i for i in step.inputs if self.construction[i].kind is Kind.POINT
                          and i in self.values), None)
        if delta is None or start is None:
            return
        origin = self.values[start]
        rel = self.values[step.id] - origin
        length = np.hypot(rel[..., 0], rel[..., 1])
        drawn = np.round(length / delta) * delta
        with np.errstate(invalid="ignore", divide="ignore"):
            arc = np.where(drawn > 0, delta / drawn, 1.0)
            angle = np.round(np.arctan2(rel[..., 1], rel[..., 0]) / arc) * arc
        value = origin + drawn[..., None] * np.stack((np.cos(angle), np.sin(angle)), axis=-1)
        value.flags.writeable = False
        self.values[step.id] = value
