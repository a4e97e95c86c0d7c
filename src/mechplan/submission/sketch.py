"""A drawing as a graph: line ends that are one point, arrowhead corners and loose ends, the
separate drawings (components) of a sheet."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..geom.sketch import cluster, components
from .read import DrawnLine, Point

#: strokes shorter than this (mm) may be arrowhead barbs, hatching or ticks
BARB_MAX_MM = 8.0


@dataclass
class Graph:
    nodes: np.ndarray                  # (M, 2)
    line_nodes: list[tuple[int, int]]  # per line
    markers: dict[int, str]            # node → marker entity
    decoration: set[int]               # arrowhead corners: labels go elsewhere first
    component: list[int]               # node → drawing
    degree: list[int]                  # line ends at each node


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
