"""A crank-rocker four-bar from its time ratio K, the rocker's swing ψ and length (the K circle).

The rocker's extreme positions DC1, DC2 are drawn ψ apart; the circle through C1 and C2 from
whose arc the chord C1C2 is seen at θ = 180°·(K − 1)/(K + 1) carries every crank pivot A that
gives K: at the dead centres A, B, C are collinear, so AC1 = l − r (folded) and AC2 = l + r
(extended). The circle's centre lies on D's side of the chord; the family is its arc from C1
to F, the second meet of the line C2D with the circle (beyond F the two extreme positions fall on
different assembly branches); the arc from C2 gives the mirror images.
"""

from __future__ import annotations

import math
from typing import Any

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from . import geometry as g
from .design import Candidate, LinkageDesign, Step, Stroke, theta_of_k
from .scene_out import base, link_name, mm

FAMILY_SAMPLES = 61


def transmission(r: float, l: float, c: float, d: float) -> tuple[float, float]:
    """The smallest transmission angle of a crank-rocker and the crank angle (0 or π from the
    frame line A→D) where it occurs; NaN where the links do not close."""
    best, where = math.inf, 0.0
    for phi, bd in ((0.0, abs(d - r)), (math.pi, d + r)):
        cos_mu = (l * l + c * c - bd * bd) / (2.0 * l * c)
        if abs(cos_mu) > 1.0:
            return math.nan, phi
        mu = math.acos(cos_mu)
        gamma = min(mu, math.pi - mu)
        if gamma < best:
            best, where = gamma, phi
    return best, where


def assembled(spec: SynthesisSpec, A: g.Vec, D: g.Vec, C1: g.Vec, C2: g.Vec,
              n: dict[str, float], checks: tuple[bool, float, float, float],
              ) -> tuple[dict[str, Any], list[Stroke], dict[str, Any]]:
    """The crank-rocker found by a construction, handed on as a scene: A at the origin, D on the
    +x axis (the construction turned by −angle(AD)); the mechanism drawn at both dead centres
    (B2 extended towards C2, B1 folded towards C1); its conditions: ``checks`` (Grashof and its
    margin, γ_min and where) and what its dead centres give (crank angles as the analysis counts
    them: from +x in the sense of rotation)."""
    r, l_, c, d = n["r"], n["l"], n["c"], n["d"]
    turn = -g.angle_of(g.sub(D, A))

    def moved(p: g.Vec) -> g.Vec:
        return g.rotate(g.sub(p, A), turn)

    B_ext = g.add(A, g.mul(g.unit(g.sub(C2, A)), r))
    B_fold = g.sub(A, g.mul(g.unit(g.sub(C1, A)), r))
    side = g.cross(g.sub(D, B_ext), g.sub(C2, B_ext))
    phi_ext = (spec.sense * g.angle_of(moved(B_ext))) % (2 * math.pi)
    phi_fold = (spec.sense * g.angle_of(moved(B_fold))) % (2 * math.pi)
    sweep = (phi_fold - phi_ext) % (2 * math.pi)                   # ext → fold, driven sense
    scene = base(spec, {"A": ["0 mm", "0 mm"], "D": [mm(d), "0 mm"]}, {
        "1": {"name": link_name("crank", spec), "lengths": {"AB": mm(r)}},
        "2": {"name": link_name("coupler", spec), "lengths": {"BC": mm(l_)}},
        "3": {"name": link_name("rocker", spec), "lengths": {"DC": mm(c)}},
    }, {"extreme": "3", "which": "min"},
        {"C": ("left" if side > 0 else "right") + " of B->D"})
    mechanism = [
        Stroke("line", A, B_ext, role="mechanism", label="B2"),
        Stroke("line", B_ext, C2, role="mechanism"),
        Stroke("line", A, B_fold, role="mechanism", label="B1"),
        Stroke("line", B_fold, C1, role="mechanism"),
        Stroke("line", A, D, role="mechanism"),
    ]
    ok, margin, gamma_min, gamma_at = checks
    conditions: dict[str, Any] = {
        "grashof": ok, "grashof_margin": margin, "turns_fully": "1", "rocks": "3",
        "gamma_min": gamma_min, "gamma_min_at_phi": gamma_at,
        "dead_centres_phi": [phi_ext, phi_fold],
        "working_stroke_phi": max(sweep, 2 * math.pi - sweep),
        "working_from": "C2" if sweep > math.pi else "C1",
    }
    return scene, mechanism, conditions


def grashof(lengths: dict[str, float]) -> tuple[bool, float]:
    """Grashof's condition s + l ≤ p + q and its margin (p + q − s − l, m)."""
    v = sorted(lengths.values())
    margin = v[1] + v[2] - v[0] - v[3]
    return margin >= 0.0, margin


class _Circle:
    """The K circle of a crank-rocker and the pivot A as a function of its arc parameter t."""

    def __init__(self, k: float, psi: float, c: float) -> None:
        self.theta = theta_of_k(k)
        self.c = c
        self.D: g.Vec = (0.0, 0.0)
        self.C1 = g.polar(c, math.pi / 2 + psi / 2)     # left: the folded dead centre
        self.C2 = g.polar(c, math.pi / 2 - psi / 2)     # right: the extended dead centre
        half = c * math.sin(psi / 2)
        self.R = half / math.sin(self.theta)
        h = half / math.tan(self.theta)
        self.O = (0.0, c * math.cos(psi / 2) - h)       # on D's side of the chord
        # P: the point of the circle opposite C1 (C1P a diameter: the angle at C2 is 90°)
        self.P = g.sub(g.mul(self.O, 2.0), self.C1)
        w = g.sub(self.D, self.C2)
        u = -2.0 * ((self.C2[0] - self.O[0]) * w[0] + (self.C2[1] - self.O[1]) * w[1]) / (
            w[0] ** 2 + w[1] ** 2)
        self.F = g.add(self.C2, g.mul(w, u))
        self.t_lo = g.angle_of(g.sub(self.C1, self.O))
        t_f = g.angle_of(g.sub(self.F, self.O))
        self.t_hi = self.t_lo + math.fmod(t_f - self.t_lo + 4 * math.pi, 2 * math.pi)

    def pivot(self, t: float) -> g.Vec:
        return g.polar(self.R, t, self.O)

    def lengths(self, t: float) -> dict[str, float]:
        a = self.pivot(t)
        a1, a2 = g.norm(g.sub(self.C1, a)), g.norm(g.sub(self.C2, a))
        return {"r": 0.5 * (a2 - a1), "l": 0.5 * (a1 + a2), "c": self.c,
                "d": g.norm(g.sub(self.D, a))}

    def gamma(self, t: float) -> float:
        n = self.lengths(t)
        return transmission(n["r"], n["l"], n["c"], n["d"])[0]

    def psi0(self, t: float) -> float:
        return g.angle_between(g.sub(self.pivot(t), self.D), g.sub(self.C1, self.D))


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def _pick(spec: SynthesisSpec, circ: _Circle) -> tuple[float, Step]:
    """The arc parameter of the chosen member and the sentence that explains the choice."""
    lo, hi = circ.t_lo, circ.t_hi
    eps = 1e-9 * (hi - lo)
    if spec.frame is not None:
        frame = spec.frame
        found = g.roots(lambda t: circ.lengths(t)["d"] - frame, lo + eps, hi - eps)
        if not found:
            ds = [circ.lengths(lo + (hi - lo) * i / 200)["d"] for i in range(1, 200)]
            raise _error(spec, "frame", "frame_range", value=repr(frame * 1e3),
                         lo=repr(round(min(ds) * 1e3, 3)), hi=repr(round(max(ds) * 1e3, 3)))
        t = max(found, key=circ.gamma)
        return t, Step("synth.cr.choice_frame", {"d": frame, "n": len(found)})
    if spec.frame_angle is not None:
        psi0 = spec.frame_angle
        found = g.roots(lambda t: circ.psi0(t) - psi0, lo + eps, hi - eps)
        if not found:
            ps = [circ.psi0(lo + (hi - lo) * i / 200) for i in range(1, 200)]
            raise _error(spec, "frame_angle", "angle_range",
                         value=repr(round(math.degrees(psi0), 6)),
                         lo=repr(round(math.degrees(min(ps)), 3)),
                         hi=repr(round(math.degrees(max(ps)), 3)))
        t = max(found, key=circ.gamma)
        return t, Step("synth.cr.choice_angle", {"psi0": psi0, "n": len(found)})
    if spec.rod_ratio is not None:
        lam = spec.rod_ratio

        def ratio(t: float) -> float:
            n = circ.lengths(t)
            return n["r"] / n["l"] - lam

        found = g.roots(ratio, lo + eps, hi - eps)
        if not found:
            ls = [ratio(lo + (hi - lo) * i / 200) + lam for i in range(1, 200)]
            raise _error(spec, "lambda", "cr_lambda_range", value=repr(lam),
                         lo=repr(round(min(ls), 6)), hi=repr(round(max(ls), 6)))
        t = max(found, key=circ.gamma)
        return t, Step("synth.cr.choice_lambda", {"lam": lam, "n": len(found)})
    t = g.maximise(circ.gamma, lo + eps, hi - eps)
    return t, Step("synth.cr.choice_best", {"gamma": circ.gamma(t)})


def crank_rocker(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the crank-rocker a ``problem = "crank_rocker"`` scene asks for."""
    psi, c = spec.swing, spec.rocker
    if psi is None or c is None:
        raise _error(spec, "swing" if psi is None else "rocker", "needs", problem=spec.problem)
    if not 0.0 < psi < math.pi:
        raise _error(spec, "swing", "swing_range", value=repr(round(math.degrees(psi), 6)))
    if spec.k == 1.0 and spec.rod_ratio is not None:
        from .central_rocker import central_crank_rocker

        return central_crank_rocker(spec)
    if not spec.k > 1.0:
        raise _error(spec, "K", "k_above_one", value=repr(spec.k))
    theta = theta_of_k(spec.k)
    circ = _Circle(spec.k, psi, c)
    if not circ.t_hi > circ.t_lo:
        raise _error(spec, "K", "no_arc", value=repr(spec.k))
    t, choice = _pick(spec, circ)
    n = circ.lengths(t)
    r, l_, d = n["r"], n["l"], n["d"]
    A = circ.pivot(t)
    gamma_min, gamma_at = transmission(r, l_, c, d)
    ok, margin = grashof({"1": r, "2": l_, "3": c, "0": d})
    if not ok or min(r, l_, c, d) != r:
        raise _error(spec, "K", "no_grashof_crank", value=repr(spec.k))
    if spec.gamma_limit is not None and not gamma_min >= spec.gamma_limit:
        raise _error(spec, "gamma_min", "gamma_below",
                     got=repr(round(math.degrees(gamma_min), 4)),
                     limit=repr(round(math.degrees(spec.gamma_limit), 4)))

    scene, mechanism, conditions = assembled(spec, A, circ.D, circ.C1, circ.C2,
                                             {"r": r, "l": l_, "c": c, "d": d},
                                             (ok, margin, gamma_min, gamma_at))

    family = []
    for i in range(FAMILY_SAMPLES):
        ti = circ.t_lo + (circ.t_hi - circ.t_lo) * (i + 0.5) / FAMILY_SAMPLES
        gm = circ.gamma(ti)
        family.append(Candidate(ti, circ.lengths(ti), gm, not math.isnan(gm)))
    strokes = [
        Stroke("point", circ.D, role="given", label="D"),
        Stroke("line", circ.D, circ.C1, role="given", label="C1"),
        Stroke("line", circ.D, circ.C2, role="given", label="C2"),
        Stroke("line", circ.C1, circ.C2),
        Stroke("line", circ.C2, circ.P),
        Stroke("line", circ.C1, circ.P, label="P"),
        Stroke("circle", circ.O, r=circ.R, label="O"),
        Stroke("arc", circ.O, (circ.t_lo, circ.t_hi), r=circ.R, role="family"),
        Stroke("line", circ.C2, circ.F, role="aux", label="F"),
        Stroke("line", A, circ.C1, role="result"),
        Stroke("line", A, circ.C2, role="result"),
        Stroke("circle", A, r=r, role="result", label="A"),
        *mechanism,
    ]
    chord = g.norm(g.sub(circ.C2, circ.C1))
    protocol = [
        Step("synth.theta", {"k": spec.k, "theta": theta}),
        Step("synth.cr.rocker", {"c": c, "psi": psi}),
        Step("synth.cr.chord", {"chord": chord}),
        Step("synth.cr.perp", {"angle": math.pi / 2 - theta}),
        Step("synth.cr.circle", {"R": circ.R, "theta": theta}),
        Step("synth.cr.arc", {}),
        choice,
        Step("synth.cr.measure", {"a1": l_ - r, "a2": l_ + r}),
        Step("synth.cr.lengths", {"r": r, "l": l_, "d": d}),
    ]
    return LinkageDesign("crank_rocker", spec.k, theta, {"r": r, "l": l_, "c": c, "d": d},
                         strokes, protocol, conditions, family, choice, scene, "3", "angle", psi)
