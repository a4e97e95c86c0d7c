"""Label placement: try positions around a point, keep the one that crosses the fewest lines and
that a reader gives to its own point (nearer to it than to any other point of the plan)."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from shapely import STRtree, box, distance, points
from shapely.geometry import LineString

from .fonts import text_width_mm
from .primitives import Arrow, HAlign, Line, Polyline, Primitive, Text, VAlign

#: candidate directions (degrees), right-above first as draftsmen usually write
_DIRECTIONS = (45, 135, 315, 225, 0, 90, 180, 270, 22, 158, 338, 202)
#: a label's box must be this much (mm) nearer its own point than any other point of the plan
OWN_MARGIN_MM = 0.8
#: how much nearer (mm) an unmarked line end must be than a marked point for a reader to take
#: it instead (it prefers marked points; mechplan.submission.sketch gives them 1.4 mm at least)
WEAK_MARGIN_MM = 1.2
#: the cost of a spot where a reader could give the label to another point
AMBIGUOUS_COST = 50.0


class LabelPlacer:
    """Place labels near anchors avoiding the given lines and each other."""

    def __init__(self, obstacles: Sequence[Primitive], height_mm: float,
                 points_mm: Sequence[tuple[float, float]] = (),
                 weak_mm: Sequence[tuple[float, float]] = ()) -> None:
        """``points_mm``: the points of the plan (markers) a reader attaches labels to;
        ``weak_mm``: unmarked line ends a reader takes over a marked point only when nearer by
        more than :data:`WEAK_MARGIN_MM` (the other positions of a position plan)."""
        geoms = []
        for p in obstacles:
            if isinstance(p, (Line, Arrow)):
                geoms.append(LineString([p.start, p.end]))
            elif isinstance(p, Polyline):
                pts = list(p.points) + ([p.points[0]] if p.closed else [])
                geoms.append(LineString(pts))
        self.lines = geoms
        self.tree = STRtree(geoms) if geoms else None
        self.placed: list = []
        self.h = height_mm
        self.xy = np.asarray(points_mm, dtype=float).reshape(-1, 2)
        self.points = points(self.xy)
        self.weak_xy = np.asarray(weak_mm, dtype=float).reshape(-1, 2)
        self.weak = points(self.weak_xy)

    def _cost(self, rect) -> float:
        cost = 0.0
        if self.tree is not None:
            for i in self.tree.query(rect):
                cost += self.lines[int(i)].intersection(rect).length
        for other in self.placed:
            if other.intersects(rect):
                cost += 100.0 + other.intersection(rect).area
        return cost

    def _ambiguity(self, rect, anchor: tuple[float, float]) -> float:
        """How much nearer (mm) the box is to another point than to its own, plus the margin."""
        if not len(self.points) and not len(self.weak_xy):
            return 0.0
        d = distance(rect, self.points)
        own = float(distance(rect, points(anchor)))
        mine = np.hypot(*(self.xy - anchor).T) < 0.3
        others = d[~mine]
        worse = max(0.0, own + OWN_MARGIN_MM - float(others.min())) if len(others) else 0.0
        if len(self.weak_xy):
            weak = distance(rect, self.weak)[np.hypot(*(self.weak_xy - anchor).T) >= 0.3]
            if len(weak):
                worse = max(worse, own + OWN_MARGIN_MM - WEAK_MARGIN_MM - float(weak.min()))
        return worse

    def place(self, anchor: tuple[float, float], text: str) -> Text:
        """Return the label as a Text at the best free spot around ``anchor``."""
        w = text_width_mm(text, self.h)
        best = None
        for gap in (1.2, 2.5, 4.0):
            for deg in _DIRECTIONS:
                a = math.radians(deg)
                cx = anchor[0] + math.cos(a) * (gap + w / 2)
                cy = anchor[1] + math.sin(a) * (gap + self.h / 2)
                rect = box(cx - w / 2, cy - self.h / 2 - 0.3, cx + w / 2, cy + self.h / 2 + 0.3)
                cost = self._cost(rect) + 0.05 * gap
                worse = self._ambiguity(rect, anchor)
                if worse > 0:
                    cost += AMBIGUOUS_COST + worse
                if best is None or cost < best[0]:
                    best = (cost, cx, cy, rect)
            if best is not None and best[0] < 0.2:
                break
        assert best is not None
        self.placed.append(best[3])
        return Text((best[1], best[2]), text, self.h, halign=HAlign.CENTER, valign=VAlign.MIDDLE)
