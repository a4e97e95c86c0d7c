"""A sheet with plans of several crank positions: each plan graded at its own position.

Sheet 1 of the course project draws the velocity plan of every position (and students draw
several plans on one sheet). Graded at one crank angle, every plan but one would be "wrong". When
the angle is not given and the sheet holds more than one plan of a kind, each drawn plan is given
the scene position its drawing fits best, and the plans of one position are graded together (the
student's own points of one plan re-derive only the plans of the same position).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Sequence

import numpy as np

from .context import Ctx
from .report import SLIP, WRONG, CheckReport, PlanReport, PointRow, SegmentRow, ValueRow
from .texts import T

Grader = Callable[[Ctx, int], CheckReport]


def several_positions(ctx: Ctx) -> bool:
    """Whether the sheet holds more than one drawn plan of a kind (e.g. velocity plans #1, #2)."""
    if ctx.sheet is None:
        return False
    kinds = [dp.plan for dp in ctx.sheet.plans]
    return len(set(kinds)) < len(kinds)


def fit_score(rows: Sequence[SegmentRow | ValueRow],
              points: Sequence[PointRow] = ()) -> tuple[float, float]:
    """How badly rows (and points) fit a position: wrong ones, then the median relative error."""
    wrong = sum(1 for row in [*rows, *points] if row.verdict in (WRONG, SLIP))
    errs = [abs(row.error_pct) for row in rows if row.error_pct is not None]
    return (wrong, float(np.median(errs)) if errs else math.inf)


def _best_position(reports: list[CheckReport], j: int) -> int:
    """The candidate position at which drawn plan ``j`` fits best."""
    plans = [r.plans[j] for r in reports]
    return min(range(len(plans)), key=lambda k: fit_score(plans[k].segments, plans[k].points))


def grade_per_plan(ctx: Ctx, reports: list[CheckReport], best: int,
                   grade: Grader) -> CheckReport:
    """One report whose drawn plans are each graded at their best-fitting position.

    ``reports[k]`` graded every plan at candidate position k (drawn plans first, in the sheet's
    order); ``best`` is the position that fits the whole sheet best — its written values and
    table segments are kept.
    """
    assert ctx.sheet is not None
    drawn = ctx.sheet.plans
    at = [_best_position(reports, j) for j in range(len(drawn))]
    groups = {k: [j for j in range(len(drawn)) if at[j] == k] for k in dict.fromkeys(at)}
    graded: dict[int, PlanReport] = {}
    base = reports[best]
    names = {dp.name for dp in drawn}
    out = CheckReport(base.scene, base.submission, base.kind, base.phi_deg,
                      T("phi.per_plan", n=len(reports)))
    for k, members in groups.items():
        sheet = dataclasses.replace(ctx.sheet, plans=[drawn[j] for j in members])
        rep = grade(dataclasses.replace(ctx, sheet=sheet), k)
        mine = {drawn[j].name for j in members}
        for j, pr in zip(members, rep.plans):
            pr.phi_deg = rep.phi_deg
            graded[j] = pr
        out.findings += [f for f in rep.findings if f.plan in mine]
        out.notes += rep.notes
    # the written values and table segments as graded at the sheet's best position
    out.plans = [graded[j] for j in range(len(drawn))] + base.plans[len(drawn):]
    out.values = base.values
    out.findings += [f for f in base.findings if f.plan not in names]
    first = graded[0].phi_deg if drawn else None
    out.phi_deg = base.phi_deg if first is None else first
    return out
