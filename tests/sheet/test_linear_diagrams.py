"""Kinematic diagrams of machines driven by a cylinder or a slider: over the driver's length, on
the sheet and in the JSON (``kinematic_diagram``), with the law's time of each position.

Golden values: the excavator arm's boom angle and ω from the loop closure (bracketing root-finder,
five-point finite differences in time: tests/construct/test_cylinder_second_driver.py); the
graphical differentiation's chords of s over the positions' times against the exact rates.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.drafting.primitives import Text
from mechplan.model.output import output_link
from mechplan.scene.loader import load_scene, parse_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve, to_json

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
from test_cylinder_second_driver import TEMPLATE, boom_angle, fd, state
from test_driver_law_table import scene_text

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"


def test_the_output_link_is_not_a_cylinder_barrel():
    for stem, link in (("excavator_boom", "2"), ("excavator_arm", "2"), ("slider_coulisse", "3")):
        out = output_link(load_scene(TEMPLATES / f"{stem}.toml").mechanism)
        assert out is not None and out.link == link and out.point is None, stem


def test_json_diagram_of_the_arm_equals_the_loop_closure():
    sol = solve(load_scene(TEMPLATE))
    d = to_json(sol)["kinematic_diagram"]
    assert d["output"] == {"link": "2", "point": None, "kind": "rocker"}
    assert d["coordinate"] == "l"
    for k, q in enumerate(d["x"]):
        assert d["t"][k] == pytest.approx((q - 2.2) / 0.1, abs=1e-12)   # constant l̇4 = 0.1 m/s
        l7 = 2.7 + 0.75 * (q - 2.2)

        def motion(tau, q=q, l7=l7):
            return state(boom_angle(q + 0.1 * tau), l7 + 0.075 * tau)
        x, v, a = fd(motion)
        assert math.remainder(d["s"][k] - x[0], 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
        assert d["v"][k] == pytest.approx(v[0], rel=1e-8)
        assert d["a"][k] == pytest.approx(a[0], rel=1e-5, abs=1e-9)


def test_chords_over_the_laws_time_converge_to_the_exact_rates():
    """A law by a table: the positions' times come from its spline inverted; the chords of s
    over them approach the exact v and a with h² (41 positions)."""
    text = scene_text().replace("[positions]\ncount = 5", "[positions]\ncount = 41")
    d = to_json(solve(parse_scene(text, "arm.toml")))["kinematic_diagram"]
    t, s, v, a = (np.asarray(d[k]) for k in "tsva")
    chord_v = np.diff(s) / np.diff(t)
    mid_v = 0.5 * (v[1:] + v[:-1])
    assert np.max(np.abs(chord_v - mid_v)) < 1e-3 * np.max(np.abs(v))
    tm = 0.5 * (t[1:] + t[:-1])
    chord_a = np.diff(chord_v) / np.diff(tm)
    assert np.max(np.abs(chord_a - a[1:-1])) < 2e-2 * np.max(np.abs(a))


@pytest.mark.parametrize("stem", ["excavator_boom", "slider_coulisse", "excavator_arm"])
@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_the_sheets_draw_the_diagrams_over_the_laws_time(stem, lang):
    sol = solve(load_scene(TEMPLATES / f"{stem}.toml"))
    comp = compose(sol, "A3", "iso", lang, name=stem)
    panels = [p for pl in comp.placements for p, _ in pl if p.name.startswith("diagram-kinematic")]
    assert panels, stem
    texts = [t.string for p in panels for t in p.primitives if isinstance(t, Text)]
    titles = [s for s in texts if "(t)" in s and not s.startswith("μ")]
    assert len(titles) == 3, texts                      # ψ(t), ω(t), ε(t) of the output link
    assert any(s.startswith("t,") for s in texts)       # the time axis: "t, s"
