"""Scale factors μ: round values (1, 2, 2.5, 4, 5 × 10^k) so a plan fills its place."""

from __future__ import annotations

import math

from ..model.plans import Plan

ROUND_MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0, 10.0)

#: plan name → scale-factor key and unit text (derived from :class:`Plan`)
SCALE_KEYS = {p.value: (p.scale_key, p.scale_unit) for p in Plan}


def round_scale(per_mm: float) -> float:
    """Smallest round scale factor ≥ per_mm (physical units per mm of paper)."""
    if not per_mm > 0 or not math.isfinite(per_mm):
        return 1.0
    k = math.floor(math.log10(per_mm))
    for m in ROUND_MANTISSAS:
        value = m * 10.0 ** k
        if value >= per_mm * (1 - 1e-12):
            return float(f"{value:.12g}")
    return 10.0 ** (k + 1)


def choose_scale(largest: float, target_mm: float) -> float:
    """Round μ so that the largest quantity is drawn at most ``target_mm`` long."""
    return round_scale(largest / target_mm)
