"""A class of variants: per student a folder with the scene, its sheets and its answer key.

Each variant is one task on the engine. A folder is complete when its marker ``.complete`` (written
last, holding a fingerprint of the scene and the options) matches: re-running skips it. Every file
is written atomically; a variant that fails (cannot be assembled, bad value) is reported in
``summary.csv`` with its error and the others go on.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import stat
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .. import __version__
from ..errors import MechplanError
from ..i18n import Text
from ..render.atomic import write_atomic
from ..scene.document import parse_toml, read_text
from .csvsafe import csv_safe_row
from .engine import check_scheduler, run_tasks
from .keys import edited_text, with_values
from .outdir import locked, prepare_output, remove_stale, subfolder
from .variants import Variant

MARKER = ".complete"
SUMMARY = "summary.csv"


@dataclass(frozen=True)
class ClassJob:
    """What every variant of a class shares: the template and the output options."""

    template_text: str
    template_file: str
    name: str                       # stem of the sheets' file names
    out_dir: str
    formats: tuple[str, ...] = ("dxf", "svg", "pdf")
    size: str | None = None
    standard: str | None = None
    language: str | None = None
    #: the formats of each student's explanatory note ("docx", "pdf"); none: no note
    note: tuple[str, ...] = ()


@dataclass(frozen=True)
class ClassResult:
    """What a class run did."""

    rows: list[dict[str, Any]]
    solved: int
    skipped: int
    failed: int
    summary: Path


def variant_scene(job: ClassJob, variant: Variant) -> str:
    """Return the TOML text of a variant's scene: the template with the variant's values set.

    The template's text is edited in place (its comments, order and layout kept; see
    :func:`edited_text`); the id and name only in the first comment line, with every character
    that is not printable escaped — data, never TOML source.
    """
    header = f"# {_comment(variant.id)}" + (f" — {_comment(variant.name)}" if variant.name
                                             else "") + "\n"
    return header + edited_text(job.template_text, variant.values, job.template_file)


def _comment(text: str) -> str:
    """Text for a TOML comment: one line, non-printable characters and "\\" escaped."""
    return "".join(c if c.isprintable() and c != "\\" else
                   (f"\\u{ord(c):04x}" if ord(c) < 0x10000 else f"\\U{ord(c):08x}")
                   for c in text)


def _fingerprint(job: ClassJob, scene: str) -> str:
    h = hashlib.sha256()
    for part in (__version__, scene, ",".join(job.formats), str(job.size), str(job.standard),
                 str(job.language), ",".join(job.note)):
        h.update(part.encode())
        h.update(b"\0")
    return h.hexdigest()


def solve_variant(job: ClassJob, variant: Variant, index: int) -> tuple[int, dict[str, Any], bool]:
    """Write one variant's folder (or find it complete); return (index, summary row, skipped).

    The folder is a real folder inside the output (a symbolic link there fails the variant).
    """
    row: dict[str, Any] = {"id": variant.id, "name": variant.name, "status": "ok", "error": "",
                           **variant.values}
    try:
        scene = variant_scene(job, variant)
        folder = subfolder(Path(job.out_dir), variant.id)
    except MechplanError as exc:
        return index, {**row, "status": "failed", "error": str(exc)}, False
    marker = folder / MARKER
    stamp = _fingerprint(job, scene)
    if _regular(marker) and marker.read_text(encoding="utf-8") == stamp and _regular(
            folder / "summary.json"):
        with (folder / "summary.json").open(encoding="utf-8") as fh:
            return index, json.load(fh), True
    marker.unlink(missing_ok=True)
    remove_stale(folder, ("",))       # a killed run's temporary files (we hold the lock)
    scene_path = folder / "scene.toml"
    write_atomic(scene_path, scene.encode())
    try:
        row.update(_solve_and_write(job, variant, scene, str(scene_path), folder))
    except MechplanError as exc:     # one bad variant does not stop the class; a bug does
        row.update(status="failed", error=str(exc))
    write_atomic(folder / "summary.json", json.dumps(row, ensure_ascii=False, indent=1).encode())
    if row["status"] == "ok":
        write_atomic(marker, stamp.encode())
    return index, row, False


def _regular(path: Path) -> bool:
    """A regular file, not a link (a link to elsewhere is never read as our marker)."""
    try:
        return stat.S_ISREG(path.lstat().st_mode)
    except OSError:
        return False


def _solve_and_write(job: ClassJob, variant: Variant, scene: str, scene_file: str,
                     folder: Path) -> dict[str, Any]:
    from ..render import write
    from ..studies import solve_text
    from .answer import answer_key, answer_pdf, headline

    # the variant's scene is written in its folder; the data files it names stay the template's
    study = solve_text(scene, scene_file, data_dir=Path(job.template_file).parent)
    solution = getattr(study, "solution", None)
    failures = getattr(solution, "failures", ())
    if failures and solution is not None:   # an assignment must be buildable at every position
        first = failures[0]
        raise MechplanError(Text("batchvars.unbuildable", {
            "failed": str(len(failures)), "total": str(solution.positions),
            "phi": f"{first.phi_deg:g}", "reason": first.reason}), file=scene_file)
    language = job.language or str(parse_toml(scene, scene_file).get("language", "en"))
    sheets = study.sheets(job.size, job.standard, job.language, job.name)
    for sheet in sheets:
        write(sheet, folder, list(job.formats))
    if job.note:
        _write_note(job, variant, scene, scene_file, study, sheets, language, folder)
    key = answer_key(study.to_json(), variant.id, variant.name, variant.values)
    write_atomic(folder / "answer_key.json",
                 json.dumps(key, ensure_ascii=False, indent=1).encode())
    write_atomic(folder / "answer_key.pdf", answer_pdf(key, language))
    return headline(key)


def _write_note(job: ClassJob, variant: Variant, scene: str, scene_file: str, study: Any,
                sheets: list[Any], language: str, folder: Path) -> None:
    """The student's explanatory note (docs/note.md) beside their sheets: the project of one
    study, with the student's name and variant on its title page."""
    from ..note.build import build_note
    from ..note.project import DEFAULT_TRADITION, ROLES, Project
    from ..note.write import note_files
    from ..scene.document import scene_kind

    kind = scene_kind(parse_toml(scene, scene_file), scene_file)
    role = next(r for r, k in ROLES.items() if k == kind)
    lang = language if language in DEFAULT_TRADITION else "en"
    project = Project(file=scene_file, title="", language=lang,
                      tradition=DEFAULT_TRADITION[lang], studies={role: Path(scene_file)},
                      people={"student": variant.name, "variant": variant.id},
                      sheet=job.size)
    note = build_note(project, {role: study}, sheets)
    for name, data in note_files(note, job.name, job.note).items():
        write_atomic(folder / name, data)


def write_summary(path: Path, rows: Sequence[dict[str, Any]]) -> Path:
    """Write the class summary (one row per variant, failed ones with their error) atomically."""
    columns: list[str] = []
    for row in rows:
        columns += [c for c in row if c not in columns]
    buf = io.StringIO()
    writer = csv.DictWriter(buf, columns, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow(csv_safe_row({c: _csv_value(row.get(c, "")) for c in columns}))
    return write_atomic(path, buf.getvalue().encode())


def _csv_value(value: Any) -> Any:
    return f"{value:.10g}" if isinstance(value, float) else value


def run_class(template: str | Path, variants: Sequence[Variant], out_dir: str | Path, *,
              formats: Sequence[str] = ("dxf", "svg", "pdf"), workers: int | None = None,
              scheduler: str | None = None, progress: bool | None = None,
              size: str | None = None, standard: str | None = None,
              language: str | None = None, variants_file: str | None = None,
              note: Sequence[str] = ()) -> ClassResult:
    """Solve and draw every variant of a class; write ``summary.csv`` at the top of ``out_dir``.

    Every key a variant sets is checked against the template first: a key the template does not
    have, a table or a path out of the folder refuses the class (naming ``variants_file``).
    """
    if scheduler:
        check_scheduler(scheduler)
    template = Path(template)
    text = read_text(template)
    doc = parse_toml(text, str(template))
    for variant in variants:
        with_values(doc, variant.values, variants_file)
    out = prepare_output(out_dir)
    job = ClassJob(text, str(template), template.stem, str(out.resolve()),
                   tuple(formats), size, standard, language, tuple(note))
    rows: list[dict[str, Any] | None] = [None] * len(variants)
    skipped = 0
    calls = [(job, v, i) for i, v in enumerate(variants)]
    with locked(out):
        remove_stale(out, (SUMMARY + ".",))
        for index, row, was_skipped in run_tasks(solve_variant, calls, workers=workers,
                                                 scheduler=scheduler, progress=progress,
                                                 desc="variants", unit="variant"):
            rows[index] = row
            skipped += was_skipped
        done = [r for r in rows if r is not None]
        failed = sum(r["status"] != "ok" for r in done)
        summary = write_summary(out / SUMMARY, done)
    return ClassResult(done, len(done) - skipped - failed, skipped, failed, summary)
