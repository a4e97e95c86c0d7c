"""A plan's tables set apart from it, split by rows into a sheet's free room.

The tables of a plan (its segments, each vector equation with its caption) stand one under the
other under the plan's title. Where they do not fit the room a sheet leaves, the layout takes
as many whole tables as fit and then the first rows of the next one (its heading repeated in
the rest, its caption kept with its first rows); the rest, under the same title, goes on
(``Panel.split_off``), and is split again where it is placed. A table part keeps at least
:data:`MIN_ROWS` rows on each side of a cut. ``Panel.refit`` splits them into parts of whole
tables (a table cut only where it alone is taller than the room): the layout tries both and
keeps the one that takes fewer sheets (:func:`.layout.fewest_sheets`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from ..drafting.primitives import Primitive, Table, Text
from .panels import TITLE_H, Panel

#: vertical gap (mm) between one table (with its caption) and the next
BETWEEN_MM = 4.0
#: rows (besides the heading) a table keeps on each side of a cut
MIN_ROWS = 2
#: a first part cut off into a sheet's free room is at least this tall (mm): no slivers of
#: two rows at the foot of a sheet, the rest of the table elsewhere
MIN_PART_MM = 25.0

Block = list[Primitive | Table]


def _blocks(prims: Sequence[Primitive | Table]) -> list[Block]:
    """The tables each with the captions written above it (in drawing order)."""
    blocks: list[Block] = [[]]
    for p in prims:
        blocks[-1].append(p)
        if isinstance(p, Table):
            blocks.append([])
    return [b for b in blocks if b]


def _stacked(blocks: Sequence[Block]) -> list[Primitive | Table]:
    """The blocks one under the other from y = 0 down, left edges at x = 0."""
    from .layout import moved

    out: list[Primitive | Table] = []
    y = 0.0
    for block in blocks:
        x0, y0, _x1, y1 = Panel("", list(block)).bounds()
        out.extend(moved(p, -x0, y - y1) for p in block)
        y -= (y1 - y0) + BETWEEN_MM
    return out


def _titled(name: str, blocks: Sequence[Block], title: str) -> Panel:
    """A panel of tables under the plan's title, splittable again."""
    prims = _stacked(blocks)
    panel = Panel(name, [*prims, Text((0.0, 3.0), title, TITLE_H - 1.5)])
    if len(blocks) > 1 or _rows(blocks[0]) > 2 * MIN_ROWS:
        panel.split_off = lambda w, h: split_off(name, list(blocks), title, w, h)
        panel.refit = lambda w, h: in_parts(name, list(blocks), title, w, h)
    return panel


def _rows(block: Block) -> int:
    """Data rows (besides the heading) of a block's table."""
    t = next((p for p in block if isinstance(p, Table)), None)
    return len(t.cells) - 1 if t is not None else 0


def _cut(block: Block, n: int) -> tuple[Block, Block]:
    """A block's captions and heading with its first ``n`` rows; the heading with the others."""
    t = next(p for p in block if isinstance(p, Table))
    head = dataclasses.replace(t, cells=t.cells[:n + 1], row_heights_mm=t.row_heights_mm[:n + 1])
    tail = dataclasses.replace(t, cells=(t.cells[0], *t.cells[n + 1:]),
                               row_heights_mm=(t.row_heights_mm[0], *t.row_heights_mm[n + 1:]))
    return [p for p in block if p is not t] + [head], [tail]


def _size(block: Block) -> tuple[float, float]:
    """Width and height (mm) of a block as :func:`_stacked` draws it."""
    x0, y0, x1, y1 = Panel("", list(block)).bounds()
    return x1 - x0, y1 - y0


def _first(blocks: list[Block], title: str, w: float, h: float,
           cut: bool = True) -> tuple[list[Block], list[Block]]:
    """The blocks that fit w × h under the title (``cut``: the last one perhaps cut by rows)
    and the rest. Sizes are added up from each block's box as :func:`_titled` stacks them."""
    head_box = Panel("", [Text((0.0, 3.0), title, TITLE_H - 1.5)]).bounds()
    top, title_w = head_box[3], head_box[2] - head_box[0]

    def fits(width: float, height: float) -> bool:
        return max(width, title_w) <= w + 1e-9 and top + height <= h + 1e-9

    first: list[Block] = []
    used_w = used_h = 0.0
    for i, block in enumerate(blocks):
        bw, bh = _size(block)
        gap = BETWEEN_MM if first else 0.0
        if fits(max(used_w, bw), used_h + gap + bh):
            first.append(block)
            used_w, used_h = max(used_w, bw), used_h + gap + bh
            continue
        t = next((p for p in block if isinstance(p, Table)), None)
        heights = t.row_heights_mm if t is not None else ()
        rows = len(heights) - 1 if cut or not first else 0
        for n in range(rows - MIN_ROWS, MIN_ROWS - 1, -1):
            cut_h = bh - sum(heights[n + 1:])               # the table is the block's foot
            if fits(max(used_w, bw), used_h + gap + cut_h):
                head, tail = _cut(block, n)
                return first + [head], [tail] + blocks[i + 1:]
        return first, blocks[i:]
    return first, []


def split_off(name: str, blocks: list[Block], title: str, w: float, h: float) -> list[Panel]:
    """The tables as a first part of at most w × h mm and the rest (one panel, split again where
    it goes); the whole panel when nothing fits (the layout then looks elsewhere)."""
    first, rest = _first(blocks, title, w, h)
    if first and rest:
        _x0, y0, _x1, y1 = _titled("", first, title).bounds()
        if y1 - y0 < MIN_PART_MM:
            first = []
    if not first or not rest:
        return [_titled(name, blocks, title)]
    return [_titled(f"{name}.1", first, title), _titled(f"{name}.2", rest, title)]


def in_parts(name: str, blocks: list[Block], title: str, w: float, h: float) -> list[Panel]:
    """The tables in parts of whole tables each at most ``h`` tall (only a table taller than
    that cut by rows)."""
    parts: list[list[Block]] = []
    rest = blocks
    while rest:
        first, left = _first(rest, title, w, h, cut=False)
        if not first:                  # not even two rows fit: as it is
            first, left = rest[:1], rest[1:]
        parts.append(first)
        rest = left
    if len(parts) == 1:
        return [_titled(name, parts[0], title)]
    return [_titled(f"{name}.{i + 1}", p, title) for i, p in enumerate(parts)]


def splittable(keep: Sequence[Primitive | Table], name: str, title: str) -> Panel:
    """The tables ``keep`` (captions and tables, in drawing order) as a panel under ``title``
    that the layout can split by rows."""
    return _titled(name, _blocks(keep), title)


__all__ = ["in_parts", "split_off", "splittable"]
