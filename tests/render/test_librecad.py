"""LibreCAD 2.2 draws our DXF text as glyphs, not ◊: title-block values, Vietnamese, μ φ ⊥, Ё.

LibreCAD picks the stroke font named like the TEXT's style; our styles are named after LibreCAD
fonts that have the glyphs, and Vietnamese uses the font mechplan ships
(src/mechplan/fonts/librecad/mechplan-vi.lff, added to LibreCAD's font path in its settings).
Each character is drawn alone; the rendered pictures of the characters must all differ from each
other and from the picture of a character no font has (which LibreCAD draws as ◊).
"""

from __future__ import annotations

import io
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from mechplan.render import dxf as dxf_backend
from mechplan.render.librecad import stroke_fonts
from mechplan.sheet.frame import make_frame
from mechplan.sheet.primitives import Text
from mechplan.studies import solve_file

ROOT = Path(__file__).resolve().parents[2]
FONTS = ROOT / "src" / "mechplan" / "fonts" / "librecad"
MISSING = "\u2603"          # ☃: in no LibreCAD font → ◊
CHARS = "ạệơưđμφ⊥ЁЭ"
DPI = 100


def _render(tmp_path: Path, dxf: bytes, name: str) -> np.ndarray:
    pdfplumber = pytest.importorskip("pdfplumber")
    home = tmp_path / "home"
    conf = home / ".config" / "LibreCAD"
    conf.mkdir(parents=True, exist_ok=True)
    (conf / "LibreCAD.conf").write_text(f"[Paths]\nFonts={FONTS}\n", encoding="utf-8")
    src = tmp_path / f"{name}.dxf"
    src.write_bytes(dxf)
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "HOME": str(home),
           "XDG_CONFIG_HOME": str(home / ".config")}
    subprocess.run(["librecad", "dxf2pdf", "-s", "1", "-f", "0,0,0,0", "-t", str(tmp_path),
                    str(src)], env=env, capture_output=True, timeout=120, check=True)
    with pdfplumber.open(tmp_path / f"{name}.pdf") as pdf:
        page = pdf.pages[0]
        assert page.width * 25.4 / 72 == pytest.approx(210.0, abs=0.5)     # A4 at true scale
        img = page.to_image(resolution=DPI).original.convert("L")
    return np.asarray(img, dtype=float) / 255.0


def _cell(img: np.ndarray, x_mm: float, y_mm: float, w_mm: float, h_mm: float) -> np.ndarray:
    px = DPI / 25.4
    rows = img.shape[0]
    top, left = round(rows - (y_mm + h_mm) * px), round(x_mm * px)
    return img[top:top + round(h_mm * px), left:left + round(w_mm * px)]


@pytest.mark.external
def test_librecad_draws_title_block_values_and_every_script_as_glyphs(tmp_path, require):
    require(shutil.which("librecad") is not None, "LibreCAD (apt-get install librecad)")
    fields = {"title": "Cơ cấu tay quay con trượt", "sheet_number": "1", "sheets_total": "2"}
    frame = make_frame("A4", "tcvn", fields, language="vi")
    empty = make_frame("A4", "tcvn", {"title": ""}, language="vi")
    chars = [Text((20.0 + 15.0 * i, 250.0), c, 7.0) for i, c in enumerate(CHARS + MISSING)]
    full = _render(tmp_path, dxf_backend.to_bytes(frame.sheet(chars, "full")), "full")
    blank = _render(tmp_path, dxf_backend.to_bytes(empty.sheet((), "blank")), "blank")
    # every character is a glyph of its own: no two pictures alike, none like the missing one's
    cells = [_cell(full, 19.0 + 15.0 * i, 247.0, 13.0, 12.0) < 0.5 for i in range(len(CHARS) + 1)]
    assert all(c.any() for c in cells)
    for i, a in enumerate(cells):
        for b in cells[i + 1:]:
            assert (a != b).mean() > 0.005, CHARS[i]
    # the title block shows its values (the title cell is drawn, not left empty)
    t = frame.title_block
    diff = np.abs(_cell(full, t.x0, t.y0, t.width, t.height)
                  - _cell(blank, t.x0, t.y0, t.width, t.height))
    assert (diff > 0.5).mean() > 0.002


def _text_boxes_drawn_by_librecad(tmp_path: Path, sheet, name: str) -> list[tuple[str, tuple]]:
    """(string, box in mm) of every text of `sheet` as LibreCAD draws its DXF.

    The DXF keeps only its texts (and the title block's insert), each in a true colour of its
    own; LibreCAD's PDF strokes carry the colours, so each stroke is its text's.
    """
    from ezdxf import colors

    pdfplumber = pytest.importorskip("pdfplumber")
    doc = dxf_backend.to_document(sheet)
    strings: dict[int, str] = {}
    layouts = [doc.modelspace(), *(b for b in doc.blocks if not b.name.startswith("*"))]
    for layout in layouts:
        for e in list(layout):
            if e.dxftype() in ("TEXT", "MTEXT"):
                key = len(strings) + 1
                strings[key] = e.dxf.text if e.dxftype() == "TEXT" else e.text
                e.dxf.true_color = colors.rgb2int((key >> 16 & 255, key >> 8 & 255, key & 255))
            elif e.dxftype() not in ("INSERT", "ATTDEF"):
                layout.delete_entity(e)
    stream = io.StringIO()
    doc.write(stream)
    home = tmp_path / "home"
    conf = home / ".config" / "LibreCAD"
    conf.mkdir(parents=True, exist_ok=True)
    (conf / "LibreCAD.conf").write_text(f"[Paths]\nFonts={FONTS}\n", encoding="utf-8")
    (tmp_path / f"{name}.dxf").write_bytes(doc.encode(stream.getvalue()))
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "HOME": str(home),
           "XDG_CONFIG_HOME": str(home / ".config")}
    subprocess.run(["librecad", "dxf2pdf", "-s", "1", "-f", "0,0,0,0", "-t", str(tmp_path),
                    str(tmp_path / f"{name}.dxf")], env=env, capture_output=True, timeout=120,
                   check=True)
    mm = 25.4 / 72
    boxes: dict[int, tuple[float, float, float, float]] = {}
    with pdfplumber.open(tmp_path / f"{name}.pdf") as pdf:
        page = pdf.pages[0]
        assert page.width * mm == pytest.approx(sheet.width_mm, abs=0.5)
        for o in [*page.lines, *page.curves, *page.rects]:
            r, g, b = (round(v * 255) for v in o["stroking_color"])
            key = r << 16 | g << 8 | b
            x0, y0, x1, y1 = o["x0"] * mm, o["top"] * mm, o["x1"] * mm, o["bottom"] * mm
            if key in boxes:
                a = boxes[key]
                x0, y0, x1, y1 = min(a[0], x0), min(a[1], y0), max(a[2], x1), max(a[3], y1)
            boxes[key] = (x0, y0, x1, y1)
    assert set(boxes) <= set(strings)
    assert len(boxes) > 0.95 * len(strings)          # (a lone "." may draw nothing)
    return [(strings[k], b) for k, b in sorted(boxes.items())]


@pytest.mark.external
@pytest.mark.parametrize(("template", "index"),
                         [("slider_crank", 0), ("v_engine", 0), ("machine_unit", 0)])
def test_librecad_draws_a_russian_gost_sheet_without_overprinting(tmp_path, require, template,
                                                                  index):
    """Table headers, headings and title-block captions: LibreCAD's stroke fonts are wider than
    osifont, so a text measured in osifont overprinted its neighbour (16 pairs on slider_crank's
    sheet 1)."""
    require(shutil.which("librecad") is not None, "LibreCAD (apt-get install librecad)")
    sheet = solve_file(ROOT / "templates" / f"{template}.toml").sheets(None, "gost", "ru",
                                                                       template)[index]
    # every glyph exists in the LibreCAD font of its text's style (nothing is drawn as ◊)
    fonts = stroke_fonts()
    doc = dxf_backend.to_document(sheet)
    for e in doc.query("TEXT"):
        assert fonts[e.dxf.style].has(e.dxf.text), (e.dxf.style, e.dxf.text)
    boxes = _text_boxes_drawn_by_librecad(tmp_path, sheet, f"{template}_{index}")
    overlaps = []
    for i, (sa, a) in enumerate(boxes):
        for sb, b in boxes[i + 1:]:
            w = min(a[2], b[2]) - max(a[0], b[0])
            h = min(a[3], b[3]) - max(a[1], b[1])
            if w > 0.05 and h > 0.05:
                overlaps.append((sa, sb, round(w, 2), round(h, 2)))
    assert not overlaps, overlaps[:10]
