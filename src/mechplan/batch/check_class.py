"""A class at once: every submission of a folder checked against its variant, one report per
student and a summary table (``summary.csv``), on the batch engine (joblib workers)."""

from __future__ import annotations

import csv
import io
import json
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..check.grade import Options, check
from ..check.texts import T
from ..errors import CheckError, MechplanError
from ..render.atomic import write_atomic
from .csvsafe import csv_safe_row
from .engine import run_tasks
from .outdir import prepare_output

SUFFIXES = (".dxf", ".toml", ".csv", ".tsv")
COLUMNS = ("student", "submission", "scene", "phi_deg", "passed", "checked", "ok", "wrong", "new",
           "carried", "swapped", "accumulated", "slip", "missing", "findings", "error")


@dataclass(frozen=True, slots=True)
class Student:
    """One submission of a class and the scene (variant) it is checked against."""

    name: str
    submission: Path
    scene: Path | None


def variant_of(submission: Path, scenes: list[Path]) -> Path | None:
    """The scene whose file name is a word of the submission's name ("ivanov_v07.dxf" →
    "v07.toml"; the longest wins); the only scene when there is one."""
    if len(scenes) == 1:
        return scenes[0]
    named = [s for s in scenes if re.search(rf"(?:^|[\W_]){re.escape(s.stem)}(?:$|[\W_])",
                                            submission.stem, re.IGNORECASE)]
    return max(named, key=lambda s: len(s.stem)) if named else None


def students(scene: Path, folder: Path) -> list[Student]:
    """The submissions of a folder with their variants (``scene`` is a file or a folder)."""
    scenes = sorted(scene.glob("*.toml")) if scene.is_dir() else [scene]
    if not scenes:
        raise CheckError(T("error.no_variants"), file=str(scene))
    # a symlink is listed (it fails, unread: it may point at any file of the machine)
    subs = sorted(p for p in folder.iterdir() if (p.is_symlink() or p.is_file())
                  and p.suffix.lower() in SUFFIXES
                  and p.resolve() not in {s.resolve() for s in scenes})
    if not subs:
        raise CheckError(T("error.no_submissions"), file=str(folder))
    return [Student(p.stem, p, variant_of(p, scenes)) for p in subs]


def _one(i: int, st: Student, options: Options, lang: str,
         out: Path) -> tuple[int, dict[str, Any]]:
    row: dict[str, Any] = {"student": st.name, "submission": st.submission.name,
                           "scene": st.scene.name if st.scene else ""}
    if st.submission.is_symlink():
        row["error"] = T("class.symlink", name=st.submission.name).tr(lang)
        return i, row
    if st.scene is None:
        row["error"] = T("class.no_variant", name=st.submission.name).tr(lang)
        return i, row
    try:
        report = check(st.scene, st.submission, options)
    except MechplanError as exc:      # an unusable submission is a row of the summary
        row["error"] = str(exc)
        return i, row
    write_atomic(out / f"{st.name}.txt", (report.text(lang) + "\n").encode("utf-8"))
    write_atomic(out / f"{st.name}.json", (json.dumps(report.to_json(lang), ensure_ascii=False,
                                                      indent=1) + "\n").encode("utf-8"))
    summary = report.summary()
    phi = round(report.phi_deg, 4) if math.isfinite(report.phi_deg) else ""   # answer tables
    row |= {"phi_deg": phi, "passed": report.passed,
            **{k: summary.get(k, "") for k in COLUMNS if k in summary}}
    return i, row


def check_class(scene: Path, folder: Path, out: Path, options: Options, lang: str = "en",
                jobs: int = 1) -> list[dict[str, Any]]:
    """Check every submission of ``folder``; write ``out/<student>.txt|.json`` and
    ``out/summary.csv``; return the summary rows."""
    class_ = students(scene, folder)
    out = prepare_output(out)
    calls = [(i, st, options, lang, out) for i, st in enumerate(class_)]
    done = dict(run_tasks(_one, calls, workers=jobs if jobs > 0 else None, progress=False))
    rows = [done[i] for i in range(len(calls))]
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=COLUMNS, restval="", lineterminator="\n")
    writer.writeheader()
    writer.writerows(csv_safe_row(r) for r in rows)
    write_atomic(out / "summary.csv", buf.getvalue().encode("utf-8"))
    return list(rows)
