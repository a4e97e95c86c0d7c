#!/usr/bin/env python
"""Speed against error (issue 6): every method, every mechanism, N = 1, 12, 360, 100 000.

Writes the section "Speed against error" of ``benchmarks/RESULTS.md`` and the log–log scatter
``benchmarks/speed_error.png``. Run from the repository root::

    python benchmarks/speed_error.py            # full run, a few minutes
    python benchmarks/speed_error.py --quick    # the reduced run of `bench.py --quick`
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time

from _common import (
    HERE,
    ROOT,
    bench,
    goals_block,
    machine_block,
    tables_by_mechanism,
    write_section,
)

PNG = HERE / "speed_error.png"

MODEL_TEXT = f"""\
**How errors are measured.** The reference is `tests/independent/mpref.py`: the loop-closure
equations of each mechanism solved by Newton's method at 40 significant digits, velocities and
accelerations by mpmath differentiation of that position solution (not the project's plans). For
each kind of quantity — positions r, velocities v and accelerations a of the compared points, ω and
ε of the compared links — the error is the largest vector difference from the reference over the
compared positions, divided by the largest magnitude of that kind over {bench.SCALE_POSITIONS}
positions of the cycle (so a velocity that passes through zero at a dead centre does not make the
error meaningless). "max rel. error" is the largest of the kinds a method gives. Up to N = 360 every
position is compared; at N = 100 000 a deterministic subsample of 50 evenly spread positions
(indices `round(linspace(0, N−1, 50))`), because the mpmath reference costs 10–45 ms per position.
Positions are φ = {bench.PHI0} rad + 2πk/N in each scene's own convention; none of the four
mechanisms has a singular position, so all of them are "regular positions".

**Timing.** `time.perf_counter`, best of k runs in one process (k ≥ 7 and ≥ 0.5 s of runs, fewer
only for runs longer than 2 s), after the model is built: the construction graph (scene → steps),
the pylinkage `Linkage` and its numba compilation, the `mechanism` objects are all set up outside
the timed call. What is timed computes, for all N positions, the positions, velocities and
accelerations of the compared points (and ω, ε where the method has them). The process keeps freed
heap memory (glibc `mallopt(M_TRIM_THRESHOLD = 1 GiB, M_MMAP_THRESHOLD = 32 MiB)`) so that every
method is timed in steady state rather than paying first-touch page faults whose count depends on
what the process allocated before; the "cold allocator" table below shows the effect.

**Methods.**
- *exact float64 / float32*: the construction graph evaluated lazily and vectorised
  (`Construction.evaluate(phi, dtype)`); float32 carries every step in single precision.
- *ruler 0.5 mm / 0.1 mm*: the same construction drawn at the scale factors the sheet would use (the
  scene's fixed μ, or the round μ that fits the largest segment of each plan in 150 mm / 120 mm) and
  carried on as a student carries measured segments: every point placed on a plan (crank pin,
  compass meet, image on the velocity or acceleration plan, end of a normal or Coriolis component)
  is measured from the point its segment starts at, its length is rounded to the ruler's precision
  and its direction to the angle whose arc at that length is the same precision (the end moves at
  most half a step sideways), and everything after it — lines through it, meets, ω and ε computed
  from measured segments — is built from the rounded point (`mechplan_bench.RulerEvaluation`). Frame
  points and poles are exact. Rounding is deterministic (nearest), so this is one realisation of a
  careful drawing, not an average over students.
- *finite differences*: positions from the construction, v and a by central differences in φ with
  steps h_v = {bench.FD_STEP_V:g} rad and h_a = {bench.FD_STEP_A:g} rad (near the optimum (3ε)^(1/3)
  and (48ε)^(1/4) for double precision), ω and ε the same way from the link angles; all five φ grids
  are evaluated in one vectorised call.
- *λ-series*: the engine formulas x = r cos θ + l − λr(1 − cos 2θ)/4, v = −rω(sin θ + λ/2 sin 2θ),
  a = −rω²(cos θ + λ cos 2θ), λ = r/l (central slider-crank, piston B only).
- *numpy closed form*: `tests/independent/closed_form.py`, hand-written vectorised formulas for the
  slider-crank and the four-bar (the speed baseline of the goals).
- *pylinkage*: `Linkage.step_fast_with_kinematics`, positions, velocities and accelerations of the
  joints (pylinkage has no link ω, ε output). Slider joints are `RRPDyad`s on a frame line, the
  coupler point, the lug D and the coulisse point B are `FixedDyad`s (B as the point 600 mm from O3
  on the line O3→A — the coulisse turns with the slider, so the shaper needs no prismatic pair on a
  moving guide). pylinkage advances the crank step by step (θ ← atan2(current) + Δθ) and keeps the
  nearest solution, so its k-th position is θ0 + kΔθ up to accumulated rounding, which is part of
  its measured error. "no numba" runs the same code with `NUMBA_DISABLE_JIT=1` in a child process
  (numba cannot be switched off inside a process that has imported it).
- *mechanism (fsolve)*: the `mechanism` package: vector loop equations solved by
  `scipy.optimize.fsolve` at each position, three solves per position (position, velocity,
  acceleration) in a Python loop. Modelled for the slider-crank (points A, B, link 2) and the
  four-bar (points B, C, links 2, 3; the package has no rigid coupler point without an extra
  hand-written loop). Not run at N = 100 000 (its cost per position is flat; the N = 360 row gives
  it)."""


def cold_allocator(n: int) -> list[dict]:
    """Exact float64 and the closed form at N in a fresh child process without the allocator
    setting."""
    code = ("import json, sys; from mechplan import bench\n"
            f"cfg = bench.Config(cases=('slider_crank', 'four_bar'), ns=({n},), "
            "methods=('exact float64', 'numpy closed form'), steady_allocator=False)\n"
            "rows = bench.run_benchmark(cfg)\n"
            "print(json.dumps([{'mechanism': r.mechanism, 'method': r.method, "
            "'ns': r.ns_per_position} for r in rows]))")
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                          timeout=600, check=False)
    if proc.returncode:
        return []
    return json.loads(proc.stdout.strip().splitlines()[-1])


def scatter(rows: list[bench.Row], path=PNG) -> None:
    """Log–log scatter of time per position against max relative error."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    big = max(r.n for r in rows)
    mid = max((r.n for r in rows if r.n < big), default=big)
    methods = list(dict.fromkeys(r.method for r in rows if r.repeats))
    cmap = plt.get_cmap("tab10")
    colour = {m: cmap(i % 10) for i, m in enumerate(methods)}
    markers = dict(zip(bench.CASES, ("o", "s", "^", "D")))
    floor = 1e-17
    fig, ax = plt.subplots(figsize=(9, 6.5), dpi=120)
    for r in rows:
        if not r.repeats or r.n not in (big, mid) or not math.isfinite(r.max_error):
            continue
        filled = r.n == big
        ax.scatter(r.ns_per_position, max(r.max_error, floor), s=46 if filled else 30,
                   marker=markers.get(r.mechanism, "o"),
                   facecolors=colour[r.method] if filled else "none",
                   edgecolors=colour[r.method], linewidths=1.2, zorder=3)
    for m in methods:
        ax.scatter([], [], color=colour[m], label=m)
    for name, mk in markers.items():
        ax.scatter([], [], marker=mk, facecolors="none", edgecolors="0.3", label=name)
    ax.axhline(1e-13, color="0.5", lw=0.8, ls="--")
    ax.annotate("goal: 1e-13", xy=(0.01, 1.4e-13), xycoords=("axes fraction", "data"),
                color="0.4", fontsize=8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per position (ns)")
    ax.set_ylabel("max relative error vs 40-digit reference")
    ax.set_title(f"mechplan: speed against error (filled N = {big:,}, hollow N = {mid:,})")
    ax.grid(True, which="major", lw=0.4, alpha=0.6)
    ax.legend(fontsize=7.5, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def profile_block(n: int) -> str:
    """Markdown: where the exact float64 evaluation spends its time at N positions."""
    lines = [("| mechanism | steps evaluated | ns/position (sum of steps) "
              "| top operations (share) |"),
             "|---|---|---|---|"]
    for name, case in bench.CASES.items():
        model = bench.Model.load(case)
        prof = bench.profile(model, n)
        total = sum(t for _, _, t in prof)
        steps = sum(k for _, k, _ in prof)
        top = ", ".join(f"{op} ×{k} {t / total:.0%}" for op, k, t in prof[:5])
        lines.append(f"| {name} | {steps} | {total / n * 1e9:,.0f} | {top} |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """Run, write RESULTS.md's section and the PNG."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="the reduced run")
    p.add_argument("--no-write", action="store_true", help="print only")
    args = p.parse_args(argv)
    cfg = bench.quick_config() if args.quick else bench.Config()
    cfg.steady_allocator = True
    t0 = time.time()
    rows = bench.run_benchmark(cfg, log=lambda m: print(m, file=sys.stderr, flush=True))
    big = max(cfg.ns)
    print("profiling", file=sys.stderr, flush=True)
    prof = profile_block(big)
    print("cold allocator child", file=sys.stderr, flush=True)
    cold = cold_allocator(big)
    warm = {(r.mechanism, r.method): r.ns_per_position for r in rows if r.n == big and r.repeats}
    elapsed = time.time() - t0
    print(bench.format_table(rows))
    if args.no_write:
        return 0
    scatter(rows)
    cold_lines = [("| mechanism | method | steady allocator ns/position | fresh process, default "
                   "allocator ns/position |"), "|---|---|---|---|"]
    for c in cold:
        w = warm.get((c["mechanism"], c["method"]))
        cold_lines.append(f"| {c['mechanism']} | {c['method']} | "
                          f"{'—' if w is None else f'{w:,.0f}'} | {c['ns']:,.0f} |")
    body = f"""
{machine_block()}
- command: `python benchmarks/speed_error.py{' --quick' if args.quick else ''}` ({elapsed:.0f} s)

![speed against error](speed_error.png)

### Goals (measured in this run)

{goals_block(rows)}

{MODEL_TEXT}

### Where the exact evaluation spends its time (N = {big:,}, steady allocator)

Each step timed on its own, best of 5, summed per operation:

{prof}

### Cold allocator

The same two methods at N = {big:,} in a fresh child process with glibc's default allocator
settings (freed memory returned to the kernel and faulted in again on the next run):

{chr(10).join(cold_lines)}

### Results (time per position; relative errors by kind; "compared" = positions checked)

{tables_by_mechanism(rows)}
"""
    write_section("speed_error", "Speed against error", body)
    print(f"wrote {HERE / 'RESULTS.md'} and {PNG}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
