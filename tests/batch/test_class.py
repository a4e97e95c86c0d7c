"""A small class of slider-cranks: folders, answer keys against the closed form, failures,
resume."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import pytest

from mechplan.batch import Variant, run_class
from mechplan.cli import main

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
SLIDER = TEMPLATES / "slider_crank.toml"
CLASS = [Variant("s1", "Иван", {"links.1.lengths.OA": "90 mm"}),
         Variant("bad", "", {"links.1.lengths.OA": "500 mm"}),
         Variant("s2", "Mai", {"links.1.lengths.OA": "110 mm", "drive.speed": "1200 rpm"})]


def slider(theta: float, r: float, l: float, omega: float) -> tuple[float, float]:
    """|v_B|, |a_B| of a central slider-crank with a guide along x (closed form, ε = 0)."""
    s, c = r * math.sin(theta), r * math.cos(theta)
    root = math.sqrt(l * l - s * s)
    d1 = -s - s * c / root
    d2 = -c - (c * c - s * s) / root - s * s * c * c / root ** 3
    return abs(omega * d1), abs(omega * omega * d2)


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    out = tmp_path_factory.mktemp("class")
    return out, run_class(SLIDER, CLASS, out, formats=("svg",), workers=1, progress=False)


def test_folders_and_summary(klass):
    out, result = klass
    assert (result.solved, result.skipped, result.failed) == (2, 0, 1)
    for sid in ("s1", "s2"):
        names = {p.name for p in (out / sid).iterdir()}
        assert {"scene.toml", "slider_crank.svg", "answer_key.json", "answer_key.pdf",
                "summary.json", ".complete"} <= names
        assert not [n for n in names if n.endswith(".tmp")]
    assert not (out / "bad" / ".complete").exists()
    with (out / "summary.csv").open(encoding="utf-8") as fh:
        rows = {r["id"]: r for r in csv.DictReader(fh)}
    assert rows["s1"]["status"] == "ok" and rows["s1"]["name"] == "Иван"
    assert rows["bad"]["status"] == "failed" and "cannot" in rows["bad"]["error"]
    assert rows["s2"]["drive.speed"] == "1200 rpm"
    # the class summary's key number is the largest |a_B| over the key's positions
    key = json.loads((out / "s2" / "answer_key.json").read_text(encoding="utf-8"))
    a_b = next(r for r in key["rows"] if r["quantity"] == "a_B")
    assert float(rows["s2"]["max|a_B|"]) == pytest.approx(max(a_b["values"]), rel=1e-9)


@pytest.mark.parametrize("sid, r, omega", [("s1", 0.09, 1500 * math.pi / 30),
                                           ("s2", 0.11, 1200 * math.pi / 30)])
def test_answer_key_matches_the_closed_form(klass, sid, r, omega):
    out, _ = klass
    key = json.loads((out / sid / "answer_key.json").read_text(encoding="utf-8"))
    assert key["id"] == sid and len(key["phi_deg"]) == 12
    rows = {row["quantity"]: row["values"] for row in key["rows"]}
    for k, pos in enumerate(key["solution"]["positions"]):
        v, a = slider(math.radians(pos["crank_angle_deg"]), r, 0.4, omega)
        assert rows["v_B"][k] == pytest.approx(v, rel=1e-9, abs=1e-9)
        assert rows["a_B"][k] == pytest.approx(a, rel=1e-9)
    assert "M_b" in rows and "ω2" in rows
    scene = (out / sid / "scene.toml").read_text(encoding="utf-8")
    assert f'OA = "{round(r * 1000)} mm"' in scene


def test_answer_key_pdf_is_a_printable_table(klass):
    import pdfplumber

    out, _ = klass
    with pdfplumber.open(out / "s1" / "answer_key.pdf") as pdf:
        text = "\n".join(page.extract_text() or "" for page in pdf.pages)
        assert len(pdf.pages) == 2               # 12 positions: 8 columns per page
    # v_B is drawn with a real subscript (two text runs); R23 has none
    assert "s1" in text and "Иван" in text and "R23" in text and "φ = 0.0°" in text


def test_rerun_skips_complete_folders(klass):
    out, first = klass
    stamp = (out / "s1" / "answer_key.pdf").stat().st_mtime_ns
    again = run_class(SLIDER, CLASS, out, formats=("svg",), workers=1, progress=False)
    assert (again.solved, again.skipped, again.failed) == (0, 2, 1)
    assert (out / "s1" / "answer_key.pdf").stat().st_mtime_ns == stamp
    assert again.rows == first.rows
    # a changed variant is solved again
    changed = [Variant("s1", "Иван", {"links.1.lengths.OA": "95 mm"}), CLASS[2]]
    third = run_class(SLIDER, changed, out, formats=("svg",), workers=1, progress=False)
    assert (third.solved, third.skipped) == (1, 1)


def test_cli_batch_exit_code(tmp_path, capsys):
    table = tmp_path / "class.csv"
    table.write_text("id,name,links.1.lengths.OA\nok1,A,95 mm\nno,B,450 mm\n", encoding="utf-8")
    code = main(["batch", str(SLIDER), str(table), "-o", str(tmp_path / "out"), "--format", "svg",
                 "-j", "1", "--no-progress"])
    assert code == 1
    assert "1 solved, 0 complete already, 1 failed" in capsys.readouterr().out
    code = main(["batch", str(SLIDER), str(tmp_path / "missing.csv"), "-o", str(tmp_path)])
    assert code == 2


def test_a_students_scene_reads_like_the_template(klass):
    """Issue 35: only the changed numbers differ; comments, [[loads]] and layout are kept."""
    out, _ = klass
    template = SLIDER.read_text(encoding="utf-8").splitlines()
    scene = (out / "s2" / "scene.toml").read_text(encoding="utf-8").splitlines()
    assert scene[0].startswith("# s2") and "Mai" in scene[0]
    body = scene[1:]
    assert len(body) == len(template)
    changed = [(a, b) for a, b in zip(template, body, strict=True) if a != b]
    assert len(changed) == 2, changed
    assert any("110 mm" in b and "OA" in b for _, b in changed)
    assert any("1200 rpm" in b for _, b in changed)
    assert sum(line.lstrip().startswith("#") for line in body) == \
        sum(line.lstrip().startswith("#") for line in template) > 0
