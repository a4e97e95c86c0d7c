"""Grade tables of lengths and named values (v_S2, ω2, Q2, M_b …) against the exact ones and
against the student's own numbers (new, carried, slip)."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

import numpy as np

from ..construct.graph import Construction
from ..construct.ops import Grade
from ..construct.segments import Segment
from ..construct.step import Kind
from ..errors import MechplanError
from ..model.plans import Plan
from ..submission.labels import PlanKey, plan_key
from ..submission.read import Note
from ..units import si_unit
from .context import (
    Ctx,
    Drawn,
    Rederive,
    exact_length,
    given_mu,
    roots_of,
    segment_finding,
)
from .hints import depends_on, text_of
from .labels import segment_key
from .match import GivenValue, Quantity, TableSegment
from .report import (
    CARRIED,
    NEW,
    OK,
    REFERENCE,
    SLIP,
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
def grade_table_segments(ctx: Ctx, k: int, report: CheckReport) -> list[PlanReport]:
    """A plan report per plan of a table of lengths, rows in construction order."""
    by_key: dict[PlanKey, list[TableSegment]] = {}
    if ctx.sheet is None:   # lengths written on a drawn sheet are checked against the drawing
        for ts in ctx.interp.segments:
            by_key.setdefault(ts.key, []).append(ts)
    order = {id(s): i for i, s in enumerate(ctx.c.segments)}
    return [_grade_table(ctx, k, key, sorted(items, key=lambda t: order.get(id(t.segment), 0)),
                         report) for key, items in by_key.items()]


def _grade_table(ctx: Ctx, k: int, key: PlanKey, items: list[TableSegment],
                 report: CheckReport) -> PlanReport:
    """The lengths of one plan at the student's μ (given, written on a row, or fixed by the first
    row taken at its exact length); a wrong one is new, or carried from an earlier wrong row."""
    c, plan = ctx.c, key[0]
    tol = ctx.options.tol(plan)
    mu, source = given_mu(ctx, plan) or (None, "")
    with_mu = next((t for t in items if t.mu), None)
    reference = None
    if mu is None and with_mu is not None:
        mu, source = with_mu.mu, T("mu.row", written=with_mu.written, where=with_mu.where)
    elif mu is None:
        reference = items[0]
        if reference.length_mm > 0:
            seg = reference.segment
            mu = exact_length(ctx, seg.start, seg.end, k) / reference.length_mm
            source = T("mu.inferred_table", written=reference.written, q=seg.quantity,
                       plan=plan_title(plan.value, case="gen"))
    pr = PlanReport(plan_title(plan.value, key[1], table=True), plan.value, key[1], mu, source,
                    tol)
    present = {t.segment.end for t in items} | {t.segment.start for t in items}
    wrong_ends: dict[str, str] = {}
    for ts in items:
        seg = ts.segment
        row_mu = ts.mu or mu
        exact_value = exact_length(ctx, seg.start, seg.end, k)
        exact_mm = exact_value / row_mu if row_mu else None
        row = SegmentRow(seg.name, seg.quantity, seg.kind.value, seg.end, ts.length_mm,
                         exact_mm, exact_value=exact_value, where=ts.where, start=seg.start,
                         end=seg.end)
        row.submitted_value = ts.length_mm * row_mu if row_mu else None
        row.depends_on = depends_on(c, seg.end, present)
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
        if row.verdict == WRONG:
            built_from = set(c.ancestors([seg.end])) - {seg.end}
            earlier = [name for sid, name in wrong_ends.items() if sid in built_from]
            if earlier:
                row.cause = CARRIED
                row.carried_from = earlier
                row.hint = T("hint.may_carried_segment", earlier=join(earlier))
            else:
                row.cause = NEW
                end = c[seg.end]
                row.hint = text_of(end.op.hint(end, c))     # the hint of its operation
                report.findings.append(segment_finding(pr.name, row))
            wrong_ends[seg.end] = seg.name
        pr.segments.append(row)
    return pr


# -- named values -------------------------------------------------------------------------------
def grade_values(ctx: Ctx, k: int, first: dict[PlanKey, Drawn], red: Rederive,
                 mu_all: dict[Plan, float], report: CheckReport) -> None:
    """Grade each written value against the exact one and the student's own numbers."""
    c = ctx.c
    status = {sid: cause for d in first.values() for sid, cause in d.status.items()}
    table_len: dict[int, TableSegment] = {id(t.segment): t for t in ctx.interp.segments}
    written = _FirstWritten(ctx.interp.values)
    for gv in ctx.interp.values:
        q = gv.quantity
        row = ValueRow(gv.written, q.display, si_unit(q.dimension), gv.value, None,
                       where=gv.where)
        report.values.append(row)
        exact = _value_exact(ctx, q, k, report.notes, gv.where)
        if exact is None:
            row.verdict = UNCHECKED
            continue
        signed = q.step is not None and c[q.step].kind is Kind.SCALAR and gv.value < 0
        exact_cmp = exact if signed else abs(exact)
        sub_cmp = gv.value if signed else abs(gv.value)
        row.exact = exact_cmp
        plan = q.plan
        plan_name = plan_word(plan.value) if plan else ""
        tol = ctx.options.tol(plan)
        mu = mu_all.get(plan) if plan else None
        seg = q.segment or _absolute_segment(c, q.step)
        rate_length = _rate_length(ctx, q.step, k)
        tol_abs = tol.pct / 100 * abs(exact_cmp)
        # a value is right within the paper tolerance of its segment (ω, ε: of their relative
        # segment over the link's length), at the student's μ or (when they gave none) at the
        # scene's: a short segment is not held to ±2 %
        paper = mu or (ctx.scales.get(plan) if plan else None)
        if seg is not None and paper:
            tol_abs = max(tol_abs, tol.mm * paper)
        elif rate_length and paper:
            tol_abs = max(tol_abs, tol.mm * paper / rate_length)
        row.tolerance = max(tol_abs, gv.half_unit)      # "0.00" is right for anything below 0.005
        row.error_pct = 100 * (sub_cmp - exact_cmp) / exact_cmp if exact_cmp else None
        # what the student's own drawing or lengths give
        own, own_text, arith = _own_value(ctx, gv, seg, rate_length, red, first, table_len, mu,
                                          written)
        row.own = own
        if own is not None and abs(sub_cmp - (own if signed else abs(own))) > arith:
            row.verdict = SLIP
            row.cause = NEW
            row.hint = T("hint.slip", own=own_text, written=gv.written, text=gv.text)
            report.findings.append(Finding("arithmetic slip", plan_name, gv.written, row.hint,
                                           q.step or ""))
        elif abs(sub_cmp - exact_cmp) <= row.tolerance:
            row.verdict = OK
        else:
            row.verdict = WRONG
            if seg is not None:     # its segment's end first, when that point is wrong itself
                roots = roots_of(ctx, status, seg.end, also=seg.end)
            else:
                roots = roots_of(ctx, status, q.step) if q.step is not None else []
            root_labels = join(dict.fromkeys(c[s].label for s in roots))
            if own is not None:
                row.cause = CARRIED
                row.hint = (T("hint.own_carried", own=own_text, roots=root_labels)
                            if roots else T("hint.own", own=own_text))
            elif roots:
                row.cause = CARRIED
                row.hint = T("hint.may_carried", roots=root_labels)
            else:
                row.cause = NEW
                row.hint = _value_hint(ctx, q)
                report.findings.append(Finding("wrong value", plan_name, gv.written, T(
                    "finding.wrong_value", written=gv.written, text=gv.text, exact=exact_cmp,
                    unit=row.unit, pct=row.error_pct, hint=row.hint)
                    if row.error_pct is not None else row.hint, q.step or ""))


def _value_hint(ctx: Ctx, q: Quantity) -> str:
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


def _rate_length(ctx: Ctx, sid: str | None, k: int) -> float | None:
    """The length of the link a rate (ω, ε) is read over (None: the step is no rate)."""
    if sid is None:
        return None
    st = ctx.c[sid]
    lever = st.op.lever_of(st)              # ω, ε: the link's two points
    if st.op.rate_of is None or lever is None:
        return None
    return exact_length(ctx, *lever, k)


def _value_exact(ctx: Ctx, q: Quantity, k: int, notes: list[Note], where: str) -> float | None:
    if q.step is not None:
        v = ctx.ev[q.step][k]
        return float(np.hypot(*v)) if v.ndim == 1 and v.shape[0] == 2 else float(v)
    if q.segment is not None:
        return exact_length(ctx, q.segment.start, q.segment.end, k)
    if q.extra in ("J_red", "M_red"):
        try:
            from ..dynamics import Loading
            from ..dynamics.reduced import reduced_of

            if not ctx.reduced:
                loading = Loading.from_scene(ctx.scene)
                m_red, j_red = reduced_of(ctx.c, ctx.ev, ctx.scene.mechanism, loading)
                ctx.reduced.update(M_red=m_red, J_red=j_red)
            return float(ctx.reduced[q.extra][k])
        except MechplanError as exc:
            notes.append(Note("warning", T("note.not_computable", extra=q.extra,
                                           error=exc.detail), where))
            return None
    return None


def _own_value(ctx: Ctx, gv: GivenValue, seg: Segment | None, rate_length: float | None,
               red: Rederive, first: dict[PlanKey, Drawn], table_len: dict[int, TableSegment],
               mu: float | None, written: _FirstWritten) -> tuple[float | None, str, float]:
    """The student's own value of a quantity, its derivation and the arithmetic tolerance."""
    c, q = ctx.c, gv.quantity
    unit = si_unit(q.dimension)

    def slack(rel: float, reading: float = 0.0) -> float:
        """What the arithmetic may be off by: ``rel`` of the value, half its last written digit,
        or what the reading it comes from is written to."""
        return max(rel * abs(gv.value), gv.half_unit, reading)

    if gv.length_mm is not None and (m := gv.mu or mu):
        own = gv.length_mm * m
        return own, T("own.length", len=gv.length_mm, mu=m, own=own, unit=unit), slack(
            0.005, gv.length_half_unit * m)
    if seg is not None:
        d = first.get(segment_key(seg))
        if d is not None and d.mu and seg.start in d.dp.points and seg.end in d.dp.points:
            length = math.dist(d.dp.points[seg.start].at, d.dp.points[seg.end].at)
            own = length * d.mu
            return own, T("own.drawn", seg=seg.name, len=length, mu=d.mu, own=own,
                          unit=unit), slack(0.005, 0.5 * d.mu)
        measured = _table_length(table_len, seg, mu)
        if measured is not None:
            ts, m = measured
            own = ts.length_mm * m
            return own, T("own.table", seg=seg.name, len=ts.length_mm, mu=m, own=own,
                          unit=unit), slack(0.005, ts.length_half_unit * m)
    rate_of = c[q.step].op.rate_of if q.step is not None else None
    if q.step is not None and rate_of is not None:     # ω, ε of a link
        st = c[q.step]
        d = first.get(plan_key(st.plan))
        if d is not None and d.si:
            own = abs(float(red.own(q.step)[0]))
            return own, T("own.plan", label=st.label, own=own, unit=unit), slack(0.01)
        # from a table: the relative segment's length × μ / l
        a, b = (st.input(name) for name in rate_of)
        relseg = next((s for s in c.segments if {s.start, s.end} == {a, b}), None)
        measured = _table_length(table_len, relseg, mu)
        if measured is not None and rate_length:
            ts, m = measured
            own = ts.length_mm * m / rate_length
            return own, T("own.omega", seg=ts.segment.name, len=ts.length_mm, mu=m,
                          l=rate_length, own=own, unit=unit), slack(0.01)
        written_rel = written.of_segment(relseg)
        if written_rel is not None and rate_length:
            own = abs(written_rel.value) / rate_length
            return own, T("own.ratio", a=written_rel.written, text=written_rel.text,
                          l=rate_length, own=own, unit=unit), slack(
                0.005, written_rel.half_unit / rate_length)
    link = _inertia_link(q)
    spec = ctx.scene.masses.get(link) if link else None
    if spec is not None and spec.mass > 0:
        acc = f"a_{spec.centre}"
        a_gv = written.named(acc)
        if a_gv is not None:
            own = spec.mass * abs(a_gv.value)
            return own, T("own.product", m=spec.mass, a=a_gv.written, text=a_gv.text, own=own,
                          unit=unit), slack(0.005, spec.mass * a_gv.half_unit)
    return None, "", 0.0


def _table_length(table_len: dict[int, TableSegment], seg: Segment | None,
                  mu: float | None) -> tuple[TableSegment, float] | None:
    """A segment's length written in a table and the μ it is multiplied by (its row's, else the
    plan's); None when there is no such row or no μ."""
    ts = table_len.get(id(seg)) if seg is not None else None
    if ts is None:
        return None
    m = ts.mu or mu
    return (ts, m) if m else None


class _FirstWritten:
    """The first value the student wrote for each quantity name and each segment, looked up in
    one step (a table of 10^4 values is not searched once per value)."""

    def __init__(self, values: Sequence[GivenValue]) -> None:
        self._by_name: dict[str, GivenValue] = {}
        self._by_segment: dict[int, GivenValue] = {}
        for w in values:
            self._by_name.setdefault(w.quantity.name, w)
            if w.quantity.segment is not None:
                self._by_segment.setdefault(id(w.quantity.segment), w)

    def named(self, name: str) -> GivenValue | None:
        """The first value written for the quantity ``name``."""
        return self._by_name.get(name)

    def of_segment(self, seg: Segment | None) -> GivenValue | None:
        """The first value written for the quantity of segment ``seg``."""
        return None if seg is None else self._by_segment.get(id(seg))


def _inertia_link(q: Quantity) -> str | None:
    """The link of an inertia force Q_k (a result "Q_2" or a force-plan segment "Q2")."""
    m = re.fullmatch(r"Q_?(\w+)", q.name)
    return m.group(1) if m else None
