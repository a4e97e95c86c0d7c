"""A sheet with plans of several crank positions: each plan graded at its own position.

Sheet 1 of the course project draws the velocity plan of every position (and students draw
several plans on one sheet). Graded at one crank angle, every plan but one would be "wrong". When
the angle is not given and the sheet holds more than one plan of a kind, or its titles name
several crank angles (a velocity plan of one position beside the plans of another), each drawn
plan is given the scene position its drawing fits best, and the plans of one position are graded
together (the student's own points of one plan re-derive only the plans of the same position).
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Callable, Sequence

import numpy as np

from ..errors import MechplanError
from ..submission.read import Entry, Note, Point, SheetText
from ..submission.titles import position_written, written_step
from ..submission.written import is_angle_name, parse_angle
from .context import Ctx
from .report import SLIP, WRONG, CheckReport, Finding, PlanReport, PointRow, SegmentRow, ValueRow
from .texts import T

Grader = Callable[[Ctx, int], CheckReport]


def several_positions(ctx: Ctx) -> bool:
    """Whether the sheet holds more than one drawn plan of a kind (e.g. velocity plans #1, #2),
    or plans under texts that name different crank angles ("velocity plan, φ = 1°" beside
    "acceleration plan, φ = 61°": a velocity plan of another position next to the plans of one)
    or different lengths of a linear driver ("l4 = 3000 mm" beside "l4 = 2400 mm")."""
    if ctx.sheet is None:
        return False
    kinds = [dp.plan for dp in ctx.sheet.plans]
    if len(set(kinds)) < len(kinds):
        return True
    return len(kinds) > 1 and len(written_positions(ctx)) > 1


def written_positions(ctx: Ctx) -> set[float]:
    """The distinct positions written on a sheet: crank angles (° in [0, 360), to 0.01°), or a
    linear driver's coordinate ending a title ("Положение 0, l4 = 1450,0 мм", in mm)."""
    if not ctx.scene.mechanism.drive.linear:
        return written_angles(ctx.sub.texts)
    name = ctx.c["pos.q"].label.replace("_", "").casefold()
    out: set[float] = set()
    for t in ctx.sub.texts:
        written = position_written(t.text)
        if written is not None and written[0].replace("_", "").casefold() == name:
            out.add(round(written[1], 3))
    return out


#: a crank angle written on a sheet, alone or ending a plan's title: "φ = 60°", "position 11,
#: φ = 1,0°", "phi1 = 30 deg" (not a scale "μφ = 4 °/mm")
_WRITTEN_PHI = re.compile(r"(?<!\w)(?:φ|ϕ|phi)_?1?\s*=\s*(-?\d+(?:[.,]\d+)?)\s*(?:°|deg\b)"
                          r"(?!\s*/)", re.IGNORECASE)


def written_angles(texts: Sequence[SheetText]) -> set[float]:
    """The distinct crank angles (° in [0, 360), to 0.01°) written on a sheet."""
    return {round(float(m.group(1).replace(",", ".")) % 360.0, 2) % 360.0
            for t in texts for m in _WRITTEN_PHI.finditer(t.text)}


def fit_score(rows: Sequence[SegmentRow | ValueRow],
              points: Sequence[PointRow] = ()) -> tuple[float, float]:
    """How badly rows (and points) fit a position: wrong ones, then the median relative error."""
    wrong = sum(1 for row in [*rows, *points] if row.verdict in (WRONG, SLIP))
    errs = [abs(row.error_pct) for row in rows if row.error_pct is not None]
    return (wrong, float(np.median(errs)) if errs else math.inf)


def _best_position(reports: list[CheckReport], j: int, title: str = "") -> int:
    """The candidate position of drawn plan ``j``: the one its title names ("Force plan I(0,1)
    — position 1, φ = 30.0°"; plans of one kind with the same letters cannot be told apart by
    their fit) where it fits there with no more wrong segments than at its best fit, else the
    one it fits best."""
    plans = [r.plans[j] for r in reports]
    scores = [fit_score(p.segments, p.points) for p in plans]
    best = min(range(len(plans)), key=lambda k: scores[k])
    titled = _title_position(title, reports)
    # a title taken from a neighbouring cell (a grid's titles stand close) names a position the
    # plan does not fit: the title decides only where it fits no worse than the best fit
    if titled is not None and scores[titled][0] <= scores[best][0]:
        return titled
    return best


def _title_position(title: str, reports: Sequence[CheckReport]) -> int | None:
    """The candidate whose position a title ends with: a crank angle (°) or a linear driver's
    coordinate (as ``shown_coordinate`` gives it), to the title's last written digit."""
    written = position_written(title) if title else None
    if written is None:
        return None
    name, value, unit = written
    if unit in ("°", "deg") or is_angle_name(name):
        return _position_of(value, reports)
    step = written_step(title) * (1.0 + 1e-9)
    near = [k for k, r in enumerate(reports) if abs(r.phi_deg - value) <= step]
    return near[0] if len(near) == 1 else None


def grade_per_plan(ctx: Ctx, reports: list[CheckReport], best: int,
                   grade: Grader) -> CheckReport:
    """One report whose drawn plans are each graded at their best-fitting position.

    ``reports[k]`` graded every plan at candidate position k (drawn plans first, in the sheet's
    order); ``best`` is the position that fits the whole sheet best — its written values and
    table segments are kept.
    """
    assert ctx.sheet is not None
    drawn = ctx.sheet.plans
    at = [_best_position(reports, j, drawn[j].title) for j in range(len(drawn))]
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


#: what a title writes before its crank angle: "Zhukovsky's lever — φ", "Position 10, φ"
_TITLE_TAIL = re.compile(r"[\s,;:—–-]+")
#: a title's angle is a candidate position's when they differ by less than this (degrees)
_SAME_ANGLE_DEG = 0.05


def titled_positions(ctx: Ctx, reports: Sequence[CheckReport]) -> list[tuple[Point, int, Entry]]:
    """The candidate positions the sheet names in titles — a crank angle ("Zhukovsky's lever —
    φ = 30°", "Position 10, φ = 300°") or a linear driver's coordinate ("Zhukovsky's lever —
    l4 = 2400.0 mm") —, each with where its title stands and the title."""
    if ctx.sheet is None:
        return []
    linear = ctx.scene.mechanism.drive.linear
    coordinate = ctx.c["pos.q"].label.replace("_", "").casefold() if linear else ""
    out: list[tuple[Point, int, Entry]] = []
    for e in ctx.sheet.other_entries:
        words = [w for w in _TITLE_TAIL.split(e.name.strip()) if w]
        text = e.text or e.value
        if e.at is None or len(words) < 2 or not text:
            continue
        k: int | None = None
        if linear:
            if words[-1].replace("_", "").casefold() == coordinate:
                k = _title_position(f"{e.name} = {text}", reports)
        elif is_angle_name(words[-1]):
            try:
                k = _position_of(parse_angle(text), reports)
            except MechplanError:
                continue
        if k is not None:
            out.append((e.at, k, e))
    return out


def _position_of(angle: float, reports: Sequence[CheckReport]) -> int | None:
    """The candidate position at the crank angle ``angle`` (degrees), if one is."""
    for k, r in enumerate(reports):
        if abs((angle - r.phi_deg + 180.0) % 360.0 - 180.0) < _SAME_ANGLE_DEG:
            return k
    return None


def values_at_titled_positions(ctx: Ctx, reports: list[CheckReport], out: CheckReport) -> None:
    """Grade each written value at the position (crank angle or driver coordinate) of the title
    it is written under.

    A value written on a panel titled with its position (Zhukovsky's lever "— φ = 30°" with its
    M_b beneath) belongs to that position, whatever position the other plans of the sheet fit
    best. The title is the nearest one that stands above the value (a panel is titled above its
    drawing); a value with no such title, or whose title's angle is no candidate position,
    keeps the grade ``out`` gave it. ``reports[k]`` graded every value at candidate k, in the
    order of ``ctx.interp.values``.
    """
    titles = titled_positions(ctx, reports)
    if not titles or len(out.values) != len(ctx.interp.values):
        return
    out.values = list(out.values)
    for i, gv in enumerate(ctx.interp.values):
        if gv.at is None:
            continue
        above = [(math.dist(at, gv.at), k, e) for at, k, e in titles
                 if at[1] >= gv.at[1] - 1.0]
        if not above:
            continue
        _, k, title = min(above, key=lambda t: t[0])
        if len(reports[k].values) != len(out.values):
            continue
        row = reports[k].values[i]
        if row is out.values[i]:
            continue

        def about(f: Finding, name: str = gv.written, step: str = gv.quantity.step or "") -> bool:
            return f.kind in ("wrong value", "arithmetic slip") and (f.subject, f.step) == (
                name, step)

        out.values[i] = row
        out.notes.append(Note("info", T("note.value_at_title", name=gv.written,
                                        title=f"{title.name} = {title.text or title.value}"),
                              gv.where))
        out.findings = [f for f in out.findings if not about(f)]
        out.findings += [f for f in reports[k].findings if about(f)]
