"""``mechplan check SCENE_OR_VARIANTS SUBMISSIONS.zip|folder``: the LMS round trip on the command
line (options ``--roster``, ``--worksheet``, ``--rule``)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from .layout import CANVAS, MOODLE, MOODLE_FLAT


def add_arguments(p: Any) -> None:
    """The LMS options of ``mechplan check``."""
    p.add_argument("--roster", metavar="CSV", help="a class roster: Moodle participants export "
                   "or Canvas roster CSV, with a 'variant' column (see docs/classes.md)")
    p.add_argument("--worksheet", metavar="CSV", help="Moodle's offline grading worksheet to "
                   "fill (as downloaded; it is written back with the same columns)")
    p.add_argument("--rule", metavar="TOML", help="the grading rule (default: docs/classes.md)")
    p.add_argument("--gradebook", metavar="CSV", help="Canvas's exported gradebook to fill in "
                   "place (the rule's [canvas] assignment column; everything else kept)")


def wanted(args: argparse.Namespace) -> bool:
    """True when the submission is an LMS download (a zip, a Moodle or Canvas folder) or an
    LMS option was given."""
    sub = Path(args.submission)
    if args.roster or args.worksheet or args.rule or getattr(args, "gradebook", None) \
            or sub.suffix.lower() == ".zip":
        return True
    if sub.is_dir():
        return any(MOODLE.match(e.name) or MOODLE_FLAT.match(e.name) or CANVAS.match(e.name)
                   for e in sub.iterdir())
    return False


def run(args: argparse.Namespace) -> int:
    """Run the round trip; print a line per student, problem and same-work pair."""
    from ..i18n import message, significant
    from .run import round_trip

    lang = args.lang or "en"
    sub = Path(args.submission)
    out = Path(args.output[0]) if args.output else sub.parent / f"{sub.stem}_graded"
    done = round_trip(Path(args.scene), Path(args.submission), out,
                      roster=Path(args.roster) if args.roster else None,
                      worksheet=Path(args.worksheet) if args.worksheet else None,
                      rule=Path(args.rule) if args.rule else None, lang=lang, jobs=args.jobs,
                      gradebook=Path(args.gradebook) if args.gradebook else None)
    for r in done.results:
        grade = "—" if r.grade is None else significant(r.grade, 6, lang)
        print(message("lms.cli.student", lang, student=f"{r.p.name} ({r.p.id})",
                      variant=r.variant or "—", grade=grade))
    for p in done.problems:
        print(message("lms.cli.problem", lang, student=p.who, file=p.file, problem=p.problem))
    for s in done.same:
        evidence = message("lms.evidence." + s.evidence.replace(" ", "_"), lang)
        print(message("lms.cli.same", lang, first=s.first, second=s.second, evidence=evidence,
                      detail=s.detail))
    for path in done.written:
        print(message("check.cli.wrote", lang, path=str(path)), file=sys.stderr)
    return 0 if not done.problems and all(r.grade is not None for r in done.results) else 1

