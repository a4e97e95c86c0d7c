"""Time `mechplan draw templates/v_engine.toml` (DXF + SVG + PDF of a full A1 sheet), start-up
included.

Writes the section "Drawing a sheet" of RESULTS.md. Goal (issue 4): < 3 s on this machine.
"""

from __future__ import annotations

import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from _common import ROOT, machine_block, write_section

RUNS = 7


def main() -> None:
    """Run the CLI in fresh processes and record best, median and worst wall times."""
    times = []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(RUNS):
            t0 = time.perf_counter()
            subprocess.run([sys.executable, "-m", "mechplan.cli", "draw",
                            str(ROOT / "templates" / "v_engine.toml"), "-o", out,
                            "--format", "dxf,svg,pdf"], check=True, capture_output=True,
                           cwd=ROOT)
            times.append(time.perf_counter() - t0)
            shutil.rmtree(out, ignore_errors=True)
    best, median, worst = min(times), statistics.median(times), max(times)
    verdict = "**met**" if median < 3.0 else "**not met**"
    body = f"""{machine_block()}
- command: `python benchmarks/draw.py` ({RUNS} fresh processes of
  `mechplan draw templates/v_engine.toml -o DIR --format dxf,svg,pdf`, start-up included)

| runs | best | median | worst |
|---|---|---|---|
| {RUNS} | {best:.2f} s | {median:.2f} s | {worst:.2f} s |

Goal of issue 4, a full A1 sheet (position plan with extreme positions and trajectories, velocity
and acceleration plans, three force polygons, Zhukovsky's lever, all tables) as DXF + SVG + PDF in
< 3 s including start-up: {verdict} (median {median:.2f} s).
"""
    write_section("draw", "Drawing a sheet", body)
    print(body)


if __name__ == "__main__":
    main()
