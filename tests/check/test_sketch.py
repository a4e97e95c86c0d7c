"""geom.sketch (clusters, components, crossings, box distances, nearest points, gaps),
submission.sketch (labels given their points) and legacy Vietnamese text, by hand-made cases."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.geom.sketch import box_distance, box_gap, cluster, components, crossings, nearest
from mechplan.submission.read import DrawnLine, SheetText
from mechplan.submission.sketch import drawn_graph, place_labels
from mechplan.submission.written import label_names


def test_cluster_is_transitive_and_numbered_by_first_point() -> None:
    pts = np.array([[5.0, 5.0], [0.0, 0.0], [0.15, 0.0], [0.3, 0.0], [5.1, 5.0], [9.0, 9.0]])
    assert cluster(pts, 0.2).tolist() == [0, 1, 1, 1, 0, 2]       # 0–0.15–0.3 chain
    assert cluster(np.zeros((0, 2)), 0.2).tolist() == []


def test_components_of_edges() -> None:
    assert components(5, np.array([0, 3]), np.array([1, 4])).tolist() == [0, 0, 1, 2, 2]


def test_crossings() -> None:
    segs = np.array([[[0, 0], [10, 10]], [[0, 10], [10, 0]],       # cross at (5, 5)
                     [[0, 1], [10, 1.5]],                           # 2.9° to ... and far
                     [[20, 0], [30, 0]]])                           # elsewhere
    got = crossings(segs, (5.0, 5.0), 1.0)
    assert got.shape == (1, 2) and got[0] == pytest.approx([5.0, 5.0])
    # nearly parallel lines (< 5°) do not define a point
    assert len(crossings(np.array([[[0, 0], [10, 0]], [[0, -0.2], [10, 0.2]]]), (5, 0), 1)) == 0


def test_box_distance() -> None:
    # a 4 × 2 box about (10, 0): inside, beside, off a corner (3-4-5), and the same box turned 90°
    pts = np.array([[11.0, 0.5], [10.0, 3.0], [15.0, 5.0]])
    assert box_distance(pts, (10.0, 0.0), (2.0, 1.0)).tolist() == pytest.approx([0.0, 2.0, 5.0])
    assert box_distance(np.array([[10.0, 3.0]]), (10.0, 0.0), (2.0, 1.0), 90.0)[0] == \
        pytest.approx(1.0)


def test_nearest() -> None:
    pts = np.array([[0.0, 0.0], [3.0, 4.0], [1.0, 0.0], [1.0, 0.0]])
    assert nearest(pts, (1.2, 0.0)) == 2                        # the first of equals
    assert nearest(pts, (3.0, 3.0), within=0.5) == -1           # 1 mm away: too far
    assert nearest(pts, (1.2, 0.0), mask=np.array([True, True, False, False])) == 0
    assert nearest(np.zeros((0, 2)), (0.0, 0.0)) == -1


def test_box_gap() -> None:
    assert box_gap([(0.0, 0.0), (2.0, 1.0)], [(5.0, 0.0), (6.0, 1.0)]) == pytest.approx(3.0)
    assert box_gap([(0.0, 0.0), (2.0, 2.0)], [(1.0, 1.0)]) == 0.0          # overlapping boxes
    assert box_gap([], [(1.0, 1.0)]) == math.inf


def test_label_names() -> None:
    assert label_names(" p≡c ") == ["p", "c"] and label_names("p, o1") == ["p", "o1"]
    assert label_names("μv = 0,1") == [] and label_names("42") == []


def _label(text: str, x: float, y: float) -> SheetText:
    return SheetText(text, (x, y), 1.5, text, half=(0.5, 0.75))


def test_labels_take_points_of_their_own() -> None:
    # two vectors from the pole (0, 0) to b (20, 0) and c (20, 3); two lines crossing at (50, 50)
    lines = [DrawnLine((0.0, 0.0), (20.0, 0.0), "1"), DrawnLine((0.0, 0.0), (20.0, 3.0), "2"),
             DrawnLine((40.0, 40.0), (60.0, 60.0), "3"), DrawnLine((40.0, 60.0), (60.0, 40.0), "4")]
    graph = drawn_graph(lines, [], 0.2)
    texts = [_label("b", 21.5, -1.5), _label("c", 21.5, 1.0), _label("k", 51.5, 50.0),
             _label("z", 70.0, 60.0)]
    b, c, k, z = place_labels(texts, graph, lines, 3.0)
    # "c" is nearer b's end than its own, but each label takes a point of its own
    assert b.at == (20.0, 0.0) and c.at == (20.0, 3.0) and b.node >= 0 and c.node >= 0
    assert k.node == -1 and k.at == pytest.approx((50.0, 50.0))      # a crossing of two lines
    assert z.at is None and z.distance == pytest.approx(9.5)         # no point within 3 mm
    assert graph.nearest_component((1.0, 1.0)) == graph.component[b.node] == 0
    assert graph.nearest_component((1.0, 1.0), among=[1]) == 1       # only drawing 1
    pole = graph.ends_from([(20.0, 0.0), (20.0, 3.0)])      # where the vectors to b and c start
    assert list(pole.items()) == [(0, 2)] and graph.nodes[0].tolist() == [0.0, 0.0]


@pytest.mark.parametrize("text, font, expected", [
    ("H\xe4a \xae\xe5 v\xcbn t\xe8c", "", ("Họa đồ vận tốc", "tcvn3")),
    ("gia t\xe8c", ".VnTime.ttf", ("gia tốc", "tcvn3")),          # the font decides
    ("accélération", "", ("accélération", None)),                  # French stays French
    ("μv = 0,01 m/s/mm; N·m; 5 µm", "", ("μv = 0,01 m/s/mm; N·m; 5 µm", None)),
    ("Họa đồ vận tốc", "", ("Họa đồ vận tốc", None)),              # already Unicode
    ("Hoïa ñoà vaän toác", "VNI-Times", ("Hoïa ñoà vaän toác", "vni")),
])
def test_legacy_vietnamese(text: str, font: str, expected: tuple[str, str | None]) -> None:
    from mechplan.submission.notation import decode_legacy

    assert decode_legacy(text, font) == expected
