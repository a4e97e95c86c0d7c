"""Issue 35: the errors of cam, gear, load and machine-dynamics scenes, of gear synthesis, of the
drawing frame and of the Python API are said in the user's language (``--lang`` or the scene's
``language``) with the same file and key, and say nothing in English."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from mechplan.cli import main
from mechplan.errors import MechplanError
from mechplan.i18n import catalogue

ROOT = Path(__file__).resolve().parents[2]


def _template(name: str) -> str:
    return (ROOT / "templates" / f"{name}.toml").read_text(encoding="utf-8")


#: mistake → (template, edit, key said, message id, words said in ru, in vi, English not said)
MISTAKES = {
    "swing of a translating follower": (
        "cam_cycloidal", ('stroke = "10 mm"', 'stroke = "10 mm"\nswing = "20 deg"'),
        "motion.swing", "errmsg.scene_cam.oscillating_follower_give",
        "относится к коромысловому толкателю", "dành cho cần lắc", "is for an oscillating"),
    "phases out of order": (
        "cam_cycloidal", (('{ kind = "rise", angle = "60 deg", law = "cycloidal" },\n'
                          '    { kind = "far_dwell", angle = "20 deg" },'),
                          ('{ kind = "far_dwell", angle = "20 deg" },\n'
                          '    { kind = "rise", angle = "60 deg", law = "cycloidal" },')),
        "motion.phases[0].kind", "errmsg.scene_cam.value_start_from",
        "дальнего положения (после подъёма)", "vị trí xa (sau pha đi)", "far position"),
    "impossible planetary ratio": (
        "planetary_single_row", ("ratio = 5", "ratio = 1.5"), "planetary.ratio",
        "errmsg.gears_search.no_tooth_set", "ни один набор чисел зубьев с z в пределах 17…150",
        "không có bộ số răng nào với z trong khoảng 17…150", "no tooth set"),
    "gear that cannot be cut": (
        "planetary_two_row", ("addendum = 1.0 ", "addendum = 10.0 "), "pair.addendum",
        "errmsg.synthesis_gears_involute.gear_j_z", "нельзя нарезать", "không thể cắt được",
        "cannot be cut"),
    "load at an unknown point": (
        "press_friction", ('point = "B"\nmagnitude', 'point = "Q"\nmagnitude'), "loads[0].point",
        "errmsg.scene_loads.unknown_point_point", "неизвестная точка 'Q'",
        "điểm 'Q' không xác định", "unknown point"),
    "coefficient of speed fluctuation above 1": (
        "shaper_flywheel", ('delta = "1/40"', 'delta = "2"'), "dynamics.delta",
        "errmsg.scene_dynamics.coefficient_speed_fluctuation",
        "коэффициент неравномерности хода δ", "hệ số không đều δ", "coefficient of speed"),
}


def _scene(tmp_path: Path, mistake: str) -> Path:
    template, (old, new), *_ = MISTAKES[mistake]
    text = _template(template)
    assert old in text, (template, old)
    path = tmp_path / f"{template}.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    return path


@pytest.mark.parametrize("lang", ["ru", "vi"])
@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_scene_mistakes_are_said_in_the_chosen_language(mistake, lang, tmp_path, capsys):
    _, _, key, _msgid, ru, vi, english = MISTAKES[mistake]
    path = _scene(tmp_path, mistake)
    code = main(["solve", str(path), "--lang", lang])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert str(path) in err and f"'{key}'" in err, err
    assert (ru if lang == "ru" else vi) in err, err
    assert english not in err, err


@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_english_and_json_code_are_kept(mistake, tmp_path, capsys):
    """In English the message reads as before; ``--json`` gives the message id as its code."""
    _, _, key, msgid, *_, english = MISTAKES[mistake]
    path = _scene(tmp_path, mistake)
    assert main(["solve", str(path), "--lang", "en"]) == 2
    assert english in capsys.readouterr().err
    assert main(["solve", str(path), "--json", "--lang", "zh"]) == 2
    doc = json.loads(capsys.readouterr().out)["error"]
    assert doc["code"] == msgid and doc["key"] == key
    assert english not in doc["message"] and re.search(r"[\u4e00-\u9fff]", doc["message"])


def test_drawing_frame_errors_are_said_in_russian_and_vietnamese():
    from mechplan.drafting.frame import paper_size

    with pytest.raises(MechplanError) as info:
        paper_size("A9")
    exc = info.value
    assert exc.code == "errmsg.drafting_frame.sheet_size_one"
    assert str(exc.detail).startswith("sheet size must be one of")
    assert "формат листа должен быть одним из" in exc.text("ru") and "'A9'" in exc.text("ru")
    assert "khổ bản vẽ phải là một trong" in exc.text("vi")


def test_api_errors_are_said_in_russian_and_vietnamese():
    from mechplan import api

    with pytest.raises(MechplanError) as info:
        api.loads(42)                       # type: ignore[arg-type]
    exc = info.value
    assert exc.code == "errmsg.api.scene_toml_text" and "must be TOML text" in str(exc)
    assert "сцена должна быть текстом TOML" in exc.text("ru")
    assert "cảnh phải là văn bản TOML" in exc.text("vi") and "must be" not in exc.text("vi")


def test_every_errmsg_id_is_in_every_language_with_its_placeholders():
    """The errmsg area is complete (the catalogue test checks the placeholders of all areas)."""
    ids = {k for k in catalogue("en") if k.startswith("errmsg.")}
    assert len(ids) > 150
    for lang in ("ru", "vi", "zh"):
        said = catalogue(lang)
        assert ids <= set(said), lang
        same = [k for k in ids if said[k] == catalogue("en")[k] and re.search(r"[a-z]{4}", said[k])]
        assert not same, (lang, same)           # no English left untranslated


def test_toml_limit_reason_is_a_catalogue_text():
    """The reason a scene's TOML is refused (a number of thousands of digits) keeps its message id
    and arguments, so a reader of the limit error can say it in the user's language."""
    from mechplan.scene import toml

    with pytest.raises(toml.TomlLimitError) as info:
        toml.loads("a = " + "9" * 5000)
    reason = info.value.args[0]
    assert "numbers this large cannot be computed exactly" in str(reason)
    assert "столь большие числа нельзя вычислить точно" in reason.tr("ru")
    assert "số lớn như vậy không thể tính chính xác" in reason.tr("vi")


def test_gear_tooth_list_of_wrong_length_in_russian(tmp_path, capsys):
    path = tmp_path / "g.toml"
    path.write_text(_template("planetary_single_row").replace("teeth = [17, 150]", "teeth = [17]"),
                    encoding="utf-8")
    assert main(["solve", str(path), "--lang", "ru"]) == 2
    err = capsys.readouterr().err
    assert "ключ 'planetary.teeth'" in err and "должно быть списком из 2 целых чисел" in err, err
    assert main(["solve", str(path)]) == 2          # the scene's language: English
    assert "must be a list of 2 whole numbers (got [17])" in capsys.readouterr().err
