"""The protocol of the velocities by instant centres: one sentence per step, with what is measured.

Each step's sentence is its operation's catalogue message (``protocol.op.ic_*``, area file
``locale/*/icdraw.po``). A centre is written with the language's letter (I13, P13); lengths on the
drawing are measured in mm at μl, velocity arrows in mm at μv and multiplied back (the value a
student reads off the sheet). Where a link's absolute centre is at infinity at that position the
link translates and the sentence says so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..i18n import message, number, unit
from .graph import Evaluation
from .plans.centre_velocity import CENTRE, CentreVelocity
from .step import Kind, Step


@dataclass(frozen=True, slots=True)
class Measured:
    """A velocity arrow measured on paper: its length (mm, to 0.1) and the value it gives."""

    mm: float
    value: float
    exact: float


def measure(v: np.ndarray, mu_v: float) -> Measured:
    """The arrow of a velocity (m/s) drawn at μv, measured to 0.1 mm."""
    exact = float(np.hypot(*v))
    mm = round(exact / mu_v, 1) if math.isfinite(exact) else math.nan
    return Measured(mm, mm * mu_v, exact)


def names(text: str, sym: str) -> str:
    """A label or subject with its centres (``@13``) written with the letter ``sym``."""
    return text.replace(CENTRE, sym)


def _centre_of(step: Step) -> str:
    return step.input("centre")


def _radius_mm(ev: Evaluation, step: Step, point_id: str, k: int, mu_l: float) -> float:
    """|centre X| on the drawing (mm) for a step whose first input is a homogeneous centre."""
    h = ev[_centre_of(step)][k]
    if not h[2]:
        return math.nan
    c = h[:2] * step.param("length") / h[2]
    return float(np.hypot(*(ev[point_id][k] - c))) / mu_l


def sentence(cv: CentreVelocity, step: Step, ev: Evaluation, k: int, lang: str, mu_l: float,
             mu_v: float) -> str:
    """The sentence of one step at position k."""
    sym = message("centres.symbol", lang)
    s = [names(x, sym) for x in step.subject] + ["", "", ""]
    lbl = names(step.label, sym)
    mm = unit("mm", lang)
    value = ev[step.id][k]
    if step.kind is Kind.SCALAR:
        v = f"{number(float(value), 3, lang)} {unit('rad/s', lang)}"
    else:
        meas = measure(value, mu_v)
        v = f"{number(meas.exact, 3, lang)} {unit('m/s', lang)}"
    centre_inf = "centre" in step.op.inputs and bool(ev[_centre_of(step)][k][2] == 0.0)
    op = step.op.value
    if centre_inf and op == "ic_carry":     # no arc about a centre at infinity: nothing drawn
        return ""
    if centre_inf and op in ("ic_arc_velocity", "ic_similar_velocity", "ic_pole_velocity",
                             "ic_pole_omega"):
        return message("icdraw.translates", lang, label=lbl, link=s[2] if op.endswith(
            ("omega", "pole_velocity")) else "", centre=s[1], v=v)
    fields: dict[str, str] = {"label": lbl, "s0": s[0], "s1": s[1], "s2": s[2], "v": v,
                              "r": "", "m": ""}
    if step.kind is not Kind.SCALAR and op != "ic_carry":
        meas = measure(value, mu_v)
        fields["m"] = message("icdraw.arrow", lang, mm=number(meas.mm, 1, lang),
                              unit=mm, value=number(meas.value, 3, lang),
                              si=unit("m/s", lang))
    if op in ("ic_drive_velocity", "ic_pole_velocity", "ic_carry", "ic_pole_omega"):
        r = _radius_mm(ev, step, step.input("point"), k, mu_l)
        fields["r"] = f"{number(r, 1, lang)} {mm}"
    assert step.op.message is not None
    return message(step.op.message, lang, **fields)


def protocol(cv: CentreVelocity, ev: Evaluation, k: int, lang: str, mu_l: float,
             mu_v: float) -> list[str]:
    """The sentences of every written step at position k, in construction order."""
    out = [sentence(cv, st, ev, k, lang, mu_l, mu_v) for st in cv.construction
           if st.op.message is not None and st.id in ev.values]
    return [s for s in out if s]


__all__ = ["Measured", "measure", "names", "protocol", "sentence"]
