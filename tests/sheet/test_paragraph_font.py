"""One font per paragraph: the lines of a wrapped title or note are drawn in one font — the one
that shows the whole paragraph — even when only one line has the glyph that needs it (osifont
has no "ё", "э", "′", "−": such a line went to DejaVu Sans while the next stayed in osifont)."""

from __future__ import annotations

import io
import re

import ezdxf

from mechplan.render import dxf as dxf_backend
from mechplan.render import svg as svg_backend
from mechplan.sheet.fit import text_block
from mechplan.sheet.primitives import Sheet, Text

TITLE = ("Приведённые моменты движущих сил и сил сопротивления по углу поворота кривошипа "
         "за полный цикл установившегося движения машинного агрегата")


def _block() -> list[Text]:
    lines = text_block((10.0, 150.0), TITLE, 3.5, 60.0)
    assert len(lines) >= 3
    assert "ё" in lines[0].string and not any("ё" in t.string or "э" in t.string
                                              for t in lines[1:])
    return lines


def _sheet(texts: list[Text]) -> Sheet:
    return Sheet(200.0, 200.0, tuple(texts), language="ru", name="p")


def test_the_lines_of_a_paragraph_share_one_dxf_style():
    doc = ezdxf.read(io.StringIO(dxf_backend.to_bytes(_sheet(_block())).decode("utf-8")))
    styles = {e.dxf.style for e in doc.modelspace() if e.dxftype() in ("TEXT", "MTEXT")}
    assert len(styles) == 1, styles


def test_the_lines_of_a_paragraph_share_one_svg_font_family_and_size():
    svg = svg_backend.to_svg(_sheet(_block()))
    families = set(re.findall(r'font-family="([^"]*)"', svg))
    sizes = set(re.findall(r'<text[^>]*font-size="([^"]*)"', svg))
    assert len(families) == 1 and len(sizes) == 1, (families, sizes)


def test_a_line_alone_keeps_the_font_its_string_needs():
    (line,) = text_block((0.0, 0.0), "μφ = 2 °/мм", 2.5, 200.0)
    assert line.font is None
    other = _sheet([line, Text((0.0, 20.0), "Приведённые", 3.5)])
    doc = ezdxf.read(io.StringIO(dxf_backend.to_bytes(other).decode("utf-8")))
    assert len({e.dxf.style for e in doc.modelspace() if e.dxftype() == "TEXT"}) == 2
