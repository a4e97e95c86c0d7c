"""Labelled points that nearly coincide: a force polygon whose small loads (inertia forces of a
slow machine, a link's weight beside a 40 kN digging force) are too short to draw — their points
marked, not joined by lines, or joined by stubs a millimetre long — is one drawing, graded as
its plan; and a label read only by an alias ("G5", a weight, read as g₅) does not push the exact
label "g" off its point. Hand-made sheets; step ids are opaque."""

from __future__ import annotations

import numpy as np
import pytest

from mechplan.model.plans import Plan
from mechplan.submission.drawn_plans import find_plans
from mechplan.submission.labels import LabelBook, plan_key
from mechplan.submission.read import DrawnLine, Entry, SheetText, Submission
from mechplan.submission.sketch import drawn_graph

FORCE = plan_key(Plan.FORCE, "II(2,3)")
VELOCITY = plan_key(Plan.VELOCITY)


def _text(text: str, x: float, y: float) -> SheetText:
    return SheetText(text, (x, y), 2.5, f"TEXT {text}", half=(0.6, 1.25))


def test_marked_points_and_stubs_join_the_drawing_they_are_part_of():
    a, b, l_ = (0.0, 0.0), (60.0, 0.0), (30.0, 40.0)
    c, stub_end = (60.4, 0.3), (60.9, 0.7)
    lines = [DrawnLine(a, b, "1"), DrawnLine(b, l_, "2"), DrawnLine(l_, a, "3"),
             DrawnLine(c, stub_end, "stub"),                  # a 0.6 mm vector
             # another plan 1.5 mm beside b: its lines are long, it stays a drawing of its own
             DrawnLine((61.5, -0.5), (61.5, -40.0), "4"),
             DrawnLine((61.5, -40.0), (90.0, -20.0), "5")]
    markers = [((60.6, -0.4), "lone marker"), ((200.0, 200.0), "far marker")]
    g = drawn_graph(lines, markers, 0.2)

    def comp(p):
        d = ((g.nodes - np.asarray(p)) ** 2).sum(axis=1)
        return g.component[int(np.argmin(d))]
    assert comp(c) == comp(stub_end) == comp((60.6, -0.4)) == comp(b) == comp(a)
    assert comp((61.5, -40.0)) != comp(a)                     # two real drawings stay apart
    assert comp((200.0, 200.0)) not in (comp(a), comp((61.5, -40.0)))


def _book() -> LabelBook:
    """A force polygon a, b, c, d and a velocity plan p, b, c, d (letters shared)."""
    book = LabelBook(plans={FORCE: {f"f-{x}": x for x in "abcd"},
                            VELOCITY: {f"v-{x}": x for x in "pbcd"}},
                     poles={VELOCITY: "v-p"})
    for key, steps in book.plans.items():
        for sid, label in steps.items():
            book.add(key, label, sid, 3)
    return book


def test_a_polygon_with_vectors_too_short_to_draw_is_graded_as_one_plan():
    # a → b → c → d → a: bc (0.5 mm) and cd (0.54 mm) too short to draw, c only marked
    a, b, c, d = (10.0, 10.0), (70.0, 10.0), (70.3, 10.4), (70.5, 10.9)
    lines = [DrawnLine(a, b, "LINE ab"), DrawnLine(d, a, "LINE da")]
    texts = [_text("a", 8.0, 7.0), _text("b", 70.0, 7.5), _text("c", 72.5, 10.0),
             _text("d", 70.5, 13.5)]
    mu = Entry("μF", "TEXT μF", value="100 N/mm", at=(40.0, 2.0))
    sub = Submission("sheet.dxf", "dxf", lines=lines, texts=texts, entries=[mu],
                     markers=[(pt, f"CIRCLE {i}") for i, pt in enumerate((a, b, c, d))])
    sheet = find_plans(sub, _book())
    assert [dp.key for dp in sheet.plans] == [FORCE]
    assert {sid: p.at for sid, p in sheet.plans[0].points.items()} == {
        "f-a": a, "f-b": b, "f-c": c, "f-d": pytest.approx(d)}


def test_an_alias_elsewhere_does_not_push_the_exact_label_off_its_point():
    book = LabelBook(plans={VELOCITY: {"v-p": "p", "v-e": "e", "v-g": "g", "v-s": "s"}},
                     poles={VELOCITY: "v-p"})
    for sid, label in book.plans[VELOCITY].items():
        book.add(VELOCITY, label, sid, 3)
    book.add(VELOCITY, "g5", "v-g", 2)                  # g of link 5 written "g5"
    p, e, g, s = (10.0, 10.0), (70.0, 10.0), (40.0, 50.0), (30.0, 30.0)
    lines = [DrawnLine(p, e, "1"), DrawnLine(p, g, "2"), DrawnLine(e, g, "3"),
             DrawnLine(p, s, "4")]
    # the weight G5 of the lever drawn at s, its name beside it
    texts = [_text("p", 8.0, 7.0), _text("e", 72.0, 7.0), _text("g", 40.0, 53.0),
             _text("G5", 28.0, 32.5)]
    mu = Entry("μv", "TEXT μv", value="0,01 м/с/мм", at=(40.0, 0.0))
    sheet = find_plans(Submission("sheet.dxf", "dxf", lines=lines, texts=texts, entries=[mu]),
                       book)
    (dp,) = sheet.plans
    assert dp.points["v-g"].at == g and dp.points["v-g"].written == "g"
    assert any("G5" in str(n.message) and "alias" in str(n.message) for n in sheet.notes)
