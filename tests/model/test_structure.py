"""Degrees of freedom, Assur groups of all five kinds, structure formulas."""

import pytest
from scenes import ROOT, SCOTCH_YOKE, SLOTTED_CRANK_PRP

from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene

EXPECTED = {
    "slider_crank": ("I(0,1) → II(2,3)", ["RRP"]),
    "offset_slider_crank": ("I(0,1) → II(2,3)", ["RRP"]),
    "machine_unit": ("I(0,1) → II(2,3)", ["RRP"]),
    "four_bar": ("I(0,1) → II(2,3)", ["RRR"]),
    "v_engine": ("I(0,1) → II(2,3) → II(4,5)", ["RRP", "RRP"]),
    "quick_return": ("I(0,1) → II(2,3)", ["RPR"]),
    "shaper": ("I(0,1) → II(2,3) → II(4,5)", ["RPR", "RRP"]),
}

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
