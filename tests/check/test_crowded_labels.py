"""Crowded plans: labels of points 2 mm apart are placed where a reader gives each to its own
point, and the checker's reader reads them back; an arrow's shaft ending at the base of its head
is no point of its own."""

from __future__ import annotations

import math

import pytest
from shapely import box, distance, points

from mechplan.check import read_submission
from mechplan.check.labels import LabelBook
from mechplan.check.points import find_plans
from mechplan.check.sketch import drawn_graph
from mechplan.check.submission import DrawnLine
from mechplan.construct.step import Plan
from mechplan.drafting.fonts import text_width_mm
from mechplan.drafting.labels import OWN_MARGIN_MM, LabelPlacer
from mechplan.drafting.primitives import Arrow, Circle, Line, Role, Sheet, Text
from mechplan.render import write

from .sheets import solved

H = 3.5
#: a velocity plan of the four-bar squeezed: b, c, e about 2 mm apart, p 20 mm off
POINTS = {"p": (50.0, 50.0), "b": (70.0, 52.0), "c": (71.5, 53.3), "e": (72.9, 51.9)}


def _crowded(with_points: bool = True) -> list:
    p = POINTS["p"]
    prims: list = [Arrow(p, POINTS[n], Role.OUTLINE, head_length_mm=3.5, head_width_mm=1.2)
                   for n in "bce"]
    prims += [Line(POINTS["b"], POINTS["c"], Role.THIN), Line(POINTS["c"], POINTS["e"], Role.THIN)]
    placer = LabelPlacer(prims, H, list(POINTS.values()) if with_points else ())
    prims += [Circle(xy, 0.5, Role.OUTLINE) for xy in POINTS.values()]
    prims += [placer.place(xy, name) for name, xy in POINTS.items()]
    return prims


def _box(t: Text) -> object:
    w, h, (x, y) = text_width_mm(t.string, t.height_mm), t.height_mm, t.position
    return box(x - w / 2, y - h / 2, x + w / 2, y + h / 2)


def test_each_label_is_nearer_its_own_point_than_any_other() -> None:
    texts = [q for q in _crowded() if isinstance(q, Text)]
    assert [t.string for t in texts] == list(POINTS)
    for t in texts:
        d = {n: float(distance(_box(t), points(xy))) for n, xy in POINTS.items()}
        others = min(v for n, v in d.items() if n != t.string)
        assert d[t.string] + OWN_MARGIN_MM - 0.31 <= others, (t.string, d)  # box ± 0.3 mm in y
        assert d[t.string] < 5.0, (t.string, d)                            # still beside it


def test_the_reader_reads_the_crowded_plan_back(tmp_path) -> None:
    scene, sol = solved("four_bar", 60)
    book = LabelBook.build(sol.construction, scene.mechanism)
    (path,) = write(Sheet(150.0, 100.0, tuple(_crowded()), name="crowded"), tmp_path, ["dxf"])
    found = find_plans(read_submission(path), book)
    (plan,) = [p for p in found.plans if p.plan is Plan.VELOCITY]
    steps = {"p": "vel.p", "b": "vel.B", "c": "vel.C", "e": "vel.E"}
    for name, xy in POINTS.items():
        assert plan.points[steps[name]].at == pytest.approx(xy, abs=1e-6), name


def _arrow_graph(heads: bool):
    # p → b drawn as our sheets draw it: the shaft ends at the head's base, 3.5 mm before b
    p, b = (0.0, 0.0), (20.0, 0.0)
    base = (16.5, 0.0)
    lines = [DrawnLine(p, base, "LINE", "0"), DrawnLine(b, base, "SOLID", "0")]
    markers = [(b, "SOLID"), (p, "CIRCLE")]
    return drawn_graph(lines, markers, 0.2, [(b, base)] if heads else [])


def test_an_arrows_shaft_end_at_its_heads_base_is_no_point() -> None:
    g = _arrow_graph(heads=True)
    base = next(i for i, xy in enumerate(g.nodes) if math.dist(xy, (16.5, 0.0)) < 1e-9)
    assert base in g.decoration and base not in g.markers
    # the same lines without the arrowhead known: a junction of two lines, a point as any
    assert base not in _arrow_graph(heads=False).decoration
