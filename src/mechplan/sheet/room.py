"""The free room of a drawing area as panels are packed on it: exact top-left (or leftmost)
spots, the free rectangles left, and a plain packing in order (:mod:`.layout` pages with it)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from shapely import box, get_coordinates
from shapely.geometry.base import BaseGeometry

from ..errors import DrawingError
from .panels import Panel

GAP = 8.0          # mm between panels


class Bounds:
    """``Panel.bounds`` remembered while a set of panels is packed (and its panels kept alive,
    so that an id is never reused for another panel)."""

    def __init__(self) -> None:
        self._known: dict[int, tuple[Panel, int, tuple[float, float, float, float]]] = {}

    def __call__(self, panel: Panel) -> tuple[float, float, float, float]:
        known = self._known.get(id(panel))
        if known is None or known[1] != len(panel.primitives):
            known = (panel, len(panel.primitives), panel.bounds())
            self._known[id(panel)] = known
        return known[2]


def _footprint(panel: Panel, bounds: Callable[[Panel], tuple[float, float, float, float]]
               ) -> tuple[float, float, float, float, float, float]:
    """(x0, y0, x1, y1) of a panel and its width and height with the gap around it."""
    x0, y0, x1, y1 = bounds(panel)
    return x0, y0, x1, y1, x1 - x0 + GAP, y1 - y0 + GAP


def _overlaps(rects: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """For rectangles (..., 4) as (x0, y0, x1, y1): whether each overlaps any of ``boxes``."""
    if not len(boxes):
        return np.zeros(rects.shape[:-1], dtype=bool)
    r = rects[..., None, :]
    e = 1e-6
    hit = ((boxes[:, 0] < r[..., 2] - e) & (boxes[:, 2] > r[..., 0] + e)
           & (boxes[:, 1] < r[..., 3] - e) & (boxes[:, 3] > r[..., 1] + e))
    return np.asarray(hit.any(axis=-1))


class Sheetful:
    """The free room of one drawing area as panels are put on it (each with the gap around it).

    The area is its bounding box less rectangles (the title block's corner). A spot is found
    exactly: a rectangle that fits can be slid left and up until its left edge lies on a
    vertical edge of the area or of a placed box and its top edge on a horizontal one, so those
    edges are the only candidates; the highest, then leftmost, is taken.
    """

    def __init__(self, area: BaseGeometry, *, columns: bool = False,
                 bounds: Bounds | None = None) -> None:
        """``columns``: take the leftmost, then highest spot (fill columns, not rows)."""
        self.columns = columns
        self.panel_bounds = bounds or Bounds()
        self.bounds = area.bounds
        cut = box(*self.bounds).difference(area)
        pieces = list(getattr(cut, "geoms", [cut])) if not cut.is_empty else []
        blocked = [g.bounds for g in pieces]
        if any(abs(box(*b).area - g.area) > 1e-6 for b, g in zip(blocked, pieces)):
            raise DrawingError("the drawing area must be a rectangle less rectangles")
        self.blocked = np.asarray(blocked, dtype=float).reshape(-1, 4)
        self.boxes = np.zeros((0, 4))
        corners = get_coordinates(area)
        self.xs, self.ys = set(corners[:, 0].tolist()), set(corners[:, 1].tolist())

    def _obstacles(self) -> np.ndarray:
        return np.vstack([self.blocked, self.boxes])

    def _edges(self) -> tuple[np.ndarray, np.ndarray]:
        xs = np.array(sorted(self.xs | set(self.boxes[:, 2].tolist())))
        ys = np.array(sorted(self.ys | set(self.boxes[:, 1].tolist()), reverse=True))
        return xs, ys

    def spot(self, w: float, h: float) -> tuple[float, float] | None:
        """The top-left corner of the highest, then leftmost, free w × h rectangle, or None."""
        ax0, ay0, ax1, ay1 = self.bounds
        xs, ys = self._edges()
        cx, cy = np.meshgrid(xs, ys)              # rows: y from the top, columns: x
        rects = np.stack([cx, cy - h, cx + w, cy], axis=-1)
        ok = ((rects[..., 0] >= ax0 - 1e-9) & (rects[..., 2] <= ax1 + 1e-9)
              & (rects[..., 1] >= ay0 - 1e-9) & (rects[..., 3] <= ay1 + 1e-9))
        ok &= ~_overlaps(rects, self._obstacles())
        if self.columns:
            found = np.argwhere(ok.T)             # leftmost, then highest
            if not len(found):
                return None
            i, j = found[0]
        else:
            found = np.argwhere(ok)               # row-major: highest, then leftmost
            if not len(found):
                return None
            j, i = found[0]
        return float(xs[i]), float(ys[j])

    def free_rectangles(self) -> list[tuple[float, float]]:
        """Sizes (w, h) of the free rectangles between the edges, largest area first."""
        ax0, ay0, ax1, ay1 = self.bounds
        xs, ys = self._edges()
        x0, y1, x1, y0 = np.meshgrid(xs, ys, xs, ys, indexing="ij", sparse=False)
        rects = np.stack([x0, y0, x1, y1], axis=-1)
        ok = (x1 > x0 + 1e-9) & (y1 > y0 + 1e-9)
        ok &= (x0 >= ax0 - 1e-9) & (x1 <= ax1 + 1e-9) & (y0 >= ay0 - 1e-9) & (y1 <= ay1 + 1e-9)
        rects = rects[ok]
        rects = rects[~_overlaps(rects, self._obstacles())]
        sizes = {(round(float(r[2] - r[0]), 6), round(float(r[3] - r[1]), 6)) for r in rects}
        return sorted(sizes, key=lambda wh: -wh[0] * wh[1])

    def put(self, panel: Panel) -> tuple[float, float] | None:
        """Place a panel at its spot: the offset that moves it there, or None (no room)."""
        x0, _y0, _x1, y1, w, h = _footprint(panel, self.panel_bounds)
        at = self.spot(w, h)
        if at is None:
            return None
        cx, cy = at
        self.boxes = np.vstack([self.boxes, [cx, cy - h, cx + w, cy]])
        # a panel's box includes the gap: half of it keeps the panel off the area's edge
        return (cx + GAP / 2 - x0, cy - GAP / 2 - y1)


def pack(panels: Sequence[Panel],
         area: BaseGeometry) -> tuple[list[tuple[float, float]], int | None]:
    """Top-left-first packing in order; return the offsets of the panels placed and the first
    that did not fit (None when all did)."""
    room = Sheetful(area)
    offsets: list[tuple[float, float]] = []
    for index, panel in enumerate(panels):
        at = room.put(panel)
        if at is None:
            return offsets, index
        offsets.append(at)
    return offsets, None
