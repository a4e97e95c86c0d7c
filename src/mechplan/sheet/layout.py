"""Lay panels out on framed sheets: pack them top-left first, flow onto more sheets when full.

Used by every capability's sheet set (dynamics, engine, cam, gears); each sheet gets its frame and
title block with its number and the total.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence

from shapely import box
from shapely.geometry.base import BaseGeometry
from shapely.prepared import prep

from ..drafting.frame import FrameLayout, make_frame
from ..drafting.primitives import Arc, Arrow, Circle, Line, Polyline, Primitive, Sheet, Table, Text
from ..errors import DrawingError
from .panels import Panel

GAP = 8.0          # mm between panels

#: enlargements of a capability sheet's drawings and diagrams tried, largest first; text heights
#: and tables keep their size
ENLARGEMENTS = (2.0, 1.6, 1.25, 1.0, 0.8, 0.6, 0.5)


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


def pack(panels: Sequence[Panel],
         area: BaseGeometry) -> tuple[list[tuple[float, float]], int | None]:
    """Top-left-first packing; return the offsets of the panels placed and the first that did not
    fit."""
    inside = prep(area)
    ax0, ay0, ax1, ay1 = area.bounds
    placed: list[BaseGeometry] = []
    offsets: list[tuple[float, float]] = []
    for index, panel in enumerate(panels):
        x0, y0, x1, y1 = panel.bounds()
        w, h = x1 - x0 + GAP, y1 - y0 + GAP
        if w > ax1 - ax0 or h > ay1 - ay0:
            return offsets, index
        candidates = {(ax0 + GAP / 2, ay1 - GAP / 2)}
        for r in placed:
            bx0, by0, bx1, by1 = r.bounds
            candidates |= {(bx1, by1), (bx0, by0), (ax0 + GAP / 2, by0), (bx1, ay1 - GAP / 2)}
        grid = [(ax0 + i * 10.0, ay1 - j * 10.0) for j in range(int((ay1 - ay0 - h) / 10) + 1)
                for i in range(int((ax1 - ax0 - w) / 10) + 1)]
        best = None
        for cx, cy in sorted(candidates, key=lambda q: (-q[1], q[0])) + grid:
            if cx + w > ax1 or cy - h < ay0:
                continue
            rect = box(cx, cy - h, cx + w, cy)
            if inside.contains(rect) and not any(rect.intersects(r) and
                                                 rect.intersection(r).area > 1e-6 for r in placed):
                best = rect
                break
        if best is None:
            return offsets, index
        placed.append(best)
        bx0, by0, _, by1 = best.bounds
        offsets.append((bx0 + GAP / 2 - x0, by1 - GAP / 2 - y1))
    return offsets, None


def framed_sheets(panels: Sequence[Panel], *, size: str, standard: str, language: str, name: str,
                  fields: Mapping[str, str]) -> list[Sheet]:
    """Put panels, in order, on as many framed sheets as they need (``name``, ``name-2``, …).

    Raise :class:`DrawingError` when one panel alone is larger than the sheet's drawing area.
    """
    area = drawing_area(make_frame(size, standard, dict(fields), language=language))
    groups = _flow(panels, area)
    if isinstance(groups, Panel):
        x0, y0, x1, y1 = groups.bounds()
        raise DrawingError(f"the panel '{groups.name}' ({x1 - x0:.0f} × {y1 - y0:.0f} mm) "
                           f"does not fit on an {size} sheet; use a larger sheet "
                           "(--sheet A1 or A0)")
    sheets: list[Sheet] = []
    for i, (part, offsets) in enumerate(groups):
        f = dict(fields)
        f.update({"sheet_number": str(i + 1), "sheets_total": str(len(groups))})
        frame = make_frame(size, standard, f, language=language)
        prims: list[Primitive] = []
        for panel, (dx, dy) in zip(part, offsets):
            for p in panel.primitives:
                m = moved(p, dx, dy)
                prims.extend(m.expand() if isinstance(m, Table) else (m,))
        sheets.append(frame.sheet(prims, name if i == 0 else f"{name}-{i + 1}"))
    return sheets


Groups = list[tuple[list[Panel], list[tuple[float, float]]]]


def _flow(panels: Sequence[Panel], area: BaseGeometry) -> Groups | Panel:
    """The panels, in order, packed sheet after sheet: (panels, offsets) per sheet — or the first
    panel that does not fit on a sheet alone."""
    groups: Groups = []
    rest = list(panels)
    while rest:
        offsets, failed = pack(rest, area)
        if failed == 0:
            return rest[0]
        n = len(offsets) if failed is not None else len(rest)
        groups.append((rest[:n], offsets))
        rest = rest[n:]
    return groups


def enlargement(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                language: str, fields: Mapping[str, str]) -> float:
    """The largest of :data:`ENLARGEMENTS` at which the panels ``build(k)`` draws take the fewest
    sheets (one when they can)."""
    area = drawing_area(make_frame(size, standard, dict(fields), language=language))
    best: tuple[int, float] | None = None
    for k in ENLARGEMENTS:
        groups = _flow(build(k), area)
        if isinstance(groups, Panel):
            continue                           # a panel alone is larger than the sheet
        if len(groups) == 1:
            return k
        if best is None or len(groups) < best[0]:
            best = (len(groups), k)
    return best[1] if best is not None else 1.0


def fitted_sheets(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                  language: str, name: str, fields: Mapping[str, str]) -> list[Sheet]:
    """Panels drawn at the :func:`enlargement` that fills the sheet, on framed sheets."""
    k = enlargement(build, size=size, standard=standard, language=language, fields=fields)
    return framed_sheets(build(k), size=size, standard=standard, language=language, name=name,
                         fields=fields)
