"""Same work: submissions whose drawings are one geometry up to a move, a rotation, a mirror or a
scale, or whose tables hold the same entries, listed with the evidence (never graded down)."""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass
from itertools import combinations
from typing import Any

#: two drawings are the same when every line length (as a share of the longest) agrees this well
RELATIVE = 1e-4
#: fewest lines / entries worth comparing
MIN_ITEMS = 5


@dataclass(frozen=True)
class Fingerprint:
    """What is compared: the raw bytes' hash, the sorted relative line lengths, the table."""

    who: str
    digest: str
    lengths: tuple[float, ...] = ()
    entries: frozenset[tuple[str, str]] = frozenset()


def fingerprint(who: str, data: bytes, submission: Any | None) -> Fingerprint:
    """The fingerprint of one submission (``submission`` as mechplan read it, or None)."""
    digest = hashlib.sha256(data).hexdigest()
    if submission is None:
        return Fingerprint(who, digest)
    lengths = [math.dist(ln.start, ln.end) for ln in submission.lines]
    lengths = [x for x in lengths if x > 1e-9]
    top = max(lengths, default=0.0)
    rel = tuple(sorted(x / top for x in lengths)) if top else ()
    entries = frozenset((" ".join((e.section or "", e.name)).strip().casefold(),
                         " ".join(str(x) for x in (e.length, e.mu, e.quantity, e.value, e.text)
                                  if x)) for e in submission.entries)
    return Fingerprint(who, digest, rel, entries)


@dataclass(frozen=True)
class Same:
    """A pair of students with the same work, and why."""

    first: str
    second: str
    evidence: str          # "identical file", "same geometry", "same table"
    detail: str            # e.g. "412 lines, scale 1.25"


def _same_lengths(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return len(a) == len(b) >= MIN_ITEMS and all(abs(x - y) <= RELATIVE for x, y in zip(a, b,
                                                                                      strict=True))


def same_work(prints: list[Fingerprint]) -> list[Same]:
    """Every pair of submissions that are the same work."""
    out: list[Same] = []
    for a, b in combinations(prints, 2):
        if a.who == b.who:
            continue
        if a.digest == b.digest:
            out.append(Same(a.who, b.who, "identical file", a.digest[:12]))
        elif _same_lengths(a.lengths, b.lengths):
            out.append(Same(a.who, b.who, "same geometry", str(len(a.lengths))))
        elif len(a.entries) >= MIN_ITEMS and a.entries == b.entries:
            out.append(Same(a.who, b.who, "same table", str(len(a.entries))))
    return out
