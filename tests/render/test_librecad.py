"""LibreCAD 2.2 draws our DXF text as glyphs, not ◊: title-block values, Vietnamese, μ φ ⊥, Ё.

LibreCAD picks the stroke font named like the TEXT's style; our styles are named after LibreCAD
fonts that have the glyphs, and Vietnamese uses the font mechplan ships
(src/mechplan/fonts/librecad/mechplan-vi.lff, added to LibreCAD's font path in its settings).
Each character is drawn alone; the rendered pictures of the characters must all differ from each
other and from the picture of a character no font has (which LibreCAD draws as ◊).
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from mechplan.render import dxf as dxf_backend
from mechplan.sheet.frame import make_frame
from mechplan.sheet.primitives import Text

FONTS = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "fonts" / "librecad"
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
