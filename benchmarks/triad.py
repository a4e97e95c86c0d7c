"""Cost of a class III group (triad) against a class II group (dyad) per position (issue 29).

Run: ``python benchmarks/triad.py [N]`` (default 100 000 positions); writes the section "Class III
group against a dyad" of ``benchmarks/RESULTS.md``.

- numpy path: each kinematic step's evaluation (position, velocity and acceleration plans) is timed
  and summed by the group it belongs to, on the six-bar with a triad (``six_bar_triad.toml``) and
  the four-bar (``four_bar.toml``, its RRR dyad); the triad's closure (``triad_angle``) is shown
  apart. Two sums per group: every step of the group, and its construction proper — without the
  points a link carries that are no pair of the group (centres of mass S2…S5 of the six-bar,
  the coupler point E of the four-bar: each costs the same similarity steps in any group, and the
  two mechanisms carry different numbers of them).
- fused kernel (numba, one thread): the kernel of every point and link on the three plans less the
  kernel of the crank's point alone, for each mechanism — the group's share of the fused loop.

Times are the process's CPU time (``time.process_time``: on a shared machine the time the process
was not running is not counted; the page faults of fresh arrays are). Each numpy measurement runs
in a fresh process, so both mechanisms are measured in the same state of memory — a group's
cost depended on the other's before (the four-bar's arrays fit in memory the allocator had kept
from an earlier evaluation, the six-bar's did not and paid the first touch of every page):

- cold: the first evaluation of the process (as a user's one run: every fresh array's pages
  touched for the first time are counted);
- warm: the second evaluation, the allocator told to keep freed memory (``MALLOC_TRIM_THRESHOLD_``,
  ``MALLOC_MMAP_THRESHOLD_``): the arithmetic alone.

The rounds alternate the two mechanisms and each ratio is the median over rounds of the ratio
within a round (both measured under the same load).
"""

from __future__ import annotations

import json
import math
import os
import statistics
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from _common import machine_block, write_section

from mechplan.construct import graph
from mechplan.construct.graph import Construction
from mechplan.scene import load_scene
from mechplan.solve import build, targets_for

ROOT = HERE.parent / "templates"
KINEMATIC = ("position", "velocity", "acceleration")
ROUNDS = 7
GROUPS = {"six_bar_triad": "III(2,3,4,5)", "four_bar": "II(2,3)"}
MODES = ("cold", "warm")
SIMILAR = ("similar_position", "similar_image")
clock = time.process_time


def construction(stem: str) -> tuple[Construction, set[str]]:
    """The mechanism's kinematic construction and the steps that place a point of a link that is
    no pair (a point in one link only) by similarity."""
    scene = load_scene(ROOT / f"{stem}.toml")
    _, c = build(scene, KINEMATIC)
    count: dict[str, int] = defaultdict(int)
    for link in scene.mechanism.links.values():
        for name in link.points:
            count[name] += 1
    extra = {s.id for s in c.steps.values() if s.op.value in SIMILAR
             and count.get(s.id.split(".", 1)[1], 0) == 1}
    return c, extra


def numpy_times(stem: str, c: Construction, extra: set[str], phi: np.ndarray, warm: bool
                ) -> dict[str, float]:
    """CPU seconds spent evaluating the group's steps at the positions ``phi`` (the first
    evaluation, or ``warm`` the second): all of them (``group``), without the extra points
    (``own``), the triad's closure alone (``closure``)."""
    spent: dict[str, float] = defaultdict(float)
    original = graph.Evaluation._compute

    def timed(self: graph.Evaluation, step: object) -> None:
        t0 = clock()
        original(self, step)  # type: ignore[arg-type]
        dt = clock() - t0
        if step.group == GROUPS[stem]:  # type: ignore[attr-defined]
            spent["group"] += dt
            if step.id not in extra:  # type: ignore[attr-defined]
                spent["own"] += dt
        if step.op.value == "triad_angle":  # type: ignore[attr-defined]
            spent["closure"] += dt

    if warm:
        c.evaluate(phi).evaluate_all(list(c.steps))
    graph.Evaluation._compute = timed  # type: ignore[method-assign]
    try:
        ev = c.evaluate(phi)
        ev.evaluate_all(list(c.steps))
    finally:
        graph.Evaluation._compute = original  # type: ignore[method-assign]
    return dict(spent)


def kernel_runner(stem: str, phi: np.ndarray, crank_only: bool):
    """A serial run of the compiled kernel of the mechanism's kinematics (or of its crank's point
    alone) at ``phi``."""
    from mechplan.construct.kernel import compile_kernel

    scene = load_scene(ROOT / f"{stem}.toml")
    _, c = build(scene, KINEMATIC)
    targets = ([c.position("A"), c.velocity_image("A"), c.acceleration_image("A")] if crank_only
               else list(targets_for(scene, c, KINEMATIC)))
    k = compile_kernel(c, targets)
    n = phi.size
    block = np.empty((n, k.width), order="F")
    xs = np.empty((n, len(k.deferred)), order="F")
    rel = np.empty((1, len(k.targets)))
    bad = np.empty(n, dtype=np.bool_)

    def run() -> float:
        t0 = clock()
        k.function(phi, math.inf, block, xs, rel, bad, False)
        return clock() - t0
    run()                                      # compiled (or loaded from the cache) before timing
    return run


KEEP = {"MALLOC_TRIM_THRESHOLD_": "4000000000", "MALLOC_MMAP_THRESHOLD_": "1000000000"}


def child(stem: str, mode: str, n: int) -> dict[str, float]:
    """:func:`numpy_times` in a fresh process (``mode``: cold or warm)."""
    env = {**os.environ, **(KEEP if mode == "warm" else {})}
    out = subprocess.run([sys.executable, __file__, "--child", stem, mode, str(n)], env=env,
                         check=True, capture_output=True, text=True).stdout
    result: dict[str, float] = json.loads(out.strip().splitlines()[-1])
    return result


def main() -> None:
    if sys.argv[1:2] == ["--child"]:
        stem, mode, count = sys.argv[2:5]
        phi = np.linspace(0.0, 2 * np.pi, int(count), endpoint=False)
        print(json.dumps(numpy_times(stem, *construction(stem), phi, mode == "warm")))
        return
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    load0 = os.getloadavg()[0]
    rows: dict[str, list[float]] = defaultdict(list)
    for _ in range(ROUNDS):
        for mode in MODES:
            t3, t2 = child("six_bar_triad", mode, n), child("four_bar", mode, n)
            for key in ("group", "own"):
                rows[f"{mode}3_{key}"].append(t3[key])
                rows[f"{mode}2_{key}"].append(t2[key])
                rows[f"{mode}_ratio_{key}"].append(t3[key] / t2[key])
            rows[f"{mode}_closure"].append(t3["closure"])
    fused = True
    try:
        runners = {(s, crank): kernel_runner(s, phi, crank)
                   for s in GROUPS for crank in (False, True)}
    except Exception as exc:          # noqa: BLE001 - no numba: the fused rows are left out
        print(f"fused kernel not measured: {exc}")
        fused = False
    if fused:
        for _ in range(ROUNDS):
            t = {key: run() for key, run in runners.items()}
            g3 = t[("six_bar_triad", False)] - t[("six_bar_triad", True)]
            g2 = t[("four_bar", False)] - t[("four_bar", True)]
            rows["k3"].append(g3)
            rows["k2"].append(g2)
            rows["k_ratio"].append(g3 / g2)
    med = {k: statistics.median(v) for k, v in rows.items()}

    def us(x: float) -> str:
        return f"{x / n * 1e6:.2f} µs"

    lines = [("| path | class III III(2,3,4,5) per position | of it the closure | "
             "class II II(2,3) per position | ratio III / II |"), "|---|---|---|---|---|"]
    for mode in MODES:
        for key, what in (("own", "the group's construction"),
                          ("group", "with the links' other points")):
            lines.append(f"| numpy {mode}, {what} | {us(med[f'{mode}3_{key}'])} | "
                         f"{us(med[f'{mode}_closure'])} | {us(med[f'{mode}2_{key}'])} | "
                         f"**{med[f'{mode}_ratio_{key}']:.2f}×** |")
    if fused:
        lines.append(f"| fused kernel (numba, one thread) | {us(med['k3'])} | — | "
                     f"{us(med['k2'])} | **{med['k_ratio']:.2f}×** |")
    body = "\n".join([
        (f"Generated by `python benchmarks/triad.py {n}`: N = {n:,} positions, float64; the "
        f"median over {ROUNDS} rounds (each round measures both mechanisms; the ratio is taken "
        "within a round). Load average (1 min) at the start: "
        f"{load0:.2f}, at the end: {os.getloadavg()[0]:.2f}."), "",
        machine_block(), "",
        ("CPU time of the process. numpy: every kinematic step of the group (position, "
        "velocity and acceleration plans) timed and summed — the group's construction (its "
        "pairs, the special point, ω and ε), and with the points its links carry besides "
        "(centres of mass S2…S5 of the six-bar, the coupler point E of the four-bar); the "
        "closure is `triad_angle` (the base link's angle). Each in a fresh process: cold, the "
        "first evaluation (every new array's first touch counted, as in one run); warm, the "
        "second with the allocator keeping freed memory (the arithmetic alone). Fused: the "
        "kernel of every point and link less the kernel of the crank's point, one thread."), "",
        *lines, "",
        ("Goal (issue 29): a class III group costs at most 3× a dyad per position in the numpy "
        "path.")])
    print(body)
    write_section("triad", "Class III group against a dyad (issue 29)", body)


if __name__ == "__main__":
    main()
