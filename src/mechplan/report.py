"""Plain-text report of a solution in the user's language (what `mechplan solve` prints)."""

from __future__ import annotations

import math

import numpy as np

from .construct.protocol import (MM, PLAN_TITLE, SENSE, localize_direction, pole_label, protocol,
                                 vector_text)
from .construct.step import Plan
from .solve import Solution, segment_table
from .units import format_number

WORDS = {
    "en": {"dof": "Degrees of freedom", "structure": "Structure formula", "cls": "class", "position": "Position",
               "equation": "Vector equation", "term": "term", "direction": "direction", "magnitude": "magnitude",
               "segments": "Measured segments", "results": "Results", "point": "point", "link": "link",
               "groups": "Assur groups", "crank": "crank at", "fromx": "from +x"},
    "ru": {"dof": "Степень подвижности", "structure": "Формула строения", "cls": "класс", "position": "Положение",
               "equation": "Векторное уравнение", "term": "вектор", "direction": "направление", "magnitude": "величина",
               "segments": "Измеренные отрезки", "results": "Результаты", "point": "точка", "link": "звено",
               "groups": "Группы Ассура", "crank": "кривошип под углом", "fromx": "от оси +x"},
    "vi": {"dof": "Bậc tự do", "structure": "Công thức cấu trúc", "cls": "loại", "position": "Vị trí",
               "equation": "Phương trình véc tơ", "term": "véc tơ", "direction": "phương chiều", "magnitude": "giá trị",
               "segments": "Các đoạn đo được", "results": "Kết quả", "point": "điểm", "link": "khâu",
               "groups": "Nhóm Axua", "crank": "tay quay ở góc", "fromx": "so với trục +x"},
    "zh": {"dof": "自由度", "structure": "机构的组成式", "cls": "级", "position": "位置", "equation": "矢量方程",
               "term": "矢量", "direction": "方向", "magnitude": "大小", "segments": "测量线段", "results": "结果",
               "point": "点", "link": "构件", "groups": "杆组", "crank": "曲柄位于", "fromx": "（自 +x 轴）"},
}
PLANS = {"position": Plan.POSITION, "velocity": Plan.VELOCITY, "acceleration": Plan.ACCELERATION,
         "force": Plan.FORCE}
UNITS = {Plan.POSITION: "m/mm", Plan.VELOCITY: "(m/s)/mm", Plan.ACCELERATION: "(m/s²)/mm",
         Plan.FORCE: "N/mm"}


def text_report(sol: Solution, lang: str | None = None) -> str:
    """The full report: structure, then per position the plans' protocols, tables and results."""
    lang = lang or sol.scene.language
    w = WORDS[lang]
    st = sol.structure
    out = [sol.scene.title, "=" * len(sol.scene.title),
           f"{w['dof']}: W = 3·{st.moving_links} − 2·{st.lower_pairs} = {st.dof}",
           f"{w['structure']}: {st.formula}  ({w['cls']} {st.mechanism_class})"]
    for g in st.groups:
        out.append(f"  {g.name}: {g.kind}")
    plans = tuple(PLANS[p] for p in sol.plans if p in PLANS)
    theta = sol.construction.drive.absolute(sol.phi)
    for k in range(sol.positions):
        phi_txt = format_number(math.degrees(sol.phi[k]), 2, lang)
        th_txt = format_number(math.degrees(math.remainder(theta[k], 2 * math.pi)), 2, lang)
        out += ["", f"## {w['position']} {k}: φ = {phi_txt}° ({w['crank']} {th_txt}° {w['fromx']})"]
        steps = protocol(sol.construction, sol.ev, k, lang, sol.scales, plans)
        for plan in plans:
            mu = sol.scales.get(plan, 1.0)
            unit = UNITS[plan]
            out += ["", f"### {PLAN_TITLE[plan][lang]} (μ = {format_number(mu, 6, lang).rstrip('0').rstrip(',.')} {unit})"]
            for (p, group), (eq, rows) in sol.construction.equations.items():
                if p is plan:
                    out.append(f"{w['equation']} {group}: {eq}")
                    for term, direction, magnitude in rows:
                        out.append(f"    {term:<16} {localize_direction(direction, lang):<12} "
                                   f"{magnitude}")
            n = 0
            for p, label, text in steps:
                if p is plan:
                    n += 1
                    out.append(f"  {n:>2}. {text}")
            measured = segment_table(sol, plan, k)
            if measured:
                out.append(f"  {w['segments']}:")
                for name, mm, _mu, quantity, value in measured:
                    out.append(f"    {pole_label(name, lang):<14} {format_number(mm, 1, lang):>8} {MM[lang]}"
                               f"   {quantity:<14} {format_number(value, 4, lang)}")
        out += ["", f"### {w['results']}"]
        out += _results(sol, k, lang)
        if "forces" in sol.extras:
            out += [""] + _forces(sol, k, lang)
    return "\n".join(out)


def _results(sol: Solution, k: int, lang: str) -> list[str]:
    c, ev = sol.construction, sol.ev
    lines = []
    pts = sol.scene.points_of_interest or tuple(
        p for lk in sol.scene.mechanism.links.values() if lk.id != "0" for p in lk.points)
    for p in dict.fromkeys(pts):
        parts = [f"{p:<4}"]
        if f"pos.{p}" in ev.values:
            x, y = ev[f"pos.{p}"][k] * 1000
            parts.append(f"r = ({format_number(x, 2, lang)}; {format_number(y, 2, lang)}) mm")
        for sym, unit in (("v", "m/s"), ("a", "m/s²")):
            sid = c.results.get(f"{sym}_{p}")
            if sid in ev.values:
                vec = ev[sid][k]
                mag = float(np.hypot(*vec))
                text = f"{sym} = {format_number(mag, 4, lang)} {unit}"
                if float(f"{mag:.4f}") != 0:
                    text += f" ∠ {format_number(math.degrees(math.atan2(vec[1], vec[0])), 1, lang)}°"
                parts.append(text)
        lines.append("  " + "   ".join(parts))
    for lid in sol.scene.mechanism.moving:
        parts = []
        for key, sym, unit in (("omega", "ω", "rad/s"), ("epsilon", "ε", "rad/s²")):
            sid = c.results.get(f"{key}_{lid}")
            if sid in ev.values:
                parts.append(f"{sym}{lid} = {format_number(float(ev[sid][k]), 4, lang)} {unit}")
        if parts:
            lines.append("  " + "   ".join(parts))
    return lines


FORCE_WORDS = {
    "en": ("Reactions R_ij (force of link i on link j)", "Guide reactions (⊥ guide), line of action from",
           "Balancing moment on link", "driving", "resisting", "Zhukovsky's lever", "difference",
           "Reduced moment of forces", "Reduced moment of inertia", "at", "pure couple"),
    "ru": ("Реакции R_ij (сила звена i на звено j)", "Реакции направляющих (⊥ направляющей), линия действия от",
           "Уравновешивающий момент на звене", "движущий", "момент сопротивления", "Рычаг Жуковского",
           "расхождение", "Приведённый момент сил", "Приведённый момент инерции", "в точке",
           "чистая пара"),
    "vi": ("Áp lực khớp động R_ij (lực của khâu i lên khâu j)", "Phản lực dẫn hướng (⊥ đường dẫn), đường tác dụng cách",
           "Mômen cân bằng trên khâu", "phát động", "cản", "Đòn Giucôpxki", "sai lệch",
           "Mômen thay thế của lực", "Mômen quán tính thay thế", "tại", "ngẫu lực thuần"),
    "zh": ("运动副反力 R_ij（构件 i 对构件 j 的力）", "导路反力（⊥ 导路），作用线距",
           "构件上的平衡力矩", "驱动", "阻抗", "儒可夫斯基杠杆", "相差", "等效力矩", "等效转动惯量",
           "作用于", "纯力偶"),
}


def _forces(sol: Solution, k: int, lang: str) -> list[str]:
    """Reactions, guide reactions, balancing moment (two ways), M_red and J_red at position k."""
    fa = sol.extras["forces"]
    w = FORCE_WORDS[lang]
    out = [f"### {w[0]}"]
    for r in fa.reactions.values():
        out.append(f"  R_{r.key} = {vector_text(r.force[k], lang, 2)}   ({w[9]} {r.point})")
    if fa.guide_reactions:
        out.append(f"### {w[1]} {', '.join(r.point for r in fa.guide_reactions.values())}")
    for r in fa.guide_reactions.values():
        d = float(r.offset[k]) if r.offset is not None else math.nan
        where = f"d = {format_number(d * 1000, 2, lang)} mm ({r.guide})" if math.isfinite(d) else w[10]
        out.append(f"  R_{r.key} = {vector_text(r.force[k], lang, 2)};  {where}")
    mb, mz = float(fa.balancing_moment[k]), float(fa.zhukovsky_moment[k])
    role = w[3] if fa.driving(k) else w[4]
    link = sol.scene.mechanism.drive.link
    sense = SENSE[lang][0 if mb > 0 else 1]
    out.append(f"### {w[2]} {link}: M_b = {format_number(mb, 3, lang)} N·m ({sense}; {role})")
    out.append(f"  {w[5]}: M_b = {format_number(mz, 3, lang)} N·m; {w[6]} "
               f"{float(fa.difference_percent[k]):.2e} %")
    out.append(f"  {w[7]}: M_red = {format_number(float(fa.reduced_moment[k]), 3, lang)} N·m")
    out.append(f"  {w[8]}: J_red = {format_number(float(fa.reduced_inertia[k]), 6, lang)} kg·m²")
    return out
