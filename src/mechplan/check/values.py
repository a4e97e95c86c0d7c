"""Grade tables of lengths and named values (v_S2, ω2, Q2, M_b …) against the exact ones and
against the student's own numbers (new, carried, slip)."""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

from ..construct.graph import Construction
from ..construct.ops import Grade
from ..construct.segments import Segment
from ..construct.step import Kind, Plan
from ..errors import MechplanError
from ..submission.read import Note
from ..units import si_unit
from .context import (
    Ctx,
    Drawn,
    Rederive,
    exact_at,
    labels_fn,
    roots_of,
    row_brief,
    seg_exact,
)
from .hints import depends_on, text_of
from .labels import PlanKey, plan_key, segment_key
from .match import GivenValue, TableSegment
from .report import (
    CARRIED,
    NEW,
    OK,
    REFERENCE,
    SLIP,
    SWAPPED,
    UNCHECKED,
    WRONG,
    CheckReport,
    Finding,
    PlanReport,
    SegmentRow,
    ValueRow,
)
from .texts import T, join, plan_title, plan_word


# -- tables of lengths -------------------------------------------------------------------------
def grade_table_segments(ctx: Ctx, k: int, mu_all: dict[Plan, float],
                          report: CheckReport) -> list[PlanReport]:
    c = ctx.c
    by_key: dict[PlanKey, list[TableSegment]] = {}
    for ts in ctx.interp.segments:
        if ctx.sheet is not None:
            continue     # lengths written on a drawn sheet are checked against the drawing below
        by_key.setdefault(ts.key, []).append(ts)
    out = []
    order = {id(s): i for i, s in enumerate(c.segments)}
    for key, items in by_key.items():
        plan = key[0]
        tol = ctx.options.tol(plan)
        items.sort(key=lambda t: order.get(id(t.segment), 0))
        mu, source = None, ""
        if plan in ctx.options.mu:
            mu, source = ctx.options.mu[plan], T("mu.cli")
        elif plan in ctx.interp.scales:
            mu, source = ctx.interp.scales[plan]
        elif any(t.mu for t in items):
            t0 = next(t for t in items if t.mu)
            mu, source = t0.mu, T("mu.row", written=t0.written, where=t0.where)
        reference = None
        if mu is None and items:
            reference = items[0]
            exact = seg_exact(ctx, reference.segment, k)
            if reference.length_mm > 0:
                mu = exact / reference.length_mm
                source = T("mu.inferred_table", written=reference.written,
                           q=reference.segment.quantity, plan=plan_title(plan.value, case="gen"))
        pr = PlanReport(plan_title(plan.value, key[1], table=True), plan.value, key[1], mu,
                        source, tol)
        wrong_ends: dict[str, str] = {}
        for ts in items:
            seg = ts.segment
            row_mu = ts.mu or mu
            exact_val = seg_exact(ctx, seg, k)
            exact_mm = exact_val / row_mu if row_mu else None
            row = SegmentRow(seg.name, seg.quantity, seg.kind.value, seg.end, ts.length_mm,
                             exact_mm, exact_value=exact_val, where=ts.where, start=seg.start,
                             end=seg.end)
            row.submitted_value = ts.length_mm * row_mu if row_mu else None
            if exact_mm is None:
                row.verdict = UNCHECKED
                row.hint = T("hint.no_mu")
            else:
                row.tolerance_mm = tol.allowed_mm(exact_mm)
                row.error_mm = ts.length_mm - exact_mm
                row.error_pct = 100 * row.error_mm / exact_mm if exact_mm else None
                if ts is reference:
                    row.verdict = REFERENCE
                    row.hint = T("hint.reference")
                else:
                    row.verdict = OK if abs(row.error_mm) <= row.tolerance_mm else WRONG
            present = {t.segment.end for t in items} | {t.segment.start for t in items}
            row.depends_on = depends_on(c, seg.end, present, labels_fn(ctx))
            if row.verdict == WRONG:
                anc = set(c.ancestors([seg.end])) - {seg.end}
                earlier = [name for sid, name in wrong_ends.items() if sid in anc]
                if earlier:
                    row.cause = CARRIED
                    row.carried_from = earlier
                    row.hint = T("hint.may_carried_segment", earlier=join(earlier))
                else:
                    row.cause = NEW
                    row.hint = _table_hint(ctx, seg)
                    report.findings.append(Finding("wrong segment", pr.name, seg.name,
                                                   T("colon", a=row_brief(row), b=row.hint),
                                                   seg.end, "length"))
                wrong_ends[seg.end] = seg.name
            pr.segments.append(row)
        out.append(pr)
    return out


def _table_hint(ctx: Ctx, seg: Segment) -> str:
    st = ctx.c[seg.end]
    return text_of(st.op.hint(st, ctx.c))          # the hint of its operation (``OpSpec.hint``)


# -- named values -------------------------------------------------------------------------------
def grade_values(ctx: Ctx, k: int, drawn: list[Drawn], first: dict[PlanKey, Drawn],
                  red: Rederive, mu_all: dict[Plan, float], report: CheckReport) -> None:
    c = ctx.c
    status: dict[str, str] = {}
    for d in first.values():
        for sid, cause in d.status.items():
            status[sid] = cause
    table_len: dict[int, TableSegment] = {id(t.segment): t for t in ctx.interp.segments}
    for gv in ctx.interp.values:
        q = gv.quantity
        row = ValueRow(gv.written, q.display, si_unit(q.dimension), gv.value, None,
                       where=gv.where)
        exact = _value_exact(ctx, q, k, report.notes, gv.where)
        if exact is None:
            row.verdict = UNCHECKED
            report.values.append(row)
            continue
        scalar = q.step is not None and ctx.c[q.step].kind is Kind.SCALAR
        signed = scalar and gv.value < 0
        exact_cmp = exact if signed else abs(exact)
        sub_cmp = gv.value if signed else abs(gv.value)
        row.exact = exact_cmp
        plan = q.plan
        tol = ctx.options.tol(plan)
        mu = mu_all.get(plan) if plan else None
        seg = q.segment or _absolute_segment(c, q.step)
        tol_abs = tol.pct / 100 * abs(exact_cmp)
        # a value is right within the paper tolerance of its segment, at the student's μ or
        # (when they gave none) at the scene's: a short segment is not held to ±2 %
        paper = mu or (ctx.scales.get(plan) if plan else None)
        if seg is not None and paper:
            tol_abs = max(tol_abs, tol.mm * paper)
        elif q.step is not None and c[q.step].op.rate_of is not None and plan is not None:
            mu_p = mu_all.get(plan) or ctx.scales.get(plan)
            l = _link_length(ctx, q.step, k)
            if mu_p and l:
                tol_abs = max(tol_abs, tol.mm * mu_p / l)
        tol_abs = max(tol_abs, gv.half_unit)      # "0.00" is right for anything below 0.005
        row.tolerance = tol_abs
        row.error_pct = 100 * (sub_cmp - exact_cmp) / exact_cmp if exact_cmp else None
        # what the student's own drawing or lengths give
        own, own_text, arith = _own_value(ctx, gv, seg, q, k, red, first, table_len, mu)
        row.own = own
        if own is not None and abs(sub_cmp - (own if signed else abs(own))) > arith:
            row.verdict = SLIP
            row.cause = NEW
            row.hint = T("hint.slip", own=own_text, written=gv.written, text=gv.text)
            report.findings.append(Finding("arithmetic slip", plan_word(plan.value) if plan else "",
                                           gv.written, row.hint, q.step or ""))
        elif abs(sub_cmp - exact_cmp) <= tol_abs:
            row.verdict = OK
        else:
            row.verdict = WRONG
            roots = []
            if seg is not None:
                roots = [c[s].label for s in roots_of(ctx, status, seg.end)]
                if status.get(seg.end) in (NEW, SWAPPED):
                    roots.insert(0, c[seg.end].label)
            elif q.step is not None:
                roots = [c[s].label for s in roots_of(ctx, status, q.step)]
            if own is not None:
                row.cause = CARRIED
                row.hint = (T("hint.own_carried", own=own_text, roots=join(dict.fromkeys(roots)))
                            if roots else T("hint.own", own=own_text))
            elif roots:
                row.cause = CARRIED
                row.hint = T("hint.may_carried", roots=join(dict.fromkeys(roots)))
            else:
                row.cause = NEW
                row.hint = _value_hint(ctx, q)
                report.findings.append(Finding("wrong value",
                                               plan_word(plan.value) if plan else "",
                                               gv.written, T("finding.wrong_value",
                                                             written=gv.written, text=gv.text,
                                                             exact=exact_cmp, unit=row.unit,
                                                             pct=row.error_pct, hint=row.hint)
                                               if row.error_pct is not None else row.hint,
                                               q.step or ""))
        report.values.append(row)


def _value_hint(ctx: Ctx, q: Any) -> str:
    c = ctx.c
    if q.step is not None:
        st = c[q.step]
        if st.op.value_hint is not None:         # ω, ε: the rule of its operation
            return text_of(st.op.value_hint(st, c))
        return T("hint.value_step", display=q.display, op=T(f"op.{st.op.value}"),
                 label=st.label)
    if q.segment is not None:
        return T("hint.value_segment", display=q.display, seg=q.segment.name)
    return T("hint.value_dynamics", display=q.display)


def _absolute_segment(c: Construction, step: str | None) -> Segment | None:
    if step is None:
        return None
    return next((s for s in c.segments
                 if s.end == step and c[s.start].op.grade is Grade.ORIGIN), None)


def _link_length(ctx: Ctx, sid: str, k: int) -> float | None:
    st = ctx.c[sid]
    lever = st.op.lever_of(st)              # ω, ε: the link's two points
    if st.op.rate_of is None or lever is None:
        return None
    p, q = lever
    return float(np.hypot(*(exact_at(ctx, q, k) - exact_at(ctx, p, k))))


def _value_exact(ctx: Ctx, q: Any, k: int, notes: list[Note], where: str) -> float | None:
    if q.step is not None:
        v = exact_at(ctx, q.step, k)
        return float(np.hypot(*v)) if v.ndim == 1 and v.shape[0] == 2 else float(v)
    if q.segment is not None:
        return seg_exact(ctx, q.segment, k)
    if q.extra in ("J_red", "M_red"):
        try:
            from ..dynamics import Loading
            from ..dynamics.reduced import reduced_of

            loading = Loading.from_scene(ctx.scene)
            m_red, j_red = reduced_of(ctx.c, ctx.ev, ctx.scene.mechanism, loading)
            return float((j_red if q.extra == "J_red" else m_red)[k])
        except MechplanError as exc:
            notes.append(Note("warning", T("note.not_computable", extra=q.extra,
                                           error=exc.detail), where))
            return None
    return None


def _own_value(ctx: Ctx, gv: GivenValue, seg: Segment | None, q: Any, k: int, red: Rederive,
               first: dict[PlanKey, Drawn], table_len: dict[int, TableSegment],
               mu: float | None) -> tuple[float | None, str, float]:
    """The student's own value of a quantity, its derivation and the arithmetic tolerance."""
    c = ctx.c
    rel = 0.005 * abs(gv.value)
    unit = si_unit(q.dimension)
    if gv.length_mm is not None:
        m = gv.mu or mu
        if m:
            own = gv.length_mm * m
            return own, T("own.length", len=gv.length_mm, mu=m, own=own, unit=unit), max(
                rel, gv.half_unit, gv.length_half_unit * m)
    if seg is not None:
        key = segment_key(seg)
        d = first.get(key)
        if d is not None and d.mu and seg.start in d.dp.points and seg.end in d.dp.points:
            length = math.dist(d.dp.points[seg.start].at, d.dp.points[seg.end].at)
            own = length * d.mu
            return own, T("own.drawn", seg=seg.name, len=length, mu=d.mu, own=own,
                          unit=unit), max(
                rel, gv.half_unit, 0.5 * d.mu)
        ts = table_len.get(id(seg))
        m = (ts.mu if ts else None) or mu
        if ts is not None and m:
            own = ts.length_mm * m
            return own, T("own.table", seg=seg.name, len=ts.length_mm, mu=m, own=own,
                          unit=unit), max(
                rel, gv.half_unit, ts.length_half_unit * m)
    rate_of = c[q.step].op.rate_of if q.step is not None else None
    if q.step is not None and rate_of is not None:     # ω, ε of a link
        st = c[q.step]
        plan_points = [first.get(plan_key(st.plan))]
        if plan_points[0] is not None and plan_points[0].si:
            own = float(np.asarray(red.own(q.step)).reshape(-1)[0])
            return abs(own), T("own.plan", label=st.label, own=abs(own), unit=unit), max(
                0.01 * abs(gv.value), gv.half_unit)
        # from a table: the relative segment's length × μ / l
        a, b = (st.input(name) for name in rate_of)
        relseg = next((s for s in c.segments if {s.start, s.end} == {a, b}), None)
        ts = table_len.get(id(relseg)) if relseg is not None else None
        m = (ts.mu if ts else None) or mu
        l = _link_length(ctx, q.step, k)
        if ts is not None and m and l:
            own = ts.length_mm * m / l
            return own, T("own.omega", seg=relseg.name,  # type: ignore[union-attr]
                          len=ts.length_mm, mu=m, l=l, own=own, unit=unit), max(
                0.01 * abs(gv.value), gv.half_unit)
        written_rel = _written(ctx, lambda w: relseg is not None and w.quantity.segment is relseg)
        if written_rel is not None and l:
            own = abs(written_rel.value) / l
            return own, T("own.ratio", a=written_rel.written, text=written_rel.text, l=l, own=own,
                          unit=unit), \
                max(0.005 * abs(gv.value), gv.half_unit, written_rel.half_unit / l)
    link = _inertia_link(q)
    spec = ctx.scene.masses.get(link) if link else None
    if spec is not None and spec.mass > 0:
        acc = f"a_{spec.centre}"
        a_gv = _written(ctx, lambda w: w.quantity.name == acc)
        if a_gv is not None:
            own = spec.mass * abs(a_gv.value)
            return own, T("own.product", m=spec.mass, a=a_gv.written, text=a_gv.text, own=own,
                          unit=unit), max(0.005 * abs(gv.value), gv.half_unit,
                                          spec.mass * a_gv.half_unit)
    return None, "", 0.0


def _written(ctx: Ctx, which: Any) -> GivenValue | None:
    """The first value the student wrote for a quantity (``which(value) → bool``)."""
    return next((w for w in ctx.interp.values if which(w)), None)


def _inertia_link(q: Any) -> str | None:
    """The link of an inertia force Q_k (a result "Q_2" or a force-plan segment "Q2")."""
    m = re.fullmatch(r"Q_?(\w+)", q.name)
    return m.group(1) if m else None
