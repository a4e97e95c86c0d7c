"""Plain-text report of a solution in the user's language (what `mechplan solve` prints)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .construct.protocol import mm, plan_title, protocol, sense_text, vector_text
from .construct.terms import pole_label
from .i18n import message, scale_factor, scientific, unit
from .i18n import number as format_number
from .model.plans import Plan
from .scene.spec import PLANS
from .solve import Solution, segment_table
from .textbook_report import cycle_lines
from .textbook_report import position_lines as textbook_lines
from .trust_report import summary_lines


def _w(key: str, lang: str) -> str:
    return message(f"report.{key}", lang)

_KEYS = ("dof", "structure", "cls", "position", "equation", "segments", "results", "crank", "fromx")

def text_report(sol: Solution, lang: str | None = None) -> str:
    """The full report: structure, then per position the plans' protocols, tables and results."""
    lang = lang or sol.scene.language
    w = {key: _w(key, lang) for key in _KEYS}
    st = sol.structure
    out = [sol.scene.title, "=" * len(sol.scene.title),
           f"{w['dof']}: W = 3·{st.moving_links} − 2·{st.lower_pairs} = {st.dof}",
           f"{w['structure']}: {st.formula}  ({w['cls']} {st.mechanism_class})"]
    for g in st.groups:
        out.append(f"  {g.name}: {g.kind}")
    plans = tuple(Plan(p) for p in sol.plans if p in PLANS)
    theta = sol.construction.drive.absolute(sol.phi)
    failed = {f.k: f for f in sol.failures}
    for k in range(sol.positions):
        if sol.scene.mechanism.drive.linear:   # the driver's length: l4 = 1450.0 mm
            q_txt = format_number(sol.phi[k] * 1000, 1, lang)
            out += ["", (f"## {w['position']} {k}: {sol.construction['pos.q'].label} = {q_txt} "
                    f"{unit('mm', lang)}")]
        else:
            phi_txt = format_number(math.degrees(sol.phi[k]), 2, lang)
            th_txt = format_number(math.degrees(math.remainder(theta[k], 2 * math.pi)), 2, lang)
            out += ["", (f"## {w['position']} {k}: φ = {phi_txt}° ({w['crank']} {th_txt}° "
                    f"{w['fromx']})")]
        if k in failed:
            out.append(message("estimate.not_built", lang, reason=failed[k].reason))
            continue
        steps = protocol(sol.construction, sol.ev, k, lang, sol.scales, plans)
        for plan in plans:
            mu = sol.scales.get(plan, 1.0)
            scale_unit = unit(plan.scale_unit, lang)
            num = scale_factor(mu, lang)
            out += ["", f"### {plan_title(plan, lang)} (μ = {num} {scale_unit})"]
            for (p, group), (eq, rows) in sol.construction.equations.items():
                if p is plan:
                    out.append(f"{w['equation']} {group}: {eq}")
                    for term, direction, magnitude in rows:
                        out.append(f"    {term:<16} {direction.text(lang):<12} "
                                   f"{magnitude}")
            n = 0
            for p, label, text in steps:
                if p is plan:
                    n += 1
                    out.append(f"  {n:>2}. {text}")
            measured = segment_table(sol, plan, k)
            if measured:
                out.append(f"  {w['segments']}:")
                for name, mm_, _mu, quantity, value in measured:
                    out.append(
                        f"    {pole_label(name, lang):<14} "
                        f"{format_number(mm_, 1, lang):>8} {mm(lang)}"
                        f"   {quantity:<14} {format_number(value, 4, lang)}"
                    )
        out += ["", f"### {w['results']}"]
        out += _results(sol, k, lang)
        out += textbook_lines(sol, k, lang)
        if "forces" in sol.extras:
            out += [""] + _forces(sol, k, lang)
    out += cycle_lines(sol, lang)
    out += summary_lines(sol, lang)
    return "\n".join(out)


def _results(sol: Solution, k: int, lang: str) -> list[str]:
    c, ev = sol.construction, sol.ev
    lines = []
    pts = sol.scene.points_of_interest or tuple(
        p for lk in sol.scene.mechanism.links.values() if lk.id != "0" for p in lk.points)
    for p in dict.fromkeys(pts):
        parts = [f"{p:<4}"]
        if c.has_position(p) and c.position(p) in ev.values:
            x, y = ev[c.position(p)][k] * 1000
            parts.append(f"r = ({format_number(x, 2, lang)}; {format_number(y, 2, lang)}) "
                         f"{unit('mm', lang)}")
        for sym, si_unit, image in (
            ("v", "m/s", c.velocity_image),
            ("a", "m/s²", c.acceleration_image),
        ):
            sid = image(p) if c.has_result(sym, p) else None
            if sid in ev.values:
                vec = ev[sid][k]
                mag = float(np.hypot(*vec))
                text = f"{sym} = {format_number(mag, 4, lang)} {unit(si_unit, lang)}"
                if round(mag, 4) != 0:
                    text += (
                        f" ∠ {format_number(math.degrees(math.atan2(vec[1], vec[0])), 1, lang)}°"
                    )
                parts.append(text)
        lines.append("  " + "   ".join(parts))
    for lid in sol.scene.mechanism.moving:
        parts = []
        for key, sym, si_unit, of in (("omega", "ω", "rad/s", c.omega),
                                   ("epsilon", "ε", "rad/s²", c.epsilon)):
            sid = of(lid) if c.has_result(key, lid) else None
            if sid in ev.values:
                parts.append(f"{sym}{lid} = {format_number(float(ev[sid][k]), 4, lang)} "
                             f"{unit(si_unit, lang)}")
        if parts:
            lines.append("  " + "   ".join(parts))
    return lines


_FORCE_KEYS = ("reactions", "guide_reactions", "balancing", "driving", "resisting", "lever",
               "difference", "reduced_moment", "reduced_inertia", "at", "pure_couple")


def _forces(sol: Solution, k: int, lang: str) -> list[str]:
    """Reactions, guide reactions, balancing moment (two ways), M_red and J_red at position k."""
    fa = sol.extras["forces"]
    w = [_w(f"force.{key}", lang) for key in _FORCE_KEYS]
    out = [f"### {w[0]}"]
    for r in fa.reactions.values():
        out.append(f"  R_{r.key} = {vector_text(r.force[k], lang, 2)}   ({w[9]} {r.point})")
    if fa.guide_reactions:
        out.append(f"### {w[1]} {', '.join(r.point for r in fa.guide_reactions.values())}")
    for r in fa.guide_reactions.values():
        d = float(r.offset[k]) if r.offset is not None else math.nan
        where = (f"d = {format_number(d * 1000, 2, lang)} {unit('mm', lang)} ({r.guide})"
                 if math.isfinite(d) else w[10])
        out.append(f"  R_{r.key} = {vector_text(r.force[k], lang, 2)};  {where}")
    mb, mz = float(fa.balancing_moment[k]), float(fa.zhukovsky_moment[k])
    role = w[3] if fa.driving(k) else w[4]
    link = sol.scene.mechanism.drive.link
    if fa.linear:       # a cylinder or slider: its driving force (two ways), F_red and m_red
        n = unit("N", lang)
        pct = scientific(float(fa.difference_percent[k]), 3, lang)
        out += [
            message("drivers.force", lang, link=link, F=format_number(mb, 3, lang), unit=n,
                    role=role), *_second_lines(sol, fa, k, lang, w),
            f"  {w[5]}: F_d = {format_number(mz, 3, lang)} {n}; {w[6]} {pct} %",
            f"  {w[7]}: F_red = {format_number(float(fa.reduced_moment[k]), 3, lang)} {n}",
            (f"  {w[8]}: m_red = {format_number(float(fa.reduced_inertia[k]), 6, lang)} "
            f"{unit('kg', lang)}")]
        return out + _friction_lines(fa, k, lang)
    sense = sense_text(mb, lang)
    nm = unit("N·m", lang)
    out.append(f"### {w[2]} {link}: M_b = {format_number(mb, 3, lang)} {nm} ({sense}; {role})")
    out += _second_lines(sol, fa, k, lang, w)
    out.append(f"  {w[5]}: M_b = {format_number(mz, 3, lang)} {nm}; {w[6]} "
               f"{scientific(float(fa.difference_percent[k]), 3, lang)} %")
    out.append(f"  {w[7]}: M_red = {format_number(float(fa.reduced_moment[k]), 3, lang)} {nm}")
    out.append(f"  {w[8]}: J_red = {format_number(float(fa.reduced_inertia[k]), 6, lang)} "
               f"{unit('kg·m²', lang)}")
    return out + _friction_lines(fa, k, lang)


def _friction_lines(fa: Any, k: int, lang: str) -> list[str]:
    """The friction block (a scene with ``[friction]``), else nothing."""
    if fa.friction is None:
        return []
    from .dynamics.friction import report_lines
    return report_lines(fa.friction, k, lang)


def _second_lines(sol: Solution, fa: Any, k: int, lang: str, w: list[str]) -> list[str]:
    """W = 2: the second driver's own balancing moment (a crank) or driving force (a cylinder)."""
    if fa.second is None:
        return []
    value = float(fa.second[1][k])
    drive2 = sol.scene.mechanism.drive2
    role2 = w[3] if drive2 is not None and value * drive2.omega > 0 else w[4]
    if fa.second_linear:
        return [message("drivers.force", lang, link=fa.second[0],
                        F=format_number(value, 3, lang), unit=unit("N", lang), role=role2)]
    nm = unit("N·m", lang)
    return ["### " + message("twoinputs.balancing", lang, link=fa.second[0],
                             value=f"{format_number(value, 3, lang)} {nm} "
                                   f"({sense_text(value, lang)}; {role2})")]
