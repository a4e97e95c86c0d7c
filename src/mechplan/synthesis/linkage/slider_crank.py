"""A central or offset slider-crank from its time ratio K and stroke H (the K circle).

The slider's extreme positions C1, C2 lie H apart on the guide; the circle through them from
whose arc C1C2 is seen at θ carries the crank pivot A; its distance from the guide is the offset
e. At the dead centres AC1 = l − r, AC2 = l + r. K = 1 gives the central slider-crank (e = 0,
r = H/2); then λ = r/l must be given.
"""

from __future__ import annotations

import math

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from . import geometry as g
from .design import Candidate, LinkageDesign, Step, Stroke, theta_of_k
from .scene_out import base, deg, link_name, mm

FAMILY_SAMPLES = 61


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def stroke_of(r: float, l_: float, e: float) -> float:
    """H = √((l + r)² − e²) − √((l − r)² − e²)."""
    return math.sqrt((l_ + r) ** 2 - e * e) - math.sqrt((l_ - r) ** 2 - e * e)


def pressure_max(r: float, l_: float, e: float) -> float:
    """The largest pressure angle α = asin((e + r)/l) (crank square to the guide, away from it)."""
    s = (e + r) / l_
    return math.asin(s) if s < 1.0 else math.nan


class _Circle:
    def __init__(self, k: float, h_stroke: float) -> None:
        self.theta = theta_of_k(k)
        self.H = h_stroke
        self.C1: g.Vec = (-h_stroke / 2, 0.0)     # folded dead centre (nearer A)
        self.C2: g.Vec = (h_stroke / 2, 0.0)      # extended dead centre
        if self.theta > 0:
            self.R = h_stroke / (2 * math.sin(self.theta))
            self.h = h_stroke / (2 * math.tan(self.theta))
        else:
            self.R = self.h = math.inf
        self.O = (0.0, self.h)
        self.e_max = 2 * self.h

    def pivot(self, e: float) -> g.Vec:
        if self.theta == 0:
            return self.C1
        return -math.sqrt(max(self.R ** 2 - (e - self.h) ** 2, 0.0)), e

    def lengths(self, e: float) -> dict[str, float]:
        a = self.pivot(e)
        a1, a2 = g.norm(g.sub(self.C1, a)), g.norm(g.sub(self.C2, a))
        return {"r": 0.5 * (a2 - a1), "l": 0.5 * (a1 + a2), "e": e}

    def gamma(self, e: float) -> float:
        n = self.lengths(e)
        return math.pi / 2 - pressure_max(n["r"], n["l"], e)


def _pick(spec: SynthesisSpec, circ: _Circle) -> tuple[float, float, float, Step]:
    """(e, r, l) of the chosen slider-crank and the sentence explaining the choice."""
    h_ = circ.H
    if circ.theta == 0:
        if spec.offset not in (None, 0.0):
            raise _error(spec, "offset", "offset_needs_k", value=repr(spec.offset * 1e3))
        if spec.rod_ratio is None:
            raise _error(spec, "lambda", "central_needs_lambda")
        r = h_ / 2
        return 0.0, r, r / spec.rod_ratio, Step("synth.sc.central", {"lam": spec.rod_ratio})
    if spec.offset is not None:
        if not 0.0 < spec.offset < circ.e_max:
            raise _error(spec, "offset", "offset_range", value=repr(spec.offset * 1e3),
                         hi=repr(round(circ.e_max * 1e3, 3)))
        n = circ.lengths(spec.offset)
        return spec.offset, n["r"], n["l"], Step("synth.sc.choice_offset", {"e": spec.offset})
    eps = 1e-12 * circ.e_max
    if spec.rod_ratio is not None:
        lam = spec.rod_ratio
        lo = math.tan(circ.theta / 2) ** 2
        if not lo < lam < 1.0:
            raise _error(spec, "lambda", "lambda_range", value=repr(lam), lo=repr(round(lo, 6)))
        e = g.bisect(lambda e: circ.lengths(e)["r"] / circ.lengths(e)["l"] - lam,
                     eps, circ.e_max - eps)
        n = circ.lengths(e)
        return e, n["r"], n["l"], Step("synth.sc.choice_lambda", {"lam": lam})
    e = g.maximise(circ.gamma, eps, circ.e_max - eps)
    if spec.gamma_target is not None:
        target, best = spec.gamma_target, circ.gamma(e)
        if not target <= best:
            raise _error(spec, "gamma", "gamma_unreachable",
                         value=repr(round(math.degrees(target), 6)),
                         best=repr(round(math.degrees(best), 4)))
        found = g.roots(lambda x: circ.gamma(x) - target, eps, circ.e_max - eps)
        e = min(found, key=lambda x: circ.lengths(x)["l"]) if found else e
        n = circ.lengths(e)
        return e, n["r"], n["l"], Step("synth.sc.choice_gamma", {"gamma": target,
                                                                 "n": len(found)})
    n = circ.lengths(e)
    return e, n["r"], n["l"], Step("synth.sc.choice_best", {"gamma": circ.gamma(e)})


def slider_crank(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the slider-crank a ``problem = "slider_crank"`` scene asks for."""
    if spec.stroke is None:
        raise _error(spec, "stroke", "needs", problem=spec.problem)
    if not spec.k >= 1.0:
        raise _error(spec, "K", "k_not_below_one", value=repr(spec.k))
    circ = _Circle(spec.k, spec.stroke)
    e, r, l_, choice = _pick(spec, circ)
    A = circ.pivot(e)
    alpha = pressure_max(r, l_, e)
    if math.isnan(alpha):
        raise _error(spec, "K", "no_crank", value=repr(spec.k))
    gamma_min = math.pi / 2 - alpha
    if spec.gamma_limit is not None and not gamma_min >= spec.gamma_limit:
        raise _error(spec, "gamma_min", "gamma_below",
                     got=repr(round(math.degrees(gamma_min), 4)),
                     limit=repr(round(math.degrees(spec.gamma_limit), 4)))

    if circ.theta == 0:          # central: the stroke's ends lie l − r and l + r from A
        A = (circ.C1[0] - (l_ - r), 0.0)
    B_ext = g.add(A, g.mul(g.unit(g.sub(circ.C2, A)), r))
    B_fold = g.sub(A, g.mul(g.unit(g.sub(circ.C1, A)), r))
    def moved(p: g.Vec) -> g.Vec:
        return g.sub(p, A)

    # crank angles as the analysis counts them: from +x in the sense of rotation
    phi_ext = (spec.sense * g.angle_of(moved(B_ext))) % (2 * math.pi)
    phi_fold = (spec.sense * g.angle_of(moved(B_fold))) % (2 * math.pi)
    sweep = (phi_fold - phi_ext) % (2 * math.pi)
    c_ext = moved(circ.C2)
    scene = base(spec, {"A": ["0 mm", "0 mm"], "G": ["0 mm", mm(-e)],
                        "guides": {"g": {"through": "G", "angle": "0 deg"}}}, {
        "1": {"name": link_name("crank", spec), "lengths": {"AB": mm(r)}},
        "2": {"name": link_name("rod", spec), "lengths": {"BC": mm(l_)}},
        "3": {"name": link_name("slider", spec), "slides": {"point": "C", "on": "g"}},
    }, {"extreme": "C", "which": "max"},
        {"at": deg(phi_ext), "C": [mm(c_ext[0]), mm(c_ext[1])]})
    family = []
    if circ.theta > 0:
        for i in range(FAMILY_SAMPLES):
            ei = circ.e_max * (i + 0.5) / FAMILY_SAMPLES
            gm = circ.gamma(ei)
            family.append(Candidate(ei, circ.lengths(ei), gm, not math.isnan(gm)))
    strokes = [Stroke("line", (circ.C1[0] - 0.15 * circ.H, circ.C1[1]),
                      (circ.C2[0] + 0.15 * circ.H, circ.C2[1]), role="given", label="C1"),
               Stroke("point", circ.C2, role="given", label="C2")]
    if circ.theta > 0:
        P = (circ.C2[0], 2 * circ.h)
        strokes += [Stroke("line", circ.C2, P), Stroke("line", circ.C1, P, label="P"),
                    Stroke("circle", circ.O, r=circ.R, label="O"),
                    Stroke("line", (A[0] - 0.1 * circ.H, e), (circ.C2[0], e), label="e")]
    strokes += [Stroke("line", A, circ.C1, role="result"),
                Stroke("line", A, circ.C2, role="result"),
                Stroke("circle", A, r=r, role="result", label="A"),
                Stroke("line", A, B_ext, role="mechanism", label="B2"),
                Stroke("line", B_ext, circ.C2, role="mechanism"),
                Stroke("line", A, B_fold, role="mechanism", label="B1"),
                Stroke("line", B_fold, circ.C1, role="mechanism")]
    protocol = [Step("synth.theta", {"k": spec.k, "theta": circ.theta}),
                Step("synth.sc.stroke", {"H": circ.H})]
    if circ.theta > 0:
        protocol += [Step("synth.sc.perp", {"angle": math.pi / 2 - circ.theta}),
                     Step("synth.cr.circle", {"R": circ.R, "theta": circ.theta})]
    protocol += [choice, Step("synth.cr.measure", {"a1": l_ - r, "a2": l_ + r}),
                 Step("synth.sc.lengths", {"r": r, "l": l_, "e": e, "lam": r / l_})]
    conditions = {
        "turns_fully": "1", "gamma_min": gamma_min, "pressure_max": alpha,
        "pressure_max_at_phi": (spec.sense * math.pi / 2) % (2 * math.pi),
        "dead_centres_phi": [phi_ext, phi_fold],
        "working_stroke_phi": max(sweep, 2 * math.pi - sweep),
        "working_from": "C2" if sweep > math.pi else "C1",
    }
    return LinkageDesign("slider_crank", spec.k, circ.theta, {"r": r, "l": l_, "e": e},
                         strokes, protocol, conditions, family, choice, scene, "C", "length",
                         circ.H)
