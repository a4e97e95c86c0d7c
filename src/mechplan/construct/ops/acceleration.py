"""Operations of the acceleration plan: the driving vector, normal and Coriolis components, ε."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ...geom.vec import Array, cross, dot, perp
from ..step import Step
from .spec import (
    Drawn,
    Grade,
    Hint,
    HintView,
    Line,
    OpSpec,
    Result,
    Written,
    drive_hint,
    hint,
    labelled,
    measured,
    point_of,
    rigid_hint,
    scaled,
)

if TYPE_CHECKING:
    from ..graph import Construction


def drive_acceleration(step: Step, pivot: Array, tip: Array, *rates: Array) -> Result:
    """π b′: the crank's normal component −ω²·AB plus its tangential component ε × AB; ω and ε
    of each position from the two steps after ``tip`` when the crank moves by a law by a table
    (``omega``, ``epsilon`` then their largest)."""
    r = tip - pivot
    if rates:
        w, e = rates[0][:, None], rates[1][:, None]
        return e * perp(r) - w * w * r, None, None
    omega, eps = step.param("omega"), step.param("epsilon", 0.0)
    out = perp(r)                       # eps·perp(r) − ω²·r, in place: the same values
    out *= eps
    out -= omega * omega * r
    return out, None, None


def normal(step: Step, start: Array, omega: Array, p: Array, q: Array) -> Result:
    """From the image of P, ∥ QP towards P, of length ω²·l_PQ."""
    return start - scaled(omega * omega, q - p), None, None


def coriolis(step: Step, start: Array, omega: Array, v_from: Array, v_to: Array) -> Result:
    """Coriolis component 2ω × v_rel laid off from an image."""
    return start + scaled(2.0 * omega, perp(v_to - v_from)), None, None


def epsilon(step: Step, p: Array, q: Array, normal_end: Array, aq: Array) -> Result:
    """ε of the link pq from its tangential component: (pq × a^t) / |pq|²."""
    r = q - p
    out = cross(r, aq - normal_end)
    out /= dot(r, r)
    return out, None, None


def rigid_acceleration(step: Step, origin: Array, omega: Array, eps: Array, p_origin: Array,
                       p_point: Array) -> Result:
    """a_X = a_O + ε × OX − ω² OX."""
    r = p_point - p_origin
    return origin + scaled(eps, perp(r)) - scaled(omega * omega, r), None, None


# -- check rules ----------------------------------------------------------------------------------
def drive_acceleration_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """π b′ of the crank: its normal (and tangential) component."""
    return drive_hint(step, view, at, "rule.drive_a")


def normal_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The normal component: from the image of P, ∥ QP, of length ω²·l_PQ (with the student's ω)."""
    c, plan = view.c, step.plan
    ap, omega_ = step.input("start"), step.input("omega")
    p, q = step.input("p"), step.input("q")
    own_w = float(np.asarray(view.own(omega_)).reshape(-1)[0])
    exact_w = float(np.asarray(view.exact(omega_)).reshape(-1)[0])
    length = float(np.hypot(*(point_of(view.exact(q)) - point_of(view.exact(p)))))
    P, Q = c[p].label, c[q].label
    own_len = view.mm(plan, own_w * own_w * length)
    exact_len = view.mm(plan, exact_w * exact_w * length)
    wl = c[omega_].label
    own_txt = (hint("rule.normal_own", w=wl, ow=own_w, olen=own_len)
               if abs(own_w - exact_w) > 1e-9 * max(1.0, abs(exact_w)) else "")
    return measured(hint("rule.normal", label=view.labels(step.id), ap=view.labels(ap), P=P, Q=Q,
                         w=wl, len=exact_len, own=own_txt))


def coriolis_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """The Coriolis component: 2ω × v_rel laid off from an image."""
    start, omega_ = step.input("start"), step.input("omega")
    length = view.mm(step.plan, float(np.hypot(*(point_of(view.exact(step.id))
                                                 - point_of(view.exact(start))))))
    return measured(hint("rule.coriolis", label=view.labels(step.id), w=view.c[omega_].label,
                         start=view.labels(start), len=length))


def epsilon_value_hint(step: Step, c: Construction) -> Hint:
    """A wrong ε: the tangential component over the link's length."""
    p, q, n, aq = (c[step.input(name)].label for name in ("p", "q", "normal_end", "aq"))
    return hint("hint.epsilon", label=step.label, p=p, q=q, n=n, a=aq)


# -- the operations -------------------------------------------------------------------------------
DRIVE_ACCELERATION = OpSpec("drive_acceleration", drive_acceleration,
                            "protocol.op.drive_acceleration", Drawn.POINT, Line.OUTLINE,
                            Grade.POINT, hint=labelled("hint.drive"),
                            hint_rule=drive_acceleration_hint)
NORMAL = OpSpec("normal", normal, "protocol.op.normal", Drawn.POINT, Line.THIN, Grade.POINT,
                hint=labelled("hint.normal"), hint_rule=normal_hint, alias="n")
CORIOLIS = OpSpec("coriolis", coriolis, "protocol.op.coriolis", Drawn.POINT, Line.THIN,
                  Grade.POINT, hint_rule=coriolis_hint, alias="k")
EPSILON = OpSpec("epsilon", epsilon, "protocol.op.epsilon", grade=Grade.RATE,
                 written=Written.RATE, lever=("p", "q"), rate_of=("normal_end", "aq"),
                 value_hint=epsilon_value_hint)
RIGID_ACCELERATION = OpSpec("rigid_acceleration", rigid_acceleration,
                            "protocol.op.rigid_acceleration", Drawn.POINT, Line.OUTLINE,
                            Grade.POINT, written=Written.MEET, hint_rule=rigid_hint)

__all__ = ["CORIOLIS", "DRIVE_ACCELERATION", "EPSILON", "NORMAL", "RIGID_ACCELERATION"]
