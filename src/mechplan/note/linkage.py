"""The linkage chapters of a note: task data, structure, kinematics per position, forces.

Everything is read off the solved construction (its equations, protocol sentences and measured
segments) and the study's JSON; nothing is computed here beyond the arithmetic a student writes
between a formula and its result (a ratio of two printed numbers, π·n/30).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..construct.protocol import protocol, sense_text
from ..construct.segments import SegmentKind
from ..construct.terms import pole_label
from ..i18n import message, scale_factor, significant, unit
from ..i18n import number as fmt
from ..model.plans import Plan
from ..scene.spec import PLANS
from ..solve import segment_table
from ..studies.mechanism import MechanismStudy
from .model import Block, Equation, Heading, Paragraph, Steps, Table


def _m(key: str, lang: str, **values: Any) -> str:
    return message(f"note.{key}", lang, **values)


def sig(value: float, lang: str, figures: int = 4) -> str:
    """A result to ``figures`` significant figures in the language's writing."""
    return significant(value, figures, lang)


def linkage_blocks(study: MechanismStudy, doc: dict[str, Any], lang: str) -> list[Block]:
    """Task, structure, kinematics (per position) and forces of a solved linkage."""
    sol = study.solution
    out: list[Block] = [Heading(_m("h.linkage", lang, title=sol.scene.title), 1, "linkage")]
    out += _data(sol, lang)
    out += _structure(sol, lang)
    out += _kinematics(sol, doc, lang)
    if any("forces" in p for p in doc["positions"]):
        out += _forces(sol, doc, lang)
    return out


def _data(sol: Any, lang: str) -> list[Block]:
    """The given data: the links' lengths (as the position plan draws them), the crank's speed,
    the masses and moments of inertia."""
    rows: list[tuple[str, str, str]] = []
    seen: set[str] = set()
    for s in sol.construction.segments:
        if s.kind is SegmentKind.LINK and s.quantity not in seen:
            found = _link_of(sol, s.quantity, "l_")
            if found is not None:
                seen.add(s.quantity)
                lid, x, y = found
                length = sol.scene.mechanism.links[lid].distance(x, y)
                rows.append((s.quantity, sig(length * 1000, lang, 6), unit("mm", lang)))
    drive = sol.scene.mechanism.drive
    rows.append((f"n{drive.link}", sig(abs(drive.omega) * 30 / math.pi, lang, 6),
                 unit("rpm", lang)))
    for lid, spec in sorted(sol.scene.masses.items()):
        if spec.mass:
            rows.append((f"m{lid}", sig(spec.mass, lang, 6), unit("kg", lang)))
        if spec.inertia:
            rows.append((f"J_{spec.centre}", sig(spec.inertia, lang, 6), unit("kg·m²", lang)))
    return [Table(_m("t.data", lang), (_m("c.quantity", lang), _m("c.value", lang),
                                        _m("c.unit", lang)), tuple(rows))]


def _structure(sol: Any, lang: str) -> list[Block]:
    st = sol.structure
    rows = tuple((g.name, str(g.kind), ", ".join(g.links), str(2))
                 for g in st.groups)
    n, p5, p4 = st.moving_links, st.lower_pairs, st.higher_pairs
    return [
        Heading(_m("h.structure", lang), 2, "structure"),
        Paragraph(_m("p.structure", lang, n=n, p5=p5, p4=p4)),
        Equation("W", "3n − 2p₅ − p₄", f"3·{n} − 2·{p5} − {p4}", str(st.dof)),
        Paragraph(_m("p.groups", lang, formula=st.formula, cls=st.mechanism_class)),
        Table(_m("t.groups", lang),
              (_m("c.group", lang), _m("c.kind", lang), _m("c.links", lang), _m("c.class", lang)),
              rows),
    ]


def _kinematics(sol: Any, doc: dict[str, Any], lang: str) -> list[Block]:
    c, scene = sol.construction, sol.scene
    drive = scene.mechanism.drive
    omega = abs(drive.omega)
    n_rpm = omega * 30 / math.pi
    rad_s = unit("rad/s", lang)
    out: list[Block] = [Heading(_m("h.kinematics", lang), 2, "kinematics"),
                        Paragraph(_m("p.drive", lang, link=drive.link, pivot=drive.pivot,
                                     sense=sense_text(drive.omega, lang)))]
    out.append(Equation(f"ω{drive.link}", "π·n/30",
                        f"{fmt(math.pi, 4, lang)}·{sig(n_rpm, lang, 6)}/30",
                        fmt(omega, 2, lang), rad_s))
    plans = tuple(Plan(p) for p in sol.plans if p in PLANS)
    failed = {f.k for f in sol.failures}
    for k in range(sol.positions):
        if k in failed:
            continue
        phi = float(doc["positions"][k]["phi_deg"])
        out.append(Heading(_m("h.position", lang, k=k, phi=fmt(phi, 1, lang)), 3, f"position{k}"))
        steps = protocol(c, sol.ev, k, lang, sol.scales, plans)
        for plan in plans:
            out += _plan(sol, plan, k, steps, lang)
        out += _angular(sol, k, lang)
    return out


def _plan(sol: Any, plan: Plan, k: int, steps: list[tuple[Plan, str, str]],
          lang: str) -> list[Block]:
    from ..construct.protocol import plan_title

    mu = sol.scales.get(plan, 1.0)
    title = plan_title(plan, lang)
    out: list[Block] = [Paragraph(f"{title} (μ = {scale_factor(mu, lang)} "
                                  f"{unit(plan.scale_unit, lang)})")]
    measured = segment_table(sol, plan, k)
    measured = [(n, mm_, mu_, q, v if abs(v) > _ROUNDING else 0.0)
                for n, mm_, mu_, q, v in measured]
    first = next((r for r in measured if r[1] > 0), None)
    if first is not None:           # the segment drawn first: its length at the scale factor
        name, mm_, mu_, quantity, value = first
        out += _drive_vector(sol, plan, quantity, value, lang)
        out.append(Equation(pole_label(name, lang), f"{quantity}/μ",
                            f"{sig(value, lang)}/{scale_factor(mu_, lang)}",
                            fmt(mm_, 1, lang), unit("mm", lang)))
    for (p, group), (eq, rows) in sol.construction.equations.items():
        if p is not plan:
            continue
        out.append(Paragraph(_m("p.equation", lang, group=group, equation=eq)))
        out.append(Table(_m("t.equation", lang, group=group),
                         (_m("c.term", lang), _m("c.direction", lang), _m("c.magnitude", lang)),
                         tuple((t, d.text(lang), str(m)) for t, d, m in rows)))
    sentences = tuple(text for p, _label, text in steps if p is plan)
    if sentences:
        out.append(Steps(sentences))
    if measured:
        mm = unit("mm", lang)
        out.append(Table(_m("t.segments", lang, plan=title),
                         (_m("c.segment", lang), f"{_m('c.length', lang)}, {mm}", "μ",
                          _m("c.quantity", lang), _m("c.value", lang)),
                         tuple((pole_label(name, lang), fmt(mm_, 1, lang),
                                scale_factor(mu_, lang), q, sig(v, lang, 5))
                               for name, mm_, mu_, q, v in measured)))
    return out


#: m/s or m/s²: below it a relative velocity or tangential acceleration is written as 0
_ROUNDING = 1e-9


def _drive_vector(sol: Any, plan: Plan, quantity: str, value: float,
                  lang: str) -> list[Block]:
    """v_B = ω1·l_AB, a_B = ω1²·l_AB of the crank's end (constant speed), as the plan lays it."""
    drive = sol.scene.mechanism.drive
    crank = sol.scene.mechanism.links[drive.link]
    point = quantity.split("_", 1)[-1]
    if point not in crank.points or point == drive.pivot:
        return []
    length = crank.distance(drive.pivot, point)
    w = fmt(abs(drive.omega), 3, lang)
    l_name = f"l_{drive.pivot}{point}"
    if plan is Plan.VELOCITY and quantity == f"v_{point}":
        return [Equation(quantity, f"ω{drive.link}·{l_name}", f"{w}·{sig(length, lang)}",
                         fmt(value, 3, lang), unit("m/s", lang))]
    if plan is Plan.ACCELERATION and quantity == f"a_{point}" and drive.epsilon == 0:
        return [Equation(quantity, f"ω{drive.link}²·{l_name}", f"{w}²·{sig(length, lang)}",
                         fmt(value, 3, lang), unit("m/s²", lang))]
    return []


def _link_of(sol: Any, quantity: str, prefix: str) -> tuple[str, str, str] | None:
    """(link, X, Y) of a relative quantity ``v_XY`` / ``a^t_XY`` whose points share a link."""
    body = quantity.removeprefix(prefix)
    for lid in sol.scene.mechanism.moving:
        pts = sol.scene.mechanism.links[lid].points
        for i in range(1, len(body)):
            x, y = body[:i], body[i:]
            if x in pts and y in pts:
                return lid, x, y
    return None


def _angular(sol: Any, k: int, lang: str) -> list[Block]:
    """ω_i = v_XY / l_XY and ε_i = a^t_XY / l_XY of each link with a relative segment."""
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    out: list[Block] = []
    done: set[tuple[str, str]] = set()
    for s in c.segments:
        if s.start not in ev.values or s.end not in ev.values:
            continue
        if s.plan is Plan.VELOCITY and s.kind is SegmentKind.RELATIVE:
            sym, key, prefix, si = "ω", "omega", "v_", "rad/s"
        elif s.plan is Plan.ACCELERATION and s.kind is SegmentKind.TANGENTIAL:
            sym, key, prefix, si = "ε", "epsilon", "a^t_", "rad/s²"
        else:
            continue
        found = _link_of(sol, s.quantity, prefix)
        if found is None or (key, found[0]) in done or not c.has_result(key, found[0]):
            continue
        lid, x, y = found
        done.add((key, lid))
        value = float(np.hypot(*(ev[s.end][k] - ev[s.start][k])))
        if value < _ROUNDING:            # a zero the floating point left a trace of (a dead centre)
            value = 0.0
        length = mech.links[lid].distance(x, y)
        signed = float(ev[c.omega(lid) if key == "omega" else c.epsilon(lid)][k])
        result = value / length
        sense = f" ({sense_text(signed, lang)})" if round(result, 3) != 0 else ""
        out.append(Equation(f"{sym}{lid}", f"{s.quantity}/l_{x}{y}",
                            f"{sig(value, lang)}/{sig(length, lang)}",
                            fmt(result, 3, lang), unit(si, lang) + sense))
    return out


def _forces(sol: Any, doc: dict[str, Any], lang: str) -> list[Block]:
    out: list[Block] = [Heading(_m("h.forces", lang), 2, "forces")]
    n_unit, nm = unit("N", lang), unit("N·m", lang)
    link = sol.scene.mechanism.drive.link
    for k, pos in enumerate(doc["positions"]):
        f = pos.get("forces")
        if not f:
            continue
        phi = float(pos["phi_deg"])
        out.append(Heading(_m("h.position", lang, k=k, phi=fmt(phi, 1, lang)), 3, f"forces{k}"))
        inertia = f.get("inertia", {})
        if inertia:
            out.append(Table(_m("t.inertia", lang),
                             (_m("c.link", lang), f"F, {n_unit}", f"M, {nm}"),
                             tuple((lid, fmt(float(np.hypot(*q["force"])), 1, lang),
                                    fmt(float(q["moment"]), 2, lang))
                                   for lid, q in inertia.items())))
        rows = [(f"R_{key}", fmt(float(np.hypot(*r)), 1, lang),
                 fmt(math.degrees(math.atan2(r[1], r[0])), 1, lang))
                for key, r in f.get("reactions", {}).items()]
        rows += [(f"R_{key}", fmt(float(np.hypot(*r["force"])), 1, lang),
                  fmt(math.degrees(math.atan2(r["force"][1], r["force"][0])), 1, lang))
                 for key, r in f.get("guide_reactions", {}).items()]
        out.append(Table(_m("t.reactions", lang),
                         (_m("c.reaction", lang), f"{_m('c.magnitude', lang)}, {n_unit}",
                          f"{_m('c.angle', lang)}, °"), tuple(rows)))
        mb = float(f["balancing_moment"])
        mz = float(f["zhukovsky_balancing_moment"])
        out.append(Paragraph(_m("p.balancing", lang, link=link, sense=sense_text(mb, lang))))
        out.append(Equation("M_b", _m("s.polygons", lang), "", fmt(mb, 2, lang), nm))
        out.append(Equation(_m("s.lever_symbol", lang), _m("s.lever", lang), "",
                            fmt(mz, 2, lang), nm))
        diff = abs(mb - mz) / abs(mb) * 100 if mb else 0.0
        out.append(Equation("Δ", "|M_b − " + _m("s.lever_symbol", lang) + "|/|M_b|·100 %",
                            f"|{fmt(mb, 2, lang)} − ({fmt(mz, 2, lang)})|/"
                            f"{fmt(abs(mb), 2, lang)}·100 %", significant(diff, 3, lang), "%"))
        red = pos.get("reduced")
        if red:
            out.append(Table(_m("t.reduced", lang), (_m("c.quantity", lang), _m("c.value", lang)),
                             (("M_red, " + nm, fmt(float(red["moment"]), 2, lang)),
                              ("J_red, " + unit("kg·m²", lang),
                               sig(float(red["inertia"]), lang, 5)))))
    return out
