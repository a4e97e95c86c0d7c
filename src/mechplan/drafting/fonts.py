"""Sheet fonts: where the files are, which font a string needs, how wide a string is.

osifont (ISO 3098 lettering; Latin, Vietnamese, Cyrillic, Greek) is the default; a CJK font (Noto
Sans CJK SC) is used for strings it cannot show. Heights are ISO 3098 capital heights, so backends
that size text by the em (SVG, matplotlib) scale by the font's capital-height ratio.
"""

from __future__ import annotations

import functools
import logging
import math
import os
from collections.abc import Iterable
from dataclasses import dataclass
from enum import Enum
from pathlib import Path

from fontTools.ttLib import TTFont, TTLibError

from mechplan.drafting.primitives import Text, VAlign

log = logging.getLogger(__name__)

_FONT_DIRS = (
    "/usr/share/fonts",
    "/usr/local/share/fonts",
    "~/.local/share/fonts",
    "~/.fonts",
    "C:/Windows/Fonts",
    "/Library/Fonts",
    "/System/Library/Fonts",
)


@dataclass(frozen=True, slots=True)
class FontSpec:
    """A sheet font: family name, candidate file names, fallback metrics."""

    family: str
    file_names: tuple[str, ...]
    collection_index: int
    cap_ratio: float  # capital height / em, used when the file is missing
    advance_em: float  # typical advance width / em, used when the file is missing


class SheetFont(Enum):
    """The fonts a sheet uses: ISO lettering, a symbol fallback (⊥ ∥ ′ → ✓), CJK."""

    ISO = FontSpec("osifont", ("osifont-lgpl3fe.ttf", "osifont.ttf"), 0, 0.74, 0.6)
    # DejaVu Sans covers the plan symbols osifont lacks; it is small, so PDFs embed it quickly
    # where the CJK collection would take a second to subset
    SYMBOL = FontSpec("DejaVu Sans", ("DejaVuSans.ttf",), 0, 0.729, 0.6)
    CJK = FontSpec(
        "Noto Sans CJK SC",
        ("NotoSansCJK-Regular.ttc", "NotoSansCJKsc-Regular.otf", "NotoSansSC-Regular.otf"),
        2,  # index of "Noto Sans CJK SC" in the Debian collection
        0.733,
        1.0,
    )

    @property
    def spec(self) -> FontSpec:
        """Return the font's description."""
        return self.value

    @property
    def family(self) -> str:
        """Return the font family name."""
        return self.value.family

    @property
    def file_name(self) -> str:
        """Return the font file name a DXF text style refers to (the one installed, if any)."""
        path = font_path(self)
        return path.name if path else self.value.file_names[0]


#: Fallback families for backends that pick glyphs per character (SVG, matplotlib).
FALLBACK_FAMILIES: tuple[str, ...] = ("DejaVu Sans",)


#: fonts installed with mechplan: osifont and a subset of Noto Sans CJK SC (see the licences there)
BUNDLED_DIR = Path(__file__).resolve().parents[1] / "fonts"


def _font_dirs() -> Iterable[Path]:
    extra = os.environ.get("MECHPLAN_FONT_DIRS", "")
    import matplotlib  # its own copy of DejaVu Sans is a last resort

    mpl_fonts = str(Path(matplotlib.get_data_path()) / "fonts" / "ttf")
    # the system's fonts first (a full CJK font covers more than the bundled subset)
    for d in [*filter(None, extra.split(os.pathsep)), *_FONT_DIRS, str(BUNDLED_DIR), mpl_fonts]:
        p = Path(d).expanduser()
        if p.is_dir():
            yield p


@functools.cache
def font_path(font: SheetFont) -> Path | None:
    """Return the installed file of `font`, or None (searched once per process)."""
    wanted = {n.lower() for n in font.value.file_names}
    for d in _font_dirs():
        for root, _dirs, files in os.walk(d):
            for f in files:
                if f.lower() in wanted:
                    return Path(root) / f
    log.info("font %s not found; text metrics are estimated", font.family)
    return None


@dataclass(frozen=True, slots=True)
class _Metrics:
    units_per_em: int
    cap_height: int
    advances: dict[int, int]  # code point -> advance width in font units


@functools.cache
def _metrics(font: SheetFont) -> _Metrics | None:
    path = font_path(font)
    if path is None:
        return None
    try:
        tt = TTFont(path, fontNumber=font.value.collection_index, lazy=True)
        upem = int(tt["head"].unitsPerEm)
        os2 = tt["OS/2"]
        cap = int(getattr(os2, "sCapHeight", 0) or 0) or int(upem * font.value.cap_ratio)
        cmap = tt.getBestCmap()
        hmtx = tt["hmtx"]
        # only osifont has placeholder boxes (Ё ё Э э); expanding every glyph of the other fonts
        # would cost half a second per drawing
        glyf = tt.get("glyf") if font is SheetFont.ISO else None
        advances = {
            cp: int(hmtx[name][0])
            for cp, name in cmap.items()
            if glyf is None or not _is_placeholder(glyf[name], upem)
        }
        tt.close()
    except (OSError, KeyError, ValueError, TTLibError) as exc:  # a broken font stops no drawing
        log.warning("cannot read font %s (%s); text metrics are estimated", path, exc)
        return None
    return _Metrics(upem, cap, advances)


def _is_placeholder(glyph: object, upem: int) -> bool:
    """Return True for a filled-box glyph standing in for a missing letter.

    Debian's osifont maps Ё, ё, Э, э to such boxes; strings with them go to the CJK font instead.
    """
    if getattr(glyph, "numberOfContours", 0) != 1:
        return False
    coords = list(getattr(glyph, "coordinates", []))
    if len(coords) != 4:
        return False
    xs, ys = [c[0] for c in coords], [c[1] for c in coords]
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    area = abs(sum(xs[i] * ys[i - 1] - xs[i - 1] * ys[i] for i in range(4))) / 2.0
    return bool(w > 0.15 * upem and h > 0.15 * upem and area > 0.85 * w * h)


def cap_ratio(font: SheetFont) -> float:
    """Return capital height / em of `font` (em size = ISO height / this)."""
    m = _metrics(font)
    return m.cap_height / m.units_per_em if m else font.value.cap_ratio


def _is_cjk(cp: int) -> bool:
    return (
        0x2E80 <= cp <= 0x9FFF  # radicals, kana, CJK symbols, unified ideographs
        or 0xAC00 <= cp <= 0xD7AF  # hangul
        or 0xF900 <= cp <= 0xFAFF
        or 0xFE30 <= cp <= 0xFE4F
        or 0xFF00 <= cp <= 0xFFEF  # full-width forms
        or 0x20000 <= cp <= 0x3FFFF
    )


def has_cjk(text: str) -> bool:
    """Return True if `text` contains CJK characters."""
    return any(_is_cjk(ord(c)) for c in text)


def covers(font: SheetFont, text: str) -> bool:
    """Return True if `font` has a glyph for every non-space character of `text`."""
    m = _metrics(font)
    if m is None:
        return font is SheetFont.CJK or not has_cjk(text)
    return all(ord(c) in m.advances for c in text if not c.isspace())


def font_for(text: str) -> SheetFont:
    """Return the font that shows `text`: osifont unless the string needs the CJK font."""
    if has_cjk(text):
        return SheetFont.CJK
    if covers(SheetFont.ISO, text):
        return SheetFont.ISO
    if covers(SheetFont.SYMBOL, text):
        return SheetFont.SYMBOL
    if not covers(SheetFont.CJK, text):
        return SheetFont.ISO
    return SheetFont.CJK


def font_of(text: Text) -> SheetFont:
    """Return the font a text is drawn in: its paragraph's (``Text.font``) or its string's."""
    return SheetFont[text.font] if text.font else font_for(text.string)


def paragraph_font(lines: Iterable[str]) -> SheetFont:
    """Return the one font that shows every line of a paragraph (so its lines never differ)."""
    return font_for(" ".join(lines))


def text_width_mm(text: str, height_mm: float, font: SheetFont | None = None) -> float:
    """Return the advance width of `text` at ISO capital height `height_mm`."""
    font = font or font_for(text)
    m = _metrics(font)
    em_mm = height_mm / cap_ratio(font)
    if m is None:
        return sum(1.0 if _is_cjk(ord(c)) else font.value.advance_em for c in text) * em_mm
    fallback = {SheetFont.ISO: 0.6, SheetFont.SYMBOL: 0.6, SheetFont.CJK: 1.0}[
        font
    ] * m.units_per_em
    units = sum(
        m.advances.get(ord(c), 1.0 * m.units_per_em if _is_cjk(ord(c)) else fallback) for c in text
    )
    return units / m.units_per_em * em_mm


def families_for(text: str, font: SheetFont | None = None) -> tuple[str, ...]:
    """Return the family fallback list for `text`, its own font (or `font`) first."""
    first = font or font_for(text)
    others = [f.family for f in SheetFont if f is not first]
    return tuple(dict.fromkeys((first.family, *others, *FALLBACK_FAMILIES)))


def baseline_shift_mm(valign: VAlign, height_mm: float) -> float:
    """Return the offset from a text's anchor to its baseline along the text's up direction.

    Matches DXF TEXT alignment: BOTTOM is the descender line (3/10 h below the baseline per ISO
    3098), MIDDLE half the capital height, TOP the capital line.
    """
    return {
        VAlign.BASELINE: 0.0,
        VAlign.BOTTOM: 0.3 * height_mm,
        VAlign.MIDDLE: -0.5 * height_mm,
        VAlign.TOP: -height_mm,
    }[valign]


def baseline_point(text: Text) -> tuple[float, float]:
    """Return the anchor point of `text` moved onto its baseline, in sheet mm."""
    shift = baseline_shift_mm(text.valign, text.height_mm)
    a = math.radians(text.rotation_deg)
    x, y = text.position
    return (x - math.sin(a) * shift, y + math.cos(a) * shift)


def em_size_mm(text: Text) -> float:
    """Return the em size (font size) in mm that gives `text` its ISO capital height."""
    return text.height_mm / cap_ratio(font_of(text))
