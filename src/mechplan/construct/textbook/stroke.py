"""Stroke H (slider) or swing ψ (rocker), the extreme positions and the time ratio K.

The extremes are the crank angles where the output's rate vanishes with a change of sign, found
by bisection to machine precision (:mod:`..extremes`). From the extreme minimum to the maximum
the crank turns θ_up (in its sense of rotation), back θ_down = 360° − θ_up. The working stroke is
the slower one — the longer crank angle θ_w — the return the quicker, θ_r; K = θ_w/θ_r ≥ 1.
K and the strokes are given only when the output has exactly one maximum and one minimum.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...errors import SceneError
from ...model.mechanism import GROUND, Mechanism, PairKind
from ..extremes import ExtremePosition, extreme_positions
from ..graph import Construction

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, slots=True)
class Stroke:
    """An output's extremes; ``size`` is H (m) of a slider or ψ (rad) of a rocker."""

    subject: str
    rocker: bool
    extremes: tuple[ExtremePosition, ...]
    size: float
    phi_min: float | None = None
    phi_max: float | None = None
    theta_up: float | None = None       # crank angle from the minimum to the maximum (rad)
    theta_down: float | None = None
    working_up: bool | None = None      # the working (slower) stroke goes from min to max

    @property
    def K(self) -> float | None:
        """The time ratio (coefficient of speed change) θ_w/θ_r ≥ 1."""
        if self.theta_up is None or self.theta_down is None:
            return None
        return max(self.theta_up, self.theta_down) / min(self.theta_up, self.theta_down)

    @property
    def theta_work(self) -> float | None:
        """Crank angle of the working stroke (the longer one)."""
        if self.theta_up is None or self.theta_down is None:
            return None
        return max(self.theta_up, self.theta_down)

    @property
    def theta_return(self) -> float | None:
        """Crank angle of the return stroke (the shorter one)."""
        if self.theta_up is None or self.theta_down is None:
            return None
        return min(self.theta_up, self.theta_down)


def default_outputs(mech: Mechanism) -> list[str]:
    """Every point sliding on a frame guide and every rocker pivoted on the frame (not the
    crank); fully rotating links drop out later (they have no extremes)."""
    out: list[str] = []
    for lid, lk in mech.links.items():
        if lid in (GROUND, mech.drive.link):
            continue
        if lk.slides_on and mech.guides[lk.slides_on].link == GROUND:
            out += [p for p in lk.points if any(
                pr.kind is PairKind.PRISMATIC and pr.point == p and pr.joins(lid)
                for pr in mech.pairs)][:1]
        elif any(pr.kind is PairKind.REVOLUTE and pr.joins(lid) and pr.other(lid) == GROUND
                 for pr in mech.pairs):
            out.append(lid)
    return out


def stroke(c: Construction, mech: Mechanism, subject: str) -> Stroke:
    """The stroke or swing of ``subject`` (a slider's point or a rocker's link number)."""
    ex = tuple(extreme_positions(c, mech, subject))
    rocker = subject in mech.links
    if not ex:
        return Stroke(subject, rocker, ex, math.nan)
    hi, lo = max(ex, key=lambda e: e.value), min(ex, key=lambda e: e.value)
    size = hi.value - lo.value
    if rocker:
        size = abs(math.remainder(size, TWO_PI))
    maxima = [e for e in ex if e.which == "max"]
    minima = [e for e in ex if e.which == "min"]
    if len(maxima) != 1 or len(minima) != 1:
        return Stroke(subject, rocker, ex, size)
    mx, mn = maxima[0], minima[0]
    up = (mx.phi - mn.phi) % TWO_PI
    down = TWO_PI - up
    return Stroke(subject, rocker, ex, size, mn.phi, mx.phi, up, down, up >= down)


def strokes(c: Construction, mech: Mechanism, outputs: tuple[str, ...] = (),
            file: str | None = None) -> list[Stroke]:
    """The strokes of the outputs named (default: :func:`default_outputs`) that have extremes."""
    out = []
    for s in outputs or tuple(default_outputs(mech)):
        try:
            st = stroke(c, mech, s)
        except SceneError as exc:
            raise SceneError(exc.detail, file=file, key="answers.outputs") from None
        if st.extremes or outputs:
            out.append(st)
    return out
