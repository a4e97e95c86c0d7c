"""Command line: mechplan solve | draw | check | batch | sweep | new | doctor | completion."""

from __future__ import annotations

import argparse
import json
import os
import sys
from importlib import resources
from pathlib import Path

from .. import __version__
from ..drafting.fields import SHEETS, STANDARDS
from ..errors import MechplanError, shown
from ..i18n import LANGUAGES, Text

#: exit code of a run that completed but flagged results or left positions out (see README)
FLAGGED = 3


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"must be a whole number ≥ 1 (got {shown(text)})") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a whole number ≥ 1 (got {shown(text)})")
    return value


_DATA_DIR_HELP = ("folder of the data files a scene names (an indicator table), which must lie "
                  "inside it; default: the scene's folder")


def angle_deg(text: str) -> float:
    """An ``--at`` angle: a finite number of degrees within the limit (argparse type)."""
    from ..limits import LimitError, check_angle_deg

    try:
        return check_angle_deg(float(text))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"must be a number of degrees (got {shown(text)})") from None
    except LimitError as exc:
        raise argparse.ArgumentTypeError(exc.detail) from None


#: a report of more positions than this is first measured on one position (see below)
REPORT_PROBE_FROM = 2000


def _ensure_report_fits(args: argparse.Namespace) -> None:
    """Refuse, before solving, a linkage report (JSON or text) of more positions than the memory
    budget holds: one position is solved and its JSON measured (well under a second)."""
    from ..scene.document import parse_toml, read_text, scene_kind

    text = read_text(args.scene)
    if args.at or scene_kind(parse_toml(text, args.scene), args.scene) != "mechanism":
        return
    from ..limits import ensure_report_within_budget
    from ..scene import parse_scene
    from ..solve import position_count
    from ..studies import solve_text

    n = position_count(parse_scene(text, args.scene), args.positions)
    if n <= REPORT_PROBE_FROM:
        return
    probe = solve_text(text, args.scene, count=1, data_dir=args.data_dir)
    first = probe.to_json()["positions"][0]
    ensure_report_within_budget(n, len(json.dumps(first, ensure_ascii=False, indent=1)),
                                file=args.scene,
                                key="--positions" if args.positions else "positions.count")


def _solve(args: argparse.Namespace) -> int:
    from ..studies import solve_file
    from ..studies.mechanism import MechanismStudy

    _ensure_report_fits(args)
    study = solve_file(args.scene, at_deg=args.at, count=args.positions, data_dir=args.data_dir)
    if isinstance(study, MechanismStudy) and (args.sheet or args.standard):
        # the scale factors (μ, segment lengths) of the sheet `mechplan draw --sheet` draws
        from ..solve import choose_scales

        sol = study.solution
        sol.scales = choose_scales(sol.scene, sol.construction, sol.ev, sol.plans, args.sheet,
                                   args.standard)
        sol.extras["sheet"] = (args.sheet, args.standard)
    if not isinstance(study, MechanismStudy) and (args.answers or args.pin_radius is not None):
        raise MechplanError(Text("batchvars.answers_kind", {"scene": str(args.scene)}))
    if isinstance(study, MechanismStudy) and (args.answers or args.pin_radius is not None):
        from ..textbook_report import attach, spec_from_flags

        sol = study.solution
        attach(sol, spec_from_flags(args.answers or "rubbing", args.pin_radius, sol.scene.textbook))
    if args.json:
        print(json.dumps(study.to_json(), ensure_ascii=False, indent=1))
    else:
        print(study.report(args.lang))
    if args.csv:
        write_csv = getattr(study, "write_csv", None)
        if write_csv is None:
            raise MechplanError(Text("errors.cli.csv", {"scene": str(args.scene)}))
        write_csv(args.csv)
    warnings = study.warnings(args.lang) if hasattr(study, "warnings") else []
    for line in warnings:
        print(line, file=sys.stderr)
    if isinstance(study, MechanismStudy):        # scale factors not as the scene asks
        for line in study.scale_notes(args.lang):
            print(f"mechplan: warning: {line}", file=sys.stderr)
    if args.stats and isinstance(study, MechanismStudy):
        sol = study.solution
        print(f"steps: {len(sol.construction.steps)} in the construction, "
              f"{sol.ev.evaluated} evaluated for {sol.positions} position(s)", file=sys.stderr)
    return FLAGGED if warnings else 0


def _draw(args: argparse.Namespace) -> int:
    """Draw every scene; a failing one is reported and the others are still drawn."""
    from ..outputs import prepare_dir
    from ..render import FORMATS, write
    from ..studies import solve_file

    formats = [f.strip().lower() for f in args.format.split(",") if f.strip()]
    unknown = [f for f in formats if f not in (*FORMATS, "html")]
    if unknown or not formats:
        raise MechplanError(Text("errors.cli.format", {"formats": ", ".join((*FORMATS, "html")),
                                                       "value": repr(args.format)}))
    page = "html" in formats                   # the live page (docs/html.md)
    formats = [f for f in formats if f != "html"]
    if args.system_fonts:
        from ..drafting.fonts import ENV_SYSTEM_FONTS

        os.environ[ENV_SYSTEM_FONTS] = "1"     # read by every font look-up of this process
    out = prepare_dir(args.output)
    failed = 0
    progress = len(args.scenes) > 1 and sys.stderr.isatty()
    for i, path in enumerate(args.scenes, start=1):
        if progress:
            print(f"mechplan: [{i}/{len(args.scenes)}] {path}", file=sys.stderr, flush=True)
        try:
            study = solve_file(path, data_dir=args.data_dir)
            for sheet in study.sheets(args.sheet, args.standard, args.lang,
                                      Path(path).stem) if formats else ():
                for written in write(sheet, out, formats):
                    print(written)
            if page:
                from ..live_page import write_page

                print(write_page(study, out, Path(path).stem, size=args.sheet,
                                 standard=args.standard, language=args.lang))
            for line in getattr(study, "warnings", lambda _lang: [])(args.lang):
                print(line, file=sys.stderr)          # positions left out, poor estimates
            scale_notes = getattr(study, "scale_notes", None)   # μ not as the scene asks
            for line in scale_notes(args.lang, args.sheet, args.standard) if scale_notes else ():
                print(f"mechplan: warning: {line}", file=sys.stderr)
            extra = getattr(study, "write_files", None)     # e.g. a cam's profile DXF
            if extra is not None and "dxf" in formats:
                for written in extra(out, Path(path).stem):
                    print(written)
        except MechplanError as exc:
            failed += 1
            print(say_error(exc, error_language(args, path)), file=sys.stderr)
    if failed and len(args.scenes) > 1:
        from ..i18n import message

        print(message("errors.cli.scenes_failed", error_language(args), failed=failed,
                      total=len(args.scenes)), file=sys.stderr)
    return 2 if failed else 0


def _project(args: argparse.Namespace) -> int:
    from ..note.project import run_project

    formats = tuple(f.strip().lower() for f in args.format.split(",") if f.strip())
    known = ("docx", "pdf", "svg", "dxf", "png")
    if not formats or any(f not in known for f in formats):
        raise MechplanError(Text("errors.cli.format", {"formats": ", ".join(known),
                                                       "value": repr(args.format)}))
    for path in run_project(args.project, args.output, formats):
        print(path)
    return 0


def template_names() -> list[str]:
    """Names of the bundled templates (without ``.toml``)."""
    folder = resources.files("mechplan") / "templates"
    return sorted(p.name.removesuffix(".toml") for p in folder.iterdir()
                  if p.name.endswith(".toml"))


def _template_text(name: str) -> str:
    stem = name.removesuffix(".toml")
    names = template_names()
    if stem not in names:
        raise MechplanError(Text("errors.cli.template", {"names": ", ".join(names),
                                                         "value": repr(name)}))
    return (resources.files("mechplan") / "templates" / f"{stem}.toml").read_text(
        encoding="utf-8")


def _new(args: argparse.Namespace) -> int:
    if args.list:
        for name in template_names():
            print(name)
        return 0
    if not args.template:
        raise MechplanError(Text("errors.cli.name_template"))
    text = _template_text(args.template)
    name = f"{Path(args.template).name.removesuffix('.toml')}.toml"
    dest = Path(args.output or name)
    # "-o sub/" (a trailing separator) or an existing folder: write into that folder
    into = bool(args.output) and args.output.endswith(("/", os.sep))
    if into or dest.is_dir():
        if dest.exists() and not dest.is_dir():
            raise MechplanError(Text("errors.cli.not_folder", {"path": str(dest),
                                                               "output": args.output}))
        try:
            dest.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            from ..errors import os_reason

            said = Text("errors.cli.cannot_create", {"path": str(dest), "reason": os_reason(exc)})
            raise MechplanError(said) from None
        dest = dest / name
    if dest.exists():
        raise MechplanError(Text("errors.cli.exists", {"path": str(dest)}))
    from ..render.atomic import write_atomic

    write_atomic(dest, text.encode("utf-8"))
    print(dest)
    return 0


def _doctor(args: argparse.Namespace) -> int:
    from ..doctor import report

    print(report())
    return 0


def _completion(args: argparse.Namespace) -> int:
    from ..completion import bash_script

    print(bash_script(parser(), template_names()))
    return 0


def parser() -> argparse.ArgumentParser:
    """The argument parser."""
    p = argparse.ArgumentParser(prog="mechplan", description="Graphical method of planar "
                                "mechanism analysis, constructed step by step.")
    p.add_argument("--version", action="version", version=f"mechplan {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    s = sub.add_parser("solve", help="structure, plans, construction protocol and results")
    s.add_argument("scene")
    where = s.add_mutually_exclusive_group()
    where.add_argument("--at", type=angle_deg, nargs="+", metavar="DEG",
                       help="crank angles φ in degrees (a cylinder or slider driver: its "
                       "length in mm)")
    where.add_argument("--positions", type=_positive_int, metavar="N",
                       help="N ≥ 1 equal steps from the scene's start")
    s.add_argument("--lang", choices=LANGUAGES)
    s.add_argument("--json", action="store_true", help="one JSON document, SI units")
    s.add_argument("--stats", action="store_true", help="print step counts to stderr")
    s.add_argument("--csv", metavar="PATH",
                   help="write the per-angle table (engine scenes) as CSV")
    s.add_argument("--sheet", choices=SHEETS,
                   help="scale factors of this sheet size (as `draw --sheet`)")
    s.add_argument("--standard", choices=STANDARDS,
                   help="scale factors of this standard's sheet (as `draw --standard`)")
    s.add_argument("--data-dir", metavar="DIR", help=_DATA_DIR_HELP)
    s.add_argument("--answers", metavar="LIST",
                   help="textbook answers: all or relative,rubbing,transmission,stroke,"
                        "least_velocity (docs/textbook.md)")
    s.add_argument("--pin-radius", type=float, metavar="MM",
                   help="radius of every pin in mm, for the rubbing velocities")
    s.set_defaults(func=_solve)
    d = sub.add_parser("draw", help="draw the sheet: DXF, SVG, PDF, PNG",
                       description="Draw the sheets of one or more scenes. A scene that fails is "
                       "reported and the others are still drawn; the exit code is 2 if any "
                       "failed.")
    d.add_argument("scenes", nargs="+", metavar="SCENE")
    d.add_argument("-o", "--output", default=".", help="output folder (default: .)")
    d.add_argument("--format", default="dxf,svg,pdf",
                   help="comma-separated: dxf,svg,pdf,png,html (html: the live page)")
    d.add_argument("--sheet", choices=SHEETS)
    d.add_argument("--lang", choices=LANGUAGES)
    d.add_argument("--standard", choices=STANDARDS)
    d.add_argument("--data-dir", metavar="DIR", help=_DATA_DIR_HELP)
    d.add_argument("--system-fonts", action="store_true",
                   help="measure and embed the system's fonts (e.g. a full CJK font) instead of "
                   "the bundled ones; the sheet then depends on the machine")
    d.set_defaults(func=_draw)
    pr = sub.add_parser("project", help="a course project: every study's sheets and the note",
                        description="Solve the studies a project file names and write their "
                        "sheets and the explanatory note (DOCX, PDF) into the output folder.")
    pr.add_argument("project", metavar="PROJECT.toml")
    pr.add_argument("-o", "--output", default=".", help="output folder (default: .)")
    pr.add_argument("--format", default="docx,pdf,svg,dxf",
                    help="comma-separated: docx,pdf (the note; pdf also the sheets),svg,dxf,png")
    pr.set_defaults(func=_project)
    from .batch import add_parser as add_batch
    from .check import add_parser as add_check
    from .synth import add_parser as add_synth

    add_check(sub)
    add_batch(sub)
    add_synth(sub)
    names = template_names()
    n = sub.add_parser("new", help="start a scene from a bundled template",
                       description="Copy a bundled template to start a scene.",
                       epilog="templates: " + ", ".join(names))
    n.add_argument("template", nargs="?", help="a template name (with or without .toml)")
    n.add_argument("-o", "--output", help="file or folder to write (default: TEMPLATE.toml)")
    n.add_argument("--list", action="store_true", help="list the templates and exit")
    n.set_defaults(func=_new)
    dr = sub.add_parser("doctor", help="report fonts, viewers and optional extras found")
    dr.set_defaults(func=_doctor)
    c = sub.add_parser("completion", help="print a shell completion script",
                       description="Print a completion script: eval \"$(mechplan completion "
                       "bash)\", or save it in ~/.local/share/bash-completion/completions/"
                       "mechplan.")
    c.add_argument("shell", choices=("bash",))
    c.set_defaults(func=_completion)
    return p


def error_language(args: argparse.Namespace, scene: str | None = None) -> str:
    """The language errors are said in: ``--lang``, else the ``language`` of the scene (by
    default the command's first) when it can be read, else English."""
    lang = getattr(args, "lang", None)
    if lang in LANGUAGES:
        return str(lang)
    scene = scene or getattr(args, "scene", None) or (getattr(args, "scenes", None) or [None])[0]
    if isinstance(scene, str):
        try:
            from ..scene.document import parse_toml, read_text

            said = parse_toml(read_text(scene), scene).get("language")
        except MechplanError:
            said = None
        if said in LANGUAGES:
            return str(said)
    return "en"


def say_error(exc: MechplanError, language: str) -> str:
    """``mechplan: error: …`` in a language."""
    from ..i18n import message

    return message("errors.cli.error", language, message=exc.text(language))


def main(argv: list[str] | None = None) -> int:
    """Entry point; user errors print one message (in the scene's language or ``--lang``) and
    exit with code 2; with ``--json`` the error is also a JSON object on standard output."""
    args = parser().parse_args(argv)
    try:
        return int(args.func(args))
    except MechplanError as exc:
        lang = error_language(args)
        print(say_error(exc, lang), file=sys.stderr)
        if getattr(args, "json", False):
            print(json.dumps(exc.to_json(lang), ensure_ascii=False, indent=1))
        return 2
    except BrokenPipeError:          # output piped into `head`
        sys.stderr.close()
        return 0
    except KeyboardInterrupt:
        print("mechplan: interrupted", file=sys.stderr)
        return 130

