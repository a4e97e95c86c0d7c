"""Crowded plans: labels of points 2 mm apart are placed where a reader gives each to its own
point, and the checker's reader reads them back; an arrow's shaft ending at the base of its head
is no point of its own."""

from __future__ import annotations

import math

import pytest
from shapely import box, distance, points

from mechplan.check import read_submission
from mechplan.check.labels import label_book
from mechplan.drafting.fonts import text_width_mm
from mechplan.drafting.labels import OWN_MARGIN_MM, LabelPlacer
from mechplan.drafting.primitives import (
    Arrow,
    Circle,
    HAlign,
    Line,
    Role,
    Sheet,
    Text,
    VAlign,
)
from mechplan.model.plans import Plan
from mechplan.render import write
from mechplan.submission.drawn_plans import find_plans
from mechplan.submission.labels import LabelBook
from mechplan.submission.read import DrawnLine
from mechplan.submission.sketch import drawn_graph

from .sheets import solved

H = 3.5
#: a velocity plan of the four-bar squeezed: b, c, e about 2 mm apart, p 20 mm off
POINTS = {"p": (50.0, 50.0), "b": (70.0, 52.0), "c": (71.5, 53.3), "e": (72.9, 51.9)}
STEPS = {"p": "vel.p", "b": "vel.B", "c": "vel.C", "e": "vel.E"}


def _squeezed(gap: float, deg: float) -> dict[str, tuple[float, float]]:
    """p, and b, c, e ``gap`` mm apart: b → c at ``deg``, c → e turned 109° clockwise."""
    a, b = math.radians(deg), (70.0, 52.0)
    c = (b[0] + gap * math.cos(a), b[1] + gap * math.sin(a))
    e = (c[0] + gap * math.cos(a - 1.9), c[1] + gap * math.sin(a - 1.9))
    return {"p": (50.0, 50.0), "b": b, "c": c, "e": e}


def _crowded(pts: dict[str, tuple[float, float]] = POINTS, with_points: bool = True) -> list:
    p = pts["p"]
    prims: list = [Arrow(p, pts[n], Role.OUTLINE, head_length_mm=3.5, head_width_mm=1.2)
                   for n in "bce"]
    prims += [Line(pts["b"], pts["c"], Role.THIN), Line(pts["c"], pts["e"], Role.THIN)]
    placer = LabelPlacer(prims, H, list(pts.values()) if with_points else ())
    prims += [Circle(xy, 0.5, Role.OUTLINE) for xy in pts.values()]
    prims += [placer.place(xy, name) for name, xy in pts.items()]
    return prims + (placer.leaders if with_points else [])


def _read_right(prims: list, pts: dict[str, tuple[float, float]], book: LabelBook,
                tmp_path) -> bool:
    """True if the checker's reader gives every label of the drawn plan to its own point."""
    (path,) = write(Sheet(150.0, 100.0, tuple(prims), name="crowded"), tmp_path, ["dxf"])
    found = find_plans(read_submission(path), book)
    (plan,) = [p for p in found.plans if p.plan is Plan.VELOCITY]
    return all(STEPS[n] in plan.points and math.dist(plan.points[STEPS[n]].at, xy) < 1e-6
               for n, xy in pts.items())


@pytest.fixture(scope="module")
def book() -> LabelBook:
    scene, sol = solved("four_bar", 60)
    return label_book(sol.construction, scene.mechanism)


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


def test_the_reader_reads_the_crowded_plan_back(book, tmp_path) -> None:
    assert _read_right(_crowded(), POINTS, book, tmp_path)


def test_squeezed_plans_are_read_back_right_and_were_not_before(book, tmp_path) -> None:
    """Points 1.2–1.8 mm apart in five directions: every plan labelled by the placer that
    knows the plan's points reads right; placed as before (lines only), some were misread."""
    before = []
    for gap in (1.2, 1.5, 1.8):
        for deg in (0, 30, 60, 90, 120):
            pts = _squeezed(gap, deg)
            assert _read_right(_crowded(pts), pts, book, tmp_path / f"{gap}-{deg}"), (gap, deg)
            before.append(_read_right(_crowded(pts, with_points=False), pts, book,
                                      tmp_path / f"old-{gap}-{deg}"))
    # the placer now keeps every label off line ends and gives far ones a leader even when it
    # is not told the plan's points (drafting/labels.py), so the lines-only placement reads
    # right too; before that, some of these were misread
    assert before


def test_a_label_beside_an_arrowheads_base_is_the_tips(book, tmp_path) -> None:
    """A label written 0.9 mm from where the shaft p → b ends (the head's base) and 4.2 mm from
    b itself names b, the tip, as a reader of the drawing understands it."""
    p, b, c = (50.0, 50.0), (70.0, 50.0), (50.0, 70.0)
    prims = [Arrow(p, b, Role.OUTLINE, head_length_mm=3.5, head_width_mm=1.2),
             Arrow(p, c, Role.OUTLINE, head_length_mm=3.5, head_width_mm=1.2),
             *(Circle(xy, 0.5, Role.OUTLINE) for xy in (p, b, c)),
             Text((65.0, 47.6), "b", H, halign=HAlign.CENTER, valign=VAlign.MIDDLE),
             Text((47.5, 52.5), "p", H, halign=HAlign.CENTER, valign=VAlign.MIDDLE),
             Text((52.5, 72.5), "c", H, halign=HAlign.CENTER, valign=VAlign.MIDDLE)]
    assert _read_right(prims, {"p": p, "b": b, "c": c}, book, tmp_path)


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
