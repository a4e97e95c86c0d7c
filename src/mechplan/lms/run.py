"""The round trip: a submissions download checked student by student against their variants,
graded by the instructor's rule, and the files the LMS takes back written atomically into one
output folder (a re-run checks only what changed)."""

from __future__ import annotations

import csv
import hashlib
import io
import json
import os
import zipfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .. import __version__
from ..i18n import message, significant
from ..render.atomic import write_atomic
from .archive import Member, read_download, safe_name
from .layout import Participant, participants
from .roster import Person, find, read_roster
from .rule import Rule, grade_report, load_rule
from .samework import Same, fingerprint, same_work
from .sheets import (
    CanvasRow,
    Filled,
    canvas_gradebook,
    fill_worksheet,
    new_worksheet,
    read_worksheet,
)
from .variants import VariantFile, load_variants, variant_in

#: files mechplan grades; anything else handed in is listed, never skipped silently
GRADED = (".dxf", ".toml", ".csv", ".tsv", ".xlsx", ".xlsm", ".pdf")
PRIVATE = ".submissions"
OUTPUTS = ("grading_worksheet.csv", "feedback_files.zip", "canvas_gradebook.csv", "problems.csv",
           "same_work.csv", "lms_summary.csv", "quiz_moodle.xml", "quiz_canvas_qti.zip")


@dataclass
class Problem:
    """Something that could not be matched or read."""

    who: str
    file: str
    problem: str


@dataclass
class Result:
    """One student's outcome."""

    p: Participant
    person: Person | None
    variant: str
    files: list[dict[str, Any]] = field(default_factory=list)
    grade: float | None = None
    comment: str = ""


@dataclass
class RoundTrip:
    """What a round trip found and wrote."""

    results: list[Result]
    problems: list[Problem]
    same: list[Same]
    out: Path
    written: list[Path]


def _participant_person(p: Participant, roster: list[Person],
                        emails: dict[str, str]) -> Person | None:
    if not roster:
        return None
    if p.lms == "canvas":
        return find(roster, id=p.id) or find(roster, login=p.name) or find(roster, name=p.name)
    return find(roster, email=emails.get(p.id, "")) or find(roster, name=p.name)


def _variant(p: Participant, person: Person | None, variants: dict[str, VariantFile]) -> str:
    if person is not None:
        for v in (person.variant, person.id_number, person.login):
            if v and v in variants:
                return v
    for m in p.files:
        named = variant_in("/".join(m.parts), variants)
        if named:
            return named
    if p.id in variants:
        return p.id
    return next(iter(variants)) if len(variants) == 1 else ""


def _check_one(scene: str, sub: str, tol: tuple[float, float], lang: str, folder: str,
               stem: str, digest: str, rule: Rule, light: bool = False) -> dict[str, Any]:
    """Check one file (or find it checked: ``<stem>.json`` with the same digest); write its
    report (text) and, for a drawing, its overlay DXF into ``folder`` (not when ``light``: a
    check against another variant, for the same-work list)."""
    from ..check.grade import Options, check
    from ..check.overlay import write_overlay
    from ..check.report import Tolerance
    from ..errors import MechplanError

    cache = Path(folder) / f"{stem}.json"
    if cache.is_file() and not cache.is_symlink():
        done: dict[str, Any] = json.loads(cache.read_text(encoding="utf-8"))
        if done.get("digest") == digest:
            return done
    row: dict[str, Any] = {"digest": digest, "file": Path(sub).name, "error": ""}
    try:
        report = check(scene, sub, Options(tolerance={None: Tolerance(tol[0], tol[1])}))
    except MechplanError as exc:
        row["error"] = str(exc).replace(sub, Path(sub).name[3:])
    else:
        g = grade_report(report, rule)
        summary = report.summary()
        row |= {"grade": g.grade, "earned": g.earned, "possible": g.possible, "lost": g.lost,
                "passed": report.passed, "nothing_found": report.nothing_found, **summary}
    if not light and "grade" in row:
        write_atomic(Path(folder) / f"{stem}.txt", (report.text(lang) + "\n").encode())
        if report.kind == "dxf":
            try:
                write_overlay(report, Path(folder) / f"{stem}_overlay.dxf", lang)
                write_overlay(report, Path(folder) / f"{stem}_overlay.pdf", lang)
                row["overlay"] = f"{stem}_overlay.dxf"
                row["overlay_pdf"] = f"{stem}_overlay.pdf"
            except MechplanError as exc:
                row["overlay_error"] = str(exc)
        row["report"] = f"{stem}.txt"
    write_atomic(cache, json.dumps(row, ensure_ascii=False).encode())
    return row


def _comment(r: Result, rule: Rule, lang: str) -> str:
    """The feedback comment of one student."""
    parts = []
    for f in r.files:
        if f.get("error"):
            parts.append(message("lms.comment.unreadable", lang, file=f["file"], error=f["error"]))
        elif f.get("nothing_found"):
            parts.append(message("lms.comment.nothing", lang, file=f["file"]))
        else:
            parts.append(message("lms.comment.checked", lang, file=f["file"], ok=f["ok"],
                                 checked=f["checked"], new=f["new"], carried=f["carried"],
                                 slip=f["slip"], missing=f["missing"]))
    if r.grade is not None:
        parts.append(message("lms.comment.grade", lang, grade=significant(r.grade, 6, lang),
                             max=significant(rule.max_grade, 6, lang)))
    return " ".join(parts)


def round_trip(variants_path: Path, download: Path, out: Path, *, roster: Path | None = None,
               worksheet: Path | None = None, rule: Path | None = None, lang: str = "en",
               jobs: int = 1, progress: bool | None = None,
               gradebook: Path | None = None) -> RoundTrip:
    """Check a Moodle or Canvas download; write the grade files into ``out`` (Canvas's
    exported ``gradebook``, when given, filled in place)."""
    from ..batch.engine import run_tasks
    from ..batch.outdir import locked, prepare_output, subfolder
    from ..submission.read import read_submission
    from .gradebook import read_gradebook

    variants = load_variants(variants_path)
    the_rule = load_rule(rule)
    people = read_roster(roster) if roster else []
    sheet = read_worksheet(worksheet) if worksheet else None
    book = read_gradebook(gradebook) if gradebook else None
    members = read_download(download, out)     # refuses a hostile archive before writing anything
    found, loose = participants(members)
    if not found and not loose:
        from ..check.texts import T
        from ..errors import CheckError

        raise CheckError(T("error.no_submissions"), file=str(download))
    out = prepare_output(out)
    problems = [Problem("", "/".join(m.parts), message("lms.problem.whose", lang)) for m in loose]
    emails: dict[str, str] = {}
    if sheet is not None:
        col = {n: i for i, n in enumerate(sheet.header)}
        for row in sheet.rows:
            ident = row[col["Identifier"]].split()
            if ident and "Email address" in col and len(row) > col["Email address"]:
                emails[ident[-1]] = row[col["Email address"]]
    with locked(out):
        private = subfolder(out, PRIVATE)
        os.chmod(private, 0o700)
        reports = subfolder(out, "reports")
        results: list[Result] = []
        calls: list[tuple[Any, ...]] = []
        where: list[tuple[int, str, str]] = []
        for p in found:
            person = _participant_person(p, people, emails)
            r = Result(p, person, _variant(p, person, variants))
            results.append(r)
            who = f"{p.name} ({p.id})"
            if roster and person is None:
                problems.append(Problem(who, "", message("lms.problem.not_on_roster", lang)))
            if not r.variant:
                problems.append(Problem(who, "", message("lms.problem.no_variant", lang)))
            graded = [m for m in p.files if m.name.lower().endswith(GRADED)]
            for m in p.files:
                if m not in graded:
                    problems.append(Problem(who, "/".join(m.parts),
                                            message("lms.problem.not_graded", lang)))
            if not graded:
                problems.append(Problem(who, "", message("lms.problem.no_file", lang)))
            if not r.variant:
                continue
            key = safe_name(f"{p.lms}_{p.id}_{p.name}")
            own = subfolder(private, key)
            mine = subfolder(reports, key)
            scene = variants[r.variant].scene
            for k, m in enumerate(graded):
                name = f"{k:02d}_{safe_name(m.name)}"
                path = own / name
                write_atomic(path, m.data)
                digest = hashlib.sha256(m.data + scene.read_bytes() + repr(the_rule).encode()
                                        + lang.encode() + __version__.encode()).hexdigest()
                calls.append((str(scene), str(path), (the_rule.tolerance_mm,
                              the_rule.tolerance_pct), lang, str(mine), name, digest, the_rule))
                where.append((len(results) - 1, key, m.name))
        done = list(run_tasks(_indexed, [(i, c) for i, c in enumerate(calls)],
                              workers=jobs if jobs > 0 else None, progress=progress,
                              desc="submissions", unit="file"))
        for i, row in sorted(done, key=lambda x: x[0]):
            idx, key, original = where[i]
            row["folder"], row["file"] = key, original
            row["call"] = i
            results[idx].files.append(row)
        others = _other_variants(results, calls, variants, the_rule)
        fits = list(run_tasks(_indexed, [(i, c[:9]) for i, c in enumerate(others)],
                              workers=jobs if jobs > 0 else None, progress=progress,
                              desc="other variants", unit="file"))
        prints = []
        for r in results:
            who = f"{r.p.name} ({r.p.id})"
            for f in r.files:
                if f.get("error"):
                    problems.append(Problem(who, f["file"], f["error"]))
            grades = [f["grade"] for f in r.files if f.get("grade") is not None]
            r.grade = max(grades) if grades else the_rule.unreadable if r.files else None
            r.comment = _comment(r, the_rule, lang) or message("lms.comment.none", lang)
            for m in r.p.files:
                if m.name.lower().endswith(GRADED):
                    sub = _read_quietly(read_submission, private, r, m)
                    prints.append(fingerprint(who, m.data, sub))
        same = same_work(prints, lang) + _better_fits(results, others, fits, lang)
        written = _write_outputs(out, results, problems, same, the_rule, sheet, people,
                                 variants, lang, reports)
        if book is not None:
            _fill_gradebook(out, book, results, problems, the_rule, lang)
    return RoundTrip(results, problems, same, out, written)


def _other_variants(results: list[Result], calls: list[tuple[Any, ...]],
                    variants: dict[str, VariantFile], rule: Rule) -> list[tuple[Any, ...]]:
    """Checks of every file graded below the maximum against every other variant (light:
    no report written), for the same-work list."""
    out = []
    for r in results:
        for f in r.files:
            if f.get("grade") is None or f["grade"] >= rule.max_grade or f.get("nothing_found"):
                continue
            _, sub, tol, lang, folder, stem, digest, _ = calls[f["call"]]
            for vid, v in variants.items():
                if vid != r.variant:
                    out.append((str(v.scene), sub, tol, lang, folder, f"{stem}@{safe_name(vid)}",
                                hashlib.sha256((digest + vid).encode()).hexdigest(), rule, True,
                                r, f, vid))
    return out


def _better_fits(results: list[Result], others: list[tuple[Any, ...]],
                 fits: list[tuple[int, dict[str, Any]]], lang: str) -> list[Same]:
    """Submissions that fit another variant better than their own."""
    best: dict[tuple[int, int], tuple[float, str, Result, dict[str, Any]]] = {}
    for i, row in fits:
        *_, r, f, vid = others[i]
        if row.get("grade") is not None and row["grade"] > f["grade"]:
            k = (id(r), f["call"])
            if k not in best or row["grade"] > best[k][0]:
                best[k] = (row["grade"], vid, r, f)
    return [Same(f"{r.p.name} ({r.p.id})", vid, "fits another variant",
                 message("lms.same.fits", lang, file=f["file"], own=r.variant,
                         own_grade=significant(f["grade"], 6, lang), other=vid,
                         grade=significant(g, 6, lang)))
            for g, vid, r, f in best.values()]


def _indexed(i: int, call: tuple[Any, ...]) -> tuple[int, dict[str, Any]]:
    return i, _check_one(*call[:9])


def _read_quietly(reader: Any, private: Path, r: Result, m: Member) -> Any:
    from ..errors import MechplanError

    key = safe_name(f"{r.p.lms}_{r.p.id}_{r.p.name}")
    for path in sorted((private / key).glob(f"*_{safe_name(m.name)}")) if (private / key).is_dir() \
            else ():
        try:
            return reader(path)
        except (MechplanError, OSError):
            return None
    return None


def _number(text: str) -> float | None:
    try:
        return float(text.replace(",", "."))
    except ValueError:
        return None


def _csv(rows: list[list[Any]]) -> bytes:
    from ..batch.csvsafe import csv_safe

    buf = io.StringIO(newline="")
    csv.writer(buf, lineterminator="\n").writerows([[csv_safe(c) for c in r] for r in rows])
    return buf.getvalue().encode("utf-8")


def _write_outputs(out: Path, results: list[Result], problems: list[Problem], same: list[Same],
                   rule: Rule, sheet: Any, people: list[Person],
                   variants: dict[str, VariantFile], lang: str, reports: Path) -> list[Path]:
    from .quiz import canvas_qti, moodle_quiz

    written = []
    moodle = [r for r in results if r.p.lms == "moodle"]
    if moodle or sheet is not None:
        filled = [Filled(r.p.id, r.p.name, r.person.email if r.person else "", r.grade, r.comment)
                  for r in moodle]
        data, missing = fill_worksheet(sheet or new_worksheet(rule.max_grade), filled,
                                       rule.max_grade, rule.decimals)
        problems += [Problem(n, "", message("lms.problem.not_in_worksheet", lang))
                     for n in missing]
        if sheet is not None:
            maxima = {r[sheet.header.index("Maximum Grade")] for r in sheet.rows
                      if "Maximum Grade" in sheet.header
                      and len(r) > sheet.header.index("Maximum Grade")}
            if any(_number(m) not in (None, rule.max_grade) for m in maxima):
                problems.append(Problem("", "grading_worksheet.csv", message(
                    "lms.problem.max_grade", lang, worksheet=", ".join(sorted(maxima)),
                    rule=significant(rule.max_grade, 6, lang))))
        written.append(write_atomic(out / "grading_worksheet.csv", data))
        written.append(write_atomic(out / "feedback_files.zip",
                                    lambda fh: _feedback_zip(fh, moodle, reports)))
    column = f"{rule.assignment} ({rule.assignment_id})" if rule.assignment_id else rule.assignment
    canvas = []
    graded_people = set()
    for r in results:
        pr = r.person
        if pr is not None:
            graded_people.add(id(pr))
        canvas.append(CanvasRow(pr.name if pr else r.p.name, pr.id if pr and pr.id else r.p.id,
                                pr.id_number if pr else "", pr.login if pr else r.p.name,
                                pr.section if pr else "", r.grade))
    for pr in people:
        if id(pr) not in graded_people:
            problems.append(Problem(pr.name, "", message("lms.problem.no_submission", lang)))
            canvas.append(CanvasRow(pr.name, pr.id, pr.id_number, pr.login, pr.section, None))
    written.append(write_atomic(out / "canvas_gradebook.csv",
                                canvas_gradebook(canvas, column, rule.max_grade, rule.decimals)))
    written.append(write_atomic(out / "problems.csv", _csv(
        [["student", "file", "problem"]] + [[p.who, p.file, p.problem] for p in problems])))
    written.append(write_atomic(out / "same_work.csv", _csv(
        [["first", "second", "evidence", "detail"]]
        + [[s.first, s.second, s.evidence, s.detail] for s in same])))
    rows: list[list[Any]] = [["student", "id", "lms", "variant", "file", "grade", "passed",
                              "checked", "ok", "wrong", "new", "carried", "slip", "missing",
                              "error"]]
    for r in results:
        for f in r.files or [{}]:
            rows.append([r.p.name, r.p.id, r.p.lms, r.variant, f.get("file", ""),
                         "" if f.get("grade") is None else f["grade"], f.get("passed", ""),
                         *(f.get(k, "") for k in ("checked", "ok", "wrong", "new", "carried",
                                                  "slip", "missing")), f.get("error", "")])
    written.append(write_atomic(out / "lms_summary.csv", _csv(rows)))
    keys = []
    for r in results:
        key = variants[r.variant].answer_key() if r.variant else None
        if key is not None:
            keys.append((f"{safe_name(r.p.name)} {r.p.id} — {r.variant}", key))
    if keys:
        written.append(write_atomic(out / "quiz_moodle.xml",
                                    moodle_quiz(keys, rule.tolerance_pct, lang)))
        seen: dict[str, dict[str, Any]] = {}
        for r in results:                  # Canvas: a quiz per variant, assigned to its students
            key = variants[r.variant].answer_key() if r.variant else None
            if key is not None:
                seen.setdefault(r.variant, key)
        written.append(write_atomic(out / "quiz_canvas_qti.zip", canvas_qti(
            [(f"mechplan {vid}", k) for vid, k in sorted(seen.items())],
            rule.tolerance_pct, lang)))
    return written


def _fill_gradebook(out: Path, book: Any, results: list[Result], problems: list[Problem],
                    rule: Rule, lang: str) -> None:
    """Canvas's own gradebook export with the assignment's column filled (replacing the
    gradebook made from the roster), and ``problems.csv`` written again with what it lacks."""
    from .gradebook import Graded, assignment_column, fill_gradebook, scaled_note

    column = assignment_column(book, rule.assignment, rule.assignment_id)
    graded = []
    for r in results:
        pr = r.person
        canvas = r.p.lms == "canvas"
        graded.append(Graded(
            f"{r.p.name} ({r.p.id})", r.grade,
            ids=tuple(x for x in ((r.p.id if canvas else ""), pr.id if pr else "") if x),
            sis=tuple(x for x in (pr.id_number if pr else "",) if x),
            logins=tuple(x for x in ((r.p.name if canvas else ""), pr.login if pr else "")
                         if x),
            names=tuple(x for x in (pr.name if pr else "", r.p.name) if x)))
    data, missing, scaled = fill_gradebook(book, graded, column, rule.max_grade, rule.decimals)
    problems += [Problem(w, Path(book.path).name, message("lms2.not_in_gradebook", lang))
                 for w in missing]
    if scaled is not None:
        problems.append(Problem("", Path(book.path).name,
                                scaled_note(scaled, rule.max_grade, lang).tr(lang)))
    write_atomic(out / "canvas_gradebook.csv", data)
    write_atomic(out / "problems.csv", _csv(
        [["student", "file", "problem"]] + [[p.who, p.file, p.problem] for p in problems]))


def _feedback_zip(fh: Any, moodle: list[Result], reports: Path) -> None:
    """Moodle's feedback files layout: ``Full Name_<id>_assignsubmission_file_/<files>``."""
    with zipfile.ZipFile(fh, "w", zipfile.ZIP_DEFLATED) as zf:
        for r in moodle:
            folder = r.p.folder
            for f in r.files:
                stem = safe_name(Path(f["file"]).stem)
                for name, shown in ((f.get("report"), f"{stem}_report.txt"),
                                    (f.get("overlay"), f"{stem}_overlay.dxf"),
                                    (f.get("overlay_pdf"), f"{stem}_overlay.pdf")):
                    if name:
                        src = reports / f["folder"] / name
                        if src.is_file() and not src.is_symlink():
                            zf.writestr(f"{folder}/{shown}", src.read_bytes())
