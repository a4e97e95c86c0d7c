"""Sheet frames and title blocks: ISO 5457 + ISO 7200, ГОСТ 2.301/2.104 form 1, TCVN 7285 form.

`make_frame` returns the frame lines, the title block as a `Block` whose field values are tagged
texts (DXF ATTRIBs), and the free drawing area (frame interior minus title block) as a shapely
polygon.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from enum import Enum
from types import MappingProxyType

from shapely.geometry import Polygon, box

from mechplan.drafting.fields import TITLE_BLOCK_FIELDS
from mechplan.drafting.fonts import text_width_mm
from mechplan.drafting.primitives import (
    LANGUAGES,
    Block,
    HAlign,
    Line,
    Point,
    Polyline,
    Primitive,
    Role,
    Sheet,
    Text,
    VAlign,
)
from mechplan.errors import DrawingError
from mechplan.i18n import message

from ..i18n import Text as Msg


class Standard(Enum):
    """Drafting standard of the frame and title block."""

    ISO = "iso"
    GOST = "gost"
    TCVN = "tcvn"


class Orientation(Enum):
    """Sheet orientation."""

    LANDSCAPE = "landscape"
    PORTRAIT = "portrait"


#: ISO 5457 trimmed sheet sizes (short side, long side) in mm; the same in TCVN 7285, ГОСТ 2.301.
PAPER_SIZES_MM: Mapping[str, tuple[float, float]] = MappingProxyType(
    {"A0": (841.0, 1189.0), "A1": (594.0, 841.0), "A2": (420.0, 594.0),
     "A3": (297.0, 420.0), "A4": (210.0, 297.0)}
)

#: Field names accepted by `make_frame`.
TITLE_FIELDS: tuple[str, ...] = TITLE_BLOCK_FIELDS

#: Margins (left, bottom, right, top) in mm.
_MARGINS = {
    Standard.ISO: (20.0, 10.0, 10.0, 10.0),
    Standard.TCVN: (20.0, 10.0, 10.0, 10.0),
    Standard.GOST: (20.0, 5.0, 5.0, 5.0),
}
_TITLE_SIZE = {Standard.ISO: (180.0, 40.0), Standard.TCVN: (180.0, 40.0),
               Standard.GOST: (185.0, 55.0)}

_LABEL_H = 2.5
_PAD = 1.0


@dataclass(frozen=True, slots=True)
class Rect:
    """An axis-parallel rectangle in sheet mm."""

    x0: float
    y0: float
    x1: float
    y1: float

    @property
    def width(self) -> float:
        """Return the width in mm."""
        return self.x1 - self.x0

    @property
    def height(self) -> float:
        """Return the height in mm."""
        return self.y1 - self.y0

    def polygon(self) -> Polygon:
        """Return the rectangle as a shapely polygon."""
        return box(self.x0, self.y0, self.x1, self.y1)


@dataclass(frozen=True, slots=True)
class FrameLayout:
    """A framed sheet without content: primitives, frame and title-block rectangles, free area."""

    width_mm: float
    height_mm: float
    standard: Standard
    size: str
    language: str
    frame: Rect
    title_block: Rect
    drawing_area: Polygon
    primitives: tuple[Primitive, ...]
    fields: Mapping[str, str] = field(default_factory=dict)

    def sheet(self, primitives: Sequence[Primitive] = (), name: str = "sheet") -> Sheet:
        """Return a `Sheet` of the frame, the title block and `primitives`."""
        return Sheet(self.width_mm, self.height_mm, self.primitives + tuple(primitives),
                     dict(self.fields), self.language, name)


# ---------------------------------------------------------------------------------------------
# Labels
# ---------------------------------------------------------------------------------------------

#: keys of the labelled fields of a title block (texts: ``drafting.title_block.<key>``)
_LABEL_KEYS = ("school", "department", "document_type", "author", "instructor", "group", "date",
               "scale", "language", "title", "designation", "sheet")


def _labels(language: str) -> dict[str, str]:
    return {key: message(f"drafting.title_block.{key}", language) for key in _LABEL_KEYS}


# ---------------------------------------------------------------------------------------------
# Text fitting
# ---------------------------------------------------------------------------------------------

def _split_two(text: str) -> tuple[str, str] | None:
    spaces = [i for i, c in enumerate(text) if c == " "]
    if not spaces:
        return None
    best = min(spaces, key=lambda i: abs(len(text[:i]) - len(text[i + 1:])))
    return text[:best], text[best + 1:]


def _fit(text: str, width: float, height: float, max_h: float, max_lines: int,
         what: str) -> list[tuple[str, float, float]]:
    """Return lines (string, height, width factor) fitting `text` into a width × height box."""
    heights = [h for h in (10.0, 7.0, 5.0, 3.5, 2.5) if h <= max_h]
    if not text:
        return [("", heights[-1] if heights else 2.5, 1.0)]
    one = next((h for h in heights
                if 1.4 * h <= height and text_width_mm(text, h) <= width), None)
    parts = _split_two(text) if max_lines >= 2 else None
    two = None
    if parts:
        two = next((h for h in heights if 3.0 * h <= height
                    and max(text_width_mm(p, h) for p in parts) <= width), None)
    if two is not None and parts and (one is None or two > one):
        return [(parts[0], two, 1.0), (parts[1], two, 1.0)]
    if one is not None:
        return [(text, one, 1.0)]
    for h, min_factor in ((2.5, 0.7), (1.8, 1.0), (1.8, 0.6)):
        if 1.4 * h > height:
            continue
        factor = width / text_width_mm(text, h)
        if factor >= min_factor:
            return [(text, h, min(1.0, factor))]
    raise DrawingError(
        Msg(
            "errmsg.drafting_frame.title_block_field",
            {
                "what": str(what),
                "width": f"{width:.0f}",
                "height": f"{height:.0f}",
                "text": repr(text),
                "text2": f"{text_width_mm(text, 1.8):.0f}",
            },
        )
    )


@dataclass(slots=True)
class _Builder:
    """Collects title-block primitives in local coordinates, shifted to the sheet on output."""

    ox: float
    oy: float
    out: list[Primitive] = field(default_factory=list)

    def p(self, x: float, y: float) -> Point:
        return (self.ox + x, self.oy + y)

    def line(self, x0: float, y0: float, x1: float, y1: float, role: Role = Role.TABLE) -> None:
        self.out.append(Line(self.p(x0, y0), self.p(x1, y1), role))

    def rect(self, x0: float, y0: float, x1: float, y1: float, role: Role = Role.FRAME) -> None:
        pts = (self.p(x0, y0), self.p(x1, y0), self.p(x1, y1), self.p(x0, y1))
        self.out.append(Polyline(pts, role, closed=True))

    def label(self, x: float, y: float, s: str, halign: HAlign = HAlign.LEFT,
              valign: VAlign = VAlign.MIDDLE, h: float = _LABEL_H) -> None:
        self.out.append(Text(self.p(x, y), s, h, halign=halign, valign=valign))

    def value(self, cell: tuple[float, float, float, float], tag: str, s: str, *,
              max_h: float = 3.5, halign: HAlign = HAlign.CENTER, max_lines: int = 1) -> None:
        """Place field `s` (attribute `tag`) centred vertically in `cell` = (x0, y0, x1, y1)."""
        x0, y0, x1, y1 = cell
        lines = _fit(s, x1 - x0 - 2 * _PAD, y1 - y0, max_h, max_lines, tag.lower())
        if halign is HAlign.LEFT:
            x = x0 + _PAD
        elif halign is HAlign.RIGHT:
            x = x1 - _PAD
        else:
            x = (x0 + x1) / 2.0
        ym = (y0 + y1) / 2.0
        pitch = 1.6 * lines[0][1]
        for i, (string, h, factor) in enumerate(lines):
            y = ym + pitch * ((len(lines) - 1) / 2.0 - i)
            self.out.append(Text(self.p(x, y), string, h, halign=halign, valign=VAlign.MIDDLE,
                                 tag=tag if i == 0 else f"{tag}_{i + 1}", width_factor=factor))

    def labelled(self, cell: tuple[float, float, float, float], label: str, tag: str, s: str, *,
                 max_h: float = 3.5, max_lines: int = 1, halign: HAlign = HAlign.CENTER) -> None:
        """Place a small label in the top-left corner of `cell` and the value below it."""
        x0, y0, x1, y1 = cell
        self.label(x0 + _PAD, y1 - _PAD, label, valign=VAlign.TOP)
        self.value((x0, y0 + 0.5, x1, y1 - _LABEL_H - 1.5), tag, s, max_h=max_h,
                   max_lines=max_lines, halign=halign)


# ---------------------------------------------------------------------------------------------
# Title blocks (local coordinates: origin at the block's bottom-left corner)
# ---------------------------------------------------------------------------------------------

def _sheet_of(f: Mapping[str, str]) -> str:
    n, total = f.get("sheet_number", ""), f.get("sheets_total", "")
    return f"{n}/{total}" if n and total else n


def _iso_block(b: _Builder, f: Mapping[str, str], language: str) -> None:
    lab = _labels(language)
    b.rect(0, 0, 180, 40)
    for y in (10, 20, 30):
        b.line(0, y, 70, y)
    b.line(70, 30, 180, 30)
    b.line(70, 10, 180, 10)
    b.line(70, 0, 70, 40)
    b.line(35, 0, 35, 30)
    b.line(125, 30, 125, 40)
    b.line(140, 0, 140, 10)
    b.labelled((0, 30, 70, 40), lab["school"], "SCHOOL", f.get("school", ""))
    b.labelled((70, 30, 125, 40), lab["department"], "DEPARTMENT", f.get("department", ""))
    b.labelled((125, 30, 180, 40), lab["document_type"], "DOCUMENT_TYPE",
               f.get("document_type", ""))
    b.labelled((0, 20, 35, 30), lab["author"], "AUTHOR", f.get("author", ""))
    b.labelled((35, 20, 70, 30), lab["instructor"], "INSTRUCTOR", f.get("instructor", ""))
    b.labelled((0, 10, 35, 20), lab["group"], "GROUP", f.get("group", ""))
    b.labelled((35, 10, 70, 20), lab["date"], "DATE", f.get("date", ""))
    b.labelled((0, 0, 35, 10), lab["scale"], "SCALE", f.get("scale", ""))
    b.labelled((35, 0, 70, 10), lab["language"], "LANGUAGE", language)
    b.labelled((70, 10, 180, 30), lab["title"], "TITLE", f.get("title", ""), max_h=7.0,
               max_lines=2)
    b.labelled((70, 0, 140, 10), lab["designation"], "DESIGNATION", f.get("designation", ""))
    b.labelled((140, 0, 180, 10), lab["sheet"], "SHEET", _sheet_of(f))


def _gost_block(b: _Builder, f: Mapping[str, str], size: str) -> None:
    # Grid of ГОСТ 2.104 form 1 (185 × 55): left part 7/10/23/15/10 mm in 11 rows of 5 mm,
    # name 70 × 25 and material 70 × 15, right part 50 mm (Лит. 15, Масса 17, Масштаб 18).
    b.rect(0, 0, 185, 55)
    thick = Role.FRAME
    for row in (30.0, 35.0):
        b.line(0, row, 65, row, thick)
    for row in (5.0, 10.0, 15.0, 20.0, 25.0, 40.0, 45.0, 50.0):
        b.line(0, row, 65, row)
    b.line(65, 40, 185, 40, thick)
    b.line(65, 15, 185, 15, thick)
    b.line(135, 35, 185, 35, thick)
    b.line(135, 20, 185, 20, thick)
    b.line(7, 30, 7, 55, thick)
    for col in (17.0, 40.0, 55.0, 65.0):
        b.line(col, 0, col, 55, thick)
    b.line(135, 0, 135, 40, thick)
    b.line(150, 20, 150, 40, thick)
    b.line(167, 20, 167, 40, thick)
    b.line(155, 15, 155, 20, thick)
    b.line(140, 20, 140, 35)
    b.line(145, 20, 145, 35)
    for x, s in ((3.5, "Изм."), (12, "Лист"), (28.5, "№ докум."), (47.5, "Подп."), (60, "Дата")):
        b.label(x, 32.5, s, HAlign.CENTER)
    for y, s in ((27.5, "Разраб."), (22.5, "Пров."), (17.5, "Т.контр."), (7.5, "Н.контр."),
                 (2.5, "Утв.")):
        b.label(1, y, s)
    for x, s in ((142.5, "Лит."), (158.5, "Масса"), (176, "Масштаб")):
        b.label(x, 37.5, s, HAlign.CENTER)
    b.label(136, 17.5, "Лист")
    b.label(156, 17.5, "Листов")
    b.label(75, -2.5, "Копировал")
    b.label(145, -2.5, f"Формат {size}")
    b.value((17, 25, 40, 30), "AUTHOR", f.get("author", ""), max_h=2.5, halign=HAlign.LEFT)
    b.value((17, 20, 40, 25), "INSTRUCTOR", f.get("instructor", ""), max_h=2.5,
            halign=HAlign.LEFT)
    b.value((55, 25, 65, 30), "DATE", f.get("date", ""), max_h=2.5)
    b.value((65, 40, 185, 55), "DESIGNATION", f.get("designation", ""), max_h=7.0)
    b.value((65, 15, 135, 40), "TITLE", f.get("title", ""), max_h=7.0, max_lines=2)
    b.value((65, 0, 135, 15), "MATERIAL", f.get("material", ""), max_h=5.0)
    b.value((135, 20, 140, 35), "LITERA", f.get("litera", ""), max_h=3.5)
    b.value((167, 20, 185, 35), "SCALE", f.get("scale", ""), max_h=5.0)
    b.value((145, 15, 155, 20), "SHEET", f.get("sheet_number", ""), max_h=2.5)
    b.value((169, 15, 185, 20), "SHEETS", f.get("sheets_total", ""), max_h=2.5)
    if f.get("group"):
        b.value((135, 5, 185, 15), "SCHOOL", f.get("school", ""), max_h=3.5, max_lines=2)
        b.value((135, 0, 185, 5), "GROUP", f["group"], max_h=2.5)
    else:
        b.value((135, 0, 185, 15), "SCHOOL", f.get("school", ""), max_h=3.5, max_lines=2)


def _tcvn_block(b: _Builder, f: Mapping[str, str]) -> None:
    # Vietnamese school title block (khung tên), 180 × 40: people | title | school.
    b.rect(0, 0, 180, 40)
    for x in (60, 130):
        b.line(x, 0, x, 40, Role.FRAME)
    for y in (8, 16, 24, 32):
        b.line(0, y, 60, y)
    b.line(18, 8, 18, 40)
    b.line(45, 16, 45, 40)
    b.line(18, 0, 18, 8)
    b.line(60, 32, 130, 32)
    b.line(60, 12, 130, 12)
    b.line(83, 0, 83, 12)
    b.line(106, 0, 106, 12)
    b.line(130, 22, 180, 22)
    b.line(130, 11, 180, 11)
    b.label(31.5, 36, "Họ và tên", HAlign.CENTER)
    b.label(52.5, 36, "Chữ ký", HAlign.CENTER)
    for y, s in ((28, "Người vẽ"), (20, "GVHD"), (12, "Lớp"), (4, "Ngày")):
        b.label(_PAD, y, s)
    b.value((18, 24, 45, 32), "AUTHOR", f.get("author", ""), max_h=2.5, halign=HAlign.LEFT)
    b.value((18, 16, 45, 24), "INSTRUCTOR", f.get("instructor", ""), max_h=2.5,
            halign=HAlign.LEFT)
    b.value((18, 8, 60, 16), "GROUP", f.get("group", ""), max_h=3.5, halign=HAlign.LEFT)
    b.value((18, 0, 60, 8), "DATE", f.get("date", ""), max_h=3.5, halign=HAlign.LEFT)
    b.value((60, 32, 130, 40), "DOCUMENT_TYPE",
            f.get("document_type") or "ĐỒ ÁN NGUYÊN LÝ MÁY", max_h=3.5)
    b.value((60, 12, 130, 32), "TITLE", f.get("title", ""), max_h=7.0, max_lines=2)
    b.labelled((60, 0, 83, 12), "Tỉ lệ", "SCALE", f.get("scale", ""))
    b.labelled((83, 0, 106, 12), "Tờ số", "SHEET", f.get("sheet_number", ""))
    b.labelled((106, 0, 130, 12), "Số tờ", "SHEETS", f.get("sheets_total", ""))
    b.labelled((130, 22, 180, 40), "Trường", "SCHOOL", f.get("school", ""), max_lines=2)
    b.labelled((130, 11, 180, 22), "Khoa", "DEPARTMENT", f.get("department", ""))
    b.labelled((130, 0, 180, 11), "Ký hiệu bản vẽ", "DESIGNATION", f.get("designation", ""))


# ---------------------------------------------------------------------------------------------
# Frame
# ---------------------------------------------------------------------------------------------

def _clean_fields(fields: Mapping[str, object] | None) -> dict[str, str]:
    out: dict[str, str] = {}
    for key, value in (fields or {}).items():
        if key not in TITLE_FIELDS:
            raise DrawingError(
                Msg(
                    "errmsg.drafting_frame.title_block_field2",
                    {"title_fields": ", ".join(TITLE_FIELDS), "key": repr(key)},
                ),
                key=str(key),
            )
        text = "" if value is None else str(value).strip()
        if "\n" in text or "\r" in text:
            raise DrawingError(
                Msg("errmsg.drafting_frame.title_block_field3", {"text": repr(text)}), key=key
            )
        out[key] = text
    return out


def paper_size(size: str, orientation: Orientation | str | None = None) -> tuple[float, float]:
    """Return (width, height) in mm of ISO sheet `size`; A4 is portrait, others landscape."""
    key = str(size).upper()
    if key not in PAPER_SIZES_MM:
        raise DrawingError(
            Msg(
                "errmsg.drafting_frame.sheet_size_one",
                {"paper_sizes_mm": ", ".join(PAPER_SIZES_MM), "size": repr(size)},
            )
        )
    short, long_ = PAPER_SIZES_MM[key]
    if orientation is None:
        orientation = Orientation.PORTRAIT if key == "A4" else Orientation.LANDSCAPE
    try:
        orient = Orientation(orientation)
    except ValueError as exc:
        raise DrawingError(
            Msg(
                "errmsg.drafting_frame.orientation_landscape_portrait",
                {"orientation": repr(orientation)},
            )
        ) from exc
    return (long_, short) if orient is Orientation.LANDSCAPE else (short, long_)


def make_frame(
    size: str = "A1",
    standard: Standard | str = Standard.ISO,
    fields: Mapping[str, object] | None = None,
    *,
    language: str = "en",
    orientation: Orientation | str | None = None,
) -> FrameLayout:
    """Lay out the frame and title block of an empty sheet.

    A4 defaults to portrait (the title block runs along the short side, as ISO 5457 and ГОСТ 2.104
    require); the other sizes to landscape. ISO labels follow `language`; ГОСТ labels are Russian
    and TCVN labels Vietnamese whatever the language.
    """
    try:
        std = Standard(standard)
    except ValueError as exc:
        raise DrawingError(
            Msg(
                "errmsg.drafting_frame.standard_one_value",
                {"value": ", ".join(s.value for s in Standard), "standard": repr(standard)},
            )
        ) from exc
    if language not in LANGUAGES:
        raise DrawingError(
            Msg(
                "errmsg.drafting_frame.language_one_languages",
                {"languages": str(LANGUAGES), "language": repr(language)},
            )
        )
    f = _clean_fields(fields)
    w, h = paper_size(size, orientation)
    ml, mb, mr, mt = _MARGINS[std]
    frame = Rect(ml, mb, w - mr, h - mt)
    tw, th = _TITLE_SIZE[std]
    if tw > frame.width + 1e-9 or th > frame.height:
        raise DrawingError(Msg("errmsg.drafting_frame.sheet_size_too", {"size": str(size),
                                                                         "value": str(std.value)}))
    title = Rect(frame.x1 - tw, frame.y0, frame.x1, frame.y0 + th)

    b = _Builder(title.x0, title.y0)
    if std is Standard.ISO:
        _iso_block(b, f, language)
    elif std is Standard.GOST:
        _gost_block(b, f, str(size).upper())
    else:
        _tcvn_block(b, f)
    block = Block(f"TITLE_BLOCK_{std.name}", (title.x0, title.y0), tuple(b.out))

    prims: list[Primitive] = [
        Polyline(((frame.x0, frame.y0), (frame.x1, frame.y0), (frame.x1, frame.y1),
                  (frame.x0, frame.y1)), Role.FRAME, closed=True)
    ]
    area = frame.polygon().difference(title.polygon())
    if std is not Standard.GOST:
        # ISO 5457 centring marks: from the trimmed edge to 5 mm inside the frame.
        cx, cy = w / 2.0, h / 2.0
        bottom = frame.y0 if title.x0 <= cx <= title.x1 else frame.y0 + 5
        marks = [((cx, 0.0), (cx, bottom)), ((cx, h), (cx, frame.y1 - 5)),
                 ((0.0, cy), (frame.x0 + 5, cy)), ((w, cy), (frame.x1 - 5, cy))]
        for a, c in marks:
            prims.append(Line(a, c, Role.FRAME))
            area = area.difference(box(min(a[0], c[0]) - 1, min(a[1], c[1]) - 1,
                                       max(a[0], c[0]) + 1, max(a[1], c[1]) + 1))
    prims.append(block)
    return FrameLayout(w, h, std, str(size).upper(), language, frame, title, area, tuple(prims),
                       MappingProxyType(f))
