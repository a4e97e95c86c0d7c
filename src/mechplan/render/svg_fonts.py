"""Fonts embedded in an SVG sheet: each sheet font subset to the characters the sheet uses.

A browser or viewer without osifont (or a CJK font) then draws the sheet exactly as designed. The
subsets are TrueType/OpenType data in ``@font-face`` rules (base64 data URIs); subsetting is
deterministic (no timestamps), so the same sheet gives the same SVG.
"""

from __future__ import annotations

import base64
import functools
import io
import logging
from pathlib import Path

from fontTools import subset
from fontTools.ttLib import TTFont

from mechplan.drafting.fonts import SheetFont, face_index, font_path, has_cjk
from mechplan.drafting.primitives import Sheet, Text

log = logging.getLogger(__name__)


def _texts(sheet: Sheet) -> list[str]:
    return [p.string for p in sheet.flat() if isinstance(p, Text)]


def _subset(font: SheetFont, chars: str) -> tuple[str, str] | None:
    """(mime type, base64 data) of ``font`` cut down to ``chars``, or None when not installed."""
    path = font_path(font)
    return None if path is None else _subset_file(path, face_index(path, font), chars)


@functools.lru_cache(maxsize=64)
def _subset_file(path: Path, index: int, chars: str) -> tuple[str, str]:
    # lazy: only the tables the subset keeps are parsed (same bytes, ~3× faster)
    tt = TTFont(str(path), fontNumber=index, recalcTimestamp=False, lazy=True)
    options = subset.Options()
    options.layout_features = ["*"]
    options.name_IDs = ["*"]
    options.notdef_outline = True
    options.drop_tables = [*options.drop_tables, "FFTM"]   # FontForge timestamps: not needed
    sub = subset.Subsetter(options)
    sub.populate(text=chars)
    sub.subset(tt)
    buf = io.BytesIO()
    tt.save(buf)
    mime = "font/otf" if "CFF " in tt else "font/ttf"
    return mime, base64.b64encode(buf.getvalue()).decode("ascii")


def font_faces_css(sheet: Sheet) -> str:
    """CSS ``@font-face`` rules embedding the sheet's fonts (empty when no font is installed)."""
    texts = _texts(sheet)
    if not texts:
        return ""
    chars = "".join(sorted(set("".join(texts)) - {" "}))
    fonts = [SheetFont.ISO, SheetFont.SYMBOL]
    if any(has_cjk(t) for t in texts):
        fonts.append(SheetFont.CJK)
    rules = []
    for font in fonts:
        data = _subset(font, chars)
        if data is None:
            log.warning("font %s is not installed: the SVG names it without embedding it",
                        font.value.family)
            continue
        mime, b64 = data
        fmt = "opentype" if mime == "font/otf" else "truetype"
        rules.append(f"@font-face {{ font-family: '{font.value.family}'; "
                     f"src: url(data:{mime};base64,{b64}) format('{fmt}'); }}")
    return "\n".join(rules)
