"""The follower's motion over a cam turn: s(φ), s′ = ds/dφ, s″ = d²s/dφ² (exact, vectorised).

φ is the cam angle from the start of the first phase, in rad; values outside [0, 2π) wrap.
A return is the mirror image of its law: s = h·(1 − y(x)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...model.cam import Law, Phase, PhaseKind
from .laws import normalised

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Motion:
    """s, s′, s″ at the cam angles ``phi`` (rad); s in the stroke's unit (m or rad)."""

    phi: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray


def phase_starts(phases: tuple[Phase, ...]) -> np.ndarray:
    """Cam angle at the start of each phase and at the end of the last (rad)."""
    return np.concatenate([[0.0], np.cumsum([p.angle for p in phases])])


def motion(phases: tuple[Phase, ...], stroke: float, phi: np.ndarray | float) -> Motion:
    """Evaluate the program at ``phi``; the follower starts each turn at s = 0 (near position)."""
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    wrapped = np.mod(phi, TWO_PI)
    starts = phase_starts(phases)
    s = np.zeros_like(wrapped)
    s1 = np.zeros_like(wrapped)
    s2 = np.zeros_like(wrapped)
    index = np.clip(np.searchsorted(starts, wrapped, side="right") - 1, 0, len(phases) - 1)
    for i, p in enumerate(phases):
        m = index == i
        beta = p.angle
        if p.kind in (PhaseKind.RISE, PhaseKind.RETURN) and p.law is not None:
            x = np.clip((wrapped[m] - starts[i]) / beta, 0.0, 1.0)
            table = p.table
            if p.law is Law.TABLE_S:
                # a table of s is stored in the stroke's unit: normalise it to 0 … 1
                t = np.asarray(table, float) / stroke
                table = tuple(t if p.kind is PhaseKind.RISE else 1.0 - t)
            y, y1, y2 = normalised(p.law, x, blend=p.blend, table=table, key=p.key)
            sign = 1.0 if p.kind is PhaseKind.RISE else -1.0
            base = 0.0 if p.kind is PhaseKind.RISE else stroke
            s[m] = base + sign * stroke * y
            s1[m] = sign * stroke * y1 / beta
            s2[m] = sign * stroke * y2 / beta ** 2
        else:
            s[m] = stroke if p.kind is PhaseKind.FAR_DWELL else 0.0
    return Motion(phi, s, s1, s2)


def phase_of(phases: tuple[Phase, ...], phi: np.ndarray) -> np.ndarray:
    """Index of the phase each cam angle falls in."""
    starts = phase_starts(phases)
    return np.clip(np.searchsorted(starts, np.mod(phi, TWO_PI), side="right") - 1, 0,
                   len(phases) - 1)
