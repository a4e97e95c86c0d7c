"""Frames and title blocks of ISO 5457/7200, ГОСТ 2.104 form 1 and the TCVN school form."""

from __future__ import annotations

import itertools
import math

import pytest
from shapely.geometry import LineString, box

from mechplan.errors import DrawingError
from mechplan.sheet import (
    PAPER_SIZES_MM,
    Block,
    Line,
    Polyline,
    Role,
    Text,
    make_frame,
    paper_size,
)
from mechplan.sheet.fonts import baseline_point, text_width_mm
from mechplan.sheet.primitives import HAlign

FIELDS = {"title": "Phân tích động học cơ cấu culít", "author": "Nguyễn Văn An", "group": "CK-K65",
              "instructor": "TS. Trần Bình", "school": "Trường Đại học Bách khoa Hà Nội",
              "department": "Khoa Cơ khí", "date": "12.05.2025", "scale": "1:2", "sheet_number": 2,
              "sheets_total": 3, "designation": "NLM-01"}


def _block(layout) -> Block:
    return next(p for p in layout.primitives if isinstance(p, Block))


def _segments(block: Block) -> list[tuple[tuple[float, float], tuple[float, float], Role]]:
    """Return the block's straight segments in block-local coordinates."""
    ox, oy = block.origin
    segs = []
    for p in block.primitives:
        if isinstance(p, Line):
            pts = [p.start, p.end]
        elif isinstance(p, Polyline):
            pts = list(p.points) + ([p.points[0]] if p.closed else [])
        else:
            continue
        for a, b in itertools.pairwise(pts):
            segs.append(((a[0] - ox, a[1] - oy), (b[0] - ox, b[1] - oy), p.role))
    return segs


def _text_box(t: Text):
    x, y = baseline_point(t)
    w = text_width_mm(t.string, t.height_mm) * t.width_factor
    x0 = {HAlign.LEFT: x, HAlign.CENTER: x - w / 2, HAlign.RIGHT: x - w}[t.halign]
    return box(x0, y - 0.2 * t.height_mm, x0 + w, y + 1.1 * t.height_mm)


@pytest.mark.parametrize(("size", "standard"),
                         list(itertools.product(PAPER_SIZES_MM, ["iso", "gost", "tcvn"])))
def test_frame_margins_title_block_and_free_area(size: str, standard: str) -> None:
    layout = make_frame(size, standard, FIELDS, language="vi")
    w, h = paper_size(size)
    assert (layout.width_mm, layout.height_mm) == (w, h)
    left, other = (20.0, 5.0) if standard == "gost" else (20.0, 10.0)
    f = layout.frame
    assert (f.x0, f.y0, w - f.x1, h - f.y1) == (left, other, other, other)
    tb = layout.title_block
    assert (tb.width, tb.height) == ((185.0, 55.0) if standard == "gost" else (180.0, 40.0))
    assert (tb.x1, tb.y0) == (f.x1, f.y0)  # bottom-right corner of the frame
    area = layout.drawing_area
    assert area.is_valid
    assert area.intersection(tb.polygon()).area == pytest.approx(0.0, abs=1e-9)
    assert f.polygon().contains(area)
    expected = f.width * f.height - tb.width * tb.height
    assert expected - 100.0 < area.area <= expected + 1e-6  # only centring marks cut out more
    frame_lines = [p for p in layout.primitives if isinstance(p, Polyline) and p.role is Role.FRAME]
    assert len(frame_lines) == 1 and frame_lines[0].closed


def test_orientation() -> None:
    assert paper_size("A4") == (210.0, 297.0)
    assert paper_size("a1") == (841.0, 594.0)
    assert paper_size("A4", "landscape") == (297.0, 210.0)
    assert paper_size("A3", "portrait") == (297.0, 420.0)
    with pytest.raises(DrawingError, match="sheet size"):
        paper_size("A5")
    with pytest.raises(DrawingError, match="orientation"):
        paper_size("A3", "sideways")


def test_gost_form_1_grid() -> None:
    block = _block(make_frame("A1", "gost", FIELDS))
    segs = _segments(block)
    vertical = {(round(a[0], 6), min(a[1], b[1]), max(a[1], b[1])) for a, b, _ in segs
                if a[0] == b[0]}
    # columns 7/10/23/15/10 mm, then 70 mm, then 50 mm (Лит. 15, Масса 17, Масштаб 18)
    for x in (0, 17, 40, 55, 65, 185):
        assert (x, 0, 55) in vertical
    assert (7, 30, 55) in vertical
    assert (135, 0, 40) in vertical
    assert (150, 20, 40) in vertical and (167, 20, 40) in vertical
    assert (155, 15, 20) in vertical
    horizontal = {(a[1], min(a[0], b[0]), max(a[0], b[0])) for a, b, _ in segs if a[1] == b[1]}
    for y in range(5, 55, 5):  # 11 rows of 5 mm on the left
        assert (y, 0, 65) in horizontal
    assert (40, 65, 185) in horizontal  # designation field 120 × 15
    assert (15, 65, 185) in horizontal  # name 70 × 25 above material 70 × 15, organisation 50 × 15
    assert (35, 135, 185) in horizontal and (20, 135, 185) in horizontal
    roles = {(a[1], min(a[0], b[0])): r for a, b, r in segs if a[1] == b[1]}
    assert roles[(30, 0)] is Role.FRAME and roles[(45, 0)] is Role.TABLE
    labels = {t.string for t in block.primitives if isinstance(t, Text) and t.tag is None}
    assert {"Изм.", "Лист", "№ докум.", "Подп.", "Дата", "Разраб.", "Пров.", "Т.контр.",
            "Н.контр.", "Утв.", "Лит.", "Масса", "Масштаб", "Листов"} <= labels


@pytest.mark.parametrize(("language", "labels"), [
    ("en", {"Created by", "Approved by", "Title", "Identification number", "Date of issue"}),
    ("ru", {"Разработал", "Проверил", "Наименование", "Обозначение", "Масштаб"}),
    ("vi", {"Người vẽ", "Người kiểm tra", "Tên bản vẽ", "Tỉ lệ", "Tờ số"}),
    ("zh", {"设计", "审核", "图名", "图号", "比例"}),
])
def test_iso_labels_follow_language(language: str, labels: set[str]) -> None:
    layout = make_frame("A3", "iso", FIELDS, language=language)
    texts = {t.string for t in _block(layout).primitives if isinstance(t, Text)}
    assert labels <= texts
    attrs = _block(layout).attributes
    assert attrs["SHEET"] == "2/3" and attrs["LANGUAGE"] == language


def test_tcvn_school_form() -> None:
    layout = make_frame("A1", "tcvn", FIELDS, language="vi")
    block = _block(layout)
    texts = {t.string for t in block.primitives if isinstance(t, Text)}
    assert {"Trường", "Khoa", "Lớp", "Người vẽ", "GVHD", "Ngày", "Tỉ lệ", "Tờ số", "Số tờ",
            "ĐỒ ÁN NGUYÊN LÝ MÁY"} <= texts
    attrs = block.attributes
    assert attrs["AUTHOR"] == "Nguyễn Văn An" and attrs["INSTRUCTOR"] == "TS. Trần Bình"
    assert attrs["SHEET"] == "2" and attrs["SHEETS"] == "3"
    assert " ".join(v for k, v in sorted(attrs.items()) if k.startswith("SCHOOL")) == FIELDS[
        "school"]
    assert layout.sheet(name="x").attributes["title"] == FIELDS["title"]


@pytest.mark.parametrize(("standard", "language"), [("iso", "en"), ("iso", "ru"), ("iso", "vi"),
                                                    ("iso", "zh"), ("gost", "ru"),
                                                    ("tcvn", "vi")])
def test_title_block_texts_stay_in_their_cells(standard: str, language: str) -> None:
    fields = dict(FIELDS)
    if language == "zh":
        fields.update(title="牛头刨床机构运动分析", author="张伟", school="清华大学")
    layout = make_frame("A2", standard, fields, language=language)
    block = _block(layout)
    tb = layout.title_block
    outline = box(tb.x0, tb.y0 - 5.0, tb.x1, tb.y1)  # ГОСТ writes "Копировал" below the frame
    lines = [LineString([p.start, p.end]) for p in block.primitives if isinstance(p, Line)]
    boxes = [(t, _text_box(t)) for t in block.primitives if isinstance(t, Text) and t.string]
    for t, b in boxes:
        assert outline.contains(b), t.string
        for ln in lines:
            assert not b.buffer(-0.05).intersects(ln), (t.string, ln)
    for (t1, b1), (t2, b2) in itertools.combinations(boxes, 2):
        assert not b1.buffer(-0.05).intersects(b2.buffer(-0.05)), (t1.string, t2.string)


def test_long_title_wraps_and_too_long_field_fails() -> None:
    long_title = "Kinematic and kinetostatic analysis of a shaper mechanism"
    attrs = _block(make_frame("A1", "iso", {"title": long_title})).attributes
    assert attrs["TITLE"] + " " + attrs["TITLE_2"] == long_title
    with pytest.raises(DrawingError, match="'author' must fit"):
        make_frame("A1", "gost", {"author": "Константинопольский-Ветлугин А.А. и соавторы"})


def test_unknown_field_and_standard() -> None:
    with pytest.raises(DrawingError, match="title-block field must be one of") as err:
        make_frame("A1", "iso", {"titel": "x"})
    assert err.value.key == "titel"
    with pytest.raises(DrawingError, match="standard must be one of"):
        make_frame("A1", "din")
    with pytest.raises(DrawingError, match="language"):
        make_frame("A1", "iso", language="fr")


def test_centring_marks_on_iso_sheets() -> None:
    layout = make_frame("A3", "iso")
    marks = [p for p in layout.primitives if isinstance(p, Line) and p.role is Role.FRAME]
    assert len(marks) == 4
    w, h = layout.width_mm, layout.height_mm
    starts = sorted((round(m.start[0], 6), round(m.start[1], 6)) for m in marks)
    assert starts == sorted([(w / 2, 0.0), (w / 2, h), (0.0, h / 2), (w, h / 2)])
    # from the trimmed edge to 5 mm inside the frame (20 mm binding margin on the left)
    lengths = sorted(round(m.length, 6) for m in marks)
    assert lengths == [15.0, 15.0, 15.0, 25.0]
    assert all(math.isclose(m.length, 25.0) == (m.start[0] == 0.0) for m in marks)
