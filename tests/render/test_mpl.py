"""PDF measured back with pdfplumber; PNG checked for size and content."""

from __future__ import annotations

import importlib.util
import io
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from mechplan import render
from mechplan.render import mpl
from mechplan.sheet.fonts import SheetFont, font_path

from .samples import LINE_END, LINE_START, sample_sheet

MM_PER_PT = 25.4 / 72.0


def _embedded_fonts(pdf) -> dict[str, bool]:
    """Return {font name: has an embedded font file} for every font the first page uses."""
    from pdfminer.pdftypes import resolve1

    fonts = resolve1(pdf.pages[0].page_obj.resources["Font"])
    result = {}
    for ref in fonts.values():
        font = resolve1(ref)
        name = resolve1(font["BaseFont"]).name
        parts = [font] + [resolve1(d) for d in resolve1(font.get("DescendantFonts", []))]
        result[name] = any(
            any(k in resolve1(p["FontDescriptor"]) for k in ("FontFile", "FontFile2", "FontFile3"))
            for p in parts if "FontDescriptor" in p
        )
    return result


@pytest.mark.external
def test_pdf_true_scale_and_embedded_fonts(tmp_path: Path, require) -> None:
    require(importlib.util.find_spec("pdfplumber") is not None, "pdfplumber (pip)")
    require(font_path(SheetFont.ISO) is not None and font_path(SheetFont.CJK) is not None,
            "fonts osifont and Noto Sans CJK (apt-get install fonts-osifont fonts-noto-cjk)")
    import pdfplumber

    path = render.write(sample_sheet("iso", "vi"), tmp_path / "sheet.pdf", ("pdf",))[0]
    with pdfplumber.open(path) as pdf:
        page = pdf.pages[0]
        assert page.width * MM_PER_PT == pytest.approx(210.0, abs=0.01)
        assert page.height * MM_PER_PT == pytest.approx(297.0, abs=0.01)
        top = (297.0 - LINE_START[1]) / MM_PER_PT
        known = [ln for ln in page.lines
                 if abs(ln["top"] - top) < 0.5 and abs(ln["x0"] * MM_PER_PT - LINE_START[0]) < 0.5]
        assert len(known) == 1
        ln = known[0]
        assert (ln["x1"] - ln["x0"]) * MM_PER_PT == pytest.approx(
            LINE_END[0] - LINE_START[0], abs=0.1)
        assert ln["linewidth"] * MM_PER_PT == pytest.approx(0.5, abs=0.01)
        chars = "".join(c["text"] for c in page.chars).replace(" ", "")
        for s in ("Nguyễn Văn An", "Trường Đại học", "План скоростей", "速度多边形", "π ω μ"):
            assert s.replace(" ", "") in chars
        fonts = _embedded_fonts(pdf)
    assert any("osifont" in name for name in fonts)
    assert any("NotoSansCJK" in name for name in fonts)
    assert fonts and all(fonts.values())


def test_png_size_and_content() -> None:
    data = mpl.to_bytes(sample_sheet("gost", "ru"), "png", dpi=100)
    image = Image.open(io.BytesIO(data))
    assert image.size[0] == pytest.approx(210 / 25.4 * 100, abs=1)
    assert image.size[1] == pytest.approx(297 / 25.4 * 100, abs=1)
    gray = np.asarray(image.convert("L"))
    dark = gray < 128
    assert 0.005 < dark.mean() < 0.2
    # the frame line of ГОСТ 2.104 lies 20 mm from the left edge
    col = np.flatnonzero(dark[gray.shape[0] // 2, : round(25 / 25.4 * 100)])
    assert col.size and abs(col.mean() - 20 / 25.4 * 100) < 1.5


def test_pdf_is_reproducible() -> None:
    sheet = sample_sheet("tcvn", "vi")
    assert mpl.to_bytes(sheet, "pdf") == mpl.to_bytes(sheet, "pdf")
