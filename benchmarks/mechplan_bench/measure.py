"""The run: every configured method on every case and N, timed and compared with the reference."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

import mechplan_bench as bench
from mechplan.construct.graph import Evaluation

from .config import CASES, FD_STEP_A, FD_STEP_V, SCALE_POSITIONS, Config
from .formulas import closed_form, lambda_series
from .model import Model
from .no_numba import pylinkage_without_numba
from .peers import installed, mechanism_runner, pylinkage_runner
from .reference import Reference, reference_result, relative_errors, sizes
from .results import Result, Row
from .timing import best_time


def compared_indices(n: int, cfg: Config) -> np.ndarray:
    """All positions up to ``max_compared``, else an evenly spread deterministic subsample."""
    if n <= cfg.max_compared:
        return np.arange(n)
    return np.unique(np.round(np.linspace(0, n - 1, cfg.subsample)).astype(int))


def run_benchmark(cfg: Config | None = None, log: Callable[[str], None] | None = None,
                  reference: Reference | None = None) -> list[Row]:
    """Measure every configured method on every configured case and N; return the rows."""
    cfg = cfg or Config()
    log = log or (lambda msg: None)
    ref = reference or Reference()
    if cfg.steady_allocator:
        # looked up on the package, so that a substitute set there (as the tests do) is used
        bench.steady_allocator()
    rows: list[Row] = []
    slow_peer: dict[tuple[str, int], tuple[float, int, Result]] = {}
    if "pylinkage (no numba)" in cfg.methods and installed("pylinkage"):
        ns = [n for n in cfg.ns if n <= cfg.slow_peer_max_n]
        slow_peer = pylinkage_without_numba(cfg, cfg.cases, ns, log)
    for name in cfg.cases:
        case = CASES[name]
        model = Model.load(case)
        cycle = model.phi(SCALE_POSITIONS)
        size = sizes(case, reference_result(case, ref.at(name, model.theta(cycle))))
        for n in cfg.ns:
            phi = model.phi(n)
            idx = compared_indices(n, cfg)
            log(f"{name}: N = {n}, reference at {idx.size} position(s)")
            want = reference_result(case, ref.at(name, model.theta(phi[idx])))
            for method in cfg.methods:
                runner, note = _runner(method, model, phi, cfg, slow_peer)
                if runner is None:
                    if note:
                        rows.append(Row(name, method, n, math.nan, 0, 0, {}, note))
                    continue
                best, k, out = best_time(runner, cfg) if callable(runner) else runner
                got = model.result(out) if isinstance(out, Evaluation) else out
                errs = relative_errors(got, want, idx, size)
                rows.append(Row(name, method, n, best, k, idx.size, errs, note))
    return rows


def _runner(method: str, model: Model, phi: np.ndarray, cfg: Config,
            slow_peer: dict) -> tuple[Any, str]:
    """The runner of a method (or a finished measurement) and a note; (None, note) if not run."""
    n, name = phi.shape[0], model.case.name
    if method == "exact float64":
        return model.exact(phi), ""
    if method == "exact float32":
        return model.exact(phi, np.float32), ""
    if method.startswith("ruler"):
        return model.ruler(phi, float(method.split()[1])), ""
    if method == "finite differences":
        return model.finite_differences(phi), f"h_v = {FD_STEP_V:g}, h_a = {FD_STEP_A:g} rad"
    if method == "λ-series":
        if name != "slider_crank":
            return None, ""
        return lambda_series(model, phi), "slider B only"
    if method == "numpy closed form":
        return closed_form(model, phi), ""
    if method == "pylinkage + numba":
        if not (installed("pylinkage") and installed("numba")):
            return None, "pylinkage or numba not installed"
        return pylinkage_runner(model, phi), "points only (no ω, ε)"
    if method == "pylinkage (no numba)":
        if (name, n) in slow_peer:
            return slow_peer[(name, n)], "points only; NUMBA_DISABLE_JIT=1 child process"
        if not installed("pylinkage"):
            return None, "pylinkage not installed"
        return None, ""
    if method == "mechanism (fsolve)":
        if name not in ("slider_crank", "four_bar"):
            return None, ""
        if not installed("mechanism"):
            return None, "mechanism not installed"
        if n > cfg.fsolve_max_n:
            return None, (f"not run: a Python loop of three fsolve calls per position (see the "
                          f"largest N ≤ {cfg.fsolve_max_n} for its cost per position)")
        run = mechanism_runner(model, phi)
        return run, ("" if run is None else "four-bar: B, C only" if name == "four_bar" else
                     "slider: A, B only")
    raise KeyError(method)
