"""Texts and tables keep their size on every sheet; here they are fitted to the room there is.

- A title, note or scale-factor line is wrapped to the width of the drawing it belongs to (never
  narrower than :data:`MEASURE_MIN`), with the fonts' real metrics (:func:`drafting.wrap.wrap`).
- A table (:func:`table_panel`) or a panel of sentences (:func:`text_panel`) that is wider or taller
  than a sheet's drawing area is redrawn by the layout through ``Panel.refit``: a long text column
  is wrapped, then the columns are split into groups that each repeat the identifying first
  column(s) (№, φ), then the rows into groups that each repeat the heading; the parts are panels
  of their own, titled "title (1/2)", "title (2/2)".
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from ..drafting.fonts import SheetFont, paragraph_font, text_width_mm
from ..drafting.primitives import LINE_SPACING, HAlign, Primitive, Table, Text, VAlign
from ..drafting.wrap import wrap
from .panels import Panel

#: mm: the narrowest measure a text is wrapped to, even over a narrower drawing
MEASURE_MIN = 60.0
#: mm: a text column of a table is not wrapped narrower than this
TEXT_COLUMN_MIN = 40.0


def lines_of(text: str | Sequence[str], height_mm: float, width_mm: float,
             sep: str = ";   ", measure_min: float = MEASURE_MIN,
             font: SheetFont | None = None) -> list[str]:
    """``text`` wrapped to ``width_mm`` (at least ``measure_min``); a sequence of parts (scale
    factors, say) is joined by ``sep`` on as few lines as fit, a part wider than the measure
    itself wrapped. Widths are measured in ``font`` (default: each line's own)."""
    width = max(width_mm, measure_min)
    if isinstance(text, str):
        return wrap(text, height_mm, width, font)
    out: list[str] = []
    line = ""
    for part in text:
        candidate = f"{line}{sep}{part}" if line else part
        if line and text_width_mm(candidate, height_mm, font) > width:
            out.append(line + sep.rstrip())
            line = part
        else:
            line = candidate
    if line:
        out.append(line)
    return [s for ln in out for s in wrap(ln, height_mm, width, font)]


def text_block(origin: tuple[float, float], text: str | Sequence[str], height_mm: float,
               width_mm: float, *, upward: bool = False, valign: VAlign = VAlign.BASELINE,
               halign: HAlign = HAlign.LEFT, pitch: float | None = None,
               measure_min: float = MEASURE_MIN) -> list[Text]:
    """``text`` wrapped to ``width_mm`` (at least ``measure_min``) as lines from ``origin`` down —
    or up (``upward``: the last line at ``origin``, so a title stays just above its drawing
    however many lines it takes). The lines are one paragraph in one font: the font that shows
    all of it (a line is never in osifont while the next, for a "ё" or a "′", is not)."""
    font = paragraph_font([text] if isinstance(text, str) else text)
    lines = lines_of(text, height_mm, width_mm, measure_min=measure_min, font=font)
    named = font.name if len(lines) > 1 else None
    step = pitch or LINE_SPACING * height_mm
    n = len(lines)
    x, y = origin
    return [Text((x, y + step * ((n - 1 - i) if upward else -i)), s, height_mm, halign=halign,
                 valign=valign, font=named) for i, s in enumerate(lines)]


def drawing_right(primitives: Sequence[Primitive | Table]) -> float:
    """The right edge (mm) of what is drawn so far — the measure of a title written above it."""
    return Panel("", list(primitives)).bounds()[2]


@dataclass(frozen=True)
class TableStyle:
    """How a table panel is drawn: text and title heights, row heights, cell padding."""

    text_h: float = 2.5
    row_h: float = 5.0
    head_h: float | None = None        # the heading row (None: row_h)
    pad: float = 3.0                   # added to the widest text of a column
    halign: HAlign = HAlign.CENTER
    title_h: float = 3.5
    key_columns: int = 1               # identifying columns repeated in every column group


def column_widths(cells: Sequence[Sequence[str]], style: TableStyle) -> list[float]:
    """Widths (mm) that fit the widest line of each column."""
    return [max(text_width_mm(ln, style.text_h) for r in cells for ln in r[c].split("\n"))
            + style.pad for c in range(len(cells[0]))]


def _row_heights(cells: Sequence[Sequence[str]], style: TableStyle) -> list[float]:
    pitch = LINE_SPACING * style.text_h
    out = []
    for i, row in enumerate(cells):
        base = style.head_h if i == 0 and style.head_h is not None else style.row_h
        n = max(len(c.split("\n")) for c in row)
        out.append(base + (n - 1) * pitch)
    return out


def table_panel(name: str, title: str, cells: Sequence[Sequence[str]],
                style: TableStyle = TableStyle(), *, widths: Sequence[float] | None = None,
                notes: Sequence[str] = ()) -> Panel:
    """A titled table (its first row the heading) with notes under it; the layout splits it (see
    the module) when it is larger than a sheet's drawing area."""
    rows = [list(r) for r in cells]
    w = list(widths) if widths is not None else column_widths(rows, style)
    panel = _drawn(name, title, rows, w, style, notes)

    def refit(max_w: float, max_h: float) -> list[Panel]:
        parts = _split(rows, w, style, max_w, max_h - _extra_height(panel))
        if len(parts) == 1:
            return [_drawn(name, title, parts[0][0], parts[0][1], style, notes)]
        # each part can be split again (its rows into a sheet's free room)
        return [table_panel(f"{name}.{i + 1}", f"{title} ({i + 1}/{len(parts)})", p, style,
                            widths=pw, notes=notes if i == len(parts) - 1 else ())
                for i, (p, pw) in enumerate(parts)]

    def split_off(max_w: float, max_h: float) -> list[Panel]:
        parts = _split(rows, w, style, max_w, max_h - _extra_height(panel))
        if len(parts) == 1 or any(len(p[0]) != len(rows[0]) for p, _ in parts):
            return refit(max_w, max_h)          # one part, or column groups: as refit
        # the rows in two: those that fit the room, the others in one table (split again)
        first = parts[0][0]
        rest = [rows[0], *rows[len(first):]]
        return [table_panel(f"{name}.1", f"{title} (1/2)", first, style, widths=parts[0][1]),
                table_panel(f"{name}.2", f"{title} (2/2)", rest, style, widths=w, notes=notes)]

    panel.refit = refit
    panel.split_off = split_off
    return panel


def _drawn(name: str, title: str, rows: Sequence[Sequence[str]], widths: Sequence[float],
           style: TableStyle, notes: Sequence[str]) -> Panel:
    heights = _row_heights(rows, style)
    table = Table((0.0, 0.0), tuple(widths), tuple(heights), tuple(tuple(r) for r in rows),
                  style.text_h, halign=style.halign)
    width = sum(widths)
    prims: list[Primitive | Table] = []
    if title:
        prims += text_block((0.0, 4.0), title, style.title_h, width, upward=True)
    prims.append(table)
    y = -sum(heights) - 5.0
    for note in notes:
        block = text_block((0.0, y), note, style.text_h, width, pitch=1.8 * style.text_h)
        prims += block
        y -= 1.8 * style.text_h * len(block)
    return Panel(name, prims)


def _extra_height(panel: Panel) -> float:
    """Height of a table panel outside its table (title, notes)."""
    _, y0, _, y1 = panel.bounds()
    t = next(p for p in panel.primitives if isinstance(p, Table))
    return (y1 - y0) - sum(t.row_heights_mm)


def _split(rows: list[list[str]], widths: list[float], style: TableStyle, max_w: float,
           max_h: float) -> list[tuple[list[list[str]], list[float]]]:
    """The table as parts each at most ``max_w`` wide and (its table) ``max_h`` tall."""
    rows = [list(r) for r in rows]
    widths = list(widths)
    key = style.key_columns
    excess = sum(widths) - max_w
    if excess > 0:                          # a long text column is wrapped first
        j = max(range(key, len(widths)), key=lambda c: widths[c], default=None)
        target = widths[j] - excess - style.pad if j is not None else 0.0
        if j is not None and target >= TEXT_COLUMN_MIN and any(" " in r[j] for r in rows[1:]):
            for r in rows:
                r[j] = "\n".join(wrap(r[j], style.text_h, target))
            widths[j] = column_widths([[r[j]] for r in rows], style)[0]
    groups = _column_groups(widths, key, max_w)
    heights = _row_heights(rows, style)
    parts: list[tuple[list[list[str]], list[float]]] = []
    for g in groups:
        sub = [[r[c] for c in g] for r in rows]
        gw = [widths[c] for c in g]
        start = 1
        while start < len(sub):
            room = max_h - heights[0]
            end = start
            while end < len(sub) and (room >= heights[end] or end == start):
                room -= heights[end]
                end += 1
            parts.append(([sub[0], *sub[start:end]], gw))
            start = end
        if len(sub) == 1:
            parts.append((sub, gw))
    return parts


def _column_groups(widths: Sequence[float], key: int, max_w: float) -> list[list[int]]:
    """Columns in as few groups as fit ``max_w`` with the ``key`` columns repeated, balanced: the
    widest group as narrow as that number of groups allows."""
    def greedy(limit: float) -> list[list[int]]:
        groups: list[list[int]] = [[]]
        used = 0.0
        for c in range(key, len(widths)):
            if groups[-1] and used + widths[c] > limit:
                groups.append([])
                used = 0.0
            groups[-1].append(c)
            used += widths[c]
        return groups

    room = max_w - sum(widths[:key])
    widest = max(widths[key:], default=0.0)
    n = len(greedy(room))
    lo, hi = widest, max(room, widest)
    for _ in range(30):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if len(greedy(mid)) <= n else (mid, hi)
    return [list(range(key)) + g for g in greedy(hi)]


def text_panel(name: str, title: str, paragraphs: Sequence[str], *, title_h: float = 3.5,
               text_h: float = 2.5) -> Panel:
    """A title over sentences, one line each; the layout rewraps them to the width of a sheet
    narrower than the longest."""
    def drawn(width: float) -> Panel:
        prims: list[Primitive | Table] = [*text_block((0.0, 0.0), title, title_h, width,
                                                      upward=True)]
        y = -6.0
        for para in paragraphs:
            block = text_block((0.0, y), para, text_h, width, pitch=1.8 * text_h)
            prims += block
            y -= 1.8 * text_h * len(block)
        return Panel(name, prims)

    panel = drawn(math.inf)
    panel.refit = lambda w, h: [drawn(w)]
    return panel
