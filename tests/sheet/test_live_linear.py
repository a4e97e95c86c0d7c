"""The live page of a cylinder- or slider-driven machine: the animation runs over the driver's
range and the diagrams are drawn over the law's time t (the sheets' abscissa), with the axis
titled "t, s" in each language; a crank's page keeps φ in degrees over one turn.

Everything is read back from the JSON the page embeds. Golden values: t = (l − l⁰)/l̇ from the
template's law, and the excavator arm's boom angle ψ and ω from the loop closure solved by a
bracketing root-finder and five-point finite differences in time
(tests/construct/test_cylinder_second_driver.py), never from the construction.
"""

from __future__ import annotations

import json
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.i18n import LANGUAGES, unit
from mechplan.live_page import page_text
from mechplan.studies import solve_file

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
from test_cylinder_second_driver import boom_angle

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"
#: the driver's range (m), rate (m/s) and symbol of each linear template
LINEAR = {"excavator_arm": (2.2, 3.0, 0.1, "l4"), "excavator_boom": (1.45, 1.9, 0.25, "l4"),
          "slider_coulisse": (-0.2, 0.3, 1.0, "s1")}


def _doc(stem: str, frames: int = 41) -> dict:
    page = page_text(solve_file(str(TEMPLATES / f"{stem}.toml")), name=stem, frames=frames)
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.DOTALL)
    assert m
    return json.loads(m.group(1).replace("<\\/", "</"))["animation"]


def _xy(points: dict) -> np.ndarray:
    (p,) = points.values()
    return np.array([np.nan if v is None else v for v in p["xy"]], dtype=float).reshape(-1, 2)


def _affine(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float]:
    """y ≈ a + b·x: (a, b, largest residual)."""
    b, a = np.polyfit(x, y, 1)
    return float(a), float(b), float(np.max(np.abs(y - (a + b * x))))


def _ticks(static: list[dict]) -> list[tuple[float, float]]:
    """(x on paper, value written) of the x axis' tick labels (centred under the axis)."""
    out = []
    for p in static:
        if p.get("a") == "middle" and "t" in p:
            out.append((p["x"], float(p["t"].replace(",", ".").replace("\u2212", "-"))))
    return out


@pytest.mark.parametrize("stem", sorted(LINEAR))
def test_the_diagrams_of_a_linear_driver_are_over_its_time(stem):
    lo, hi, rate, symbol = LINEAR[stem]
    an = _doc(stem)
    q = np.asarray(an["coordinate"]["values"], dtype=float) / 1000.0      # mm on the page
    assert q[0] == pytest.approx(lo, abs=1e-6) and q[-1] == pytest.approx(hi, abs=1e-6)
    np.testing.assert_allclose(np.diff(q), (hi - lo) / (len(q) - 1), atol=1e-6)
    assert set(an["coordinate"]["symbol"].values()) == {symbol}
    assert an["coordinate"]["unit"] == {lang: unit("mm", lang) for lang in LANGUAGES}
    t = (q - lo) / rate                                     # the law's time
    diagrams = [p for p in an["panels"] if p["plan"] == "diagram"]
    assert [p["id"] for p in diagrams][:2] == ["diagram-s", "diagram-v"]
    for p in diagrams:
        x = _xy(p["points"])[:, 0]
        a, b, worst = _affine(t, x)
        assert b > 0 and worst < 0.01, (p["id"], worst)    # paper mm rounded to 0.01
        # the tick labels are seconds at the same abscissa: x = a + b·t
        ticks = _ticks(p["static"]["en"])
        assert len(ticks) >= 2
        for px, value in ticks:
            assert px == pytest.approx(a + b * value, abs=0.02), (p["id"], px, value)
        for lang in LANGUAGES:
            titles = {s["t"] for s in p["static"][lang] if "t" in s}
            assert f"t, {unit('s', lang)}" in titles, (stem, lang)
            assert not any(s.startswith("φ") for s in titles)
    # every frame of the mechanism is built over the range (a crank's turn of metres was not)
    pos = next(p for p in an["panels"] if p["id"] == "position")
    assert all(np.isfinite(_xy({k: v}).all()) for k, v in pos["points"].items())
    chosen = [m for m in an["marks"] if m["kind"] == "chosen"]
    assert chosen and all(0 <= m["k"] < an["frames"] for m in chosen)


def test_the_arm_diagrams_equal_the_loop_closure():
    """ψ(t) and ω(t) of the boom on the page against the loop closure: the ordinates are an
    affine image of the independent ψ and ω (origin and scale factor of the panel)."""
    lo, _hi, rate, _ = LINEAR["excavator_arm"]
    an = _doc("excavator_arm", frames=21)
    q = np.asarray(an["coordinate"]["values"], dtype=float) / 1000.0
    psi = np.degrees([boom_angle(x) for x in q])
    h = 1e-3
    omega = np.array([(boom_angle(x - 2 * rate * h) - 8 * boom_angle(x - rate * h)
                       + 8 * boom_angle(x + rate * h) - boom_angle(x + 2 * rate * h)) / (12 * h)
                      for x in q])
    panels = {p["id"]: p for p in an["panels"]}
    for pid, golden in (("diagram-s", psi), ("diagram-v", omega)):
        y = _xy(panels[pid]["points"])[:, 1]
        _a, b, worst = _affine(golden, y)
        assert abs(b) > 0 and worst < 0.01, (pid, worst)
    # the driver's t: l4 = 2.2 m at t = 0 s, 3.0 m at 8 s
    assert (q[-1] - lo) / rate == pytest.approx(8.0, abs=1e-6)


def test_a_crank_page_keeps_the_crank_angle():
    an = _doc("four_bar", frames=72)
    assert "coordinate" not in an
    phi = np.asarray(an["phi_deg"], dtype=float)
    steps = np.mod(np.diff(phi), 360.0)
    np.testing.assert_allclose(steps, steps[0], atol=1e-3)
    assert steps[0] == pytest.approx(5.0, abs=1e-3)                   # 360° / 72 frames
    for p in (p for p in an["panels"] if p["plan"] == "diagram"):
        x = _xy(p["points"])[:, 0]
        a, b, worst = _affine(np.arange(72) * 5.0, x)
        assert b > 0 and worst < 0.01
        for px, value in _ticks(p["static"]["en"]):
            assert px == pytest.approx(a + b * value, abs=0.02)
        for lang in LANGUAGES:
            assert "φ, °" in {s["t"] for s in p["static"][lang] if "t" in s}
    assert math.isfinite(float(phi[0]))
