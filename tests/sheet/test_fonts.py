"""Font choice, metrics and baseline placement."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from mechplan.sheet import Text, VAlign
from mechplan.sheet.fonts import (
    SheetFont,
    _is_placeholder,
    baseline_point,
    cap_ratio,
    covers,
    em_size_mm,
    families_for,
    font_for,
    font_path,
    has_cjk,
    text_width_mm,
)

SAMPLES = ["Họa đồ vận tốc", "ĐỒ ÁN NGUYÊN LÝ MÁY", "План скоростей", "π ω μ", "速度多边形",
           "v ∥ AB ⊥", "МГТУ им. Н.Э. Баумана"]


def test_cjk_strings_use_the_cjk_font() -> None:
    assert has_cjk("速度") and not has_cjk("Tốc độ")
    assert font_for("速度多边形 p") is SheetFont.CJK
    assert families_for("速度")[0] == "Noto Sans CJK SC"
    assert families_for("Tốc độ")[0] == "osifont"
    for s in ("Họa đồ vận tốc", "План скоростей", "π ω μ"):
        assert font_for(s) is SheetFont.ISO


def test_chosen_font_has_every_glyph() -> None:
    # the bundled files: present on every machine, no system font needed
    assert font_path(SheetFont.ISO) is not None and font_path(SheetFont.CJK) is not None
    for s in SAMPLES:
        assert covers(font_for(s), s), s
    assert 0.6 < cap_ratio(SheetFont.ISO) < 0.8
    assert 0.6 < cap_ratio(SheetFont.CJK) < 0.8


def test_placeholder_glyphs_count_as_missing() -> None:
    box = SimpleNamespace(numberOfContours=1, coordinates=[(84, 1511), (824, 1511), (829, 0),
                                                           (94, 0)])
    bar = SimpleNamespace(numberOfContours=1,
                          coordinates=[(0, 0), (100, 0), (100, 1500), (0, 1500)])
    o = SimpleNamespace(numberOfContours=2, coordinates=[(0, 0)] * 8)
    assert _is_placeholder(box, 2048)
    assert not _is_placeholder(bar, 2048)  # a narrow stroke such as "I" or "l"
    assert not _is_placeholder(o, 2048)


def test_text_width_scales_with_height() -> None:
    w = text_width_mm("Người vẽ", 2.5)
    assert w > 0
    assert text_width_mm("Người vẽ", 5.0) == pytest.approx(2 * w)
    # CJK ideographs are one em wide
    em = 5.0 / cap_ratio(SheetFont.CJK)
    assert text_width_mm("速度多边形", 5.0) == pytest.approx(5 * em, rel=0.02)


@pytest.mark.parametrize(("valign", "shift"), [(VAlign.BASELINE, 0.0), (VAlign.MIDDLE, -2.5),
                                               (VAlign.TOP, -5.0), (VAlign.BOTTOM, 1.5)])
def test_baseline_point(valign: VAlign, shift: float) -> None:
    t = Text((10.0, 20.0), "A", 5.0, valign=valign)
    assert baseline_point(t) == pytest.approx((10.0, 20.0 + shift))
    r = Text((10.0, 20.0), "A", 5.0, rotation_deg=90.0, valign=valign)
    assert baseline_point(r) == pytest.approx((10.0 - shift, 20.0))
    assert em_size_mm(t) == pytest.approx(5.0 / cap_ratio(SheetFont.ISO))
    assert math.isfinite(em_size_mm(t))
