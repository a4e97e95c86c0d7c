"""The textbook answers of a solution: compute them when asked, and say them in text and JSON.

Asked by the scene's ``[answers]`` section or by ``mechplan solve --answers``; see docs/textbook.md.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .construct.protocol import vector_text
from .construct.terms import from_to, parallel, perp
from .construct.textbook import Rubbing, Sliding, TextbookAnswers, textbook_answers
from .errors import SceneError
from .i18n import Text, message, unit
from .i18n import number as format_number
from .model.mechanism import GROUND
from .model.textbook import Answer, TextbookSpec
from .solve import Solution

KEY = "textbook"


def attach(sol: Solution, spec: TextbookSpec | None = None) -> TextbookAnswers | None:
    """Compute the answers ``spec`` (default: the scene's ``[answers]``) asks for into
    ``sol.extras["textbook"]``; None when nothing is asked."""
    spec = spec or sol.scene.textbook
    if spec is None:
        return None
    sol.extras[KEY] = textbook_answers(sol.construction, sol.ev, sol.scene.mechanism,
                                       sol.structure, spec, sol.scene.points_of_interest,
                                       sol.scene.path)
    return sol.extras[KEY]


def spec_from_flags(asked: str, pin_radius_mm: float | None,
                    base: TextbookSpec | None) -> TextbookSpec:
    """The spec of ``--answers relative,stroke`` (or ``all``) and ``--pin-radius MM``."""
    names = [a.strip() for a in asked.split(",") if a.strip()]
    known = tuple(a.value for a in Answer)
    bad = [a for a in names if a not in (*known, "all")]
    if bad or not names:
        raise SceneError(Text(
            "errmsg2.textbook_report.answers_flag",
            {"known": ', '.join(known), "value": repr(asked)}))
    chosen = frozenset(Answer) if "all" in names else frozenset(Answer(a) for a in names)
    if pin_radius_mm is not None and not (0.0 < pin_radius_mm < 1e6):
        raise SceneError(Text(
            "errmsg2.textbook_report.pin_radius_flag",
            {"value": f'{pin_radius_mm:g}'}))
    radius = pin_radius_mm / 1000.0 if pin_radius_mm is not None else (
        base.pin_radius if base else None)
    if Answer.RUBBING in chosen and radius is None and not (base and base.pins):
        raise SceneError(Text("errmsg2.textbook_report.pin_radius_needed"))
    return TextbookSpec(chosen | (base.asked if base else frozenset()), radius,
                        dict(base.pins) if base else {}, base.outputs if base else ())


def _w(key: str, lang: str, **kw: Any) -> str:
    return message(f"textbook.{key}", lang, **kw)


def _n(x: float, digits: int, lang: str) -> str:
    return format_number(float(x), digits, lang)


def phi_deg(phi: float) -> float:
    """A crank angle in degrees within [0°, 360°) (a root found at 360° − 1e-14 is 0°)."""
    d = math.degrees(phi) % 360.0
    return 0.0 if d > 360.0 - 1e-9 else d


def _deg(x: float, lang: str, digits: int = 2) -> str:
    return format_number(math.degrees(float(x)), digits, lang)


def _slider(s: Sliding) -> str:
    return s.pair.a if s.guide_link == s.pair.b else s.pair.b


def _pin_key(r: Rubbing, all_: list[Rubbing]) -> str:
    same = [x for x in all_ if x.pair.point == r.pair.point]
    return r.pair.point if len(same) == 1 else f"{r.pair.point}({r.pair.a},{r.pair.b})"


# -- text -----------------------------------------------------------------------------------
def position_lines(sol: Solution, k: int, lang: str) -> list[str]:
    """The answers at position ``k`` (empty when none were asked)."""
    t: TextbookAnswers | None = sol.extras.get(KEY)
    if t is None:
        return []
    ms, ms2, mm_ = unit("m/s", lang), unit("m/s²", lang), unit("mm", lang)
    out = ["", f"### {_w('heading', lang)}"]
    for s in t.sliding:
        g = s.pair.guide or ""
        out.append("  " + _w("sliding", lang, slider=_slider(s), guide=g, link=s.guide_link,
                                point=s.pair.point))
        line = (f"    v_rel = {_n(s.v_slide[k], 4, lang)} {ms} ({parallel(g).text(lang)})")
        if s.a_slide is not None:
            line += f";  a_rel = {_n(s.a_slide[k], 4, lang)} {ms2} ({parallel(g).text(lang)})"
        if s.a_cor is not None and s.guide_link != GROUND:
            line += (f";  a^k = 2·ω{s.guide_link}·v_rel = "
                     f"{_n(float(np.hypot(*s.a_cor[k])), 4, lang)} {ms2} ("
                     + _w("dir.coriolis", lang, guide=g, link=s.guide_link) + ")")
        out.append(line)
    for pp in t.point_pairs:
        name = f"{pp.p}{pp.q}"
        line = (f"  v_{name} = {_n(float(np.hypot(*pp.v[k])), 4, lang)} {ms} "
                f"({perp(pp.q + pp.p).text(lang)})")
        if pp.a is not None and pp.a_n is not None and pp.a_t is not None:
            line += (f";  a_{name} = {vector_text(pp.a[k], lang, 4, 'm/s²')}"
                     f";  a^n_{name} = ω{pp.link}²·l_{pp.q}{pp.p} = "
                     f"{_n(float(np.hypot(*pp.a_n[k])), 4, lang)} {ms2} "
                     f"({from_to(pp.p, pp.q).text(lang)})"
                     f";  a^t_{name} = ε{pp.link}·l_{pp.q}{pp.p} = "
                     f"{_n(float(np.hypot(*pp.a_t[k])), 4, lang)} {ms2} "
                     f"({perp(pp.q + pp.p).text(lang)})")
        out.append(line)
    if t.turning:
        rad_s, rad_s2 = unit("rad/s", lang), unit("rad/s²", lang)
        parts = []
        for tu in t.turning:
            a, b = tu.pair.a, tu.pair.b
            text = f"{tu.pair.point}: ω{a}{b} = {_n(tu.omega_rel[k], 4, lang)} {rad_s}"
            if tu.epsilon_rel is not None:
                text += f", ε{a}{b} = {_n(tu.epsilon_rel[k], 4, lang)} {rad_s2}"
            parts.append(text)
        out.append("  " + _w("turning", lang) + ": " + ";  ".join(parts))
    for r in t.rubbing:
        out.append("  " + _w("rubbing", lang, point=r.pair.point, a=r.pair.a, b=r.pair.b,
                             r=f"{_n(r.radius * 1000, 1, lang)} {mm_}",
                             v=f"{_n(r.v_rub[k], 4, lang)} {ms}"))
    for tr in t.transmission:
        line = "  " + _w("gamma", lang, group=tr.group.name, kind=tr.group.kind.value,
                         gamma=_deg(tr.gamma[k], lang))
        if tr.mu is not None:
            line += "; " + _w("mu", lang, mu=_deg(tr.mu[k], lang))
        out.append(line)
    for lv in t.least_velocity:
        if not np.isfinite(lv.G[k]).all():
            out.append("  " + _w("translating", lang, link=lv.link,
                                 v=f"{_n(lv.v_min[k], 4, lang)} {ms}"))
            continue
        gx, gy = lv.G[k] * 1000
        ix, iy = lv.centre[k] * 1000
        line = "  " + _w("least_velocity", lang, link=lv.link,
                         G=f"({_n(gx, 2, lang)}; {_n(gy, 2, lang)}) {mm_}",
                         v=f"{_n(lv.v_min[k], 4, lang)} {ms}",
                         I=f"({_n(ix, 2, lang)}; {_n(iy, 2, lang)}) {mm_}")
        if lv.along is not None:
            line += f"; {lv.points[0]}G = {_n(lv.along[k] * 1000, 2, lang)} {mm_}"
        out.append(line)
    return out


def cycle_lines(sol: Solution, lang: str) -> list[str]:
    """The answers over the crank's turn: strokes, extremes, K, least transmission angles."""
    t: TextbookAnswers | None = sol.extras.get(KEY)
    if t is None or not (t.strokes or t.least_gamma):
        return []
    mm_ = unit("mm", lang)
    out = ["", f"## {_w('cycle', lang)}"]
    for s in t.strokes:
        if not s.extremes:
            out.append("  " + _w("no_extremes", lang, subject=s.subject))
            continue
        if s.rocker:
            head = _w("swing", lang, subject=s.subject, size=_deg(s.size, lang))
        else:
            head = _w("stroke", lang, subject=s.subject,
                      size=f"{_n(s.size * 1000, 3, lang)} {mm_}")
        ex = "; ".join(_w("extreme", lang, which=_w(e.which, lang), phi=_n(phi_deg(e.phi), 2, lang))
                       for e in s.extremes)
        out.append(f"  {head}; {ex}")
        if s.K is None:
            out.append("    " + _w("many_extremes", lang, subject=s.subject,
                                   n=len(s.extremes)))
            continue
        out.append("    " + _w("strokes", lang, work=_w("up" if s.working_up else "down", lang),
                               tw=_deg(s.theta_work or 0.0, lang),
                               tr=_deg(s.theta_return or 0.0, lang), K=_n(s.K, 4, lang)))
    for name, least in t.least_gamma.items():
        if least is not None and math.isnan(least[0]):
            out.append("  " + _w("gamma_constant", lang, group=name, gamma=_deg(least[1], lang)))
        elif least is not None:
            out.append("  " + _w("gamma_min", lang, group=name, gamma=_deg(least[1], lang),
                                 phi=_n(phi_deg(least[0]), 2, lang)))
    return out


# -- JSON -----------------------------------------------------------------------------------
def _v(a: np.ndarray) -> list[float]:
    return [float(a[0]), float(a[1])]


def _f(x: Any) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def position_json(sol: Solution, k: int) -> dict[str, Any] | None:
    """The ``"textbook"`` entry of position ``k`` of ``mechplan solve --json``."""
    t: TextbookAnswers | None = sol.extras.get(KEY)
    if t is None:
        return None
    doc: dict[str, Any] = {}
    if Answer.RELATIVE in t.asked:
        sl: dict[str, Any] = {}
        for s in t.sliding:
            e: dict[str, Any] = {"pair": s.pair.name, "point": s.pair.point, "slider": _slider(s),
                                 "guide": s.pair.guide, "guide_link": s.guide_link,
                                 "direction": _v(s.direction[k]), "v_rel": _v(s.v_rel[k]),
                                 "v_slide": float(s.v_slide[k]),
                                 "omega_guide": float(s.omega_guide[k])}
            if s.a_rel is not None and s.a_cor is not None and s.a_slide is not None:
                e |= {"a_rel": _v(s.a_rel[k]), "a_slide": float(s.a_slide[k]),
                      "a_cor": _v(s.a_cor[k]), "a_cor_magnitude": float(np.hypot(*s.a_cor[k]))}
            sl[f"{s.pair.point}/{s.pair.guide}"] = e
        rel: dict[str, Any] = {}
        for pp in t.point_pairs:
            e = {"link": pp.link, "of": pp.p, "relative_to": pp.q, "length": pp.length,
                 "v": _v(pp.v[k]), "v_magnitude": float(np.hypot(*pp.v[k]))}
            if pp.a is not None and pp.a_n is not None and pp.a_t is not None:
                e |= {"a": _v(pp.a[k]), "a_magnitude": float(np.hypot(*pp.a[k])),
                      "a_n": _v(pp.a_n[k]), "a_n_magnitude": float(np.hypot(*pp.a_n[k])),
                      "a_t": _v(pp.a_t[k]), "a_t_magnitude": float(np.hypot(*pp.a_t[k]))}
            rel[f"{pp.p}{pp.q}"] = e
        turn: dict[str, Any] = {}
        for tu in t.turning:
            same = [x for x in t.turning if x.pair.point == tu.pair.point]
            key = tu.pair.point if len(same) == 1 else f"{tu.pair.point}({tu.pair.a},{tu.pair.b})"
            turn[key] = {"links": [tu.pair.a, tu.pair.b], "omega_rel": float(tu.omega_rel[k]),
                         **({"epsilon_rel": float(tu.epsilon_rel[k])}
                            if tu.epsilon_rel is not None else {})}
        doc["sliding"], doc["relative"], doc["turning"] = sl, rel, turn
    if Answer.RUBBING in t.asked:
        doc["rubbing"] = {_pin_key(r, t.rubbing): {
            "links": [r.pair.a, r.pair.b], "radius": r.radius,
            "omega_rel": float(r.omega_rel[k]), "v_rub": float(r.v_rub[k])} for r in t.rubbing}
    if Answer.TRANSMISSION in t.asked:
        doc["transmission"] = {tr.group.name: {
            "kind": tr.group.kind.value, "gamma_deg": _f(math.degrees(tr.gamma[k])),
            **({"mu_deg": _f(math.degrees(tr.mu[k]))} if tr.mu is not None else {})}
            for tr in t.transmission}
    if Answer.LEAST_VELOCITY in t.asked:
        lvs: dict[str, Any] = {}
        for lv in t.least_velocity:
            finite = bool(np.isfinite(lv.G[k]).all())
            lvs[lv.link] = {"G": _v(lv.G[k]) if finite else None,
                            "centre": _v(lv.centre[k]) if finite else None,
                            "v_min": float(lv.v_min[k]),
                            **({"from": lv.points[0], "along": _f(lv.along[k])}
                               if lv.along is not None else {})}
        doc["least_velocity"] = lvs
    return doc


def cycle_json(sol: Solution) -> dict[str, Any] | None:
    """The top-level ``"textbook"`` entry: strokes, extremes, K, least transmission angles."""
    t: TextbookAnswers | None = sol.extras.get(KEY)
    if t is None:
        return None
    doc: dict[str, Any] = {"asked": sorted(a.value for a in t.asked)}
    if Answer.STROKE in t.asked:
        st: dict[str, Any] = {}
        for s in t.strokes:
            e: dict[str, Any] = {"kind": "swing" if s.rocker else "stroke",
                                 "extremes": [{"which": x.which, "phi_deg": phi_deg(x.phi),
                                               "value": x.value} for x in s.extremes]}
            if s.extremes:
                e["swing_deg" if s.rocker else "H"] = (math.degrees(s.size) if s.rocker
                                                       else s.size)
            if s.K is not None:
                e |= {"phi_min_deg": phi_deg(s.phi_min or 0.0),
                      "phi_max_deg": phi_deg(s.phi_max or 0.0),
                      "theta_up_deg": math.degrees(s.theta_up or 0.0),
                      "theta_down_deg": math.degrees(s.theta_down or 0.0),
                      "working": "min_to_max" if s.working_up else "max_to_min",
                      "theta_work_deg": math.degrees(s.theta_work or 0.0),
                      "theta_return_deg": math.degrees(s.theta_return or 0.0), "K": s.K}
            st[s.subject] = e
        doc["strokes"] = st
    if Answer.TRANSMISSION in t.asked:
        doc["transmission_min"] = {
            name: ({"gamma_min_deg": math.degrees(v[1]),
                    "phi_deg": None if math.isnan(v[0]) else phi_deg(v[0])}
                   if v is not None else None) for name, v in t.least_gamma.items()}
    return doc
