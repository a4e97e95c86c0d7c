"""The drawn velocities by instant centres of an evaluated mechanism: the construction evaluated
on its positions, centres and driver's ω, and its agreement with the velocity plan — exact, and
as the arrows measured to 0.1 mm at a scale give it."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..geom.vec import Array
from ..model.mechanism import Mechanism
from .centre_protocol import measure
from .graph import Construction, Evaluation
from .plans.centre_velocity import (
    CentreVelocity,
    build_centre_velocity,
    crank_driven,
    evaluate_centre_velocity,
)
from .plans.centres import Centres


@dataclass
class DrawnVelocities:
    """The construction, its evaluation and the agreement (n,) of its exact values with the
    velocity plan: the largest difference of ω (over the plan's largest |ω|) and of v (over the
    plan's largest |v|), NaN where the plan is not built."""

    cv: CentreVelocity
    ev: Evaluation
    agreement: Array


def drawn(c: Construction, ev: Evaluation, mech: Mechanism, cs: Centres) -> DrawnVelocities | None:
    """The drawn construction at an evaluation's positions (None: the driver is not a crank)."""
    if not crank_driven(mech):
        return None
    cv = build_centre_velocity(mech, cs.diagram, cs.length)
    omega = {d.link: ev[c.omega(d.link)] for d in mech.drivers if c.has_result("omega", d.link)}
    dev = evaluate_centre_velocity(cv, cs, lambda p: ev[c.position(p)], omega)
    return DrawnVelocities(cv, dev, plan_agreement(c, ev, cv, dev))


def plan_agreement(c: Construction, ev: Evaluation, cv: CentreVelocity,
                   dev: Evaluation) -> Array:
    """Relative difference of the construction's ω and v from the velocity plan, per position."""
    w_plan = {lk: ev[c.omega(lk)] for lk in cv.omega if c.has_result("omega", lk)}
    v_plan = {p: ev[c.velocity_image(p)] for p in cv.v if c.has_result("v", p)}
    out = np.zeros(ev.n)
    with np.errstate(invalid="ignore"):
        w_scale = max([float(np.nanmax(np.abs(w))) for w in w_plan.values()] + [0.0]) or 1.0
        v_scale = max([float(np.nanmax(np.hypot(v[:, 0], v[:, 1]))) for v in v_plan.values()]
                      + [0.0]) or 1.0
        bad = np.zeros(ev.n, dtype=bool)
        for lk, w in w_plan.items():
            d = np.abs(dev[cv.omega[lk]] - w) / w_scale
            bad |= ~np.isfinite(w)
            out = np.fmax(out, np.where(np.isfinite(d), d, np.inf))
        for p, v in v_plan.items():
            dv = dev[cv.v[p]] - v
            d = np.hypot(dv[:, 0], dv[:, 1]) / v_scale
            out = np.fmax(out, np.where(np.isfinite(d), d, np.inf))
    out[bad] = np.nan
    return out


def measured_agreement(c: Construction, ev: Evaluation, dv: DrawnVelocities, k: int,
                       mu_v: float) -> float:
    """The largest difference (over the plan's largest |v|) of the arrows measured to 0.1 mm at
    μv from the velocity plan at position k."""
    worst, scale = 0.0, 0.0
    pairs = []
    for p, sid in dv.cv.v.items():
        if c.has_result("v", p):
            plan_v = ev[c.velocity_image(p)][k]
            scale = max(scale, float(np.hypot(*plan_v)))
            pairs.append((dv.ev[sid][k], plan_v))
    for v, plan_v in pairs:
        m = measure(v, mu_v)
        speed = float(np.hypot(*v))
        shown = v * (m.value / speed) if speed > 0 else v
        worst = max(worst, float(np.hypot(*(shown - plan_v))))
    return worst / scale if scale > 0 else 0.0


__all__ = ["DrawnVelocities", "drawn", "measured_agreement", "plan_agreement"]
