"""Tooth-number search of a planetary stage: every set in the range that meets every condition.

Two enumerations give the same sets:

- :func:`plain_sets` — the plain vectorised one: the whole grid of free tooth numbers (z1, z2, z3 of
  a two-row train, z4 from coaxiality), evaluated in blocks;
- :func:`candidate_sets` — the search used: over the (z1, z2) grid only; for each pair the ratio
  band is solved for z3 (i_14^h is monotonic in z3 once coaxiality fixes z4 = q·(z1 ± z2) ± z3), so
  only the few z3 that can meet the ratio are generated.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import PlanetarySpec, Scheme
from . import train

BLOCK = 8 * 1024 * 1024      # grid cells per block of the plain enumeration


def _coaxial_pairs(spec: PlanetarySpec) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """(z1, z2) grid of a two-row train with the integer q·S (S = z1 ± z2) and τ
    (z4 = qS + τ z3)."""
    lo, hi = spec.z_range
    zs = np.arange(lo, hi + 1, dtype=np.int64)
    z1, z2 = (a.ravel() for a in np.meshgrid(zs, zs, indexing="ij"))
    int1, int2 = spec.scheme.internal
    S = z1 - z2 if int1 else z1 + z2
    qS = train.module_ratio(spec) * S
    qS_r = np.rint(qS).astype(np.int64)
    keep = (np.abs(qS - qS_r) < 1e-9) & (S > 0)
    return z1[keep], z2[keep], qS_r[keep], (1 if int2 else -1)


def _single_row(spec: PlanetarySpec, delta: int = 0) -> np.ndarray:
    lo, hi = spec.z_range
    zs = np.arange(lo, hi + 1, dtype=np.int64)
    z1, z2 = (a.ravel() for a in np.meshgrid(zs, zs, indexing="ij"))
    z3 = z1 + 2 * z2 + delta
    keep = (z3 <= hi) & (z3 >= lo)
    return np.stack([z1[keep], z2[keep], z3[keep]], axis=1)


def offsets(spec: PlanetarySpec) -> range:
    """Tooth-sum offsets δ of the last gear from its unshifted coaxial value: 0 alone, or with a
    working centre distance every δ that shift sums within ``max_shift_sum`` may reach."""
    if not train.shifted(spec):
        return range(1)
    reach = math.ceil(2.5 * spec.max_shift_sum) + 2
    if spec.centre_distance is not None:     # the given a_w may sit far from the standard ones
        m = spec.modules[1] if spec.scheme.two_row else spec.modules[0]
        reach += math.ceil(2 * spec.centre_distance / m)
    return range(-reach, reach + 1)


def _keep_shifted(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    return z[train.shift_ok(spec, z)] if train.shifted(spec) and z.shape[0] else z


def plain_sets(spec: PlanetarySpec) -> Iterator[np.ndarray]:
    """Every coaxial set in the range (with a working centre distance: coaxial with shifted
    gears), in blocks of shape (n, g) (the plain enumeration)."""
    for delta in offsets(spec):
        for block in _plain_sets(spec, delta):
            yield _keep_shifted(spec, block)


def _plain_sets(spec: PlanetarySpec, delta: int) -> Iterator[np.ndarray]:
    if spec.scheme is Scheme.SINGLE_ROW:
        yield _single_row(spec, delta)
        return
    lo, hi = spec.z_range
    z1, z2, qS, tau = _coaxial_pairs(spec)
    qS = qS + delta
    z3 = np.arange(lo, hi + 1, dtype=np.int64)
    step = max(1, BLOCK // z3.size)
    for start in range(0, z1.size, step):
        a, b, s = z1[start:start + step], z2[start:start + step], qS[start:start + step]
        Z3 = np.broadcast_to(z3, (a.size, z3.size))
        Z4 = s[:, None] + tau * Z3
        ok = (Z4 >= lo) & (Z4 <= hi)
        rows, cols = np.nonzero(ok)
        yield np.stack([a[rows], b[rows], Z3[rows, cols], Z4[rows, cols]], axis=1)


def ratio_mask(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    """Sets whose ratio is within the allowed deviation of the target."""
    u = train.ratio_from_i(train.willis_i(spec.scheme, z), spec.scheme, spec.fixed, spec.input,
                           spec.output)
    with np.errstate(invalid="ignore"):
        return np.abs(u - spec.ratio) <= (spec.deviation + 1e-12) * abs(spec.ratio)


def candidate_sets(spec: PlanetarySpec) -> np.ndarray:
    """Coaxial sets in the range (with a working centre distance: coaxial with shifted gears)
    whose ratio may meet the band (a superset of those that do)."""
    parts = [_keep_shifted(spec, _candidate_sets(spec, delta)) for delta in offsets(spec)]
    return np.concatenate(parts) if len(parts) > 1 else parts[0]


def _candidate_sets(spec: PlanetarySpec, delta: int) -> np.ndarray:
    if spec.scheme is Scheme.SINGLE_ROW:
        return _single_row(spec, delta)
    lo, hi = spec.z_range
    z1, z2, qS, tau = _coaxial_pairs(spec)
    qS = qS + delta
    band = spec.deviation * abs(spec.ratio)
    u_lo, u_hi = spec.ratio - band, spec.ratio + band
    i_a = train.i_from_ratio(u_lo, spec.scheme, spec.fixed, spec.input, spec.output)
    i_b = train.i_from_ratio(u_hi, spec.scheme, spec.fixed, spec.input, spec.output)
    s = train.willis_sign(spec.scheme)
    full = np.full(z1.size, True) if not (np.isfinite(i_a) and np.isfinite(i_b)
                                          and u_lo * u_hi > 0) else np.full(z1.size, False)
    with np.errstate(divide="ignore", invalid="ignore"):
        i_pole = s * tau * z2 / z1                     # z3 → ∞
        full |= (i_pole >= min(i_a, i_b)) & (i_pole <= max(i_a, i_b))
        z3a = s * z2 * qS / (i_a * z1 - s * tau * z2)
        z3b = s * z2 * qS / (i_b * z1 - s * tau * z2)
    bad = ~(np.isfinite(z3a) & np.isfinite(z3b))
    full |= bad
    z3a, z3b = np.where(bad, lo, z3a), np.where(bad, hi, z3b)
    first = np.where(full, lo, np.maximum(lo, np.floor(np.minimum(z3a, z3b)) - 1)).astype(np.int64)
    last = np.where(full, hi, np.minimum(hi, np.ceil(np.maximum(z3a, z3b)) + 1)).astype(np.int64)
    count = np.maximum(last - first + 1, 0)
    rows = np.repeat(np.arange(z1.size), count)
    offset = np.arange(rows.size) - np.repeat(np.cumsum(count) - count, count)
    z3 = first[rows] + offset
    z4 = qS[rows] + tau * z3
    keep = (z4 >= lo) & (z4 <= hi)
    return np.stack([z1[rows][keep], z2[rows][keep], z3[keep], z4[keep]], axis=1)


STAGES = ("ratio", "z_min", "ring_difference", "assembly", "neighbour")


def _stage_masks(spec: PlanetarySpec, z: np.ndarray, k: int | None = None) -> list[np.ndarray]:
    return [ratio_mask(spec, z),
            z.min(axis=1) >= spec.z_min,
            (train.ring_differences(spec, z) >= spec.ring_difference).all(axis=1),
            train.assembles(spec, z, k),
            train.neighbour_gap(spec, z, k) > 0]


def _apply(spec: PlanetarySpec, z: np.ndarray) -> tuple[np.ndarray, list[int]]:
    counts = []
    for stage in range(len(STAGES)):
        z = z[_stage_masks(spec, z)[stage]]
        counts.append(int(z.shape[0]))
    return z, counts


def rank(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    """Order sets by overall size, then ratio error, then tooth numbers."""
    if z.shape[0] == 0:
        return z
    size = np.round(train.envelope_diameter(spec, z) / 1e-9)
    u = train.ratio_from_i(train.willis_i(spec.scheme, z), spec.scheme, spec.fixed, spec.input,
                           spec.output)
    err = np.round(np.abs(u - spec.ratio) / 1e-12)
    keys = [z[:, j] for j in range(z.shape[1] - 1, -1, -1)] + [err, size]
    return z[np.lexsort(keys)]


@dataclass(frozen=True)
class SearchResult:
    """The sets that meet every condition, best first, and the survivors after each stage."""

    sets: np.ndarray
    counts: dict[str, int]


def search(spec: PlanetarySpec, *, plain: bool = False) -> SearchResult:
    """Every valid set, ranked; ``plain`` uses the plain enumeration (for comparison)."""
    if plain:
        parts = [_apply(spec, block) for block in plain_sets(spec)]
        z = np.concatenate([p[0] for p in parts]) if parts else np.zeros((0, 4), np.int64)
        counts = [sum(p[1][j] for p in parts) for j in range(len(STAGES))]
    else:
        z, counts = _apply(spec, candidate_sets(spec))
    return SearchResult(rank(spec, z), dict(zip(STAGES, counts)))


def nearest(spec: PlanetarySpec) -> tuple[tuple[int, ...], float] | None:
    """The coaxial set in the range whose ratio is nearest the target (for the error message)."""
    best: tuple[float, tuple[int, ...], float] | None = None
    for z in plain_sets(spec):
        if z.shape[0] == 0:
            continue
        u = train.ratio_from_i(train.willis_i(spec.scheme, z), spec.scheme, spec.fixed,
                               spec.input, spec.output)
        err = np.where(np.isfinite(u), np.abs(u - spec.ratio), np.inf)
        j = int(np.argmin(err))
        if best is None or err[j] < best[0]:
            best = (float(err[j]), tuple(int(v) for v in z[j]), float(u[j]))
    return None if best is None else (best[1], best[2])


def explain_empty(spec: PlanetarySpec, result: SearchResult) -> SceneError:
    """The error naming the key whose condition no set in the range can meet."""
    c = result.counts
    lo, hi = spec.z_range
    where = Text("errmsg.gears_search.where", {"lo": str(lo), "hi": str(hi),
                                               "scheme": str(spec.scheme.value)})
    target = f"u = {spec.ratio:g} ± {spec.deviation * 100:g} %"
    if c["ratio"] == 0:
        near = nearest(spec)
        hint = (Text("errmsg.gears_search.nearest", {"u": f"{near[1]:.4g}",
                                                      "z": ", ".join(map(str, near[0]))})
                if near else Text("errmsg.gears_search.no_coaxial"))
        return SceneError(Text("errmsg.gears_search.no_tooth_set",
                               {"where": where, "target": target, "hint": hint}),
                          key="planetary.ratio")
    if c["z_min"] == 0:
        return SceneError(Text("errmsg.gears_search.z_min", {"where": where, "target": target,
                                                              "z_min": str(spec.z_min)}),
                          key="planetary.z_min")
    if c["ring_difference"] == 0:
        return SceneError(Text("errmsg.gears_search.ring_difference",
                               {"where": where, "target": target,
                                "difference": str(spec.ring_difference)}),
                          key="planetary.ring_difference")
    z = candidate_sets(spec)
    for stage in range(3):
        z = z[_stage_masks(spec, z)[stage]]
    possible = [k for k in range(2, 13)
                if np.any(train.assembles(spec, z, k) & (train.neighbour_gap(spec, z, k) > 0))]
    alt = (Text("errmsg.gears_search.k_can", {"k": ", ".join(map(str, possible))}) if possible
           else Text("errmsg.gears_search.no_k_can"))
    what = (Text("errmsg.gears_search.not_assembled") if c["assembly"] == 0
            else Text("errmsg.gears_search.not_side_by_side"))
    return SceneError(Text("errmsg.gears_search.planets",
                           {"planets": str(spec.planets), "what": what, "where": where,
                            "target": target, "alt": alt}), key="planetary.planets")


def best_or_error(spec: PlanetarySpec) -> SearchResult:
    """Search, and raise the explaining error when no set meets every condition."""
    result = search(spec)
    if result.sets.shape[0] == 0:
        raise explain_empty(spec, result)
    return result
