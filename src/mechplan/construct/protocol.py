"""The construction protocol: one sentence per step in en/ru/vi/zh, with measured lengths."""

from __future__ import annotations

import math
import re

import numpy as np

from ..units import format_number
from .graph import Construction, Evaluation
from .segments import Segment
from .step import Op, Plan, Step

SENSE = {"en": ("counter-clockwise", "clockwise"), "ru": ("против часовой стрелки", "по часовой стрелке"),
         "vi": ("ngược chiều kim đồng hồ", "cùng chiều kim đồng hồ"), "zh": ("逆时针", "顺时针")}

PLAN_TITLE = {
    Plan.POSITION: {"en": "Position plan", "ru": "План положений", "vi": "Họa đồ vị trí", "zh": "机构位置图"},
    Plan.VELOCITY: {"en": "Velocity plan", "ru": "План скоростей", "vi": "Họa đồ vận tốc", "zh": "速度多边形"},
    Plan.ACCELERATION: {"en": "Acceleration plan", "ru": "План ускорений", "vi": "Họa đồ gia tốc",
                        "zh": "加速度多边形"},
    Plan.FORCE: {"en": "Force plan", "ru": "План сил", "vi": "Họa đồ lực", "zh": "力多边形"},
}

# {0}, {1}, {2}: the step's subject; {label}: its label; {m}: measured text; {v}: value text
TEXT: dict[Op, dict[str, str]] = {
    Op.CRANK_ANGLE: {"en": "Crank angle {label} = {v}", "ru": "Угол кривошипа {label} = {v}",
                     "vi": "Góc tay quay {label} = {v}", "zh": "曲柄转角 {label} = {v}"},
    Op.FIXED_POINT: {"en": "Mark the frame point {label}", "ru": "Отмечаем точку стойки {label}",
                     "vi": "Đánh dấu điểm giá {label}", "zh": "标出机架点 {label}"},
    Op.POLAR_POINT: {"en": "Draw the crank {0}{1} at its angle: {m}",
                     "ru": "Строим кривошип {0}{1} под заданным углом: {m}",
                     "vi": "Dựng tay quay {0}{1} theo góc đã cho: {m}",
                     "zh": "按给定转角作曲柄 {0}{1}：{m}"},
    Op.CIRCLE_CIRCLE: {"en": "Arcs about {0} and {1} with radii {0}{2} and {1}{2} meet at {2}",
                       "ru": "Засечки из {0} и {1} радиусами {0}{2} и {1}{2} пересекаются в точке {2}",
                       "vi": "Các cung tâm {0} và {1}, bán kính {0}{2} và {1}{2} cắt nhau tại {2}",
                       "zh": "以 {0}、{1} 为圆心，{0}{2}、{1}{2} 为半径作圆弧，交于 {2}"},
    Op.CIRCLE_LINE: {"en": "An arc about {0} with radius {0}{1} cuts the guide at {1}",
                     "ru": "Засечка из {0} радиусом {0}{1} пересекает направляющую в точке {1}",
                     "vi": "Cung tâm {0}, bán kính {0}{1} cắt đường dẫn tại {1}",
                     "zh": "以 {0} 为圆心、{0}{1} 为半径作圆弧，与导路交于 {1}"},
    Op.LINE_LINE: {"en": "Lines {0} and {1} meet at {label}{m}",
                   "ru": "Прямые {0} и {1} пересекаются в точке {label}{m}",
                   "vi": "Các đường {0} và {1} cắt nhau tại {label}{m}",
                   "zh": "直线 {0} 与 {1} 交于 {label}{m}"},
    Op.LOCUS_LINE: {"en": "Draw the guide line {label}", "ru": "Проводим направляющую {label}",
                    "vi": "Kẻ đường dẫn hướng {label}", "zh": "作导路 {label}"},
    Op.CARRIER_ANGLE: {"en": "The guide {2} passes through {1}: draw link {label} from {0} through {1}",
                       "ru": "Направляющая {2} проходит через {1}: проводим кулису из {0} через {1}",
                       "vi": "Đường dẫn {2} đi qua {1}: kẻ culít từ {0} qua {1}",
                       "zh": "导路 {2} 过 {1}：自 {0} 过 {1} 作导杆"},
    Op.PLACE: {"en": "Mark {label} on its link", "ru": "Отмечаем точку {label} на звене",
               "vi": "Đánh dấu điểm {label} trên khâu", "zh": "在构件上标出 {label}"},
    Op.SIMILAR_POSITION: {"en": "Build {2} on {0}{1} (the link's shape)",
                          "ru": "Строим точку {2} на стороне {0}{1} (по форме звена)",
                          "vi": "Dựng điểm {2} trên cạnh {0}{1} (theo hình dạng khâu)",
                          "zh": "在 {0}{1} 上按构件形状作出 {2}"},
    Op.SIMILAR_IMAGE: {"en": "By similarity, {label} on {a}{b}: triangle {a}{b}{label} ∼ {0}{1}{2}{m}",
                       "ru": "По теореме подобия точка {label}: △{a}{b}{label} ∼ △{0}{1}{2}{m}",
                       "vi": "Theo định lý đồng dạng, điểm {label}: △{a}{b}{label} ∼ △{0}{1}{2}{m}",
                       "zh": "由影像原理作 {label}：△{a}{b}{label} ∽ △{0}{1}{2}{m}"},
    Op.RIGID_VELOCITY: {"en": "Image {label} of {1} from {0}{m}", "ru": "Изображение {label} точки {1} от {0}{m}",
                        "vi": "Ảnh {label} của {1} từ {0}{m}", "zh": "由 {0} 作 {1} 的影像 {label}{m}"},
    Op.RIGID_ACCELERATION: {"en": "Image {label} of {1} from {0}{m}", "ru": "Изображение {label} точки {1} от {0}{m}",
                            "vi": "Ảnh {label} của {1} từ {0}{m}", "zh": "由 {0} 作 {1} 的影像 {label}{m}"},
    Op.POLE: {"en": "Choose the pole {label}", "ru": "Выбираем полюс {label}", "vi": "Chọn gốc {label}",
              "zh": "任取极点 {label}"},
    Op.DRIVE_VELOCITY: {"en": "From {pole} draw {pole}{label} ⊥ {0}{1} in the sense of ω: {m}",
                        "ru": "Из полюса {pole} откладываем {pole}{label} ⊥ {0}{1} по направлению ω: {m}",
                        "vi": "Từ gốc {pole} kẻ {pole}{label} ⊥ {0}{1} theo chiều ω: {m}",
                        "zh": "自 {pole} 作 {pole}{label} ⊥ {0}{1}，指向 ω 转向：{m}"},
    Op.DRIVE_ACCELERATION: {"en": "From {pole} draw {pole}{label} ∥ {1}{0}, from {1} towards {0}: {m}",
                            "ru": "Из полюса {pole} откладываем {pole}{label} ∥ {1}{0} от {1} к {0}: {m}",
                            "vi": "Từ gốc {pole} kẻ {pole}{label} ∥ {1}{0}, hướng từ {1} về {0}: {m}",
                            "zh": "自 {pole} 作 {pole}{label} ∥ {1}{0}，由 {1} 指向 {0}：{m}"},
    Op.LINE_PERP: {"en": "Through {0} draw a line ⊥ {1}", "ru": "Через точку {0} проводим прямую ⊥ {1}",
                   "vi": "Qua {0} kẻ đường thẳng ⊥ {1}", "zh": "过 {0} 作 {1} 的垂线"},
    Op.LINE_PARALLEL: {"en": "Through {0} draw a line ∥ {1}", "ru": "Через точку {0} проводим прямую ∥ {1}",
                       "vi": "Qua {0} kẻ đường thẳng ∥ {1}", "zh": "过 {0} 作 {1} 的平行线"},
    Op.OMEGA: {"en": "{label} = v / l_{0}{1} = {v}", "ru": "{label} = v / l_{0}{1} = {v}",
               "vi": "{label} = v / l_{0}{1} = {v}", "zh": "{label} = v / l_{0}{1} = {v}"},
    Op.EPSILON: {"en": "{label} = a^t / l_{0}{1} = {v}", "ru": "{label} = a^t / l_{0}{1} = {v}",
                 "vi": "{label} = a^t / l_{0}{1} = {v}", "zh": "{label} = a^t / l_{0}{1} = {v}"},
    Op.NORMAL: {"en": "From {0} lay off {label} ∥ {1}{2}, from {1} towards {2}: {m}",
                "ru": "Из точки {0} откладываем {label} ∥ {1}{2} от {1} к {2}: {m}",
                "vi": "Từ {0} đặt {label} ∥ {1}{2}, hướng từ {1} về {2}: {m}",
                "zh": "自 {0} 作 {label} ∥ {1}{2}，由 {1} 指向 {2}：{m}"},
    Op.CORIOLIS: {"en": "From {0} lay off the Coriolis component {label} = 2{1}·v_rel, v_rel turned 90° in the sense of {1}: {m}",
                  "ru": "Из точки {0} откладываем кориолисово ускорение {label} = 2{1}·v_отн (v_отн, повёрнутая на 90° по {1}): {m}",
                  "vi": "Từ {0} đặt gia tốc Côriôlít {label} = 2{1}·v_tđ (v_tđ quay 90° theo chiều {1}): {m}",
                  "zh": "自 {0} 作哥氏加速度 {label} = 2{1}·v_相对（v_相对 沿 {1} 转向转 90°）：{m}"},
    Op.CONSTANT: {"en": "{label} = {v}", "ru": "{label} = {v}", "vi": "{label} = {v}", "zh": "{label} = {v}"},
    Op.COPY: {"en": "{label} = {0} = {v} (the slider turns with its guide)",
              "ru": "{label} = {0} = {v} (ползун поворачивается вместе с направляющей)",
              "vi": "{label} = {0} = {v} (con trượt quay cùng đường dẫn)",
              "zh": "{label} = {0} = {v}（滑块与导路一起转动）"},
    Op.ANGLE_OF: {"en": "{label} = {v}", "ru": "{label} = {v}", "vi": "{label} = {v}", "zh": "{label} = {v}"},
    Op.ANGLE_PLUS: {"en": "{label} = {v}", "ru": "{label} = {v}", "vi": "{label} = {v}", "zh": "{label} = {v}"},
}

_FORCE_TEXT = {
    "FORCE_INERTIA": ("Inertia force {label} = −m·a_S = {v}", "Сила инерции {label} = −m·a_S = {v}",
                      "Lực quán tính {label} = −m·a_S = {v}", "惯性力 {label} = −m·a_S = {v}"),
    "MOMENT_INERTIA": ("Inertia couple {label} = −J_S·ε = {v}", "Момент сил инерции {label} = −J_S·ε = {v}",
                       "Mômen lực quán tính {label} = −J_S·ε = {v}", "惯性力偶矩 {label} = −J_S·ε = {v}"),
    "INERTIA_OFFSET": ("Offset of the single inertia force {label} = |M_q|/|Q| = {v}",
                       "Плечо переноса силы инерции {label} = |M_q|/|Q| = {v}",
                       "Độ lệch của lực quán tính {label} = |M_q|/|Q| = {v}",
                       "惯性力的偏移 {label} = |M_q|/|Q| = {v}"),
    "FORCE_LOAD": ("Load {label} = {v}", "Нагрузка {label} = {v}", "Tải trọng {label} = {v}",
                   "载荷 {label} = {v}"),
    "MOMENT_SUM": ("{label}: moments about {0} of the known loads on link {1} = {v}",
                   "{label}: сумма моментов известных сил звена {1} относительно точки {0} = {v}",
                   "{label}: tổng mômen các lực đã biết của khâu {1} đối với điểm {0} = {v}",
                   "{label}：构件 {1} 上已知力对 {0} 点之矩 = {v}"),
    "MOMENT_ARM_TANGENTIAL": ("From the moment equation about {1}: {label} = {v}",
                              "Из уравнения моментов относительно точки {1}: {label} = {v}",
                              "Từ phương trình mômen đối với điểm {1}: {label} = {v}",
                              "由对 {1} 点的力矩方程：{label} = {v}"),
    "MOMENT_CLOSE": ("{label} = {v}", "{label} = {v}", "{label} = {v}", "{label} = {v}"),
    "FORCE_SUM": ("Lay off {m}", "Откладываем {m}", "Đặt {m}", "依次作 {m}"),
    "FORCE_LINE": ("Through {0} draw a line {1}", "Через точку {0} проводим прямую {1}",
                   "Qua {0} kẻ đường thẳng {1}", "过 {0} 作直线 {1}"),
    "FORCE_CLOSE": ("Lines {0} and {1} meet at {label}{m}", "Прямые {0} и {1} пересекаются в точке {label}{m}",
                    "Các đường {0} và {1} cắt nhau tại {label}{m}", "直线 {0} 与 {1} 交于 {label}{m}"),
    "DIFFERENCE": ("{label} = {v}", "{label} = {v}", "{label} = {v}", "{label} = {v}"),
    "FORCE_REVERSE": ("{label} = −{0}", "{label} = −{0}", "{label} = −{0}", "{label} = −{0}"),
    "GUIDE_OFFSET": ("The line of action of the guide reaction crosses {2} at {label} = {v} from {0}",
                     "Линия действия реакции направляющей пересекает {2} на расстоянии {label} = {v} от {0}",
                     "Đường tác dụng của phản lực dẫn hướng cắt {2} cách {0} một đoạn {label} = {v}",
                     "导路反力作用线与 {2} 交于距 {0} {label} = {v} 处"),
    "BALANCING_MOMENT": ("Balancing moment {label} = {v}", "Уравновешивающий момент {label} = {v}",
                         "Mômen cân bằng {label} = {v}", "平衡力矩 {label} = {v}"),
    "ZHUKOVSKY": ("Zhukovsky's lever (velocity plan turned by 90°): {label} = {v}",
                  "Рычаг Жуковского (план скоростей, повёрнутый на 90°): {label} = {v}",
                  "Đòn Giucôpxki (họa đồ vận tốc quay 90°): {label} = {v}",
                  "儒可夫斯基杠杆（速度图转 90°）：{label} = {v}"),
}
for _name, _texts in _FORCE_TEXT.items():
    if hasattr(Op, _name):
        TEXT[getattr(Op, _name)] = dict(zip(("en", "ru", "vi", "zh"), _texts))
#: force-plan steps that say nothing a reader needs (drawn, not written)
SILENT = {getattr(Op, n) for n in ("LINE_OF_ACTION",) if hasattr(Op, n)}
_OFFSETS = {getattr(Op, n) for n in ("GUIDE_OFFSET", "INERTIA_OFFSET") if hasattr(Op, n)}

UNITS = {Plan.POSITION: "m", Plan.VELOCITY: "m/s", Plan.ACCELERATION: "m/s²", Plan.FORCE: "N"}
MM = {"en": "mm", "ru": "мм", "vi": "mm", "zh": "mm"}


_DIRECTION_WORDS = [
    (re.compile(r"opposite to (\S+)"), {"ru": r"противоположно \1", "vi": r"ngược chiều \1",
                                         "zh": r"与 \1 反向"}),
    (re.compile(r"against (\S+)"), {"ru": r"против \1", "vi": r"ngược chiều \1", "zh": r"与 \1 反向"}),
    (re.compile(r"towards (\S+)"), {"ru": r"к \1", "vi": r"hướng về \1", "zh": r"指向 \1"}),
]


def localize_direction(text: str, lang: str) -> str:
    """Translate the words of a vector-equation direction ("opposite to πs2′", "towards A")."""
    if lang == "en":
        return text
    for pattern, words in _DIRECTION_WORDS:
        text = pattern.sub(words[lang], text)
    return pole_label(text, lang)


def pole_label(label: str, lang: str) -> str:
    """Chinese texts call the acceleration pole p′."""
    return label.replace("π", "p′") if lang == "zh" else label


def vector_text(value: np.ndarray, lang: str, digits: int = 1, unit: str = "N") -> str:
    """"1459,8 N ∠ -120,0°": magnitude and direction (no angle for a zero vector)."""
    mag = float(np.hypot(*value))
    text = f"{format_number(mag, digits, lang)} {unit}"
    if float(f"{mag:.{digits}f}") != 0:
        text += f" ∠ {format_number(math.degrees(math.atan2(value[1], value[0])), digits, lang)}°"
    return text


def _scalar_text(step: Step, value: float, lang: str) -> str:
    if step.plan is Plan.FORCE:
        if step.op in _OFFSETS:
            return f"{format_number(value * 1000, 1, lang)} {MM[lang]}"
        return f"{format_number(value, 2, lang)} N·m"
    if step.op in (Op.CRANK_ANGLE, Op.ANGLE_OF, Op.ANGLE_PLUS, Op.CARRIER_ANGLE) or step.label.startswith("θ"):
        return f"{format_number(math.degrees(value), 2, lang)}°"
    unit = "rad/s" if step.plan is Plan.VELOCITY else "rad/s²"
    text = f"{format_number(value, 3, lang)} {unit}"
    if float(format_number(value, 3, "en")) != 0 and step.op in (Op.OMEGA, Op.EPSILON):
        text += f" ({SENSE[lang][0 if value > 0 else 1]})"
    return text


def measured(seg: Segment, ev: Evaluation, k: int, mu: float, lang: str) -> str:
    """"pb = 67.0 mm → v_B = 6.70 m/s" for one segment at position k."""
    a, b = ev[seg.start][k], ev[seg.end][k]
    length = float(np.hypot(*(b - a)))
    unit = UNITS[seg.plan]
    if seg.plan is Plan.POSITION:
        return f"{seg.name} = {format_number(length / mu, 1, lang)} {MM[lang]}"
    return (f"{pole_label(seg.name, lang)} = {format_number(length / mu, 1, lang)} {MM[lang]} → "
            f"{seg.quantity} = {format_number(length, 3, lang)} {unit}")


def sentence(c: Construction, step: Step, ev: Evaluation, k: int, lang: str,
             mu: dict[Plan, float]) -> str:
    """The protocol sentence of one step at position k."""
    subject = [pole_label(s, lang) for s in step.subject] + ["", "", ""]
    segs = [s for s in c.segments if s.end == step.id and s.plan is step.plan]
    m = "; ".join(measured(s, ev, k, mu.get(s.plan, 1.0), lang) for s in segs)
    value = ev[step.id]
    if value.ndim == 1:
        v = _scalar_text(step, float(value[k]), lang)
    elif step.plan is Plan.FORCE and value.ndim == 2:
        v = vector_text(value[k], lang)
    else:
        v = ""
    templates = TEXT.get(step.op)
    fields = {"label": pole_label(step.label, lang), "m": (": " + m) if m and step.op in (
        Op.LINE_LINE, Op.SIMILAR_IMAGE, Op.RIGID_VELOCITY, Op.RIGID_ACCELERATION,
        getattr(Op, "FORCE_CLOSE", Op.LINE_LINE)) else m, "v": v,
        "pole": "p" if step.plan is Plan.VELOCITY else pole_label("π", lang), "a": "", "b": ""}
    if step.op is Op.SIMILAR_IMAGE:
        a_lbl, b_lbl = (pole_label(c[i].label, lang) for i in step.inputs[:2])
        fields.update(a=a_lbl, b=b_lbl)
    if templates is None:
        return f"{fields['label']} = {v or m}"
    return templates[lang].format(*subject, **fields)


def protocol(c: Construction, ev: Evaluation, k: int, lang: str, mu: dict[Plan, float],
             plans: tuple[Plan, ...]) -> list[tuple[Plan, str, str]]:
    """(plan, label, sentence) for every evaluated step of the given plans at position k."""
    out = []
    for step in c:
        if step.plan in plans and step.id in ev.values and step.op is not Op.FIXED_POINT \
                and step.op not in SILENT:
            out.append((step.plan, pole_label(step.label, lang), sentence(c, step, ev, k, lang, mu)))
    return out
