"""Gear scenes: parsing errors name the key; the study reports, serialises and draws."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from mechplan.errors import SceneError
from mechplan.i18n import LANGUAGES
from mechplan.sheet.primitives import Polyline, Text
from mechplan.studies import solve_file, solve_text

TEMPLATES = Path(__file__).resolve().parents[2] / "templates"

SCENE = """
kind = "gears"
title = "t"
[planetary]
scheme = "{scheme}"
fixed = "4"
input = "1"
output = "h"
ratio = {ratio}
planets = {k}
module = "{module}"
teeth = [17, 60]
[ordinary]
module = "3 mm"
ratio = 2
[pair]
shift_rule = "no_undercut"
"""


def scene(**kw) -> str:
    values = {"scheme": "two_row_ext_int", "ratio": 4, "k": 4, "module": "2 mm"}
    values.update(kw)
    return SCENE.format(**values)


@pytest.mark.parametrize(("kw", "key", "words"), [
    ({"module": "0 mm"}, "planetary.module", "positive"),
    ({"scheme": "three_row"}, "planetary.scheme", "single_row"),
    ({"ratio": 500}, "planetary.ratio", "nearest"),
    ({"k": 3, "ratio": 4}, None, None),
    ({"k": 0}, "planetary.planets", "at least 1"),
])
def test_errors_name_the_key(kw, key, words):
    if key is None:
        assert solve_text(scene(**kw), "s.toml").to_json()["planetary"]["chosen"]["valid"]
        return
    with pytest.raises(SceneError) as err:
        solve_text(scene(**kw), "s.toml")
    assert err.value.key == key and err.value.file == "s.toml"
    assert words in str(err.value)


def test_wrong_links():
    text = scene().replace('fixed = "4"', 'fixed = "3"')
    with pytest.raises(SceneError) as err:
        solve_text(text, "s.toml")
    assert err.value.key == "planetary.fixed"


def test_ordinary_stage_chosen_for_its_ratio_and_drawn_as_the_pair():
    doc = solve_text(scene(), "s.toml").to_json()
    assert (doc["ordinary"]["z5"], doc["ordinary"]["z6"]) == (17, 34)
    assert doc["ordinary"]["total_ratio"] == pytest.approx(4.0 * -2.0)
    assert doc["pair"]["z"] == [17, 34]


def test_worked_example_template():
    study = solve_file(TEMPLATES / "planetary_two_row.toml")
    doc = json.loads(json.dumps(study.to_json()))
    p = doc["planetary"]
    assert p["chosen"]["z"] == [17, 17, 17, 51] and p["chosen"]["valid"]
    assert p["ratio_from_velocity_plan"] == pytest.approx(4.0)
    assert p["omega_rad_s"]["1"] == pytest.approx(1500 * 2 * math.pi / 60)
    assert p["omega_rad_s"]["h"] == pytest.approx(1500 * 2 * math.pi / 60 / 4)
    assert doc["ordinary"]["z5"] == 17 and doc["ordinary"]["z6"] == 34
    assert abs(doc["ordinary"]["total_ratio"]) == pytest.approx(8.0)
    ru = study.report("ru")
    assert "выполнено" in ru and "z4 = 51" in ru and "4,0000" in ru
    for lang in LANGUAGES:
        assert "17, 17, 17, 51" in study.report(lang).replace("z1 = 17, z2 = 17, z3 = 17, z4 = 51",
                                                             "17, 17, 17, 51")


def test_sheet_has_every_part():
    study = solve_file(TEMPLATES / "planetary_two_row.toml")
    sheets = study.sheets("A1", "iso", "en", "planetary_two_row")
    texts = " ".join(p.string for s in sheets for p in s.primitives if isinstance(p, Text))
    for words in ("Kinematic diagram", "Velocity plan", "Angular velocity plan",
                  "Synthesis of the planetary train", "Meshing of the involute pair", "trochoids",
                  "μv", "μl", "μω", "N1", "B2"):
        assert words in texts, words
    assert sum(isinstance(p, Polyline) for s in sheets for p in s.primitives) > 20


def test_angular_plan_reads_the_ratio():
    study = solve_file(TEMPLATES / "planetary_two_row.toml")
    sheets = study.sheets("A1", "iso", "en", "x")
    texts = [p.string for s in sheets for p in s.primitives if isinstance(p, Text)]
    read = [t for t in texts if t.startswith("u_1h = ")]
    assert read and read[0].endswith("= 4.0000")


def test_given_set_is_checked_and_its_failures_shown():
    text = scene(k=3).replace("teeth = [17, 60]", "teeth = [17, 60]\ngiven = [17, 17, 17, 51]")
    study = solve_text(text, "s.toml")
    chosen = study.to_json()["planetary"]["chosen"]
    assert chosen["z"] == [17, 17, 17, 51] and not chosen["valid"]
    assert chosen["assembly_p"] is None and chosen["neighbour_ok"]    # 68/3 never an integer
    report = study.report("en")
    assert "assembly" in report and "— fails" in report


def test_output_shaft_drives_the_ordinary_pair():
    doc = solve_file(TEMPLATES / "planetary_two_row.toml").to_json()
    w_h = doc["planetary"]["omega_rad_s"]["h"]
    assert doc["ordinary"]["omega_rad_s"]["5"] == pytest.approx(w_h)
    assert doc["ordinary"]["omega_rad_s"]["6"] == pytest.approx(-w_h * 17 / 34)


def test_cli_solve_json_and_error_exit(capsys, tmp_path):
    from mechplan.cli import main

    assert main(["solve", str(TEMPLATES / "planetary_single_row.toml"), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["kind"] == "gears" and doc["planetary"]["chosen"]["valid"]
    bad = tmp_path / "bad.toml"
    bad.write_text(scene(module="0 mm"), encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    assert "planetary.module" in capsys.readouterr().err
