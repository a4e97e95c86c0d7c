"""Texts of a sheet that are no plan: axis titles, a pole alone (issue 28, item 4)."""

from __future__ import annotations

import pytest
from scenes import ROOT

from mechplan.check import Options, check
from mechplan.check.report import MISSING
from mechplan.submission.drawn_plans import axis_title


@pytest.mark.parametrize(("text", "title"), [
    ("a, m/s²", True), ("s, m", True), ("ψ, °", True), ("M_b, N·m", True), ("v, м/с", True),
    ("ε, rad/s²", True), ("p, o1", False), ("c, d", False), ("p≡c", False), ("a", False),
    ("μv = 0,1 (m/s)/mm", False)])
def test_an_axis_title_is_no_label(text, title):
    assert axis_title(text) is title


def test_the_v_engine_sheet_has_no_phantom_position_plan():
    """drawings/v_engine.dxf (A1): the acceleration diagram's axis title 'a, m/s²' was read as
    point A of a second position plan with 6 "missing" segments, drawn over the acceleration
    plan in the overlay."""
    report = check(ROOT / "templates" / "v_engine.toml", ROOT / "drawings" / "v_engine.dxf",
                   Options())
    assert [p.plan for p in report.plans].count("position") == 1
    assert not [s.name for p in report.plans for s in p.segments if s.verdict == MISSING]
    assert report.passed
