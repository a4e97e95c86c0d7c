"""The public solve path — numpy and fused (numba) — against a numpy closed form and pylinkage.

Run from a clone with the bench extra (``pip install -e ".[bench,fast]"``):
``python benchmarks/kernel.py [--quick]``; writes ``benchmarks/KERNEL_RESULTS.md``
(``--triads``: only the class III groups' rows, printed and written to their own section of
``benchmarks/RESULTS.md``, in well under a minute). All methods are
timed side by side in one process (best of several runs; this machine is shared and noisy, so read
the ratios, not the absolute times). Like with like: the public path is asked for the case's points
and links only (``solve(points=..., links=...)``, the ``CASES`` of ``mechplan_bench/config.py``):
r, v, a of those points and angle, ω, ε of those links — what the closed form and pylinkage return
for them. The "all" columns solve every point and link of the template, as ``solve()`` does by
default.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import sys
import tempfile
import time
import tracemalloc
from collections.abc import Callable
from functools import partial
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

from _common import RESULTS, write_section
from mechplan_bench.config import CASES
from mechplan_bench.formulas import closed_form
from mechplan_bench.model import Model
from mechplan_bench.peers import installed, pylinkage_runner

import mechplan
from mechplan.construct.kernel import PARALLEL_FROM
from mechplan.construct.kernel_load import spare_cores
from mechplan.fast import numba_available
from mechplan.limits import LimitError

KINEMATIC = ("position", "velocity", "acceleration")


def best(run: Callable[[], object], budget_s: float, max_runs: int = 2000) -> float:
    """Best wall time of back-to-back runs within a time budget (at least 3 runs): a user
    calling ``solve`` once per position in a loop."""
    times: list[float] = []
    start = time.perf_counter()
    while len(times) < 3 or (time.perf_counter() - start < budget_s and len(times) < max_runs):
        t0 = time.perf_counter()
        run()
        times.append(time.perf_counter() - t0)
    return min(times)


def best_of_rounds(runs: dict[str, Callable[[], object] | None], budget_s: float,
                   max_rounds: int = 50) -> dict[str, float]:
    """Each method's best wall time over rounds in which every method runs once, in an order
    turned by one each round, until the budget (per method) is spent (at least 5 rounds).

    Side by side rather than one method after the other: a drift of the machine's load or of
    the allocator's state (freed memory returned and faulted in again) then touches every
    method alike instead of whichever happened to run during it.
    """
    live = [k for k, r in runs.items() if r is not None]
    times: dict[str, list[float]] = {k: [] for k in live}
    start = time.perf_counter()
    rounds = 0
    while live and (rounds < 5 or (time.perf_counter() - start < budget_s * len(live)
                                   and rounds < max_rounds)):
        turn = rounds % len(live)
        for k in live[turn:] + live[:turn]:
            run = runs[k]
            assert run is not None
            t0 = time.perf_counter()
            run()
            times[k].append(time.perf_counter() - t0)
        rounds += 1
    return {k: (min(times[k]) if k in times else math.nan) for k in runs}


def load() -> str:
    """The machine's 1-minute load average (a shared machine: read the ratios)."""
    return f"{os.getloadavg()[0]:.2f}"


def numba_version() -> str:
    import numba

    return str(numba.__version__)


def threads() -> str:
    import numba

    return f"{numba.get_num_threads()} threads"


def peak_mib(run: Callable[[], object]) -> float:
    """Peak traced memory of one run (numpy allocations are traced), MiB."""
    tracemalloc.start()
    run()
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return peak / 2**20


#: mechanisms with a class III group: no closed form nor pylinkage peer, numpy against fused only
TRIADS = ("six_bar_triad", "six_bar_triad_slider")


def triad_rows(ns: tuple[int, ...], rounds: int) -> list[str]:
    """The public path, numpy and fused, on the mechanisms with a class III group (every point
    and link, as ``solve()`` by default): a table in Markdown. CPU time of the process (not the
    wall: on a loaded machine a run's wall time counts the other processes' turns), the least
    over ``rounds`` rounds that run both paths in turn."""
    lines = [("| mechanism | N | first call (JIT compile) | public numpy | public fused "
              "| fused / numpy |"), "|---|---|---|---|---|---|"]
    for name in TRIADS:
        m = mechplan.load(ROOT / "templates" / f"{name}.toml")
        t0 = time.perf_counter()
        m.solve(phi_deg=[10.0], plans=KINEMATIC, fast=True)          # compile (or load the cache)
        first = time.perf_counter() - t0
        for n in ns:
            phi_deg = np.linspace(0.0, 360.0, n, endpoint=False)
            t = {"numpy": math.inf, "fused": math.inf}
            calls = max(1, 1000 // n)                       # N = 1: a thousand calls
            for _ in range(rounds):
                for k, least in t.items():
                    t0 = time.process_time()
                    for _ in range(calls):
                        m.solve(phi_deg=phi_deg, plans=KINEMATIC, fast=k == "fused")
                    t[k] = min(least, (time.process_time() - t0) / calls)
            scale, unit = (1e6, " µs") if n == 1 else (1e9 / n, "")
            lines.append(f"| {name} | {n:,} | {first:.2f} s | {t['numpy'] * scale:.1f}{unit} | "
                         f"{t['fused'] * scale:.1f}{unit} | {t['fused'] / t['numpy']:.3f}× |")
            print(lines[-1], flush=True)
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true", help="N up to 1e5, shorter budgets")
    ap.add_argument("--triads", action="store_true",
                    help="only the class III groups' rows (N up to 1e4, short budgets)")
    args = ap.parse_args()
    if not numba_available():
        raise SystemExit("install the fast extra: pip install -e '.[fast]'")
    os.environ.setdefault("MECHPLAN_CACHE", tempfile.mkdtemp(prefix="mechplan-kernels-"))
    if args.triads:
        rows = triad_rows((1, 1_000, 10_000), 3)
        write_section("kernel_triads", "Compiled construction: class III groups",
                      f"Generated by `python benchmarks/kernel.py --triads` ({platform.machine()}, "
                      f"{os.cpu_count()} cores shared, numba {numba_version()}; load average "
                      f"{load()} at the end). Times per position in ns (N = 1: per call in µs), "
                      "every point and link on the three plans; CPU time of the process, the "
                      "least of 3 rounds (read the ratios).\n\n" + "\n".join(rows))
        return
    ns = (1, 1_000, 100_000) if args.quick else (1, 1_000, 100_000, 1_000_000)
    budget = 0.5 if args.quick else 2.0
    lines = ["# Compiled construction: the public path against peers", "",
             f"Machine: {platform.machine()}, {os.cpu_count()} cores (shared), Python "
             f"{platform.python_version()}, numpy {np.__version__}, numba {numba_version()} "
             f"({threads()}). Times per position in ns "
             "(N = 1: per call in µs, best of back-to-back calls), otherwise best of rounds in one "
             "process (each round runs every method once, in turn). Load average "
             "(1 min) at the start of the run: " + load() + "; at its end: LOAD_AT_END.", "",
             ("Like with like: numpy and fused are `Mechanism.solve(phi_deg, plans=kinematics, "
             "points=case.points, links=case.links)` — r, v, a of the case's points and angle, "
             "ω, ε of its links, as the closed form and pylinkage compute them (points and links: "
             "`benchmarks/mechplan_bench/config.py` CASES). The \"all\" columns are the default "
             "`solve()`: every point and link of the template. ‡: the fused kernel ran on "
             "numba's threads (from 20 000 positions, when the load average left a spare core "
             "as the row began); unmarked rows ran on one thread."), "",
             ("| mechanism | N | public numpy | public fused | public numpy (all) | "
             "public fused (all) | closed form (numpy) | pylinkage+numba | fused / closed form "
             "| fused / pylinkage | numpy / closed form |"),
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    compile_rows = []
    memory_rows = []
    over_budget: list[str] = []
    for name in ("four_bar", "slider_crank", "v_engine"):
        case = CASES[name]
        model = Model.load(case)
        m = mechplan.load(ROOT / "templates" / f"{name}.toml")
        t0 = time.perf_counter()
        m.solve(phi_deg=[10.0], plans=KINEMATIC, fast=True)          # compile (or load the cache)
        first = time.perf_counter() - t0
        m.solve(phi_deg=[10.0], plans=KINEMATIC, fast=True, points=case.points, links=case.links)
        m2 = mechplan.load(ROOT / "templates" / f"{name}.toml")
        t0 = time.perf_counter()
        m2.solve(phi_deg=[10.0], plans=KINEMATIC, fast=True)         # from the on-disk cache
        cached = time.perf_counter() - t0
        compile_rows.append(f"| {name} | {first:.2f} s | {cached * 1e3:.1f} ms |")
        for n in ns:
            phi = model.phi(n)
            phi_deg = np.degrees(phi)
            few = {"points": case.points, "links": case.links}
            runs: dict[str, Callable[[], object] | None] = {
                "numpy": partial(m.solve, phi_deg=phi_deg, plans=KINEMATIC, fast=False, **few),
                "fused": partial(m.solve, phi_deg=phi_deg, plans=KINEMATIC, fast=True, **few),
                "numpy_all": partial(m.solve, phi_deg=phi_deg, plans=KINEMATIC, fast=False),
                "fused_all": partial(m.solve, phi_deg=phi_deg, plans=KINEMATIC, fast=True),
                "closed": closed_form(model, phi),
                "pylinkage": pylinkage_runner(model, phi) if installed("pylinkage") and n > 1
                else None,
            }
            for k, r in list(runs.items()):
                try:
                    if r is not None:
                        r()
                except LimitError:            # over the default memory budget (2 GB): not run
                    runs[k] = None
                    over_budget.append(f"{name}, N = {n:,}: public {k.replace('_', ' (')}"
                                       f"{')' if '_' in k else ''}")
            threaded = n >= PARALLEL_FROM and spare_cores() >= 1.5
            if n == 1:      # one call: back to back, as a loop over single positions runs
                t = {k: (best(r, budget) if r is not None else math.nan)
                     for k, r in runs.items()}
            else:
                t = best_of_rounds(runs, budget)
            scale = 1e6 if n == 1 else 1e9 / n
            unit = " µs" if n == 1 else ""

            def cell(x: float, scale: float = scale, unit: str = unit, n: int = n) -> str:
                if math.isnan(x):
                    return "—"
                return f"{x * scale:.1f}{unit}" if n == 1 else f"{x * scale:.0f}"

            def ratio(a: float, b: float) -> str:
                return "—" if math.isnan(a) or math.isnan(b) else f"{a / b:.2f}×"
            mark = " ‡" if threaded else ""
            lines.append(f"| {name} | {n:,} | {cell(t['numpy'])} | {cell(t['fused'])}{mark} | "
                         f"{cell(t['numpy_all'])} | {cell(t['fused_all'])}{mark} | "
                         f"{cell(t['closed'])} | {cell(t['pylinkage'])} | "
                         f"{ratio(t['fused'], t['closed'])} | {ratio(t['fused'], t['pylinkage'])} "
                         f"| {ratio(t['numpy'], t['closed'])} |")
            print(lines[-1], flush=True)
            if n == ns[-1]:
                peaks = " | ".join("—" if runs[k] is None else f"{peak_mib(runs[k]):.0f} MiB"
                                   for k in ("fused", "numpy", "fused_all", "numpy_all"))
                memory_rows.append(f"| {name} | {n:,} | {peaks} |")
    lines += ["", "## Class III groups (no closed form, no pylinkage peer)", "",
              *triad_rows(ns[:3], 5)]
    lines += ["", "## Compile time of the fused kernel", "",
              ("| mechanism | first call (JIT compile) "
               "| new process, same mechanism (on-disk cache) |"),
              "|---|---|---|", *compile_rows,
              "", ("The kernel source is written to the cache folder (`MECHPLAN_CACHE`, default "
              "`~/.cache/mechplan/kernels`) and compiled with `numba.njit(cache=True)`, so other "
              "processes load it instead of compiling; the table's second column is a fresh "
              "`Mechanism` in the same process reading that cache."),
              "", "## Peak memory at the largest N (tracemalloc)", "",
              ("| mechanism | N | public fused | public numpy | public fused (all) | "
              "public numpy (all) |"), "|---|---|---|---|---|---|", *memory_rows,
              "",
              ("The fused path allocates only the requested outputs: one (N, width) block "
              "(two columns a point, one a scalar) and the angles; the estimates are bounded in "
              "the kernel's loop (one product of the divisors a position's estimates are divided "
              "by), evaluated only where that bound does not show them below the tolerance, and "
              "stored only when some result is flagged. From 20 000 positions the kernel runs on "
              "numba's threads when the load leaves a spare core (‡). The numpy path keeps the "
              "values of every step the requested "
              "outputs need; their estimates are propagated only when one bound of them all does "
              "not show them below the tolerance.")]
    if over_budget:
        lines += ["", "Not run (—): over the default memory budget of 2 GB "
                  "(`MECHPLAN_MEMORY_BUDGET`), refused before any work: "
                  + "; ".join(over_budget) + "."]
    out = ROOT / "benchmarks" / "KERNEL_RESULTS.md"
    text = ("\n".join(lines) + "\n").replace("LOAD_AT_END", load())
    out.write_text(text, encoding="utf-8")
    # the same figures as a section of RESULTS.md, beside the other benchmarks
    write_section("kernel", "Compiled construction: the public path against peers",
                  text.split("\n", 1)[1].replace("\n## ", "\n### "))
    print(f"written {out} and the section of {RESULTS}")


if __name__ == "__main__":
    main()
