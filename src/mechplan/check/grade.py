"""Grade a submission against the exact construction.

Every labelled point is compared with its exact image twice: with the exact point (its total error)
and with the point the student's *own* earlier points give when the step is re-evaluated from them
(its new error). A wrong point whose new error is within tolerance is carried from earlier wrong
items; otherwise the error is new at that step, and the hint says which part of the step's rule is
broken. Two wrong points that would both be right with their labels exchanged are swapped labels.
A written value that differs from the student's own segment × μ is an arithmetic slip.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from ..construct.ops import Grade
from ..construct.ops.spec import point_of
from ..errors import CheckError, MechplanError
from ..geom.sketch import nearest
from ..model.plans import Plan
from ..scene.spec import Scene
from ..submission.centre_marks import centre_entries, find_centre_marks, table_rows
from ..submission.drawn_plans import DrawnPlan, DrawnSheet, find_plans
from ..submission.labels import PlanKey, asks_for_forces
from ..submission.read import Note, Submission, read_submission
from ..submission.written import is_angle_name, parse_angle
from .centres import grade_centres
from .context import (
    Ctx,
    Drawn,
    Options,
    Rederive,
    roots_of,
    row_brief,
    row_error,
    segment_finding,
    segments_of,
)
from .drawn import classify_points, find_swaps, overrides_of, prepare
from .hints import HintContext, depends_on, rule
from .labels import label_book
from .match import QuantityIndex, SegmentIndex, interpret
from .positions import fit_score, grade_per_plan, several_positions, values_at_titled_positions
from .report import (
    ACCUMULATED,
    CARRIED,
    MISSING,
    NEW,
    OK,
    REFERENCE,
    SWAPPED,
    UNCHECKED,
    WRONG,
    CheckReport,
    Finding,
    PlanReport,
    PointRow,
    SegmentRow,
)
from .texts import T, join, plan_title
from .values import grade_table_segments, grade_values


# -- public entry point -------------------------------------------------------------------------
def check(scene: Scene | str | Path, submission: str | Path | Submission,
          options: Options | None = None) -> CheckReport:
    """Check a submission (DXF or table) against the exact construction of a scene."""
    from ..scene import load_scene
    from .answers import maybe_check_answers

    options = options or Options()
    answers = maybe_check_answers(scene, submission, options)   # a dynamics/engine/cam/gear study
    if answers is not None:
        return answers
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    sub = submission if isinstance(submission, Submission) else read_submission(submission)
    notes: list[Note] = list(sub.notes)
    candidates, phi_source = _angles(scene, sub, options, notes)
    sol = _solve(scene, sub, candidates, notes)
    c, ev = sol.construction, sol.ev
    book = label_book(c, scene.mechanism)
    qi = QuantityIndex(c, scene.mechanism, with_dynamics=True)
    si = SegmentIndex(c, book)
    sheet: DrawnSheet | None = None
    links = ("0", *scene.mechanism.moving)
    marks = find_centre_marks(sub, links, options.label_distance, options.snap) \
        if sub.kind == "dxf" else []
    drawn_table = table_rows(sub, links) if sub.kind == "dxf" else []   # a table of centres
    if sub.kind == "dxf":
        try:
            sheet = find_plans(sub, book, options.label_distance, options.snap,
                               mu_elsewhere=options.mu)
        except CheckError:
            if not drawn_table and not any(m.at is not None for m in marks):
                raise
            sheet = DrawnSheet([], [], options.label_distance or 5.0, [])   # centres alone
        notes.extend(sheet.notes)
        centre_rows, other = centre_entries(sheet.other_entries, links)
        centre_rows += drawn_table
        interp = interpret(other, qi, si, from_sheet=True)
    else:
        centre_rows, other = centre_entries(sub.entries, links)
        interp = interpret(other, qi, si, from_sheet=False)
    notes.extend(interp.notes)
    if sheet is not None and not sheet.plans and not interp.values and not marks and \
            not centre_rows:
        why = "; ".join(str(n) for n in notes if n.level != "info")[:600]
        raise CheckError(T("error.no_plan", why=why or T("error.no_labelled_points")),
                         file=sub.path)
    if sub.kind == "table" and not interp.segments and not interp.values and not centre_rows:
        problems = "; ".join(str(n) for n in interp.notes if n.level == "error")
        raise CheckError(T("error.nothing_to_check", problems=f": {problems}" if problems else ""),
                         file=sub.path)
    ctx = Ctx(scene, sub, c, ev, book, sheet, interp, options, sol.scales)
    reports = [_grade(ctx, k) for k in range(len(candidates))]
    best = min(range(len(reports)), key=lambda i: fit_score(reports[i].rows))
    report = reports[best]
    report.phi_source = phi_source
    if len(reports) > 1:
        report.phi_source = T("phi.best_of", n=len(candidates))
        if several_positions(ctx):
            report = grade_per_plan(ctx, reports, best, _grade)
        values_at_titled_positions(ctx, reports, report)
    grade_centres(ctx, best, report, marks, centre_rows)
    report.notes = list(dict.fromkeys(notes + report.notes))   # each note once
    if sheet is not None:
        report.label_distance_mm = sheet.label_distance
    report.units = sub.units
    if scene.mechanism.drive.linear:
        report.coordinate = c["pos.q"].label
    return report


def _angles(scene: Scene, sub: Submission, options: Options,
            notes: list[Note]) -> tuple[list[float], str]:
    if options.at_deg is not None:
        return [float(options.at_deg)], T("phi.at")
    for e in sub.entries:
        if is_angle_name(e.name):
            text = e.text or e.value or e.length or ""
            try:
                value = parse_angle(text)
            except MechplanError as exc:
                notes.append(Note("warning", T("note.crank_angle", name=e.name, text=text,
                                                detail=exc.detail), e.where))
                continue
            return [value], T("read_from", name=e.name, text=text, where=e.where)
    from ..solve import build, crank_positions, shown_coordinate

    if len(scene.positions.angles) == 1:
        return [shown_coordinate(scene, scene.positions.angles[0])], T("phi.only")
    _, c = build(scene, ("position", "velocity"))
    phi = crank_positions(scene, c)
    return [float(shown_coordinate(scene, p)) for p in phi], T("phi.best")


def _solve(scene: Scene, sub: Submission, at_deg: list[float], notes: list[Note]) -> Any:
    from ..solve import solve

    plans = tuple(dict.fromkeys(("position", "velocity", "acceleration", *scene.plans)))
    if "force" in plans or asks_for_forces(sub):
        from ..dynamics import Loading

        loading = Loading.from_scene(scene)
        if not loading.is_empty:
            return solve(scene, at_deg=at_deg, plans=tuple(dict.fromkeys((*plans, "force"))),
                         loading=loading)
        notes.append(Note("info", T("note.no_loads"), scene.path or ""))
    plans = tuple(p for p in plans if p != "force")
    return solve(scene, at_deg=at_deg, plans=plans)


def _grade(ctx: Ctx, k: int) -> CheckReport:
    """Grade the submission at candidate position k."""
    from ..solve import shown_coordinate

    phi = shown_coordinate(ctx.scene, float(ctx.ev.phi[k]))   # a linear driver's: mm
    report = CheckReport(str(ctx.scene.path or ""), ctx.sub.path, ctx.sub.kind, round(phi, 10),
                         "")
    drawn = [prepare(ctx, dp, k, report.notes) for dp in (ctx.sheet.plans if ctx.sheet else [])]
    first: dict[PlanKey, Drawn] = {}
    for d in drawn:
        first.setdefault(d.dp.key, d)
    # swapped labels first: the geometry is right, so later steps use the corrected points
    for d in drawn:
        find_swaps(ctx, d, k)
    overrides = overrides_of(list(first.values()))
    # μ of each plan: given on the command line, else of its first drawing, else written
    mu_all = {plan: mu for plan, (mu, _) in ctx.interp.scales.items()}
    mu_all.update({d.dp.plan: d.mu for d in first.values() if d.mu})
    mu_all.update(ctx.options.mu)
    reds = [Rederive(ctx.c, ctx.ev, k, {**overrides, **overrides_of([d])}) for d in drawn]
    for d, red in zip(drawn, reds):
        classify_points(d, red)
    # the first drawing of a plan wins
    status = {sid: cause for d in reversed(drawn) for sid, cause in d.status.items()}
    for d in drawn:
        for sid, cause in list(d.status.items()):
            if cause == CARRIED and not roots_of(ctx, status, sid):
                d.status[sid] = ACCUMULATED
                status[sid] = ACCUMULATED if status.get(sid) == CARRIED else status[sid]
    for d, red in zip(drawn, reds):
        report.plans.append(_grade_drawn(ctx, d, k, red, mu_all, report.findings, status))
    report.plans.extend(grade_table_segments(ctx, k, report))
    grade_values(ctx, k, first, Rederive(ctx.c, ctx.ev, k, overrides), mu_all, report)
    return report


def _grade_drawn(ctx: Ctx, d: Drawn, k: int, red: Rederive, mu_all: dict[Plan, float],
                 findings: list[Finding], status: dict[str, str]) -> PlanReport:
    """Grade one drawn plan: its points, segments and drawn lines, and a finding per root cause."""
    c, dp = ctx.c, d.dp
    pr = PlanReport(dp.name, dp.plan.value, dp.key[1], d.mu, d.mu_source,
                    ctx.options.tol(dp.plan), anchor=c[d.anchor].label if d.anchor else "",
                    convention=dp.convention)
    mu_map = {p: m for p, m in mu_all.items() if m}
    if d.mu:
        mu_map[dp.plan] = d.mu
    hctx = HintContext(c, ctx.scene.mechanism, red.own, red.exact, mu_map)
    for sid, p in dp.points.items():
        err = d.errors.get(sid)
        verdict = UNCHECKED if err is None else (OK if err <= d.tol[sid] else WRONG)
        pr.points.append(PointRow(p.label, p.written, sid, p.at, err, d.tol.get(sid), verdict,
                                  d.status.get(sid, ""), d.own_err.get(sid), p.how, p.distance,
                                  p.where))
    # segments of the construction, then drawn lines between labelled points
    segs = segments_of(c, dp.key)
    rows = [_segment_row(ctx, d, k, hctx, status, s.start, s.end, s.name, s.quantity,
                         s.kind.value, s is d.reference) for s in segs]
    seen = {(s.start, s.end) for s in segs} | {(s.end, s.start) for s in segs}
    for line in dp.lines:
        a = _point_at(dp, line.start, ctx.options.snap)
        b = _point_at(dp, line.end, ctx.options.snap)
        if a is None or b is None or a == b or (a, b) in seen:
            continue
        seen |= {(a, b), (b, a)}
        row = _segment_row(ctx, d, k, hctx, status, a, b, c[a].label + c[b].label, "", "drawn")
        row.in_construction = False
        row.drawn = True
        rows.append(row)
    for row in rows:
        if row.drawn is None and row.submitted_mm is not None:
            row.drawn = _is_drawn(dp, row.start, row.end, ctx.options.snap)
    pr.segments = rows
    pr.drawn_lines = [(ln.start, ln.end) for ln in dp.lines]
    if d.mu and d.anchor is not None:
        a_at = np.asarray(dp.points[d.anchor].at)
        base = ctx.ev[d.anchor][k]
        place = {}
        for sid in ctx.book.plans.get(dp.key, {}):
            v = a_at + (ctx.ev[sid][k] - base) / d.mu
            if np.all(np.isfinite(v)):
                place[sid] = (float(v[0]), float(v[1]))
                pr.exact_mm[c[sid].label] = place[sid]
        for s in segs:
            if s.start in place and s.end in place:
                pr.exact_segments.append((s.name, place[s.start], place[s.end]))
    # findings: one per root cause
    for sid, cause in d.status.items():
        if cause == NEW:
            mine = [r for r in rows if r.verdict == WRONG and r.step == sid and r.cause == NEW]
            ends = [r for r in mine if r.end == sid]
            primary = [r for r in ends if c[r.start].op.grade is Grade.ORIGIN] or ends or mine
            error = row_error(primary[0]) if primary else ""
            segtxt = join((row_brief(r) for r in mine), "; ")
            findings.append(Finding(
                "wrong point", pr.name, c[sid].label,
                T("finding.wrong_point", label=c[sid].label, err=d.errors[sid],
                  own=d.own_err[sid], segments=T("paren", x=segtxt) if mine else "",
                  rule=rule(hctx, c[sid], d.si[sid], d.tol[sid])), sid, error))
    done: set[str] = set()
    for a, b in d.swapped.items():
        if a in done:
            continue
        done |= {a, b}
        findings.append(Finding("swapped labels", pr.name, f"{c[a].label}/{c[b].label}",
                                T("finding.swapped", a=c[a].label, b=c[b].label), a))
    for r in rows:
        if r.verdict == WRONG and r.cause == NEW and r.step not in d.status and \
                not any(f.step == r.step for f in findings):
            findings.append(segment_finding(pr.name, r))
    return pr


def _where_label(ctx: Ctx, sid: str, d: Drawn) -> str:
    """A step's label, with its plan when it is on another plan than ``d``."""
    st = ctx.c[sid]
    return st.label if st.plan is d.dp.plan else T("where_label", label=st.label,
                                                    plan=plan_title(st.plan.value))


def _point_at(dp: DrawnPlan, at: tuple[float, float], snap: float) -> str | None:
    """The labelled point of a drawn plan at a line's end (None: no point there)."""
    sids = list(dp.points)[::-1]           # the last of equally near points, as they were read
    i = nearest(np.array([dp.points[s].at for s in sids]), at, snap + 1e-9)
    return sids[i] if i >= 0 else None


def _is_drawn(dp: DrawnPlan, start: str, end: str, snap: float) -> bool:
    """Whether a drawn line joins two labelled points of a plan."""
    a, b = dp.points[start].at, dp.points[end].at
    return any(math.dist(p, a) <= snap and math.dist(q, b) <= snap
               for ln in dp.lines for p, q in ((ln.start, ln.end), (ln.end, ln.start)))


def _segment_row(ctx: Ctx, d: Drawn, k: int, hctx: HintContext, status: dict[str, str],
                 start: str, end: str, name: str, quantity: str, kind: str,
                 is_reference: bool = False) -> SegmentRow:
    """A segment between two points of a drawn plan: its length and direction against the exact
    ones, its verdict, and when wrong why."""
    c, dp = ctx.c, d.dp
    tol = ctx.options.tol(dp.plan)
    exact_vec = ctx.ev[end][k] - ctx.ev[start][k]
    exact_value = float(np.hypot(*exact_vec))
    exact_mm = exact_value / d.mu if d.mu else None
    row = SegmentRow(name, quantity, kind, end, None, exact_mm, exact_value=exact_value,
                     start=start, end=end)
    row.depends_on = depends_on(c, end, d.si)
    if start not in dp.points or end not in dp.points:
        row.verdict = MISSING
        missing = [c[s].label for s in (start, end) if s not in dp.points]
        row.hint = T("hint.missing", labels=join(missing))
        return row
    a, b = np.asarray(dp.points[start].at), np.asarray(dp.points[end].at)
    vec = b - a
    row.submitted_mm = float(np.hypot(*vec))
    row.where = T("pair", a=dp.points[start].where, b=dp.points[end].where)
    if d.mu:
        row.submitted_value = row.submitted_mm * d.mu
    ref_len = exact_mm if exact_mm is not None else row.submitted_mm
    row.tolerance_mm = tol.allowed_mm(ref_len)
    row.tolerance_deg = tol.allowed_deg(ref_len)
    if exact_value > 0 and row.submitted_mm > 1e-9:
        row.direction_deg = math.degrees(math.remainder(
            math.atan2(vec[1], vec[0]) - math.atan2(exact_vec[1], exact_vec[0]), 2 * math.pi))
    if exact_mm is not None:
        row.error_mm = row.submitted_mm - exact_mm
        row.error_pct = 100.0 * row.error_mm / exact_mm if exact_mm > 0 else None
    # the reference segment fixes μ: only its direction is graded
    len_ok = is_reference or row.error_mm is None or abs(row.error_mm) <= row.tolerance_mm
    dir_ok = row.direction_deg is None or abs(row.direction_deg) <= row.tolerance_deg
    if not (len_ok and dir_ok):
        row.verdict = WRONG
    elif exact_mm is None:
        row.verdict = UNCHECKED
    else:
        row.verdict = REFERENCE if is_reference else OK
    if is_reference:
        row.hint = T("hint.reference")
    if row.verdict != WRONG:
        return row
    # why: swapped labels, a new error at one end, carried from earlier items, or small ones
    # adding up
    if start in d.swapped or end in d.swapped:
        row.cause = SWAPPED
        x = end if end in d.swapped else start
        row.hint = T("hint.swapped", a=c[x].label, b=c[d.swapped[x]].label)
        row.step = x
        return row
    if status.get(end) == NEW or (status.get(start) == NEW and end not in status):
        x = end if status.get(end) == NEW else start
        row.cause = NEW
        row.step = x
        row.hint = rule(hctx, c[x], d.si[x], d.tol[x])
        return row
    # does the student's own construction from their earlier points give this segment?
    own_vec = (point_of(hctx.own(end)) - d.si[start]) / d.mu if d.mu else vec
    explained = bool(np.all(np.isfinite(own_vec))) and \
        float(np.hypot(*(vec - own_vec))) <= row.tolerance_mm
    roots = roots_of(ctx, status, end, also=start)
    if explained and roots:
        row.cause = CARRIED
        row.carried_from = [_where_label(ctx, r, d) for r in roots]
        row.hint = T("hint.carried", roots=join(row.carried_from))
    elif explained or status.get(end) in (CARRIED, ACCUMULATED):
        row.cause = ACCUMULATED
        errs = join(T("hint.point_err", label=c[x].label, err=d.errors.get(x, 0.0))
                    for x in (start, end))
        row.hint = T("hint.accumulated", errs=errs)
    else:
        row.cause = NEW
        row.hint = rule(hctx, c[end], d.si[end], d.tol[end])
    return row
