"""Every template of every kind draws on A4 … A0: panels inside the drawing area, none overlapping,
no free text wider than the drawing it belongs to; tables too wide are split, titles wrapped."""

from __future__ import annotations

import functools
import itertools
import re
import xml.etree.ElementTree as ET

import pytest
from scenes import ALL_TEMPLATES
from shapely import box

from mechplan.drafting.fonts import text_width_mm
from mechplan.drafting.primitives import Table, Text
from mechplan.drafting.wrap import wrap
from mechplan.errors import DrawingError
from mechplan.render.svg import to_svg
from mechplan.sheet import compose as compose_module
from mechplan.sheet.fit import MEASURE_MIN, TableStyle, table_panel
from mechplan.sheet.frame import make_frame
from mechplan.sheet.layout import ENLARGEMENTS, Layout, drawing_area, fitted_layout
from mechplan.sheet.panels import Panel, _points_of
from mechplan.studies import solve_file

BY_NAME = {p.stem: p for p in ALL_TEMPLATES}
#: one template per kind (machine_unit: a linkage with forces and the dynamics sheet)
ONE_PER_KIND = ("machine_unit", "cam_cycloidal", "planetary_two_row", "v_engine_dynamics")
CASES = ([(name, size, None) for name in BY_NAME for size in ("A4", "A0")]
         + [(name, size, None) for name in ONE_PER_KIND for size in ("A3", "A2", "A1")]
         # Chinese wraps between characters, Vietnamese words are long
         + [(name, "A4", lang) for name in ONE_PER_KIND for lang in ("zh", "vi")])


@functools.cache
def study(name: str):
    return solve_file(BY_NAME[name])


def _placements(name: str, size: str, lang: str | None, monkeypatch) -> tuple[list, list]:
    """The sheets drawn and, per sheet, (panels with offsets, size, standard, enlargement of a
    capability sheet — None for the linkage sheets of compose.py, laid out by their own rules)."""
    placed: list = []
    original_sheets = Layout.sheets
    original_compose = compose_module.compose

    def sheets(self, **kw):
        placed.extend((p, self.size, self.standard, self.k) for p in self.placements)
        return original_sheets(self, **kw)

    def compose(*args, **kw):
        comp = original_compose(*args, **kw)
        placed.extend((p, comp.size, comp.standard, None) for p in comp.placements)
        return comp

    monkeypatch.setattr(Layout, "sheets", sheets)
    monkeypatch.setattr(compose_module, "compose", compose)
    drawn = study(name).sheets(size, None, lang, name)
    return drawn, placed


def _moved_box(panel: Panel, offset: tuple[float, float]):
    x0, y0, x1, y1 = panel.bounds()
    dx, dy = offset
    return box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)


def _free_texts_fit_their_drawing(panel: Panel) -> list[str]:
    """Texts wider than the shortest measure that stick out of the rest of their panel."""
    texts = [p for p in panel.primitives if isinstance(p, Text)]
    long = [t for t in texts if text_width_mm(t.string, t.height_mm) > MEASURE_MIN + 0.01]
    rest = [p for p in panel.primitives if p not in long]
    if not any(not isinstance(p, Text) for p in rest):
        return []                      # a panel of sentences: only the area bounds it
    xs = [x for p in rest for x, _ in _points_of(p)]
    lo, hi = min(xs), max(xs)
    bad = []
    for t in long:
        (a, _), (b, _) = _points_of(t)
        if a < lo - 0.5 or b > hi + 0.5:
            bad.append(f"{panel.name}: {t.string!r} spans {a:.0f}…{b:.0f}, "
                       f"drawing {lo:.0f}…{hi:.0f}")
    return bad


@pytest.mark.parametrize(("name", "size", "lang"), CASES,
                         ids=[f"{n}-{s}" + (f"-{lang}" if lang else "") for n, s, lang in CASES])
def test_template_draws_on_every_sheet_size(name, size, lang, monkeypatch):
    drawn, placed = _placements(name, size, lang, monkeypatch)
    assert drawn and placed
    paper = make_frame(size, "iso", {}).sheet([], "x")
    assert all((s.width_mm, s.height_mm) == (paper.width_mm, paper.height_mm) for s in drawn)
    problems: list[str] = []
    for sheet_panels, sz, standard, k in placed:
        # the usual enlargements (≥ 0.5) suffice for every template, A4 included
        assert k is None or k >= ENLARGEMENTS[-1], (sz, k)
        area = drawing_area(make_frame(sz, standard, {}))
        boxes = [(p.name, _moved_box(p, o)) for p, o in sheet_panels]
        for pname, b in boxes:
            if not area.buffer(1e-6).contains(b):
                problems.append(f"{pname} is outside the drawing area on {sz}")
        for (n1, b1), (n2, b2) in itertools.combinations(boxes, 2):
            if b1.intersection(b2).area > 1e-6:
                problems.append(f"{n1} overlaps {n2} on {sz}")
        for p, _ in sheet_panels if k is not None else ():
            problems += _free_texts_fit_their_drawing(p)
    assert not problems, "\n".join(problems)
    if size == "A4" and name in ONE_PER_KIND and lang is None:   # the SVG writes every text
        sheet = drawn[-1]
        svg = ET.fromstring(to_svg(sheet))
        written = {"".join(e.itertext()) for e in svg.iter() if e.tag.endswith("}text")}
        texts = [t.string for t in sheet.primitives if isinstance(t, Text)]
        missing = [t for t in texts if t not in written and re.sub(r"[\^_]", "", t) not in written]
        assert texts and not missing, missing


def test_wrap_breaks_words_and_cjk_and_keeps_values_whole():
    en = "Reduced moments of the driving (M_d) and resisting (M_c) forces, μφ = 2 °/mm"
    lines = wrap(en, 3.5, 60.0)
    assert len(lines) > 1 and " ".join(lines) == en
    assert all(text_width_mm(s, 3.5) <= 60.0 for s in lines)
    assert any(s.endswith("μφ = 2 °/mm") for s in lines)     # never "μφ =" | "2 °/mm"
    zh = "等效驱动力矩和等效阻力矩随曲柄转角的变化曲线，比例尺"
    lines = wrap(zh, 3.5, 40.0)
    assert len(lines) > 1 and "".join(lines) == zh
    assert all(text_width_mm(s, 3.5) <= 40.0 for s in lines)
    assert not any(s.startswith("，") for s in lines)           # no line starts with a comma
    assert wrap("a;   b", 2.5, 100.0) == ["a;   b"]               # what fits is kept as it is
    pole = "图解积分：极距 H = 10 mm；μA = μM·μφ·H = 69.8132 J/mm"
    lines = wrap(pole, 2.5, 90.0)
    assert len(lines) == 2 and lines[-1].endswith("= 69.8132 J/mm")    # a value keeps its unit


def test_wide_table_is_split_into_column_groups_repeating_the_key_columns():
    head = ("№", "φ, °") + tuple(f"col {i}, N·m" for i in range(10))
    rows = [head] + [(str(j), str(30 * j)) + tuple(f"{j * i:.3f}" for i in range(10))
                     for j in range(13)]
    panel = table_panel("t", "Values at the positions", rows, TableStyle(key_columns=2))
    (table,) = [p for p in panel.primitives if isinstance(p, Table)]
    assert sum(table.column_widths_mm) > 166.0
    parts = panel.refit(158.0, 219.0)
    assert len(parts) >= 2
    seen: list[str] = []
    for part in parts:
        x0, _, x1, _ = part.bounds()
        assert x1 - x0 <= 158.0 + 1e-9
        (t,) = [p for p in part.primitives if isinstance(p, Table)]
        assert [r[:2] for r in t.cells] == [r[:2] for r in rows]        # № and φ repeated
        seen += [c for c in t.cells[0][2:]]
    assert seen == list(head[2:])                                        # every column once
    widths = [sum(p.column_widths_mm) for part in parts for p in part.primitives
              if isinstance(p, Table)]
    assert max(widths) - min(widths) < 40.0                              # balanced groups


def test_long_text_column_is_wrapped_before_columns_are_split():
    rows = [("condition", "numbers", "verdict")] + [
        (f"condition {i}", "i = 3.0000;  u = 4.0000;  u* = 4.0000 ± 2.0 %;  Δu = 0.00 % and more",
         "holds") for i in range(4)]
    panel = table_panel("s", "Synthesis", rows)
    parts = panel.refit(120.0, 200.0)
    assert len(parts) == 1
    (t,) = [p for p in parts[0].primitives if isinstance(p, Table)]
    assert sum(t.column_widths_mm) <= 120.0 and len(t.cells[0]) == 3
    assert all("\n" in r[1] for r in t.cells[1:])
    assert all(r[1].split() == rows[1][1].split() for r in t.cells[1:])     # every word kept
    drawn = {p.string for p in t.expand() if isinstance(p, Text)}
    assert set(t.cells[1][1].split("\n")) <= drawn                      # each line drawn
    assert max(t.row_heights_mm[1:]) > t.row_heights_mm[0]               # taller rows


def test_a_panel_too_large_for_every_enlargement_names_the_smallest_sheet():
    def build(k: float) -> list[Panel]:
        return [Panel("huge", [Table((0.0, 0.0), (250.0,), (50.0,), (("x",),))])]

    with pytest.raises(DrawingError, match=r"'huge'.*smallest sheet that takes it is A3"):
        fitted_layout(build, size="A4", standard="iso", language="en", fields={})
    lay = fitted_layout(build, size="A3", standard="iso", language="en", fields={})
    assert len(lay.placements) == 1


def test_tall_table_is_split_into_row_groups_repeating_the_heading():
    rows = [("φ, °", "M, N·m")] + [(str(5 * j), f"{j * 1.5:.1f}") for j in range(73)]
    panel = table_panel("t", "Torque", rows)
    _, y0, _, y1 = panel.bounds()
    assert y1 - y0 > 219.0                                               # 74 rows of 5 mm
    parts = panel.refit(158.0, 219.0)
    assert len(parts) == 2
    body: list[tuple[str, ...]] = []
    for part in parts:
        _, p0, _, p1 = part.bounds()
        assert p1 - p0 <= 219.0 + 1e-9
        (t,) = [p for p in part.primitives if isinstance(p, Table)]
        assert t.cells[0] == rows[0]                                     # heading repeated
        body += t.cells[1:]
    assert body == rows[1:]                                              # every row once, in order
