"""Registration of two sets of line segments under a similarity (move, turn, scale, mirror):
which transform carries one drawing onto the other, how many segments it carries onto segments
of the other, and how far the carried endpoints land from them (the residual).

Hypotheses come from pairs of segments of about the same length relative to each drawing's
median segment (the longest segments of the first drawing against every such segment of the
second, both ways round, mirrored or not: two endpoints fix a similarity); each is scored by the
segments it carries within a tolerance (a k-d tree of the second drawing's segments as 4-D
points, both directions); the best is refitted by least squares (Umeyama's method, with the
mirror fixed) on all the endpoints it matched."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]

#: segments of the first drawing tried as the anchor of a hypothesis (the longest ones)
ANCHORS = 4
#: relative difference of (length / median length) for two segments to be tried as a pair
LENGTH_SLACK = 0.02
#: most pairs tried for one anchor
MAX_CANDIDATES = 40
#: segments every hypothesis is first scored on
SAMPLE = 64
#: hypotheses (the best on the sample) scored on the whole drawing
FULL = 8


@dataclass(frozen=True, slots=True)
class Similarity:
    """``y = scale · R(angle) · M · x + shift``, M the mirror ``diag(1, −1)`` when ``mirrored``."""

    scale: float
    angle_deg: float
    mirrored: bool
    shift: tuple[float, float]

    @property
    def matrix(self) -> Array:
        """The 2×2 linear part."""
        c, s = math.cos(math.radians(self.angle_deg)), math.sin(math.radians(self.angle_deg))
        m = np.array([[c, -s], [s, c]]) * self.scale
        return m @ np.diag([1.0, -1.0]) if self.mirrored else m

    def apply(self, pts: Array) -> Array:
        """Points (…, 2) carried by the transform."""
        out: Array = pts @ self.matrix.T + np.asarray(self.shift)
        return out


def fit_similarity(x: Array, y: Array, mirrored: bool) -> Similarity:
    """The similarity carrying points ``x`` (N, 2) closest to ``y`` (N, 2) in least squares
    (Umeyama 1991), a mirror included or not."""
    xm = x * np.array([1.0, -1.0]) if mirrored else x
    mx, my = xm.mean(axis=0), y.mean(axis=0)
    xc, yc = xm - mx, y - my
    var = float((xc**2).sum() / len(x))
    if var <= 0.0:
        return Similarity(1.0, 0.0, mirrored, (float(my[0] - mx[0]), float(my[1] - mx[1])))
    u, sv, vt = np.linalg.svd(yc.T @ xc / len(x))
    d = np.diag([1.0, 1.0 if np.linalg.det(u @ vt) >= 0 else -1.0])
    r = u @ d @ vt
    scale = float(np.trace(np.diag(sv) @ d) / var)
    shift = my - scale * (r @ mx)
    angle = math.degrees(math.atan2(r[1, 0], r[0, 0]))
    return Similarity(scale, angle, mirrored, (float(shift[0]), float(shift[1])))


@dataclass(frozen=True, slots=True)
class Registration:
    """The best similarity found and its evidence."""

    transform: Similarity
    matched: int              # segments of the first drawing carried onto one of the second
    residual: float           # RMS distance of the matched endpoints after the refit (units of b)
    size: float               # RMS radius of the second drawing's endpoints (units of b)

    @property
    def relative(self) -> float:
        """The residual as a share of the second drawing's size."""
        return self.residual / self.size if self.size else math.inf


def _size(seg: Array) -> float:
    pts = seg.reshape(-1, 2)
    return float(np.sqrt(((pts - pts.mean(axis=0)) ** 2).sum(axis=1).mean()))


def _matches(a: Array, tree: object, tol: float) -> NDArray[np.intp]:
    """Index into the second drawing's 4-D points of each carried segment, −1 when none."""
    dist, idx = tree.query(a.reshape(-1, 4), distance_upper_bound=tol)  # type: ignore[attr-defined]
    return np.where(np.isfinite(dist), idx, -1)


def _hypotheses(a: Array, b: Array, la: Array, ra: Array, rb: Array) -> tuple[Any, Any, Any]:
    """Similarities ``z ↦ s·z + t`` (``s·z̄ + t`` when mirrored), in complex numbers, carrying
    one of the longest segments of ``a`` onto a segment of ``b`` of about the same relative
    length, either way round, mirrored or not: arrays ``s``, ``t``, ``mirrored``."""
    za = a[..., 0] + 1j * a[..., 1]
    zb = b[..., 0] + 1j * b[..., 1]
    ss, ts, ms = [], [], []
    for i in np.argsort(-la)[:ANCHORS]:
        close = np.flatnonzero(np.abs(rb - ra[i]) <= LENGTH_SLACK * ra[i])
        close = close[np.argsort(np.abs(rb[close] - ra[i]))][:MAX_CANDIDATES]
        if not len(close):
            continue
        q0 = np.concatenate([zb[close, 0], zb[close, 1]])      # both ways round
        q1 = np.concatenate([zb[close, 1], zb[close, 0]])
        p0, p1 = za[i]
        for mirrored, d, z0 in ((False, p1 - p0, p0), (True, np.conj(p1 - p0), np.conj(p0))):
            s = (q1 - q0) / d
            ss.append(s)
            ts.append(q0 - s * z0)
            ms.append(np.full(len(s), mirrored))
    if not ss:
        return np.zeros(0, complex), np.zeros(0, complex), np.zeros(0, bool)
    return np.concatenate(ss), np.concatenate(ts), np.concatenate(ms)


def _carry(z: Any, s: Any, t: Any, mirrored: Any) -> Array:
    """Complex points ``z`` (K, 2) carried by each similarity: 4-D points (H, K, 4)."""
    w = s[:, None, None] * np.where(mirrored[:, None, None], np.conj(z), z) + t[:, None, None]
    return np.stack([w[..., 0].real, w[..., 0].imag, w[..., 1].real, w[..., 1].imag], axis=-1)


def _similarity(s: complex, t: complex, mirrored: bool) -> Similarity:
    return Similarity(abs(s), math.degrees(math.atan2(s.imag, s.real)), bool(mirrored),
                      (t.real, t.imag))


def register(a: Array, b: Array, tol: float = 1e-3) -> Registration | None:
    """The similarity carrying most segments ``a`` (N, 2, 2) onto segments ``b`` (M, 2, 2),
    matching within ``tol`` × the size of ``b``; None when either has fewer than two segments
    or no hypothesis carries two segments."""
    from scipy.spatial import cKDTree

    if len(a) < 2 or len(b) < 2:
        return None
    la = np.linalg.norm(a[:, 1] - a[:, 0], axis=1)
    lb = np.linalg.norm(b[:, 1] - b[:, 0], axis=1)
    ma, mb = float(np.median(la)), float(np.median(lb))
    if ma <= 0 or mb <= 0:
        return None
    size = _size(b)
    both = np.concatenate([b.reshape(-1, 4), b[:, ::-1].reshape(-1, 4)])
    tree = cKDTree(both)
    radius = tol * size
    s, t, mirrored = _hypotheses(a, b, la, la / ma, lb / mb)
    if not len(s):
        return None
    # every hypothesis scored at once on a sample of the drawing (every k-th segment); the
    # most promising ones scored on all of it
    sample = a[:: max(1, len(a) // SAMPLE)]
    zs = sample[..., 0] + 1j * sample[..., 1]
    dist, _ = tree.query(_carry(zs, s, t, mirrored).reshape(-1, 4), distance_upper_bound=radius)
    score = np.isfinite(dist).reshape(len(s), -1).sum(axis=1)
    za = a[..., 0] + 1j * a[..., 1]
    best: tuple[int, Similarity, NDArray[np.intp]] | None = None
    for h in np.argsort(-score, kind="stable")[:FULL]:
        if score[h] < 2:
            break
        hit = _matches(_carry(za, s[h:h + 1], t[h:h + 1], mirrored[h:h + 1])[0], tree, radius)
        n = int((hit >= 0).sum())
        if best is None or n > best[0]:
            best = (n, _similarity(complex(s[h]), complex(t[h]), bool(mirrored[h])), hit)
        if n >= len(a):
            break                                   # every segment carried: nothing better
    if best is None or best[0] < 2:
        return None
    n, t, hit = best
    ok = hit >= 0
    x = a[ok].reshape(-1, 2)
    y = both[hit[ok]].reshape(-1, 2)
    refit = fit_similarity(x, y, t.mirrored)
    residual = float(np.sqrt(((refit.apply(x) - y) ** 2).sum(axis=1).mean()))
    return Registration(refit, n, residual, size)
