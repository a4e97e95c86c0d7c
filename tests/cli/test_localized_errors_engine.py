"""Issue 35: the errors of an engine scene and of a note project are said in the user's language
(``--lang``) with the same file and key, and say nothing in English; in English they read as
before, and ``--json`` gives the message id as the error's code."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from mechplan.cli import main
from mechplan.errors import SceneError

ROOT = Path(__file__).resolve().parents[2]

#: mistake → (edit of the in-line four, key said, message id, words in ru, in vi, English said)
MISTAKES = {
    "cylinder count out of range": (
        ("cylinders = 4", "cylinders = 30"), "engine.cylinders", "errmsg3.engine.cylinders",
        "должно быть целым числом от 1 до 24 (получено 30)",
        "phải là số nguyên từ 1 đến 24 (nhận được 30)",
        "must be a whole number from 1 to 24 (got 30)"),
    "rod shorter than the crank": (
        ('rod_length = "136 mm"', 'rod_length = "30 mm"'), "engine.rod_length",
        "errmsg3.engine.rod_short",
        "шатун должен быть длиннее радиуса кривошипа",
        "thanh truyền phải dài hơn bán kính tay quay",
        ("λ = R/L must be less than 1 (got λ = 1.33333); "
         "the rod must be longer than the crank radius")),
    "peak pressure below the end of compression": (
        ('p_z = "6.5 MPa"', 'p_z = "1 MPa"'), "indicator.p_z", "errmsg3.engine.p_z_low",
        "максимальное давление не может быть ниже давления конца сжатия",
        "áp suất cực đại không được nhỏ hơn áp suất cuối kỳ nén", "the peak pressure must not be"),
}


def _scene(tmp_path: Path, mistake: str) -> Path:
    (old, new), *_ = MISTAKES[mistake]
    text = (ROOT / "templates" / "inline_four_engine.toml").read_text(encoding="utf-8")
    assert old in text, old
    path = tmp_path / "engine.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    return path


@pytest.mark.parametrize("lang", ["ru", "vi"])
@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_engine_mistakes_are_said_in_the_chosen_language(mistake, lang, tmp_path, capsys):
    _, key, _msgid, ru, vi, english = MISTAKES[mistake]
    path = _scene(tmp_path, mistake)
    code = main(["solve", str(path), "--lang", lang])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert str(path) in err and f"'{key}'" in err, err
    said = ru if lang == "ru" else vi
    assert said.split(" (got")[0] in err, err
    assert english.split(" (got")[0] not in err, err


@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_engine_english_and_json_code_are_kept(mistake, tmp_path, capsys):
    _, key, msgid, *_, english = MISTAKES[mistake]
    path = _scene(tmp_path, mistake)
    assert main(["solve", str(path), "--lang", "en"]) == 2
    assert english in capsys.readouterr().err
    assert main(["solve", str(path), "--json", "--lang", "zh"]) == 2
    doc = json.loads(capsys.readouterr().out)["error"]
    assert doc["code"] == msgid and doc["key"] == key
    assert re.search(r"[\u4e00-\u9fff]", doc["message"])


def test_project_errors_are_said_in_russian_and_vietnamese(tmp_path):
    from mechplan.note.project import read_project

    path = tmp_path / "project.toml"
    path.write_text('[project]\ntitle = "x"\nlanguage = "fr"\n[studies]\n'
                    'engine = "engine.toml"\n', encoding="utf-8")
    with pytest.raises(SceneError) as info:
        read_project(path)
    exc = info.value
    assert exc.code == "errmsg3.project.language" and exc.key == "project.language"
    assert str(exc.detail) == "project.language must be one of en, ru, vi, zh (got 'fr')"
    assert "project.language должен быть одним из en, ru, vi, zh (получено 'fr')" in exc.text("ru")
    assert "phải là một trong en, ru, vi, zh (nhận được 'fr')" in exc.text("vi")
