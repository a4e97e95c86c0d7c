"""Diagram panels: round scale factors, curves at their physical coordinates, sheets that flow."""

from __future__ import annotations

import numpy as np
import pytest

from mechplan.errors import DrawingError
from mechplan.sheet.diagram import Axis, Curve, diagram_panel, mu_text
from mechplan.sheet.layout import framed_sheets
from mechplan.sheet.primitives import Polyline, Text


def test_curve_is_drawn_at_its_scale():
    x = np.linspace(0.0, 360.0, 37)
    y = 100.0 * np.sin(np.radians(x))
    d = diagram_panel("m", "M", [Curve(x, y)], Axis("φ", "°", 180.0), Axis("M", "N·m", 60.0), "en")
    assert d.mu_x == 2.0                      # 360° over 180 mm is already round
    assert d.mu_y == 4.0                      # 200 N·m over 60 mm → 3.33 → next round value 4
    (curve,) = [p for p in d.panel.primitives if isinstance(p, Polyline)]
    pts = np.asarray(curve.points)
    assert np.allclose(pts[:, 0] * d.mu_x, x) and np.allclose(pts[:, 1] * d.mu_y, y)


def test_nan_breaks_the_curve_and_ru_uses_decimal_comma():
    x = np.arange(5.0)
    y = np.array([0.1, 0.2, np.nan, 0.3, 0.25])
    d = diagram_panel("a", "A", [Curve(x, y)], Axis("φ", "rad", 40.0), Axis("A", "J", 40.0), "ru")
    assert len([p for p in d.panel.primitives if isinstance(p, Polyline)]) == 2
    texts = [p.string for p in d.panel.primitives if isinstance(p, Text)]
    assert any("0,1" in t for t in texts) and not any("0.1" in t for t in texts)
    assert mu_text("μM", 2.5, "N·m", "ru") == "μM = 2,5 Н·м/мм"
    assert "A, Дж" in texts and "φ, рад" in texts          # a Russian sheet writes Russian units


def test_panels_flow_onto_numbered_sheets():
    x = np.linspace(0.0, 720.0, 73)
    d = diagram_panel("p", "P", [Curve(x, np.cos(np.radians(x)))], Axis("φ", "°", 240.0),
                      Axis("P", "kN", 80.0), "en")
    sheets = framed_sheets([d.panel] * 6, size="A3", standard="iso", language="en", name="eng",
                           fields={"title": "Engine"})
    assert len(sheets) >= 2
    assert [s.name for s in sheets][:2] == ["eng", "eng-2"]
    with pytest.raises(DrawingError):
        framed_sheets([diagram_panel("w", "W", [Curve(x * 10, x)], Axis("φ", "°", 900.0),
                                     Axis("W", "J", 50.0), "en").panel],
                      size="A4", standard="iso", language="en", name="w", fields={})


def test_scale_factor_text_keeps_its_unit_whole_and_in_one_script():
    assert mu_text("μM", 2.5, "N·m", "en") == "μM = 2.5 N·m/mm"
    assert mu_text("μv", 0.2, "m/s", "en") == "μv = 0.2 (m/s)/mm"        # not "m/s/mm"
    assert mu_text("μv", 0.2, "m/s", "ru") == "μv = 0,2 (м/с)/мм"        # Russian unit symbols
    assert mu_text("μJ", 0.002, "kg·m²", "vi") == "μJ = 0,002 kg·m²/mm"  # vi, zh: SI symbols
    assert mu_text("μa", 10.0, "m/s²", "en") == "μa = 10 (m/s²)/mm"
    assert mu_text("μs", 0.25, "мм", "ru") == "μs = 0,25 мм/мм"          # not "мм/mm"
    assert mu_text("μv", 0.02, "м/с", "ru") == "μv = 0,02 (м/с)/мм"
    assert mu_text("μk", 0.5, "", "en") == "μk = 0.5 1/mm"
