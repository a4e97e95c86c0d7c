"""``python benchmarks/bench.py``: the subcommand's parser and its entry point."""

from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any

import mechplan_bench as bench

from .config import CASES


def add_parser(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``python benchmarks/bench.py`` on the CLI's subparsers."""
    b = subparsers.add_parser("bench", help="speed against error of every method, against a "
                              "40-digit reference")
    b.add_argument("--quick", action="store_true", help="N = 1, 12, 10 000; fewer repeats")
    b.add_argument("--mechanism", nargs="+", choices=sorted(CASES), metavar="NAME",
                   help=f"only these ({', '.join(CASES)})")
    b.add_argument("--json", action="store_true", help="rows as one JSON document")
    b.set_defaults(func=run)
    return b


def run(args: argparse.Namespace) -> int:
    """Run the benchmark for the CLI; print the table (progress goes to stderr).

    The package's names are looked up at call time, so that substitutes set on
    ``mechplan_bench`` (as the tests do) are the ones used.
    """
    cfg = bench.quick_config() if args.quick else bench.Config()
    if getattr(args, "mechanism", None):
        cfg.cases = tuple(args.mechanism)
    cfg.steady_allocator = True
    rows = bench.run_benchmark(cfg, log=lambda msg: print(msg, file=sys.stderr, flush=True))
    if getattr(args, "json", False):
        def num(x: float) -> float | str:
            return x if math.isfinite(x) else str(x)
        doc = {"machine": bench.machine(), "rows": [
            {"mechanism": r.mechanism, "method": r.method, "n": r.n, "seconds": num(r.seconds),
             "repeats": r.repeats, "compared": r.compared, "note": r.note,
             "ns_per_position": num(r.ns_per_position), "max_error": num(r.max_error),
             "errors": {k: num(v) for k, v in r.errors.items()}} for r in rows],
            "goals": [{"goal": g, "met": m, "detail": d} for g, m, d in bench.goals(rows)]}
        print(json.dumps(doc, ensure_ascii=False, indent=1, default=float))
        return 0
    print(bench.format_table(rows))
    print()
    for goal, met, detail in bench.goals(rows):
        print(f"{'met' if met else 'NOT met' if met is False else 'not measured'}: "
              f"{goal} ({detail})")
    return 0
