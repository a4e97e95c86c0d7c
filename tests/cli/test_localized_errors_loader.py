"""Issue 35: the errors of the scene loader, the structural analysis and the assembly are said in
the user's language (``--lang``) with the same file and key, say nothing in English there, read
as before in English, and give their message id as the JSON error code."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mechplan.cli import main

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")

#: mistake → (edits of four_bar.toml, key said, message id, said in ru, in vi, English said)
MISTAKES = {
    "unknown driving link": (
        [('link = "1"', 'link = "9"')], "drive.link", "errmsg2.scene_loader.unknown_drive_link",
        "неизвестное звено '9'; звенья: 1, 2, 3", "khâu '9' không rõ; các khâu là 1, 2, 3",
        "unknown link '9'; links are 1, 2, 3"),
    "link with no points": (
        [("[drive]", '[links.4]\nname = "extra"\n\n[drive]')], "links.4",
        "errmsg2.scene_loader.link_no_points", "у звена 4 нет точек", "khâu 4 không có điểm nào",
        "link 4 has no points"),
    "W differs from the drivers": (
        [("[drive]", '[links.4]\nlengths = { CF = "100 mm" }\n\n[drive]')], "links",
        "errmsg2.structure.w_drivers",
        "степень подвижности механизма W = 3·4 − 2·5 = 2, а ведущее звено: 1 ([drive], звено 1)",
        "cơ cấu có bậc tự do W = 3·4 − 2·5 = 2 nhưng có 1 khâu dẫn ([drive], khâu 1)",
        "W = 3·4 − 2·5 = 2 degrees of freedom but 1 driver ([drive], link 1)"),
    # a change-point four-bar: at φ = 0 B, C and D are collinear (BD = 170 = 350 − 180)
    "assembly side that cannot be decided": (
        [('BC = "260 mm", BE = "150 mm", CE = "180 mm"',
          'BC = "350 mm", BE = "150 mm", CE = "250 mm"'),
         ('C = "left of B->D"', 'C = "left of B->D"\nat = "0 deg"')],
        "assembly.C", "errmsg2.builder.side_undecided",
        "сторону точки C относительно B->D нельзя определить при φ = 0°",
        "không thể xác định phía của điểm C so với B->D tại φ = 0°",
        "the side of point C relative to B->D cannot be decided at φ = 0°"),
}


def _scene(tmp_path: Path, mistake: str) -> Path:
    text = FOUR_BAR
    for old, new in MISTAKES[mistake][0]:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / "four_bar.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("lang", ["ru", "vi"])
@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_loader_mistakes_are_said_in_the_chosen_language(mistake, lang, tmp_path, capsys):
    _, key, _msgid, ru, vi, english = MISTAKES[mistake]
    path = _scene(tmp_path, mistake)
    code = main(["solve", str(path), "--lang", lang])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert str(path) in err and f"'{key}'" in err, err
    assert (ru if lang == "ru" else vi) in err, err
    assert english not in err, err


@pytest.mark.parametrize("mistake", sorted(MISTAKES))
def test_english_text_and_json_code_are_kept(mistake, tmp_path, capsys):
    _, key, msgid, *_, english = MISTAKES[mistake]
    path = _scene(tmp_path, mistake)
    assert main(["solve", str(path), "--lang", "en"]) == 2
    assert english in capsys.readouterr().err
    assert main(["solve", str(path), "--json", "--lang", "ru"]) == 2
    doc = json.loads(capsys.readouterr().out)["error"]
    assert doc["code"] == msgid and doc["key"] == key
    assert english not in doc["message"]
