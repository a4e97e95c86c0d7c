"""The page of each tradition measured back from the note's PDF: the ГОСТ frame (20 mm left,
5 mm elsewhere) and its main inscription (form 2 then 2a), and the margins of the others."""

from __future__ import annotations

from pathlib import Path

import pytest

from mechplan.note.layout import PAGES
from mechplan.note.project import run_project

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
MM = 72 / 25.4


def _note(tmp_path: Path, lang: str, tradition: str) -> Path:
    path = tmp_path / f"{tradition}.toml"
    path.write_text(f'[project]\ntitle = "T"\nlanguage = "{lang}"\ntradition = "{tradition}"\n'
                    f'code = "TMM.01.00"\n[studies]\n'
                    f'cam = "{(TEMPLATES / "cam_cycloidal.toml").as_posix()}"\n',
                    encoding="utf-8")
    run_project(path, tmp_path / "out", ("pdf",))
    return tmp_path / "out" / f"{tradition}-note.pdf"


def _stamp_top_mm(page) -> float:
    """Top of the main inscription: the highest full-width horizontal rule of the frame."""
    rules = [line["top"] / MM for line in page.lines
             if abs(line["top"] - line["bottom"]) < 0.1 and abs(line["x0"] / MM - 20) < 0.3
             and abs(line["x1"] / MM - 205) < 0.3]
    return min(rules)


def test_gost_frame_and_main_inscription(tmp_path: Path) -> None:
    pdfplumber = pytest.importorskip("pdfplumber")
    with pdfplumber.open(_note(tmp_path, "ru", "gost")) as pdf:
        assert pdf.pages[0].width / MM == pytest.approx(210, abs=0.01)
        assert pdf.pages[0].height / MM == pytest.approx(297, abs=0.01)
        assert not pdf.pages[0].rects                      # the title page has no frame
        for i, stamp in ((1, 40.0), (2, 15.0)):            # form 2, then form 2a
            page = pdf.pages[i]
            frames = [(r["x0"] / MM, r["top"] / MM, r["width"] / MM, r["height"] / MM)
                      for r in page.rects if r["width"] / MM > 150]
            assert len(frames) == 1
            assert frames[0] == pytest.approx((20, 5, 185, 287), abs=0.05)
            assert 292 - _stamp_top_mm(page) == pytest.approx(stamp, abs=0.1)
            text = page.extract_text()
            assert "TMM.01.00" in text and "Изм." in text and str(i + 1) in text.split()
            # the text stays inside the frame and above the inscription
            words = page.extract_words()
            assert min(w["x0"] for w in words) / MM >= 20
            body = [w for w in words if w["bottom"] / MM < 292 - stamp]
            assert body and max(w["x1"] for w in body) / MM <= 205


@pytest.mark.parametrize("lang,tradition", [("vi", "tcvn"), ("zh", "gb"), ("en", "plain")])
def test_margins_of_the_other_traditions(tmp_path: Path, lang: str, tradition: str) -> None:
    pdfplumber = pytest.importorskip("pdfplumber")
    page = PAGES[tradition]
    with pdfplumber.open(_note(tmp_path, lang, tradition)) as pdf:
        p = pdf.pages[2]
        assert not [r for r in p.rects if r["width"] / MM > 150]           # no frame
        # full-width CJK punctuation is set half-width: its glyph box overhangs its ink
        chars = [c for c in p.chars if c["text"].strip()
                 and not ("\u3000" <= c["text"] <= "\u303f" or "\uff00" <= c["text"] <= "\uffef")]
        assert min(c["x0"] for c in chars) / MM == pytest.approx(page.left, abs=0.6)
        assert max(c["x1"] for c in chars) / MM <= 210 - page.right + 0.3
        head = [c for c in chars if c["top"] / MM < page.top - 1]
        assert bool(head) == page.running_head              # GB: the title above a rule
        body = [c for c in chars if c not in head]
        assert min(c["top"] for c in body) / MM >= page.top - 1.5      # the font box of a heading


@pytest.mark.external
def test_gost_frame_of_the_docx_in_libreoffice(tmp_path: Path, require) -> None:
    """The DOCX's frame (page borders) and main inscription (a footer table), as LibreOffice
    lays them out: 20 mm / 5 mm, form 2a 185 × 15 mm with its columns."""
    import shutil
    import subprocess

    soffice = shutil.which("soffice") or shutil.which("libreoffice")
    require(soffice is not None, "LibreOffice (apt-get install libreoffice-writer-nogui)")
    pdfplumber = pytest.importorskip("pdfplumber")
    path = tmp_path / "gost.toml"
    path.write_text('[project]\ntitle = "T"\nlanguage = "ru"\ncode = "TMM.01.00"\n[studies]\n'
                    f'cam = "{(TEMPLATES / "cam_cycloidal.toml").as_posix()}"\n',
                    encoding="utf-8")
    run_project(path, tmp_path / "out", ("docx",))
    subprocess.run([soffice, "--headless", f"-env:UserInstallation=file://{tmp_path}/lo",
                    "--convert-to", "pdf", "--outdir", str(tmp_path / "lo"),
                    str(tmp_path / "out" / "gost-note.docx")],
                   check=True, capture_output=True, timeout=300)
    with pdfplumber.open(tmp_path / "lo" / "gost-note.pdf") as pdf:
        page = pdf.pages[2]
        lines = [(ln["x0"] / MM, ln["top"] / MM, ln["x1"] / MM, ln["bottom"] / MM)
                 for ln in page.lines]
    vertical = [x0 for x0, top, x1, bottom in lines if abs(x1 - x0) < 0.2 and bottom - top > 250]
    horizontal = [top for x0, top, x1, bottom in lines
                  if abs(bottom - top) < 0.2 and x1 - x0 > 180]
    assert sorted(vertical) == pytest.approx([20, 205], abs=0.5)          # the frame
    assert min(horizontal) == pytest.approx(5, abs=0.5)
    assert max(horizontal) == pytest.approx(292, abs=0.5)
    stamp_top = min(t for t in horizontal if t > 200)
    assert 292 - stamp_top == pytest.approx(15, abs=0.5)                 # form 2a
    columns = sorted({round(x0, 0) for x0, top, x1, bottom in lines
                      if abs(x1 - x0) < 0.2 and top > 270 and bottom - top > 10})
    assert columns == pytest.approx([20, 27, 37, 60, 75, 85, 195, 205], abs=0.6)
