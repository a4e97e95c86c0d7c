"""Cost of a class III group (triad) against a class II group (dyad) per position, numpy path.

Run: ``python benchmarks/triad.py [N]``. Each step's evaluation is timed and summed by the group
it belongs to (position, velocity and acceleration plans), on the six-bar with a triad
(``six_bar_triad.toml``) and the four-bar (``four_bar.toml``, its RRR dyad); the ratio is the
triad's time per position over the dyad's. Median of 5 runs. Writes nothing; prints a table
(recorded in benchmarks/TRIAD_RESULTS.md).
"""

from __future__ import annotations

import statistics
import sys
import time
from collections import defaultdict
from pathlib import Path

import numpy as np

from mechplan.construct import graph
from mechplan.scene import load_scene
from mechplan.solve import build

ROOT = Path(__file__).resolve().parents[1] / "templates"


def group_times(stem: str, n: int) -> dict[str, float]:
    """Seconds spent per group evaluating every kinematic step at n positions (median of 5)."""
    scene = load_scene(ROOT / f"{stem}.toml")
    _, c = build(scene, ("position", "velocity", "acceleration"))
    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    runs: list[dict[str, float]] = []
    original = graph.Evaluation._compute
    for _ in range(5):
        spent: dict[str, float] = defaultdict(float)

        def timed(self: graph.Evaluation, step: object, spent: dict[str, float] = spent) -> None:
            t0 = time.perf_counter()
            original(self, step)  # type: ignore[arg-type]
            spent[step.group] += time.perf_counter() - t0  # type: ignore[attr-defined]

        graph.Evaluation._compute = timed  # type: ignore[method-assign]
        try:
            ev = c.evaluate(phi)
            ev.evaluate_all(list(c.steps))
        finally:
            graph.Evaluation._compute = original  # type: ignore[method-assign]
        runs.append(dict(spent))
    return {g: statistics.median(r.get(g, 0.0) for r in runs) for g in runs[0]}


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    triad = group_times("six_bar_triad", n)
    dyad = group_times("four_bar", n)
    t3 = triad["III(2,3,4,5)"]
    t2 = dyad["II(2,3)"]
    print(f"N = {n} positions, numpy path, float64")
    print("| group | time | per position |")
    print("|---|---|---|")
    print(f"| class III III(2,3,4,5) | {t3 * 1e3:.1f} ms | {t3 / n * 1e6:.2f} µs |")
    print(f"| class II II(2,3) | {t2 * 1e3:.1f} ms | {t2 / n * 1e6:.2f} µs |")
    print(f"ratio class III / class II: {t3 / t2:.2f}")


if __name__ == "__main__":
    main()
