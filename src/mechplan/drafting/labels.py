"""Label placement: try positions around a point, ring after ring, and keep the nearest one that
overprints no other label, no line's end and no other point, crosses the fewest lines and that a
reader gives to its own point (nearer to it than to any other point of the plan)."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from shapely import STRtree, box, intersection, length, points
from shapely.geometry import LineString

from .fonts import font_of, text_width_mm
from .primitives import Arrow, HAlign, Line, Polyline, Primitive, Role, Text, VAlign

#: candidate directions (degrees), right-above first as draftsmen usually write
_DIRECTIONS = (45, 135, 315, 225, 0, 90, 180, 270, 22, 158, 338, 202, 68, 112, 248, 292)
#: distances (mm) from the anchor to the label's box tried, nearest first; the farther rings
#: only when every nearer spot overprints something
GAPS_MM = (1.2, 2.5, 4.0, 5.5, 7.5, 10.0, 13.0, 17.0)
#: a label's box must be this much (mm) nearer its own point than any other point of the plan
OWN_MARGIN_MM = 0.8
#: how much nearer (mm) an unmarked line end must be than a marked point for a reader to take
#: it instead (it prefers marked points; mechplan.submission.sketch gives them 1.4 mm at least)
WEAK_MARGIN_MM = 1.2
#: the cost of a spot where a reader could give the label to another point
AMBIGUOUS_COST = 50.0
#: clearance (mm) kept around a label's box from other labels, line ends and points
CLEAR_MM = 0.3
#: the descender below the baseline of a text, in text heights (as the panels' boxes count it)
DESCENDER = 0.3
#: a label placed farther than this (mm) from its point is tied to it by a thin leader
LEADER_FROM_MM = 2.4
#: … or nearer another point of the plan than its own, when it is this far (mm) from it
LEADER_MIN_MM = 0.5


def text_box(t: Text) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of a one-line text: its advance width, the capital height above the
    baseline and a descender below it."""
    w = text_width_mm(t.string, t.height_mm, font_of(t))
    x, y = t.position
    dx = {HAlign.LEFT: 0.0, HAlign.CENTER: -w / 2, HAlign.RIGHT: -w}[t.halign]
    dy = {VAlign.BASELINE: 0.0, VAlign.BOTTOM: 0.0, VAlign.MIDDLE: -t.height_mm / 2,
          VAlign.TOP: -t.height_mm}[t.valign]
    return (x + dx, y + dy - DESCENDER * t.height_mm, x + dx + w, y + dy + t.height_mm)


class LabelPlacer:
    """Place labels near anchors avoiding the given lines, their ends, the given texts and each
    other."""

    def __init__(self, obstacles: Sequence[Primitive], height_mm: float,
                 points_mm: Sequence[tuple[float, float]] = (),
                 weak_mm: Sequence[tuple[float, float]] = ()) -> None:
        """``obstacles``: lines to avoid crossing (their ends never overprinted) and texts already
        drawn; ``points_mm``: the points of the plan (markers) a reader attaches labels to;
        ``weak_mm``: unmarked line ends a reader takes over a marked point only when nearer by
        more than :data:`WEAK_MARGIN_MM` (the other positions of a position plan)."""
        geoms = []
        ends: list[tuple[float, float]] = []
        self.boxes: list[tuple[float, float, float, float]] = []
        for p in obstacles:
            if isinstance(p, (Line, Arrow)):
                geoms.append(LineString([p.start, p.end]))
                ends += [p.start, p.end]
            elif isinstance(p, Polyline):
                pts = list(p.points) + ([p.points[0]] if p.closed else [])
                geoms.append(LineString(pts))
                if not p.closed:
                    ends += [p.points[0], p.points[-1]]
            elif isinstance(p, Text):
                self.boxes.append(text_box(p))
        self.lines = np.asarray(geoms, dtype=object)
        self.tree = STRtree(geoms) if geoms else None
        self.h = height_mm
        self.xy = np.asarray(points_mm, dtype=float).reshape(-1, 2)
        self.points = points(self.xy)
        self.ends = np.asarray(ends, dtype=float).reshape(-1, 2)
        #: thin leaders (layer DIMENSION) from far labels to their points; the caller draws them
        self.leaders: list[Line] = []
        self.weak_xy = np.asarray(weak_mm, dtype=float).reshape(-1, 2)
        self.weak = points(self.weak_xy)

    @property
    def placed(self) -> list:
        """The boxes of the texts placed or given, as shapely boxes."""
        return [box(*b) for b in self.boxes]

    def _overprints(self, rects: np.ndarray, anchor: tuple[float, float]) -> np.ndarray:
        """For boxes (n, 4): whether each (with its clearance) covers a label, a line's end or
        another point."""
        r = rects + np.array([-CLEAR_MM, -CLEAR_MM, CLEAR_MM, CLEAR_MM])
        x0, y0, x1, y1 = (r[:, i:i + 1] for i in range(4))
        hit = np.zeros(len(r), dtype=bool)
        if self.boxes:
            b = np.asarray(self.boxes)
            hit |= ((b[:, 0] < x1) & (b[:, 2] > x0) & (b[:, 1] < y1) & (b[:, 3] > y0)).any(axis=1)
        for pts in (self.ends, self.xy):
            if len(pts):
                pts = pts[np.hypot(pts[:, 0] - anchor[0], pts[:, 1] - anchor[1]) > 0.3]
                px, py = pts[:, 0], pts[:, 1]
                hit |= ((px > x0) & (px < x1) & (py > y0) & (py < y1)).any(axis=1)
        return hit

    def _crossing(self, rect) -> float:
        """The length (mm) of the lines and leaders inside a box."""
        cost = 0.0
        if self.tree is not None:
            near = self.tree.query(rect)
            if len(near):
                cost += float(length(intersection(self.lines[near], rect)).sum())
        for leader in self.leaders:
            cost += LineString([leader.start, leader.end]).intersection(rect).length
        return cost

    def _ambiguity(self, rect, anchor: tuple[float, float]) -> float:
        """How much nearer (mm) the box is to another point or line end than to its own point,
        plus the margin (a reader, and ``mechplan check``, gives a label to the nearest end);
        a weak point counts only when nearer by more than :data:`WEAK_MARGIN_MM`."""
        x0, y0, x1, y1 = rect.bounds

        def nearest(pts: np.ndarray) -> float:
            pts = pts[np.hypot(*(pts - anchor).T) >= 0.3] if len(pts) else pts
            if not len(pts):
                return math.inf
            dx = np.maximum(np.maximum(x0 - pts[:, 0], pts[:, 0] - x1), 0.0)
            dy = np.maximum(np.maximum(y0 - pts[:, 1], pts[:, 1] - y1), 0.0)
            return float(np.hypot(dx, dy).min())

        own = math.hypot(max(x0 - anchor[0], anchor[0] - x1, 0.0),
                         max(y0 - anchor[1], anchor[1] - y1, 0.0))
        strong = own + OWN_MARGIN_MM - nearest(np.vstack([self.xy, self.ends]))
        weak = own + OWN_MARGIN_MM - WEAK_MARGIN_MM - nearest(self.weak_xy)
        return max(0.0, strong, weak)

    def place(self, anchor: tuple[float, float], text: str, height_mm: float | None = None,
              toward_deg: float | None = None) -> Text:
        """Return the label as a Text at the best free spot around ``anchor``.

        ``toward_deg``: the direction preferred (a position's number outward from the crank
        circle); else right-above first.
        """
        h = self.h if height_mm is None else height_mm
        w = text_width_mm(text, h)
        # the box's vertical offset from the text's middle (descender below the baseline)
        lo, hi = -h / 2 - DESCENDER * h, h / 2
        directions: Sequence[float] = _DIRECTIONS
        if toward_deg is not None:
            directions = sorted(_DIRECTIONS, key=lambda d: abs((d - toward_deg + 180) % 360 - 180))
        best = None
        angles = np.radians(np.asarray(directions, dtype=float))
        for ring, gap in enumerate(GAPS_MM):
            cxs = anchor[0] + np.cos(angles) * (gap + w / 2)
            cys = anchor[1] + np.sin(angles) * (gap + (hi - lo) / 2) - (hi + lo) / 2
            rects = np.stack([cxs - w / 2, cys + lo, cxs + w / 2, cys + hi], axis=1)
            covered = self._overprints(rects, anchor)
            for order in range(len(directions)):
                cx, cy = float(cxs[order]), float(cys[order])
                r = (cx - w / 2, cy + lo, cx + w / 2, cy + hi)
                if covered[order] or self._leader_crosses(anchor, r):
                    continue
                rect = box(r[0] - CLEAR_MM, r[1] - CLEAR_MM, r[2] + CLEAR_MM, r[3] + CLEAR_MM)
                cost = self._crossing(rect) + 0.05 * gap + (0.02 * order if toward_deg else 0.0)
                worse = self._ambiguity(rect, anchor)
                if worse > 0:
                    cost += AMBIGUOUS_COST + worse
                if best is None or cost < best[0]:
                    best = (cost, cx, cy, r, worse > 0)
                if cost <= 0.05 * gap + 1e-9:
                    break               # clear of lines and its own: the ring's first choice
            if best is not None and (best[0] < 0.2 + 0.05 * gap + 0.4 or ring >= 2) \
                    and best[0] < AMBIGUOUS_COST:
                break
        if best is None:            # crowded everywhere: the spot right-above the farthest ring
            gap = GAPS_MM[-1] + 4.0
            cx, cy = anchor[0] + gap + w / 2, anchor[1] + gap
            best = (0.0, cx, cy, (cx - w / 2, cy + lo, cx + w / 2, cy + hi), True)
        self.boxes.append(best[3])
        self._leader(anchor, best[3], best[4])
        return Text((best[1], best[2]), text, h, halign=HAlign.CENTER, valign=VAlign.MIDDLE)

    @staticmethod
    def _leader_line(anchor: tuple[float, float], r: tuple[float, float, float, float],
                     ambiguous: bool = False) -> Line | None:
        """A thin line from the point to the edge of the label's box when the label is far from
        it or nearer another point (None otherwise); ``mechplan check`` reads the label at the
        leader's start."""
        nx, ny = min(max(anchor[0], r[0]), r[2]), min(max(anchor[1], r[1]), r[3])
        d = math.hypot(nx - anchor[0], ny - anchor[1])
        if d <= (LEADER_MIN_MM if ambiguous else LEADER_FROM_MM):
            return None
        # aimed at the label's middle and ended at its box: a reader follows the leader into the
        # text (its nearest corner may lie as near a neighbour's label)
        (ax, ay), (cx, cy) = anchor, ((r[0] + r[2]) / 2, (r[1] + r[3]) / 2)
        enter = [(lo - a) / (c - a) if c > a else (hi - a) / (c - a)
                 for a, c, lo, hi in ((ax, cx, r[0], r[2]), (ay, cy, r[1], r[3])) if c != a]
        t = min(max([0.0, *enter]), 1.0)
        return Line(anchor, (ax + t * (cx - ax), ay + t * (cy - ay)), Role.DIMENSION)

    def _leader_crosses(self, anchor: tuple[float, float],
                        r: tuple[float, float, float, float]) -> bool:
        """Tell whether the leader a far spot needs would cross a label placed before."""
        line = self._leader_line(anchor, r)
        if line is None or not self.boxes:
            return False
        seg = LineString([line.start, line.end])
        return any(seg.intersects(box(b[0] - CLEAR_MM, b[1] - CLEAR_MM, b[2] + CLEAR_MM,
                                      b[3] + CLEAR_MM)) for b in self.boxes)

    def _leader(self, anchor: tuple[float, float], r: tuple[float, float, float, float],
                ambiguous: bool) -> None:
        line = self._leader_line(anchor, r, ambiguous)
        if line is not None:
            self.leaders.append(line)
            self.ends = np.vstack([self.ends, [line.start, line.end]])
