"""Structure and scene errors of the linear drivers: what is refused names the key, link and why."""

from __future__ import annotations

from pathlib import Path

import pytest

from mechplan.errors import SceneError, TopologyError
from mechplan.model.mechanism import DriverKind
from mechplan.scene import parse_scene

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"
BOOM = (TEMPLATES / "excavator_boom.toml").read_text(encoding="utf-8")
COULISSE = (TEMPLATES / "slider_coulisse.toml").read_text(encoding="utf-8")


def test_cylinder_structure_formula_and_driver():
    scene = parse_scene(BOOM, "boom.toml")
    from mechplan.model.structure import analyse

    st = analyse(scene.mechanism)
    assert st.dof == 3 * 3 - 2 * 4 == 1
    assert st.cylinder == ("3", "4") and st.formula == "I(3,4) → II(2,3)"
    assert [g.kind.value for g in st.groups] == ["RRR"]
    drive = scene.mechanism.drive
    assert (drive.kind, drive.carrier, drive.guide, drive.pivot) == (
        DriverKind.CYLINDER, "3", "bore", "B")


def test_slider_structure_formula():
    from mechplan.model.structure import analyse

    st = analyse(parse_scene(COULISSE, "c.toml").mechanism)
    assert st.formula == "I(0,1) → II(2,3)" and st.cylinder is None
    assert [g.kind.value for g in st.groups] == ["RPR"]


def test_w_not_equal_to_the_number_of_drivers_names_w_and_the_driver():
    # a second rod pinned at D with nothing else: one more link, one pair → W = 2
    text = BOOM.replace('[drive]', '[links.5]\nname = "extra"\npoints = { D = ["0 mm", "0 mm"], '
                        'F = ["100 mm", "0 mm"] }\n\n[drive]')
    with pytest.raises(TopologyError, match=r"W = 3·4 − 2·5 = 2 .*1 driver .*link 4") as exc:
        parse_scene(text, "w2.toml")
    assert exc.value.key == "links"


def test_a_slider_driver_must_be_on_a_frame_guide():
    text = BOOM.replace('kind = "cylinder"', 'kind = "slider"')
    with pytest.raises(SceneError, match=r"frame guide .*guide bore belongs to link 3") as exc:
        parse_scene(text, "s.toml")
    assert exc.value.key == "drive.link"


def test_a_cylinder_rod_must_slide_in_a_barrel():
    text = COULISSE.replace('kind = "slider"', 'kind = "cylinder"')
    with pytest.raises(SceneError, match=r"frame guide g.*kind = \"slider\"") as exc:
        parse_scene(text, "c.toml")
    assert exc.value.key == "drive.link"


def test_the_barrels_guide_must_start_at_its_pivot():
    text = BOOM.replace('guides.bore = { through = "A", toward = "C" }',
                        'guides.bore = { through = "C", toward = "A" }')
    with pytest.raises(SceneError,
                       match=r"must pass through the barrel's pivot .*passes through C"):
        parse_scene(text, "g.toml")


def test_a_rod_that_is_not_a_slider_is_refused():
    text = BOOM.replace('link = "4"', 'link = "2"')
    with pytest.raises(SceneError, match=r"rod 2 must slide on one guide") as exc:
        parse_scene(text, "r.toml")
    assert exc.value.key == "drive.link"


def test_positions_need_a_range_or_a_list():
    text = BOOM.replace('range = ["1450 mm", "1900 mm"]\n', '')
    with pytest.raises(SceneError, match=r"needs its positions") as exc:
        parse_scene(text, "p.toml")
    assert exc.value.key == "drive.range"
    listed = text.replace("[positions]\ncount = 5", '[positions]\nat = ["1500 mm", "1600 mm"]')
    scene = parse_scene(listed, "p.toml")
    assert scene.positions.angles == pytest.approx((1.5, 1.6))
    assert scene.mechanism.drive.q_range == pytest.approx((1.5, 1.6))


def test_crank_scenes_read_as_before():
    text = (TEMPLATES / "four_bar.toml").read_text(encoding="utf-8")
    scene = parse_scene(text, "f.toml")
    assert scene.mechanism.drive.kind is DriverKind.CRANK and not scene.mechanism.drive.linear
    explicit = parse_scene(text.replace("[drive]", '[drive]\nkind = "crank"'), "f.toml")
    assert explicit.mechanism == scene.mechanism
