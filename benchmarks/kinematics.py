#!/usr/bin/env python
"""Kinematics engine benchmark (issue 2): the construction against the numpy closed form.

The construction engine on the slider-crank, the four-bar and the V-engine at N = 1, 360 and
100 000 positions, beside the hand-written vectorised numpy closed form of the same slider-crank and
four-bar, in one run: time per position and max relative error against the 40-digit mpmath reference
(tests/independent/mpref.py). Writes the section "Kinematics engine" of benchmarks/RESULTS.md::

    python benchmarks/kinematics.py
"""

from __future__ import annotations

import argparse
import sys
import time

from _common import bench, goals_block, machine_block, tables_by_mechanism, write_section


def main(argv: list[str] | None = None) -> int:
    """Run and write the section."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--no-write", action="store_true", help="print only")
    args = p.parse_args(argv)
    cfg = bench.Config(cases=("slider_crank", "four_bar", "v_engine"), ns=(1, 360, 100_000),
                       methods=("exact float64", "numpy closed form"), steady_allocator=True)
    t0 = time.time()
    rows = bench.run_benchmark(cfg, log=lambda m: print(m, file=sys.stderr, flush=True))
    print(bench.format_table(rows))
    goals = [g for g in goals_block(rows).splitlines() if "pylinkage" not in g]
    for g in goals:
        print(g)
    if args.no_write:
        return 0
    body = f"""
{machine_block()}
- command: `python benchmarks/kinematics.py` ({time.time() - t0:.0f} s)

Goals of issue 2 (measured in this run):

{chr(10).join(goals)}

"exact float64" evaluates the construction graph (`Construction.evaluate` → `evaluate_all` of the
compared points' r, v, a and the links' ω, ε); "numpy closed form" is
`tests/independent/closed_form.py`. Errors are relative to the largest magnitude of each kind over
the cycle, against the 40-digit reference, on every position up to N = 360 and on 50 evenly spread
positions at N = 100 000; see "Speed against error" for the method, the timing rules and the other
methods.

{tables_by_mechanism(rows)}
"""
    write_section("kinematics", "Kinematics engine", body)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
