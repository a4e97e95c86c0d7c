"""Every human-readable text of the checker in en / ru / vi / zh: one catalogue, message id →
{language: template}.

The checker builds its hints, findings, notes and sources as :class:`Text` objects: a ``str`` whose
value is the English sentence (so the report's fields, ``==`` and ``in`` read as before) and which
remembers its message id and arguments, so :func:`tr` can say it again in another language when
the report is written. Arguments may themselves be texts, lists (joined), or numbers (formatted
with the language's decimal mark: a comma in ru and vi, a point in en and zh).

Symbols and labels (pb, v_B, μv, π, b′, ω, v_rel) and SI units are the same in every language;
only millimetres of paper read "мм" in Russian, as in the construction protocol. Terms follow the
project glossary (ru "план скоростей", "теорема подобия"; vi "họa đồ vận tốc", "định lý đồng
dạng"; zh "速度多边形", "影像原理").
"""

from __future__ import annotations

import math
import re
import string
import unicodedata
from collections.abc import Iterable
from typing import Any, Self

from ..units import format_number

#: the languages of the reports
LANGUAGES: tuple[str, ...] = ("en", "ru", "vi", "zh")


def _m(en: str, ru: str, vi: str, zh: str) -> dict[str, str]:
    return {"en": en, "ru": ru, "vi": vi, "zh": zh}


# -- the catalogue ---------------------------------------------------------------------------------
# Placeholders are str.format fields; a number's format spec may start with "~": a number that is
# not finite is written "?".
MESSAGES: dict[str, dict[str, str]] = {
    # -- common pieces -----------------------------------------------------------------------------
    "paren": _m(" ({x})", " ({x})", " ({x})", "（{x}）"),
    "pair": _m("{a}; {b}", "{a}; {b}", "{a}; {b}", "{a}；{b}"),
    "colon": _m("{a}: {b}", "{a}: {b}", "{a}: {b}", "{a}：{b}"),
    "concat": _m("{a}{b}", "{a}{b}", "{a}{b}", "{a}{b}"),
    "xy": _m("({x:.1f}, {y:.1f})", "({x:.1f}; {y:.1f})", "({x:.1f}; {y:.1f})",
             "({x:.1f}, {y:.1f})"),
    "mm": _m("{v} mm", "{v} мм", "{v} mm", "{v} mm"),
    "read_from": _m("read from '{name} = {text}' ({where})",
                    "прочитан из '{name} = {text}' ({where})",
                    "đọc từ '{name} = {text}' ({where})",
                    "读自 '{name} = {text}'（{where}）"),
    "name_text_where": _m("'{name} = {text}' ({where})", "'{name} = {text}' ({where})",
                          "'{name} = {text}' ({where})", "'{name} = {text}'（{where}）"),

    # -- the text report -------------------------------------------------------------------------
    "report.title": _m("mechplan check: {submission}",
                       "mechplan check — проверка работы: {submission}",
                       "mechplan check — kiểm tra bài làm: {submission}",
                       "mechplan check — 作业检查：{submission}"),
    "report.scene": _m("scene: {scene}", "задание (сцена): {scene}", "đề bài (scene): {scene}",
                       "题目（场景文件）：{scene}"),
    "report.phi": _m("crank angle φ = {phi:.2f}° ({source})",
                     "угол кривошипа φ = {phi:.2f}° ({source})",
                     "góc tay quay φ = {phi:.2f}° ({source})",
                     "曲柄转角 φ = {phi:.2f}°（{source}）"),
    "report.units": _m("drawing units: {units}", "единицы чертежа: {units}",
                       "đơn vị bản vẽ: {units}", "图纸单位：{units}"),
    "report.label_distance": _m("labels taken within {d:.1f} mm of a line end",
                                "обозначения точек принимаются на расстоянии до {d:.1f} мм от "
                                "конца линии",
                                "nhãn điểm được nhận trong phạm vi {d:.1f} mm quanh đầu mút "
                                "đoạn thẳng",
                                "距线段端点 {d:.1f} mm 以内的文字视为点的标注"),
    "report.passed": _m("PASSED", "ЗАЧТЕНО", "ĐẠT", "通过"),
    "report.failed": _m("FAILED", "НЕ ЗАЧТЕНО", "KHÔNG ĐẠT", "未通过"),
    "report.result": _m(
        "result: {verdict} — {checked} checked, {ok} ok, {wrong} wrong ({new} new, {carried} "
        "carried, {swapped} by swapped labels, {accumulated} by small errors adding up), {slip} "
        "arithmetic slip(s), {missing} not on the submission",
        "итог: {verdict} — проверено: {checked}, верно: {ok}, неверно: {wrong} (новые ошибки: "
        "{new}, перенесённые: {carried}, из-за перепутанных обозначений: {swapped}, из-за "
        "накопления малых погрешностей: {accumulated}), арифметические ошибки: {slip}, нет в "
        "работе: {missing}",
        "kết quả: {verdict} — đã kiểm tra {checked}, đúng {ok}, sai {wrong} (lỗi mới {new}, lỗi "
        "kéo theo {carried}, do nhầm nhãn {swapped}, do sai số nhỏ cộng dồn {accumulated}), lỗi "
        "tính toán {slip}, không có trong bài {missing}",
        "结果：{verdict} — 共检查 {checked} 项：正确 {ok}，错误 {wrong}（新错误 {new}，传递误差 "
        "{carried}，标注互换 {swapped}，小误差累积 {accumulated}），计算错误 {slip}，作业中缺少 "
        "{missing}"),
    "report.mu": _m("μ = {mu:.6g} {unit}", "μ = {mu:.6g} {unit}", "μ = {mu:.6g} {unit}",
                    "μ = {mu:.6g} {unit}"),
    "report.mu_unknown": _m("μ unknown", "μ неизвестен", "chưa biết μ", "μ 未知"),
    "report.plan": _m("## {title}: {mu}", "## {title}: {mu}", "## {title}: {mu}",
                      "## {title}：{mu}"),
    "report.plan_source": _m("## {title}: {mu} ({source})", "## {title}: {mu} ({source})",
                             "## {title}: {mu} ({source})", "## {title}：{mu}（{source}）"),
    "report.tolerance": _m("tolerance {tol}", "допуск {tol}", "dung sai {tol}", "允许误差 {tol}"),
    "report.tolerance_anchor": _m("tolerance {tol}; placed by {anchor}",
                                  "допуск {tol}; точный план совмещён по точке {anchor}",
                                  "dung sai {tol}; họa đồ chính xác được đặt theo điểm {anchor}",
                                  "允许误差 {tol}；精确图按点 {anchor} 定位"),
    "report.points_off": _m("points off their exact place: {points}",
                            "точки не на своих местах: {points}",
                            "các điểm lệch khỏi vị trí đúng: {points}",
                            "偏离精确位置的点：{points}"),
    "report.point_off": _m("{label} {err:.1f} mm ({cause})", "{label} {err:.1f} мм ({cause})",
                           "{label} {err:.1f} mm ({cause})", "{label} {err:.1f} mm（{cause}）"),
    "report.not_in_construction": _m(
        "* drawn between labelled points, not a segment of the construction",
        "* проведён между обозначенными точками, но не является отрезком построения",
        "* được vẽ giữa các điểm có nhãn, không phải là đoạn của phép dựng",
        "* 连接两个已标注点的线，不是作图中的线段"),
    "report.values": _m("## Values", "## Величины", "## Giá trị", "## 数值"),
    "report.findings": _m("## Findings (root causes)", "## Найденные ошибки (первопричины)",
                          "## Các lỗi phát hiện (nguyên nhân gốc)", "## 发现的问题（根本原因）"),
    "report.notes": _m("## Notes", "## Замечания", "## Ghi chú", "## 说明"),
    "report.finding": _m("{i}. [{kind}] {plan}: {subject}: {message}",
                         "{i}. [{kind}] {plan}: {subject}: {message}",
                         "{i}. [{kind}] {plan}: {subject}: {message}",
                         "{i}. [{kind}] {plan}：{subject}：{message}"),
    "report.note": _m("{level}: {note}", "{level}: {note}", "{level}: {note}", "{level}：{note}"),
    "report.note_where": _m("{where}: {message}", "{where}: {message}", "{where}: {message}",
                            "{where}：{message}"),
    "report.verdict_cause": _m("{word} ({cause})", "{word} ({cause})", "{word} ({cause})",
                               "{word}（{cause}）"),
    # column titles (kept within the column widths of the table)
    "col.segment": _m("segment", "отрезок", "đoạn", "线段"),
    "col.quantity": _m("quantity", "величина", "đại lượng", "物理量"),
    "col.drawn_mm": _m("drawn mm", "черт. мм", "vẽ mm", "作图 mm"),
    "col.exact_mm": _m("exact mm", "точн. мм", "đúng mm", "精确 mm"),
    "col.err_mm": _m("err mm", "ош. мм", "sai mm", "误差 mm"),
    "col.err_pct": _m("err %", "ош. %", "sai %", "误差 %"),
    "col.dir": _m("dir °", "угол °", "lệch °", "方向 °"),
    "col.verdict": _m("verdict", "оценка", "kết luận", "结论"),
    "col.name": _m("name", "обозначение", "tên", "名称"),
    "col.submitted": _m("submitted", "в работе", "bài làm", "提交值"),
    "col.exact": _m("exact", "точно", "chính xác", "精确值"),
    "col.unit": _m("unit", "ед.", "đơn vị", "单位"),
    "tolerance": _m("±{mm:g} mm or ±{pct:g} %", "±{mm:g} мм или ±{pct:g} %",
                    "±{mm:g} mm hoặc ±{pct:g} %", "±{mm:g} mm 或 ±{pct:g} %"),
    "tolerance_deg": _m("±{mm:g} mm or ±{pct:g} % (directions ±{deg:g}°)",
                        "±{mm:g} мм или ±{pct:g} % (направления ±{deg:g}°)",
                        "±{mm:g} mm hoặc ±{pct:g} % (hướng ±{deg:g}°)",
                        "±{mm:g} mm 或 ±{pct:g} %（方向 ±{deg:g}°）"),

    # -- the overlay sheet -------------------------------------------------------------------------
    "overlay.title": _m("{plan}: μ = {mu:.4g} {unit}", "{plan}: μ = {mu:.4g} {unit}",
                        "{plan}: μ = {mu:.4g} {unit}", "{plan}：μ = {mu:.4g} {unit}"),
    "overlay.err_mm": _m("{v:+.1f} mm", "{v:+.1f} мм", "{v:+.1f} mm", "{v:+.1f} mm"),
    "overlay.err_pct": _m("({v:+.1f} %)", "({v:+.1f} %)", "({v:+.1f} %)", "({v:+.1f} %)"),
    "overlay.err_deg": _m("{v:+.1f}°", "{v:+.1f}°", "{v:+.1f}°", "{v:+.1f}°"),
    "overlay.legend": _m(
        "blue: submission   green: exact plan (placed by the pole)   red: wrong, with its error",
        "синий: работа   зелёный: точный план (совмещён по полюсу)   красный: ошибки и их "
        "величина",
        "xanh lam: bài làm   xanh lục: họa đồ chính xác (đặt theo gốc)   đỏ: sai, kèm sai số",
        "蓝色：作业   绿色：精确图（按极点定位）   红色：错误及其误差"),

    # -- sources of φ and μ, conventions -----------------------------------------------------------
    "phi.at": _m("given with --at", "задан ключом --at", "cho bằng --at", "由 --at 给出"),
    "phi.only": _m("the scene's only position", "единственное положение в задании",
                   "vị trí duy nhất của đề bài", "题目中唯一的位置"),
    "phi.best": _m("best fit", "наилучшее совпадение", "vị trí khớp nhất", "最佳吻合"),
    "phi.best_of": _m("the best fit of the scene's {n} positions (no --at given)",
                      "из {n} положений задания выбрано лучше всего совпадающее с работой "
                      "(--at не задан)",
                      "vị trí khớp nhất trong {n} vị trí của đề bài (không cho --at)",
                      "题目 {n} 个位置中最吻合的一个（未给出 --at）"),
    "mu.cli": _m("given on the command line", "задан в командной строке", "cho trên dòng lệnh",
                 "由命令行给出"),
    "mu.text": _m("read from the text '{name} = {text}' ({where})",
                  "прочитан из надписи '{name} = {text}' ({where})",
                  "đọc từ dòng chữ '{name} = {text}' ({where})",
                  "读自文字 '{name} = {text}'（{where}）"),
    "mu.row": _m("read from the row of {written} ({where})",
                 "прочитан из строки {written} ({where})",
                 "đọc từ dòng của {written} ({where})",
                 "读自 {written} 所在行（{where}）"),
    "mu.inferred_drawn": _m(
        "inferred from {ref} ↔ {q} ({ref} is drawn {drawn:.1f} mm; {q} = {exact:.4g} {unit}); "
        "no scale factor is written for the {plan}",
        "выведен из {ref} ↔ {q} ({ref} начерчен длиной {drawn:.1f} мм; {q} = {exact:.4g} "
        "{unit}); масштабный коэффициент {plan} не записан",
        "suy ra từ {ref} ↔ {q} ({ref} được vẽ dài {drawn:.1f} mm; {q} = {exact:.4g} {unit}); "
        "tỉ lệ xích của {plan} không được ghi",
        "由 {ref} ↔ {q} 推算（{ref} 画长 {drawn:.1f} mm；{q} = {exact:.4g} {unit}）；{plan}未写"
        "比例尺"),
    "mu.inferred_table": _m(
        "inferred from {written} ↔ {q} (no scale factor is given for the {plan})",
        "выведен из {written} ↔ {q} (масштабный коэффициент {plan} не задан)",
        "suy ra từ {written} ↔ {q} (không cho tỉ lệ xích của {plan})",
        "由 {written} ↔ {q} 推算（{plan}未给出比例尺）"),
    "convention.turned": _m(
        "drawn turned by {turn:+.0f}° (Zhukovsky's lever); checked turned back about {label}",
        "план повёрнут на {turn:+.0f}° (рычаг Жуковского); проверен после поворота обратно "
        "вокруг точки {label}",
        "họa đồ được vẽ quay {turn:+.0f}° (đòn Giucôpxki); được kiểm tra sau khi quay ngược lại "
        "quanh điểm {label}",
        "图形转过了 {turn:+.0f}°（儒可夫斯基杠杆）；绕点 {label} 转回后检查"),
    "convention.numbered": _m("numbered labels ({written}) read by {how}",
                              "нумерованные обозначения ({written}) прочитаны по {how}",
                              "các nhãn đánh số ({written}) được hiểu theo {how}",
                              "带编号的标注（{written}）按{how}解读"),
    "convention.link": _m("link number", "номеру звена", "số hiệu khâu", "构件编号"),
    "convention.ordinal": _m("order of construction", "порядку построения", "thứ tự dựng",
                             "作图顺序"),
    "how.line_end": _m("line end", "конец линии", "đầu mút đoạn thẳng", "线段端点"),
    "how.marker": _m("point marker", "маркер точки", "dấu điểm", "点标记"),
    "how.crossing": _m("crossing of two lines", "пересечение двух линий", "giao điểm của hai đường",
                       "两线交点"),
    "how.inferred": _m("inferred", "определён по линиям", "suy ra từ các đường", "由线段推断"),

    # -- findings ----------------------------------------------------------------------------------
    "finding.wrong_point": _m(
        "{label} is {err:.1f} mm from its exact place and {own:.1f} mm from where your own "
        "earlier points put it{segments}: {rule}",
        "точка {label} находится в {err:.1f} мм от точного положения и в {own:.1f} мм от "
        "положения, которое дают ваши же предыдущие точки{segments}: {rule}",
        "điểm {label} cách vị trí đúng {err:.1f} mm và cách vị trí suy ra từ chính các điểm "
        "trước đó của bạn {own:.1f} mm{segments}: {rule}",
        "点 {label} 距精确位置 {err:.1f} mm，距由你自己前面各点所得的位置 {own:.1f} mm"
        "{segments}：{rule}"),
    "finding.swapped": _m(
        "the labels {a} and {b} are swapped: the point labelled {a} is where {b} belongs and "
        "the other way round",
        "обозначения {a} и {b} перепутаны: точка с обозначением {a} стоит там, где должна быть "
        "{b}, и наоборот",
        "nhãn {a} và {b} bị đổi chỗ cho nhau: điểm ghi {a} nằm ở vị trí của {b} và ngược lại",
        "标注 {a} 与 {b} 互换了：标为 {a} 的点位于 {b} 应在的位置，反之亦然"),
    "finding.wrong_value": _m(
        "{written} = {text} differs from the exact {exact:.4g} {unit} by {pct:+.1f} %: {hint}",
        "{written} = {text} отличается от точного значения {exact:.4g} {unit} на {pct:+.1f} %: "
        "{hint}",
        "{written} = {text} lệch {pct:+.1f} % so với giá trị chính xác {exact:.4g} {unit}: "
        "{hint}",
        "{written} = {text} 与精确值 {exact:.4g} {unit} 相差 {pct:+.1f} %：{hint}"),
    "brief.long": _m("{name} is {err:.1f} mm too long", "{name} длиннее на {err:.1f} мм",
                     "{name} dài hơn {err:.1f} mm", "{name} 长了 {err:.1f} mm"),
    "brief.short": _m("{name} is {err:.1f} mm too short", "{name} короче на {err:.1f} мм",
                      "{name} ngắn hơn {err:.1f} mm", "{name} 短了 {err:.1f} mm"),
    "brief.turned": _m("{name} is turned {dir:+.1f}°", "{name} повёрнут на {dir:+.1f}°",
                       "{name} bị lệch hướng {dir:+.1f}°", "{name} 方向偏转 {dir:+.1f}°"),
    "brief.off": _m("{name} is off", "{name} неверен", "{name} bị sai", "{name} 有误"),
    "where_label": _m("{label} ({plan})", "{label} ({plan})", "{label} ({plan})",
                      "{label}（{plan}）"),

    # -- hints of wrong rows -----------------------------------------------------------------------
    "hint.missing": _m("not labelled on the submission: {labels}",
                       "в работе не обозначены: {labels}",
                       "chưa ghi nhãn trong bài: {labels}", "作业中未标注：{labels}"),
    "hint.reference": _m("used for the scale factor: its length is right by definition",
                         "по нему определён масштабный коэффициент: его длина верна по "
                         "определению",
                         "được dùng để suy ra tỉ lệ xích: độ dài của nó đúng theo định nghĩa",
                         "用于推算比例尺：其长度按定义是正确的"),
    "hint.swapped": _m("the labels {a} and {b} are swapped", "перепутаны обозначения {a} и {b}",
                       "nhãn {a} và {b} bị đổi chỗ cho nhau", "标注 {a} 与 {b} 互换了"),
    "hint.carried": _m("carried from {roots}: built right from wrong earlier points",
                       "ошибка перенесена из {roots}: построено верно, но от неверных "
                       "предыдущих точек",
                       "lỗi kéo theo từ {roots}: dựng đúng nhưng từ các điểm trước đó bị sai",
                       "误差传递自 {roots}：作法正确，但所依据的前面各点有误"),
    "hint.accumulated": _m("small errors of the points ({errs}) add up on this short segment",
                           "малые погрешности точек ({errs}) складываются на этом коротком "
                           "отрезке",
                           "các sai số nhỏ của các điểm ({errs}) cộng dồn trên đoạn ngắn này",
                           "各点的小误差（{errs}）在这条短线段上累积"),
    "hint.point_err": _m("{label} {err:.1f} mm", "{label} {err:.1f} мм", "{label} {err:.1f} mm",
                         "{label} {err:.1f} mm"),
    "hint.no_mu": _m("no scale factor", "нет масштабного коэффициента", "không có tỉ lệ xích",
                     "没有比例尺"),
    "hint.may_carried_segment": _m(
        "may be carried from {earlier} (an earlier wrong segment it is built from)",
        "возможно, ошибка перенесена из {earlier} (более ранний неверный отрезок, от которого "
        "он строится)",
        "có thể là lỗi kéo theo từ {earlier} (đoạn sai trước đó mà đoạn này được dựng từ nó)",
        "可能由 {earlier} 传递而来（它所依据的前面的错误线段）"),
    "hint.step": _m("built by the step '{op}' ({label})", "строится шагом '{op}' ({label})",
                    "được dựng bằng bước '{op}' ({label})", "由作图步骤 '{op}' 得到（{label}）"),
    "hint.meet": _m("{label} is where the lines {a} and {b} meet",
                    "{label} — точка пересечения прямых {a} и {b}",
                    "{label} là giao điểm của các đường {a} và {b}",
                    "{label} 是直线 {a} 与 {b} 的交点"),
    "hint.normal": _m("{label}: ω²·l of the link, with ω from the velocity plan",
                      "{label}: ω²·l звена, где ω берётся из плана скоростей",
                      "{label}: ω²·l của khâu, với ω lấy từ họa đồ vận tốc",
                      "{label}：构件的 ω²·l，ω 取自速度多边形"),
    "hint.similar": _m("{label} follows by the similarity theorem from the images of its link",
                       "{label} находится по теореме подобия из изображений точек своего звена",
                       "{label} được xác định theo định lý đồng dạng từ ảnh các điểm của khâu",
                       "{label} 由影像原理从其所在构件的影像求得"),
    "hint.drive": _m("the driving vector to {label}", "вектор ведущего звена к точке {label}",
                     "véc tơ của khâu dẫn tới {label}", "原动件的矢量（至 {label}）"),
    "hint.slip": _m("arithmetic slip: {own}, but {written} = {text} is written",
                    "арифметическая ошибка: {own}, а записано {written} = {text}",
                    "lỗi tính toán: {own}, nhưng bài ghi {written} = {text}",
                    "计算错误：{own}，但写的是 {written} = {text}"),
    "hint.own": _m("follows from your own drawing ({own})", "следует из вашего же чертежа ({own})",
                   "suy ra từ chính hình vẽ của bạn ({own})", "与你自己的作图一致（{own}）"),
    "hint.own_carried": _m("follows from your own drawing ({own}); carried from {roots}",
                           "следует из вашего же чертежа ({own}); ошибка перенесена из {roots}",
                           "suy ra từ chính hình vẽ của bạn ({own}); lỗi kéo theo từ {roots}",
                           "与你自己的作图一致（{own}）；误差传递自 {roots}"),
    "hint.may_carried": _m("may be carried from {roots}", "возможно, ошибка перенесена из {roots}",
                           "có thể là lỗi kéo theo từ {roots}", "可能由 {roots} 传递而来"),
    "hint.omega": _m("{label} = v_rel / l_{p}{q} with v_rel the segment {a}{b} of the velocity "
                     "plan",
                     "{label} = v_rel / l_{p}{q}, где v_rel — отрезок {a}{b} плана скоростей",
                     "{label} = v_rel / l_{p}{q}, với v_rel là đoạn {a}{b} trên họa đồ vận tốc",
                     "{label} = v_rel / l_{p}{q}，其中 v_rel 为速度多边形上的线段 {a}{b}"),
    "hint.epsilon": _m("{label} = a^t / l_{p}{q} with a^t the segment {n} {a} of the acceleration "
                       "plan",
                       "{label} = a^t / l_{p}{q}, где a^t — отрезок {n} {a} плана ускорений",
                       "{label} = a^t / l_{p}{q}, với a^t là đoạn {n} {a} trên họa đồ gia tốc",
                       "{label} = a^t / l_{p}{q}，其中 a^t 为加速度多边形上的线段 {n} {a}"),
    "hint.value_step": _m("{display} comes from the step '{op}' ({label})",
                          "{display} получается шагом '{op}' ({label})",
                          "{display} có được từ bước '{op}' ({label})",
                          "{display} 由作图步骤 '{op}' 得到（{label}）"),
    "hint.value_segment": _m("{display} is the segment {seg} × μ",
                             "{display} — это отрезок {seg} × μ",
                             "{display} bằng đoạn {seg} × μ", "{display} 等于线段 {seg} × μ"),
    "hint.value_dynamics": _m("{display} is computed from the velocity plan and the masses",
                              "{display} вычисляется по плану скоростей и массам звеньев",
                              "{display} được tính từ họa đồ vận tốc và khối lượng các khâu",
                              "{display} 由速度多边形和各构件质量算出"),
    "own.length": _m("{len:g} mm × {mu:g} = {own:.4g} {unit}",
                     "{len:g} мм × {mu:g} = {own:.4g} {unit}",
                     "{len:g} mm × {mu:g} = {own:.4g} {unit}",
                     "{len:g} mm × {mu:g} = {own:.4g} {unit}"),
    "own.drawn": _m("{seg} = {len:.1f} mm × {mu:g} = {own:.4g} {unit}",
                    "{seg} = {len:.1f} мм × {mu:g} = {own:.4g} {unit}",
                    "{seg} = {len:.1f} mm × {mu:g} = {own:.4g} {unit}",
                    "{seg} = {len:.1f} mm × {mu:g} = {own:.4g} {unit}"),
    "own.table": _m("{seg} = {len:g} mm × {mu:g} = {own:.4g} {unit}",
                    "{seg} = {len:g} мм × {mu:g} = {own:.4g} {unit}",
                    "{seg} = {len:g} mm × {mu:g} = {own:.4g} {unit}",
                    "{seg} = {len:g} mm × {mu:g} = {own:.4g} {unit}"),
    "own.plan": _m("from your plan {label} = {own:.4g} {unit}",
                   "по вашему плану {label} = {own:.4g} {unit}",
                   "theo họa đồ của bạn {label} = {own:.4g} {unit}",
                   "由你的图得 {label} = {own:.4g} {unit}"),
    "own.omega": _m("{seg} × μ / l = {len:g} mm × {mu:g} / {l:.4g} m = {own:.4g} {unit}",
                    "{seg} × μ / l = {len:g} мм × {mu:g} / {l:.4g} m = {own:.4g} {unit}",
                    "{seg} × μ / l = {len:g} mm × {mu:g} / {l:.4g} m = {own:.4g} {unit}",
                    "{seg} × μ / l = {len:g} mm × {mu:g} / {l:.4g} m = {own:.4g} {unit}"),

    # -- the rule a step follows (hints.rule) ------------------------------------------------------
    "rule.tail": _m("{body}; from your own earlier points it belongs {off:~.1f} mm from where it "
                    "is drawn",
                    "{body}; по вашим же предыдущим точкам эта точка должна быть в {off:~.1f} мм "
                    "от того места, где начерчена",
                    "{body}; theo chính các điểm trước đó của bạn, điểm này phải cách chỗ đã vẽ "
                    "{off:~.1f} mm",
                    "{body}；按你自己前面的各点，该点应距所画位置 {off:~.1f} mm"),
    "rule.load_missing": _m(
        "the load {name} is missing from this force polygon: it acts on the group and is laid "
        "off from {prev}, {len:~.1f} mm long",
        "в этом плане сил пропущена сила {name}: она действует на группу и откладывается от "
        "{prev}, длина {len:~.1f} мм",
        "họa đồ lực này thiếu lực {name}: lực này tác dụng lên nhóm và được đặt từ {prev}, dài "
        "{len:~.1f} mm",
        "此力多边形漏掉了载荷 {name}：它作用于该杆组，应自 {prev} 画起，长 {len:~.1f} mm"),
    "rule.load_end": _m(
        "{label} is the end of the load {name} laid off from {prev}: {len:~.1f} mm long, in the "
        "direction of the force",
        "{label} — конец вектора силы {name}, отложенного от {prev}: длина {len:~.1f} мм, по "
        "направлению силы",
        "{label} là mút của véc tơ lực {name} đặt từ {prev}: dài {len:~.1f} mm, theo phương "
        "chiều của lực",
        "{label} 是自 {prev} 画出的载荷 {name} 的终点：长 {len:~.1f} mm，沿力的方向"),
    "rule.on_line": _m("on the line through {through} {line} ({where})",
                       "на прямой {line} через {through} ({where})",
                       "trên đường thẳng {line} qua {through} ({where})",
                       "过 {through} 的直线 {line} 上（{where}）"),
    "rule.on_it": _m("on it", "на ней", "nằm trên đó", "在线上"),
    "rule.off_by": _m("{d:~.1f} mm off", "отклонение {d:~.1f} мм", "lệch {d:~.1f} mm",
                      "偏离 {d:~.1f} mm"),
    "rule.must_lie": _m("{label} must lie {parts}", "{label} должна лежать {parts}",
                        "{label} phải nằm {parts}", "{label} 必须位于{parts}"),
    "rule.closes": _m("{label} closes the force polygon: it must lie {parts}",
                      "{label} замыкает план сил: она должна лежать {parts}",
                      "{label} khép kín họa đồ lực: nó phải nằm {parts}",
                      "{label} 使力多边形封闭：它必须位于{parts}"),
    "rule.of_link": _m(" of link {link}", " звена {link}", " thuộc khâu {link}", "构件 {link} 上"),
    "rule.similar": _m(
        "by the similarity theorem the image {label} of a point{link} makes the triangle "
        "{a}{b}{label} similar to {A}{B}{X} (same sense of rotation)",
        "по теореме подобия изображение {label} точки{link} образует треугольник {a}{b}{label}, "
        "подобный {A}{B}{X} (с тем же направлением обхода)",
        "theo định lý đồng dạng, ảnh {label} của một điểm{link} tạo thành tam giác "
        "{a}{b}{label} đồng dạng với {A}{B}{X} (cùng chiều quay)",
        "由影像原理，{link}点的影像 {label} 应使三角形 {a}{b}{label} 与 {A}{B}{X} 相似（顶点"
        "顺序的转向相同）"),
    "rule.similar_line": _m(
        "the image of a point{link} lies on the image of the link: {label} must lie on {a}{b} "
        "({d:~.1f} mm off it) and divide it as {A}{X}/{A}{B} = {t:.3f} (yours {yours:.3f})",
        "изображение точки{link} лежит на изображении звена: {label} должна лежать на {a}{b} "
        "(отклонение {d:~.1f} мм) и делить его в отношении {A}{X}/{A}{B} = {t:.3f} (у вас "
        "{yours:.3f})",
        "ảnh của một điểm{link} nằm trên ảnh của khâu: {label} phải nằm trên {a}{b} (đang lệch "
        "{d:~.1f} mm) và chia nó theo tỉ số {A}{X}/{A}{B} = {t:.3f} (của bạn {yours:.3f})",
        "{link}点的影像位于构件的影像上：{label} 必须在 {a}{b} 上（现偏离 {d:~.1f} mm），且"
        "分比为 {A}{X}/{A}{B} = {t:.3f}（你的为 {yours:.3f}）"),
    "rule.drive": _m(
        "the driving vector to {label} is drawn {how} = {len:~.1f} mm at this scale; yours is "
        "{drawn:~.1f} mm, turned {ang:~.1f}°",
        "вектор ведущего звена к {label} откладывается {how} = {len:~.1f} мм в этом масштабе; "
        "у вас {drawn:~.1f} мм, с поворотом на {ang:~.1f}°",
        "véc tơ của khâu dẫn tới {label} được vẽ {how} = {len:~.1f} mm theo tỉ lệ xích này; "
        "của bạn dài {drawn:~.1f} mm, lệch {ang:~.1f}°",
        "原动件至 {label} 的矢量应画成 {how} = {len:~.1f} mm（按此比例尺）；你画的长 "
        "{drawn:~.1f} mm，偏转 {ang:~.1f}°"),
    "rule.drive_v": _m("⊥ {pivot}{tip} in the sense of ω, ω·l_{pivot}{tip}",
                       "⊥ {pivot}{tip} в сторону вращения ω, ω·l_{pivot}{tip}",
                       "⊥ {pivot}{tip} theo chiều ω, ω·l_{pivot}{tip}",
                       "⊥ {pivot}{tip}，指向 ω 转向，ω·l_{pivot}{tip}"),
    "rule.drive_a": _m("∥ {tip}{pivot} from {tip} towards {pivot}, ω²·l_{pivot}{tip}",
                       "∥ {tip}{pivot} от {tip} к {pivot}, ω²·l_{pivot}{tip}",
                       "∥ {tip}{pivot}, hướng từ {tip} về {pivot}, ω²·l_{pivot}{tip}",
                       "∥ {tip}{pivot}，由 {tip} 指向 {pivot}，ω²·l_{pivot}{tip}"),
    "rule.normal": _m(
        "the normal component {label} is laid off from {ap} ∥ {Q}{P}, from {Q} towards {P}, "
        "{w}²·l_{P}{Q} long: {len:~.1f} mm{own}",
        "нормальное ускорение {label} откладывается от {ap} ∥ {Q}{P}, от {Q} к {P}, длиной "
        "{w}²·l_{P}{Q}: {len:~.1f} мм{own}",
        "gia tốc pháp tuyến {label} được đặt từ {ap} ∥ {Q}{P}, hướng từ {Q} về {P}, dài "
        "{w}²·l_{P}{Q}: {len:~.1f} mm{own}",
        "法向加速度 {label} 自 {ap} 画出，∥ {Q}{P}，由 {Q} 指向 {P}，长为 {w}²·l_{P}{Q}："
        "{len:~.1f} mm{own}"),
    "rule.normal_own": _m(" (with {w} = {ow:.3f} rad/s from your velocity plan: {olen:~.1f} mm)",
                          " (при {w} = {ow:.3f} rad/s по вашему плану скоростей: {olen:~.1f} мм)",
                          " (với {w} = {ow:.3f} rad/s lấy từ họa đồ vận tốc của bạn: "
                          "{olen:~.1f} mm)",
                          "（按你的速度多边形 {w} = {ow:.3f} rad/s：{olen:~.1f} mm）"),
    "rule.coriolis": _m(
        "the Coriolis component {label} = 2{w}·v_rel is laid off from {start}, perpendicular to "
        "the guide, v_rel turned 90° in the sense of {w}: {len:~.1f} mm",
        "кориолисово ускорение {label} = 2{w}·v_rel откладывается от {start} перпендикулярно "
        "направляющей, по v_rel, повёрнутой на 90° в сторону {w}: {len:~.1f} мм",
        "gia tốc Côriôlít {label} = 2{w}·v_rel được đặt từ {start}, vuông góc với đường dẫn, "
        "theo chiều v_rel quay 90° theo chiều {w}: {len:~.1f} mm",
        "哥氏加速度 {label} = 2{w}·v_rel 自 {start} 画出，垂直于导路，方向为 v_rel 沿 {w} 转向转 "
        "90°：{len:~.1f} mm"),
    "rule.rigid": _m("the image {label} of {X} follows from {o} by the link's rotation",
                     "изображение {label} точки {X} получается из {o} по вращению звена",
                     "ảnh {label} của {X} được suy ra từ {o} theo chuyển động quay của khâu",
                     "{X} 的影像 {label} 由 {o} 按构件的转动求得"),
    "rule.position": _m("{label} follows from the link lengths and the points before it",
                        "{label} определяется длинами звеньев и предыдущими точками",
                        "{label} được xác định từ chiều dài các khâu và các điểm trước đó",
                        "{label} 由各构件长度和前面的点确定"),
    "rule.pole": _m("{label} is the pole", "{label} — полюс", "{label} là gốc", "{label} 是极点"),
    "rule.op": _m("{label} is built by '{op}'", "{label} строится операцией '{op}'",
                  "{label} được dựng bằng phép '{op}'", "{label} 由 '{op}' 作出"),

    # -- notes -------------------------------------------------------------------------------------
    "note.no_loads": _m("the scene gives no masses or loads; force quantities are not checked",
                        "в задании нет масс и нагрузок; силовые величины не проверяются",
                        "đề bài không cho khối lượng và tải trọng; các đại lượng lực không được "
                        "kiểm tra",
                        "题目未给出质量和载荷；不检查力的数值"),
    "note.no_force_plan": _m("the force plan cannot be built ({error}); force quantities are not "
                             "checked",
                             "план сил построить нельзя ({error}); силовые величины не "
                             "проверяются",
                             "không dựng được họa đồ lực ({error}); các đại lượng lực không được "
                             "kiểm tra",
                             "无法作出力多边形（{error}）；不检查力的数值"),
    "note.crank_angle": _m("crank angle '{name} = {text}': {detail}",
                           "угол кривошипа '{name} = {text}': {detail}",
                           "góc tay quay '{name} = {text}': {detail}",
                           "曲柄转角 '{name} = {text}'：{detail}"),
    "note.no_mu": _m(
        "no scale factor for the {plan}: none is written (e.g. 'μ{v} = …'), none given on the "
        "command line, and no segment with both ends labelled to infer it from; its lengths are "
        "not checked",
        "нет масштабного коэффициента {plan}: он не записан (например, 'μ{v} = …'), не задан в "
        "командной строке, и нет отрезка с обозначенными концами, чтобы его вывести; длины не "
        "проверяются",
        "không có tỉ lệ xích cho {plan}: không được ghi (ví dụ 'μ{v} = …'), không cho trên dòng "
        "lệnh, và không có đoạn nào được ghi nhãn cả hai đầu để suy ra; độ dài trên đó không "
        "được kiểm tra",
        "{plan}没有比例尺：图上未写（例如 'μ{v} = …'），命令行未给出，也没有两端都已标注的线段"
        "可供推算；不检查其长度"),
    "note.not_computable": _m("{extra} cannot be computed for this scene ({error})",
                              "{extra} нельзя вычислить для этого задания ({error})",
                              "không tính được {extra} cho đề bài này ({error})",
                              "此题目无法计算 {extra}（{error}）"),
    "note.not_label": _m("text '{text}' is not a label of any plan of this mechanism; it is not "
                         "used",
                         "надпись '{text}' не является обозначением точки ни одного плана этого "
                         "механизма; она не используется",
                         "chữ '{text}' không phải là nhãn của họa đồ nào của cơ cấu này; không "
                         "được dùng",
                         "文字 '{text}' 不是此机构任何图上的标注；未采用"),
    "note.label_far": _m("label '{written}' is {d:.1f} mm from the nearest line end, more than "
                         "the {tol:.1f} mm allowed (--label-distance); it is not used",
                         "обозначение '{written}' находится в {d:.1f} мм от ближайшего конца "
                         "линии, больше допустимых {tol:.1f} мм (--label-distance); оно не "
                         "используется",
                         "nhãn '{written}' cách đầu mút gần nhất {d:.1f} mm, xa hơn mức cho phép "
                         "{tol:.1f} mm (--label-distance); không được dùng",
                         "标注 '{written}' 距最近的线段端点 {d:.1f} mm，超过允许的 {tol:.1f} mm"
                         "（--label-distance）；未采用"),
    "note.repeated_plans": _m("the sheet holds {n} drawings of the {plan} whose labels repeat; "
                              "each is checked on its own",
                              "на листе несколько изображений {plan} с повторяющимися "
                              "обозначениями (всего: {n}); каждое проверяется отдельно",
                              "bản vẽ có {n} hình của {plan} với nhãn lặp lại; mỗi hình được "
                              "kiểm tra riêng",
                              "图纸上有 {n} 个标注重复的{plan}；逐个分别检查"),
    "note.not_point_of_plan": _m("label '{written}' is not a point of the {plan} (its points: "
                                 "{known}); it is not used",
                                 "обозначение '{written}' не является точкой {plan} (его точки: "
                                 "{known}); оно не используется",
                                 "nhãn '{written}' không phải là điểm của {plan} (các điểm của "
                                 "nó: {known}); không được dùng",
                                 "标注 '{written}' 不是{plan}上的点（其点为：{known}）；未采用"),
    "note.ambiguous_numbered": _m("cannot tell which point '{written}' is on the plan; it is not "
                                  "used",
                                  "нельзя определить, какая точка плана обозначена '{written}'; "
                                  "обозначение не используется",
                                  "không xác định được '{written}' là điểm nào trên họa đồ; "
                                  "không được dùng",
                                  "无法确定 '{written}' 是图上的哪个点；未采用"),
    "note.label_repeated": _m("label '{label}' appears {n} times on the {plan} at different "
                              "points ({where}); it is not used",
                              "обозначение '{label}' стоит на {plan} в разных местах (раз: {n}; "
                              "{where}); оно не используется",
                              "nhãn '{label}' xuất hiện {n} lần trên {plan} tại các điểm khác "
                              "nhau ({where}); không được dùng",
                              "标注 '{label}' 在{plan}上的不同位置出现了 {n} 次（{where}）；未采用"),
    "note.where_at": _m("{where} at {xy}", "{where}, точка {xy}", "{where} tại {xy}",
                        "{where}，位于 {xy}"),
    "note.pole_unknown": _m("the pole of the {plan} is not labelled and cannot be told from the "
                            "lines; absolute vectors are not checked",
                            "полюс {plan} не обозначен, и по линиям его определить нельзя; "
                            "абсолютные векторы не проверяются",
                            "gốc của {plan} không được ghi nhãn và không xác định được từ các "
                            "đường; các véc tơ tuyệt đối không được kiểm tra",
                            "{plan}的极点未标注，也无法从线段判断；不检查绝对矢量"),
    "note.pole_inferred": _m("the pole {label} of the {plan} is not labelled; taken as the point "
                             "{xy} where {n} vectors to labelled points start",
                             "полюс {label} {plan} не обозначен; за полюс принята точка {xy}, "
                             "из которой выходят векторы к обозначенным точкам (их {n})",
                             "gốc {label} của {plan} không được ghi nhãn; lấy điểm {xy}, nơi "
                             "xuất phát {n} véc tơ tới các điểm có nhãn",
                             "{plan}的极点 {label} 未标注；取 {n} 条指向已标注点的矢量的共同"
                             "起点 {xy} 为极点"),
    "note.mu_unusable": _m("scale factor '{name} = {text}' cannot be used: {detail}",
                           "масштабный коэффициент '{name} = {text}' нельзя использовать: "
                           "{detail}",
                           "không dùng được tỉ lệ xích '{name} = {text}': {detail}",
                           "比例尺 '{name} = {text}' 无法使用：{detail}"),
    "note.mu_positive": _m("scale factor '{name} = {text}' must be positive",
                           "масштабный коэффициент '{name} = {text}' должен быть положительным",
                           "tỉ lệ xích '{name} = {text}' phải là số dương",
                           "比例尺 '{name} = {text}' 必须为正"),
    "note.mu_error": _m("scale factor '{name} = {text}': {detail}",
                        "масштабный коэффициент '{name} = {text}': {detail}",
                        "tỉ lệ xích '{name} = {text}': {detail}",
                        "比例尺 '{name} = {text}'：{detail}"),
    "note.mu_second": _m("a second scale factor for the {plan} ({name} = {text}) differs from the "
                         "first; the first is used",
                         "второй масштабный коэффициент {plan} ({name} = {text}) отличается от "
                         "первого; используется первый",
                         "tỉ lệ xích thứ hai của {plan} ({name} = {text}) khác tỉ lệ xích đầu "
                         "tiên; dùng tỉ lệ xích đầu tiên",
                         "{plan}的第二个比例尺（{name} = {text}）与第一个不同；采用第一个"),
    "note.row_mu_error": _m("scale factor '{mu}' of {name}: {detail}",
                            "масштабный коэффициент '{mu}' в строке {name}: {detail}",
                            "tỉ lệ xích '{mu}' của {name}: {detail}",
                            "{name} 的比例尺 '{mu}'：{detail}"),
    "note.not_finite": _m("'{name} = {text}' is not a finite number",
                          "'{name} = {text}' не является конечным числом",
                          "'{name} = {text}' không phải là số hữu hạn",
                          "'{name} = {text}' 不是有限数"),
    "note.no_unit": _m("'{name} = {text}' has no unit; read in SI ({unit})",
                       "'{name} = {text}' записано без единицы измерения; прочитано в СИ ({unit})",
                       "'{name} = {text}' không có đơn vị; đọc theo hệ SI ({unit})",
                       "'{name} = {text}' 没有单位；按国际单位制读取（{unit}）"),
    "note.value_error": _m("'{name} = {text}': {detail}", "'{name} = {text}': {detail}",
                           "'{name} = {text}': {detail}", "'{name} = {text}'：{detail}"),
    "note.length_expected": _m("'{name} = {text}': expected a length in mm such as 67.0 or "
                               "\"67,0 mm\"",
                               "'{name} = {text}': ожидается длина в мм, например 67,0 или "
                               "\"67,0 мм\"",
                               "'{name} = {text}': cần một độ dài tính bằng mm, ví dụ 67,0 hoặc "
                               "\"67,0 mm\"",
                               "'{name} = {text}'：应为以 mm 为单位的长度，例如 67.0 或 "
                               "\"67,0 mm\""),
    "note.unknown_quantity": _m("unknown quantity '{name}'; its value is not checked",
                                "неизвестная величина '{name}'; её значение не проверяется",
                                "đại lượng không rõ '{name}'; giá trị của nó không được kiểm tra",
                                "未知物理量 '{name}'；不检查其数值"),
    "note.length_not_value": _m(
        "'{name} = {text}' is a length on the paper, but {display} is {dim}; write the segment's "
        "name (e.g. pb) for a drawn length, or the value with its unit",
        "'{name} = {text}' — длина на чертеже, а {display} — {dim}; для начерченной длины "
        "пишите имя отрезка (например, pb), иначе — значение с единицей измерения",
        "'{name} = {text}' là độ dài trên bản vẽ, nhưng {display} là {dim}; hãy ghi tên đoạn "
        "(ví dụ pb) cho độ dài đã vẽ, hoặc ghi giá trị kèm đơn vị",
        "'{name} = {text}' 是图上的长度，但 {display} 是{dim}；作图长度请写线段名（如 pb），否则"
        "请写带单位的数值"),
    "note.force_without_plan": _m(
        "'{name}' looks like a force or moment, but this check has no force plan (the scene "
        "gives no loads or masses); it is not checked",
        "'{name}' похоже на силу или момент, но в этой проверке нет плана сил (в задании нет "
        "нагрузок и масс); не проверяется",
        "'{name}' có vẻ là lực hoặc mômen, nhưng lần kiểm tra này không có họa đồ lực (đề bài "
        "không cho tải trọng hay khối lượng); không được kiểm tra",
        "'{name}' 看似是力或力矩，但本次检查没有力多边形（题目未给出载荷或质量）；不检查"),
    "note.unknown_name": _m("unknown quantity or segment '{name}'",
                            "неизвестная величина или отрезок '{name}'",
                            "đại lượng hoặc đoạn không rõ '{name}'",
                            "未知的物理量或线段 '{name}'"),
    "note.unknown_name_known": _m(
        "unknown quantity or segment '{name}'; known quantities: {known} …, segments: their "
        "names as on the plan (pb, bc, πb′, b′n_CB …)",
        "неизвестная величина или отрезок '{name}'; известные величины: {known} …, отрезки: "
        "их имена как на плане (pb, bc, πb′, b′n_CB …)",
        "đại lượng hoặc đoạn không rõ '{name}'; các đại lượng đã biết: {known} …, các đoạn: "
        "tên như trên họa đồ (pb, bc, πb′, b′n_CB …)",
        "未知的物理量或线段 '{name}'；已知物理量：{known} …；线段：按图上的名称（pb, bc, πb′, "
        "b′n_CB …）"),
    "note.truncated": _m("the file ends early (no EOF marker): it may be truncated; what could be "
                         "read is checked",
                         "файл обрывается (нет маркера EOF): возможно, он неполон; проверяется "
                         "то, что удалось прочитать",
                         "tệp kết thúc sớm (không có dấu EOF): có thể bị cắt cụt; phần đọc được "
                         "vẫn được kiểm tra",
                         "文件提前结束（没有 EOF 标记）：可能不完整；检查能读出的部分"),
    "note.repaired_values": _m("{n} damaged value(s) repaired on reading, e.g. {example}",
                               "при чтении исправлены повреждённые значения (всего: {n}), "
                               "например: {example}",
                               "đã sửa {n} giá trị hỏng khi đọc, ví dụ {example}",
                               "读取时修复了 {n} 个损坏的值，例如 {example}"),
    "note.repaired_dxf": _m("the DXF was damaged and repaired on reading ({n} problem(s), e.g. "
                            "{example})",
                            "DXF был повреждён и исправлен при чтении (проблем: {n}, например: "
                            "{example})",
                            "tệp DXF bị hỏng và đã được sửa khi đọc ({n} lỗi, ví dụ {example})",
                            "DXF 文件已损坏，读取时已修复（{n} 处问题，例如 {example}）"),
    "note.insunits": _m("drawing units $INSUNITS = {code} are not supported; lengths are read as "
                        "millimetres",
                        "единицы чертежа $INSUNITS = {code} не поддерживаются; длины читаются в "
                        "миллиметрах",
                        "không hỗ trợ đơn vị bản vẽ $INSUNITS = {code}; độ dài được đọc theo "
                        "milimét",
                        "不支持图纸单位 $INSUNITS = {code}；长度按毫米读取"),
    "note.layout": _m("model space is empty; read layout '{name}'",
                      "пространство модели пусто; прочитан лист '{name}'",
                      "không gian mô hình trống; đã đọc layout '{name}'",
                      "模型空间为空；读取了布局 '{name}'"),
    "note.skipped": _m("{n} dash-dot line(s) (axes, trajectories) and lines of frames and tables "
                       "are not read as lines of a plan",
                       "штрихпунктирные линии (оси, траектории), линии рамок и таблиц не "
                       "считаются линиями плана (пропущено: {n})",
                       "{n} đường chấm gạch (trục, quỹ đạo) và các đường khung, bảng không được "
                       "coi là đường của họa đồ",
                       "{n} 条点划线（轴线、轨迹）以及图框和表格的线不作为图的线段读取"),
    "note.units_too_big": _m("the drawing units say {unit}, but the drawing would then be "
                             "{m:.1f} m across; it is read in millimetres ({mm:.0f} mm across)",
                             "единицы чертежа — {unit}, но тогда чертёж имел бы размер {m:.1f} "
                             "м; он читается в миллиметрах (размер {mm:.0f} мм)",
                             "đơn vị bản vẽ là {unit}, nhưng khi đó bản vẽ sẽ rộng {m:.1f} m; "
                             "bản vẽ được đọc theo milimét (rộng {mm:.0f} mm)",
                             "图纸单位为{unit}，但那样图形宽达 {m:.1f} m；改按毫米读取（宽 "
                             "{mm:.0f} mm）"),
    "note.unreadable_entity": _m("skipped an unreadable {kind} ({error})",
                                 "пропущен нечитаемый объект {kind} ({error})",
                                 "bỏ qua một đối tượng {kind} không đọc được ({error})",
                                 "跳过了无法读取的 {kind}（{error}）"),
    "note.nonfinite_line": _m("skipped a line with non-finite coordinates",
                              "пропущена линия с нечисловыми координатами",
                              "bỏ qua một đường có tọa độ không hữu hạn",
                              "跳过了坐标非有限值的线段"),
    "note.arc_chords": _m("arc segments of the polyline are read as straight chords",
                          "дуговые участки полилинии читаются как прямые хорды",
                          "các đoạn cung của polyline được đọc như các dây cung thẳng",
                          "多段线中的圆弧段按直线弦读取"),
    "note.row_no_name_toml": _m("a row without 'name' (or 'segment', 'quantity') is skipped",
                                "строка без 'name' (или 'segment', 'quantity') пропущена",
                                "bỏ qua dòng không có 'name' (hoặc 'segment', 'quantity')",
                                "跳过了没有 'name'（或 'segment'、'quantity'）的行"),
    "note.cannot_use": _m("cannot use {value}; expected a number, a text such as \"2.95 m/s\", or "
                          "a table",
                          "нельзя использовать {value}; ожидается число, текст вида "
                          "\"2,95 m/s\" или таблица",
                          "không dùng được {value}; cần một số, một chuỗi như \"2,95 m/s\", "
                          "hoặc một bảng",
                          "无法使用 {value}；应为数字、形如 \"2.95 m/s\" 的文本或表"),
    "note.row_no_name": _m("a row without a name is skipped", "строка без названия пропущена",
                           "bỏ qua dòng không có tên", "跳过了没有名称的行"),
    "note.expected_name_value": _m("expected 'name, value' (got {row})",
                                   "ожидается 'название, значение' (получено {row})",
                                   "cần 'tên, giá trị' (nhận được {row})",
                                   "应为 '名称, 数值'（实际为 {row}）"),
    "units.insunits": _m("$INSUNITS = {code}, read as millimetres",
                         "$INSUNITS = {code}, прочитаны как миллиметры",
                         "$INSUNITS = {code}, đọc theo milimét", "$INSUNITS = {code}，按毫米读取"),
    "units.unitless": _m("unitless, read as millimetres", "без единиц, прочитаны как миллиметры",
                         "không có đơn vị, đọc theo milimét", "无单位，按毫米读取"),
    "units.scaled": _m("{unit} (× {scale:g} mm)", "{unit} (× {scale:g} мм)",
                       "{unit} (× {scale:g} mm)", "{unit}（× {scale:g} mm）"),
    "units.header": _m("{unit} in the header, read as millimetres",
                       "в заголовке указаны {unit}, прочитаны как миллиметры",
                       "tiêu đề ghi {unit}, đọc theo milimét", "文件头为{unit}，按毫米读取"),
    "unit.0": _m("unitless", "без единиц", "không có đơn vị", "无单位"),
    "unit.1": _m("inches", "дюймы", "inch", "英寸"),
    "unit.2": _m("feet", "футы", "feet", "英尺"),
    "unit.4": _m("millimetres", "миллиметры", "milimét", "毫米"),
    "unit.5": _m("centimetres", "сантиметры", "xentimét", "厘米"),
    "unit.6": _m("metres", "метры", "mét", "米"),
    "unit.14": _m("decimetres", "дециметры", "đềximét", "分米"),

    # -- where an item is -------------------------------------------------------------------------
    "where.line": _m("{file} line {n}", "{file}, строка {n}", "{file} dòng {n}", "{file} 第 {n} 行"),
    "where.key": _m("{file} key '{key}'", "{file}, ключ '{key}'", "{file} khóa '{key}'",
                    "{file} 键 '{key}'"),
    "where.row": _m("{where}, row {n}", "{where}, запись {n}", "{where}, hàng {n}",
                    "{where}，第 {n} 项"),
    "where.entity": _m("{type} #{handle}{extra}", "{type} #{handle}{extra}",
                       "{type} #{handle}{extra}", "{type} #{handle}{extra}"),
    "where.entity_layer": _m("{type} #{handle} on layer '{layer}'{extra}",
                             "{type} #{handle} на слое '{layer}'{extra}",
                             "{type} #{handle} trên lớp '{layer}'{extra}",
                             "图层 '{layer}' 上的 {type} #{handle}{extra}"),
    "where.block": _m(" in block '{name}' (INSERT #{handle})",
                      " в блоке '{name}' (INSERT #{handle})",
                      " trong khối '{name}' (INSERT #{handle})",
                      "（位于块 '{name}' 中，INSERT #{handle}）"),
    "where.segment": _m("{where}, segment {n}", "{where}, участок {n}", "{where}, đoạn {n}",
                        "{where}，第 {n} 段"),
    "where.text_line": _m("{where}, line {n}", "{where}, строка {n}", "{where}, dòng {n}",
                          "{where}，第 {n} 行"),

    # -- words ------------------------------------------------------------------------------------
    "verdict.ok": _m("ok", "верно", "đúng", "正确"),
    "verdict.wrong": _m("WRONG", "НЕВЕРНО", "SAI", "错误"),
    "verdict.slip": _m("SLIP", "ОШИБКА СЧЁТА", "TÍNH SAI", "计算错误"),
    "verdict.reference": _m("reference", "опорный", "tham chiếu", "基准"),
    "verdict.missing": _m("missing", "нет в работе", "thiếu", "缺少"),
    "verdict.unchecked": _m("unchecked", "не проверено", "chưa kiểm tra", "未检查"),
    "cause.new": _m("new", "новая ошибка", "lỗi mới", "新出现"),
    "cause.carried": _m("carried", "перенесена", "kéo theo", "传递"),
    "cause.swapped": _m("swapped", "перепутаны обозначения", "nhầm nhãn", "标注互换"),
    "cause.accumulated": _m("accumulated", "накопление погрешностей", "sai số cộng dồn",
                            "误差累积"),
    "kind.wrong point": _m("wrong point", "неверная точка", "điểm sai", "点的位置错误"),
    "kind.wrong segment": _m("wrong segment", "неверный отрезок", "đoạn sai", "线段错误"),
    "kind.swapped labels": _m("swapped labels", "перепутаны обозначения", "nhầm nhãn",
                              "标注互换"),
    "kind.arithmetic slip": _m("arithmetic slip", "арифметическая ошибка", "lỗi tính toán",
                               "计算错误"),
    "kind.wrong value": _m("wrong value", "неверное значение", "giá trị sai", "数值错误"),
    "error.length": _m("length", "длина", "độ dài", "长度"),
    "error.direction": _m("direction", "направление", "hướng", "方向"),
    "error.length and direction": _m("length and direction", "длина и направление",
                                     "độ dài và hướng", "长度和方向"),
    "level.error": _m("error", "ошибка", "lỗi", "错误"),
    "level.warning": _m("warning", "предупреждение", "cảnh báo", "警告"),
    "level.info": _m("info", "сведения", "thông tin", "信息"),
    "dim.length": _m("a length", "длина", "độ dài", "长度"),
    "dim.angle": _m("an angle", "угол", "góc", "角度"),
    "dim.angular_velocity": _m("an angular velocity", "угловая скорость", "vận tốc góc", "角速度"),
    "dim.angular_acceleration": _m("an angular acceleration", "угловое ускорение", "gia tốc góc",
                                   "角加速度"),
    "dim.velocity": _m("a velocity", "скорость", "vận tốc", "速度"),
    "dim.acceleration": _m("an acceleration", "ускорение", "gia tốc", "加速度"),
    "dim.mass": _m("a mass", "масса", "khối lượng", "质量"),
    "dim.inertia": _m("an inertia", "момент инерции", "mômen quán tính", "转动惯量"),
    "dim.force": _m("a force", "сила", "lực", "力"),
    "dim.moment": _m("a moment", "момент", "mômen", "力矩"),
    "dim.pressure": _m("a pressure", "давление", "áp suất", "压强"),
    "dim.area": _m("an area", "площадь", "diện tích", "面积"),
    "dim.dimensionless": _m("a dimensionless", "безразмерная величина",
                            "đại lượng không thứ nguyên", "无量纲量"),
    "cli.wrote": _m("wrote {path}", "записан файл {path}", "đã ghi {path}", "已写入 {path}"),
}

#: plan names: (nominative, genitive, prepositional) in Russian; one form elsewhere
PLAN_NAMES: dict[str, dict[str, tuple[str, ...]]] = {
    "position": {"ru": ("план положений", "плана положений", "плане положений"),
                 "vi": ("họa đồ vị trí",), "zh": ("机构位置图",)},
    "velocity": {"ru": ("план скоростей", "плана скоростей", "плане скоростей"),
                 "vi": ("họa đồ vận tốc",), "zh": ("速度多边形",)},
    "acceleration": {"ru": ("план ускорений", "плана ускорений", "плане ускорений"),
                     "vi": ("họa đồ gia tốc",), "zh": ("加速度多边形",)},
    "force": {"ru": ("план сил", "плана сил", "плане сил"), "vi": ("họa đồ lực",),
              "zh": ("力多边形",)},
}
_CASES = {"nom": 0, "gen": 1, "loc": 2}
_TABLE = {"en": " (table)", "ru": " (таблица)", "vi": " (bảng)", "zh": "（表格）"}
_DECIMAL_COMMA = re.compile(r"\d,\d")
_SEPARATORS = {", ": {"zh": "、"}, "; ": {"zh": "；"},
               " and ": {"ru": " и ", "vi": " và ", "zh": "，且"}}


# -- texts -----------------------------------------------------------------------------------------
class Text(str):
    """A sentence of the catalogue: its English wording as a ``str``, plus its message id and
    arguments, to say it in another language with :meth:`tr`."""

    key: str
    args: dict[str, Any]

    def __new__(cls, key: str, args: dict[str, Any] | None = None) -> Self:
        args = dict(args or {})
        obj = super().__new__(cls, _render(key, args, "en"))
        obj.key = key
        obj.args = args
        return obj

    def __reduce__(self) -> tuple[Any, ...]:
        return (Text, (self.key, self.args))

    def tr(self, lang: str) -> str:
        """The text in a language (en, ru, vi, zh)."""
        return str(self) if lang == "en" else _render(self.key, self.args, lang)


def T(key: str, /, **args: Any) -> Text:
    """The catalogue's message ``key`` with its arguments."""
    if key not in MESSAGES and key not in _SPECIAL:
        raise KeyError(f"no message {key!r} in the catalogue")
    return Text(key, args)


def join(items: Iterable[Any], sep: str = ", ") -> Text:
    """Items joined by a separator said in each language (", " is "、" in Chinese)."""
    return Text("_join", {"items": list(items), "sep": sep})


def plan_title(plan: str, group: str = "", number: int = 0, table: bool = False,
               case: str = "nom") -> Text:
    """"velocity plan", "force II(2,3) plan #2", "velocity plan (table)"; in Russian in the case
    the sentence needs (nom, gen, loc)."""
    return Text("_plan", {"plan": plan, "group": group, "number": number, "table": table,
                          "case": case, "bare": False})


def plan_word(plan: str) -> Text:
    """The kind of a plan: "velocity" in English, "план скоростей" in Russian."""
    return Text("_plan", {"plan": plan, "group": "", "number": 0, "table": False,
                          "case": "nom", "bare": True})


def with_case(text: Any, case: str) -> Any:
    """A plan title in another grammatical case (other texts are returned as they are)."""
    if isinstance(text, Text) and text.key == "_plan":
        return Text("_plan", {**text.args, "case": case})
    return text


def tr(x: Any, lang: str) -> str:
    """Any report string in a language: a :class:`Text` is said again, other strings are kept."""
    if isinstance(x, Text):
        return x.tr(lang)
    return "" if x is None else str(x)


def word(group: str, value: str, lang: str) -> str:
    """A verdict, cause, finding kind, error kind or note level in a language (unknown values
    are kept as they are)."""
    entry = MESSAGES.get(f"{group}.{value}")
    return value if entry is None else entry.get(lang, entry["en"])


def capitalize(text: str) -> str:
    """First letter upper case."""
    return text[:1].upper() + text[1:]


# -- numbers ---------------------------------------------------------------------------------------
def num(value: Any, spec: str, lang: str) -> str:
    """A number formatted by a format spec with the language's decimal mark; in English exactly
    ``format(value, spec)``. A spec starting with "~" writes a number that is not finite as "?"."""
    unknown = spec.startswith("~")
    if unknown:
        spec = spec[1:]
    if isinstance(value, bool) or not hasattr(value, "__float__"):
        return format(value, spec)
    if unknown and not math.isfinite(float(value)):
        return "?"
    if lang == "en" or isinstance(value, int) and not spec:
        return format(value, spec)
    m = re.fullmatch(r"([<>^=]?)([+]?)(\d*)\.(\d+)f", spec)
    if m and math.isfinite(float(value)):
        text = format_number(float(value), int(m.group(4)), lang)
        if m.group(2) and not text.startswith("-"):
            text = "+" + text
        width = int(m.group(3) or 0)
        return text.ljust(width) if m.group(1) == "<" else text.rjust(width)
    text = format(value, spec)
    return text.replace(".", ",") if lang in ("ru", "vi") else text


def width(text: str) -> int:
    """Columns a string takes in a terminal (East Asian wide characters take two)."""
    return sum(0 if unicodedata.combining(ch) else
               2 if unicodedata.east_asian_width(ch) in ("W", "F") else 1 for ch in text)


def pad(text: str, size: int, align: str = "<") -> str:
    """A string padded to ``size`` terminal columns."""
    fill = " " * max(0, size - width(text))
    return text + fill if align == "<" else fill + text


# -- rendering -------------------------------------------------------------------------------------
class _Formatter(string.Formatter):
    def __init__(self, lang: str) -> None:
        super().__init__()
        self.lang = lang

    def format_field(self, value: Any, format_spec: str) -> str:
        lang = self.lang
        if isinstance(value, Text):
            return format(value.tr(lang), format_spec)
        if isinstance(value, (list, tuple)):
            return format(_render("_join", {"items": list(value), "sep": ", "}, lang),
                          format_spec)
        if isinstance(value, str):
            return format(value, format_spec)
        if value is None:
            return ""
        return num(value, format_spec, lang)


def _render(key: str, args: dict[str, Any], lang: str) -> str:
    if lang not in LANGUAGES:
        lang = "en"
    special = _SPECIAL.get(key)
    if special is not None:
        return special(args, lang)
    entry = MESSAGES[key]
    return _Formatter(lang).vformat(entry.get(lang) or entry["en"], (), args)


def _render_join(args: dict[str, Any], lang: str) -> str:
    sep = args.get("sep", ", ")
    items = [tr(x, lang) if isinstance(x, str) else num(x, "", lang) for x in args["items"]]
    if sep == ", " and lang in ("ru", "vi") and any(_DECIMAL_COMMA.search(x) for x in items):
        sep = "; "          # "b 0,6 мм; c 0,9 мм", not "b 0,6 мм, c 0,9 мм"
    return _SEPARATORS.get(sep, {}).get(lang, sep).join(items)


def _render_plan(args: dict[str, Any], lang: str) -> str:
    plan, group, number = args["plan"], args.get("group", ""), args.get("number", 0)
    if lang == "en" or plan not in PLAN_NAMES:
        if args.get("bare"):
            return plan
        text = f"{plan} {group}".strip() + " plan" + (f" #{number}" if number else "")
        return text + (_TABLE["en"] if args.get("table") else "")
    forms = PLAN_NAMES[plan][lang]
    text = forms[min(_CASES.get(args.get("case", "nom"), 0), len(forms) - 1)]
    if group:
        text += f" {group}"
    if number:
        text += f" #{number}"
    return text + (_TABLE[lang] if args.get("table") else "")


_SPECIAL = {"_join": _render_join, "_plan": _render_plan}
