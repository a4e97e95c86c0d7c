"""Rows, goals and machine facts of a run, formatted as text or Markdown."""

from __future__ import annotations

import math
import os
import platform
from collections.abc import Iterable, Sequence
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import numpy as np

from .config import CASES, KINDS
from .results import Row


def _fmt_err(x: float | None) -> str:
    if x is None:
        return "—"
    if math.isinf(x):
        return "fail"
    return f"{x:.1e}"


def format_table(rows: Iterable[Row], markdown: bool = False) -> str:
    """The rows as a text or Markdown table."""
    head = ["mechanism", "method", "N", "ns/position", "max rel. error", *KINDS, "compared", "note"]
    body = []
    for r in rows:
        if r.repeats == 0:
            body.append([r.mechanism, r.method, str(r.n), "—", "—", *(["—"] * len(KINDS)), "0",
                         r.note])
            continue
        body.append([r.mechanism, r.method, str(r.n), f"{r.ns_per_position:,.0f}",
                     _fmt_err(r.max_error), *(_fmt_err(r.errors.get(k)) for k in KINDS),
                     str(r.compared), r.note])
    if markdown:
        lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        lines += ["| " + " | ".join(row) + " |" for row in body]
        return "\n".join(lines)
    widths = [max(len(x) for x in col) for col in zip(head, *body)]
    fmt = "  ".join(f"{{:{'<' if i < 2 or i == len(head) - 1 else '>'}{w}}}"
                    for i, w in enumerate(widths))
    return "\n".join(fmt.format(*row).rstrip() for row in [head, *body])


def goals(rows: Sequence[Row]) -> list[tuple[str, bool | None, str]]:
    """The issue's goals checked on measured rows: (goal, met or None if not measured, detail)."""
    by = {(r.mechanism, r.method, r.n): r for r in rows if r.repeats}
    big = max((r.n for r in rows), default=0)
    out: list[tuple[str, bool | None, str]] = []
    ratios, faster = [], []
    for name in CASES:
        ex = by.get((name, "exact float64", big))
        cf = by.get((name, "numpy closed form", big))
        pl = by.get((name, "pylinkage + numba", big))
        if ex and cf:
            ratios.append((name, ex.seconds / cf.seconds))
        if ex and pl:
            faster.append((name, ex.seconds / pl.seconds))
    out.append((f"exact float64 at N = {big:,} faster per position than pylinkage + numba",
                all(x < 1 for _, x in faster) if faster else None,
                ", ".join(f"{n}: {x:.2f}× pylinkage's time" for n, x in faster) or "not measured"))
    out.append((f"exact float64 at N = {big:,} within 3× of the numpy closed form",
                all(x <= 3 for _, x in ratios) if ratios else None,
                ", ".join(f"{n}: {x:.2f}×" for n, x in ratios) or "not measured"))
    errs = [r.max_error for r in rows if r.method == "exact float64" and r.repeats]
    out.append(("exact float64 max relative error ≤ 1e-13 (all mechanisms, all N)",
                max(errs) <= 1e-13 if errs else None,
                f"worst {max(errs):.1e}" if errs else "not measured"))
    return out


def machine() -> dict[str, str]:
    """The machine and versions a run measured on."""
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    info = {"cpu": cpu, "cores": str(os.cpu_count()), "os": platform.platform(),
            "python": platform.python_version(), "numpy": np.__version__}
    for mod in ("mpmath", "numba", "pylinkage", "mechanism", "scipy"):
        try:
            info[mod] = version(mod)
        except PackageNotFoundError:
            info[mod] = "not installed"
    return info
