"""Smoke test of the speed-against-error benchmark (``python benchmarks/bench.py``) on a tiny
configuration."""

from __future__ import annotations

import argparse
import math

import mechplan_bench as bench
import numpy as np
import pytest

from mechplan.construct.ops import Op
from mechplan.construct.step import Kind

METHODS = ("exact float64", "exact float32", "ruler 0.5 mm", "finite differences", "λ-series",
           "numpy closed form")


def tiny(**changes) -> bench.Config:
    cfg = bench.Config(cases=("slider_crank",), ns=(1, 12), methods=METHODS, max_compared=4,
                       subsample=4, min_repeats=1, min_seconds=0.0, max_repeats=2)
    for key, value in changes.items():
        setattr(cfg, key, value)
    return cfg


@pytest.fixture(scope="module")
def rows() -> list[bench.Row]:
    return bench.run_benchmark(tiny())


def test_rows_have_finite_times_and_sane_errors(rows: list[bench.Row]) -> None:
    got = {(r.method, r.n): r for r in rows}
    assert set(got) == {(m, n) for m in METHODS for n in (1, 12)}
    bounds = {"exact float64": 1e-13, "numpy closed form": 1e-13, "exact float32": 1e-5,
              "finite differences": 1e-5, "ruler 0.5 mm": 0.1, "λ-series": 0.05}
    for (method, n), r in got.items():
        assert r.repeats >= 1 and math.isfinite(r.seconds) and r.seconds > 0
        assert r.compared == min(n, 4)
        assert r.errors and all(math.isfinite(e) for e in r.errors.values())
        assert r.max_error <= bounds[method], (method, n, r.errors)
    # what each method gives
    assert set(got[("exact float64", 12)].errors) == set(bench.KINDS)
    assert set(got[("λ-series", 12)].errors) == {"r", "v", "a"}
    # the ruler is coarser than float32, which is coarser than float64
    for n in (1, 12):
        assert (got[("exact float64", n)].max_error < got[("exact float32", n)].max_error
                < got[("ruler 0.5 mm", n)].max_error)


def test_table_and_goals_render(rows: list[bench.Row]) -> None:
    text = bench.format_table(rows)
    assert "exact float64" in text.splitlines()[1] and "ns/position" in text.splitlines()[0]
    md = bench.format_table(rows, markdown=True)
    assert md.startswith("| mechanism | method |") and md.count("\n") == len(rows) + 1
    goals = bench.goals(rows)
    assert [g[1] for g in goals][2] is True          # error goal met on this tiny run
    assert goals[0][1] is None                       # pylinkage not measured


def test_subsample_is_deterministic_and_spread() -> None:
    cfg = bench.Config()
    idx = bench.compared_indices(100_000, cfg)
    assert idx.size == 50 and idx[0] == 0 and idx[-1] == 99_999
    assert np.array_equal(idx, bench.compared_indices(100_000, cfg))
    assert np.array_equal(bench.compared_indices(360, cfg), np.arange(360))


def test_ruler_mode_places_every_point_at_a_ruler_length() -> None:
    model = bench.Model.load(bench.CASES["four_bar"])
    phi = model.phi(12)
    ev = model.ruler(phi, 0.5)()
    ruler = ev
    c = model.c
    checked = 0
    for step in c:
        if step.id not in ruler.values or step.kind is not Kind.POINT or step.op in (
                Op.FIXED_POINT, Op.POLE):
            continue
        start = ruler.starts.get(step.id)
        if start is None or start not in ruler.values:
            continue
        delta = ruler.delta[step.plan]
        length = np.hypot(*(ruler[step.id] - ruler[start]).T)
        assert np.allclose(length / delta, np.round(length / delta), atol=1e-6), step.id
        checked += 1
    assert checked >= 10


def test_cli_entry_runs_a_reduced_benchmark(monkeypatch, capsys) -> None:
    monkeypatch.setattr(bench, "quick_config", lambda: tiny(ns=(3,), methods=METHODS[:2]))
    monkeypatch.setattr(bench, "steady_allocator", lambda: False)
    parser = argparse.ArgumentParser()
    bench.add_parser(parser.add_subparsers(dest="command"))
    args = parser.parse_args(["bench", "--quick"])
    assert args.func(args) == 0
    out = capsys.readouterr().out
    assert "exact float32" in out and "max relative error ≤ 1e-13" in out
