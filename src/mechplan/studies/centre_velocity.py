"""The velocities by instant centres as drawn (line of centres, МЦС) for a solved linkage: the
construction evaluated on its positions and centres, its agreement with the velocity plan (exact
and as measured on a drawing), the report's protocol and the JSON's ``drawn`` entries."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..construct.centre_drawn import DrawnVelocities, drawn
from ..construct.centre_drawn import measured_agreement as _measured
from ..construct.centre_protocol import measure, names, protocol
from ..construct.plans.centre_velocity import KENNEDY, PIN, centre_token
from ..i18n import message, scientific, significant
from ..model.plans import Plan
from .centres import analyse_centres

if TYPE_CHECKING:
    from ..solve import Solution


def drawn_velocities(sol: Solution) -> DrawnVelocities | None:
    """The drawn construction of a solution (None for a driver that is not a crank); memoised
    in ``sol.extras`` (the sheet reads the same entry)."""
    if "centres_drawn" not in sol.extras:
        sol.extras["centres_drawn"] = drawn(sol.construction, sol.ev, sol.scene.mechanism,
                                            analyse_centres(sol).centres)
    return sol.extras["centres_drawn"]  # type: ignore[no-any-return]


def measured_agreement(sol: Solution, dv: DrawnVelocities, k: int, mu_v: float) -> float:
    """The arrows measured at μv against the velocity plan at position k (relative)."""
    return _measured(sol.construction, sol.ev, dv, k, mu_v)


def scales_of(sol: Solution) -> tuple[float, float]:
    """μl and μv the report measures at: the sheet's position and velocity plans' (SI per mm)."""
    mu_l = sol.scales.get(Plan.POSITION) or 1e-3
    mu_v = sol.scales.get(Plan.VELOCITY)
    if not mu_v:
        dv = sol.extras.get("centres_drawn")
        top = 0.0
        if dv is not None:
            for sid in dv.cv.v.values():
                top = max(top, float(np.nanmax(np.hypot(*dv.ev[sid].T))))
        mu_v = top / 50.0 if top > 0 else 1.0
    return float(mu_l), float(mu_v)


def route_lines(dv: DrawnVelocities, links: tuple[str, ...], lang: str) -> list[str]:
    """How each link is reached (the same at every position)."""
    sym = message("centres.symbol", lang)
    out = []
    for r in dv.cv.routes:
        key = {PIN: "pin", KENNEDY: "kennedy"}.get(r.kind, "slide")
        centre = names(centre_token(*r.centre, links), sym)
        out.append(message(f"icdraw.route.{key}", lang, link=r.link, source=r.source,
                           centre=centre))
    return out


def report_lines(sol: Solution, k: int, lang: str) -> list[str]:
    """The drawn construction at position k: its protocol and its agreement with the plan."""
    dv = drawn_velocities(sol)
    mech = sol.scene.mechanism
    if dv is None:
        return ["  " + message("icdraw.refused", lang, link=mech.drive.link)]
    mu_l, mu_v = scales_of(sol)
    out = ["  " + message("icdraw.heading", lang),
           "    " + message("icdraw.scales", lang, mu_l=significant(mu_l, 4, lang),
                            mu_v=significant(mu_v, 4, lang))]
    out += ["    " + s for s in route_lines(dv, analyse_centres(sol).centres.diagram.links, lang)]
    out += ["    " + s for s in protocol(dv.cv, dv.ev, k, lang, mu_l, mu_v)]
    cs = analyse_centres(sol).centres
    sym = message("centres.symbol", lang)
    for lk in mech.moving:
        if lk in dv.cv.omega:
            continue
        if ("0", lk) in cs.values:
            out.append("    " + message("icdraw.unreached", lang, link=lk))
        else:
            out.append("    " + message("icdraw.unreached_centre", lang, link=lk,
                                        centre=names(centre_token("0", lk, cs.diagram.links),
                                                     sym)))
    exact = float(dv.agreement[k])
    if math.isfinite(exact):
        out.append("    " + message(
            "icdraw.agreement", lang, exact=scientific(max(exact, 0.0), 2, lang),
            measured=scientific(measured_agreement(sol, dv, k, mu_v), 2, lang)))
    return out


def drawn_json(sol: Solution) -> dict[str, Any] | None:
    """The ``centres.drawn`` object: routes, the scales measured at and per position ω, v,
    the arrows' lengths (mm) and both agreements."""
    dv = drawn_velocities(sol)
    if dv is None:
        return None
    mu_l, mu_v = scales_of(sol)
    names_ = {PIN: "pin", KENNEDY: "kennedy"}
    per = []
    for k in range(sol.positions):
        exact = float(dv.agreement[k])
        per.append({
            "omega": {lk: _num(dv.ev[s][k]) for lk, s in dv.cv.omega.items()},
            "v": {p: [_num(dv.ev[s][k][0]), _num(dv.ev[s][k][1])] for p, s in dv.cv.v.items()},
            "arrow_mm": {p: _num(measure(dv.ev[s][k], mu_v).mm) for p, s in dv.cv.v.items()},
            "agreement": exact if math.isfinite(exact) else None,
            "agreement_measured": measured_agreement(sol, dv, k, mu_v)
            if math.isfinite(exact) else None,
        })
    finite = dv.agreement[np.isfinite(dv.agreement)]
    return {"routes": [{"link": r.link, "from": r.source, "through": list(r.centre),
                        "kind": names_.get(r.kind, "slide"), "carried": r.carried}
                       for r in dv.cv.routes],
            "mu_l": mu_l, "mu_v": mu_v,
            "agreement_max": float(finite.max()) if finite.size else None,
            "positions": per}


def _num(x: float) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


__all__ = ["DrawnVelocities", "drawn_json", "drawn_velocities", "measured_agreement",
           "report_lines", "route_lines", "scales_of"]
