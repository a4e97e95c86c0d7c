"""A sweep's Parquet parts: each holds an exact range of variants, named and stamped with it.

``part-<start>-<stop>.parquet`` holds variants ``start``…``stop - 1`` and records the range and the
sweep's fingerprint in its metadata. A resume keeps the parts whose name, metadata, row count and
``variant`` column agree, removes the rest and the temporary files of interrupted writes, and
evaluates only the variants no kept part covers — so the result does not depend on how the sweep
was chunked, interrupted or resumed. Only the owner of the folder's lock calls these.
"""

from __future__ import annotations

import contextlib
import json
import re
import stat
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..render.atomic import atomic_open
from .outdir import remove_stale

META_KEY = b"mechplan.sweep.part"
_NAME = re.compile(r"^part-(\d{12})-(\d{12})\.parquet$")


@dataclass(frozen=True, slots=True)
class Part:
    """A valid part file holding variants ``start``…``stop - 1``."""

    path: Path
    start: int
    stop: int


def part_path(folder: Path, start: int, stop: int) -> Path:
    """The file of the part holding variants ``start``…``stop - 1``."""
    return folder / f"part-{start:012d}-{stop:012d}.parquet"


def write_part(folder: Path, fingerprint: str, table: Any, start: int, stop: int) -> Part:
    """Write a chunk's table as a part (atomically), with its range in the metadata."""
    import pyarrow.parquet as pq

    meta = json.dumps({"fingerprint": fingerprint, "start": start, "stop": stop}).encode()
    table = table.replace_schema_metadata({**(table.schema.metadata or {}), META_KEY: meta})
    path = part_path(folder, start, stop)
    with atomic_open(path) as fh:
        pq.write_table(table, fh)
    return Part(path, start, stop)


def _valid(path: Path, fingerprint: str, size: int) -> Part | None:
    """The part a file is, or None when its name, metadata or variants disagree."""
    import pyarrow.parquet as pq

    m = _NAME.match(path.name)
    if not m:
        return None
    start, stop = int(m.group(1)), int(m.group(2))
    if not 0 <= start < stop <= size:
        return None
    try:
        if not stat.S_ISREG(path.lstat().st_mode):      # never read through a link
            return None
        pf = pq.ParquetFile(path)
        meta = json.loads((pf.schema_arrow.metadata or {}).get(META_KEY, b"{}"))
        if (meta != {"fingerprint": fingerprint, "start": start, "stop": stop}
                or pf.metadata.num_rows != stop - start):
            return None
        variants = pf.read(columns=["variant"]).column("variant").to_numpy()
    except Exception:  # noqa: BLE001 - a damaged file is any error of the reader: redo it
        return None
    if not np.array_equal(variants, np.arange(start, stop)):
        return None
    return Part(path, start, stop)


def scan(folder: Path, fingerprint: str, size: int) -> list[Part]:
    """Keep the valid parts of a folder; remove damaged or foreign part files and stale
    temporary files. Return the kept parts sorted by (start, -stop)."""
    remove_stale(folder, ("part-",))
    parts: list[Part] = []
    for entry in folder.iterdir():
        if not entry.name.startswith("part-"):
            continue
        part = _valid(entry, fingerprint, size)
        if part is None:
            with contextlib.suppress(FileNotFoundError, IsADirectoryError, PermissionError):
                entry.unlink()
        else:
            parts.append(part)
    return sorted(parts, key=lambda p: (p.start, -p.stop))


@dataclass(frozen=True, slots=True)
class Cover:
    """How parts cover ``0…size - 1``: the rows to take from each part, in order, and the gaps."""

    segments: list[tuple[Part, int, int]]      # (part, lo, hi): variants lo…hi - 1 of it
    gaps: list[tuple[int, int]]                # variants lo…hi - 1 no part holds
    unused: list[Part]                         # parts other parts cover entirely


def cover(parts: list[Part], size: int) -> Cover:
    """Choose, left to right, the part reaching farthest at each point; each variant once."""
    segments: list[tuple[Part, int, int]] = []
    gaps: list[tuple[int, int]] = []
    used: set[Path] = set()
    pos, i = 0, 0
    ordered = sorted(parts, key=lambda p: (p.start, -p.stop))
    while pos < size:
        best: Part | None = None
        while i < len(ordered) and ordered[i].start <= pos:
            if ordered[i].stop > pos and (best is None or ordered[i].stop > best.stop):
                best = ordered[i]
            i += 1
        if best is not None:
            segments.append((best, pos, best.stop))
            used.add(best.path)
            pos = best.stop
            continue
        nxt = ordered[i].start if i < len(ordered) else size
        gaps.append((pos, nxt))
        pos = nxt
    return Cover(segments, gaps, [p for p in parts if p.path not in used])


def chunks(gaps: list[tuple[int, int]], size: int) -> list[tuple[int, int]]:
    """Cut the gaps into chunks of at most ``size`` consecutive variants."""
    return [(a, min(a + size, hi)) for lo, hi in gaps for a in range(lo, hi, size)]
