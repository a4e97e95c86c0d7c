"""Answer tables of a linkage's textbook answers (K, H, ψ, θ, γ_min, v_slide, a_k, v_rub …):
names in the four traditions are read, right values pass, planted mistakes are found.

Exact values come from closed forms computed here: the crank–coulisse with r = 100 mm,
O1O3 = 300 mm gives ψ = 2·asin(r/d), θ_r = 2·acos(r/d), K = θ_w/θ_r; γ = 90° (centred slot);
the offset slider-crank's stroke and K as in tests/construct/test_textbook.py."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from mechplan.check import check
from mechplan.check.answers import maybe_check_answers

QR = """
title = "Crank-coulisse"
[ground]
O1 = ["0 mm", "0 mm"]
O3 = ["0 mm", "-300 mm"]
[links.1]
lengths = { O1A = "100 mm" }
[links.2]
slides = { point = "A", on = "slot" }
[links.3]
lengths = { O3B = "600 mm" }
guides.slot = { through = "O3", toward = "B" }
[drive]
link = "1"
speed = "10 rad/s"
[positions]
at = ["90 deg"]
[answers]
pin_radius = "10 mm"
"""

SC = """
[ground]
O = ["0 mm", "0 mm"]
G = ["0 mm", "50 mm"]
Y = ["0 mm", "1000 mm"]
guides.x = { through = "G", angle = "0 deg" }
[links.1]
lengths = { OA = "100 mm" }
[links.2]
lengths = { AB = "350 mm" }
[links.3]
slides = { point = "B", on = "x" }
[drive]
link = "1"
speed = "10 rad/s"
[assembly]
B = "right of O->Y"
[positions]
at = ["90 deg"]
[answers]
ask = ["stroke", "transmission", "relative"]
"""


def _files(tmp_path: Path, scene: str, table: str, suffix: str = ".toml") -> tuple[Path, Path]:
    s, t = tmp_path / "scene.toml", tmp_path / f"answers{suffix}"
    s.write_text(scene, encoding="utf-8")
    t.write_text(table, encoding="utf-8")
    return s, t


def _qr_exact() -> dict[str, float]:
    r, d = 0.1, 0.3
    tr = 2 * math.acos(r / d)
    # at φ = 90° (A straight above O1): O3A = 0.4 m along the slot, A moves ⊥ O1A at 1 m/s,
    # which is ⊥ the slot, so v_rel = 0, ω3 = 1/0.4 and the Coriolis part vanishes
    return {"psi": math.degrees(2 * math.asin(r / d)), "tw": 360 - math.degrees(tr),
            "tr": math.degrees(tr), "K": (2 * math.pi - tr) / tr,
            "v_rub_O3": 0.01 * 1 / 0.4, "v_rub_A": 0.01 * (10 - 2.5)}


def test_right_answers_in_russian_names_pass(tmp_path):
    e = _qr_exact()
    s, t = _files(tmp_path, QR, f"""
Kv = "{e['K']:.4f}"
"ψ" = "{e['psi']:.2f}°"
"φр" = "{e['tw']:.2f} deg"
"φх" = "{e['tr']:.2f} deg"
"γmin" = "90°"
["φ = 90°"]
"vотн" = "0 m/s"
"aкор" = "0 m/s^2"
"vтр O3" = "{e['v_rub_O3']:.5f} m/s"
"vтр_A" = "{e['v_rub_A']:.5f} m/s"
"γ" = "90 deg"
""")
    report = check(str(s), str(t))
    rows = {v.name: v for v in report.values}
    assert len(rows) == 10
    assert all(v.verdict == "ok" for v in rows.values()), [
        (v.name, v.submitted, v.exact) for v in rows.values() if v.verdict != "ok"]
    assert rows["Kv"].exact == pytest.approx(e["K"], rel=1e-9)
    assert rows["vтр O3 (90°)"].exact == pytest.approx(e["v_rub_O3"], rel=1e-9)


def test_planted_mistakes_are_found_with_their_cause(tmp_path):
    e = _qr_exact()
    s, t = _files(tmp_path, QR, f"""
K = "{(e['tw'] + 10) / (e['tr'] - 10):.4f}"
"θw" = "{e['tw'] + 10:.2f} deg"
"θr" = "{e['tr'] - 10:.2f} deg"
"ψ" = "{e['psi'] * 2:.2f} deg"
""")
    rows = {v.name: v for v in check(str(s), str(t)).values}
    assert rows["ψ"].verdict == "wrong" and rows["ψ"].cause == "new"
    assert rows["θw"].verdict == "wrong"
    assert rows["K"].verdict == "wrong" and rows["K"].cause == "carried"


def test_arithmetic_slip_in_K_from_own_angles(tmp_path):
    e = _qr_exact()
    s, t = _files(tmp_path, QR, f"""
"θw" = "{e['tw']:.2f} deg"
"θr" = "{e['tr']:.2f} deg"
K = "1.9"
""")
    rows = {v.name: v for v in check(str(s), str(t)).values}
    assert rows["K"].verdict == "slip"


def test_slider_crank_stroke_K_and_chinese_english_names(tmp_path):
    r, l, e = 0.1, 0.35, 0.05
    H = math.sqrt((l + r) ** 2 - e ** 2) - math.sqrt((l - r) ** 2 - e ** 2)
    th = math.asin(e / (l - r)) - math.asin(e / (l + r))
    K = (math.pi + th) / (math.pi - th)
    s, t = _files(tmp_path, SC, f"""name, value, unit
行程, {H * 1000:.3f}, mm
行程速比系数, {K:.4f},
极位夹角, {math.degrees(th):.3f}, deg
TR, {K:.4f},
""", ".csv")
    rows = {v.name: v for v in check(str(s), str(t)).values}
    assert {v.verdict for v in rows.values()} == {"ok"}, rows
    assert rows["行程"].exact == pytest.approx(H, rel=1e-12)


def test_a_linkage_without_answers_and_a_drawing_are_not_answer_tables(tmp_path):
    s, t = _files(tmp_path, QR.replace('[answers]\npin_radius = "10 mm"\n', ""), 'K = "1.5"\n')
    assert maybe_check_answers(str(s), str(t)) is None
    s, t = _files(tmp_path, QR, "", ".dxf")
    assert maybe_check_answers(str(s), str(t)) is None


def test_where_the_transmission_angle_is_least(tmp_path):
    """Offset slider-crank: γ_min = 90° − asin((r + e)/l) with the crank ⊥ the guide, pointing
    away from it (φ = 270° when the guide is above the crank's pivot)."""
    s, t = _files(tmp_path, SC, f"""
"γmin" = "{90 - math.degrees(math.asin(0.15 / 0.35)):.3f} deg"
"φ_γmin" = "270 deg"
""")
    rows = {v.name: v for v in check(str(s), str(t)).values}
    assert rows["φ_γmin"].verdict == "ok" and rows["γmin"].verdict == "ok"
    assert rows["φ_γmin"].exact == pytest.approx(270.0, abs=1e-6)
