"""Issue 35: the ten mistakes students make most, said in their language (``--lang`` or the
scene's ``language``), with the file and key as before, no traceback, exit code 2; with
``--json`` the error is an object with a stable code."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mechplan.cli import main
from mechplan.i18n import catalogue

ROOT = Path(__file__).resolve().parents[2]
TEMPLATE = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")

#: mistake → (edit of the template, the message id it must be said with)
MISTAKES = {
    "bad unit": (("\"80 mm\"", "\"80 kg\""), "errors.units.wrong_dimension"),
    "no unit": (("\"80 mm\"", "80"), "errors.units.needs_unit"),
    "unreadable number": (("\"80 mm\"", "\"8,0,1 mm\""), "errors.units.two_marks"),
    "unknown key": (("sense = \"ccw\"", "sence = \"ccw\""), "errors.key.unknown_close"),
    "missing key": (("link = \"1\"\n", ""), "errors.key.missing"),
    "wrong choice": (("sense = \"ccw\"", "sense = \"left\""), "errors.key.one_of"),
    "bad TOML": (("[drive]", "[drive"), "errors.toml.invalid"),
    "unknown kind": (("title =", "kind = \"robot\"\ntitle ="), "errors.scene.kind"),
    "unreachable": (("AB = \"80 mm\"", "AB = \"200 mm\""), "errors.unreachable"),
}
#: more for a mistake: the crank is too long to close at φ = 0 (assembled at 90°)
ARGS = {"unreachable": ["--at", "0"]}
EDITS = {"unreachable": ('C = "left of B->D"', 'C = "left of B->D"\nat = "90 deg"')}


def _fixed_words(msgid: str, lang: str) -> list[str]:
    """The words of a message's text outside its placeholders (what the user must read)."""
    text = catalogue(lang)[msgid]
    parts, depth, word = [], 0, ""
    for ch in text:
        if ch == "{":
            depth += 1
            parts.append(word)
            word = ""
        elif ch == "}":
            depth -= 1
        elif depth == 0:
            word += ch
    parts.append(word)
    stripped = (p.strip(" ;:,()'«»（）；：，") for p in parts)
    return [p for p in stripped if len(p) > 3]


def _scene(tmp_path: Path, mistake: str, language: str = "en") -> Path:
    (old, new), _ = MISTAKES[mistake]
    assert old in TEMPLATE
    text = TEMPLATE.replace(old, new, 1).replace('language = "en"', f'language = "{language}"')
    if mistake in EDITS:
        text = text.replace(*EDITS[mistake])
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("lang", ["ru", "vi"])
@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_mistakes_are_said_in_the_chosen_language(mistake, lang, tmp_path, capsys):
    path = _scene(tmp_path, mistake)
    code = main(["solve", str(path), "--lang", lang, *ARGS.get(mistake, [])])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    head = catalogue(lang)["errors.cli.error"].split("{")[0]
    assert err.startswith(head), err
    assert str(path) in err
    words = _fixed_words(MISTAKES[mistake][1], lang)
    assert words and all(w in err for w in words), (words, err)


def test_the_scenes_own_language_is_used_without_lang(tmp_path, capsys):
    path = _scene(tmp_path, "unknown key", language="vi")
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err
    assert "lỗi" in err and "khóa không xác định" in err and "'drive.sence'" in err


def test_output_folder_that_is_a_file(tmp_path, capsys):
    (tmp_path / "out").write_text("not a folder")
    code = main(["draw", str(ROOT / "templates" / "four_bar.toml"), "-o", str(tmp_path / "out"),
                 "--lang", "ru"])
    err = capsys.readouterr().err
    assert code == 2 and "папка вывода должна быть папкой, а не файлом" in err
    assert (tmp_path / "out").read_text() == "not a folder"


def test_missing_scene_file_is_said_in_russian(tmp_path, capsys):
    code = main(["solve", str(tmp_path / "nothing.toml"), "--lang", "ru"])
    err = capsys.readouterr().err
    assert code == 2 and "ошибка" in err and "nothing.toml" in err
    assert "does not exist" not in err


def test_json_error_object_has_a_stable_code(tmp_path, capsys):
    path = _scene(tmp_path, "bad unit")
    for lang in ("en", "zh"):
        assert main(["solve", str(path), "--json", "--lang", lang]) == 2
        doc = json.loads(capsys.readouterr().out)["error"]
        assert doc["code"] == "errors.units.wrong_dimension"
        assert doc["key"] == "links.1.lengths.AB" and doc["file"] == str(path)
        assert doc["kind"] == "SceneError" and "80 kg" in doc["message"]
    assert "不是长度" in doc["message"]


def test_every_dimension_has_its_noun_in_every_language():
    """A quantity error names the kind of quantity wanted: each dimension a scene may read."""
    from mechplan.units import DIMENSIONS

    for lang in ("en", "ru", "vi", "zh"):
        missing = [d for d in DIMENSIONS if f"errors.noun.{d}" not in catalogue(lang)]
        assert not missing, (lang, missing)
