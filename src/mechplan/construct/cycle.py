"""The phases of a machine's members over one turn of the main shaft (the cycle diagram).

A linkage member's phases come from its output's exact extremes (:mod:`.textbook.stroke`): the
working stroke and the return, θ_w + θ_r = 360°; a cam member's from its motion program as given
(rise, far dwell, return, near dwell). Each member's own angle φ (crank angle or cam angle, both
growing with time) is φ = ψ + phase on the main shaft ψ; the diagram runs from ψ_0 over 360°.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import SceneError
from ..i18n import Text
from ..model.cam import Phase, PhaseKind
from ..model.cycle import Working
from ..model.mechanism import Mechanism
from .graph import Construction
from .textbook.stroke import default_outputs, stroke

TWO_PI = 2.0 * math.pi

#: the level of the output (0 near / min, 1 far / max) at the start and end of each kind of span
_CAM_LEVELS = {PhaseKind.RISE: (0.0, 1.0), PhaseKind.FAR_DWELL: (1.0, 1.0),
               PhaseKind.RETURN: (1.0, 0.0), PhaseKind.NEAR_DWELL: (0.0, 0.0)}


@dataclass(frozen=True)
class Span:
    """One phase of a member: its kind ("work", "return", "rise", "far_dwell", "return",
    "near_dwell"), its start in the member's own angle φ (rad), its angle (rad) and the output's
    level (0: near / minimum, 1: far / maximum) at its start and end."""

    kind: str
    start: float
    angle: float
    level0: float
    level1: float


@dataclass(frozen=True)
class MemberCycle:
    """A member's phases on the shaft: its name, kind ("linkage", "cam" or "driven" — a linkage
    turned by a cam's follower), its phase offset (φ = turns·ψ + phase), the spans in its own
    angle in order, its output's stroke (m or rad) and how many turns it makes in one turn of the
    diagram's shaft (a member on a faster shaft of the machine's train)."""

    name: str
    kind: str
    phase: float
    spans: tuple[Span, ...]
    stroke: float
    subject: str = ""
    turns: int = 1

    def _start(self, s: Span, origin: float) -> float:
        """ψ of the span's first occurrence from the diagram's origin, in [0, 2π/turns)."""
        period = TWO_PI / self.turns
        a = ((s.start - self.phase) / self.turns - origin) % period
        return 0.0 if a > period - 1e-12 else a

    def on_shaft(self, origin: float) -> list[tuple[Span, float, float]]:
        """(span, ψ start, ψ end) with ψ from the diagram's origin in [0, 2π], each span once
        per turn of the member; a span crossing the origin is split in two."""
        out: list[tuple[Span, float, float]] = []
        for k in range(self.turns):
            for s in self.spans:
                a = self._start(s, origin) + k * TWO_PI / self.turns
                b = a + s.angle / self.turns
                if b <= TWO_PI + 1e-12:
                    out.append((s, a, min(b, TWO_PI)))
                else:
                    out.append((s, a, TWO_PI))
                    out.append((s, 0.0, b - TWO_PI))
        return sorted(out, key=lambda t: t[1])

    def fraction_in(self, s: Span, a: float, origin: float) -> float:
        """How far into span ``s`` (a fraction of it) the piece starting at ψ = ``a`` begins."""
        period = TWO_PI / self.turns
        start = self._start(s, origin)
        off = (a - start) % period if abs(a - start) > 1e-12 else 0.0
        if off > period - 1e-12:
            off = 0.0
        return off * self.turns / s.angle if s.angle > 0 else 0.0


def linkage_cycle(c: Construction, mech: Mechanism, name: str, phase: float,
                  subject: str | None, working: Working, key: str) -> MemberCycle:
    """The working stroke and the return of a linkage's output from its exact extremes."""
    if mech.drive.linear:
        raise SceneError(Text("machine_cycle.error.linear", {"name": name,
                                                     "kind": mech.drive.kind.value}),
                         key=key.rsplit(".", 1)[0] + ".scene")
    outs = [subject] if subject else default_outputs(mech)
    if not outs:
        raise SceneError(Text("machine_cycle.error.no_output", {"name": name}), key=key)
    try:
        st = stroke(c, mech, outs[0])
    except SceneError as exc:
        raise SceneError(exc.detail, key=key) from None
    if st.phi_min is None or st.phi_max is None or st.theta_up is None:
        raise SceneError(Text("machine_cycle.error.extremes", {"name": name, "output": outs[0],
                                                       "count": str(len(st.extremes))}), key=key)
    up = {Working.LONGER: st.working_up, Working.TO_MAX: True, Working.TO_MIN: False}[working]
    if up:
        spans = (Span("work", st.phi_min, st.theta_up, 0.0, 1.0),
                 Span("return", st.phi_max, TWO_PI - st.theta_up, 1.0, 0.0))
    else:
        spans = (Span("work", st.phi_max, TWO_PI - st.theta_up, 1.0, 0.0),
                 Span("return", st.phi_min, st.theta_up, 0.0, 1.0))
    return MemberCycle(name, "linkage", phase, spans, st.size, outs[0])


def cam_cycle(phases: tuple[Phase, ...], stroke_: float, name: str, phase: float
              ) -> MemberCycle:
    """The cam's phases as its program gives them (cam angle 0 at the start of the first)."""
    spans = []
    start = 0.0
    for p in phases:
        lo, hi = _CAM_LEVELS[p.kind]
        spans.append(Span(p.kind.value, start, p.angle, lo, hi))
        start += p.angle
    return MemberCycle(name, "cam", phase, tuple(spans), stroke_)


def driven_cycle(cam: MemberCycle, name: str, subject: str, stroke_: float) -> MemberCycle:
    """A linkage turned by a cam's follower: the cam's phases, on the cam's shaft."""
    return MemberCycle(name, "driven", cam.phase, cam.spans, stroke_, subject, cam.turns)


def diagram_origin(members: list[MemberCycle], start: float | None) -> float:
    """ψ_0 of the diagram: ``start`` or the first member's first span (its working stroke)."""
    if start is not None:
        return start % TWO_PI
    m = members[0]
    return ((m.spans[0].start - m.phase) / m.turns) % TWO_PI
