"""Same work: submissions whose drawings are one geometry up to a move, a rotation, a mirror or a
scale, or whose tables hold the same entries, listed with the evidence (never graded down).

Two drawings are the same geometry when one similarity (found by registering their segment sets,
:mod:`mechplan.geom.registration`) carries at least :data:`SHARE` of the smaller drawing's lines
onto lines of the other with a residual under :data:`RESIDUAL` of its size; the evidence names
the transform (turn, scale, mirror, move), the lines matched and the residual."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from itertools import combinations
from typing import Any

import numpy as np

from ..geom.registration import Registration, register
from ..i18n import message, significant

#: fewest lines / entries worth comparing
MIN_ITEMS = 5
#: share of the smaller drawing's lines one similarity must carry onto the other's
SHARE = 0.9
#: largest RMS residual of the matched endpoints, as a share of the drawing's size: a copy moved,
#: turned or scaled in CAD lands within rounding; two drawings made apart never do
RESIDUAL = 1e-4
#: bins of the histogram of log(length / median) compared before registering (a quick sieve)
BINS = np.linspace(-4.0, 4.0, 33)
#: least overlap of two length histograms worth a registration
OVERLAP = 0.5


@dataclass(frozen=True)
class Fingerprint:
    """What is compared: the raw bytes' hash, the drawing's segments (K, 2, 2) and their length
    histogram, the table's entries."""

    who: str
    digest: str
    segments: Any = field(default=None, compare=False)
    histogram: Any = field(default=None, compare=False)
    entries: frozenset[tuple[str, str]] = frozenset()


def fingerprint(who: str, data: bytes, submission: Any | None) -> Fingerprint:
    """The fingerprint of one submission (``submission`` as mechplan read it, or None)."""
    digest = hashlib.sha256(data).hexdigest()
    if submission is None:
        return Fingerprint(who, digest)
    seg = np.array([(ln.start, ln.end) for ln in submission.lines], dtype=float).reshape(-1, 2, 2)
    length = np.linalg.norm(seg[:, 1] - seg[:, 0], axis=1)
    seg = seg[length > 1e-9]
    hist = None
    if len(seg):
        rel = np.log(length[length > 1e-9] / float(np.median(length[length > 1e-9])))
        counts, _ = np.histogram(np.clip(rel, BINS[0], BINS[-1]), BINS)
        hist = counts / counts.sum()
    entries = frozenset((" ".join((e.section or "", e.name)).strip().casefold(),
                         " ".join(str(x) for x in (e.length, e.mu, e.quantity, e.value, e.text)
                                  if x)) for e in submission.entries)
    return Fingerprint(who, digest, seg if len(seg) else None, hist, entries)


@dataclass(frozen=True)
class Same:
    """A pair of students with the same work, and why."""

    first: str
    second: str
    evidence: str          # "identical file", "same geometry", "same table"
    detail: str            # e.g. "412 lines, scale 1.25"


def same_geometry(a: Fingerprint, b: Fingerprint) -> Registration | None:
    """The registration of two drawings when they are the same geometry, else None."""
    if a.segments is None or b.segments is None:
        return None
    small = min(len(a.segments), len(b.segments))
    if small < MIN_ITEMS or float(np.minimum(a.histogram, b.histogram).sum()) < OVERLAP:
        return None
    first, second = (a, b) if len(a.segments) <= len(b.segments) else (b, a)
    found = register(first.segments, second.segments)
    if found is None or found.matched < SHARE * small or found.relative > RESIDUAL:
        return None
    return found


def geometry_detail(found: Registration, lines: int, lang: str = "en") -> str:
    """The evidence of a registration: lines matched, the transform, the residual."""
    t = found.transform
    return message("lms2.same_geometry", lang, matched=found.matched, lines=lines,
                   angle=significant(t.angle_deg, 4, lang), scale=significant(t.scale, 6, lang),
                   mirror=message("lms2.mirrored" if t.mirrored else "lms2.not_mirrored", lang),
                   dx=significant(t.shift[0], 4, lang), dy=significant(t.shift[1], 4, lang),
                   residual=significant(found.residual, 2, lang))


def same_work(prints: list[Fingerprint], lang: str = "en") -> list[Same]:
    """Every pair of submissions that are the same work."""
    out: list[Same] = []
    for a, b in combinations(prints, 2):
        if a.who == b.who:
            continue
        if a.digest == b.digest:
            out.append(Same(a.who, b.who, "identical file", a.digest[:12]))
        elif (found := same_geometry(a, b)) is not None:
            lines = min(len(a.segments), len(b.segments))
            out.append(Same(a.who, b.who, "same geometry", geometry_detail(found, lines, lang)))
        elif len(a.entries) >= MIN_ITEMS and a.entries == b.entries:
            out.append(Same(a.who, b.who, "same table", str(len(a.entries))))
    return out
