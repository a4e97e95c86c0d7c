"""The engine-style (central) crank-rocker by the rod ratio λ = r/l and the swing: K = 1.

With K = 1 the angle of overlap θ is zero, the K circle degenerates into the line C1C2 and the
crank pivot A lies on it: AC1 = l − r, AC2 = l + r, so the chord C1C2 = 2c·sin(ψ/2) is 2r and
r = c·sin(ψ/2), l = r/λ (as the central slider-crank has r = H/2, l = r/λ). With D at the origin
and C1, C2 symmetric about the vertical, A = (−l, c·cos(ψ/2)) and d = √(l² + c²cos²(ψ/2)).
"""

from __future__ import annotations

import math

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from . import geometry as g
from .crank_rocker import assembled, grashof, transmission
from .design import LinkageDesign, Step, Stroke


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def central_crank_rocker(spec: SynthesisSpec) -> LinkageDesign:
    """The crank-rocker with K = 1 from the swing ψ, the rocker c and λ = r/l."""
    psi, c, lam = spec.swing, spec.rocker, spec.rod_ratio
    assert psi is not None and c is not None
    if lam is None:
        raise _error(spec, "lambda", "central_rocker_needs_lambda")
    if not 0.0 < lam < 1.0:
        raise _error(spec, "lambda", "lambda_below_one", value=repr(lam))
    h = c * math.cos(psi / 2)
    r = c * math.sin(psi / 2)
    l_ = r / lam
    D: g.Vec = (0.0, 0.0)
    C1: g.Vec = (-r, h)
    C2: g.Vec = (r, h)
    A: g.Vec = (-l_, h)
    d = g.norm(A)
    ok, margin = grashof({"1": r, "2": l_, "3": c, "0": d})
    if not ok or min(r, l_, c, d) != r:
        raise _error(spec, "lambda", "central_no_grashof", value=repr(lam))
    gamma_min, gamma_at = transmission(r, l_, c, d)
    if math.isnan(gamma_min):
        raise _error(spec, "lambda", "central_no_grashof", value=repr(lam))
    if spec.gamma_limit is not None and not gamma_min >= spec.gamma_limit:
        raise _error(spec, "gamma_min", "gamma_below",
                     got=repr(round(math.degrees(gamma_min), 4)),
                     limit=repr(round(math.degrees(spec.gamma_limit), 4)))
    scene, mechanism, conditions = assembled(spec, A, D, C1, C2,
                                             {"r": r, "l": l_, "c": c, "d": d},
                                             (ok, margin, gamma_min, gamma_at))
    strokes = [
        Stroke("point", D, role="given", label="D"),
        Stroke("line", D, C1, role="given", label="C1"),
        Stroke("line", D, C2, role="given", label="C2"),
        Stroke("line", A, C2, role="result"),
        Stroke("circle", A, r=r, role="result", label="A"),
        *mechanism,
    ]
    choice = Step("synth.cr.central", {"lam": lam})
    protocol = [
        Step("synth.cr.rocker", {"c": c, "psi": psi}),
        Step("synth.cr.central_chord", {"r": r}),
        choice,
        Step("synth.cr.measure", {"a1": l_ - r, "a2": l_ + r}),
        Step("synth.cr.lengths", {"r": r, "l": l_, "d": d}),
    ]
    return LinkageDesign("crank_rocker", 1.0, 0.0, {"r": r, "l": l_, "c": c, "d": d},
                         strokes, protocol, conditions, [], choice, scene, "3", "angle", psi)
