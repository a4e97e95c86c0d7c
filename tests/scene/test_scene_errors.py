"""Bad scenes raise SceneError naming the file, the key path and what was expected."""

import pytest
from scenes import slider_crank_text

from mechplan.errors import SceneError, TopologyError
from mechplan.scene import parse_scene

GOOD = slider_crank_text()


def error_of(text: str) -> SceneError:
    with pytest.raises(SceneError) as info:
        parse_scene(text, "bad.toml")
    return info.value


def test_good_scene_parses_with_si_values():
    scene = parse_scene(GOOD, "good.toml")
    assert scene.mechanism.links["1"].distance("O", "A") == pytest.approx(0.1, rel=1e-15)
    assert scene.mechanism.drive.omega == pytest.approx(1500 * 2 * 3.141592653589793 / 60,
                                                        rel=1e-15)


@pytest.mark.parametrize("old,new,key,words", [
    ('lengths = { OA = "100.0 mm" }', 'lengths = { OA = "100 kg" }', "links.1.lengths.OA",
     "not a length"),
    ('lengths = { OA = "100.0 mm" }', 'lengths = { OA = "0 mm" }', "links.1.lengths.OA",
     "must be positive"),
    ('lengths = { OA = "100.0 mm" }', 'lengths = { OA = "-5 mm" }', "links.1.lengths.OA",
     "must be positive"),
    ('lengths = { OA = "100.0 mm" }', 'lengths = { OA = "100" }', "links.1.lengths.OA",
     "needs a unit"),
    ('lengths = { OA = "100.0 mm" }', 'lenghts = { OA = "100 mm" }', "links.1.lenghts",
     "did you mean 'lengths'"),
    ('speed = "1500 rpm"', 'speed = "1500 mm"', "drive.speed", "not an angular velocity"),
    ('link = "1"', 'link = "7"', "drive.link", "unknown link"),
    ('B = "+"', 'Q = "+"', "assembly.Q", "unknown point"),
    ('points = { S2 = "0.3 of A B" }', 'points = { S2 = "0.3 of A X" }', "links.2.points.S2",
     "not a point of this link"),
    ('slides = { point = "B", on = "g" }', 'slides = { point = "B", on = "h" }',
     "links.3.slides.on", "unknown guide"),
    ('guides.g = { through = "G"', 'guides.g = { through = "Z"', "ground.guides.g.through",
     "unknown point"),
])
def test_error_names_file_key_and_expectation(old, new, key, words):
    assert old in GOOD
    err = error_of(GOOD.replace(old, new))
    text = str(err)
    assert text.startswith("bad.toml: ")
    assert f"key '{key}'" in text
    assert words in text


def test_point_on_no_link_is_reported():
    err = error_of(GOOD + '\n[analysis]\npoints = ["Z"]\n')
    assert "key 'analysis.points'" in str(err) and "unknown point 'Z'" in str(err)
    err = error_of(GOOD.replace('B = "+"', 'B = "left of O->Z"'))
    assert "key 'assembly.B'" in str(err) and "unknown point 'Z'" in str(err)


def test_missing_length_in_triangle():
    text = GOOD.replace('lengths = { AB = "400.0 mm" }',
                        'lengths = { AB = "400 mm", AD = "50 mm" }\npoints = {}')
    text = text.replace('points = { S2 = "0.3 of A B" }', "")
    scene_err = error_of(text.replace('AD = "50 mm"', 'AD = "50 mm", BE = "20 mm"'))
    assert "needs lengths to two other points" in str(scene_err)


def test_triangle_without_side_asks_for_side():
    text = GOOD.replace('lengths = { AB = "400.0 mm" }',
                        'lengths = { AB = "400 mm", AD = "300 mm", BD = "200 mm" }')
    err = error_of(text)
    assert "key 'links.2.side'" in str(err) and "left of A->B" in str(err)


def test_impossible_triangle():
    text = GOOD.replace('lengths = { AB = "400.0 mm" }',
                        'lengths = { AB = "400 mm", AD = "100 mm", BD = "100 mm" }\n'
                        'side = { D = "left of A->B" }')
    assert "do not form a triangle" in str(error_of(text))


def test_wrong_degrees_of_freedom():
    text = GOOD + '\n[links.4]\nlengths = { BF = "50 mm" }\n'
    err = error_of(text)
    assert isinstance(err, TopologyError)
    assert "W = 3·4 − 2·5 = 2" in str(err) and "1 drive" in str(err)


def test_not_toml():
    assert "not valid TOML" in str(error_of("title = ["))


def test_unknown_top_level_key():
    assert "did you mean 'positions'" in str(error_of(GOOD + "\n[positons]\ncount = 3\n"))


def test_class_four_group_is_named_not_supported():
    # links 2..5 close a four-link contour (2 and 4 ternary) attached at B and D: class IV
    text = """
[ground]
A = ["0 mm", "0 mm"]
D = ["300 mm", "0 mm"]
[links.1]
lengths = { AB = "50 mm" }
[links.2]
lengths = { BC = "150 mm", BG = "150 mm", CG = "100 mm" }
side = { G = "right of B->C" }
[links.3]
lengths = { CE = "120 mm" }
[links.4]
lengths = { DE = "150 mm", DH = "150 mm", EH = "100 mm" }
side = { H = "left of D->E" }
[links.5]
lengths = { GH = "120 mm" }
[drive]
link = "1"
speed = "10 rad/s"
"""
    with pytest.raises(TopologyError) as info:
        parse_scene(text, "quad.toml")
    msg = str(info.value)
    assert msg.startswith("quad.toml: ")
    assert "links 2, 3, 4, 5 form a class IV group" in msg and "not supported" in msg


def test_loads_are_validated():
    base = GOOD.replace('[links.3]\nslides', '[links.3]\nmass = "2 kg"\nslides')
    assert "must not be negative" in str(error_of(base.replace('mass = "2 kg"', 'mass = "-2 kg"')))
    assert "unknown point 'Q'" in str(error_of(
        base + '\n[[loads]]\ntype = "force"\npoint = "Q"\nvector = ["1 N", "0 N"]\n'))
    assert "bore" in str(error_of(
        base + '\n[[loads]]\ntype = "pressure"\npoint = "B"\npressure = "1 MPa"\ntowards = "O"\n'))


def test_load_towards_its_own_point_and_table_longer_than_a_turn():
    base = GOOD.replace('[links.3]\nslides', '[links.3]\nmass = "2 kg"\nslides')
    err = error_of(base
                   + '\n[[loads]]\ntype = "force"\npoint = "B"\nmagnitude = "5 N"\ntowards = "B"\n')
    assert "key 'loads[0].towards'" in str(err) and "towards B itself" in str(err)
    table = '[["0 deg", "0 N"], ["800 deg", "10 N"]]'
    err = error_of(base
                   + f'\n[[loads]]\ntype = "table"\npoint = "B"\ntowards = "O"\ntable = {table}\n')
    assert "key 'loads[0].table'" in str(err) and "two crank turns" in str(err)


def test_title_block_fields_are_checked():
    err = error_of(GOOD + '\n[title_block]\nautor = "Nguyễn Văn A"\n')
    assert "key 'title_block.autor'" in str(err) and "did you mean 'author'" in str(err)
