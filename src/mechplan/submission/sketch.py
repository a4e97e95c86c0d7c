"""A drawing as a graph: line ends that are one point, arrowhead corners and loose ends, the
separate drawings (components) of a sheet, and the points its label texts stand for."""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import linear_sum_assignment

from ..geom.sketch import cluster, components, crossings, nearest
from .read import DrawnLine, Point, SheetText

#: strokes shorter than this (mm) may be arrowhead barbs, hatching or ticks
BARB_MAX_MM = 8.0
#: extra cost (× the label distance) of giving a label to a point where only 1 or 2 line ends
#: meet: points of a plan are where vectors meet; a construction line drawn past its point ends
#: loose, and the label is often nearer to that end
LOOSE_END_COST = {0: 0.45, 1: 0.45, 2: 0.15}
#: a point marked on the sheet (POINT, a small CIRCLE) is preferred by this much (× distance)
MARKER_BONUS = 0.2


@dataclass
class Graph:
    nodes: np.ndarray                  # (M, 2)
    line_nodes: list[tuple[int, int]]  # per line
    markers: dict[int, str]            # node → marker entity
    decoration: set[int]               # arrowhead corners: labels go elsewhere first
    component: list[int]               # node → drawing
    degree: list[int]                  # line ends at each node

    def nearest_component(self, at: Point, among: Iterable[int] | None = None) -> int:
        """The drawing whose node is nearest to ``at`` (only drawings ``among``); −1 if none."""
        mask = None if among is None else np.isin(self.component, list(among))
        i = nearest(self.nodes, at, mask=mask)
        return -1 if i < 0 else self.component[i]

    def ends_from(self, points: Iterable[Point]) -> Counter[int]:
        """Nodes at the far end of lines from ``points`` (the line's other end not one of them),
        with how many such lines end there: where vectors to those points start."""
        chosen = {tuple(np.round(p, 6)) for p in points}
        at_chosen = [tuple(np.round(p, 6)) in chosen for p in self.nodes]
        return Counter(b if at_chosen[a] else a for a, b in self.line_nodes
                       if at_chosen[a] != at_chosen[b])


def drawn_graph(lines: list[DrawnLine], markers: list[tuple[Point, str]], snap: float,
                heads: Sequence[tuple[Point, Point]] = ()) -> Graph:
    """The graph of a drawing; ``heads`` are the arrowheads (tip, middle of the base): where
    a vector's shaft ends at the base of its head is no point of its own — the point is the tip."""
    pts = [p for ln in lines for p in (ln.start, ln.end)] + [m[0] for m in markers]
    arr = np.asarray(pts, dtype=float).reshape(-1, 2)
    labels = cluster(arr, snap)
    m = int(labels.max()) + 1 if len(labels) else 0
    nodes = np.stack([np.bincount(labels, arr[:, i], m) for i in (0, 1)], axis=-1).reshape(
        -1, 2) / np.maximum(np.bincount(labels, minlength=m), 1)[:, None]  # mean of each cluster
    cl = labels.tolist()
    line_nodes = [(cl[2 * i], cl[2 * i + 1]) for i in range(len(lines))]
    marker_nodes = {cl[2 * len(lines) + j]: markers[j][1] for j in range(len(markers))}
    at_node: dict[int, list[int]] = {}
    for i, (a, b) in enumerate(line_nodes):
        at_node.setdefault(a, []).append(i)
        at_node.setdefault(b, []).append(i)
    length = [ln.length for ln in lines]
    decoration: set[int] = set()
    for n, idx in at_node.items():
        if n in marker_nodes or any(length[i] > BARB_MAX_MM for i in idx):
            continue
        for i in idx:
            other = line_nodes[i][1] if line_nodes[i][0] == n else line_nodes[i][0]
            if any(length[j] >= 2.5 * length[i] for j in at_node.get(other, ())):
                decoration.add(n)
                break
    degree_of = {n: len(idx) for n, idx in at_node.items()}
    for i, (a, b) in enumerate(line_nodes):
        da, db = degree_of.get(a, 0), degree_of.get(b, 0)
        if length[i] <= BARB_MAX_MM and da == 1 and db == 1 and a not in marker_nodes \
                and b not in marker_nodes:
            decoration |= {a, b}           # hatching of a support, a loose short stroke
        for end, other, deg in ((a, b, da), (b, a, db)):
            if deg == 1 and end not in marker_nodes and _overshoot(nodes, end, other, at_node,
                                                                   snap):
                decoration.add(end)
    decoration |= _head_bases(nodes, heads, marker_nodes, degree_of, snap)
    ends = np.asarray(line_nodes, dtype=np.int64).reshape(-1, 2)
    component = [int(x) for x in components(m, ends[:, 0], ends[:, 1])]
    degree = [len(at_node.get(i, ())) for i in range(m)]
    return Graph(nodes, line_nodes, marker_nodes, decoration, component, degree)


def _overshoot(nodes: np.ndarray, end: int, other: int, at_node: dict[int, list[int]],
               snap: float, reach: float = 15.0) -> bool:
    """True if the line from ``other`` to the loose ``end`` passes through a point where other
    lines meet, within ``reach`` mm of the end: a construction line drawn on past its point."""
    e, o = nodes[end], nodes[other]
    d = o - e
    length = float(np.hypot(*d))
    if length < 1e-9:
        return False
    u = d / length
    rel = nodes - e
    along = rel @ u
    across = np.abs(rel[:, 0] * u[1] - rel[:, 1] * u[0])
    hits = np.nonzero((along > snap) & (along < min(reach, length - snap)) & (across <= snap))[0]
    return any(len(at_node.get(int(k), ())) >= 2 for k in hits)


def _head_bases(nodes: np.ndarray, heads: Sequence[tuple[Point, Point]],
                marker_nodes: dict[int, str],
                degree_of: dict[int, int], snap: float) -> set[int]:
    """Nodes at the base of an arrowhead where only the shaft and the head meet: the shaft
    ends there because the head is drawn over its last millimetres, the point is the tip."""
    if not heads or not len(nodes):
        return set()
    bases = np.asarray([h[1] for h in heads], dtype=float).reshape(-1, 2)
    near = np.hypot(*(nodes[:, None, :] - bases[None, :, :]).transpose(2, 0, 1)).min(axis=1)
    return {int(n) for n in np.flatnonzero(near <= snap)
            if n not in marker_nodes and degree_of.get(int(n), 0) <= 2}


@dataclass(frozen=True, slots=True)
class Spot:
    """The point a label text stands for: a node of the graph, a crossing of two lines (``node``
    −1) or none within reach (``at`` None); ``distance`` from the text's box to it (mm), or to the
    nearest node when there is none."""

    node: int
    at: Point | None
    distance: float


def place_labels(texts: Sequence[SheetText], graph: Graph, lines: Sequence[DrawnLine],
                 tol: float) -> list[Spot]:
    """Give each label text a point within ``tol`` mm: line ends nearest to its text box, one label
    per point where possible (a minimum-cost assignment), arrowhead corners only when nothing else
    is near, a crossing of two lines when no line end is."""
    nodes, n, big = graph.nodes, len(graph.nodes), 1e6
    k = len(texts)
    node = [-1] * k
    nearest_mm = [math.inf] * k
    if n:
        d = np.stack([t.distance(nodes) for t in texts])        # labels × points
        nearest_mm = [float(row.min()) for row in d]
        # points of a plan are where lines meet; a loose end of one line (a construction line
        # drawn past its point, hatching) is taken only when nothing better is near; a point
        # marked with a dot or a small circle is preferred
        marker = np.isin(np.arange(n), list(graph.markers))
        deco = np.where(np.isin(np.arange(n), list(graph.decoration)), tol, 0.0)
        loose = np.array([LOOSE_END_COST.get(deg, 0.0) for deg in graph.degree]) * tol
        score = np.where(d <= tol, np.where(marker, d - MARKER_BONUS * tol, d + deco + loose),
                         np.inf)
        best = np.argsort(score, axis=1, kind="stable")[:, :8]          # 8 points a label
        keep = np.zeros(score.shape, dtype=bool)
        np.put_along_axis(keep, best, True, axis=1)
        keep &= np.isfinite(score)
        columns = np.flatnonzero(keep.any(axis=0))
        cost = np.full((k, len(columns) + k), big)
        cost[:, :len(columns)] = np.where(keep[:, columns], score[:, columns], big)
        # sharing a point with another label (p ≡ o1) costs more than a point of its own
        first = score[np.arange(k), best[:, 0]]
        cost[np.arange(k), len(columns) + np.arange(k)] = np.where(
            np.isfinite(first), first + 0.5 * tol, big)
        cost += tol                         # keep costs positive (marker bonus)
        for r, j in zip(*linear_sum_assignment(cost)):
            if cost[r, j] < big:
                node[r] = int(columns[j] if j < len(columns) else best[r, 0])
    segments = np.asarray([(ln.start, ln.end) for ln in lines]).reshape(-1, 2, 2)
    spots: list[Spot] = []
    for t, i, far in zip(texts, node, nearest_mm):
        if i >= 0:
            at = (float(nodes[i][0]), float(nodes[i][1]))
            spots.append(Spot(i, at, t.distance(at)))
            continue
        meets = crossings(segments, t.centre, tol + max(t.half))
        to_meets = t.distance(meets)
        if (to_meets <= tol).any():
            m = int(np.argmin(to_meets))
            spots.append(Spot(-1, (float(meets[m][0]), float(meets[m][1])), float(to_meets[m])))
        else:
            spots.append(Spot(-1, None, far))
    return spots
