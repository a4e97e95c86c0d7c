"""Every tick label of a diagram on a template's sheets equals its tick: the label read as a
number is the tick's position (panel mm) times the axis' scale factor. Steps of 2.5·10ᵏ were
labelled "2, 5, 8" (motorcycle_engine T/Z), "0.048, 0.045" (planetary_two_row) and "0.03, 0.05,
0.08" (the J axis of machine_unit)."""

from __future__ import annotations

import math

import numpy as np
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


def _y_labels(d) -> list[str]:
    return [p.string for p in d.panel.primitives if isinstance(p, Text)
            and math.isclose(p.height_mm, SMALL_H) and p.halign is HAlign.RIGHT]


def _mantissa(step: float) -> float:
    return step / 10.0 ** math.floor(math.log10(step) + 1e-9)


@pytest.mark.parametrize("language, expected", [("en", {"2.5", "5.0", "7.5", "-2.5"}),
                                                ("ru", {"2,5", "5,0", "7,5", "-2,5"})])
def test_the_case_of_the_issue_is_labelled_exactly(language, expected):
    """The case of the issue: motorcycle_engine's T/Z diagram once had a step of 2.5 kN (μ = 0.2
    kN/mm) and was labelled "2, 5, 8"; its labels are "2.5, 5.0, 7.5". The axis is built here
    with that scale factor: the layout now grows the sheet's diagram into free room, so its own
    step depends on the room left (2 kN at μ = 0.1)."""
    phi = np.linspace(0.0, 720.0, 73)
    t = 5.5 * np.sin(np.radians(phi)) + 2.5
    d = diagram_module.diagram_panel("tz", "T/Z", [diagram_module.Curve(phi, t)],
                                     diagram_module.Axis("φ", "°", 120.0),
                                     diagram_module.Axis("T", "kN", 60.0, mu=0.2), language)
    assert diagram_module._tick_step(d.mu_y) == 2.5
    labels = set(_y_labels(d))
    assert expected <= labels, labels
    assert not {"2", "5", "8", "-2", "-3"} & labels, labels
    assert _check([d], language) >= 4


def test_the_templates_steps_of_2_5_are_labelled_exactly(monkeypatch):
    """The drawn diagrams whose step is 2.5·10ᵏ (motorcycle_engine's forces, planetary_two_row's
    velocities at 0.0025, machine_unit's J at 0.025 …) write every label with the decimals of
    the step: 2.5 → "2.5, 5.0", 0.025 → "0.025, 0.050", 25 → "25, 50"."""
    seen = _recorded(monkeypatch)
    for stem in ("motorcycle_engine", "planetary_two_row", "machine_unit"):
        solve_file(ROOT / "templates" / f"{stem}.toml").sheets(None, None, "en", stem)
    checked = 0
    for d in seen:
        step = diagram_module._tick_step(d.mu_y)
        if not math.isclose(_mantissa(step), 2.5):
            continue
        decimals = max(0, -math.floor(math.log10(step) + 1e-9) + 1)
        for label in _y_labels(d):
            assert len(label.partition(".")[2]) == decimals, (d.panel.name, step, label)
            assert float(label) / step == pytest.approx(round(float(label) / step)), label
            checked += 1
    assert checked > 20
