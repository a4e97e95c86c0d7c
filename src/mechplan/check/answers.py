"""Check the answer table of a dynamics, engine, cam or gear study against its exact results.

Names are read through the ``[answers.<kind>]`` sections of the notation catalogue
(:mod:`mechplan.submission.notation`); every value is graded with its error: *ok* within the
quantity's tolerance (± pct % of the exact value, ± an absolute floor, or ± span_pct % of its
diagram's extent, whichever is largest; tooth numbers exactly); a *slip* when it does not follow
from the student's own other answers by the course's formula (:mod:`mechplan.studies.answers`);
*wrong* and *carried* when it follows from their own wrong inputs; *swapped* when two names hold
each other's values; *new* otherwise. The result is a :class:`CheckReport` with value rows only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from ..errors import CheckError
from ..scene.document import study_kind
from ..studies.answers import Keys, valid_sets
from ..submission.answer_table import read_answers
from ..submission.notation import (
    ANSWER_TABLES,
    AnswerSpec,
    answer_section,
    closest_answers,
    compact,
    is_angle_column,
    read_answer,
)
from ..submission.read import Entry, Note
from ..submission.written import parse_answer
from ..units import si_unit
from .context import Options, swaps
from .report import (
    CARRIED,
    NEW,
    OK,
    SLIP,
    SWAPPED,
    UNCHECKED,
    WRONG,
    CheckReport,
    Finding,
    ValueRow,
)
from .texts import T, join


def read_name(name: str, kind: str, section: str | None, has_angle: bool,
              keys: Keys) -> tuple[AnswerSpec, str] | None:
    """The quantity an answer's name means (its spec and its key in ``keys``), or None."""
    tables = ANSWER_TABLES[kind]
    if kind == "gears":
        sk = answer_section(section)
        if sk == "pair" or keys.study.planetary is None:
            tables = ("gears_pair",)
        elif sk == "planetary" or keys.study.pair is None:
            tables = ("gears",)
    found = read_answer(name, tables, has_angle)
    if kind != "linkage" or (found is not None and _known(keys, found[1])):
        return found
    from ..studies.linkage import subjects  # "v_rub_B", "γ II(4,5)": a name and its subject

    flat = compact(name)
    for subject in subjects(keys):
        tail = compact(subject)
        if flat.endswith(tail) and len(flat) > len(tail):
            stem = read_answer(flat[: -len(tail)], tables, has_angle)
            if stem is not None and _known(keys, f"{stem[1]}.{subject}"):
                return stem[0], f"{stem[1]}.{subject}"
    return found


def _known(keys: Keys, key: str) -> bool:
    return key in keys.scalars or key in keys.columns


#: the files an answer table may be
TABLE_SUFFIXES = (".toml", ".csv", ".tsv", ".txt", ".xlsx", ".xlsm")


# -- entry points -------------------------------------------------------------------------------
def maybe_check_answers(scene: Any, submission: Any,
                        options: Options | None = None) -> CheckReport | None:
    """Check an answer table when the scene is a dynamics, engine, cam or gear study and the
    submission a TOML/CSV table of its answers; None when it is a linkage check."""
    if not isinstance(scene, (str, Path)) or not isinstance(submission, (str, Path)):
        return None
    found = study_kind(scene)
    if found is None:
        return None
    if Path(submission).suffix.lower() not in TABLE_SUFFIXES:
        if found[0] in ("dynamics", "linkage"):
            return None                 # the plans of the linkage are checked elsewhere
        raise CheckError(T("answers.table_needed", kind=T(f"answers.kind.{found[0]}"),
                           suffixes=join(TABLE_SUFFIXES)), file=str(submission))
    from ..studies import solve_file

    kind = found[0]
    if kind not in ("dynamics", "linkage"):
        table = read_answers(submission, is_angle_column)
        return check_answers(scene, table, solve_file(scene).answers(), kind, options or Options())
    try:                                # a linkage table of the same scene is checked elsewhere
        table = read_answers(submission, is_angle_column)
    except CheckError:
        return None
    keys = solve_file(scene).answers()
    read = sum(read_name(i.name, kind, i.section, i.phi_deg is not None, keys) is not None
               for i in table.entries)
    if 2 * read < len(table.entries):
        return None                     # mostly segments and linkage values (pb, v_B …)
    return check_answers(scene, table, keys, kind, options or Options())


# -- grading ------------------------------------------------------------------------------------
@dataclass
class _Row:
    item: Entry
    spec: AnswerSpec
    key: str
    value: float
    half: float
    row: ValueRow
    exact: float | None = None
    tol: float = 0.0


def check_answers(scene: Any, table: Any, keys: Keys, kind: str,
                  options: Options) -> CheckReport:
    """Grade every answer of a table against the study's exact results."""
    notes: list[Note] = list(table.notes)
    report = CheckReport(str(scene), table.path, "table", math.nan,
                         T("answers.source", kind=T(f"answers.kind.{kind}")))
    user = options.tolerance.get(None)
    rows: list[_Row] = []
    for item in table.entries:
        found = read_name(item.name, kind, item.section, item.phi_deg is not None, keys)
        if found is None:
            notes.append(Note("error", T("answers.not_understood", name=item.name,
                                         kind=T(f"answers.kind.{kind}"),
                                         known=join(closest_answers(item.name, kind))), item.where))
            continue
        spec, key = found
        if key in keys.dimensions:
            spec = replace(spec, dimension=keys.dimensions[key])
        parsed = parse_answer(item.text or "", spec.dimension, item.where, notes, item.name)
        if parsed is None:
            continue
        if spec.magnitude:
            parsed = (abs(parsed[0]), parsed[1])
        name = item.name if item.phi_deg is None else f"{item.name} ({item.phi_deg:g}°)"
        unit = _unit(spec.dimension)
        rows.append(_Row(item, spec, key, parsed[0], parsed[1],
                         ValueRow(name, key, unit, None, None, where=item.where)))
    written = {(r.key, r.item.phi_deg): r.value for r in rows}
    chosen_set = _gear_set(keys, written, rows, notes, report)
    for r in rows:
        r.exact = chosen_set.get(r.key, keys.exact(r.key, r.item.phi_deg))
        if r.exact is None:
            angles = keys.angles(r.key)
            notes.append(Note("warning", T("answers.no_exact", name=r.item.name,
                                           phi=r.item.phi_deg if r.item.phi_deg is not None
                                           else math.nan,
                                           angles=join(f"{a:g}°" for a in angles) or "—")
                              if angles else T("answers.not_computed", name=r.item.name),
                              r.item.where))
            continue
        s = r.spec
        pct = user.pct if user is not None and not s.integer else s.pct
        r.tol = 0.5 if s.integer else max(pct / 100 * abs(r.exact), s.floor_value(),
                                          s.span_pct / 100 * keys.spans.get(r.key, 0.0), r.half)
    _grade(rows, keys, written, report)

    def scale(r: _Row, x: float) -> float:
        return math.degrees(x) if r.spec.dimension == "angle" else x

    for r in rows:
        row = r.row
        row.submitted = scale(r, r.value)
        if r.exact is not None:
            row.exact = scale(r, r.exact)
            row.tolerance = scale(r, r.tol)
            row.error_pct = (100 * (r.value - r.exact) / r.exact
                             if abs(r.exact) > r.tol else None)
        report.values.append(row)
    report.notes = notes
    return report


def _gear_set(keys: Keys, written: dict[tuple[str, float | None], float], rows: list[_Row],
              notes: list[Note], report: CheckReport) -> dict[str, float]:
    """The exact values of the student's own tooth-number set when it meets every condition."""
    if keys.kind != "gears" or keys.study.planetary is None:
        return {}
    n = len(keys.study.planetary.chosen.z)
    zs = [written.get((f"z{i}", None)) for i in range(1, n + 1)]
    if any(z is None for z in zs):
        return {}
    z = tuple(round(v) for v in zs if v is not None)
    sets = valid_sets(keys)
    chosen = tuple(int(v) for v in keys.study.planetary.chosen.z)
    if z in sets and z != chosen:
        c = sets[z]
        notes.append(Note("info", T("answers.valid_set", z=join(z), chosen=join(chosen))))
        return {**{f"z{i}": float(v) for i, v in enumerate(z, start=1)}, "u": c.ratio,
                "a_w": c.a_w[0], "assembly": c.assembly_value}
    return {}


def _grade(rows: list[_Row], keys: Keys, written: dict[tuple[str, float | None], float],
           report: CheckReport) -> None:
    kind_text = T(f"answers.kind.{keys.kind}")
    checked = [r for r in rows if r.exact is not None]
    ex = {id(r): float(r.exact) for r in checked if r.exact is not None}
    off = {id(r) for r in checked if abs(r.value - ex[id(r)]) > r.tol}
    # swapped names: two values off by themselves that are right under each other's names
    wrong = [r for r in checked if id(r) in off]
    swapped: set[int] = set()
    for a, b in swaps(wrong, lambda a, b: a.item.phi_deg == b.item.phi_deg and
                      a.spec.dimension == b.spec.dimension and abs(a.value - ex[id(b)]) <= b.tol,
                      group=lambda r: (r.item.phi_deg, r.spec.dimension)):
        swapped |= {id(a), id(b)}
        hint = T("answers.hint.swapped", a=a.row.name, b=b.row.name)
        for r in (a, b):
            r.row.verdict, r.row.cause, r.row.hint = WRONG, SWAPPED, hint
        report.findings.append(Finding("swapped labels", kind_text,
                                       f"{a.row.name} ↔ {b.row.name}", hint))
    status: dict[tuple[str, float | None], str] = {}
    pending: list[tuple[_Row, Any]] = []
    for r in checked:
        if id(r) in swapped:
            status[(r.key, r.item.phi_deg)] = WRONG
            continue
        own = keys.own(r.key, r.item.phi_deg, written)
        if own is not None:
            r.row.own = own[0]
            arith = max(0.01 * abs(own[0]), r.half, 0.25 * r.spec.floor_value(), 0.2
                        * r.spec.span_pct / 100 * keys.spans.get(r.key, 0.0), 1e-9)
            if abs(r.value - own[0]) > arith:
                r.row.verdict, r.row.cause = SLIP, NEW
                r.row.hint = T("answers.hint.slip", formula=own[1], own=_round(
                    math.degrees(own[0]) if r.spec.dimension == "angle" else own[0]),
                               written=r.item.name, text=r.item.text)
                report.findings.append(Finding("arithmetic slip", kind_text, r.row.name,
                                               r.row.hint))
                status[(r.key, r.item.phi_deg)] = SLIP
                continue
        if id(r) not in off:
            r.row.verdict = OK
            status[(r.key, r.item.phi_deg)] = OK
            continue
        status[(r.key, r.item.phi_deg)] = WRONG
        pending.append((r, own))
    for r, own in pending:
        upstream = [n for n in (own[2] if own else ())
                    if status.get((n, r.item.phi_deg if (n, r.item.phi_deg) in status else None))
                    in (WRONG, SLIP)]
        r.row.verdict = WRONG
        if upstream:
            r.row.cause = CARRIED
            r.row.hint = T("answers.hint.carried", formula=own[1], inputs=join(upstream))
            continue
        r.row.cause = NEW
        exact = r.exact if r.exact is not None else math.nan
        shown = math.degrees(exact) if r.spec.dimension == "angle" else exact
        if r.value * exact < 0 and abs(abs(r.value) - abs(exact)) <= r.tol:
            r.row.hint = T("answers.hint.sign", exact=_round(shown))
        else:
            r.row.hint = T("answers.hint.wrong", exact=round(shown) if r.spec.integer
                           else _round(shown),
                           unit=_unit(r.spec.dimension),
                           pct=100 * (r.value - exact) / exact if abs(exact) > r.tol
                           else math.nan)
        report.findings.append(Finding("wrong value", kind_text, r.row.name, r.row.hint))
    for r in rows:
        if r.exact is None:
            r.row.verdict = UNCHECKED


def _unit(dimension: str) -> str:
    return "°" if dimension == "angle" else si_unit(dimension)   # answers' angles are in degrees


def _round(x: float) -> float:
    """Four significant digits, for a hint."""
    return float(f"{x:.4g}") if math.isfinite(x) else x
