"""The instant centres in the text report: the circle diagram, the construction of each centre,
the velocities by centres and their agreement with the velocity plan, poles and circles."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..i18n import message, number, scientific, significant, width
from ..model.mechanism import GROUND, PairKind
from .centres import CENTRE_TOLERANCE, CentresAnalysis, analyse_centres, label

if TYPE_CHECKING:
    from ..construct.plans.centres import Centre
    from ..solve import Solution


def _mm(x: float, lang: str) -> str:
    return number(x * 1000.0, 2, lang)


def _construction(c: Centre, sym: str, lang: str, links: tuple[str, ...]) -> str:
    name = label(c, sym)
    if c.pair is not None:
        if c.pair.kind is PairKind.REVOLUTE:
            return message("centres.step.pin", lang, centre=name, point=c.pair.point,
                           a=c.i, b=c.j)
        return message("centres.step.slide", lang, centre=name, guide=c.pair.guide or "",
                       a=c.i, b=c.j)
    k1, k2 = c.via[0], c.via[1]
    return message("centres.step.kennedy", lang, centre=name, p=label((c.i, k1), sym, links),
                   q=label((c.j, k1), sym, links), r=label((c.i, k2), sym, links),
                   s=label((c.j, k2), sym, links))


def diagram_lines(an: CentresAnalysis, lang: str) -> list[str]:
    """The circle diagram and the construction of each centre (the same at every position)."""
    sym = message("centres.symbol", lang)
    d = an.centres.diagram
    out = [message("centres.diagram", lang, links="–".join(d.links), count=d.count,
                   order=", ".join(label(c, sym) for c in d.centres))]
    out += [f"  {n + 1:>2}. {_construction(c, sym, lang, d.links)}"
            for n, c in enumerate(d.centres)]
    if d.missing:
        out.append(message("centres.missing", lang,
                           centres=", ".join(label(p, sym) for p in d.missing)))
    return out


def position_lines(an: CentresAnalysis, sol: Solution, k: int, lang: str) -> list[str]:
    """The centres at position k, the velocities by them and the agreement."""
    sym = message("centres.symbol", lang)
    cs, mech = an.centres, sol.scene.mechanism
    out: list[str] = []
    for c in cs.diagram.centres:
        val = cs.values[(c.i, c.j)]
        h, name = val.h[k], label(c, sym)
        if not np.all(np.isfinite(h)):
            out.append("    " + message("centres.indeterminate", lang, centre=name))
            continue
        if h[2] == 0.0:
            where = message("centres.infinite", lang,
                            angle=number(math.degrees(math.atan2(h[1], h[0])), 2, lang))
        else:
            where = message("centres.at", lang, x=_mm(h[0] * cs.length, lang),
                            y=_mm(h[1] * cs.length, lang))
        out.append(f"    {name}: {where}")
        if val.error[k] > CENTRE_TOLERANCE:
            out.append("      " + message("centres.ill", lang, centre=name,
                                          size=significant(float(val.size[k]), 3, lang),
                                          error=scientific(float(val.error[k]), 2, lang)))
    drv = mech.drive.link
    out.append("  " + message("centres.velocity_heading", lang, driver=drv))
    by = an.by_centres
    drivers = {d.link for d in mech.drivers}
    for lid in mech.moving:
        if lid in drivers or lid not in by.omega:
            continue
        out.append("    " + message(
            "centres.omega", lang, link=lid, driver=drv, a=label((GROUND, drv), sym),
            b=label((drv, lid), sym, cs.diagram.links), c=label((GROUND, lid), sym),
            value=significant(float(by.omega[lid][k]), 6, lang)))
    for p, v in by.v.items():
        carrier = next((lk for lk in mech.moving if p in mech.links[lk].points
                        and lk in by.omega and (GROUND, lk) in cs.values), None)
        if carrier is None:
            continue
        lid = carrier
        speed = significant(float(np.hypot(*v[k])), 6, lang)
        abs_c = label((GROUND, lid), sym)
        if cs.of(GROUND, lid).h[k, 2] == 0.0:
            out.append("    " + message("centres.v_translating", lang, point=p, value=speed,
                                        link=lid, centre=abs_c))
        else:
            out.append("    " + message("centres.v", lang, point=p, link=lid, centre=abs_c,
                                        value=speed))
    agree = float(an.agreement[k])
    if math.isfinite(agree):
        out.append("    " + message("centres.agreement", lang,
                                    value=scientific(max(agree, 0.0), 2, lang)))
    from .centre_velocity import report_lines

    out += report_lines(sol, k, lang)
    out += _poles(an, k, lang)
    return out


def _poles(an: CentresAnalysis, k: int, lang: str) -> list[str]:
    out = []
    for lid, q in an.poles.items():
        if np.all(np.isfinite(q[k])):
            out.append("  " + message("centres.pole", lang, link=lid, x=_mm(q[k][0], lang),
                                      y=_mm(q[k][1], lang)))
        else:
            out.append("  " + message("centres.no_pole", lang, link=lid))
    for lid, (ctr, rad, j) in an.inflection.items():
        if np.all(np.isfinite(ctr[k])) and math.isfinite(float(rad[k])):
            out.append("  " + message(
                "centres.inflection", lang, link=lid, x=_mm(ctr[k][0], lang),
                y=_mm(ctr[k][1], lang), d=_mm(2.0 * float(rad[k]), lang),
                jx=_mm(j[k][0], lang), jy=_mm(j[k][1], lang)))
        else:
            out.append("  " + message("centres.no_inflection", lang, link=lid))
    return out


def centres_report(sol: Solution, lang: str) -> str:
    """The section of the text report (empty when the scene does not ask for centres)."""
    if "centres" not in sol.plans:
        return ""
    an = analyse_centres(sol)
    heading = message("centres.heading", lang)
    out = [heading, "=" * width(heading)]
    out += diagram_lines(an, lang)
    failed = {f.k for f in sol.failures}
    for k in range(sol.positions):
        if k in failed:
            continue
        phi = number(math.degrees(float(sol.phi[k])), 2, lang)
        out += ["", f"## {k}: φ = {phi}°"]
        out += position_lines(an, sol, k, lang)
    for lid, (phi_, _, _) in an.centrodes.items():
        out.append(message("centres.centrodes", lang, link=lid, count=len(phi_)))
    for lid in an.undetermined:
        out.append(message("icdraw.undetermined", lang, link=lid,
                           centre=label(("0", lid), message("centres.symbol", lang))))
    return "\n".join(out) + "\n"
