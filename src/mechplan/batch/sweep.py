"""Sweeps: every variant of a grid evaluated over the whole cycle and summarised.

The grid is cut into chunks of consecutive variants (each ≥ ~0.15 s of work); a chunk is one task on
the engine and comes back as a small table of summaries, written as a Parquet part at once (resume:
parts already written are skipped). The parts are then streamed into ``summary.parquet`` and
``summary.csv``, so memory is bounded by a chunk, not by the sweep.
"""

from __future__ import annotations

import hashlib
import json
import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .. import __version__
from ..construct.graph import Construction
from ..errors import MechplanError
from ..render.atomic import atomic_open, write_atomic
from ..scene.document import read_text
from .budget import check_sweep_budget
from .csvsafe import csv_safe_table
from .engine import check_scheduler, default_workers, run_tasks
from .outdir import locked, prepare_output, remove_stale, subfolder
from .parts import Part, chunks, cover, scan, write_part
from .plan import Axis, SweepPlan, make_plan
from .texts import say

CHUNK_SECONDS = 0.15
#: summary column → unit (SI)
UNITS = {"max_v": "m/s", "max_a": "m/s^2", "max_omega": "rad/s", "max_epsilon": "rad/s^2",
         "min_gamma": "deg", "max_M_b": "N*m"}


@dataclass(frozen=True)
class SweepResult:
    """What a sweep wrote."""

    variants: int
    chunks: int
    skipped_chunks: int
    parquet: Path
    csv: Path
    plot: Path | None
    columns: tuple[str, ...]
    cpu_seconds: float = 0.0     # CPU time the workers spent evaluating chunks


def _variant(plan: SweepPlan, index: tuple[int, ...]
             ) -> tuple[Construction | None, dict[str, float], str]:
    """The construction of one variant (prepared steps swapped in), its guide angles, or an
    error."""
    base = plan.base
    steps = dict(base.steps)
    drive = base.drive
    guides = dict(plan.guides)
    for dep, table in plan.tables.items():
        combo = tuple(index[i] for i in dep)
        row = table[combo]
        if row is None:
            return None, guides, plan.errors[(dep, combo)]
        for name, value in row.items():
            if name == "__drive__":
                drive = value
            elif name.startswith("__guide__."):
                guides[name[len("__guide__."):]] = value
            else:
                steps[name] = value
    return (Construction(drive, steps, base.segments, base.equations, base.results,
                         second_driver=base.second_driver), guides, "")


def evaluate_chunk(plan: SweepPlan, start: int, stop: int
                   ) -> tuple[int, dict[str, np.ndarray], float]:
    """Evaluate variants ``start``…``stop - 1`` over the cycle.

    Return the start, the summary columns and the CPU seconds the worker spent.
    """
    # the force plan's evaluators are registered when its module is imported (a fresh worker)
    from ..construct.plans import force  # noqa: F401

    cpu0 = time.process_time()
    n = stop - start
    grid = np.unravel_index(np.arange(start, stop), plan.shape)
    summ = plan.summaries
    targets = summ.targets()
    buf: dict[str, np.ndarray] = {}
    guide_angle = {g: np.full(n, np.nan) for g in plan.guides}
    errors = np.full(n, "", dtype=object)
    for k in range(n):
        c, guides, error = _variant(plan, tuple(int(a[k]) for a in grid))
        if c is None:
            errors[k] = error
            continue
        ev = c.evaluate(plan.phi)
        ev.evaluate_all(targets)
        for t in targets:
            value = ev.values[t]
            if t not in buf:
                buf[t] = np.full((n, *value.shape), np.nan)
            buf[t][k] = value
        for g, angle in guides.items():
            guide_angle[g][k] = angle
    cols: dict[str, np.ndarray] = {"variant": np.arange(start, stop, dtype=np.int64)}
    for ax, idx in zip(plan.axes, grid, strict=True):
        cols[ax.key] = np.asarray(ax.values)[idx]
    if not buf:           # no variant of the chunk could be built
        buf = {t: np.full((n, plan.phi.size, 2), np.nan) for t in targets}
    bad = _summarise(plan, buf, guide_angle, cols, n)
    cols["unbuilt"] = bad.sum(axis=1).astype(np.int32)
    cols["error"] = errors
    return start, cols, time.process_time() - cpu0


def _summarise(plan: SweepPlan, buf: dict[str, np.ndarray], guide_angle: dict[str, np.ndarray],
               cols: dict[str, np.ndarray], n: int) -> np.ndarray:
    """Add the summary columns; return where (variant, position) a quantity is NaN (unbuilt)."""
    summ = plan.summaries
    bad = np.zeros((n, plan.phi.size), dtype=bool)

    def _fmax(x: np.ndarray) -> np.ndarray:
        bad[...] |= np.isnan(x)
        return np.fmax.reduce(x, axis=1)
    for sym, table in (("v", summ.velocity), ("a", summ.acceleration)):
        for p, sid in table.items():
            v = buf[sid]
            cols[f"max_{sym}_{p}"] = _fmax(np.hypot(v[..., 0], v[..., 1]))
    for sym, table in (("omega", summ.omega), ("epsilon", summ.epsilon)):
        for lid, sid in table.items():
            cols[f"max_{sym}_{lid}"] = _fmax(np.abs(buf[sid]))
    for name, (kind, (s1, s2, s3), guide) in summ.groups.items():
        u = buf[s2] - buf[s1]
        if kind == "RRR":
            w = buf[s3] - buf[s2]
            with np.errstate(invalid="ignore", divide="ignore"):
                cos = np.abs((u * w).sum(-1)) / (np.hypot(*np.moveaxis(u, -1, 0))
                                                 * np.hypot(*np.moveaxis(w, -1, 0)))
            gamma = np.degrees(np.arccos(np.clip(cos, 0.0, 1.0)))
        else:
            g = guide_angle[guide][:, None]
            with np.errstate(invalid="ignore", divide="ignore"):
                cos = np.abs(u[..., 0] * np.cos(g) + u[..., 1] * np.sin(g)) / np.hypot(
                    u[..., 0], u[..., 1])
            gamma = 90.0 - np.degrees(np.arccos(np.clip(cos, 0.0, 1.0)))
        bad |= np.isnan(gamma)
        cols[f"min_gamma_{name}"] = np.fmin.reduce(gamma, axis=1)
    if summ.moment:
        cols["max_M_b"] = _fmax(np.abs(buf[summ.moment]))
    return bad


def unit_of(column: str) -> str:
    """The SI unit of a summary column."""
    return next((u for prefix, u in UNITS.items() if column.startswith(prefix + "_")
                 or column == prefix), "")


def _chunk_size(plan: SweepPlan, workers: int) -> int:
    evaluate_chunk(plan, 0, 1)                       # warm up
    probe_stop = min(plan.size, 20)
    # CPU time, not wall time: on a busy machine the wall time would shrink the chunks
    per_variant = max(evaluate_chunk(plan, 0, probe_stop)[2] / probe_stop, 1e-6)
    size = max(1, math.ceil(CHUNK_SECONDS / per_variant))
    if plan.size < size * workers:          # small sweep: one chunk per worker
        size = max(1, math.ceil(plan.size / workers))
    return size


#: the layout of the parts folder (a new one when it changes: old parts are not read)
PARTS_FORMAT = 2
#: temporary files of the summary files an interrupted run may leave in the output folder
_OUTPUTS = ("summary.parquet.", "summary.csv.", "sweep.json.")


def _fingerprint(text: str, axes: Sequence[Axis], positions: int) -> str:
    """What the rows depend on: the scene, the grid, the positions — not the chunking."""
    h = hashlib.sha256()
    h.update(json.dumps([__version__, PARTS_FORMAT, text,
                         [(a.key, a.values, a.unit) for a in axes], positions]).encode())
    return h.hexdigest()[:16]


def _to_table(cols: dict[str, np.ndarray]) -> Any:
    import pyarrow as pa

    arrays = {k: pa.array(v.tolist() if v.dtype == object else v) for k, v in cols.items()}
    return pa.table(arrays)


def run_sweep(scene: str | Path, axes: Sequence[Axis], out_dir: str | Path, *,
              positions: int = 360, workers: int | None = None, scheduler: str | None = None,
              progress: bool | None = None, chunk: int | None = None,
              plot: str | None = None, plot_axes: Sequence[str] | None = None) -> SweepResult:
    """Evaluate every variant of the grid; write ``summary.parquet``, ``summary.csv`` (and a
    plot).

    A re-run resumes: the variants valid parts already hold are not evaluated again, whatever
    chunk sizes wrote them; the summary holds every variant exactly once, in order.
    """
    if chunk is not None and chunk < 1:
        raise MechplanError(say("chunk", value=chunk))
    if scheduler:
        check_scheduler(scheduler)
    check_sweep_budget(axes, positions)
    scene = Path(scene)
    text = read_text(scene)
    out = prepare_output(out_dir)
    with locked(out):
        remove_stale(out, (*_OUTPUTS, *((f"{plot}.png.",) if plot else ())))
        plan = make_plan(text, str(scene), axes, positions)
        fingerprint = _fingerprint(text, axes, positions)
        folder = subfolder(out, f"parts-{fingerprint}")
        kept = scan(folder, fingerprint, plan.size)
        gaps = cover(kept, plan.size).gaps
        size = chunk or (_chunk_size(plan, workers or default_workers()) if gaps else None)
        todo = [(plan.restricted(a, b), a, b) for a, b in chunks(gaps, size or 1)]
        cpu = 0.0
        written: set[Path] = set()
        for start, cols, seconds in run_tasks(evaluate_chunk, todo, workers=workers,
                                              scheduler=scheduler, progress=progress,
                                              desc="chunks", unit="chunk"):
            cpu += seconds
            part = write_part(folder, fingerprint, _to_table(cols), start,
                              start + len(cols["variant"]))
            kept.append(part)
            written.add(part.path)
        final = cover(kept, plan.size)
        if final.gaps:          # a bug, never a user's doing: refuse to write a short summary
            raise RuntimeError(f"sweep parts leave variants {final.gaps} out")
        parquet, csv_path = out / "summary.parquet", out / "summary.csv"
        columns = _merge(final.segments, plan.size, parquet, csv_path)
        for part in final.unused:        # covered entirely by other parts
            part.path.unlink(missing_ok=True)
        meta = {"scene": str(scene), "positions": positions, "variants": plan.size,
                "chunk": size, "axes": [{"key": a.key, "unit": a.unit,
                                         "values": list(a.values)} for a in axes],
                "units": {c: unit_of(c) for c in columns if unit_of(c)},
                "builds": plan.builds,
                "prepared_steps": {n: list(d) for n, d in plan.depends.items() if d}}
        write_atomic(out / "sweep.json", json.dumps(meta, ensure_ascii=False,
                                                    indent=1).encode())
        png = None
        if plot:
            from .plot import plot_summary

            png = plot_summary(parquet, plan, plot, plot_axes, out / f"{plot}.png")
    reused = sum(p.path not in written for p, _, _ in final.segments)
    return SweepResult(plan.size, len(final.segments), reused, parquet, csv_path, png,
                       tuple(columns), cpu)


def _merge(segments: Sequence[tuple[Part, int, int]], size: int, parquet: Path,
           csv_path: Path) -> list[str]:
    """Stream the parts' rows, in order, into one Parquet file and one CSV file (atomically);
    verify before either is in place that they hold every variant ``0…size - 1`` once."""
    import pyarrow.csv as pcsv
    import pyarrow.parquet as pq

    schema = pq.read_schema(segments[0][0].path).remove_metadata()
    rows = 0
    with atomic_open(parquet) as pfh, atomic_open(csv_path) as cfh:
        pw = pq.ParquetWriter(pfh, schema)
        cw = pcsv.CSVWriter(cfh, schema)
        try:
            for part, lo, hi in segments:
                table = pq.read_table(part.path).slice(lo - part.start, hi - lo)
                table = table.replace_schema_metadata(None)
                if not np.array_equal(table.column("variant").to_numpy(),
                                      np.arange(rows, rows + table.num_rows)) or lo != rows:
                    raise RuntimeError(f"sweep part {part.path.name} does not hold variants "
                                       f"{lo}…{hi - 1}")
                rows += table.num_rows
                pw.write_table(table)
                cw.write_table(csv_safe_table(table))
        finally:
            pw.close()
            cw.close()
        if rows != size:
            raise RuntimeError(f"the sweep summary would hold {rows} of {size} variants")
    return list(schema.names)
