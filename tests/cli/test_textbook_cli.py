"""`mechplan solve --answers … --pin-radius …`: the textbook answers from the command line."""

from __future__ import annotations

import json
import math
from pathlib import Path

from mechplan.cli import main

ROOT = Path(__file__).resolve().parents[2]


def test_answers_and_pin_radius_in_json(capsys):
    code = main(["solve", str(ROOT / "templates" / "quick_return.toml"), "--at", "90",
                 "--answers", "stroke,rubbing", "--pin-radius", "10", "--json"])
    out, _ = capsys.readouterr()
    assert code == 0
    doc = json.loads(out)
    st = doc["textbook"]["strokes"]["3"]
    # crank–coulisse r = 100 mm, O1O3 = 300 mm: ψ = 2 asin(1/3), θ_r = 2 acos(1/3)
    assert math.isclose(st["swing_deg"], math.degrees(2 * math.asin(1 / 3)), rel_tol=1e-12)
    tr = 2 * math.acos(1 / 3)
    assert math.isclose(st["K"], (2 * math.pi - tr) / tr, rel_tol=1e-10)
    rub = doc["positions"][0]["textbook"]["rubbing"]
    # φ = 90° from the drive's reference: A right above O1, O3A = 0.4 m ⊥ v_A, ω3 = 1/0.4
    w3 = abs(doc["positions"][0]["links"]["3"]["omega"])
    assert math.isclose(rub["O3"]["v_rub"], 0.01 * w3, rel_tol=1e-12)
    assert set(doc["positions"][0]["textbook"]) == {"rubbing"}


def test_report_in_chinese(capsys):
    code = main(["solve", str(ROOT / "templates" / "four_bar.toml"), "--at", "30",
                 "--answers", "all", "--pin-radius", "5", "--lang", "zh"])
    out, _ = capsys.readouterr()
    assert code == 0
    assert "教材答案" in out and "最小传动角" in out and "K = " in out


def test_rubbing_without_radius_and_answers_of_a_cam_are_errors(capsys):
    code = main(["solve", str(ROOT / "templates" / "four_bar.toml"), "--at", "30",
                 "--answers", "rubbing"])
    _, err = capsys.readouterr()
    assert code == 2 and "--pin-radius" in err
    code = main(["solve", str(ROOT / "templates" / "four_bar.toml"), "--answers", "speed"])
    _, err = capsys.readouterr()
    assert code == 2 and "--answers" in err
    code = main(["solve", str(ROOT / "templates" / "cam_flat.toml"), "--answers", "all",
                 "--lang", "en"])
    _, err = capsys.readouterr()
    assert code == 2 and "linkage" in err
    # without --lang the error is said in the scene's language (issue 35)
    code = main(["solve", str(ROOT / "templates" / "cam_flat.toml"), "--answers", "all"])
    _, err = capsys.readouterr()
    assert code == 2 and "--answers" in err and "another kind of scene" not in err


def test_the_answer_key_of_a_class_lists_the_sliding_and_rubbing_velocities():
    from mechplan.batch.answer import answer_key
    from mechplan.scene import parse_scene
    from mechplan.solve import solve, to_json
    text = (ROOT / "templates" / "quick_return.toml").read_text(encoding="utf-8")
    sol = solve(parse_scene(text + '\n[answers]\npin_radius = "10 mm"\n', "qr.toml"),
                at_deg=[30.0, 120.0])
    doc = to_json(sol)
    key = answer_key(doc, "01", "student", {})
    rows = {r["quantity"]: r["values"] for r in key["rows"]}
    assert rows["v_rel A/slot"] == [p["textbook"]["sliding"]["A/slot"]["v_slide"]
                                    for p in doc["positions"]]
    assert rows["v_rub O3"][1] == doc["positions"][1]["textbook"]["rubbing"]["O3"]["v_rub"]
    assert key["solution"]["textbook"]["strokes"]["3"]["K"] > 1.5
