"""Hints for wrong items, from the construction graph: what rule the step follows and which part
of it the submission breaks, measured from the student's own earlier points."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..construct.graph import Construction
from ..construct.step import Kind, Op, Plan, Step
from ..model.mechanism import GROUND, Mechanism
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
    labels: Callable[[str], str]    # label of a step as written on the plans

    def mm(self, plan: Plan, length: float) -> float:
        """A physical length on a plan in mm of paper."""
        return length / self.mu.get(plan, 1.0)


def _pt(v: np.ndarray) -> np.ndarray:
    return np.asarray(v, dtype=float).reshape(-1)[:2]


def _dist_to_line(p: np.ndarray, line: np.ndarray) -> float:
    line = np.asarray(line, dtype=float).reshape(2, 2)
    o, u = line[0], line[1]
    n = math.hypot(*u)
    if not n or not np.all(np.isfinite(line)):
        return math.nan
    d = p - o
    return abs(d[0] * u[1] - d[1] * u[0]) / n


def link_of_points(mech: Mechanism, *points: str) -> str | None:
    """The moving link that holds all the named points."""
    for lid, link in mech.links.items():
        if lid != GROUND and all(p in link.points for p in points):
            return lid
    return None


def rule(ctx: HintContext, step: Step, at: np.ndarray, tol_mm: float) -> Text:
    """What the step's rule is and how the submitted point ``at`` (SI) breaks it."""
    c, plan = ctx.c, step.plan
    lbl = ctx.labels
    label = lbl(step.id)
    own_here = _pt(ctx.own(step.id))
    off = (ctx.mm(plan, float(np.hypot(*(at - own_here))))
           if np.all(np.isfinite(own_here)) else math.nan)

    def tail(body: Text) -> Text:
        return T("rule.tail", body=body, off=off)

    def on_lines() -> Text:
        parts = []
        for lid in step.inputs:
            line_step = c[lid]
            through = lbl(line_step.inputs[0]) if line_step.inputs else "?"
            d = ctx.mm(plan, _dist_to_line(at, ctx.own(lid)))
            where = T("rule.on_it") if d <= tol_mm else T("rule.off_by", d=d)
            parts.append(T("rule.on_line", through=through, line=line_step.label, where=where))
        return join(parts, " and ")

    op = step.op
    if op is Op.FORCE_SUM:
        prev, force = step.inputs[0], step.inputs[1]
        exact_len = ctx.mm(plan, float(np.hypot(*_pt(ctx.exact(force)))))
        drawn = ctx.mm(plan, float(np.hypot(*(at - _pt(ctx.own(prev))))))
        name = c[force].label
        if drawn <= tol_mm < exact_len:
            return T("rule.load_missing", name=name, prev=lbl(prev), len=exact_len)
        return tail(T("rule.load_end", label=label, name=name, prev=lbl(prev), len=exact_len))
    if op in (Op.LINE_LINE, Op.FORCE_CLOSE):
        key = "rule.closes" if op is Op.FORCE_CLOSE else "rule.must_lie"
        return tail(T(key, label=label, parts=on_lines()))
    if op is Op.SIMILAR_IMAGE:
        ia, ib, pa, pb, px = step.inputs
        a_l, b_l = lbl(ia), lbl(ib)
        A, B, X = c[pa].label, c[pb].label, c[px].label
        link = link_of_points(ctx.mech, A, B, X)
        link_txt = T("rule.of_link", link=link) if link else ""
        pts = [_pt(ctx.exact(s)) for s in (pa, pb, px)]
        cross = (pts[1] - pts[0])[0] * (pts[2] - pts[0])[1] - \
            (pts[1] - pts[0])[1] * (pts[2] - pts[0])[0]
        ab = float(np.hypot(*(pts[1] - pts[0])))
        oa, ob = _pt(ctx.own(ia)), _pt(ctx.own(ib))
        text = T("rule.similar", label=label, link=link_txt, a=a_l, b=b_l, A=A, B=B, X=X)
        if ab and abs(cross) <= 1e-9 * ab * ab:
            t = float(np.dot(pts[2] - pts[0], pts[1] - pts[0]) / ab ** 2)
            seg = ob - oa
            n2 = float(np.dot(seg, seg))
            if n2 > 0:
                line = np.array([oa, seg])
                d = ctx.mm(plan, _dist_to_line(at, line))
                yours = float(np.dot(at - oa, seg) / n2)
                text = T("rule.similar_line", link=link_txt, label=label, a=a_l, b=b_l, d=d,
                         A=A, B=B, X=X, t=t, yours=yours)
        return tail(text)
    if op in (Op.DRIVE_VELOCITY, Op.DRIVE_ACCELERATION):
        pivot, tip = c[step.inputs[0]].label, c[step.inputs[1]].label
        exact = _pt(ctx.exact(step.id))
        length = ctx.mm(plan, float(np.hypot(*exact)))
        drawn = ctx.mm(plan, float(np.hypot(*at)))
        ang = math.degrees(math.remainder(math.atan2(at[1], at[0]) - math.atan2(exact[1], exact[0]),
                                          2 * math.pi))
        how = T("rule.drive_v" if op is Op.DRIVE_VELOCITY else "rule.drive_a", pivot=pivot,
                tip=tip)
        return T("rule.drive", label=label, how=how, len=length, drawn=drawn, ang=ang)
    if op is Op.NORMAL:
        ap, omega, p, q = step.inputs
        own_w = float(np.asarray(ctx.own(omega)).reshape(-1)[0])
        exact_w = float(np.asarray(ctx.exact(omega)).reshape(-1)[0])
        l = float(np.hypot(*(_pt(ctx.exact(q)) - _pt(ctx.exact(p)))))
        P, Q = c[p].label, c[q].label
        own_len = ctx.mm(plan, own_w * own_w * l)
        exact_len = ctx.mm(plan, exact_w * exact_w * l)
        wl = c[omega].label
        own_txt = (T("rule.normal_own", w=wl, ow=own_w, olen=own_len)
                   if abs(own_w - exact_w) > 1e-9 * max(1.0, abs(exact_w)) else "")
        return tail(T("rule.normal", label=label, ap=lbl(ap), P=P, Q=Q, w=wl, len=exact_len,
                      own=own_txt))
    if op is Op.CORIOLIS:
        start, omega, _, _ = step.inputs
        wl = c[omega].label
        length = ctx.mm(plan, float(np.hypot(*(_pt(ctx.exact(step.id)) - _pt(ctx.exact(start))))))
        return tail(T("rule.coriolis", label=label, w=wl, start=lbl(start), len=length))
    if op in (Op.RIGID_VELOCITY, Op.RIGID_ACCELERATION):
        o = step.inputs[0]
        return tail(T("rule.rigid", label=label, X=c[step.inputs[-1]].label, o=lbl(o)))
    if op in (Op.POLAR_POINT, Op.CIRCLE_CIRCLE, Op.CIRCLE_LINE, Op.PLACE, Op.SIMILAR_POSITION):
        return tail(T("rule.position", label=label))
    if op is Op.POLE:
        return T("rule.pole", label=label)
    return tail(T("rule.op", label=label, op=T(f"op.{op.value}")))


def depends_on(c: Construction, sid: str, present: set[str], labels: Callable[[str], str]
               ) -> list[str]:
    """Labels of the earlier points (present on the submission) and ω/ε a step is built from."""
    out: list[str] = []
    seen: set[str] = set()
    stack = list(c[sid].inputs)
    while stack:
        x = stack.pop(0)
        if x in seen:
            continue
        seen.add(x)
        st = c[x]
        if x in present:
            out.append(labels(x))
        elif st.kind is Kind.SCALAR and st.op in (Op.OMEGA, Op.EPSILON, Op.COPY):
            out.append(st.label)
        elif st.plan is Plan.POSITION and st.kind is Kind.POINT:
            continue
        elif st.kind is Kind.POINT and st.op is Op.POLE:
            out.append(labels(x))
        else:
            stack.extend(st.inputs)
    return list(dict.fromkeys(out))
