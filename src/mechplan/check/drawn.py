"""Place a drawn plan on the exact one: its anchor (pole), a plan turned by 90° (Zhukovsky),
its scale factor; swapped labels; each wrong point new or carried from earlier ones."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..construct.ops import Grade
from ..construct.ops.spec import point_of
from ..geom.vec import rotate
from ..model.plans import Plan
from ..submission.drawn_plans import DrawnPlan
from ..submission.read import Note
from .context import (
    Ctx,
    Drawn,
    Rederive,
    exact_length,
    given_mu,
    segments_of,
    swaps,
)
from .report import (
    CARRIED,
    NEW,
    SWAPPED,
)
from .texts import T, plan_title, with_case


def anchor_of(ctx: Ctx, dp: DrawnPlan) -> str | None:
    """The point a drawn plan is placed by: its pole, else the drive pivot or the first point."""
    c = ctx.c
    pole = ctx.book.poles.get(dp.key)
    if pole in dp.points:
        return pole
    if dp.plan is Plan.POSITION:
        segs = segments_of(c, dp.key)
        if segs and segs[0].start in dp.points:
            return segs[0].start
        fixed = [s for s in dp.points if c[s].op.grade is Grade.GIVEN]
        if fixed:
            return fixed[0]
    return next((s for s in c.steps if s in dp.points), None)


def _turned(ctx: Ctx, dp: DrawnPlan, k: int, anchor: str | None) -> float:
    """±90 when a velocity plan is drawn turned by a right angle (Zhukovsky's lever), else 0."""
    if dp.plan is not Plan.VELOCITY or anchor is None:
        return 0.0
    a_at = np.asarray(dp.points[anchor].at)
    base = ctx.ev[anchor][k]
    diffs = []
    for sid, p in dp.points.items():
        v, e = np.asarray(p.at) - a_at, ctx.ev[sid][k] - base
        if sid != anchor and np.hypot(*v) > 1e-6 and np.hypot(*e) > 0:
            diffs.append(math.degrees(math.remainder(
                math.atan2(v[1], v[0]) - math.atan2(e[1], e[0]), 2 * math.pi)))
    if len(diffs) < 2:
        return 0.0
    for turn in (90.0, -90.0):
        if sum(abs(d - turn) < 3.0 for d in diffs) > len(diffs) / 2:
            return turn
    return 0.0


def _turn_back(dp: DrawnPlan, anchor: str, turn: float) -> DrawnPlan:
    """A drawn plan turned back by ``turn`` degrees about its anchor (the convention says so)."""
    o = np.asarray(dp.points[anchor].at)

    def q(p: tuple[float, float]) -> tuple[float, float]:
        x, y = o + rotate(np.asarray(p) - o, np.radians(-turn))
        return (float(x), float(y))

    note = T("convention.turned", turn=turn, label=dp.points[anchor].label)
    return replace(dp, points={s: replace(p, at=q(p.at)) for s, p in dp.points.items()},
                   lines=[replace(ln, start=q(ln.start), end=q(ln.end)) for ln in dp.lines],
                   convention=T("pair", a=dp.convention, b=note) if dp.convention else note)


def prepare(ctx: Ctx, dp: DrawnPlan, k: int, notes: list[Note]) -> Drawn:
    """A drawn plan placed on the exact one: its anchor, turn, scale factor and points in SI."""
    plan = dp.plan
    anchor = anchor_of(ctx, dp)
    turn = _turned(ctx, dp, k, anchor)
    if turn and anchor is not None:
        dp = _turn_back(dp, anchor, turn)
    mu, source = dp.mu, dp.mu_source        # written beside the plan (none when given otherwise)
    if mu is None:
        mu, source = given_mu(ctx, plan) or (None, source)
    reference = None
    if mu is None:      # the first segment drawn is taken at its exact length
        reference = next((s for s in segments_of(ctx.c, dp.key)
                          if s.start in dp.points and s.end in dp.points), None)
        if reference is not None:
            exact = exact_length(ctx, reference.start, reference.end, k)
            drawn = math.dist(dp.points[reference.end].at, dp.points[reference.start].at)
            if drawn > 1e-9 and exact > 0:
                mu = exact / drawn
                source = T("mu.inferred_drawn", ref=reference.name, q=reference.quantity,
                           drawn=drawn, exact=exact, unit=plan.unit,
                           plan=plan_title(plan.value, case="gen"))
        if mu is None:
            notes.append(Note("error", T("note.no_mu", plan=with_case(dp.name, "gen"),
                                         v=plan.value[0]), ctx.sub.path))
    si: dict[str, np.ndarray] = {}
    if mu is not None and anchor is not None:   # in SI, the anchor on its exact point
        a_at = np.asarray(dp.points[anchor].at)
        si = {sid: ctx.ev[anchor][k] + (np.asarray(p.at) - a_at) * mu
              for sid, p in dp.points.items()}
    return Drawn(dp, mu, source, anchor, si, reference)


def overrides_of(drawn: list[Drawn]) -> dict[str, np.ndarray]:
    """The submitted points (SI) as engine overrides; a point with swapped labels is taken where
    its partner's label stands."""
    return {sid: d.si[d.swapped.get(sid, sid)] for d in drawn for sid in d.si}


def find_swaps(ctx: Ctx, d: Drawn, k: int) -> None:
    """Each point's tolerance and total error (mm), and pairs of wrong points with their labels
    exchanged."""
    mu, anchor = d.mu, d.anchor
    if mu is None or anchor is None:        # not placed: no point is in SI
        return

    def off(at: np.ndarray, sid: str) -> float:
        """How far a point (SI) is from a step's exact point, in mm of paper."""
        return float(np.hypot(*(at - ctx.ev[sid][k]))) / mu

    tol = ctx.options.tol(d.dp.plan)
    wrong = []
    for sid, v in d.si.items():
        d.tol[sid] = tol.allowed_mm(exact_length(ctx, anchor, sid, k) / mu)
        d.errors[sid] = off(v, sid)
        if d.errors[sid] > d.tol[sid]:
            wrong.append(sid)
    for a, b in swaps(wrong, lambda a, b: off(d.si[a], b) <= d.tol[b]):
        d.swapped[a], d.swapped[b] = b, a


def classify_points(d: Drawn, red: Rederive) -> None:
    """Why each wrong point is wrong: swapped labels, or an error carried from earlier points
    (it lies where the student's own earlier points put it) or new at this step."""
    for sid in d.dp.points:
        err = d.errors.get(sid)
        if err is None or err <= d.tol[sid]:
            continue
        if sid in d.swapped:
            d.status[sid] = SWAPPED
            continue
        own = point_of(red.own(sid))
        own_err = (float(np.hypot(*(d.si[sid] - own))) / d.mu if d.mu and
                   np.all(np.isfinite(own)) else math.inf)
        d.own_err[sid] = own_err
        d.status[sid] = CARRIED if own_err <= d.tol[sid] else NEW
