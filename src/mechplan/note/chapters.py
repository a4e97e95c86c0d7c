"""The chapters of a note read off the JSON of the other studies: machine dynamics (flywheel),
gears, cam and engine. Each formula is written symbolically, with the printed numbers put in, and
with its result; the results themselves are the studies' (never recomputed here)."""

from __future__ import annotations

import math
from typing import Any

from ..i18n import has_message, message, significant, unit
from ..i18n import number as fmt
from .model import Block, Equation, Heading, Paragraph, Table


def _m(key: str, lang: str, **values: Any) -> str:
    return message(f"note.{key}", lang, **values)


def _s(value: float, lang: str, figures: int = 5) -> str:
    return significant(float(value), figures, lang)


def _p(text: str) -> str:
    """A substituted number in parentheses when it is negative: 4·(−2), not 4·-2."""
    return f"({text})" if text.startswith(("-", "−")) else text


def _said(msgid: str, lang: str, **values: Any) -> str:
    """A word of another area's catalogue (a cam law, a phase), or the id's last part."""
    if not has_message(msgid, lang):
        return msgid.rsplit(".", 1)[-1]
    return message(msgid, lang, **values)


def _ok(flag: Any, lang: str) -> str:
    return _m("yes" if flag else "no", lang)


def dynamics_blocks(dyn: dict[str, Any], lang: str) -> list[Block]:
    """Works, the constant moment, ΔT and the flywheel by each method."""
    nm, j_unit, rad_s = unit("N·m", lang), unit("kg·m²", lang), unit("rad/s", lang)
    j_unit_ = j_unit
    cycle = math.radians(float(dyn["cycle_deg"]))
    out: list[Block] = [Heading(_m("h.dynamics", lang), 2, "dynamics"),
                        Paragraph(_m("p.dynamics", lang, cycle=fmt(float(dyn["cycle_deg"]), 0,
                                                                     lang)))]
    work = float(dyn["work_driving"] if dyn["unknown"] == "resisting" else dyn["work_resisting"])
    out.append(Equation("M_c", "A/Φ_c", f"{_s(work, lang)}/{_s(cycle, lang)}",
                        fmt(float(dyn["constant_moment"]), 2, lang), nm))
    rows = tuple((str(p["number"]), fmt(float(p["phi_deg"]), 1, lang),
                  fmt(float(p["M_d"]), 2, lang),
                  fmt(float(p["M_c"]), 2, lang), fmt(float(p["A_d"]), 2, lang),
                  fmt(float(p["A_c"]), 2, lang), fmt(float(p["dT"]), 2, lang),
                  _s(float(p["J_red"]), lang, 4))
                 for p in dyn["positions"])
    out.append(Table(_m("t.dynamics", lang),
                     ("№", "φ, °", f"M_d, {nm}", f"M_c, {nm}", f"A_d, {unit('J', lang)}",
                      f"A_c, {unit('J', lang)}", f"ΔT, {unit('J', lang)}",
                      f"J_red, {j_unit_}"), rows))
    wm, delta = float(dyn["omega_m"]), float(dyn["delta"])
    out.append(Equation("ω_m", "π·n/30",
                        f"{fmt(math.pi, 4, lang)}·{_s(wm * 30 / math.pi, lang, 6)}/30",
                        fmt(wm, 3, lang), rad_s))
    fly = dyn["flywheel"]
    mk = fly["merkalov"]
    out.append(Paragraph(_m("p.merkalov", lang, delta=_s(delta, lang))))
    out.append(Equation("J_fl", "J_I − J_pr",
                        f"{_s(mk['J_I'], lang)} − {_s(dyn['J_present'], lang)}",
                        _s(mk["J"], lang), j_unit))
    w = fly["wittenbauer"]
    out.append(Paragraph(_m("p.wittenbauer", lang, psi_max=fmt(w["psi_max_deg"], 3, lang),
                            psi_min=fmt(w["psi_min_deg"], 3, lang))))
    out.append(Table(_m("t.flywheel", lang),
                     (_m("c.method", lang), f"J_fl, {j_unit}", "δ"),
                     ((_m("method.wittenbauer", lang), _s(w["J"], lang),
                       _s(w["delta_actual"], lang)),
                      (_m("method.merkalov", lang), _s(mk["J"], lang),
                       _s(mk["delta_actual"], lang)),
                      (_m("method.exact", lang), _s(fly["exact"]["J"], lang),
                       _s(fly["exact"]["delta_actual"], lang)))))
    size = fly.get("size")
    if size:
        out.append(Paragraph(_m("p.flywheel_size", lang, d=_s(size["diameter"], lang, 4),
                                b=_s(size["width"], lang, 4), m=_s(size["mass"], lang, 4))))
    mo = dyn["motion"]
    out.append(Equation("δ", "(ω_max − ω_min)/ω_m",
                        f"({_s(mo['omega_max'], lang)} − {_s(mo['omega_min'], lang)})/"
                        f"{_s(wm, lang)}",
                        _s((mo["omega_max"] - mo["omega_min"]) / wm, lang, 4)))
    return out


def gears_blocks(doc: dict[str, Any], lang: str) -> list[Block]:
    """The planetary train's conditions with numbers, the ordinary pair and the gear pair."""
    out: list[Block] = [Heading(_m("h.gears", lang, title=doc["title"]), 1, "gears")]
    pl = doc.get("planetary")
    if pl:
        ch = pl["chosen"]
        z = ch["z"]
        out.append(Paragraph(_m("p.planetary", lang, scheme=pl["scheme"], fixed=pl["fixed"],
                                input=pl["input"], output=pl["output"], k=pl["planets"],
                                z=", ".join(f"z{i + 1} = {v}" for i, v in enumerate(z)))))
        iw = float(pl["willis_i"])
        if pl["scheme"] == "two_row_ext_int" and len(z) == 4:
            out.append(Equation("i^h_14", "(−z2/z1)·(z4/z3)", f"(−{z[1]}/{z[0]})·({z[3]}/{z[2]})",
                                _s(iw, lang)))
            out.append(Equation("z1 + z2", "z4 − z3", f"{z[3]} − {z[2]}", str(z[0] + z[1])))
        out.append(Equation("U", "1 − i^h", f"1 − {_p(_s(iw, lang))}", _s(ch["ratio"], lang)))
        out.append(Equation("z1·U/k", "", f"{z[0]}·{_s(ch['ratio'], lang)}/{pl['planets']}",
                            _s(ch["assembly_z1u_over_k"], lang)))
        mm = unit("mm", lang)
        out.append(Table(_m("t.conditions", lang),
                         (_m("c.condition", lang), _m("c.value", lang), _m("c.met", lang)),
                         ((_m("cond.ratio", lang), _s(ch["ratio"], lang),
                           _ok(ch["ratio_ok"], lang)),
                          (_m("cond.coaxial", lang), ", ".join(_s(a * 1000, lang) for a in
                                                              ch["a_w_m"]) + f" {mm}",
                           _ok(ch["coaxial"], lang)),
                          (_m("cond.assembly", lang), _s(ch["assembly_z1u_over_k"], lang),
                           _ok(ch["valid"], lang)),
                          (_m("cond.neighbour", lang),
                           (f"{_s(ch['neighbour_span_m'] * 1000, lang)} > "
                           f"{_s(ch['planet_tip_diameter_m'] * 1000, lang)} {mm}"),
                           _ok(ch["neighbour_ok"], lang)),
                          (_m("cond.undercut", lang), str(ch["z_smallest"]),
                           _ok(ch["undercut_ok"], lang)))))
    od = doc.get("ordinary")
    if od:
        out.append(Equation("u56", "z6/z5", f"{od['z6']}/{od['z5']}", _s(od["ratio"], lang)))
        if pl:
            out.append(Equation("U_Σ", "U·u56",
                                f"{_s(pl['chosen']['ratio'], lang)}·{_p(_s(od['ratio'], lang))}",
                                _s(od["total_ratio"], lang)))
    pair = doc.get("pair")
    if pair:
        mm = unit("mm", lang)
        out.append(Paragraph(_m("p.pair", lang, m=_s(pair["module_m"] * 1000, lang),
                                z=", ".join(str(v) for v in pair["z"]),
                                x=", ".join(fmt(float(v), 3, lang) for v in pair["x"]))))
        out.append(Equation("a_w", "a·cos α/cos α_w",
                            f"{_s(pair['a_m'] * 1000, lang)}·cos {_s(pair['alpha_deg'], lang)}°/"
                            f"cos {_s(pair['alpha_w_deg'], lang)}°",
                            _s(pair["a_w_m"] * 1000, lang), mm))
        out.append(Equation("ε_α", "", "", fmt(float(pair["contact_ratio"]), 3, lang)))
    return out


def cam_blocks(doc: dict[str, Any], lang: str) -> list[Block]:
    """The laws of the phases, the base radius from the allowed pressure angle, the extremes."""
    mm, deg = unit("mm", lang), "°"
    out: list[Block] = [Heading(_m("h.cam", lang, title=doc["title"]), 1, "cam")]
    fol = doc["follower"]
    out.append(Paragraph(_m("p.cam", lang, motion=_said(f"cam.motion.{fol['motion']}", lang),
                            contact=_said(f"cam.contact.{fol['contact']}", lang,
                                          rr=_s(fol["roller_radius"] * 1000, lang)),
                            h=_s(doc["stroke"] * 1000, lang), omega=_s(doc["omega"], lang))))
    out.append(Table(_m("t.phases", lang),
                     (_m("c.phase", lang), _m("c.law", lang), f"φ, {deg}"),
                     tuple((_said(f"cam.phase.{ph['kind']}", lang),
                            _said(f"cam.law.{ph['law']}", lang) if ph["law"] else "—",
                            fmt(math.degrees(ph["angle"]), 1, lang)) for ph in doc["phases"])))
    br = doc["base_radius"]
    out.append(Equation("r0_min", "", "", _s(br["minimum"] * 1000, lang), mm))
    out.append(Equation("r0", "", "", _s(br["used"] * 1000, lang), mm))
    rows = []
    for phase in ("rise", "return"):
        alpha, at = doc["pressure_angle_max"][phase]
        rows.append((_said(f"cam.phase.{phase}", lang), fmt(math.degrees(alpha), 2, lang),
                     fmt(math.degrees(at), 1, lang)))
    out.append(Table(_m("t.pressure", lang),
                     (_m("c.phase", lang), f"α_max, {deg}", f"φ, {deg}"), tuple(rows)))
    rho = doc["radius_of_curvature_min"]["profile"]
    out.append(Equation("ρ_min", "", "", _s(rho[0] * 1000, lang), mm))
    return out


def engine_blocks(doc: dict[str, Any], lang: str, every_deg: float = 30.0) -> list[Block]:
    """Engine data with formulas, the torque table and the checks."""
    e = doc["engine"]
    mm, nm = unit("mm", lang), unit("N·m", lang)
    out: list[Block] = [Heading(_m("h.engine", lang, title=doc["title"]), 1, "engine")]
    out.append(Equation("λ", "R/L", f"{_s(e['R'] * 1000, lang)}/{_s(e['L'] * 1000, lang)}",
                        fmt(float(e["lambda"]), 4, lang)))
    out.append(Equation("F_p", "π·D²/4", f"{fmt(math.pi, 4, lang)}·{_s(e['bore'], lang)}²/4",
                        _s(e["F_p"], lang, 4), unit("m²", lang)))
    out.append(Equation("V_h", "F_p·2R", f"{_s(e['F_p'], lang, 4)}·2·{_s(e['R'], lang)}",
                        _s(e["V_h"], lang, 4), unit("m³", lang)))
    out.append(Equation("n", "30·ω/π", f"30·{_s(e['omega'], lang)}/{fmt(math.pi, 4, lang)}",
                        _s(e["omega"] * 30 / math.pi, lang, 4), unit("rpm", lang)))
    rows = []
    for a in doc["angles"]:
        phi = float(a["phi_deg"])
        if abs(math.remainder(phi, every_deg)) > 1e-6:
            continue
        cyl = a["cylinders"]
        rows.append((fmt(phi, 0, lang), *(fmt(float(cyl[c]["P"]), 0, lang) for c in cyl),
                     *(fmt(float(cyl[c]["T"]), 0, lang) for c in cyl),
                     fmt(float(a["M_total"]), 1, lang)))
    names = list(doc["angles"][0]["cylinders"])
    n_unit = unit("N", lang)
    out.append(Table(_m("t.engine", lang),
                     ("φ, °", *(f"P{c}, {n_unit}" for c in names),
                      *(f"T{c}, {n_unit}" for c in names), f"M, {nm}"), tuple(rows)))
    t = doc["torque"]
    out.append(Equation("μ", "(M_max − M_min)/M_mean",
                        f"({fmt(t['max'], 1, lang)} − ({fmt(t['min'], 1, lang)}))/"
                        f"{fmt(t['mean'], 1, lang)}", fmt(float(t["non_uniformity"]), 3, lang)))
    ch = doc["checks"]
    out.append(Table(_m("t.checks", lang), (_m("c.check", lang), _m("c.value", lang)),
                     ((_m("check.work", lang), (f"{_s(ch['work_torque'], lang)} "
                       f"{unit('J', lang)}")),
                      (_m("check.work_error", lang), _s(ch["work_error"], lang, 3)),
                      (_m("check.p_max", lang), (f"{_s(ch['p_max'] / 1e6, lang, 4)} "
                       f"{unit('MPa', lang)}")),
                      (_m("check.a_max", lang), f"{_s(ch['a_max'], lang)} {unit('m/s²', lang)}"),
                      (_m("check.series", lang),
                       f"{_s(ch['series_da_max'], lang, 3)} {unit('m/s²', lang)}"))))
    del mm
    return out
