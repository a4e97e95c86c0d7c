"""Issue 32 item 5: the batch of a class writes each student's explanatory note beside their
sheets, with their name and variant and their own numbers."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from mechplan.batch import Variant, run_class
from mechplan.cli import parser

docx = pytest.importorskip("docx")

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
SLIDER = TEMPLATES / "slider_crank.toml"
CLASS = [Variant("s1", "Иван Петров", {"links.1.lengths.OA": "90 mm"}),
         Variant("s2", "Nguyễn Thị Mai", {"links.1.lengths.OA": "110 mm",
                                          "drive.speed": "1200 rpm"})]


def _text(path: Path) -> str:
    d = docx.Document(str(path))
    parts = [p.text for p in d.paragraphs]
    for table in d.tables:
        parts += [cell.text for row in table.rows for cell in row.cells]
    for section in d.sections:
        for table in section.footer.tables:
            parts += [cell.text for row in table.rows for cell in row.cells]
        parts += [p.text for p in section.footer.paragraphs]
    return "\n".join(parts)


def test_each_student_gets_their_own_note(tmp_path):
    result = run_class(SLIDER, CLASS, tmp_path, formats=("svg",), workers=1, progress=False,
                       note=("docx",))
    assert result.failed == 0
    for variant, rpm in ((CLASS[0], 1500.0), (CLASS[1], 1200.0)):
        note = tmp_path / variant.id / "slider_crank-note.docx"
        assert note.is_file(), sorted(p.name for p in (tmp_path / variant.id).iterdir())
        text = _text(note)
        assert variant.name in text and variant.id in text
        omega = math.pi * rpm / 30.0          # ω1 = πn/30 from the variant's own speed
        assert f"{omega:.2f}" in text, (variant.id, f"{omega:.2f}")
    other = _text(tmp_path / "s1" / "slider_crank-note.docx")
    assert f"{math.pi * 1200 / 30:.2f}" not in other


def test_batch_note_option():
    args = parser().parse_args(["batch", "t.toml", "v.csv", "-o", "o", "--note"])
    assert args.note is True
    assert parser().parse_args(["batch", "t.toml", "v.csv", "-o", "o"]).note is False
