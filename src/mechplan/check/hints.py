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


def _fmt(x: float, digits: int = 1) -> str:
    return "?" if not math.isfinite(x) else f"{x:.{digits}f}"


def link_of_points(mech: Mechanism, *points: str) -> str | None:
    """The moving link that holds all the named points."""
    for lid, link in mech.links.items():
        if lid != GROUND and all(p in link.points for p in points):
            return lid
    return None


def rule(ctx: HintContext, step: Step, at: np.ndarray, tol_mm: float) -> str:
    """What the step's rule is and how the submitted point ``at`` (SI) breaks it."""
    c, plan = ctx.c, step.plan
    lbl = ctx.labels
    label = lbl(step.id)
    own_here = _pt(ctx.own(step.id))
    off = ctx.mm(plan, float(np.hypot(*(at - own_here)))) if np.all(np.isfinite(own_here)) else math.nan
    tail = f"; from your own earlier points it belongs {_fmt(off)} mm from where it is drawn"
    op = step.op
    if op is Op.FORCE_SUM:
        prev, force = step.inputs[0], step.inputs[1]
        exact_len = ctx.mm(plan, float(np.hypot(*_pt(ctx.exact(force)))))
        drawn = ctx.mm(plan, float(np.hypot(*(at - _pt(ctx.own(prev))))))
        name = c[force].label
        if drawn <= tol_mm < exact_len:
            return (f"the load {name} is missing from this force polygon: it acts on the group "
                    f"and is laid off from {lbl(prev)}, {_fmt(exact_len)} mm long")
        return (f"{label} is the end of the load {name} laid off from {lbl(prev)}: "
                f"{_fmt(exact_len)} mm long, in the direction of the force" + tail)
    if op in (Op.LINE_LINE, Op.FORCE_CLOSE):
        parts = []
        for lid in step.inputs:
            line_step = c[lid]
            through = lbl(line_step.inputs[0]) if line_step.inputs else "?"
            d = ctx.mm(plan, _dist_to_line(at, ctx.own(lid)))
            where = "on it" if d <= tol_mm else f"{_fmt(d)} mm off"
            parts.append(f"on the line through {through} {line_step.label} ({where})")
        closes = "closes the force polygon: it " if op is Op.FORCE_CLOSE else ""
        return f"{label} {closes}must lie " + " and ".join(parts) + tail
    if op is Op.LINE_LINE:
        parts = []
        for lid in step.inputs:
            line_step = c[lid]
            through = lbl(line_step.inputs[0]) if line_step.inputs else "?"
            d = ctx.mm(plan, _dist_to_line(at, ctx.own(lid)))
            where = "on it" if d <= tol_mm else f"{_fmt(d)} mm off"
            parts.append(f"on the line through {through} {line_step.label} ({where})")
        return f"{label} must lie " + " and ".join(parts) + tail
    if op is Op.SIMILAR_IMAGE:
        ia, ib, pa, pb, px = step.inputs
        a_l, b_l = lbl(ia), lbl(ib)
        A, B, X = c[pa].label, c[pb].label, c[px].label
        link = link_of_points(ctx.mech, A, B, X)
        link_txt = f" of link {link}" if link else ""
        pts = [_pt(ctx.exact(s)) for s in (pa, pb, px)]
        cross = (pts[1] - pts[0])[0] * (pts[2] - pts[0])[1] - \
            (pts[1] - pts[0])[1] * (pts[2] - pts[0])[0]
        ab = float(np.hypot(*(pts[1] - pts[0])))
        oa, ob = _pt(ctx.own(ia)), _pt(ctx.own(ib))
        text = (f"by the similarity theorem the image {label} of a point{link_txt} makes the "
                f"triangle {a_l}{b_l}{label} similar to {A}{B}{X} (same sense of rotation)")
        if ab and abs(cross) <= 1e-9 * ab * ab:
            t = float(np.dot(pts[2] - pts[0], pts[1] - pts[0]) / ab ** 2)
            seg = ob - oa
            n2 = float(np.dot(seg, seg))
            if n2 > 0:
                line = np.array([oa, seg])
                d = ctx.mm(plan, _dist_to_line(at, line))
                yours = float(np.dot(at - oa, seg) / n2)
                text = (f"the image of a point{link_txt} lies on the image of the link: {label} "
                        f"must lie on {a_l}{b_l} ({_fmt(d)} mm off it) and divide it as "
                        f"{A}{X}/{A}{B} = {t:.3f} (yours {yours:.3f})")
        return text + tail
    if op in (Op.DRIVE_VELOCITY, Op.DRIVE_ACCELERATION):
        pivot, tip = c[step.inputs[0]].label, c[step.inputs[1]].label
        exact = _pt(ctx.exact(step.id))
        length = ctx.mm(plan, float(np.hypot(*exact)))
        drawn = ctx.mm(plan, float(np.hypot(*at)))
        ang = math.degrees(math.remainder(math.atan2(at[1], at[0]) - math.atan2(exact[1], exact[0]),
                                          2 * math.pi))
        how = (f"⊥ {pivot}{tip} in the sense of ω, ω·l_{pivot}{tip}" if op is Op.DRIVE_VELOCITY
               else f"∥ {tip}{pivot} from {tip} towards {pivot}, ω²·l_{pivot}{tip}")
        return (f"the driving vector to {label} is drawn {how} = {_fmt(length)} mm at this scale; "
                f"yours is {_fmt(drawn)} mm, turned {_fmt(ang)}°")
    if op is Op.NORMAL:
        ap, omega, p, q = step.inputs
        own_w = float(np.asarray(ctx.own(omega)).reshape(-1)[0])
        exact_w = float(np.asarray(ctx.exact(omega)).reshape(-1)[0])
        l = float(np.hypot(*(_pt(ctx.exact(q)) - _pt(ctx.exact(p)))))
        P, Q = c[p].label, c[q].label
        own_len = ctx.mm(plan, own_w * own_w * l)
        exact_len = ctx.mm(plan, exact_w * exact_w * l)
        wl = c[omega].label
        text = (f"the normal component {label} is laid off from {lbl(ap)} ∥ {Q}{P}, from {Q} "
                f"towards {P}, {wl}²·l_{P}{Q} long: {_fmt(exact_len)} mm")
        if abs(own_w - exact_w) > 1e-9 * max(1.0, abs(exact_w)):
            text += (f" (with {wl} = {own_w:.3f} rad/s from your velocity plan: "
                     f"{_fmt(own_len)} mm)")
        return text + tail
    if op is Op.CORIOLIS:
        start, omega, _, _ = step.inputs
        wl = c[omega].label
        return (f"the Coriolis component {label} = 2{wl}·v_rel is laid off from {lbl(start)}, "
                f"perpendicular to the guide, v_rel turned 90° in the sense of {wl}: "
                f"{_fmt(ctx.mm(plan, float(np.hypot(*(_pt(ctx.exact(step.id)) - _pt(ctx.exact(start)))))))}"
                f" mm" + tail)
    if op in (Op.RIGID_VELOCITY, Op.RIGID_ACCELERATION):
        o = step.inputs[0]
        return (f"the image {label} of {c[step.inputs[-1]].label} follows from {lbl(o)} by the "
                f"link's rotation" + tail)
    if op in (Op.POLAR_POINT, Op.CIRCLE_CIRCLE, Op.CIRCLE_LINE, Op.PLACE, Op.SIMILAR_POSITION):
        return f"{label} follows from the link lengths and the points before it" + tail
    if op is Op.POLE:
        return f"{label} is the pole"
    return f"{label} is built by '{op.value.replace('_', ' ')}'" + tail


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
