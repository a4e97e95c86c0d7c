"""Place a drawn plan on the exact one: its anchor (pole), a plan turned by 90° (Zhukovsky),
its scale factor; swapped labels; each wrong point new or carried from earlier ones."""

from __future__ import annotations

import math

import numpy as np

from ..construct.ops import Grade
from ..construct.step import Plan
from ..geom.vec import rotate
from ..submission.read import Note
from .context import (
    Ctx,
    Drawn,
    Rederive,
    exact_at,
    segments_of,
    swaps,
)
from .points import DrawnPlan
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
    if not dp.points:
        return None
    order = list(c.steps)
    anchor = min(dp.points, key=order.index)
    if dp.plan is Plan.POSITION:
        segs = segments_of(c, dp.key)
        fixed = [s for s in dp.points if c[s].op.grade is Grade.GIVEN]
        pivot = segs[0].start if segs else None
        anchor = pivot if pivot in dp.points else (fixed[0] if fixed else anchor)
    return anchor


def _turned(ctx: Ctx, dp: DrawnPlan, k: int, anchor: str | None) -> float:
    """±90 when a velocity plan is drawn turned by a right angle (Zhukovsky's lever), else 0."""
    if dp.plan is not Plan.VELOCITY or anchor is None:
        return 0.0
    a_at = np.asarray(dp.points[anchor].at)
    base = exact_at(ctx, anchor, k)
    diffs = []
    for sid, p in dp.points.items():
        v, e = np.asarray(p.at) - a_at, exact_at(ctx, sid, k) - base
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
    from dataclasses import replace

    o = np.asarray(dp.points[anchor].at)

    def q(p: tuple[float, float]) -> tuple[float, float]:
        x, y = o + rotate(np.asarray(p) - o, np.radians(-turn))
        return (float(x), float(y))

    out = DrawnPlan(dp.key, {s: replace(p, at=q(p.at)) for s, p in dp.points.items()},
                    [replace(ln, start=q(ln.start), end=q(ln.end)) for ln in dp.lines],
                    dp.number, dp.mu, dp.mu_source, dp.convention)
    note = T("convention.turned", turn=turn, label=dp.points[anchor].label)
    out.convention = T("pair", a=dp.convention, b=note) if dp.convention else note
    return out


def prepare(ctx: Ctx, dp: DrawnPlan, k: int, notes: list[Note]) -> Drawn:
    c = ctx.c
    plan = dp.plan
    anchor = anchor_of(ctx, dp)
    turn = _turned(ctx, dp, k, anchor)
    if turn and anchor is not None:
        dp = _turn_back(dp, anchor, turn)
    mu, source = dp.mu, dp.mu_source
    if mu is None and plan in ctx.interp.scales:
        mu, source = ctx.interp.scales[plan]
    segs = segments_of(c, dp.key)
    reference = next((s for s in segs if s.start in dp.points and s.end in dp.points), None)
    if mu is None:
        if reference is not None:
            exact = float(np.hypot(*(exact_at(ctx, reference.end, k)
                                     - exact_at(ctx, reference.start, k))))
            drawn = math.dist(dp.points[reference.end].at, dp.points[reference.start].at)
            if drawn > 1e-9 and exact > 0:
                mu = exact / drawn
                source = T("mu.inferred_drawn", ref=reference.name, q=reference.quantity,
                           drawn=drawn, exact=exact,
                           unit=plan.unit,
                           plan=plan_title(plan.value, case="gen"))
        if mu is None:
            notes.append(Note("error", T("note.no_mu", plan=with_case(dp.name, "gen"),
                                         v=plan.value[0]), ctx.sub.path))
    else:
        reference = None
    si: dict[str, np.ndarray] = {}
    if mu is not None and anchor is not None:
        base = exact_at(ctx, anchor, k)
        a_at = np.asarray(dp.points[anchor].at)
        for sid, p in dp.points.items():
            si[sid] = base + (np.asarray(p.at) - a_at) * mu
    return Drawn(dp, mu, source, anchor, si, reference)


def overrides_of(drawn: list[Drawn]) -> dict[str, np.ndarray]:
    out: dict[str, np.ndarray] = {}
    for d in drawn:
        for sid, v in d.si.items():
            other = d.swapped.get(sid)
            out[sid] = d.si[other] if other else v
    return out


def _point_tol(ctx: Ctx, d: Drawn, sid: str, k: int) -> float:
    tol = ctx.options.tol(d.dp.plan)
    if d.anchor is None or d.mu is None:
        return tol.mm
    dist = float(np.hypot(*(exact_at(ctx, sid, k) - exact_at(ctx, d.anchor, k)))) / d.mu
    return tol.allowed_mm(dist)


def find_swaps(ctx: Ctx, d: Drawn, k: int) -> None:
    if d.mu is None:
        return
    wrong = []
    for sid, v in d.si.items():
        d.tol[sid] = _point_tol(ctx, d, sid, k)
        d.errors[sid] = float(np.hypot(*(v - exact_at(ctx, sid, k)))) / d.mu
        if d.errors[sid] > d.tol[sid]:
            wrong.append(sid)
    mu = d.mu
    for a, b in swaps(wrong, lambda a, b: float(np.hypot(*(d.si[a] - exact_at(ctx, b, k)))) / mu
                      <= d.tol[b]):
        d.swapped[a], d.swapped[b] = b, a


def classify_points(ctx: Ctx, d: Drawn, red: Rederive) -> None:
    """Total error of each point, and for wrong ones whether the error is new or carried."""
    for sid in d.dp.points:
        err = d.errors.get(sid)
        if err is None or err <= d.tol[sid]:
            continue
        if sid in d.swapped:
            d.status[sid] = SWAPPED
            continue
        own = np.asarray(red.own(sid)).reshape(-1)[:2]
        own_err = (float(np.hypot(*(d.si[sid] - own))) / d.mu if d.mu and
                   np.all(np.isfinite(own)) else math.inf)
        d.own_err[sid] = own_err
        d.status[sid] = CARRIED if own_err <= d.tol[sid] else NEW
