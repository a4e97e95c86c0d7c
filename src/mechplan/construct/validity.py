"""Where a construction cannot be built: unreachable crank-angle intervals and singular meets."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ..errors import SingularError, UnreachableError
from ..i18n import Text, plan_word
from .graph import Construction, Evaluation

#: meets whose condition number 1/|sin| exceeds this are refused (≈ 8 significant digits kept)
MAX_CONDITION = 1e8
TWO_PI = 2.0 * math.pi


def valid_mask(ev: Evaluation, max_condition: float = MAX_CONDITION) -> np.ndarray:
    """Positions where every evaluated meet exists and is well conditioned."""
    ok = np.ones(ev.n, dtype=bool)
    for gap in ev.gaps.values():
        ok &= ~(gap > 0)
    for sine in ev.sines.values():
        with np.errstate(divide="ignore"):
            ok &= ~(1.0 / sine > max_condition)
    return ok


def _gap_function(c: Construction, step_id: str) -> Callable[[np.ndarray], np.ndarray]:
    def gap(phi: np.ndarray) -> np.ndarray:
        ev = c.evaluate(phi)
        ev.get(step_id)
        return ev.gaps[step_id]
    return gap


def unreachable_intervals(c: Construction, step_id: str, samples: int = 3600,
                          iterations: int = 60) -> list[tuple[float, float]]:
    """Crank-angle intervals (φ, rad, scene convention) where a meet has no solution.

    Boundaries are refined by bisection on the sign of the gap to ~1e-15 rad.
    """
    gap = _gap_function(c, step_id)
    phi = np.linspace(0.0, TWO_PI, samples, endpoint=False)
    bad = gap(phi) > 0
    if not bad.any():
        return []
    if bad.all():
        return [(0.0, TWO_PI)]
    nxt = np.roll(bad, -1)
    starts = np.nonzero(~bad & nxt)[0]    # good → bad between i and i+1
    ends = np.nonzero(bad & ~nxt)[0]      # bad → good
    step = TWO_PI / samples

    def refine(idx: np.ndarray, entering: bool) -> np.ndarray:
        lo, hi = phi[idx], phi[idx] + step
        for _ in range(iterations):
            mid = 0.5 * (lo + hi)
            m_bad = gap(mid) > 0
            go_right = ~m_bad if entering else m_bad
            lo, hi = np.where(go_right, mid, lo), np.where(go_right, hi, mid)
        out: np.ndarray = 0.5 * (lo + hi)
        return out

    s = np.mod(refine(starts, True), TWO_PI)
    e = np.mod(refine(ends, False), TWO_PI)
    s.sort()
    e.sort()
    intervals = []
    for a in s:
        later = e[e > a]
        b = later[0] if later.size else e[0]
        intervals.append((float(a), float(b)))
    return intervals


def ensure_valid(c: Construction, ev: Evaluation, file: str | None = None,
                 max_condition: float = MAX_CONDITION) -> None:
    """Raise for the first position a user asked for that cannot be built or is singular."""
    for sid in c.ancestors(ev.values):
        if sid in ev.gaps and np.any(ev.gaps[sid] > 0):
            step = c[sid]
            k = int(np.argmax(ev.gaps[sid] > 0))
            phi_deg = math.degrees(ev.phi[k])
            intervals = [
                (math.degrees(a), math.degrees(b)) for a, b in unreachable_intervals(c, sid)
            ]
            where = ", ".join(f"{a:.9f}°…{b:.9f}°" for a, b in intervals)
            raise UnreachableError(
                Text("errors.unreachable", {"group": step.group, "phi": f"{phi_deg:g}",
                                            "point": step.label,
                                            "gap": f"{ev.gaps[sid][k] * 1000:.6g}",
                                            "where": where}),
                group=step.group, intervals_deg=intervals,
                gap=float(ev.gaps[sid][k]), file=file)
    for sid in c.ancestors(ev.values):
        if sid not in ev.sines:
            continue
        sine = ev.sines[sid]
        with np.errstate(divide="ignore"):
            cond = 1.0 / sine
        bad = cond > max_condition
        if np.any(bad):
            step = c[sid]
            k = int(np.argmax(bad))
            raise SingularError(
                Text("errors.singular", {"plan": plan_word(step.plan.value),
                                         "group": step.group or "I", "point": step.label,
                                         "phi": f"{math.degrees(ev.phi[k]):g}",
                                         "condition": f"{cond[k]:.3g}",
                                         "most": f"{max_condition:.0e}"}), step=step.label,
                phi_deg=math.degrees(ev.phi[k]), condition=float(cond[k]), file=file)
