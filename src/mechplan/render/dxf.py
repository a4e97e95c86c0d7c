"""DXF R2013 backend (ezdxf): one layer per role, ISO 128 lineweights and line types, title block as
a BLOCK with attributes.

Text encoding: DXF R2007+ files are UTF-8 whatever $DWGCODEPAGE says (AutoCAD and ezdxf read them
so). The code page is set to the one AutoCAD itself writes on a system of the sheet's language
(ANSI_1252 en, ANSI_1251 ru, ANSI_1258 vi, ANSI_936 zh), which is what matters when AutoCAD saves
the drawing down to R2004 or older. GDAL 3.6 instead decodes R2007+ text by the code page: read
these files with `--config DXF_ENCODING UTF-8` (checked in the tests for vi/ru/zh). ANSI_65001 was
tried too: GDAL then returns the right text only through a failed-recode fallback with one warning
per string, and it is not a code page AutoCAD writes, so it is not used.
"""

from __future__ import annotations

import dataclasses
import io
import math

import ezdxf
from ezdxf.document import Drawing
from ezdxf.enums import TextEntityAlignment
from ezdxf.layouts.base import BaseLayout
from ezdxf.layouts.blocklayout import BlockLayout

from mechplan.drafting.fonts import SheetFont, font_for, font_of, text_width_mm
from mechplan.drafting.primitives import (
    DASH_PATTERNS_MM,
    Arc,
    Arrow,
    Block,
    Circle,
    HAlign,
    Line,
    LineType,
    Polyline,
    Primitive,
    Role,
    Sheet,
    Text,
    VAlign,
)
from mechplan.drafting.typography import (
    glyph_runs,
    has_scripts,
    has_unicode_scripts,
    mtext,
    plain,
)
from mechplan.errors import DrawingError
from mechplan.render.librecad import stroke_fonts

#: $DWGCODEPAGE by sheet language, as Python codec names (ezdxf writes the ANSI_ name).
ENCODINGS = {"en": "cp1252", "ru": "cp1251", "vi": "cp1258", "zh": "gbk"}

LINETYPE_NAMES = {LineType.CONTINUOUS: "Continuous", LineType.DASHED: "DASHED",
                  LineType.DASH_DOT: "DASHDOT"}
_LINETYPE_DESCRIPTIONS = {LineType.DASHED: "ISO 128 dashed (02) __ __ __",
                          LineType.DASH_DOT: "ISO 128 long-dash dotted (04) ____ . ____ ."}
#: Text styles. AutoCAD draws a style's font file; LibreCAD 2.2 ignores the file and draws the
#: stroke (.lff) font named like the STYLE, so each style is named after a LibreCAD font that has
#: its glyphs: kst32b (Latin, Cyrillic, Greek μ φ, ⊥), azomix (symbols), unicode (CJK, ∥, ·).
TEXT_STYLES = {SheetFont.ISO: "kst32b", SheetFont.SYMBOL: "azomix", SheetFont.CJK: "unicode"}
#: Vietnamese text: no LibreCAD font has its letters; mechplan ships the stroke font
#: fonts/librecad/mechplan-vi.lff (add its folder to LibreCAD's Preferences → Paths → Fonts),
#: which also has the few symbols no LibreCAD font has (✓ – — ·): strings with them use it too
VI_STYLE = "mechplan-vi"
#: the styles tried for a string, by the sheet font it is measured in: the first whose LibreCAD
#: font has every glyph of the string is used (else the first: LibreCAD draws ◊ for the rest)
_STYLE_ORDER = {
    SheetFont.ISO: ("kst32b", "azomix", "unicode", VI_STYLE),
    SheetFont.SYMBOL: ("azomix", "kst32b", "unicode", VI_STYLE),
    SheetFont.CJK: ("unicode", "kst32b", "azomix", VI_STYLE),
}
#: the font file AutoCAD draws each style with
_STYLE_FONT = {"kst32b": SheetFont.ISO, "azomix": SheetFont.SYMBOL, "unicode": SheetFont.CJK,
               VI_STYLE: SheetFont.ISO}
#: layer of the title-block values repeated as plain TEXT for viewers that ignore attributes
TITLE_VALUES_LAYER = "TITLE_VALUES"
_VI_LETTERS = frozenset("ăâđêôơưĂÂĐÊÔƠƯ")


def _vietnamese(text: str) -> bool:
    return any(c in _VI_LETTERS or 0x1EA0 <= ord(c) <= 0x1EF9 for c in text)

_ALIGN = {
    (HAlign.LEFT, VAlign.BASELINE): TextEntityAlignment.LEFT,
    (HAlign.CENTER, VAlign.BASELINE): TextEntityAlignment.CENTER,
    (HAlign.RIGHT, VAlign.BASELINE): TextEntityAlignment.RIGHT,
    (HAlign.LEFT, VAlign.BOTTOM): TextEntityAlignment.BOTTOM_LEFT,
    (HAlign.CENTER, VAlign.BOTTOM): TextEntityAlignment.BOTTOM_CENTER,
    (HAlign.RIGHT, VAlign.BOTTOM): TextEntityAlignment.BOTTOM_RIGHT,
    (HAlign.LEFT, VAlign.MIDDLE): TextEntityAlignment.MIDDLE_LEFT,
    (HAlign.CENTER, VAlign.MIDDLE): TextEntityAlignment.MIDDLE_CENTER,
    (HAlign.RIGHT, VAlign.MIDDLE): TextEntityAlignment.MIDDLE_RIGHT,
    (HAlign.LEFT, VAlign.TOP): TextEntityAlignment.TOP_LEFT,
    (HAlign.CENTER, VAlign.TOP): TextEntityAlignment.TOP_CENTER,
    (HAlign.RIGHT, VAlign.TOP): TextEntityAlignment.TOP_RIGHT,
}


def _setup(doc: Drawing, sheet: Sheet) -> None:
    w, h = sheet.width_mm, sheet.height_mm
    doc.units = 4  # $INSUNITS: millimetres
    header = doc.header
    header["$MEASUREMENT"] = 1
    header["$LWDISPLAY"] = 1
    header["$LUNITS"] = 2
    header["$LTSCALE"] = 1.0
    header["$CELTSCALE"] = 1.0
    header["$PSLTSCALE"] = 1
    header["$LIMMIN"] = (0.0, 0.0)
    header["$LIMMAX"] = (w, h)
    header["$EXTMIN"] = (0.0, 0.0, 0.0)
    header["$EXTMAX"] = (w, h, 0.0)
    header["$TEXTSTYLE"] = TEXT_STYLES[SheetFont.ISO]
    for lt, name in LINETYPE_NAMES.items():
        pattern = DASH_PATTERNS_MM[lt]
        if not pattern:
            continue
        elements = [v if i % 2 == 0 else -v for i, v in enumerate(pattern)]
        doc.linetypes.add(name, [sum(pattern), *elements],
                          description=_LINETYPE_DESCRIPTIONS[lt])
    doc.styles.get("Standard").dxf.font = SheetFont.ISO.file_name
    for style, font in _STYLE_FONT.items():
        doc.styles.add(style, font=font.file_name)
    for role in Role:
        st = role.style
        doc.layers.add(role.layer, color=st.aci, linetype=LINETYPE_NAMES[st.linetype],
                       lineweight=round(st.lineweight_mm * 100))
    st = Role.TEXT.style
    doc.layers.add(TITLE_VALUES_LAYER, color=st.aci, lineweight=round(st.lineweight_mm * 100))
    doc.set_modelspace_vport(height=h * 1.05, center=(w / 2.0, h / 2.0))
    paper = doc.paperspace()
    paper.page_setup(size=(w, h), margins=(0, 0, 0, 0), units="mm")
    paper.add_viewport(center=(w / 2.0, h / 2.0), size=(w, h), view_center_point=(w / 2.0, h / 2.0),
                       view_height=h)


#: MTEXT attachment point of a text's alignment (the baseline taken as the bottom)
_ATTACH = {(h, v): 1 + "LCR".index(h.name[0]) + 3 * {"TOP": 0, "MIDDLE": 1}.get(v.name, 2)
           for h in HAlign for v in VAlign}


def text_style(text: str, font: SheetFont | None = None) -> str:
    """Return the DXF text style of `text`: named after a LibreCAD font with all its glyphs.

    ``font`` is the sheet font the text is drawn in (its paragraph's); by default the string's own.
    """
    font = font or font_for(text)
    if font is SheetFont.ISO and _vietnamese(text):
        return VI_STYLE
    order = _STYLE_ORDER[font]
    fonts = stroke_fonts()
    drawn = "".join(r for r, _ in glyph_runs(text))     # as the TEXT or MTEXT draws it
    return next((s for s in order if fonts[s].has(drawn)), order[0])


def fitted_width_factor(t: Text, style: str) -> float:
    """Return the width factor that keeps `t` inside the box the sheet measured for it.

    The layout measures text in the sheet fonts (osifont …); LibreCAD draws the style's stroke
    font, up to 40 % wider (Cyrillic in kst32b): such a text is condensed to its measured width.
    AutoCAD draws the style's font file, at most as wide as measured.
    """
    string = plain(t.string)
    measured = text_width_mm(string, t.height_mm, font_of(t))
    drawn = stroke_fonts()[style].width_mm(string, t.height_mm)
    if drawn <= measured or drawn <= 0.0:
        return t.width_factor
    return t.width_factor * measured / drawn


#: LibreCAD draws a stack's halves at 4/9 of the text height
_STACK_SCALE = 4.0 / 9.0


def fitted_mtext_height(t: Text, style: str) -> float:
    """Return the MTEXT height that keeps `t` (with stacked scripts) inside its measured box.

    LibreCAD reads no width factor in MTEXT, so a label its stroke font draws wider than the sheet
    measured it is drawn smaller instead.
    """
    font = stroke_fonts()[style]
    h = t.height_mm
    parts = glyph_runs(t.string)
    drawn, i = 0.0, 0
    while i < len(parts):
        text, shift = parts[i]
        if shift == 0:
            drawn += font.width_mm(text, h)
        else:
            lower = parts[i + 1][0] if shift > 0 and i + 1 < len(parts) and parts[i + 1][1] < 0 \
                else ""
            i += 1 if lower else 0
            drawn += max(font.width_mm(text, h * _STACK_SCALE),
                         font.width_mm(lower, h * _STACK_SCALE))
        i += 1
    drawn += (len(parts) - 1) * font.letter_spacing * h / 9.0
    measured = text_width_mm(t.string, h, font_of(t))   # as the sheet measured it
    return h if drawn <= measured or drawn <= 0.0 else h * measured / drawn


def _text_attribs(t: Text) -> dict[str, object]:
    style = text_style(t.string, font_of(t))
    return {
        "layer": t.role.layer,
        "style": style,
        "height": t.height_mm,
        "rotation": t.rotation_deg,
        "width": math.floor(fitted_width_factor(t, style) * 1e4) / 1e4,   # never wider
    }


def _add(layout: BaseLayout, p: Primitive, dx: float = 0.0, dy: float = 0.0) -> None:
    """Add primitive `p` to `layout`, shifted by (-dx, -dy) (block-local coordinates)."""
    def q(pt: tuple[float, float]) -> tuple[float, float]:
        return (pt[0] - dx, pt[1] - dy)

    if isinstance(p, Block):
        raise DrawingError(f"block '{p.name}' must be placed on the sheet, not inside a layout")
    layer = {"layer": p.role.layer}
    if isinstance(p, Line):
        layout.add_line(q(p.start), q(p.end), dxfattribs=layer)
    elif isinstance(p, Polyline):
        if p.filled:
            hatch = layout.add_hatch(color=256, dxfattribs=layer)  # colour by layer
            hatch.paths.add_polyline_path([q(v) for v in p.points], is_closed=True)
        else:
            layout.add_lwpolyline([q(v) for v in p.points], format="xy", close=p.closed,
                                  dxfattribs=layer)
    elif isinstance(p, Circle):
        layout.add_circle(q(p.center), p.radius, dxfattribs=layer)
    elif isinstance(p, Arc):
        layout.add_arc(q(p.center), p.radius, p.start_deg, p.end_deg, dxfattribs=layer)
    elif isinstance(p, Arrow):
        shaft = p.shaft()
        if shaft is not None:
            layout.add_line(q(shaft.start), q(shaft.end), dxfattribs=layer)
        layout.add_solid([q(v) for v in p.head()], dxfattribs=layer)
    elif isinstance(p, Text):
        if p.tag is not None and isinstance(layout, BlockLayout):
            attdef = layout.add_attdef(p.tag, q(p.position), p.string,
                                       dxfattribs={**_text_attribs(p), "prompt": p.tag})
            attdef.set_placement(q(p.position), align=_ALIGN[(p.halign, p.valign)])
        elif p.string and (has_scripts(p.string) or has_unicode_scripts(p.string)):
            # real sub- and superscripts: an MTEXT with height and alignment codes; so are the
            # Unicode ones ("1,1×10⁻¹⁶" of the number writers), which no LibreCAD font has
            attribs = _text_attribs(p)
            style = str(attribs["style"])
            layout.add_mtext(mtext(p.string), dxfattribs={
                "layer": attribs["layer"], "style": style,
                "char_height": round(fitted_mtext_height(p, style), 4),
                "rotation": p.rotation_deg, "insert": q(p.position),
                "attachment_point": _ATTACH[(p.halign, p.valign)]})
        elif p.string:
            text = layout.add_text(p.string, dxfattribs=_text_attribs(p))
            text.set_placement(q(p.position), align=_ALIGN[(p.halign, p.valign)])
    else:
        raise DrawingError(f"DXF backend cannot draw {type(p).__name__}")


def _add_block(doc: Drawing, blk: Block) -> None:
    ox, oy = blk.origin
    definition = doc.blocks.new(blk.name, base_point=(0, 0))
    for p in blk.primitives:
        _add(definition, p, ox, oy)
    ref = doc.modelspace().add_blockref(blk.name, (ox, oy), dxfattribs={"layer": "0"})
    ref.add_auto_attribs(blk.attributes)
    # the values once more as plain TEXT on their own layer: LibreCAD and other viewers do not
    # draw block attributes (freeze the layer in AutoCAD before editing the attributes)
    for p in blk.primitives:
        if not isinstance(p, Text) or not p.tag:
            continue
        value = blk.attributes.get(p.tag, "")
        if value:
            text = doc.modelspace().add_text(value, dxfattribs={
                **_text_attribs(dataclasses.replace(p, string=value, tag=None)),
                "layer": TITLE_VALUES_LAYER})
            text.set_placement(p.position, align=_ALIGN[(p.halign, p.valign)])


def to_document(sheet: Sheet) -> Drawing:
    """Build the ezdxf document of `sheet` (R2013, mm, 1 drawing unit = 1 sheet mm)."""
    doc = ezdxf.new("R2013", setup=False)
    doc.encoding = ENCODINGS[sheet.language]
    _setup(doc, sheet)
    msp = doc.modelspace()
    for p in sheet.primitives:
        if isinstance(p, Block):
            _add_block(doc, p)
        else:
            _add(msp, p)
    auditor = doc.audit()
    if auditor.has_errors:
        messages = "; ".join(str(e.message) for e in auditor.errors[:5])
        raise DrawingError(
            f"DXF audit must report no errors (got {len(auditor.errors)}: {messages})"
        )
    return doc


def to_bytes(sheet: Sheet) -> bytes:
    """Return the DXF file of `sheet` (UTF-8, as every DXF R2007+ file)."""
    doc = to_document(sheet)
    stream = io.StringIO()
    doc.write(stream)
    return doc.encode(stream.getvalue())
