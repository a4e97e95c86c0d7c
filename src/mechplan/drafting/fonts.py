"""Sheet fonts: which files, which font a string needs, how wide a string is.

osifont (ISO 3098 lettering; Latin, Vietnamese, Cyrillic, Greek) is the default; DejaVu Sans shows
the plan symbols osifont lacks; a CJK font (Noto Sans CJK SC) shows Chinese. Heights are ISO 3098
capital heights, so backends that size text by the em (SVG, matplotlib) scale by the font's
capital-height ratio.

The files are the ones mechplan ships (``src/mechplan/fonts``: osifont and a GB 2312 subset of Noto
Sans CJK SC; DejaVu Sans from matplotlib's data folder), so a sheet measures and embeds the same
fonts on every machine whatever fonts it has installed. ``MECHPLAN_FONT_DIRS`` (folders searched
first) and ``MECHPLAN_SYSTEM_FONTS=1`` (``mechplan draw --system-fonts``: the system's font folders
before the bundled files) are the opt-ins to other files; `font_source` says which one is used.
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

#: folders searched before the bundled fonts (os.pathsep-separated)
ENV_FONT_DIRS = "MECHPLAN_FONT_DIRS"
#: "1": the system's font folders are searched before the bundled fonts
ENV_SYSTEM_FONTS = "MECHPLAN_SYSTEM_FONTS"

_SYSTEM_DIRS = (
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
    """A sheet font: family, bundled file, file names to look for elsewhere, fallback metrics."""

    family: str
    bundled: str  # file name in BUNDLED_DIR (DejaVu: in matplotlib's data folder)
    dxf_file: str  # the file a DXF text style names for AutoCAD (fixed: DXFs never vary by machine)
    file_names: tuple[str, ...]  # names of the same font installed on a system
    collection_index: int  # face of the family in a .ttc collection
    cap_ratio: float  # capital height / em, used when no file can be read
    advance_em: float  # typical advance width / em, used when no file can be read


class SheetFont(Enum):
    """The fonts a sheet uses: ISO lettering, a symbol fallback (⊥ ∥ ′ → ✓), CJK."""

    ISO = FontSpec("osifont", "osifont.ttf", "osifont.ttf", ("osifont-lgpl3fe.ttf", "osifont.ttf"),
                   0, 0.74, 0.6)
    # DejaVu Sans covers the plan symbols osifont lacks; it is small, so PDFs embed it quickly
    SYMBOL = FontSpec("DejaVu Sans", "DejaVuSans.ttf", "DejaVuSans.ttf", ("DejaVuSans.ttf",), 0,
                      0.729, 0.6)
    # TrueType outlines (not CFF), so that PDFs embed it as a valid Type 42 font
    CJK = FontSpec(
        "Noto Sans CJK SC",
        "NotoSansCJKsc-Regular.ttf",
        "NotoSansCJKsc-Regular.otf",
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
        """Return the font file name a DXF text style refers to (the same on every machine)."""
        return self.value.dxf_file


#: Fallback families for backends that pick glyphs per character (SVG, matplotlib).
FALLBACK_FAMILIES: tuple[str, ...] = ("DejaVu Sans",)


#: fonts installed with mechplan: osifont and a subset of Noto Sans CJK SC (see the licences there)
BUNDLED_DIR = Path(__file__).resolve().parents[1] / "fonts"


def bundled_path(font: SheetFont) -> Path:
    """Return the file of `font` installed with mechplan (or with matplotlib, for DejaVu Sans)."""
    if font is SheetFont.SYMBOL:
        import matplotlib  # its own copy of DejaVu Sans

        return Path(matplotlib.get_data_path()) / "fonts" / "ttf" / font.value.bundled
    return BUNDLED_DIR / font.value.bundled


def system_fonts_enabled() -> bool:
    """Return True if the user asked for the system's fonts (``MECHPLAN_SYSTEM_FONTS=1``)."""
    return os.environ.get(ENV_SYSTEM_FONTS, "").strip().lower() in ("1", "true", "yes", "on")


def _search_dirs(extra: str, system: bool) -> Iterable[Path]:
    for d in [*filter(None, extra.split(os.pathsep)), *(_SYSTEM_DIRS if system else ())]:
        p = Path(d).expanduser()
        if p.is_dir():
            yield p


def font_path(font: SheetFont) -> Path | None:
    """Return the file `font` is drawn and measured with (bundled unless the user opted in)."""
    return _font_path(font, os.environ.get(ENV_FONT_DIRS, ""), system_fonts_enabled())


def font_source(font: SheetFont) -> str:
    """Return where `font_path(font)` comes from: "bundled", "MECHPLAN_FONT_DIRS", "system"."""
    path = font_path(font)
    if path is None or path == bundled_path(font):
        return "bundled"
    extra = [Path(d).expanduser().resolve() for d in
             filter(None, os.environ.get(ENV_FONT_DIRS, "").split(os.pathsep))]
    return ENV_FONT_DIRS if any(path.resolve().is_relative_to(d) for d in extra) else "system"


@functools.cache
def _font_path(font: SheetFont, extra: str, system: bool) -> Path | None:
    wanted = {n.lower() for n in (*font.value.file_names, font.value.bundled)}
    for d in _search_dirs(extra, system):
        for root, _dirs, files in sorted(os.walk(d)):
            for f in sorted(files):
                if f.lower() in wanted:
                    return Path(root) / f
    path = bundled_path(font)
    if path.is_file():
        return path
    log.info("font %s not found; text metrics are estimated", font.family)
    return None


def face_index(path: Path, font: SheetFont) -> int:
    """Return the face of `font` in the file `path` (0 unless a collection)."""
    return font.value.collection_index if path.suffix.lower() in (".ttc", ".otc") else 0


@dataclass(frozen=True, slots=True)
class _Metrics:
    units_per_em: int
    cap_height: int
    advances: dict[int, int]  # code point -> advance width in font units


def _metrics(font: SheetFont) -> _Metrics | None:
    return _metrics_of(font, os.environ.get(ENV_FONT_DIRS, ""), system_fonts_enabled())


@functools.cache       # thousands of calls per sheet: keyed by the enum, not by the file's Path
def _metrics_of(font: SheetFont, extra: str, system: bool) -> _Metrics | None:
    path = _font_path(font, extra, system)
    if path is None:
        return None
    # only osifont has placeholder boxes (Ё ё Э э); expanding every glyph of the other fonts
    # would cost half a second per drawing
    return _read_metrics(path, face_index(path, font), font is SheetFont.ISO,
                         font.value.cap_ratio)


@functools.cache
def _read_metrics(path: Path, index: int, placeholders: bool, cap_ratio: float) -> _Metrics | None:
    try:
        tt = TTFont(path, fontNumber=index, lazy=True)
        upem = int(tt["head"].unitsPerEm)
        os2 = tt["OS/2"]
        cap = int(getattr(os2, "sCapHeight", 0) or 0) or int(upem * cap_ratio)
        cmap = tt.getBestCmap()
        hmtx = tt["hmtx"]
        glyf = tt.get("glyf") if placeholders else None
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


def missing_glyphs(strings: Iterable[str]) -> str:
    """Return the characters of `strings` that no sheet font has, sorted (empty when none).

    With the bundled fonts these are Chinese characters outside GB 2312 (and rare symbols): every
    backend draws them as the font's empty box (.notdef), the same on every machine; the user can
    opt in to a full font with ``--system-fonts`` or ``MECHPLAN_FONT_DIRS``.
    """
    chars = {c for s in strings for c in s if not c.isspace()}
    tables = [m.advances for f in SheetFont if (m := _metrics(f)) is not None]
    if not tables:
        return ""
    return "".join(sorted(c for c in chars if not any(ord(c) in t for t in tables)))
