"""Timing: best of k wall times, a steady heap for fair timings, and a per-operation profile."""

from __future__ import annotations

import ctypes
import ctypes.util
import math
import platform
import time
from collections.abc import Callable
from typing import Any

from mechplan.construct.graph import Evaluation

from .config import Config
from .model import Model


def best_time(run: Callable[[], Any], cfg: Config) -> tuple[float, int, Any]:
    """Best wall time of ``run()`` over k calls (time.perf_counter), k, and the last result."""
    best, total, k, out = math.inf, 0.0, 0, None
    while k < cfg.max_repeats:
        t0 = time.perf_counter()
        out = run()
        dt = time.perf_counter() - t0
        best, total, k = min(best, dt), total + dt, k + 1
        if k >= cfg.min_repeats and total >= cfg.min_seconds:
            break
        if dt > 2.0 and k >= 2:     # slow methods: best of two is all the time allows
            break
    return best, k, out


def steady_allocator() -> bool:
    """Keep freed heap memory in the process (glibc), so timings do not count fresh-page faults.

    Without it glibc returns the tens of megabytes an N = 100 000 evaluation frees to the kernel,
    and the next evaluation pays a page fault per 4 KiB again; which runs pay depends on the
    process's allocation history. Returns whether the setting was applied.
    """
    name = ctypes.util.find_library("c")
    if not name or platform.system() != "Linux":
        return False
    try:
        libc = ctypes.CDLL(name)
        m_trim_threshold, m_mmap_threshold = -1, -3
        ok = libc.mallopt(m_trim_threshold, 1 << 30) == 1
        return bool(libc.mallopt(m_mmap_threshold, 32 << 20) == 1 and ok)
    except (OSError, AttributeError):
        return False


def profile(model: Model, n: int, repeats: int = 5) -> list[tuple[str, int, float]]:
    """Where the exact evaluation spends its time at N positions: (operation, steps, seconds).

    Each step's evaluation is timed on its own (best of ``repeats``), then summed per operation.
    """
    phi = model.phi(n)
    best: dict[str, float] = {}

    class Timed(Evaluation):
        def _compute(self, step: Any) -> None:
            t0 = time.perf_counter()
            Evaluation._compute(self, step)
            dt = time.perf_counter() - t0
            best[step.id] = min(best.get(step.id, math.inf), dt)

    for _ in range(repeats):
        Timed(model.c, phi).evaluate_all(model.targets)
    per_op: dict[str, list[float]] = {}
    for sid, dt in best.items():
        per_op.setdefault(model.c[sid].op.value, []).append(dt)
    return sorted(((op, len(v), sum(v)) for op, v in per_op.items()), key=lambda x: -x[2])
