"""Command line: mechplan solve | draw | check | bench | batch | sweep | new."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from .errors import MechplanError


def _solve(args: argparse.Namespace) -> int:
    from .studies import solve_file
    from .studies.mechanism import MechanismStudy

    study = solve_file(args.scene, at_deg=args.at, count=args.positions)
    if args.json:
        print(json.dumps(study.to_json(), ensure_ascii=False, indent=1))
    else:
        print(study.report(args.lang))
    if args.stats and isinstance(study, MechanismStudy):
        sol = study.solution
        print(f"steps: {len(sol.construction.steps)} in the construction, "
              f"{sol.ev.evaluated} evaluated for {sol.positions} position(s)", file=sys.stderr)
    return 0


def _draw(args: argparse.Namespace) -> int:
    from .render import write
    from .studies import solve_file

    formats = [f.strip() for f in args.format.split(",") if f.strip()]
    for path in args.scenes:
        study = solve_file(path)
        sheets = study.sheets(args.sheet, args.standard, args.lang, Path(path).stem)
        out = Path(args.output)
        out.mkdir(parents=True, exist_ok=True)
        for sheet in sheets:
            for written in write(sheet, out, formats):
                print(written)
    return 0


def _new(args: argparse.Namespace) -> int:
    templates = Path(__file__).resolve().parent / "templates"
    src = templates / f"{args.template}.toml"
    if not src.exists():
        names = ", ".join(sorted(p.stem for p in templates.glob("*.toml")))
        raise MechplanError(f"unknown template {args.template!r}; templates are {names}")
    dest = Path(args.output or f"{args.template}.toml")
    if dest.exists():
        raise MechplanError(f"{dest} exists already; choose another name with -o")
    dest.write_text(src.read_text(encoding="utf-8"), encoding="utf-8")
    print(dest)
    return 0


def parser() -> argparse.ArgumentParser:
    """The argument parser."""
    p = argparse.ArgumentParser(prog="mechplan", description="Graphical method of planar "
                                "mechanism analysis, constructed step by step.")
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("solve", help="structure, plans, construction protocol and results")
    s.add_argument("scene")
    s.add_argument("--at", type=float, nargs="+", metavar="DEG", help="crank angles φ in degrees")
    s.add_argument("--positions", type=int, metavar="N", help="N equal steps from the scene's start")
    s.add_argument("--lang", choices=("en", "ru", "vi", "zh"))
    s.add_argument("--json", action="store_true", help="one JSON document, SI units")
    s.add_argument("--stats", action="store_true", help="print step counts to stderr")
    s.set_defaults(func=_solve)
    d = sub.add_parser("draw", help="draw the sheet: DXF, SVG, PDF, PNG")
    d.add_argument("scenes", nargs="+", metavar="SCENE")
    d.add_argument("-o", "--output", default=".", help="output folder (default: .)")
    d.add_argument("--format", default="dxf,svg,pdf", help="comma-separated: dxf,svg,pdf,png")
    d.add_argument("--sheet", choices=("A0", "A1", "A2", "A3", "A4"))
    d.add_argument("--lang", choices=("en", "ru", "vi", "zh"))
    d.add_argument("--standard", choices=("iso", "gost", "tcvn"))
    d.set_defaults(func=_draw)
    from .batch.cli import add_parser as add_batch
    from .bench import add_parser as add_bench
    from .check.cli import add_parser as add_check

    add_check(sub)
    add_bench(sub)
    add_batch(sub)
    n = sub.add_parser("new", help="start a scene from a bundled template")
    n.add_argument("template")
    n.add_argument("-o", "--output")
    n.set_defaults(func=_new)
    return p


def main(argv: list[str] | None = None) -> int:
    """Entry point; user errors print one message and exit with code 2."""
    args = parser().parse_args(argv)
    try:
        return int(args.func(args))
    except MechplanError as exc:
        print(f"mechplan: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:          # output piped into `head`
        sys.stderr.close()
        return 0


if __name__ == "__main__":
    raise SystemExit(main())
