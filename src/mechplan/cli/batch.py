"""The ``mechplan batch`` and ``mechplan sweep`` subcommands."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ..drafting.fields import SHEETS, STANDARDS
from ..errors import MechplanError
from ..i18n import LANGUAGES, Text


def _engine_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("-j", "--jobs", "--workers", dest="workers", type=int, metavar="N",
                   help="worker processes (default: one per core; on a cluster: its threads); "
                   "--workers is the same option")
    p.add_argument("--scheduler", metavar="tcp://HOST:8786",
                   help="run on a Dask distributed cluster instead of local processes")
    bar = p.add_mutually_exclusive_group()
    bar.add_argument("--progress", dest="progress", action="store_true", default=None,
                     help="show a progress bar (default: only on a terminal)")
    bar.add_argument("--no-progress", dest="progress", action="store_false")


def add_parser(subparsers: Any) -> None:
    """Register ``mechplan batch`` and ``mechplan sweep``."""
    b = subparsers.add_parser(
        "batch", help="a class: per student a folder with the scene, sheets and answer key",
        description="Write one folder per variant (named by its id) with the scene, its sheets "
        "and answer_key.json/.pdf, and summary.csv at the top. Re-running skips complete "
        "folders. Exit code 0: every variant solved; 1: some failed (see summary.csv).")
    b.add_argument("template", help="the scene every variant starts from (TOML)")
    b.add_argument("variants", help="a .csv (id, name, key columns) or .toml (students, rules)")
    _engine_options(b)
    b.add_argument("--format", default="dxf,svg,pdf", help="sheet formats: dxf,svg,pdf,png")
    b.add_argument("--sheet", choices=SHEETS)
    b.add_argument("--standard", choices=STANDARDS)
    b.add_argument("--lang", choices=LANGUAGES)
    b.add_argument("--note", action="store_true",
                   help="also each student's explanatory note (DOCX and PDF; docs/note.md)")
    b.set_defaults(func=_batch)
    s = subparsers.add_parser(
        "sweep", help="a design space: summaries of every variant of a grid over the cycle",
        description="Evaluate every combination of the varied keys at N crank positions and "
        "write summary.parquet and summary.csv (one row per variant: max |v|, |a| of points, "
        "max |ω|, |ε| of links, min transmission angle of RRR/RRP groups, max |M_b|).")
    s.add_argument("scene", help="a mechanism scene (TOML)")
    s.add_argument("--vary", action="append", required=True, metavar="KEY=FROM..TO:STEPS",
                   help="a varied key, e.g. links.1.lengths.AB=60mm..100mm:9 (repeatable)")
    s.add_argument("--positions", type=int, default=360, metavar="N",
                   help="crank positions over the cycle (default 360)")
    s.add_argument("--chunk", type=int, metavar="VARIANTS",
                   help="variants per task (default: about 0.15 s of work)")
    s.add_argument("--plot", metavar="SUMMARY", help="plot a summary column, e.g. min_gamma_2_3")
    s.add_argument("--plot-axes", metavar="KEY1,KEY2",
                   help="the two varied keys of the plot (default: the first two)")
    _engine_options(s)
    s.set_defaults(func=_sweep)


def _interrupted() -> int:
    from ..batch.texts import say

    print(f"mechplan: {say('interrupted')}", file=sys.stderr)
    return 130


def _batch(args: argparse.Namespace) -> int:
    from ..batch.klass import run_class
    from ..batch.variants import read_variants

    if args.workers is not None and args.workers < 1:
        raise MechplanError(Text("batchvars.jobs", {"value": str(args.workers)}))
    variants = read_variants(args.variants)
    formats = [f.strip() for f in args.format.split(",") if f.strip()]
    try:
        result = run_class(args.template, variants, args.output, formats=formats,
                           workers=args.workers, scheduler=args.scheduler,
                           progress=args.progress, size=args.sheet, standard=args.standard,
                           language=args.lang, variants_file=args.variants,
                           note=("docx", "pdf") if args.note else ())
    except KeyboardInterrupt:
        return _interrupted()
    print(f"{result.summary}: {result.solved} solved, {result.skipped} complete already, "
          f"{result.failed} failed")
    return 1 if result.failed else 0


def _sweep(args: argparse.Namespace) -> int:
    from ..batch.plan import parse_vary
    from ..batch.sweep import run_sweep

    if args.workers is not None and args.workers < 1:
        raise MechplanError(Text("batchvars.jobs", {"value": str(args.workers)}))
    axes = [parse_vary(v) for v in args.vary]
    plot_axes = [k.strip() for k in args.plot_axes.split(",")] if args.plot_axes else None
    try:
        result = run_sweep(args.scene, axes, args.output, positions=args.positions,
                           workers=args.workers, scheduler=args.scheduler,
                           progress=args.progress, chunk=args.chunk, plot=args.plot,
                           plot_axes=plot_axes)
    except KeyboardInterrupt:
        return _interrupted()
    print(f"{result.parquet}, {result.csv}: {result.variants} variants in {result.chunks} "
          f"chunks ({result.skipped_chunks} complete already)")
    if result.plot:
        print(result.plot)
    return 0
