"""Grade a student's instant centres: the centres labelled on a drawing (their places on paper)
and the rows of a table (``I13 = (x, y) mm``, ``I13x``, ``I13y``, the distance ``I13A``).

The exact centres come from Kennedy's construction (:mod:`mechplan.construct.plans.centres`) at
the sheet's position. A drawing's paper frame is that of a position plan graded on the sheet
(its μl and the place of its points) or, for a drawing of its own (an instant-centre panel at
its own scale), the uniform scale and shift that put the labelled pins — the primary centres of
the revolute pairs — best on their exact places; the frame whose pins fit best is used. A wrong
centre's hint names the two lines of its Kennedy construction and how far it is off each (lines
drawn through the student's own centres, so a centre right from wrong neighbours is carried).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from ..construct.centre_kinematics import acceleration_pole
from ..construct.plans.centres import Centre, Centres, centres_at, label, ordered
from ..model.mechanism import GROUND, PairKind
from ..model.plans import Plan
from ..submission.centre_marks import COUPLER, POLE, CentreMark, CentreName
from ..submission.read import Entry, Note
from .centre_table import ARROW_DEG, exact_centre, find_centre, grade_table, rule_of
from .context import Ctx
from .report import (
    CARRIED,
    MISSING,
    NEW,
    OK,
    SWAPPED,
    WRONG,
    CentreRow,
    CheckReport,
    Finding,
    Tolerance,
)
from .texts import T, join


@dataclass
class _Frame:
    """paper = shift + world / mu."""

    mu: float
    shift: np.ndarray
    source: object

    def paper(self, r: np.ndarray) -> np.ndarray:
        return self.shift + np.asarray(r) / self.mu


def grade_centres(ctx: Ctx, k: int, report: CheckReport,
                  marks: Sequence[CentreMark], entries: Sequence[tuple[CentreName, Entry]]
                  ) -> None:
    """Grade the drawn and written centres at position k into ``report.centres``."""
    if not marks and not entries:
        return
    cs = centres_at(ctx.c, ctx.ev, ctx.scene.mechanism)
    marks, entries = _coupler_named(cs, marks, entries, report)
    drawn = [m for m in marks if m.at is not None or m.infinite]   # "I23 ∞" needs no arrow
    ks = [k] if ctx.ev.n == 1 or ctx.options.at_deg is not None else list(range(ctx.ev.n))
    if drawn:
        # a drawing of the centres is graded at the position it fits best (a sheet may hold
        # plans of several positions; the panel of centres is drawn at one)
        tries = []
        for kk in ks:
            trial = CheckReport(report.scene, report.submission, report.kind, report.phi_deg, "",
                                plans=report.plans)
            _grade_drawn(ctx, cs, kk, trial, drawn)
            tries.append((_score(trial), kk, trial))
        _, kk, best = min(tries, key=lambda t: t[:2])
        report.centres, report.centres_mu = best.centres, best.centres_mu
        report.centres_frame = best.centres_frame
        report.findings += best.findings
        report.notes += best.notes
        if kk != k:
            from ..solve import shown_coordinate

            report.centres_phi = round(shown_coordinate(ctx.scene, float(ctx.ev.phi[kk])), 10)
        ks = [kk]                       # a table beside the drawing is of the same position
    if entries:
        # a table of a sheet with plans of several positions: the position it fits best
        trials = []
        for kk in ks:
            trial = CheckReport(report.scene, report.submission, report.kind, report.phi_deg, "")
            grade_table(ctx, cs, kk, trial, entries)
            wrong = sum(v.verdict == WRONG for v in trial.values)
            trials.append((wrong, 0 if kk == k else 1, kk, trial))
        *_, best_table = min(trials, key=lambda t: t[:3])
        report.values += best_table.values
        report.notes += best_table.notes


def _coupler_named(cs: Centres, marks: Sequence[CentreMark],
                   entries: Sequence[tuple[CentreName, Entry]], report: CheckReport
                   ) -> tuple[list[CentreMark], list[tuple[CentreName, Entry]]]:
    """A centre named МЦС (tâm vận tốc tức thời, 绝对瞬心) without its link is the absolute centre
    of the one link whose absolute centre Kennedy's theorem finds (the coupler); where there are
    several such links it is not graded and a note says so."""
    found = [c.j for c in cs.diagram.centres if c.i == GROUND and not c.primary]
    link = found[0] if len(found) == 1 else None

    def named(n: CentreName) -> CentreName | None:
        if n.j != COUPLER:
            return n
        return None if link is None else replace(n, j=link)

    out_m = [replace(m, name=nm) for m in marks if (nm := named(m.name)) is not None]
    out_e = [(nm, e) for n, e in entries if (nm := named(n)) is not None]
    if len(out_m) + len(out_e) < len(marks) + len(entries):
        report.notes.append(_note("centres.coupler_ambiguous",
                                  links=", ".join(found) or "—"))
    return out_m, out_e


def _score(r: CheckReport) -> tuple[int, float]:
    """Fewer wrong and missing centres first, then the smaller sum of errors."""
    if not r.centres:                   # not placed at this position
        return 10 ** 9, math.inf
    bad = sum(c.verdict in (WRONG, MISSING) for c in r.centres)
    return bad, sum(min(c.error, 1e6) for c in r.centres if c.error is not None
                    and math.isfinite(c.error))


# -- drawn centres -------------------------------------------------------------------------------


def _frames(ctx: Ctx, cs: Centres, k: int, report: CheckReport,
            pins: dict[tuple[str, str], list[np.ndarray]]) -> list[_Frame]:
    out: list[_Frame] = []
    from ..solve import shown_coordinate

    phi = shown_coordinate(ctx.scene, float(ctx.ev.phi[k]))
    for pr in report.plans:
        at = pr.phi_deg if pr.phi_deg is not None else report.phi_deg
        if pr.plan != Plan.POSITION.value or not pr.mu or abs(at - phi) > 1e-6:
            continue
        steps = {lbl: sid for key, m in ctx.book.plans.items() if key[0] is Plan.POSITION
                 for sid, lbl in m.items()}
        for lbl, place in pr.exact_mm.items():
            if lbl in steps:
                world_at = np.asarray(ctx.ev[steps[lbl]][k], dtype=float)
                out.append(_Frame(pr.mu, np.asarray(place) - world_at / pr.mu, pr.name))
                break
    world, paper = [], []
    for key, ats in pins.items():
        r, _ = exact_centre(cs, cs.diagram.centre(*key), k)
        if r is not None:
            world.append(r)
            paper.append(ats[0])
    fit = _fit_pins(np.array(world).reshape(-1, 2), np.array(paper).reshape(-1, 2),
                    ctx.options.tol(Plan.POSITION).mm)
    if fit is not None:
        out.append(fit)
    return out


def _fit_pins(world: np.ndarray, paper: np.ndarray, tol: float) -> _Frame | None:
    """The uniform scale and shift that put the pins on their drawn places (least squares); a
    pin drawn or labelled wrong is left out (the worst first) while more than two remain."""
    keep = np.ones(len(world), dtype=bool)
    while True:
        w, p = world[keep], paper[keep]
        if len({(round(x, 3), round(y, 3)) for x, y in p}) < 2:
            return None
        wc, pc = w - w.mean(axis=0), p - p.mean(axis=0)
        ww = float(np.sum(wc * wc))
        s = float(np.sum(wc * pc)) / ww if ww > 0 else 0.0
        if not s > 0:
            return None
        frame = _Frame(1.0 / s, p.mean(axis=0) - s * w.mean(axis=0), "pins")
        res = np.hypot(*(frame.paper(world) - paper).T)
        res[~keep] = -1.0
        if keep.sum() <= 2 or res.max() <= tol:
            return frame
        keep[int(np.argmax(res))] = False


def _grade_drawn(ctx: Ctx, cs: Centres, k: int, report: CheckReport,
                 marks: list[CentreMark]) -> None:
    links = cs.diagram.links
    by_key: dict[tuple[str, str], list[CentreMark]] = {}
    for m in marks:
        if m.name.rest or m.name.i not in links or m.name.j not in links:
            continue
        by_key.setdefault(ordered(links, m.name.i, m.name.j), []).append(m)
    if not by_key:
        return
    pins = {key: [np.asarray(m.at) for m in ms
                  if m.direction is None and not m.infinite and m.at is not None]
            for key, ms in by_key.items()
            if (ctr := find_centre(cs, key)) is not None and ctr.pair is not None
            and ctr.pair.kind is PairKind.REVOLUTE}
    pins = {key: v for key, v in pins.items() if v}
    frames = _frames(ctx, cs, k, report, pins)
    if not frames:
        report.notes.append(_note("centres.no_frame"))
        return
    frame = min(frames, key=lambda f: _fit(cs, k, f, pins))
    tol = ctx.options.tol(Plan.POSITION)
    pivot = np.mean([v[0] for v in pins.values()], axis=0) if pins else frame.shift
    rows: dict[tuple[str, str], CentreRow] = {}
    chosen: dict[tuple[str, str], CentreMark] = {}
    for key, ms in by_key.items():
        ctr = find_centre(cs, key)
        if ctr is None:
            continue
        best = ms[int(np.argmin([_error(cs, ctr, k, frame, m, tol, pivot)[0] for m in ms]))]
        chosen[key] = best
        err, allowed, exact_mm, how = _error(cs, ctr, k, frame, best, tol, pivot)
        row = CentreRow(label(ctr), best.written, exact_mm, best.at, err, allowed,
                        OK if err <= allowed else WRONG, found=how, where=best.where)
        rows[key] = row
    _swaps(cs, k, frame, tol, pivot, chosen, rows)
    for key, row in rows.items():
        if row.verdict == WRONG and row.cause != SWAPPED:
            _why(cs, cs.diagram.centre(*key), k, frame, chosen, rows, row)
    for ctr in cs.diagram.centres:
        key = (ctr.i, ctr.j)
        if key not in rows and any(v is not None for v in exact_centre(cs, ctr, k)):
            rows[key] = CentreRow(label(ctr), "", None, None, None, None, MISSING,
                                  hint=T("centres.missing_hint"))
    order = {(c.i, c.j): c.order for c in cs.diagram.centres}
    report.centres.extend(rows[key] for key in sorted(rows, key=lambda x: order.get(x, 99)))
    drawn_at = np.array([r.at_mm for r in rows.values()
                         if r.at_mm is not None and r.found == "point"], dtype=float).reshape(-1, 2)
    for row in _grade_poles(ctx, k, frame, tol, pivot, marks, drawn_at):
        report.centres.append(row)
        if row.verdict == WRONG:
            report.findings.append(Finding("wrong centre", T("centres.plan"), row.label,
                                           row.hint, error=""))
    report.centres_mu = frame.mu
    report.centres_frame = T("centres.frame_pins") if frame.source == "pins" else \
        T("centres.frame_plan", plan=frame.source)
    for key, row in rows.items():
        if row.verdict == WRONG and row.cause in (NEW, SWAPPED):
            report.findings.append(Finding("wrong centre", T("centres.plan"), row.label,
                                           row.hint, error=""))


def _exact_pole(ctx: Ctx, link: str, k: int) -> np.ndarray | None:
    """The acceleration pole of a link at position k (m), or None (no acceleration plan, or a
    link with ω = ε = 0)."""
    c, ev = ctx.c, ctx.ev
    if not c.has_result("epsilon", link) or link not in ctx.scene.mechanism.links:
        return None
    p = next(iter(ctx.scene.mechanism.links[link].points))
    q = acceleration_pole(ev[c.acceleration_image(p)][k:k + 1], ev[c.position(p)][k:k + 1],
                          ev[c.omega(link)][k:k + 1], ev[c.epsilon(link)][k:k + 1])[0]
    return q if np.all(np.isfinite(q)) else None


def _grade_poles(ctx: Ctx, k: int, frame: _Frame, tol: Tolerance, pivot: np.ndarray,
                 marks: Sequence[CentreMark], drawn_at: np.ndarray) -> list[CentreRow]:
    """The acceleration poles labelled on the drawing of the centres (Q2), placed in the
    centres' frame. Only a label near that drawing is one — within its centres' box grown by
    the box's size (a force plan's inertia force Q2 is no pole); of several, the nearest."""
    if not len(drawn_at):
        return []
    lo, hi = drawn_at.min(axis=0), drawn_at.max(axis=0)
    grow = float(max(hi - lo)) or 10.0
    lo, hi = lo - grow, hi + grow
    best: dict[str, tuple[float, CentreMark, np.ndarray]] = {}
    for m in marks:
        if m.name.i != POLE or m.at is None:
            continue
        at = np.asarray(m.at, dtype=float)
        if not (np.all(at >= lo) and np.all(at <= hi)):
            continue
        q = _exact_pole(ctx, m.name.j, k)
        if q is None:
            continue
        p = frame.paper(q)
        d = float(np.hypot(*(p - at)))
        if m.name.j not in best or d < best[m.name.j][0]:
            best[m.name.j] = (d, m, p)
    out = []
    for _d, m, p in best.values():
        assert m.at is not None
        err = float(np.hypot(*(p - np.asarray(m.at))))
        allowed = tol.allowed_mm(float(np.hypot(*(p - pivot))))
        ok = err <= allowed
        out.append(CentreRow(f"Q{m.name.j}", m.written, (float(p[0]), float(p[1])), m.at, err,
                             allowed, OK if ok else WRONG, cause="" if ok else NEW,
                             hint="" if ok else T("centres.pole_hint", link=m.name.j),
                             found="point", where=m.where))
    return out


def _fit(cs: Centres, k: int, f: _Frame, pins: dict[tuple[str, str], list[np.ndarray]]) -> float:
    errs = []
    for key, ats in pins.items():
        r, _ = exact_centre(cs, cs.diagram.centre(*key), k)
        if r is not None:
            errs.append(min(float(np.hypot(*(f.paper(r) - a))) for a in ats))
    return float(np.median(errs)) if errs else math.inf


def _error(cs: Centres, ctr: Centre, k: int, f: _Frame, m: CentreMark, tol: Tolerance,
           pivot: np.ndarray) -> tuple[float, float, tuple[float, float] | None, str]:
    """(error, allowed, exact place on paper, how it was read): mm for a point, degrees for an
    arrow."""
    r, u = exact_centre(cs, ctr, k)
    at = np.asarray(m.at if m.at is not None else (math.nan, math.nan), dtype=float)
    if r is None and u is None:
        return 0.0, 0.0, None, "indeterminate"
    if r is not None:
        p = f.paper(r)
        exact = (float(p[0]), float(p[1]))
        if m.direction is not None and not m.infinite:
            to = p - at
            ang = _angle(np.asarray(m.direction), to, signed=True)
            return ang, ARROW_DEG, exact, "arrow"
        if m.infinite:
            return math.inf, 0.0, exact, "infinity"
        return float(np.hypot(*(p - at))), tol.allowed_mm(float(np.hypot(*(p - pivot)))), \
            exact, "point"
    if u is None:
        return 0.0, 0.0, None, "indeterminate"
    if m.infinite or m.direction is not None:
        if m.direction is None:
            return 0.0, ARROW_DEG, None, "infinity"
        return _angle(np.asarray(m.direction), u, signed=False), ARROW_DEG, None, "infinity"
    return math.inf, 0.0, None, "point"


def _angle(a: np.ndarray, b: np.ndarray, signed: bool) -> float:
    nb = float(np.hypot(*b))
    if not nb > 0:
        return 0.0
    c = float(np.clip(np.dot(a, b) / (np.hypot(*a) * nb), -1.0, 1.0))
    ang = math.degrees(math.acos(c))
    return ang if signed else min(ang, 180.0 - ang)


def _swaps(cs: Centres, k: int, frame: _Frame, tol: Tolerance, pivot: np.ndarray,
           chosen: dict[tuple[str, str], CentreMark],
           rows: dict[tuple[str, str], CentreRow]) -> None:
    wrong = [key for key, r in rows.items() if r.verdict == WRONG and chosen[key].direction is None]
    for n, a in enumerate(wrong):
        for b in wrong[n + 1:]:
            if rows[a].cause == SWAPPED or rows[b].cause == SWAPPED:
                continue
            ea = _error(cs, cs.diagram.centre(*b), k, frame, chosen[a], tol, pivot)
            eb = _error(cs, cs.diagram.centre(*a), k, frame, chosen[b], tol, pivot)
            if ea[0] <= ea[1] and eb[0] <= eb[1]:
                for x, y in ((a, b), (b, a)):
                    rows[x].cause = SWAPPED
                    rows[x].hint = T("centres.swapped", a=rows[x].label, b=rows[y].label)


def _why(cs: Centres, ctr: Centre, k: int, frame: _Frame,
         chosen: dict[tuple[str, str], CentreMark], rows: dict[tuple[str, str], CentreRow],
         row: CentreRow) -> None:
    """The hint of a wrong centre: its pair, or the two lines of its Kennedy construction and how
    far the drawn centre is off each; carried when it lies on the lines through the student's
    own (wrong) centres."""
    row.cause = NEW
    r, _u = exact_centre(cs, ctr, k)
    if ctr.pair is not None:
        pair = ctr.pair
        if pair.kind is PairKind.PRISMATIC:
            row.hint = T("centres.hint_prismatic", centre=row.label, a=pair.a, b=pair.b)
        else:
            row.hint = T("centres.hint_pin", centre=row.label, point=pair.point)
        return
    if r is None:
        row.hint = T("centres.hint_infinite", centre=row.label)
        return
    if row.at_mm is None:               # written "∞" for a finite centre
        row.hint = rule_of(cs, ctr, k)
        return
    tri = cs.values[(ctr.i, ctr.j)].triangles[k]
    lines, offs, own_ok = [], [], True
    for t in tri:
        kk = ctr.via[int(t)]
        a, b = ordered(cs.diagram.links, ctr.i, kk), ordered(cs.diagram.links, ctr.j, kk)
        lines.append(T("centres.line", a=label(a), b=label(b)))
        pa, pb = (_paper_of(cs, x, k, frame, chosen) for x in (a, b))
        off = _off_line(np.asarray(row.at_mm), pa, pb)
        offs.append(off)
        own_ok = own_ok and off is not None and off <= (row.tolerance or 0.0) and \
            any(rows.get(x) is not None and rows[x].verdict == WRONG for x in (a, b))
    offs_txt = join(["?" if o is None else T("centres.off", d=o) for o in offs])
    if own_ok and len(offs) == 2:
        row.cause = CARRIED
        row.hint = T("centres.hint_carried", centre=row.label, l1=lines[0], l2=lines[1])
        return
    row.hint = T("centres.hint_kennedy", centre=row.label, l1=lines[0] if lines else "",
                 l2=lines[1] if len(lines) > 1 else "", offs=offs_txt)


def _paper_of(cs: Centres, key: tuple[str, str], k: int, frame: _Frame,
              chosen: dict[tuple[str, str], CentreMark]) -> tuple[np.ndarray, bool]:
    """A centre on paper as the student drew it (else exact): (point or direction, finite)."""
    m = chosen.get(key)
    if m is not None and m.direction is None and not m.infinite and m.at is not None:
        return np.asarray(m.at, dtype=float), True
    r, u = exact_centre(cs, cs.diagram.centre(*key), k)
    if r is not None:
        return frame.paper(r), True
    return (np.asarray(u) if u is not None else np.full(2, np.nan)), False


def _off_line(p: np.ndarray, a: tuple[np.ndarray, bool], b: tuple[np.ndarray, bool]
              ) -> float | None:
    """Distance of p from the line through two centres (one may be a direction)."""
    (pa, fa), (pb, fb) = a, b
    if not fa and not fb:
        return None
    base, d = (pa, pb - pa) if fa and fb else ((pa, pb) if fa else (pb, pa))
    n = float(np.hypot(*d))
    if not n > 0 or not np.all(np.isfinite(d)):
        return None
    u, w = d / n, p - base
    return abs(float(u[0] * w[1] - u[1] * w[0]))


def _note(key: str, **args: object) -> Note:
    return Note("warning", T(key, **args))




def centres_text(report: CheckReport, lang: str) -> list[str]:
    """The text report's section of drawn centres."""
    from ..i18n import message, num
    from .report import verdict_text
    from .texts import tr

    out = [T("centres.title", frame=report.centres_frame).tr(lang)]
    if report.centres_phi is not None:
        out.append("   " + T("centres.at", phi=report.centres_phi).tr(lang))
    if report.centres_mu:
        out.append("   " + T("centres.mu", mu=report.centres_mu).tr(lang))
    sym = message("centres.symbol", lang)
    for c in report.centres:
        name = sym + c.label[1:] if c.label.startswith("I") else c.label
        err = "—" if c.error is None or not math.isfinite(c.error) else num(c.error, ".1f", lang)
        unit = T("centres.deg" if c.found in ("arrow", "infinity") else "centres.mm").tr(lang)
        out.append(f"   {name:<8}{c.written:<12}{err:>8} {unit:<4} "
                   f"{verdict_text(c.verdict, c.cause, lang)}")
        if c.verdict in (WRONG, MISSING) and c.hint:
            out.append(f"        → {tr(c.hint, lang)}")
    return out
