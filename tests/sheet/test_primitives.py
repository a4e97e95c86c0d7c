"""Primitive validation and geometry."""

from __future__ import annotations

import dataclasses
import math

import pytest

from mechplan.errors import DrawingError
from mechplan.sheet import (
    Arc,
    Arrow,
    Block,
    HAlign,
    Line,
    Polyline,
    Role,
    Sheet,
    Table,
    Text,
    VAlign,
)


def test_roles_have_iso_128_widths() -> None:
    assert Role.THICK is Role.OUTLINE
    widths = {role: role.style.lineweight_mm for role in Role}
    assert set(widths.values()) <= {0.25, 0.35, 0.5, 0.7}
    assert widths[Role.FRAME] == 0.7 and widths[Role.OUTLINE] == 0.5
    assert widths[Role.THIN] == 0.25
    assert len({role.layer for role in Role}) == len(list(Role))


@pytest.mark.parametrize("height", [2.5, 3.5, 5, 7, 10])
def test_text_accepts_iso_3098_heights(height: float) -> None:
    assert Text((0, 0), "A", height).height_mm == float(height)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"position": (0, 0), "string": "A", "height_mm": 3.0}, "ISO 3098"),
        ({"position": (0, 0), "string": ""}, "must not be empty"),
        ({"position": (0, 0), "string": "a\nb"}, "single line"),
        ({"position": (math.nan, 0), "string": "a"}, "finite"),
        ({"position": (0, 0), "string": "a", "tag": "BAD TAG"}, "tag"),
        ({"position": (0, 0), "string": "a", "width_factor": 0.1}, "width factor"),
    ],
)
def test_text_rejects(kwargs: dict, message: str) -> None:
    with pytest.raises(DrawingError, match=message):
        Text(**kwargs)


def test_empty_attribute_is_allowed() -> None:
    assert Text((0, 0), "", tag="TITLE").string == ""


def test_arrow_head_geometry() -> None:
    a = Arrow((0, 0), (30, 40), head_length_mm=5.0, head_width_mm=2.0)
    tip, left, right = a.head()
    assert tip == (30, 40)
    base = ((left[0] + right[0]) / 2, (left[1] + right[1]) / 2)
    assert math.dist(base, tip) == pytest.approx(5.0)
    assert math.dist(left, right) == pytest.approx(2.0)
    shaft = a.shaft()
    assert shaft is not None and shaft.end == pytest.approx(base)
    assert shaft.length == pytest.approx(45.0)
    assert Arrow((0, 0), (3, 0), head_length_mm=4.0).shaft() is None
    with pytest.raises(DrawingError, match="positive length"):
        Arrow((1, 1), (1, 1))


def test_arc_sweep_and_validation() -> None:
    assert Arc((0, 0), 1, 350, 10).sweep_deg == pytest.approx(20)
    assert Arc((0, 0), 1, 0, 360).sweep_deg == 360
    with pytest.raises(DrawingError, match="radius"):
        Arc((0, 0), 0, 0, 90)


def test_polyline_rules() -> None:
    with pytest.raises(DrawingError, match="at least 2"):
        Polyline(((0, 0),))
    with pytest.raises(DrawingError, match="filled"):
        Polyline(((0, 0), (1, 0), (1, 1)), filled=True)
    p = Polyline([[0, 0], [1, 0], [1, 1]], closed=True, filled=True)
    assert p.points == ((0.0, 0.0), (1.0, 0.0), (1.0, 1.0))


def test_table_expands_to_lines_and_centred_texts() -> None:
    t = Table((10, 100), (20, 30), (8, 8, 8), (("a", "b"), ("", "c"), ("d", "")))
    prims = t.expand()
    lines = [p for p in prims if isinstance(p, Line)]
    texts = [p for p in prims if isinstance(p, Text)]
    assert isinstance(prims[0], Polyline) and prims[0].role is Role.OUTLINE
    assert len(lines) == 1 + 2  # one inner column line, two inner row lines
    assert [t.string for t in texts] == ["a", "b", "c", "d"]
    assert texts[0].position == (20.0, 96.0)
    assert (texts[0].halign, texts[0].valign) == (HAlign.CENTER, VAlign.MIDDLE)
    with pytest.raises(DrawingError, match="rows"):
        Table((0, 0), (10,), (5,), (("a", "b"),))


def test_block_and_sheet_validation() -> None:
    t = Text((0, 0), "x", tag="A")
    with pytest.raises(DrawingError, match="repeats attribute tag"):
        Block("B", (0, 0), (t, t))
    blk = Block("B", (0, 0), (t, Line((0, 0), (1, 1))))
    assert blk.attributes == {"A": "x"}
    with pytest.raises(DrawingError, match="another block"):
        Block("C", (0, 0), (blk,))
    with pytest.raises(DrawingError, match="unique"):
        Sheet(100, 100, (blk, blk))
    with pytest.raises(DrawingError, match="Table.expand"):
        Sheet(100, 100, (Table((0, 0), (1,), (1,), (("",),)),))
    with pytest.raises(DrawingError, match="language"):
        Sheet(100, 100, language="de")
    sheet = Sheet(100, 50, (blk, Line((0, 0), (1, 0))), {"title": "T"})
    assert len(list(sheet.flat())) == 3
    with pytest.raises(dataclasses.FrozenInstanceError):
        sheet.width_mm = 1  # type: ignore[misc]
    with pytest.raises(TypeError):
        sheet.attributes["title"] = "x"  # type: ignore[index]
