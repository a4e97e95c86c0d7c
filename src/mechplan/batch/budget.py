"""Budgets of batch work: a class, a sweep grid, a rule — refused up front, with the estimate,
before anything is allocated or built."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from ..limits import LimitError
from .texts import say

#: students of one class run (a folder of sheets and an answer key each)
MAX_STUDENTS = 10_000
#: values of one varied key (``--vary KEY=FROM..TO:STEPS``)
MAX_AXIS_STEPS = 1_000_000
#: crank positions per variant of a sweep
MAX_SWEEP_POSITIONS = 100_000
#: variants of one sweep (rows of the summary)
MAX_SWEEP_VARIANTS = 100_000_000
#: variant-positions of one sweep (≈ 4 CPU-hours at the measured cost below)
MAX_VARIANT_POSITIONS = 10_000_000_000
#: CPU seconds per variant-position measured by benchmarks/batch.py (BATCH_RESULTS.md)
SECONDS_PER_VARIANT_POSITION = 1.4e-6
#: grid points of a generated rule's range (from, to, step)
MAX_RULE_POINTS = 10**12
#: decimal digits of a generated value
MAX_DIGITS = 12


def check_students(count: Any, *, file: str | None = None, key: str | None = None) -> None:
    """Refuse a class of more than :data:`MAX_STUDENTS` students (``count`` may be any number)."""
    if isinstance(count, int | float) and not isinstance(count, bool) and (
            not math.isfinite(count) or count > MAX_STUDENTS):
        raise LimitError(say("class_budget", count=_big(count), limit=MAX_STUDENTS),
                         file=file, key=key)


def check_axis_steps(steps: int, key: str) -> None:
    """Refuse a varied key with more than :data:`MAX_AXIS_STEPS` values (before any array)."""
    if steps > MAX_AXIS_STEPS:
        raise LimitError(say("axis_budget", steps=_big(steps), limit=MAX_AXIS_STEPS), key=key)


def check_sweep_budget(axes: Sequence[Any], positions: int) -> None:
    """Refuse a sweep whose grid or work exceeds the budgets, saying the estimate."""
    if positions > MAX_SWEEP_POSITIONS:
        raise LimitError(say("positions_budget", positions=_big(positions),
                             limit=MAX_SWEEP_POSITIONS), key="--positions")
    for ax in axes:
        check_axis_steps(len(ax.values), ax.key)
    variants = math.prod(len(ax.values) for ax in axes)
    work = variants * positions
    if variants > MAX_SWEEP_VARIANTS or work > MAX_VARIANT_POSITIONS:
        hours = work * SECONDS_PER_VARIANT_POSITION / 3600
        raise LimitError(say("sweep_budget", variants=_big(variants), positions=positions,
                             work=_big(work),
                             hours=f"{hours:.2g}" if hours < 100 else _big(round(hours)),
                             limit_variants=_big(MAX_SWEEP_VARIANTS),
                             limit_work=_big(MAX_VARIANT_POSITIONS)), key="--vary")


def check_rule(low: float, high: float, step: float | None, digits: Any, *, file: str,
               key: str) -> None:
    """Refuse a rule with a value that is not finite, too many grid points or digits."""
    for value in (low, high, *(() if step is None else (step,))):
        if not math.isfinite(value):
            raise LimitError(say("rule_not_finite", value=_big(value)), file=file, key=key)
    if step is not None:
        points = (high - low) / step
        if not math.isfinite(points) or points > MAX_RULE_POINTS:
            raise LimitError(say("rule_points", points=_big(points), limit=_big(MAX_RULE_POINTS)),
                             file=file, key=key)
    if isinstance(digits, int) and not isinstance(digits, bool) and digits > MAX_DIGITS:
        raise LimitError(say("rule_digits", digits=_big(digits), limit=MAX_DIGITS),
                         file=file, key=key)


def _big(x: float) -> str:
    """A count as a short text: 1000000 → "1000000", 10**29 → "1e+29", inf → "inf"."""
    if isinstance(x, int) and abs(x) < 10**15:
        return str(x)
    if isinstance(x, int):
        return f"{float(x):.3g}" if x < 10**308 else f"10^{len(str(x)) - 1}"
    return f"{x:.3g}"
