"""The exact textbook answers of a linkage (what its answer table is checked against).

Scalars: ``H``/``psi`` (stroke or swing), ``K``, ``theta_work``, ``theta_return``, ``theta`` (the
crank angle between the extreme positions, θ_w − 180°), ``gamma_min`` and where it is,
``phi_gamma_min``; per position: ``v_slide``, ``a_slide``, ``a_cor``, ``v_rub``, ``gamma``,
``v_min``. Each is given for the mechanism's main subject (plain name) and for every subject
(``name.subject``: a slider's point, a rocker's link, a pin's point, a group's name, a link).
See docs/textbook.md.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..model.mechanism import GROUND
from ..model.textbook import Answer, TextbookSpec
from .answers import Keys, Own, Written, span, written_all

if TYPE_CHECKING:
    from ..construct.textbook import TextbookAnswers
    from ..solve import Solution


def _full(sol: Solution) -> TextbookAnswers:
    """Every family, with the scene's pins and outputs."""
    from ..textbook_report import KEY, attach

    base = sol.scene.textbook or TextbookSpec(frozenset())
    t = sol.extras.get(KEY)
    if t is None or t.asked != frozenset(Answer):
        t = attach(sol, TextbookSpec(frozenset(Answer), base.pin_radius, dict(base.pins),
                                     base.outputs))
    assert t is not None
    return t


def linkage_answers(sol: Solution) -> Keys:
    """The exact answers of a linkage solved at its positions."""
    t = _full(sol)
    k = Keys("linkage", study=t, formulas=_own_linkage)
    phis = [float(math.degrees(p)) for p in sol.phi]

    def column(name: str, subject: str, values: np.ndarray, main: bool) -> None:
        col = {phi: float(v) for phi, v in zip(phis, values) if math.isfinite(float(v))}
        for key in (f"{name}.{subject}", *((name,) if main else ())):
            k.columns[key] = col
            k.spans[key] = span(col)

    moving = [sl for sl in t.sliding if sl.guide_link != GROUND]
    main_slide = (moving or t.sliding)[0] if t.sliding else None
    for sl in t.sliding:
        column("v_slide", sl.pair.point, np.abs(sl.v_slide), sl is main_slide)
        if sl.a_slide is not None and sl.a_cor is not None:
            column("a_slide", sl.pair.point, np.abs(sl.a_slide), sl is main_slide)
            column("a_cor", sl.pair.point, np.hypot(*sl.a_cor.T), sl is main_slide)
    for r in t.rubbing:
        column("v_rub", r.pair.point, r.v_rub, len(t.rubbing) == 1)
    for i, tr in enumerate(t.transmission):
        column("gamma", tr.group.name, tr.gamma, i == len(t.transmission) - 1)
    for lv in t.least_velocity:
        column("v_min", lv.link, lv.v_min, False)
    with_k = [s for s in t.strokes if s.K is not None]
    main = next((s for s in with_k if sol.scene.textbook and sol.scene.textbook.outputs
                 and s.subject == sol.scene.textbook.outputs[0]), with_k[-1] if with_k else None)
    for s in t.strokes:
        if not s.extremes:
            continue
        vals = {"psi" if s.rocker else "H": s.size}
        if s.K is not None:
            assert s.theta_work is not None and s.theta_return is not None
            vals |= {"K": s.K, "theta_work": s.theta_work, "theta_return": s.theta_return,
                     "theta": s.theta_work - math.pi}
        for name, v in vals.items():
            k.scalars[f"{name}.{s.subject}"] = v
            if s is main:
                k.scalars[name] = v
    least = {g: lg for g, lg in t.least_gamma.items() if lg is not None}
    if least:
        lowest = min(least.values(), key=lambda lg: lg[1])
        k.scalars["gamma_min"] = lowest[1]
        if math.isfinite(lowest[0]):
            k.scalars["phi_gamma_min"] = lowest[0]
    for group, (phi, gamma) in least.items():
        k.scalars[f"gamma_min.{group}"] = gamma
        if math.isfinite(phi):
            k.scalars[f"phi_gamma_min.{group}"] = phi
    return k


def subjects(k: Keys) -> list[str]:
    """The subjects a name may end with (longest first), from the keys ``name.subject``."""
    found = {key.partition(".")[2] for key in (*k.scalars, *k.columns) if "." in key}
    return sorted(found, key=len, reverse=True)


def _own_linkage(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    """K from the student's own θ_w and θ_r (or θ); θ_r = 360° − θ_w."""
    both = written_all(w, None, "theta_work", "theta_return")
    if name == "K" and both and both[1] > 0:
        return both[0] / both[1], "K = θ_w/θ_r", ("theta_work", "theta_return")
    theta = written_all(w, None, "theta")
    if name == "K" and theta and theta[0] < math.pi:
        return ((math.pi + theta[0]) / (math.pi - theta[0]), "K = (180° + θ)/(180° − θ)",
                ("theta",))
    work = written_all(w, None, "theta_work")
    if name == "theta_return" and work:
        return 2 * math.pi - work[0], "θ_r = 360° − θ_w", ("theta_work",)
    return None


__all__ = ["linkage_answers", "subjects"]
