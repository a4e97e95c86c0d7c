"""The courses' graphical differentiation and integration of the motion diagrams, beside the exact.

Each rise and return is divided into ``divisions`` equal parts. Differentiation by chords: the slope
of the chord of s over a part is s′ at the part's middle (drawn through the pole at the pole
distance H, parallel to the chord); s″ likewise from the chords of that s′ curve. Integration (the
route of the worked example, a → v → s) by mean ordinates: each strip of s″ is replaced by the
rectangle of its middle ordinate, so s′ grows by s″(middle)·Δφ across a part, and s by the area of
the trapezoid under the integrated s′ (the chord of the integral curve).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...model.cam import Phase, PhaseKind
from .motion import motion, phase_starts


@dataclass(frozen=True)
class PhaseComparison:
    """Largest differences of the graphical results from the exact ones over one phase."""

    index: int
    kind: PhaseKind
    d_s1_chords: float         # max |s′ by chords − s′| (at the middles)
    d_s2_chords: float         # max |s″ by chords of s′ − s″| (at the inner nodes)
    d_s1_integral: float       # max |∫ s″ − s′| (at the nodes)
    d_s_integral: float        # max |∬ s″ − s| (at the nodes)
    s1_max: float
    s2_max: float
    stroke: float
    mids: np.ndarray = field(repr=False, default_factory=lambda: np.zeros(0))       # rad
    s1_by_chords: np.ndarray = field(repr=False, default_factory=lambda: np.zeros(0))
    inner_nodes: np.ndarray = field(repr=False, default_factory=lambda: np.zeros(0))  # rad
    s2_by_chords: np.ndarray = field(repr=False, default_factory=lambda: np.zeros(0))


def compare(phases: tuple[Phase, ...], stroke: float, divisions: int = 12) -> list[PhaseComparison]:
    """Compare the graphical construction with the exact values on every rise and return."""
    out: list[PhaseComparison] = []
    starts = phase_starts(phases)
    for i, p in enumerate(phases):
        if p.kind not in (PhaseKind.RISE, PhaseKind.RETURN):
            continue
        # a hair inside the phase so that the nodes at its ends belong to it
        eps = 1e-12 * p.angle
        nodes = np.linspace(starts[i] + eps, starts[i + 1] - eps, divisions + 1)
        d = nodes[1] - nodes[0]
        mids = 0.5 * (nodes[1:] + nodes[:-1])
        ex_n = motion(phases, stroke, nodes)
        ex_m = motion(phases, stroke, mids)
        s1_ch = np.diff(ex_n.s) / d
        s2_ch = np.diff(s1_ch) / d
        s1_int = ex_n.s1[0] + np.concatenate([[0.0], np.cumsum(ex_m.s2 * d)])
        s_int = ex_n.s[0] + np.concatenate([[0.0], np.cumsum(0.5 * (s1_int[1:] + s1_int[:-1]) * d)])
        out.append(PhaseComparison(
            i, p.kind,
            float(np.max(np.abs(s1_ch - ex_m.s1))),
            float(np.max(np.abs(s2_ch - ex_n.s2[1:-1]))) if divisions > 1 else 0.0,
            float(np.max(np.abs(s1_int - ex_n.s1))),
            float(np.max(np.abs(s_int - ex_n.s))),
            float(np.max(np.abs(ex_n.s1))), float(np.max(np.abs(ex_n.s2))), stroke,
            mids, s1_ch, nodes[1:-1], s2_ch))
    return out
