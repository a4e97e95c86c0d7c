"""The instant centres of a solved linkage: computed when its scene asks (plan ``centres``).

The centres use only the position plan; the velocities found through them (from ω of the driver)
are a second method, compared with the velocity plan at every position (``agreement``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..construct.centre_kinematics import (
    ByCentres,
    acceleration_pole,
    centrodes_over_turn,
    inflection_circle,
    velocities_by_centres,
)
from ..construct.graph import Construction, Evaluation
from ..construct.plans.centres import Centre, Centres, centres_at, label
from ..geom.vec import Array
from ..model.mechanism import GROUND, Mechanism

if TYPE_CHECKING:
    from ..solve import Solution

#: an estimated relative error of a centre above this is reported
CENTRE_TOLERANCE = 1e-6


@dataclass
class CentresAnalysis:
    """Centres and what they give at the solution's positions, and centrodes over a cycle.

    ``agreement`` (n,): the largest difference of ω (over the largest |ω| of the plan) and of v
    (over the largest |v|) between the centres and the velocity plan, NaN where not built."""

    centres: Centres
    by_centres: ByCentres
    agreement: Array
    poles: dict[str, Array] = field(default_factory=dict)
    inflection: dict[str, tuple[Array, Array, Array]] = field(default_factory=dict)
    centrodes: dict[str, tuple[Array, Array, Array]] = field(default_factory=dict)
    #: links of ``[centres] links`` whose absolute centre Kennedy's theorem does not find (W = 2):
    #: no centrodes, no inflection circle
    undetermined: list[str] = field(default_factory=list)


def _position_error(sol: Solution) -> Array | None:
    c, est = sol.construction, sol.estimate
    pins = {p.point for p in sol.scene.mechanism.pairs}
    errs = []
    for p in pins:
        sid = c.position(p)
        if sid in est:
            errs.append(np.asarray(est.relative(sid), dtype=float))
    return np.max(errs, axis=0) if errs else None


def analyse_centres(sol: Solution) -> CentresAnalysis:
    """The centres of a solution (memoised in ``sol.extras``)."""
    if "centres" in sol.extras:
        return sol.extras["centres"]  # type: ignore[no-any-return]
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    cs = centres_at(c, ev, mech, _position_error(sol))
    more = {d.link: ev[c.omega(d.link)] for d in mech.drivers[1:]
            if c.has_result("omega", d.link) and (GROUND, d.link) in cs.values}
    by = velocities_by_centres(cs, mech, ev[c.omega(mech.drive.link)],
                               lambda p: ev[c.position(p)], more)
    out = CentresAnalysis(cs, by, agreement(c, ev, mech, by))
    spec = sol.scene.centres
    if spec is not None:
        accelerations = c.has_result("epsilon", mech.drive.link)
        for lid in spec.links:
            known = (GROUND, lid) in cs.values
            if not known:
                out.undetermined.append(lid)
            if accelerations:
                p = next(iter(mech.links[lid].points))
                a, r = ev[c.acceleration_image(p)], ev[c.position(p)]
                w, e = ev[c.omega(lid)], ev[c.epsilon(lid)]
                out.poles[lid] = acceleration_pole(a, r, w, e)
                if spec.inflection and known:
                    out.inflection[lid] = inflection_circle(cs.point(GROUND, lid), a, r, w, e)
            if known:
                out.centrodes[lid] = centrodes_over_turn(c, mech, lid, spec.positions)
    sol.extras["centres"] = out
    return out


def agreement(c: Construction, ev: Evaluation, mech: Mechanism, by: ByCentres) -> Array:
    """Relative difference of the velocities by centres from the velocity plan, per position."""
    n = ev.n
    w_plan = {lid: ev[c.omega(lid)] for lid in by.omega if c.has_result("omega", lid)}
    v_plan = {p: ev[c.velocity_image(p)] for p in by.v if c.has_result("v", p)}
    with np.errstate(invalid="ignore"):
        w_scale = max([float(np.nanmax(np.abs(w))) for w in w_plan.values()] + [0.0])
        v_scale = max([float(np.nanmax(np.hypot(v[:, 0], v[:, 1]))) for v in v_plan.values()]
                      + [0.0])
        out = np.zeros(n)
        for lid, w in w_plan.items():
            out = np.fmax(out, np.abs(by.omega[lid] - w) / (w_scale or 1.0))
        for p, v in v_plan.items():
            d = by.v[p] - v
            out = np.fmax(out, np.hypot(d[:, 0], d[:, 1]) / (v_scale or 1.0))
        bad = ~np.isfinite(ev[c.omega(mech.drive.link)])
        for w in w_plan.values():
            bad |= ~np.isfinite(w)
    out[bad] = np.nan
    return out


def _xy(v: Array) -> list[float]:
    return [float(v[0]), float(v[1])]


def centre_json(cs: Centres, centre: Centre, k: int) -> dict[str, Any]:
    """One centre at position k: ``r`` (m) or ``at_infinity`` + ``direction``, and how found."""
    val = cs.values[(centre.i, centre.j)]
    h = val.h[k]
    entry: dict[str, Any] = {}
    if not np.all(np.isfinite(h)):
        entry["indeterminate"] = True
    elif h[2] == 0.0:
        entry["at_infinity"] = True
        entry["direction"] = _xy(h[:2])
    else:
        entry["at_infinity"] = False
        entry["r"] = _xy(h[:2] * cs.length)
    if centre.pair is None:
        a, b = (int(x) for x in val.triangles[k])
        links = cs.diagram.links
        entry["lines"] = [[label((centre.i, kk), links=links), label((centre.j, kk), links=links)]
                          for kk in (centre.via[a], centre.via[b])]
        entry["sine"] = float(val.sine[k])
        entry["conditioning"] = float(val.size[k])
    entry["error_estimate"] = float(val.error[k])
    return entry


def centres_json(sol: Solution) -> dict[str, Any]:
    """The ``centres`` section of the JSON document."""
    an = analyse_centres(sol)
    cs = an.centres
    d = cs.diagram
    per_position = []
    for k in range(sol.positions):
        by = an.by_centres
        entry: dict[str, Any] = {
            "centres": {label(c): centre_json(cs, c, k) for c in d.centres},
            "omega": {lid: float(w[k]) for lid, w in by.omega.items()},
            "v": {p: _xy(v[k]) for p, v in by.v.items()},
            "agreement": None if math.isnan(an.agreement[k]) else float(an.agreement[k]),
        }
        if an.poles:
            entry["acceleration_pole"] = {lid: _point_or_none(q[k]) for lid, q in an.poles.items()}
        if an.inflection:
            entry["inflection_circle"] = {
                lid: {"centre": _point_or_none(ctr[k]), "radius": _float_or_none(rad[k]),
                      "inflection_pole": _point_or_none(j[k])}
                for lid, (ctr, rad, j) in an.inflection.items()}
        per_position.append(entry)
    finite = an.agreement[np.isfinite(an.agreement)]
    out: dict[str, Any] = {
        "links": list(d.links),
        "count": d.count,
        "order": [label(c) for c in d.centres],
        "primary": [label(c) for c in d.centres if c.primary],
        "missing": [label(p) for p in d.missing],
        "symbol": "I",
        "circle_diagram": [{"centre": label(c), "links": [c.i, c.j], "step": c.order,
                            "pair": c.pair.name if c.pair else None,
                            "via": list(c.via)} for c in d.centres],
        "agreement_max": float(finite.max()) if finite.size else None,
        "positions": per_position,
    }
    from .centre_velocity import drawn_json

    drawn = drawn_json(sol)
    if drawn is not None:
        out["drawn"] = drawn
    if an.centrodes:
        out["centrodes"] = {lid: {"phi_deg": [float(x) for x in np.degrees(phi)],
                                  "fixed": [_point_or_none(p) for p in fixed],
                                  "moving": [_point_or_none(p) for p in moving]}
                            for lid, (phi, fixed, moving) in an.centrodes.items()}
    return out


def _point_or_none(p: Array) -> list[float] | None:
    return _xy(p) if np.all(np.isfinite(p)) else None


def _float_or_none(x: float) -> float | None:
    return float(x) if math.isfinite(float(x)) else None


__all__ = ["CENTRE_TOLERANCE", "CentresAnalysis", "agreement", "analyse_centres",
           "centre_json", "centres_at", "centres_json", "label"]
