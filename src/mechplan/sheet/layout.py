"""Lay panels out on framed sheets: pack them top-left first, flow onto more sheets when full.

Used by every capability's sheet set (dynamics, engine, cam, gears); each sheet gets its frame and
title block with its number and the total.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

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
        # a panel's box includes the gap: half of it keeps the panel off the area's edge
        candidates = {(ax0, ay1)}
        for r in placed:
            bx0, by0, bx1, by1 = r.bounds
            candidates |= {(bx1, by1), (bx0, by0), (ax0, by0), (bx1, ay1)}
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


@dataclass(frozen=True)
class Layout:
    """Panels drawn at enlargement ``k`` and placed on sheets: per sheet, (panel, offset) pairs."""

    k: float
    size: str
    standard: str
    placements: list[list[tuple[Panel, tuple[float, float]]]]

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


def _flow(panels: Sequence[Panel], area: BaseGeometry) -> Groups | Panel:
    """The panels, in order (refitted to the area), packed sheet after sheet: (panels, offsets)
    per sheet — or the first panel that does not fit on a sheet alone."""
    groups: Groups = []
    rest = refitted(panels, area)
    while rest:
        offsets, failed = pack(rest, area)
        if failed == 0:
            return rest[0]
        n = len(offsets) if failed is not None else len(rest)
        groups.append((rest[:n], offsets))
        rest = rest[n:]
    return groups


def _search(build: Callable[[float], Sequence[Panel]], area: BaseGeometry,
            ks: Sequence[float] = ENLARGEMENTS,
            reductions: Sequence[float] = REDUCTIONS) -> tuple[float, Groups] | Panel:
    """The largest of ``ks`` at which the panels take one sheet, else the fewest sheets; when a
    panel fits at none of ``ks``, the largest of ``reductions`` at which all fit. Else the panel
    that does not fit at the smallest enlargement."""
    best: tuple[float, Groups] | None = None
    failed: Panel | None = None
    for k in ks:
        groups = _flow(build(k), area)
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
        groups = _flow(build(k), area)
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
            fields: Mapping[str, str]) -> Layout:
    area = _area(size, standard, language, fields)
    found = _search(build, area, ks, reductions)
    if isinstance(found, Panel):
        raise _too_large(found, build, ks, reductions, area, size=size, standard=standard,
                         language=language, fields=fields)
    k, groups = found
    return Layout(k, size, standard, [list(zip(p, o)) for p, o in groups])


def _too_large(panel: Panel, build: Callable[[float], Sequence[Panel]], ks: Sequence[float],
               reductions: Sequence[float], area: BaseGeometry, *, size: str, standard: str,
               language: str, fields: Mapping[str, str]) -> DrawingError:
    """The error naming the panel that fits nowhere and the smallest sheet that takes them all."""
    x0, y0, x1, y1 = panel.bounds()
    ax0, ay0, ax1, ay1 = area.bounds
    smallest = (reductions or ks)[-1]
    bigger = SIZES[SIZES.index(size.upper()) + 1:] if size.upper() in SIZES else ()
    hint = "it fits on no sheet up to A0"
    for other in bigger:
        if not isinstance(_search(build, _area(other, standard, language, fields), ks,
                                  reductions), Panel):
            hint = f"the smallest sheet that takes it is {other} (--sheet {other})"
            break
    return DrawingError(f"the panel '{panel.name}' must fit the drawing area of an {size} sheet "
                        f"({ax1 - ax0:.0f} × {ay1 - ay0:.0f} mm) (got {x1 - x0:.0f} × "
                        f"{y1 - y0:.0f} mm at the smallest enlargement {smallest:g}); {hint}")


def fitted_layout(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                  language: str, fields: Mapping[str, str]) -> Layout:
    """The panels ``build(k)`` draws at the :func:`enlargement` that fills the sheet, placed.

    Raise :class:`DrawingError` naming the panel and the smallest sheet that takes them when a
    panel is larger than the drawing area even at the smallest enlargement.
    """
    return _layout(build, ENLARGEMENTS, REDUCTIONS, size=size, standard=standard,
                   language=language, fields=fields)


def enlargement(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                language: str, fields: Mapping[str, str]) -> float:
    """The largest of :data:`ENLARGEMENTS` at which the panels ``build(k)`` draws take the fewest
    sheets (one when they can); one of :data:`REDUCTIONS` when a panel needs it; 1 when nothing
    fits (drawing then fails naming the panel)."""
    found = _search(build, _area(size, standard, language, fields))
    return 1.0 if isinstance(found, Panel) else found[0]


def fitted_sheets(build: Callable[[float], Sequence[Panel]], *, size: str, standard: str,
                  language: str, name: str, fields: Mapping[str, str]) -> list[Sheet]:
    """Panels drawn at the :func:`enlargement` that fills the sheet, on framed sheets."""
    return fitted_layout(build, size=size, standard=standard, language=language,
                         fields=fields).sheets(language=language, name=name, fields=fields)
