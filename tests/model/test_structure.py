"""Degrees of freedom, Assur groups of all five kinds, structure formulas."""

import pytest

from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene
from scenes import ROOT

EXPECTED = {
    "slider_crank": ("I(0,1) → II(2,3)", ["RRP"]),
    "offset_slider_crank": ("I(0,1) → II(2,3)", ["RRP"]),
    "machine_unit": ("I(0,1) → II(2,3)", ["RRP"]),
    "four_bar": ("I(0,1) → II(2,3)", ["RRR"]),
    "v_engine": ("I(0,1) → II(2,3) → II(4,5)", ["RRP", "RRP"]),
    "quick_return": ("I(0,1) → II(2,3)", ["RPR"]),
    "shaper": ("I(0,1) → II(2,3) → II(4,5)", ["RPR", "RRP"]),
}

SCOTCH_YOKE = """
[ground]
O = ["0 mm", "0 mm"]
guides.h = { through = "O", angle = "0 deg" }
[links.1]
lengths = { OA = "50 mm" }
[links.2]
slides = { point = "A", on = "slot" }
[links.3]
slides = { point = "Y", on = "h" }
points = { K = ["0 mm", "30 mm"] }
guides.slot = { through = "Y", angle = "90 deg" }
[drive]
link = "1"
speed = "20 rad/s"
"""

SLOTTED_CRANK_PRP = """
[ground]
O = ["0 mm", "0 mm"]
H = ["0 mm", "50 mm"]
guides.h = { through = "H", angle = "0 deg" }
[links.1]
lengths = { OA = "100 mm" }
guides.slot = { through = "O", toward = "A" }
[links.2]
slides = { point = "K", on = "slot" }
[links.3]
slides = { point = "K", on = "h" }
[drive]
link = "1"
speed = "5 rad/s"
"""


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_templates_structure(name):
    scene = load_scene(ROOT / "templates" / f"{name}.toml")
    st = analyse(scene.mechanism)
    formula, kinds = EXPECTED[name]
    assert st.dof == 1
    assert st.formula == formula
    assert [g.kind for g in st.groups] == kinds
    assert st.mechanism_class == 2


def test_v_engine_counts():
    st = analyse(load_scene(ROOT / "templates" / "v_engine.toml").mechanism)
    assert (st.moving_links, st.lower_pairs) == (5, 7)


def test_rpp_and_prp_groups_are_recognised():
    assert [g.kind for g in analyse(parse_scene(SCOTCH_YOKE).mechanism).groups] == ["RPP"]
    assert [g.kind for g in analyse(parse_scene(SLOTTED_CRANK_PRP).mechanism).groups] == ["PRP"]
