"""Speed against error: every way of getting a mechanism's kinematics, timed and checked.

``python benchmarks/bench.py [--quick]`` times, in one process, the construction engine (float64 and
float32), "ruler mode" (the construction with every placed point rounded to the drawing's precision,
as a student carries measured segments on), velocities and accelerations by finite differences of
positions, the engine λ-series (slider-crank), the hand-written numpy closed forms and the peer
packages that are installed (pylinkage with and without numba, mechanism), and measures each one's
error against a 40-digit mpmath reference (Newton on the loop-closure equations and mpmath
differentiation, ``tests/independent/mpref.py`` — not the project's plans).

Errors are relative to the size of the quantity over the cycle: for each kind (r, v, a of points,
ω, ε of links) the largest vector difference from the reference, divided by the largest magnitude
of that kind in the reference over 24 positions of the cycle. The full benchmark is
``benchmarks/speed_error.py``; ``benchmarks/kinematics.py`` is the issue-2 subset.

Modules, each importing only those listed before it: ``config`` (cases, methods, constants,
Config), ``results`` (Result, Row), ``reference`` (the mpmath reference, relative errors),
``ruler`` (RulerEvaluation), ``model`` (the construction exact, in ruler mode, by finite
differences), ``formulas`` (λ-series, closed form), ``peers`` (pylinkage, mechanism), ``timing``
(best of k, allocator, profile), ``no_numba`` (pylinkage in a child process), ``measure`` (the
run), ``report`` (table, goals, machine), ``cli`` (``python benchmarks/bench.py``). ``measure`` and
``cli`` call ``steady_allocator`` / the entry points through this package, so substitutes set here
hold.
"""

from __future__ import annotations

from .cli import add_parser, run
from .config import (
    CASES,
    FD_STEP_A,
    FD_STEP_V,
    KINDS,
    METHODS,
    PHI0,
    ROOT,
    RULER_MM,
    SCALE_POSITIONS,
    TWO_PI,
    Case,
    Config,
    quick_config,
)
from .formulas import closed_form, lambda_series
from .measure import compared_indices, run_benchmark
from .model import Model
from .peers import mechanism_runner, pylinkage_runner
from .reference import Reference, independent, reference_result, relative_errors, sizes
from .report import format_table, goals, machine
from .results import Result, Row
from .ruler import RulerEvaluation
from .timing import best_time, profile, steady_allocator

__all__ = [
    "CASES", "FD_STEP_A", "FD_STEP_V", "KINDS", "METHODS", "PHI0", "ROOT", "RULER_MM",
    "SCALE_POSITIONS", "TWO_PI", "Case", "Config", "Model", "Reference", "Result", "Row",
    "RulerEvaluation", "add_parser", "best_time", "closed_form", "compared_indices",
    "format_table", "goals", "independent", "lambda_series", "machine", "mechanism_runner",
    "profile", "pylinkage_runner", "quick_config", "reference_result", "relative_errors", "run",
    "run_benchmark", "sizes", "steady_allocator",
]
