"""PDF sheets embed their fonts so that poppler reads them without complaint.

matplotlib embeds a TrueType font as Type 42 (a CIDFontType2 with a FontFile2); a CFF-flavoured
OpenType font embedded that way is "a mismatch between font type and embedded font file" for
poppler. The bundled Noto Sans CJK SC subset therefore has TrueType outlines.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from fontTools.ttLib import TTFont
from scenes import ROOT

from mechplan.render import write
from mechplan.sheet.fonts import SheetFont, font_path
from mechplan.studies import solve_file


def test_the_cjk_font_has_truetype_outlines() -> None:
    font = TTFont(font_path(SheetFont.CJK), lazy=True)
    assert "glyf" in font and "CFF " not in font
    assert font.sfntVersion == "\x00\x01\x00\x00"


@pytest.mark.external
@pytest.mark.parametrize(("template", "lang", "sheet_index"),
                         [("machine_unit", "zh", -1), ("motorcycle_engine", None, 0)])
def test_poppler_reads_the_embedded_fonts_without_errors(tmp_path: Path, require, template: str,
                                                        lang: str | None, sheet_index: int) -> None:
    require(shutil.which("pdffonts") is not None and shutil.which("pdftoppm") is not None,
            "poppler (apt-get install poppler-utils)")
    sheet = solve_file(ROOT / "templates" / f"{template}.toml").sheets(None, None, lang,
                                                                       template)[sheet_index]
    [pdf] = write(sheet, tmp_path, ["pdf"])
    fonts = subprocess.run(["pdffonts", str(pdf)], capture_output=True, text=True, timeout=60,
                           check=True)
    raster = subprocess.run(["pdftoppm", "-r", "30", "-png", str(pdf), str(tmp_path / "page")],
                            capture_output=True, text=True, timeout=120, check=True)
    for proc in (fonts, raster):
        assert "Mismatch" not in proc.stderr and "Error" not in proc.stderr, proc.stderr
    rows = [line.split() for line in fonts.stdout.splitlines()[2:]]
    names = {row[0].split("+")[-1] for row in rows}
    assert "NotoSansCJKsc-Regular" in names, fonts.stdout
    for row in rows:
        assert row[1:3] == ["CID", "TrueType"], row           # what the file holds, too
        assert row[-5:-2] == ["yes", "yes", "yes"], row       # embedded, subset, ToUnicode
    assert list(tmp_path.glob("page*.png"))
