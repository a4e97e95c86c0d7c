"""What a benchmark run measures: the mechanisms, the methods, the fixed constants and
:class:`Config`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

#: the repository checkout (templates, ``tests/independent``, ``src``)
ROOT = Path(__file__).resolve().parents[2]
KINDS = ("r", "v", "a", "omega", "epsilon")
TWO_PI = 2.0 * math.pi
#: φ of the first position (rad, scene convention); the others follow at 2π/N
PHI0 = 0.1
#: positions of the cycle on which the reference sizes of r, v, a, ω, ε are taken
SCALE_POSITIONS = 24
#: finite-difference steps in φ (rad): ~ (3ε)^(1/3) for v, ~ (48ε)^(1/4) for a
FD_STEP_V = 1e-5
FD_STEP_A = 1e-4
#: ruler precisions (mm of paper)
RULER_MM = (0.5, 0.1)


@dataclass(frozen=True, slots=True)
class Case:
    """A benchmarked mechanism: template / reference preset name, points and links compared."""

    name: str
    points: tuple[str, ...]
    links: tuple[str, ...]


CASES: dict[str, Case] = {c.name: c for c in (
    Case("slider_crank", ("A", "B", "S2"), ("2",)),
    Case("four_bar", ("B", "C", "E"), ("2", "3")),
    Case("v_engine", ("B", "C", "D", "E", "S2"), ("2", "4")),
    Case("shaper", ("A", "B", "C"), ("3", "4")),
)}

METHODS = ("exact float64", "exact float32", "ruler 0.5 mm", "ruler 0.1 mm",
           "finite differences", "λ-series", "numpy closed form", "pylinkage + numba",
           "pylinkage (no numba)", "mechanism (fsolve)")


@dataclass
class Config:
    """What one benchmark run measures."""

    cases: tuple[str, ...] = tuple(CASES)
    ns: tuple[int, ...] = (1, 12, 360, 100_000)
    methods: tuple[str, ...] = METHODS
    #: positions compared with the reference when N is larger (a deterministic subsample)
    max_compared: int = 360
    subsample: int = 50
    #: timing: repeat until both counts are reached (best of k), at most max_repeats
    min_repeats: int = 7
    min_seconds: float = 0.5
    max_repeats: int = 200
    #: largest N for the slow peers (pure-Python pylinkage, mechanism's fsolve loop)
    slow_peer_max_n: int = 100_000
    fsolve_max_n: int = 360
    steady_allocator: bool = False


def quick_config() -> Config:
    """A reduced run for ``python benchmarks/bench.py --quick`` (about ten seconds)."""
    return Config(ns=(1, 12, 10_000), max_compared=12, subsample=12, min_repeats=3,
                  min_seconds=0.05, max_repeats=50, fsolve_max_n=12,
                  methods=tuple(m for m in METHODS if m != "pylinkage (no numba)"))
