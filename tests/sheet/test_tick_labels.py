"""Every tick label of a diagram on a template's sheets equals its tick: the label read as a
number is the tick's position (panel mm) times the axis' scale factor. Steps of 2.5·10ᵏ were
labelled "2, 5, 8" (motorcycle_engine T/Z), "0.048, 0.045" (planetary_two_row) and "0.03, 0.05,
0.08" (the J axis of machine_unit)."""

from __future__ import annotations

import math

import pytest
from scenes import ROOT

from mechplan.sheet import cam, dynamics, engine, gears_drawing, kinematics_sheet
from mechplan.sheet import diagram as diagram_module
from mechplan.sheet.primitives import HAlign, Line, Text, VAlign
from mechplan.studies import solve_file

MARK = {"en": ".", "zh": ".", "ru": ",", "vi": ","}
SMALL_H = 1.8          # ISO 3098 height of tick labels


def _recorded(monkeypatch) -> list:
    """Record every diagram the sheet modules draw (the panel and its axes' scale factors)."""
    seen: list = []
    real = diagram_module.diagram_panel

    def recording(*args, **kwargs):
        d = real(*args, **kwargs)
        seen.append(d)
        return d

    for module in (cam, dynamics, engine, gears_drawing, kinematics_sheet):
        monkeypatch.setattr(module, "diagram_panel", recording)
    return seen


def _ticks(d, language: str) -> list[tuple[str, float, float, float]]:
    """(axis, label value, tick position in mm, scale factor) of every tick label of a diagram:
    a text of tick-label height just outside a drawn tick mark (1.5 mm across its axis)."""
    marks = [p for p in d.panel.primitives if isinstance(p, Line)
             and math.isclose(math.dist(p.start, p.end), 1.5)]
    out = []
    for p in d.panel.primitives:
        if not isinstance(p, Text) or not math.isclose(p.height_mm, SMALL_H):
            continue
        x, y = p.position
        if p.halign is HAlign.CENTER and p.valign is VAlign.TOP and any(      # x axis
                math.isclose(m.start[0], x) and math.isclose(m.end[0], x)
                and math.isclose(m.start[1] - 1.25, y) for m in marks):
            out.append(("x", _read(p.string, language), x, d.mu_x))
        elif p.halign is HAlign.RIGHT and p.valign is VAlign.MIDDLE and any(  # y axis
                math.isclose(m.start[1], y) and math.isclose(m.end[1], y)
                and math.isclose(m.start[0] - 1.25, x) for m in marks):
            out.append(("y", _read(p.string, language), y, d.mu_y))
    return out


def _read(text: str, language: str) -> float:
    other = "," if MARK[language] == "." else "."
    assert other not in text and "e" not in text.lower(), text
    return float(text.replace(MARK[language], "."))


def _check(diagrams: list, language: str) -> int:
    n = 0
    for d in diagrams:
        for axis, value, at, mu in _ticks(d, language):
            assert value == pytest.approx(at * mu, rel=1e-9, abs=1e-12 * mu), (
                d.panel.name, axis, value, at * mu)
            n += 1
    return n


@pytest.mark.parametrize("stem, language", [("motorcycle_engine", "en"),
                                            ("motorcycle_engine", "ru"),
                                            ("planetary_two_row", "en"),
                                            ("machine_unit", "vi")])
def test_tick_labels_equal_their_ticks(monkeypatch, stem, language):
    seen = _recorded(monkeypatch)
    study = solve_file(ROOT / "templates" / f"{stem}.toml")
    study.sheets(None, None, language, stem)
    assert seen and _check(seen, language) > 20


def test_the_case_of_the_issue_is_labelled_exactly(monkeypatch):
    """motorcycle_engine's T/Z diagram at its final scale has a step of 2.5 kN: "2.5, 5.0, 7.5"
    (main: "2, 5, 8")."""
    seen = _recorded(monkeypatch)
    solve_file(ROOT / "templates" / "motorcycle_engine.toml").sheets(None, None, "en", "m")
    tz = [d for d in seen if d.panel.name == "tz"][-1]
    labels = [p.string for p in tz.panel.primitives if isinstance(p, Text)
              and math.isclose(p.height_mm, SMALL_H) and p.halign is HAlign.RIGHT]
    assert {"2.5", "5.0", "7.5"} <= set(labels)
