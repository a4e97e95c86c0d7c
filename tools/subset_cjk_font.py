#!/usr/bin/env python
"""Make the bundled CJK font: Noto Sans CJK SC cut to the characters mechplan's sheets need.

The glyphs kept: ASCII and Latin-1, Greek, Cyrillic, general punctuation, arrows, mathematical
operators, CJK symbols and punctuation, full-width forms, every Chinese character of GB 2312
(levels 1 and 2: 6,763 characters, the common simplified set), and every character of the
catalogues and sources under ``src/mechplan``. Run after the Chinese catalogue gains characters::

    python tools/subset_cjk_font.py [/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc]

Writes ``src/mechplan/fonts/NotoSansCJKsc-Regular.ttf`` (SIL Open Font License 1.1, see
``src/mechplan/fonts/OFL-NotoSansCJK.txt``) with its cubic CFF outlines converted to quadratic
TrueType ones (fontTools.cu2qu, 1 unit of 1000 tolerance): a PDF embeds a TrueType font as Type 42,
and a CFF font embedded so is "a mismatch between font type and embedded font file" for poppler.
Only the horizontal layout features are kept (sheets have no vertical text).
"""

from __future__ import annotations

import sys
from pathlib import Path

from fontTools import subset
from fontTools.pens.cu2quPen import Cu2QuPen
from fontTools.pens.recordingPen import DecomposingRecordingPen
from fontTools.pens.transformPen import TransformPen
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import TTFont, newTable

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "mechplan"
OUT = PACKAGE / "fonts" / "NotoSansCJKsc-Regular.ttf"
SOURCE = Path("/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc")
SC_INDEX = 2          # "Noto Sans CJK SC" in the Debian collection
RANGES = [(0x20, 0x7E), (0xA0, 0xFF), (0x370, 0x3FF), (0x400, 0x4FF), (0x2000, 0x206F),
          (0x2070, 0x209F), (0x2100, 0x214F), (0x2190, 0x21FF), (0x2200, 0x22FF),
          (0x2460, 0x24FF), (0x25A0, 0x25FF), (0x3000, 0x303F), (0xFF00, 0xFFEF)]


def gb2312() -> set[int]:
    """Code points of the GB 2312 Chinese characters (rows 16–87)."""
    out = set()
    for hi in range(0xB0, 0xF8):
        for lo in range(0xA1, 0xFF):
            try:
                out.add(ord(bytes([hi, lo]).decode("gb2312")))
            except UnicodeDecodeError:
                pass
    return out


def project_characters() -> set[int]:
    """Every character of the catalogues and sources."""
    chars: set[int] = set()
    for pattern in ("locale/*/*.po", "**/*.py", "templates/*.toml"):
        for path in PACKAGE.glob(pattern):
            chars.update(ord(c) for c in path.read_text(encoding="utf-8"))
    return chars


def to_truetype(font: TTFont, max_err: float = 1.0) -> None:
    """Replace the CFF outlines of `font` by TrueType (quadratic) ones, in place."""
    order = font.getGlyphOrder()
    glyphs = font.getGlyphSet()
    glyf = newTable("glyf")
    glyf.glyphOrder = order
    glyf.glyphs = {}
    for name in order:
        pen = TTGlyphPen(glyphs)
        glyphs[name].draw(Cu2QuPen(pen, max_err, reverse_direction=True))
        glyf[name] = pen.glyph()
    font["glyf"] = glyf
    font["loca"] = newTable("loca")
    maxp = font["maxp"]
    maxp.tableVersion = 0x00010000
    for field in ("maxZones", "maxTwilightPoints", "maxStorage", "maxFunctionDefs",
                  "maxInstructionDefs", "maxStackElements", "maxSizeOfInstructions",
                  "maxComponentElements", "maxPoints", "maxContours", "maxCompositePoints",
                  "maxCompositeContours", "maxComponentDepth"):
        setattr(maxp, field, 0)
    maxp.maxZones = 1
    for tag in ("CFF ", "VORG"):
        if tag in font:
            del font[tag]
    font["head"].glyphDataFormat = 0
    post = font["post"]
    post.formatType = 2.0
    post.extraNames = []
    post.mapping = {}
    font.sfntVersion = "\x00\x01\x00\x00"


#: characters Noto Sans CJK lacks but the sheets write in Chinese (10⁻¹², M_b⁰, S₄): their
#: glyphs are taken from matplotlib's DejaVu Sans (Bitstream Vera licence, free to copy), scaled
SUPPLEMENT = [(0x2070, 0x209F)]


def borrowed(font: TTFont, wanted: set[int]) -> list[int]:
    """Add to the TrueType `font` the glyphs of `wanted` it lacks and DejaVu Sans has; return
    the code points added."""
    import matplotlib

    donor = TTFont(Path(matplotlib.get_data_path()) / "fonts" / "ttf" / "DejaVuSans.ttf")
    dcmap, dglyphs = donor.getBestCmap(), donor.getGlyphSet()
    scale = font["head"].unitsPerEm / donor["head"].unitsPerEm
    cmap = font.getBestCmap()
    order = list(font.getGlyphOrder())
    glyf, hmtx = font["glyf"], font["hmtx"]
    added = []
    for cp in sorted(wanted):
        if cp in cmap or cp not in dcmap:
            continue
        name = f"uni{cp:04X}"
        pen = TTGlyphPen(None)
        outline = DecomposingRecordingPen(dglyphs)      # composites drawn as plain contours
        dglyphs[dcmap[cp]].draw(outline)
        outline.replay(TransformPen(pen, (scale, 0, 0, scale, 0, 0)))
        glyf[name] = pen.glyph()
        advance = round(donor["hmtx"][dcmap[cp]][0] * scale)
        glyf[name].recalcBounds(glyf)
        hmtx[name] = (advance, getattr(glyf[name], "xMin", 0))
        order.append(name)
        for table in font["cmap"].tables:
            if table.isUnicode():
                table.cmap[cp] = name
        added.append(cp)
    font.setGlyphOrder(order)
    glyf.glyphOrder = order
    font["maxp"].numGlyphs = len(order)
    return added


def main() -> int:
    source = Path(sys.argv[1]) if len(sys.argv) > 1 else SOURCE
    font = TTFont(source, fontNumber=SC_INDEX)
    cmap = font.getBestCmap()
    wanted = gb2312() | project_characters()
    for a, b in RANGES:
        wanted.update(range(a, b + 1))
    unicodes = sorted(cp for cp in wanted if cp in cmap)
    options = subset.Options()
    options.layout_features = ["ccmp", "kern"]   # the Simplified Chinese forms only (no locl)
    options.drop_tables = [*options.drop_tables, "vhea", "vmtx", "VORG"]
    options.name_IDs = ["*"]
    options.name_languages = ["*"]
    options.notdef_outline = True
    options.hinting = False
    options.desubroutinize = False
    sub = subset.Subsetter(options)
    sub.populate(unicodes=unicodes)
    sub.subset(font)
    to_truetype(font)
    extra = set()
    for a, b in SUPPLEMENT:
        extra.update(range(a, b + 1))
    added = borrowed(font, (extra | project_characters()) - set(unicodes))
    OUT.parent.mkdir(parents=True, exist_ok=True)
    font.save(OUT)
    print(f"{OUT}: {len(unicodes)} characters, {len(added)} more from DejaVu Sans, "
          f"{OUT.stat().st_size / 1e6:.2f} MB")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
