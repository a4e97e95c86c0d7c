"""Latency of the commands and of one solve call (issue 35), cold and warm, in one run.

Cold: a new process per command (`mechplan --version`, `--help`, `solve TEMPLATE`, `draw
TEMPLATE` at A1 in DXF, SVG and PDF), best and median of a few runs. Warm: `Mechanism.solve` at one
position with its default outputs (every point, link and kinematic plan) in a loaded process,
against pylinkage building the same linkage and stepping it once (its "build-and-step"), best of
back-to-back calls. Writes the section "Latency" of RESULTS.md.

    python benchmarks/latency.py [--runs 5]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _common import ROOT, machine_block, write_section

#: goals of issue 35 (seconds, or a ratio to pylinkage)
GOALS = {"--version": 0.3, "--help": 0.3, "solve": 1.0, "draw": 2.0}
PER_CALL_RATIO = 0.15


def _mechplan() -> list[str]:
    exe = shutil.which("mechplan", path=str(Path(sys.executable).parent))
    return [exe] if exe else [sys.executable, "-m", "mechplan.cli"]


def cold(args: list[str], runs: int) -> tuple[float, float]:
    """Best and median wall time (s) of a new process running ``mechplan ARGS``."""
    times = []
    env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "0"}
    for _ in range(runs + 1):                      # the first run warms the file cache only
        t0 = time.perf_counter()
        subprocess.run([*_mechplan(), *args], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, env=env)
        times.append(time.perf_counter() - t0)
    times = times[1:]
    return min(times), statistics.median(times)


def best_call(fn, repeat: int = 200) -> float:
    """Best time (s) of ``fn()`` over back-to-back calls."""
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


KINEMATIC = ("position", "velocity", "acceleration")


def warm_rows() -> list[tuple[str, float, float, float | None]]:
    """(template, default call s, kinematic-plans call s, pylinkage build-and-step s) at 10°."""
    import math

    from mechplan_bench.config import CASES
    from mechplan_bench.model import Model
    from mechplan_bench.peers import _pylinkage_linkage, installed

    import mechplan

    rows = []
    for name in ("four_bar", "slider_crank", "v_engine"):
        m = mechplan.load(ROOT / "templates" / f"{name}.toml")
        m.solve(10.0)                                   # compile or load the kernel once
        m.solve(10.0, plans=KINEMATIC)
        ours = best_call(lambda m=m: m.solve(10.0))
        kinematic = best_call(lambda m=m: m.solve(10.0, plans=KINEMATIC))
        theirs = None
        if installed("pylinkage"):
            model = Model.load(CASES[name])
            theta = float(model.theta(model.phi(1))[0])
            omega = model.scene.mechanism.drive.omega

            def build_and_step(theta: float = theta, omega: float = omega,
                               case: object = CASES[name]) -> None:
                linkage, _ = _pylinkage_linkage(case, theta, 2 * math.pi, omega)
                linkage.step_fast_with_kinematics(iterations=1)

            linkage, _ = _pylinkage_linkage(CASES[name], theta, 2 * math.pi, omega)
            linkage.compile()                           # numba compilation outside the timing
            theirs = best_call(build_and_step, repeat=50)
        rows.append((name, ours, kinematic, theirs))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    runs = parser.parse_args().runs
    started = time.perf_counter()
    with tempfile.TemporaryDirectory() as out:
        template = str(ROOT / "templates" / "four_bar.toml")
        commands = {"--version": ["--version"], "--help": ["--help"],
                    "solve": ["solve", template], "draw": ["draw", template, "-o", out]}
        measured = {k: cold(v, runs) for k, v in commands.items()}
    warm = warm_rows()
    load = os.getloadavg()[0]
    lines = [machine_block(), f"- load average (1 min) at the end: {load:.2f}",
             (f"- command: `python benchmarks/latency.py --runs {runs}` "
             f"({time.perf_counter() - started:.0f} s)"), "",
             "### Cold commands (a new process each; four_bar template, A1, dxf+svg+pdf)", "",
             "| command | goal | best | median | goal met (median) |", "|---|---|---|---|---|"]
    for k, (best, median) in measured.items():
        goal = GOALS[k]
        verdict = "met" if median <= goal else f"NOT met ({median / goal:.2f}× the goal)"
        lines.append(f"| `mechplan {' '.join(commands[k][:1])}` | < {goal:g} s | {best:.2f} s "
                     f"| {median:.2f} s | {verdict} |")
    lines += ["", "### One solve call in a loaded process (φ = 10°, default outputs)", "",
              ("The default call of a scene with masses or loads includes its force plan (the "
              "numpy path; pylinkage computes no forces); the kinematic call asks for the plans "
              "pylinkage computes. pylinkage's build-and-step: its `Linkage` of the same "
              "dimensions built and stepped once with kinematics (numba compiled beforehand)."), "",
              ("| template | `solve(10.0)` (default) | `solve(10.0, plans=kinematic)` | pylinkage "
              f"build-and-step | ratio (kinematic) | goal ≤ {PER_CALL_RATIO}× |"),
              "|---|---|---|---|---|---|"]
    for name, ours, kinematic, theirs in warm:
        if theirs is None:
            lines.append(f"| {name} | {ours * 1e6:.1f} µs | {kinematic * 1e6:.1f} µs | — | — | "
                         "not measured |")
            continue
        ratio = kinematic / theirs
        verdict = "met" if ratio <= PER_CALL_RATIO else f"NOT met ({ratio / PER_CALL_RATIO:.1f}×)"
        lines.append(f"| {name} | {ours * 1e6:.1f} µs | {kinematic * 1e6:.1f} µs | "
                     f"{theirs * 1e6:.1f} µs | {ratio:.2f}× | {verdict} |")
    body = "\n".join(lines)
    write_section("latency", "Latency (issue 35)", body)
    print(body)


if __name__ == "__main__":
    main()
