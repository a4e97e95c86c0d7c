"""Cost of the error estimates and how they compare with the actual errors on the hard cases.

Run: ``python benchmarks/estimates.py`` (from the repository root, mechplan installed); writes
``benchmarks/ESTIMATES_RESULTS.md``. Ratios are measured in one run (this machine is noisy).
"""

from __future__ import annotations

import math
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from construct import singular_refs as ref
from construct.test_error_estimates import (
    FOUR_BAR_CHANGE,
    OFFSETS_DEG,
    SLIDER_TOGGLE,
    SLOTTED_THROUGH_PIVOT,
)

from mechplan.construct.estimate import estimate_errors
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import build, targets_for

KINEMATIC = ("position", "velocity", "acceleration")
N = 100_000
REPEAT = 5


def _cost(name: str) -> tuple[float, float]:
    scene = load_scene(ROOT / "templates" / f"{name}.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    phi = np.linspace(0.0, 2 * math.pi, N, endpoint=False)
    best_eval = best_est = math.inf
    for _ in range(REPEAT):
        t0 = time.perf_counter()
        ev = c.evaluate(phi)
        ev.evaluate_all(targets)
        t1 = time.perf_counter()
        estimate_errors(c, ev, targets)
        t2 = time.perf_counter()
        best_eval, best_est = min(best_eval, t1 - t0), min(best_est, t2 - t1)
    return best_eval, best_est


def _hard_rows() -> list[str]:
    rows = []
    cases = [
        ("offset slider-crank toggle", SLIDER_TOGGLE, -math.pi / 2,
         lambda th: ref.slider_crank(0.08, 0.11, 0.03, th, 10.0),
         {"v_B": ("velocity_image", "B", 0), "a_B": ("acceleration_image", "B", 0),
          "omega_2": ("omega", "2", None), "epsilon_2": ("epsilon", "2", None)}),
        ("four-bar change point", FOUR_BAR_CHANGE, math.pi,
         lambda th: ref.four_bar(0.05, 0.2, 0.15, 0.3, th, 10.0),
         {"omega_3": ("omega", "3", None), "epsilon_3": ("epsilon", "3", None)}),
        ("slotted link through its pivot", SLOTTED_THROUGH_PIVOT, -math.pi / 2,
         lambda th: ref.slotted_through_pivot(10.0),
         {"omega_3": ("omega", "3", None), "epsilon_3": ("epsilon", "3", None)}),
    ]
    for title, text, singular, exact_of, quantities in cases:
        scene = parse_scene(text, "hard.toml")
        _, c = build(scene, KINEMATIC)
        thetas = singular + np.radians(np.asarray(OFFSETS_DEG))
        ev = c.evaluate(c.drive.scene(thetas))
        targets = targets_for(scene, c, KINEMATIC)
        ev.evaluate_all(targets)
        est = estimate_errors(c, ev, targets)
        for k, off in enumerate(OFFSETS_DEG):
            exact = exact_of(thetas[k])
            for name, (accessor, subject, col) in quantities.items():
                sid = getattr(c, accessor)(subject)
                v = ev[sid][k]
                value = float(v[col]) if col is not None else float(v)
                estimate = float(est.relative(sid)[k])
                actual = (abs(value - exact[name]) / est.scale[sid] if math.isfinite(value)
                          else math.inf)
                verdict = ("refused" if not math.isfinite(value) else
                           "flagged" if estimate > 1e-6 else
                           "bounded" if actual <= 10 * estimate else "SILENTLY WRONG")
                rows.append(f"| {title} | {off:+g}° | {name} | {actual:.2e} | {estimate:.2e} "
                            f"| {verdict} |")
    return rows


def main() -> None:
    lines = ["# Error estimates: cost and honesty", "",
             (f"Machine: {platform.processor() or platform.machine()}, "
              f"Python {platform.python_version()}, numpy {np.__version__}; "
              f"best of {REPEAT} runs, N = {N:,} positions, "
              "positions + velocities + accelerations of every point and link."), "",
             "| mechanism | evaluation, ms | estimates, ms | added time |", "|---|---|---|---|"]
    for name in ("slider_crank", "four_bar", "v_engine", "shaper"):
        e, s = _cost(name)
        lines.append(f"| {name} | {e * 1e3:.1f} | {s * 1e3:.1f} | {100 * s / e:.0f} % |")
    lines += ["", "## Actual error against the estimate on the hard cases",
              ("Relative to the plan's scale (ω1·L, ω1²·L, ω1, ω1²); "
               "references are 60-digit closed forms."),
              "", "| case | from the singular angle | quantity | actual | estimate | verdict |",
              "|---|---|---|---|---|---|"]
    lines += _hard_rows()
    out = ROOT / "benchmarks" / "ESTIMATES_RESULTS.md"
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(out.read_text(encoding="utf-8"))


if __name__ == "__main__":
    main()
