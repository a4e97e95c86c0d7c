"""Reports in en / ru / vi / zh: the glossary's words, decimal commas in ru and vi, codes kept."""

from __future__ import annotations

import argparse
import json
import re
import string
from pathlib import Path

import numpy as np
import pytest

from mechplan.check import Options, check
from mechplan.check.overlay import marks
from mechplan.check.report import CARRIED, NEW, SLIP, WRONG
from mechplan.check.texts import LANGUAGES, T, tr
from mechplan.cli.check import add_parser
from mechplan.i18n import catalogue, num
from mechplan.model.plans import Plan

from .sheets import TEMPLATES, PlanSpec, exact_sheet, move, solved, write_dxf

#: what each language must say about a table with one wrong segment (pc) and one slip (v_E)
WORDS = {
    "en": ["result: FAILED", "## Velocity plan (table): μ = 0.01 (m/s)/mm",
           "tolerance ±1 mm or ±2 %",
           "segment", "quantity", "verdict", "WRONG (new)", "WRONG (carried)", "SLIP",
           "## Values", "## Findings (root causes)", "[wrong segment] velocity plan (table): pc:",
           "[arithmetic slip] velocity: v_E: arithmetic slip:", "is 3.0 mm too long",
           "follows from your own drawing"],
    "ru": ["итог: НЕ ЗАЧТЕНО", "## План скоростей (таблица): μ = 0,01 (м/с)/мм",
           "допуск ±1 мм или ±2 %", "= 0,599 м/с, а записано v_E", "отрезок", "величина",
           "оценка", "НЕВЕРНО (новая ошибка)",
           "НЕВЕРНО (перенесена)", "ОШИБКА СЧЁТА", "## Величины", "## Найденные ошибки",
           "[неверный отрезок] план скоростей (таблица): pc:",
           "[арифметическая ошибка] план скоростей: v_E: арифметическая ошибка:",
           "pc длиннее на 3,0 мм", "следует из вашего же чертежа", "точка пересечения прямых"],
    "vi": ["kết quả: KHÔNG ĐẠT", "## Họa đồ vận tốc (bảng): μ = 0,01 (m/s)/mm",
           "dung sai ±1 mm hoặc ±2 %", "đoạn", "đại lượng", "kết luận", "SAI (lỗi mới)",
           "SAI (kéo theo)", "TÍNH SAI", "## Giá trị", "## Các lỗi phát hiện",
           "[đoạn sai] họa đồ vận tốc (bảng): pc:",
           "[lỗi tính toán] họa đồ vận tốc: v_E: lỗi tính toán:", "pc dài hơn 3,0 mm",
           "suy ra từ chính hình vẽ của bạn", "giao điểm của các đường"],
    "zh": ["结果：未通过", "## 速度多边形（表格）：μ = 0.01 (m/s)/mm", "允许误差 ±1 mm 或 ±2 %",
           "线段", "物理量", "结论", "错误（新出现）", "错误（传递）", "计算错误", "## 数值",
           "## 发现的问题", "[线段错误] 速度多边形（表格）：pc：",
           "[计算错误] 速度多边形：v_E：计算错误：", "pc 长了 3.0 mm", "与你自己的作图一致",
           "的交点"],
}
#: English that must not be left in a translated report
ENGLISH = ["result:", "FAILED", "WRONG", "SLIP", "segment", "verdict", "tolerance", "Findings",
           "Values", "arithmetic", "carried", "follows", "plan", "too long", "read from", "line"]


def _exact(sol, name: str) -> float:
    c, ev = sol.construction, sol.ev
    seg = next(s for s in c.segments if s.name == name)
    return float(np.hypot(*(ev[seg.end][0] - ev[seg.start][0])))


@pytest.fixture(scope="module")
def table(tmp_path_factory) -> tuple[Path, dict[str, float]]:
    """pb, bc right; pc 3 mm too long (and v_C from it: carried); pe right but v_E ≠ pe × μ."""
    _scene, sol = solved("four_bar", 60)
    mm = {n: _exact(sol, n) / 0.01 for n in ("pb", "bc", "pc", "pe")}
    path = tmp_path_factory.mktemp("lang") / "t.toml"
    path.write_text(f"""
at = "60 deg"
[scales]
mu_v = "0.01 m/s/mm"
[velocity]
pb = {mm['pb']:.1f}
bc = {mm['bc']:.1f}
pc = "{mm['pc'] + 3:.1f} mm → {(mm['pc'] + 3) * 0.01:.3f} m/s"
pe = {{ mm = {mm['pe']:.1f}, value = "{mm['pe'] * 0.01 * 1.2:.3f} m/s" }}
""", encoding="utf-8")
    return path, mm


@pytest.fixture(scope="module")
def report(table):
    return check(TEMPLATES / "four_bar.toml", table[0], Options())


def test_the_table_has_one_wrong_segment_and_one_slip(report) -> None:
    rows = {s.name: s for p in report.plans for s in p.segments}
    values = {v.name: v for v in report.values}
    assert rows["pc"].verdict == WRONG and rows["pc"].cause == NEW
    assert values["v_E"].verdict == SLIP
    assert values["v_C"].verdict == WRONG and values["v_C"].cause == CARRIED
    assert {(f.kind, f.subject) for f in report.findings} == {("wrong segment", "pc"),
                                                              ("arithmetic slip", "v_E")}


@pytest.mark.parametrize("lang", LANGUAGES)
def test_report_in_each_language(report, table, lang: str) -> None:
    text = report.text(lang)
    for words in WORDS[lang]:
        assert words in text, (lang, words, text)
    # symbols and labels are the same in every language
    for symbol in ("pb", "bc", "pc", "pe", "v_B", "v_C", "v_E", "μ", "⊥BC", "⊥DC", "m/s"):
        assert symbol in text, (lang, symbol)
    drawn_pc = f"{table[1]['pc'] + 3:.1f}"
    # units follow the language, as on the sheets: "м/с" in Russian
    slip = re.search(r"v_E.*?(\d+[.,]\d) (?:mm|мм) × 0[.,]01 = (\d[.,]\d+) (?:m/s|м/с)", text)
    assert slip is not None, text
    if lang in ("ru", "vi"):
        assert drawn_pc.replace(".", ",") in text
        assert "," in slip.group(1) and "," in slip.group(2)
        assert "× 0,01 =" in text and "× 0.01 =" not in text
        assert re.search(r"\+\d+,\d\b", text)            # errors: "+3,0", "+5,4"
    else:
        assert drawn_pc in text
        assert "." in slip.group(1) and "× 0.01 =" in text
        assert not re.search(r"\d,\d", text)
    if lang != "en":
        # only the student's own writing (quoted) and the file names stay as they were
        body = re.sub(r"'[^']*'|\S+\.toml", "", text)
        left = [w for w in ENGLISH if re.search(rf"\b{re.escape(w)}\b", body)]
        assert not left, (lang, left, text)


def test_english_is_the_default_and_unchanged(report) -> None:
    text = report.text()
    assert text == report.text("en")
    lines = text.splitlines()
    assert lines[0].startswith("mechplan check: ") and lines[1].startswith("scene: ")
    assert lines[2] == "crank angle φ = 60.00° (read from 'at = 60 deg' (t.toml line 2))"
    assert lines[3] == ("result: FAILED — 6 checked, 3 ok, 2 wrong (1 new, 1 carried, 0 by swapped "
                        "labels, 0 by small errors adding up), 1 arithmetic slip(s), 0 not on the "
                        "submission")
    assert ("   segment       quantity     drawn mm exact mm  err mm   err %  dir °  verdict"
            in lines)
    # the report's own fields stay English, whatever language it is written in
    vc = next(v for v in report.values if v.name == "v_C")
    assert vc.hint.startswith("follows from your own drawing (")
    assert report.findings[0].message.startswith("pc is 3.0 mm too long: ")


@pytest.mark.parametrize("lang", LANGUAGES)
def test_json_codes_stay_and_sentences_are_translated(report, lang: str) -> None:
    doc = json.loads(json.dumps(report.to_json(lang), ensure_ascii=False))
    assert doc["lang"] == lang
    plan = doc["plans"][0]
    assert plan["name"] == "velocity plan (table)" and plan["plan"] == "velocity"
    pc = next(s for s in plan["segments"] if s["name"] == "pc")
    assert pc["verdict"] == "wrong" and pc["cause"] == "new"
    vals = {v["name"]: v for v in doc["values"]}
    assert vals["v_E"]["verdict"] == "slip"
    assert [f["kind"] for f in doc["findings"]] == ["wrong segment", "arithmetic slip"]
    assert doc["summary"]["wrong"] == 2 and doc["summary"]["slip"] == 1
    expected = {"en": ("velocity plan (table)", "WRONG (new)", "wrong segment", "arithmetic slip:"),
                "ru": ("план скоростей (таблица)", "НЕВЕРНО (новая ошибка)", "неверный отрезок",
                       "арифметическая ошибка:"),
                "vi": ("họa đồ vận tốc (bảng)", "SAI (lỗi mới)", "đoạn sai", "lỗi tính toán:"),
                "zh": ("速度多边形（表格）", "错误（新出现）", "线段错误", "计算错误：")}[lang]
    assert plan["title"].lower() == expected[0].lower()
    assert pc["verdict_text"] == expected[1]
    assert doc["findings"][0]["kind_text"] == expected[2]
    assert vals["v_E"]["hint"].startswith(expected[3])
    if lang in ("ru", "vi"):
        assert "× 0,01 =" in vals["v_E"]["hint"]
    else:
        assert "× 0.01 =" in vals["v_E"]["hint"]


def _main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="mechplan")
    add_parser(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args(argv)
    return int(args.func(args))


def test_cli_lang_option_and_the_scene_language(table, tmp_path: Path, capsys) -> None:
    scene_en = TEMPLATES / "four_bar.toml"
    assert _main(["check", str(scene_en), str(table[0])]) == 1
    assert "result: FAILED" in capsys.readouterr().out
    assert _main(["check", str(scene_en), str(table[0]), "--lang", "vi"]) == 1
    assert "kết quả: KHÔNG ĐẠT" in capsys.readouterr().out
    scene_ru = tmp_path / "four_bar_ru.toml"
    scene_ru.write_text(scene_en.read_text(encoding="utf-8").replace('language = "en"',
                                                                     'language = "ru"'),
                        encoding="utf-8")
    out_json = tmp_path / "r.json"
    assert _main(["check", str(scene_ru), str(table[0]), "-o", str(out_json)]) == 1
    captured = capsys.readouterr()
    assert "итог: НЕ ЗАЧТЕНО" in captured.out and "записан файл" in captured.err
    doc = json.loads(out_json.read_text(encoding="utf-8"))
    assert doc["lang"] == "ru" and doc["result_text"] == "НЕ ЗАЧТЕНО"
    assert _main(["check", str(scene_ru), str(table[0]), "--lang", "en"]) == 1
    assert "result: FAILED" in capsys.readouterr().out
    with pytest.raises(SystemExit):
        _main(["check", str(scene_en), str(table[0]), "--lang", "de"])


@pytest.mark.parametrize("lang", LANGUAGES)
def test_drawn_sheet_hints_and_overlay(tmp_path: Path, lang: str) -> None:
    scene, sol = solved("four_bar", 60)
    specs = {Plan.VELOCITY: PlanSpec(0.01, (50, 50), "μv = 0,01 m/s/mm")}
    st = exact_sheet(sol, specs)
    move(st, Plan.VELOCITY, "c", (3.0, -4.0))
    path = write_dxf(tmp_path / "bad.dxf", sol, specs, st)
    report = check(scene, path, Options(at_deg=60))
    text = report.text(lang)
    said = {"en": ("[wrong point] velocity plan: c:", "must lie on the line through b ⊥BC",
                   "from your own earlier points"),
            "ru": ("[неверная точка] план скоростей: c:", "должна лежать на прямой ⊥BC через b",
                   "по вашим же предыдущим точкам"),
            "vi": ("[điểm sai] họa đồ vận tốc: c:", "phải nằm trên đường thẳng ⊥BC qua b",
                   "theo chính các điểm trước đó của bạn"),
            "zh": ("[点的位置错误] 速度多边形：c：", "必须位于过 b 的直线 ⊥BC 上",
                   "按你自己前面的各点")}[lang]
    for words in said:
        assert words in text, (lang, words, text)
    notes = [m.text for m in marks(report, lang) if m.layer in ("ERRORS", "NOTES") and m.text]
    legend = {"en": "blue: submission", "ru": "синий: работа", "vi": "xanh lam: bài làm",
              "zh": "蓝色：作业"}[lang]
    assert any(legend in t for t in notes)
    errors = [t for t in notes if t.startswith(("pc ", "bc "))]
    assert errors
    mm = "мм" if lang == "ru" else "mm"
    mark = "," if lang in ("ru", "vi") else "."
    assert all(re.search(rf"[+-]\d+{re.escape(mark)}\d {mm}", t) for t in errors), errors
    if lang == "en":
        assert [m.text for m in marks(report)] == [m.text for m in marks(report, "en")]


def test_catalogue_is_complete() -> None:
    fields = string.Formatter()
    ids = {lang: {k: t for k, t in catalogue(lang).items() if k.startswith("check.")}
           for lang in LANGUAGES}
    assert len(ids["en"]) > 200
    for key, text in ids["en"].items():
        names = {f for _, f, _, _ in fields.parse(text) if f}
        for lang in LANGUAGES:
            assert key in ids[lang], (key, lang)
            assert {f for _, f, _, _ in fields.parse(ids[lang][key]) if f} == names, (key, lang)
            assert ids[lang][key].strip(), (key, lang)


def test_numbers_and_texts() -> None:
    assert num(3.14159, ".2f", "ru") == "3,14" and num(3.14159, ".2f", "zh") == "3.14"
    assert num(-0.04, "+8.1f", "vi") == "    +0,0" and num(-0.04, "+8.1f", "en") == "    -0.0"
    assert num(0.000123, ".4g", "ru") == "0,000123" and num(float("nan"), "~.1f", "vi") == "?"
    t = T("brief.long", name="pc", err=3.04)
    assert t == "pc is 3.0 mm too long" and tr(t, "ru") == "pc длиннее на 3,0 мм"
    assert tr("pb", "zh") == "pb"
