"""A whole class and a whole design space: variants with answer keys, and sweeps.

``run_class`` writes per student a folder with the scene, its sheets and its answer key;
``run_sweep`` evaluates a grid of variants over the whole cycle and summarises each. Both run on
joblib's process workers, or on a Dask distributed cluster when given a scheduler address.
"""

from __future__ import annotations

from .klass import ClassResult, run_class
from .variants import Variant, read_variants

__all__ = ["ClassResult", "Variant", "read_variants", "run_class"]
