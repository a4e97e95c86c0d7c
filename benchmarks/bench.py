#!/usr/bin/env python
"""Speed against error of every method, printed to the terminal (formerly ``mechplan bench``).

Needs the repository (the independent references in ``tests/independent``), so it is not an
installed command. Run from anywhere in a clone::

    python benchmarks/bench.py --quick [--mechanism four_bar] [--json]
"""

from __future__ import annotations

import argparse
import sys

from _common import bench


def main(argv: list[str] | None = None) -> int:
    """Parse the arguments and run the benchmark."""
    parser = argparse.ArgumentParser(prog="benchmarks/bench.py")
    sub = parser.add_subparsers(dest="command")
    bench.add_parser(sub)
    args = parser.parse_args(["bench", *(argv if argv is not None else sys.argv[1:])])
    return int(bench.run(args))


if __name__ == "__main__":
    raise SystemExit(main())
