"""The reader groups a sheet's labelled points into plans from a label book alone: no construction,
step ids are opaque (the checker fills the book from its construction)."""

from __future__ import annotations

import pytest

from mechplan.model.plans import Plan
from mechplan.submission.drawn_plans import find_plans
from mechplan.submission.labels import LabelBook, mu_plan, plan_key, section_plan
from mechplan.submission.read import DrawnLine, Entry, SheetText, Submission

VELOCITY = plan_key(Plan.VELOCITY)


def _book() -> LabelBook:
    """A velocity plan p, b, c with the pole also read as "pv" (ids made up)."""
    book = LabelBook(plans={VELOCITY: {"id-p": "p", "id-b": "b", "id-c": "c"}},
                     poles={VELOCITY: "id-p"})
    for sid, label in book.plans[VELOCITY].items():
        book.add(VELOCITY, label, sid, 3)
    book.add(VELOCITY, "pv", "id-p", 2)
    return book


def _text(text: str, x: float, y: float) -> SheetText:
    return SheetText(text, (x, y), 2.5, f"TEXT {text}", half=(0.6, 1.25))


def _sheet(pole: str = "p") -> Submission:
    p, b, c = (10.0, 10.0), (70.0, 10.0), (40.0, 50.0)
    lines = [DrawnLine(p, b, "LINE 1"), DrawnLine(p, c, "LINE 2"), DrawnLine(b, c, "LINE 3")]
    texts = [_text(pole, 8.0, 7.0), _text("b", 72.0, 7.0), _text("c", 40.0, 53.0)]
    mu = Entry("μv", "TEXT μv", value="0,01 м/с/мм", at=(40.0, 0.0))
    return Submission("sheet.dxf", "dxf", lines=lines, texts=texts, entries=[mu])


@pytest.mark.parametrize("pole", ["p", "pv"])
def test_points_of_a_plan_are_found_from_the_book_alone(pole):
    sheet = find_plans(_sheet(pole), _book())
    assert len(sheet.plans) == 1
    dp = sheet.plans[0]
    assert dp.key == VELOCITY
    assert {sid: p.at for sid, p in dp.points.items()} == {
        "id-p": (10.0, 10.0), "id-b": (70.0, 10.0), "id-c": (40.0, 50.0)}
    assert dp.points["id-p"].written == pole
    assert dp.mu == pytest.approx(0.01)
    assert len(dp.lines) == 3
    assert sheet.other_entries == []


def test_a_scale_factor_given_otherwise_is_not_read_from_the_sheet():
    sheet = find_plans(_sheet(), _book(), mu_elsewhere={Plan.VELOCITY})
    assert sheet.plans[0].mu is None
    assert sheet.plans[0].mu_source == ""


@pytest.mark.parametrize(("name", "plan"), [("μv", Plan.VELOCITY), ("mu_a", Plan.ACCELERATION),
                                            ("μ_F", Plan.FORCE), ("k_l", Plan.POSITION),
                                            ("v_B", None)])
def test_scale_factor_names(name, plan):
    assert mu_plan(name) is plan


@pytest.mark.parametrize(("section", "key"), [
    ("velocity", (Plan.VELOCITY, "")), ("forces II(2,3)", (Plan.FORCE, "II(2,3)")),
    ("план ускорений", (Plan.ACCELERATION, "")), ("notes", None)])
def test_a_section_names_its_plan(section, key):
    assert section_plan(section) == key
