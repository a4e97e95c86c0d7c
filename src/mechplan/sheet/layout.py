"""Lay panels out on framed sheets: pack them top-left first, flow onto more sheets when full.

Used by every capability's sheet set (dynamics, engine, cam, gears); each sheet gets its frame and
title block with its number and the total.
"""

from __future__ import annotations

import dataclasses
import itertools
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

from shapely import box
from shapely.geometry.base import BaseGeometry

from ..drafting.frame import FrameLayout, make_frame
from ..drafting.primitives import Arc, Arrow, Circle, Line, Polyline, Primitive, Sheet, Table, Text
from ..errors import DrawingError
from ..i18n import Text as Msg
from .panels import Panel
from .room import GAP, Bounds, Sheetful, _footprint, _overlaps, pack  # noqa: F401  (re-exported)

#: the coverage a full sheet (not the last of its set) should reach
GOAL = 0.55
#: a last sheet covered less than this is worth saving by letting a plan's tables go on an
#: earlier sheet than the plan (:func:`fewest_sheets`)
WASTED = 0.15

#: enlargements of a capability sheet's drawings and diagrams tried, largest first; text heights
#: and tables keep their size
ENLARGEMENTS = (2.0, 1.6, 1.25, 1.0, 0.8, 0.6, 0.5)
#: smaller ones, tried only when a panel fits the sheet at none of :data:`ENLARGEMENTS`
REDUCTIONS = (0.4, 0.3, 0.25)
#: the sheet sizes, smallest first (the error of a panel too large names the smallest that works)
SIZES = ("A4", "A3", "A2", "A1", "A0")


def moved(p: Primitive | Table, dx: float, dy: float) -> Primitive | Table:
    """Return a primitive shifted by (dx, dy) mm."""
    def mv(q: tuple[float, float]) -> tuple[float, float]:
        return (q[0] + dx, q[1] + dy)
    if isinstance(p, (Line, Arrow)):
        return dataclasses.replace(p, start=mv(p.start), end=mv(p.end))
    if isinstance(p, Polyline):
        return dataclasses.replace(p, points=tuple(mv(q) for q in p.points))
    if isinstance(p, (Circle, Arc)):
        return dataclasses.replace(p, center=mv(p.center))
    if isinstance(p, Text):
        return dataclasses.replace(p, position=mv(p.position))
    if isinstance(p, Table):
        return dataclasses.replace(p, origin=mv(p.origin))
    raise DrawingError(f"cannot move a {type(p).__name__}")


def drawing_area(frame: FrameLayout) -> BaseGeometry:
    """The drawing area kept clear of the frame's centring marks (6 mm) and the title block."""
    f, t = frame.frame, frame.title_block
    inner = box(f.x0 + 7.0, f.y0 + 7.0, f.x1 - 7.0, f.y1 - 7.0)
    return inner.difference(box(t.x0 - 3.0, t.y0 - 3.0, t.x1 + 3.0, t.y1 + 3.0)).intersection(
        frame.drawing_area)


def chain(name: str) -> str:
    """The panels whose names differ only by trailing part numbers ("velocity-all-1",
    "velocity-all-2"; "table.1", "table.2") are one sequence: kept in order across sheets."""
    return re.sub(r"([-.]\d+)+$", "", name)


def sequence(name: str) -> str:
    """The reading sequence of a panel: its :func:`chain`, a plan's tables set apart
    ("acceleration-1-tables.2") with their plan — never on an earlier sheet than it."""
    return chain(re.sub(r"-tables([-.]\d+)*$", "", name))


def _split_into(room: Sheetful, panel: Panel, rows: bool = True) -> list[Panel] | None:
    """The panel redrawn in parts (``Panel.split_off`` — with ``rows`` —, else ``Panel.refit``),
    the first one fitting the free room of this sheet (any of its free rectangles); None when no
    part fits."""
    split = (panel.split_off if rows else None) or panel.refit
    if split is None:
        return None
    for w, h in room.free_rectangles()[:16]:
        if w <= GAP or h <= GAP:
            continue
        parts = split(w - GAP, h - GAP)
        x0, y0, x1, y1 = room.panel_bounds(parts[0])
        if x1 - x0 <= w - GAP + 1e-9 and y1 - y0 <= h - GAP + 1e-9 \
                and room.spot(x1 - x0 + GAP, y1 - y0 + GAP) is not None:
            return parts
    return None


def paginate(panels: Sequence[Panel], area: BaseGeometry, *, split: bool = False,
             columns: bool = False, bounds: Bounds | None = None,
             rows: bool = True, after_plan: bool = True) -> Groups | Panel:
    """The panels, in reading order, on as few sheets as the packing needs.

    Each sheet takes every remaining panel that still fits its free room (so no panel on a
    later sheet would have fitted an earlier one), except that the parts of one sequence
    (:func:`chain`) keep their order. With ``split``, a panel that can be redrawn in parts
    (``Panel.refit``: a grid of small plans) and does not fit is split so that its first part
    fills the free room; its parts stand for it and for the later panels of its sequence
    (the grid's other cells), which are dropped — or, split by ``Panel.split_off`` (a table:
    the rows that fit, then the others), for it alone. ``columns``: each panel at the leftmost, then
    highest spot. ``rows=False``: no ``split_off`` (a table in parts of whole tables, by
    ``Panel.refit``). ``after_plan``: a plan's tables set apart wait for their plan
    (:func:`sequence`; else only the parts of one :func:`chain` keep their order). Return
    (panels, offsets) per sheet, or the first panel that fits no empty sheet.
    """
    groups: Groups = []
    rest = list(panels)
    bounds = bounds or Bounds()
    while rest:
        room = Sheetful(area, columns=columns, bounds=bounds)
        placed: list[Panel] = []
        offsets: list[tuple[float, float]] = []
        left: list[Panel] = []
        queue = list(rest)
        while queue:
            panel = queue.pop(0)
            key = sequence if after_plan else chain
            if any(key(q.name) == key(panel.name) for q in left):
                left.append(panel)
                continue
            at = room.put(panel)
            # on an empty sheet: only a panel no sheet holds whole is split (else: an error)
            if at is None and split:
                parts = _split_into(room, panel, rows)
                if parts is not None and rows and panel.split_off is not None:
                    queue = parts + queue           # its parts stand for it alone
                    continue
                if parts is not None:
                    same = chain(panel.name)
                    queue = parts + [q for q in queue if chain(q.name) != same]
                    left = [q for q in left if chain(q.name) != same]
                    continue
            if at is None:
                left.append(panel)
            else:
                placed.append(panel)
                offsets.append(at)
        if not placed:
            return rest[0]
        groups.append((placed, offsets))
        rest = left
    return groups


def _height(panel: Panel) -> float:
    _x0, y0, _x1, y1 = panel.bounds()
    return y1 - y0


def _area_of(panel: Panel) -> float:
    x0, y0, x1, y1 = panel.bounds()
    return (x1 - x0 + GAP) * (y1 - y0 + GAP)


def _reordered(panels: Sequence[Panel], key: Callable[[Panel], float]) -> list[Panel]:
    """The first panel, then the others by ``key`` descending; the parts of a sequence stay
    together and in order (ranked by their first part)."""
    rank: dict[str, float] = {}
    for p in panels[1:]:
        rank.setdefault(sequence(p.name), key(p))
    rest = sorted(panels[1:], key=lambda p: -rank[sequence(p.name)])     # stable: order kept
    return list(panels[:1]) + rest


def fewest_sheets(panels: Sequence[Panel], area: BaseGeometry, *,
                  split: bool = False, whole: bool = False) -> Groups | Panel:
    """:func:`paginate` in reading order, rows first — or, when one saves a sheet (or fills the
    full sheets better: :func:`_fuller`), in columns first, or with the panels after the first
    taken tallest first or largest first; ``whole``: each also with tables in parts of whole
    tables (``Panel.refit``) besides split by rows into a sheet's free room."""
    bounds = Bounds()
    best = paginate(panels, area, split=split, bounds=bounds)
    if isinstance(best, Panel) or len(best) == 1:
        return best
    orders = [list(panels), _reordered(panels, _height), _reordered(panels, _area_of)]
    for order, columns, rows in itertools.product(orders, (False, True),
                                                  (True, False) if whole else (True,)):
        if not columns and rows and order is orders[0]:
            continue                                # the first one, above
        other = paginate(order, area, split=split, columns=columns, bounds=bounds, rows=rows)
        if isinstance(other, Panel):
            continue
        if len(other) < len(best) or (len(other) == len(best) and _fuller(other, best, area)):
            best = other
    if coverage(list(zip(*best[-1])), area) < WASTED:
        # a last sheet nearly empty: taken only to keep tables after their plans — saved when
        # the tables may go on an earlier sheet than their plan
        for order, columns in itertools.product(orders, (False, True)):
            other = paginate(order, area, split=split, columns=columns, bounds=bounds,
                             after_plan=False)
            if not isinstance(other, Panel) and len(other) < len(best):
                best = other
    return best


def _fuller(a: Groups, b: Groups, area: BaseGeometry) -> bool:
    """Tell whether sheets ``a`` fill their full sheets (all but the last) better than ``b``
    where ``b`` leaves one under :data:`GOAL`: fewer of them under it, or as many and the
    emptiest of them covered 10 points more (the reading order is kept otherwise)."""
    def covered(groups: Groups) -> list[float]:
        return [coverage(list(zip(p, o)), area) for p, o in groups[:-1]]

    ca, cb = covered(a), covered(b)
    under_a, under_b = sum(c < GOAL for c in ca), sum(c < GOAL for c in cb)
    if not under_b or under_a > under_b:
        return False
    return under_a < under_b or min(ca, default=1.0) > min(cb, default=1.0) + 0.10


def coverage(placed: Sequence[tuple[Panel, tuple[float, float]]], area: BaseGeometry) -> float:
    """The share of a sheet's drawing area covered by the boxes of its panels."""
    used = 0.0
    for panel, _ in placed:
        x0, y0, x1, y1 = panel.bounds()
        used += (x1 - x0) * (y1 - y0)
    return used / area.area


@dataclass(frozen=True)
class Layout:
    """Panels drawn at enlargement ``k`` and placed on sheets: per sheet, (panel, offset) pairs;
    ``grown``: the panels redrawn at a larger enlargement to fill their sheet (name → k)."""

    k: float
    size: str
    standard: str
    placements: list[list[tuple[Panel, tuple[float, float]]]]
    grown: Mapping[str, float] = dataclasses.field(default_factory=dict)

    def k_of(self, name: str) -> float:
        """The enlargement the panel ``name`` is drawn at."""
        return self.grown.get(name, self.k)

    def sheets(self, *, language: str, name: str, fields: Mapping[str, str]) -> list[Sheet]:
        """The framed sheets ``name``, ``name-2``, … with their numbers in the title block."""
        return framed(self.placements, size=self.size, standard=self.standard,
                      language=language, name=name, fields=fields)


def framed(placements: Sequence[Sequence[tuple[Panel, tuple[float, float]]]], *, size: str,
           standard: str, language: str, name: str, fields: Mapping[str, str]) -> list[Sheet]:
    """Panels moved to their places, one framed sheet per group: ``name``, ``name-2``, … with
    the sheet's number and the count in the title block."""
    out: list[Sheet] = []
    for i, placed in enumerate(placements):
        f = dict(fields)
        f.update({"sheet_number": str(i + 1), "sheets_total": str(len(placements))})
        frame = make_frame(size, standard, f, language=language)
        prims: list[Primitive] = []
        for panel, (dx, dy) in placed:
            for p in panel.primitives:
                m = moved(p, dx, dy)
                prims.extend(m.expand() if isinstance(m, Table) else (m,))
        out.append(frame.sheet(prims, name if i == 0 else f"{name}-{i + 1}"))
    return out


def framed_sheets(panels: Sequence[Panel], *, size: str, standard: str, language: str, name: str,
                  fields: Mapping[str, str]) -> list[Sheet]:
    """Put panels, in order, on as many framed sheets as they need (``name``, ``name-2``, …).

    Raise :class:`DrawingError` when one panel alone is larger than the sheet's drawing area.
    """
    lay = _layout(lambda _k: panels, (1.0,), (), size=size, standard=standard,
                  language=language, fields=fields)
    return lay.sheets(language=language, name=name, fields=fields)


Groups = list[tuple[list[Panel], list[tuple[float, float]]]]


def refitted(panels: Sequence[Panel], area: BaseGeometry) -> list[Panel]:
    """The panels, those larger than the drawing area that can be redrawn smaller
    (``Panel.refit``: a table split into parts, text rewrapped) replaced by their parts."""
    ax0, ay0, ax1, ay1 = area.bounds
    w, h = ax1 - ax0 - GAP, ay1 - ay0 - GAP
    out: list[Panel] = []
    for p in panels:
        x0, y0, x1, y1 = p.bounds()
        if p.refit is not None and (x1 - x0 > w + 1e-9 or y1 - y0 > h + 1e-9):
            out.extend(p.refit(w, h))
        else:
            out.append(p)
    return out


def _flow(panels: Sequence[Panel], area: BaseGeometry, split: bool = False) -> Groups | Panel:
    """The panels, in order (refitted to the area), packed sheet after sheet: (panels, offsets)
    per sheet — or the first panel that does not fit on a sheet alone (``split``: see
    :func:`paginate`)."""
    return fewest_sheets(refitted(panels, area), area, split=split)


def _search(build: Callable[[float], Sequence[Panel]], area: BaseGeometry,
            ks: Sequence[float] = ENLARGEMENTS, reductions: Sequence[float] = REDUCTIONS,
            split: bool = False) -> tuple[float, Groups] | Panel:
    """The largest of ``ks`` at which the panels take one sheet, else the fewest sheets; when a
    panel fits at none of ``ks``, the largest of ``reductions`` at which all fit. Else the panel
    that does not fit at the smallest enlargement."""
    best: tuple[float, Groups] | None = None
    failed: Panel | None = None
    for k in ks:
        groups = _flow(build(k), area, split)
        if isinstance(groups, Panel):
            failed = groups                    # a panel alone is larger than the sheet
            continue
        if len(groups) == 1:
            return k, groups
        if best is None or len(groups) < len(best[1]):
            best = (k, groups)
    if best is not None:
        return best
    for k in reductions:
        groups = _flow(build(k), area, split)
        if not isinstance(groups, Panel):
            return k, groups
        failed = groups
    if failed is None:
        raise DrawingError("no enlargement to try")
    return failed


def _area(size: str, standard: str, language: str, fields: Mapping[str, str]) -> BaseGeometry:
    return drawing_area(make_frame(size, standard, dict(fields), language=language))


def _layout(build: Callable[[float], Sequence[Panel]], ks: Sequence[float],
            reductions: Sequence[float], *, size: str, standard: str, language: str,
            fields: Mapping[str, str], grow: bool = False,
            split: bool | None = None) -> Layout:
    area = _area(size, standard, language, fields)
    found = _search(build, area, ks, reductions, split=grow if split is None else split)
    if isinstance(found, Panel):
        raise _too_large(found, build, ks, reductions, area, size=size, standard=standard,
                         language=language, fields=fields)
    k, groups = found
    grown: dict[str, float] = {}
    if grow:
        from .grow import GROWTH, grow_into_room

        groups, grown = grow_into_room(build, [x for x in GROWTH if x > k], groups, area)
    return Layout(k, size, standard, [list(zip(p, o)) for p, o in groups], grown)


def _too_large(panel: Panel, build: Callable[[float], Sequence[Panel]], ks: Sequence[float],
               reductions: Sequence[float], area: BaseGeometry, *, size: str, standard: str,
               language: str, fields: Mapping[str, str]) -> DrawingError:
    """The error naming the panel that fits nowhere and the smallest sheet that takes them all."""
    x0, y0, x1, y1 = panel.bounds()
    ax0, ay0, ax1, ay1 = area.bounds
    smallest = (reductions or ks)[-1]
    bigger = SIZES[SIZES.index(size.upper()) + 1:] if size.upper() in SIZES else ()
    hint = Msg("errmsg.sheet_layout.fits_no_sheet")
    for other in bigger:
        if not isinstance(_search(build, _area(other, standard, language, fields), ks,
                                  reductions), Panel):
            hint = Msg("errmsg.sheet_layout.smallest_sheet", {"size": other})
            break
    return DrawingError(Msg("errmsg.sheet_layout.panel_name_fit", {"name": str(panel.name),
                                                                    "size": str(size),
                                                                    "value": f'{ax1 - ax0:.0f}',
                                                                    "value2": f'{ay1 - ay0:.0f}',
                                                                    "value3": f'{x1 - x0:.0f}',
                                                                    "value4": f'{y1 - y0:.0f}',
                                                                    "smallest": f'{smallest:g}',
                                                                    "hint": hint}))


def fitted_layout(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                  language: str, fields: Mapping[str, str], grow: bool = False,
                  split: bool | None = None) -> Layout:
    """The panels ``build(k)`` draws at the :func:`enlargement` that fills the sheet, placed;
    with ``grow``, each drawing then redrawn larger into its sheet's free room
    (:func:`.grow.grow_into_room`: for drawings whose scale nothing outside their panel repeats).
    ``split`` (default: ``grow``): a panel that does not fit a sheet's free room is split into
    it where it can be (a table's rows, a legend rewrapped: ``Panel.split_off``).

    Raise :class:`DrawingError` naming the panel and the smallest sheet that takes them when a
    panel is larger than the drawing area even at the smallest enlargement.
    """
    return _layout(build, ENLARGEMENTS, REDUCTIONS, size=size, standard=standard,
                   language=language, fields=fields, grow=grow, split=split)


def enlargement(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                language: str, fields: Mapping[str, str], split: bool = False) -> float:
    """The largest of :data:`ENLARGEMENTS` at which the panels ``build(k)`` draws take the fewest
    sheets (one when they can); one of :data:`REDUCTIONS` when a panel needs it; 1 when nothing
    fits (drawing then fails naming the panel). ``split``: as :func:`fitted_layout` lays them
    out with it."""
    found = _search(build, _area(size, standard, language, fields), split=split)
    return 1.0 if isinstance(found, Panel) else found[0]


def fitted_sheets(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                  language: str, name: str, fields: Mapping[str, str],
                  grow: bool = False, split: bool | None = None) -> list[Sheet]:
    """Panels drawn at the :func:`enlargement` that fills the sheet, on framed sheets (``grow``:
    see :func:`fitted_layout`)."""
    return fitted_layout(build, size=size, standard=standard, language=language, fields=fields,
                         grow=grow, split=split).sheets(language=language, name=name,
                                                        fields=fields)
