"""The ``mechplan check`` subcommand."""

from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .. import i18n
from ..check.texts import LANGUAGES, T
from ..errors import CheckError, SceneError, elide
from ..model.plans import Plan
from ..units import example
from . import angle_deg

if TYPE_CHECKING:
    from ..check.report import Tolerance

#: a plan by its name or the letter of its scale factor ("velocity", "v")
PLAN_NAMES = {name: p for p in Plan for name in (p.value, p.scale_key[3:].lower())}
TEXT_SUFFIXES = (".txt", ".md", ".log", ".text")
#: largest tolerance per unit: a sheet's length, everything, a turn
def _tolerance_max(unit: str) -> float:
    from ..limits import MAX_PAPER_MM

    return {"mm": MAX_PAPER_MM, "%": 100.0, "deg": 360.0}[unit]
#: most processes ``--jobs`` may ask for (joblib refuses more than a million with a traceback)
MAX_JOBS = 1024


def add_parser(subparsers: Any) -> None:
    """Register ``mechplan check`` on the main parser's subparsers."""
    p = subparsers.add_parser(
        "check", help="check a hand-drawn plan (DXF) or a table of values against the exact one",
        description="Compare a submission with the exact construction: a DXF with the lines "
        "and labels of the plans, or a TOML/CSV table of measured lengths and values. Exit "
        "code 0: everything checked is right; 1: something is wrong; 2: unusable input.")
    p.add_argument("scene", help="the scene (TOML) the submission solves")
    p.add_argument("submission", help="a .dxf drawing, or a .toml / .csv table; or a folder of "
                   "them (a class: then SCENE may be a folder of variants, a submission is "
                   "matched to the variant named in its file name, -o is the output folder)")
    p.add_argument("--at", type=angle_deg, metavar="DEG",
                   help="crank angle φ of the submission in degrees (default: written on the "
                   "submission, the scene's only position, or the best fit of its positions)")
    p.add_argument("--tolerance", action="append", default=[], metavar="[PLAN=]SPEC",
                   help="allowed error: '1mm', '2%%', '1mm,2%%', '1.5deg'; per plan with "
                   "'velocity=0.5mm,1%%' (default ±1 mm or ±2 %%, whichever is larger)")
    for plan in Plan:
        p.add_argument("--" + plan.scale_key.replace("_", "-"), metavar="MU",
                       dest=plan.scale_key.lower(),
                       help=f"scale factor of the {plan.value} plan per mm of paper, e.g. "
                       f"{example(plan.scale_dimension)} (overrides the sheet)")
    p.add_argument("--label-distance", type=float, metavar="MM",
                   help="how far (mm) a label may stand from its point (default: twice the "
                   "text height, 3…10 mm)")
    p.add_argument("--snap", type=float, default=0.2, metavar="MM",
                   help="line ends closer than this (mm) are one point (default 0.2)")
    p.add_argument("-o", "--output", action="append", default=[], metavar="FILE",
                   help="write the report: .json, .txt, or an overlay sheet .svg / .dxf / .pdf "
                   "(may be repeated)")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("-j", "--jobs", "--workers", dest="jobs", type=int, default=1, metavar="N",
                   help="a class: check N submissions at once (joblib; -1: every core); "
                   "--workers is the same option")
    p.add_argument("--lang", choices=LANGUAGES, default=None,
                   help="language of the report, its hints and the overlay's notes: en, ru, vi "
                   "or zh (default: the scene's language); ru and vi write a decimal comma")
    from ..lms.cli import add_arguments

    add_arguments(p)
    p.set_defaults(func=run)


def parse_tolerances(specs: list[str]) -> dict[Plan | None, Tolerance]:
    """'1mm,2%' → default; 'velocity=0.5mm' → per plan (unset parts keep the defaults)."""
    from ..check.report import Tolerance

    out: dict[Plan | None, Tolerance] = {}
    for spec in specs:
        plan: Plan | None = None
        body = spec
        m = re.match(r"^\s*([A-Za-z]+)\s*[=:]\s*(.*)$", spec)
        if m:
            name = m.group(1).lower()
            if name not in PLAN_NAMES:
                raise CheckError(T("error.tolerance_plan", spec=spec, plan=m.group(1)))
            plan, body = PLAN_NAMES[name], m.group(2)
        base = out.get(plan) or out.get(None) or Tolerance()
        given: dict[str, Any] = {"mm": base.mm, "%": base.pct, "deg": base.deg}
        parts = [x for x in re.split(r"[,\s;]+", body.strip()) if x]
        if not parts:
            raise CheckError(T("error.tolerance_empty", spec=spec))
        for part in parts:
            pm = re.fullmatch(r"(\d+(?:[.,]\d+)?)\s*(mm|%|deg|°)", part.lower())
            if not pm:
                raise CheckError(T("error.tolerance_part", spec=spec, part=part))
            unit, value = pm.group(2).replace("°", "deg"), float(pm.group(1).replace(",", "."))
            high = _tolerance_max(unit)
            if not value <= high:       # a tolerance of 10^400 mm would pass anything
                raise CheckError(T("error.option_range", option=f"--tolerance {elide(spec, 60)}",
                                   low="0", high=f"{high:g} {unit}", value=elide(part, 60)))
            given[unit] = value
        out[plan] = Tolerance(given["mm"], given["%"], given["deg"])
    return out


def parse_scales(args: argparse.Namespace) -> dict[Plan, float]:
    """Scale factors given on the command line."""
    from ..submission.labels import parse_mu

    out: dict[Plan, float] = {}
    for plan in Plan:
        text, option = getattr(args, plan.scale_key.lower(), None), f"--mu-{plan.scale_key[3:]}"
        if text is None:
            continue
        try:
            value = parse_mu(text, plan)
        except SceneError as exc:
            raise CheckError(T("error.mu_option", option=option,
                               text=text, detail=exc.detail)) from None
        if not value > 0:
            raise CheckError(T("error.positive", option=option, value=text))
        out[plan] = value
    return out


def run(args: argparse.Namespace) -> int:
    """Run a check; print the report; write the requested files. 0 passed, 1 errors found.

    A :class:`CheckError` is said in the report's language (``--lang`` or the scene's)."""
    said = {"lang": args.lang or "en"}
    try:
        return _run(args, said)
    except CheckError as exc:
        if isinstance(exc.detail, i18n.Text) and said["lang"] != "en":
            raise CheckError(exc.detail.tr(said["lang"]), file=exc.file, key=exc.key) from None
        raise


def _run(args: argparse.Namespace, said: dict[str, str]) -> int:
    from ..check.grade import Options, check
    from ..check.overlay import write_overlay

    outputs = [Path(o) for o in args.output]
    many = Path(args.submission).is_dir() or Path(args.submission).suffix.lower() == ".zip"
    for o in outputs if not many else ():
        if o.suffix.lower() not in (".json", ".svg", ".dxf", ".pdf", *TEXT_SUFFIXES):
            raise CheckError(T("error.output_kind", path=str(o)))
    if args.label_distance is not None and not args.label_distance > 0:
        raise CheckError(T("error.positive", option="--label-distance", value=args.label_distance))
    if not (args.jobs == -1 or 1 <= args.jobs <= MAX_JOBS):
        raise CheckError(T("error.option_range", option="--jobs", low="1", high=str(MAX_JOBS),
                           value=str(args.jobs)))
    from ..limits import MAX_PAPER_MM

    if not args.snap >= 0:
        raise CheckError(T("error.not_negative", option="--snap", value=args.snap))
    for option, value in (("--label-distance", args.label_distance), ("--snap", args.snap)):
        if value is not None and not value <= MAX_PAPER_MM:     # also inf (nan fails above)
            raise CheckError(T("error.option_range", option=option, low="0", value=str(value),
                               high=f"{MAX_PAPER_MM:g} mm"))
    options = Options(at_deg=args.at, tolerance=parse_tolerances(args.tolerance),
                      mu=parse_scales(args), label_distance=args.label_distance, snap=args.snap)
    from ..lms import cli as lms

    if lms.wanted(args):                    # a Moodle or Canvas download (docs/classes.md)
        return lms.run(args)
    if Path(args.submission).is_dir():
        return _run_class(args, options)
    from ..check.answers import maybe_check_answers
    from ..scene import load_scene
    from ..scene.document import study_kind

    found = study_kind(args.scene)
    if found is not None:                   # a dynamics, engine, cam or gear study
        lang = getattr(args, "lang", None) or str(found[1].get("language", "en"))
        said["lang"] = lang if lang in LANGUAGES else "en"
        report = maybe_check_answers(args.scene, args.submission, options)
    if found is None or report is None:
        scene = load_scene(args.scene)
        lang = getattr(args, "lang", None) or scene.language or "en"
        said["lang"] = lang if lang in LANGUAGES else "en"
        report = check(scene, args.submission, options)
    lang = said["lang"]
    doc = report.to_json(lang)
    text = report.text(lang)
    for o in outputs:
        suffix = o.suffix.lower()
        if suffix == ".json":
            _write(o, (json.dumps(doc, ensure_ascii=False, indent=1) + "\n").encode("utf-8"))
        elif suffix in TEXT_SUFFIXES:
            _write(o, (text + "\n").encode("utf-8"))
        else:
            write_overlay(report, o, lang)
    if args.json:
        print(json.dumps(doc, ensure_ascii=False, indent=1))
    else:
        print(text)
    for o in outputs:
        print(T("cli.wrote", path=str(o)).tr(lang), file=sys.stderr)
    return 0 if report.passed else 1


def _run_class(args: argparse.Namespace, options: Any) -> int:
    """Check a folder of submissions; one report per student and summary.csv."""
    from ..batch.check_class import check_class

    folder = Path(args.submission)
    out = Path(args.output[0]) if args.output else folder / "checked"
    lang = args.lang or "en"
    rows = check_class(Path(args.scene), folder, out, options, lang, args.jobs)
    for r in rows:
        if r.get("error"):
            print(T("class.unusable", student=r["student"], error=r["error"]).tr(lang))
        else:
            print(T("class.row", student=r["student"], scene=r["scene"],
                    verdict=T("report.passed" if r["passed"] else "report.failed"),
                    wrong=r["wrong"], slip=r["slip"]).tr(lang))
    print(T("cli.wrote", path=str(out / "summary.csv")).tr(lang), file=sys.stderr)
    return 0 if all(r.get("passed") for r in rows) else 1


def _write(path: Path, data: bytes) -> None:
    from ..check.overlay import write_bytes

    write_bytes(path, data)
