"""A sweep's result does not depend on how it was chunked, interrupted or resumed (issue 38)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from hypothesis import given
from hypothesis import strategies as st

import mechplan.batch.sweep as sweep_module
from mechplan.batch.parts import Part, cover
from mechplan.batch.plan import make_plan, parse_vary
from mechplan.batch.sweep import evaluate_chunk, run_sweep

SLIDER = (Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
          / "slider_crank.toml")
VARY = ["links.1.lengths.OA=80mm..400mm:7", "links.2.lengths.AB=300mm..420mm:5"]
AXES = [parse_vary(v) for v in VARY]
POSITIONS = 12
SIZE = 35


def reference() -> pa.Table:
    """Every variant evaluated in one chunk, without parts, resume or the engine."""
    plan = make_plan(SLIDER.read_text(encoding="utf-8"), str(SLIDER), AXES, POSITIONS)
    _, cols, _ = evaluate_chunk(plan, 0, plan.size)
    return sweep_module._to_table(cols)


def leftovers(out: Path) -> list[str]:
    return sorted(str(p.relative_to(out)) for p in out.rglob("*.tmp"))


def test_cover_takes_each_variant_once():
    a, b, c = (Part(Path(n), lo, hi) for n, lo, hi in (("a", 0, 100), ("b", 50, 200),
                                                       ("c", 240, 260)))
    got = cover([c, b, a], 300)
    assert [(p.path.name, lo, hi) for p, lo, hi in got.segments] == [("a", 0, 100),
                                                                     ("b", 100, 200),
                                                                     ("c", 240, 260)]
    assert got.gaps == [(200, 240), (260, 300)] and got.unused == []
    inner = Part(Path("d"), 10, 20)
    assert cover([a, inner], 100).unused == [inner]


@given(st.integers(1, 60), st.lists(st.tuples(st.integers(0, 60), st.integers(1, 20)),
                                   max_size=12))
def test_cover_property_each_variant_exactly_once(size, spans):
    parts = [Part(Path(f"p{i}"), a, min(a + n, size)) for i, (a, n) in enumerate(spans)
             if a < size]
    got = cover(parts, size)
    taken = [v for p, lo, hi in got.segments for v in range(lo, hi)]
    missing = [v for lo, hi in got.gaps for v in range(lo, hi)]
    assert sorted(taken + missing) == list(range(size))          # each variant once
    assert taken == sorted(taken) and missing == sorted(missing)
    assert all(p.start <= lo < hi <= p.stop for p, lo, hi in got.segments)
    held = {v for p in parts for v in range(p.start, p.stop)}
    assert set(missing) == set(range(size)) - held                # only what no part holds
    assert not {p.path for p in got.unused} & {p.path for p, _, _ in got.segments}


def test_chunk_100_then_150_keeps_every_row(tmp_path):
    """The issue's case: parts named by their start lost 200 of 1,271 rows."""
    axes = [parse_vary("links.1.lengths.OA=80mm..120mm:31"),
            parse_vary("links.2.lengths.AB=300mm..420mm:41")]
    first = run_sweep(SLIDER, axes, tmp_path, positions=4, workers=1, progress=False, chunk=100)
    again = run_sweep(SLIDER, axes, tmp_path, positions=4, workers=1, progress=False, chunk=150)
    table = pq.read_table(again.parquet)
    assert table.column("variant").to_pylist() == list(range(1271))
    assert table.equals(pq.read_table(first.parquet))
    assert again.cpu_seconds == 0.0 and again.skipped_chunks == again.chunks == 13


def test_interrupted_at_random_points_and_resumed_equals_one_run(tmp_path, monkeypatch):
    expected = reference()
    assert expected.num_rows == SIZE
    rng = np.random.default_rng(38)
    out = tmp_path / "sweep"
    real_write = sweep_module.write_part
    done = interrupted = 0
    for round_ in range(7):
        chunk = int(rng.integers(1, 13))
        workers = 2 if round_ in (2, 5) else 1
        budget = int(rng.integers(0, 4))         # parts written before the interruption

        def write_then_stop(*args, budget=budget):
            nonlocal done
            if done >= budget:
                raise KeyboardInterrupt           # Ctrl-C between two parts
            done += 1
            return real_write(*args)

        done = 0
        monkeypatch.setattr(sweep_module, "write_part", write_then_stop)
        try:
            run_sweep(SLIDER, AXES, out, positions=POSITIONS, workers=workers, progress=False,
                      chunk=chunk)
        except KeyboardInterrupt:
            interrupted += 1
        if (out / "summary.parquet").exists():     # only ever a whole summary
            assert pq.read_table(out / "summary.parquet").num_rows == SIZE
        parts = next(out.glob("parts-*"))
        # what a SIGKILL in the middle of a write leaves, and a damaged part
        (parts / f".part-{round_:012d}-000000000035.parquet.k{round_}.tmp").write_bytes(b"x")
        (out / f".summary.parquet.k{round_}.tmp").write_bytes(b"half")
        if round_ == 3:
            (parts / "part-000000000030-000000000035.parquet").write_bytes(b"PAR1 damaged")
    assert interrupted >= 5
    monkeypatch.setattr(sweep_module, "write_part", real_write)
    # Ctrl-C in the middle of writing the summary: neither summary file is left half-written
    real_safe = sweep_module.csv_safe_table
    calls = 0

    def safe_then_stop(table):
        nonlocal calls
        calls += 1
        if calls == 3:
            raise KeyboardInterrupt
        return real_safe(table)

    monkeypatch.setattr(sweep_module, "csv_safe_table", safe_then_stop)
    (out / "summary.csv").unlink(missing_ok=True)
    (out / "summary.parquet").unlink(missing_ok=True)
    with pytest.raises(KeyboardInterrupt):
        run_sweep(SLIDER, AXES, out, positions=POSITIONS, workers=1, progress=False, chunk=3)
    assert not (out / "summary.csv").exists() and not (out / "summary.parquet").exists()
    assert leftovers(out) == []
    monkeypatch.setattr(sweep_module, "csv_safe_table", real_safe)
    result = run_sweep(SLIDER, AXES, out, positions=POSITIONS, workers=2, progress=False,
                       chunk=None)
    table = pq.read_table(result.parquet)
    assert table.column("variant").to_pylist() == list(range(SIZE))
    assert table.to_pylist() == expected.to_pylist()          # row for row
    assert leftovers(out) == []
    csv_rows = (out / "summary.csv").read_text(encoding="utf-8").splitlines()
    assert len(csv_rows) == SIZE + 1
    # re-running the completed sweep with other chunk sizes evaluates nothing and changes nothing
    for chunk in (None, 4, 35):
        again = run_sweep(SLIDER, AXES, out, positions=POSITIONS, workers=1, progress=False,
                          chunk=chunk)
        assert again.cpu_seconds == 0.0 and again.skipped_chunks == again.chunks
        assert pq.read_table(again.parquet).to_pylist() == expected.to_pylist()


def test_sigkill_of_the_main_process_then_resume(tmp_path):
    out = tmp_path / "sweep"
    base = [sys.executable, "-m", "mechplan.cli", "sweep", str(SLIDER), "--vary",
            "links.1.lengths.OA=80mm..400mm:40", "--vary", "links.2.lengths.AB=300mm..420mm:20",
            "--positions", "360", "--no-progress", "-o", str(out)]
    proc = subprocess.Popen([*base, "--chunk", "7", "-j", "1"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and proc.poll() is None:
        if len(list(out.glob("parts-*/part-*.parquet"))) >= 3:
            break
        time.sleep(0.05)
    assert proc.poll() is None, proc.stderr.read() if proc.stderr else ""
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    parts = next(out.glob("parts-*"))
    before = len(list(parts.glob("part-*.parquet")))
    assert 3 <= before < 115
    (parts / ".part-000000000000-000000000800.parquet.killed.tmp").write_bytes(b"half")
    (out / ".summary.csv.killed.tmp").write_bytes(b"half")
    done = subprocess.run([*base, "--chunk", "50", "-j", "2"], capture_output=True, text=True,
                          timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    assert f"({before} complete already)" in done.stdout
    table = pq.read_table(out / "summary.parquet")
    assert table.column("variant").to_pylist() == list(range(800))
    assert leftovers(out) == []
