"""A drawing as a graph: line ends that are one point, arrowhead corners and loose ends, the
separate drawings (components) of a sheet, and the points its label texts stand for."""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np
import shapely
from scipy.optimize import linear_sum_assignment
from scipy.spatial import cKDTree
from shapely import STRtree

from ..geom.sketch import cluster, components, crossings
from .read import DrawnLine, Point, SheetText

#: strokes shorter than this (mm) may be arrowhead barbs, hatching or ticks
BARB_MAX_MM = 8.0
#: extra cost (× the label distance) of giving a label to a point where only 1 or 2 line ends
#: meet: points of a plan are where vectors meet; a construction line drawn past its point ends
#: loose, and the label is often nearer to that end
LOOSE_END_COST = {0: 0.45, 1: 0.45, 2: 0.15}
#: a point marked on the sheet (POINT, a small CIRCLE) is preferred by this much (× distance)
MARKER_BONUS = 0.2
#: marked points and strokes no longer than this (mm), apart from the lines of a drawing, and
#: this near (mm) one of its nodes, are part of it (:func:`_join_fragments`)
FRAGMENT_MM = 3.0
FRAGMENT_JOIN_MM = 2.0


@dataclass
class Graph:
    nodes: np.ndarray                  # (M, 2)
    line_nodes: list[tuple[int, int]]  # per line
    markers: dict[int, str]            # node → marker entity
    decoration: set[int]               # arrowhead corners: labels go elsewhere first
    component: list[int]               # node → drawing
    degree: list[int]                  # line ends at each node
    #: loose line ends (end, other end) not yet told apart: a construction line drawn on past its
    #: point is decoration too, found only for the ends a label may take (:meth:`decorated`)
    loose: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=np.int64),
                              repr=False, compare=False)
    snap: float = 0.0
    _trees: dict[frozenset[int] | None, tuple[cKDTree, np.ndarray]] = field(
        default_factory=dict, repr=False, compare=False)
    _cache: dict[str, np.ndarray] = field(default_factory=dict, repr=False, compare=False)

    def decorated(self, nodes: np.ndarray) -> np.ndarray:
        """Whether each of ``nodes`` is decoration (an arrowhead corner, hatching, a line's
        loose end drawn past its point): labels go elsewhere first."""
        nodes = np.asarray(nodes, dtype=np.int64)
        out = np.isin(nodes, list(self.decoration))
        if len(self.loose) and len(nodes):
            ask = self.loose[np.isin(self.loose[:, 0], nodes)]
            over = _overshoots(self.nodes, ask, np.asarray(self.degree, dtype=np.int64),
                               self.snap)
            out |= np.isin(nodes, list(over))
        return out

    def tree(self, among: Iterable[int] | None = None) -> tuple[cKDTree, np.ndarray]:
        """A KD-tree of the nodes (only those of drawings ``among``) and their node indices;
        built once per choice of drawings."""
        key = None if among is None else frozenset(among)
        if key not in self._trees:
            idx = (np.arange(len(self.nodes)) if key is None else
                   np.flatnonzero(np.isin(np.asarray(self.component), list(key))))
            self._trees[key] = (cKDTree(self.nodes[idx].reshape(-1, 2)), idx)
        return self._trees[key]

    def nearest_component(self, at: Point, among: Iterable[int] | None = None) -> int:
        """The drawing whose node is nearest to ``at`` (only drawings ``among``; the first node
        of equals); −1 if none."""
        tree, idx = self.tree(among)
        if not len(idx):
            return -1
        d, _ = tree.query(at)
        if not np.isfinite(d):
            return -1
        ties = tree.query_ball_point(at, d * (1 + 1e-12) + 1e-300)
        i = int(idx[min(ties)]) if ties else int(idx[_])
        return self.component[i]

    def ends_from(self, points: Iterable[Point]) -> Counter[int]:
        """Nodes at the far end of lines from ``points`` (the line's other end not one of them),
        with how many such lines end there: where vectors to those points start."""
        chosen = np.unique(np.round(np.asarray(list(points), dtype=float).reshape(-1, 2), 6),
                           axis=0)
        if not len(chosen) or not self.line_nodes:
            return Counter()
        if "rounded" not in self._cache:
            self._cache["rounded"] = np.round(self.nodes, 6)
        rounded = self._cache["rounded"]
        at_chosen = np.zeros(len(self.nodes), dtype=bool)
        for p in chosen:                 # a plan has tens of points, a sheet 10^5 nodes
            at_chosen |= (rounded == p).all(axis=1)
        ends = np.asarray(self.line_nodes, dtype=np.int64)
        a, b = ends[:, 0], ends[:, 1]
        crossing = at_chosen[a] != at_chosen[b]
        far = np.where(at_chosen[a], b, a)[crossing]
        return Counter(far.tolist())


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
    loose: list[tuple[int, int]] = []
    for i, (a, b) in enumerate(line_nodes):
        da, db = degree_of.get(a, 0), degree_of.get(b, 0)
        if length[i] <= BARB_MAX_MM and da == 1 and db == 1 and a not in marker_nodes \
                and b not in marker_nodes:
            decoration |= {a, b}           # hatching of a support, a loose short stroke
        for end, other, deg in ((a, b, da), (b, a, db)):
            if deg == 1 and end not in marker_nodes:
                loose.append((end, other))
    decoration |= _head_bases(nodes, heads, marker_nodes, degree_of, snap)
    ends = np.asarray(line_nodes, dtype=np.int64).reshape(-1, 2)
    component = [int(x) for x in components(m, ends[:, 0], ends[:, 1])]
    degree = [len(at_node.get(i, ())) for i in range(m)]
    _join_fragments(nodes, line_nodes, length, component)
    return Graph(nodes, line_nodes, marker_nodes, decoration, component, degree,
                 np.asarray(loose, dtype=np.int64).reshape(-1, 2), snap)


def _join_fragments(nodes: np.ndarray, line_nodes: list[tuple[int, int]], length: list[float],
                    component: list[int]) -> None:
    """Give a fragment — a drawing of marked points and strokes no longer than
    :data:`FRAGMENT_MM` — the drawing of the nearest node of a larger one within
    :data:`FRAGMENT_JOIN_MM`: the points of a force polygon joined by loads too small to draw
    (an inertia force of 0.1 mm, a weight of 0.8 mm) are marked, or joined by stubs, and are
    points of that polygon, not a drawing of their own."""
    if not len(nodes):
        return
    comp = np.asarray(component, dtype=np.int64)
    longest = np.zeros(int(comp.max()) + 1)
    if line_nodes:
        ends = np.asarray(line_nodes, dtype=np.int64).reshape(-1, 2)
        np.maximum.at(longest, comp[ends[:, 0]], np.asarray(length, dtype=float))
    fragment = longest[comp] <= FRAGMENT_MM
    whole = np.flatnonzero(~fragment)
    parts = np.flatnonzero(fragment)
    if not len(whole) or not len(parts):
        return
    d, j = cKDTree(nodes[whole]).query(nodes[parts], distance_upper_bound=FRAGMENT_JOIN_MM)
    best: dict[int, tuple[float, int]] = {}
    for n, dist, k in zip(parts.tolist(), d.tolist(), j.tolist()):
        if math.isfinite(dist) and dist < best.get(component[n], (math.inf, -1))[0]:
            best[component[n]] = (dist, component[int(whole[k])])
    if best:
        for n in parts.tolist():
            if component[n] in best:
                component[n] = best[component[n]][1]


def _overshoots(nodes: np.ndarray, loose: np.ndarray, degree: np.ndarray, snap: float,
                reach: float = 15.0) -> set[int]:
    """The loose ends (``end``, ``other``) whose line from ``other`` passes through a point where
    other lines meet (2 or more line ends) within ``reach`` mm of the end: a construction line
    drawn on past its point. The nodes near each line's last ``reach`` mm come from one STRtree
    query of all of them (a sheet has 10^5 lines), then the exact test."""
    if not len(loose) or not len(nodes):
        return set()
    pairs = np.asarray(loose, dtype=np.int64).reshape(-1, 2)
    e, o = nodes[pairs[:, 0]], nodes[pairs[:, 1]]
    d = o - e
    length = np.hypot(d[:, 0], d[:, 1])
    stop = np.minimum(reach, length - snap)
    keep = (length >= 1e-9) & (stop > snap)
    if not keep.any():
        return set()
    pairs, e, d, length, stop = pairs[keep], e[keep], d[keep], length[keep], stop[keep]
    u = d / length[:, None]
    reach_lines = shapely.linestrings(np.stack([e + snap * u, e + stop[:, None] * u], axis=1))
    near, which = STRtree(shapely.points(nodes)).query(reach_lines, predicate="dwithin",
                                                       distance=snap)
    rel = nodes[which] - e[near]
    along = (rel * u[near]).sum(axis=1)
    across = np.abs(rel[:, 0] * u[near, 1] - rel[:, 1] * u[near, 0])
    hit = (along > snap) & (along < stop[near]) & (across <= snap) & (degree[which] >= 2)
    return {int(n) for n in np.unique(pairs[near[hit], 0])}


def _head_bases(nodes: np.ndarray, heads: Sequence[tuple[Point, Point]],
                marker_nodes: dict[int, str],
                degree_of: dict[int, int], snap: float) -> set[int]:
    """Nodes at the base of an arrowhead where only the shaft and the head meet: the shaft
    ends there because the head is drawn over its last millimetres, the point is the tip."""
    if not heads or not len(nodes):
        return set()
    bases = np.asarray([h[1] for h in heads], dtype=float).reshape(-1, 2)
    near, _ = cKDTree(bases).query(nodes, distance_upper_bound=snap * (1 + 1e-12))
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
    is near, a crossing of two lines when no line end is.

    Only the points near each text are looked at (a KD-tree query), and the assignment is solved
    per group of labels that compete for points: a sheet of 10^5 lines and 10^4 texts costs what
    its crowded corners cost, not labels × points."""
    nodes, n, big = graph.nodes, len(graph.nodes), 1e6
    k = len(texts)
    node = [-1] * k
    nearest_mm = [math.inf] * k
    if n and k:
        tree, _ = graph.tree()
        # points of a plan are where lines meet; a loose end of one line (a construction line
        # drawn past its point, hatching) is taken only when nothing better is near; a point
        # marked with a dot or a small circle is preferred
        marker = np.zeros(n, dtype=bool)
        marker[list(graph.markers)] = True
        loose = np.array([LOOSE_END_COST.get(deg, 0.0) for deg in graph.degree]) * tol
        rows: list[np.ndarray] = []
        cols: list[np.ndarray] = []
        scores: list[np.ndarray] = []
        first = np.full(k, np.inf)
        best0 = np.full(k, -1)
        within: list[tuple[np.ndarray, np.ndarray]] = []
        for r, t in enumerate(texts):
            radius = math.hypot(*t.half)
            near = np.asarray(tree.query_ball_point(t.centre, tol + radius), dtype=np.int64)
            d = t.distance(nodes[near]) if len(near) else np.zeros(0)
            if len(near):
                nearest_mm[r] = float(d.min())
            if not np.isfinite(nearest_mm[r]):
                nearest_mm[r] = _nearest_box_distance(t, tree, nodes)
            ok = d <= tol
            within.append((near[ok], d[ok]))
        candidates = np.unique(np.concatenate([w[0] for w in within]))
        deco = np.zeros(n)
        deco[candidates[graph.decorated(candidates)]] = tol
        for r, (near, d) in enumerate(within):
            if not len(near):
                continue
            score = np.where(marker[near], d - MARKER_BONUS * tol, d + deco[near] + loose[near])
            order = np.lexsort((near, score))[:8]          # 8 points a label; ties: first point
            rows.append(np.full(len(order), r))
            cols.append(near[order])
            scores.append(score[order])
            first[r], best0[r] = score[order[0]], near[order[0]]
        if rows:
            _assign(np.concatenate(rows), np.concatenate(cols), np.concatenate(scores), first,
                    best0, tol, big, node)
    segments = np.asarray([(ln.start, ln.end) for ln in lines]).reshape(-1, 2, 2)
    boxes = STRtree(shapely.linestrings(segments)) if len(segments) else None
    spots: list[Spot] = []
    for t, i, far in zip(texts, node, nearest_mm):
        if i >= 0:
            at = (float(nodes[i][0]), float(nodes[i][1]))
            spots.append(Spot(i, at, t.distance(at)))
            continue
        radius = tol + max(t.half)
        near = (boxes.query(shapely.box(t.centre[0] - radius, t.centre[1] - radius,
                                        t.centre[0] + radius, t.centre[1] + radius))
                if boxes is not None else np.zeros(0, dtype=np.int64))
        meets = crossings(segments[np.sort(near)], t.centre, radius)
        to_meets = t.distance(meets)
        if (to_meets <= tol).any():
            m = int(np.argmin(to_meets))
            spots.append(Spot(-1, (float(meets[m][0]), float(meets[m][1])), float(to_meets[m])))
        else:
            spots.append(Spot(-1, None, far))
    return spots


def _nearest_box_distance(t: SheetText, tree: cKDTree, nodes: np.ndarray) -> float:
    """The distance from a text's box to the nearest node: the node nearest to its centre, and
    every node that could be nearer to the box than that one."""
    d0, _ = tree.query(t.centre)
    near = tree.query_ball_point(t.centre, d0 + math.hypot(*t.half) + 1e-9)
    return float(t.distance(nodes[near]).min()) if near else math.inf


def _assign(rows: np.ndarray, cols: np.ndarray, score: np.ndarray, first: np.ndarray,
            best0: np.ndarray, tol: float, big: float, node: list[int]) -> None:
    """The minimum-cost assignment of labels (``rows``) to candidate points (``cols``, cost
    ``score``), solved for each group of labels that share candidates; a label may also share
    its best point with another at the cost ``first + tol/2`` (p ≡ o1). Fills ``node``."""
    labels, row_of = np.unique(rows, return_inverse=True)
    points, col_of = np.unique(cols, return_inverse=True)
    nr = len(labels)
    # labels and points are one graph: a group is a connected component of it
    group = components(nr + len(points), row_of, nr + col_of)[:nr]
    for g in np.unique(group):
        members = np.flatnonzero(group == g)
        pick = np.isin(row_of, members)
        local_r = np.searchsorted(members, row_of[pick])
        local_points, local_c = np.unique(col_of[pick], return_inverse=True)
        kk, nc = len(members), len(local_points)
        cost = np.full((kk, nc + kk), big)
        cost[local_r, local_c] = score[pick]
        # sharing a point with another label (p ≡ o1) costs more than a point of its own
        own = first[labels[members]]
        cost[np.arange(kk), nc + np.arange(kk)] = np.where(np.isfinite(own), own + 0.5 * tol,
                                                           big)
        cost += tol                         # keep costs positive (marker bonus)
        for r, j in zip(*linear_sum_assignment(cost)):
            if cost[r, j] < big:
                label = int(labels[members[r]])
                node[label] = int(points[local_points[j]] if j < nc else best0[label])
