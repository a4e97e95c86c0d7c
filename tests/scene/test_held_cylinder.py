"""``[drive2] hold``: the excavator arm with its arm cylinder held at 2700 mm while the boom
cylinder lifts — the arm turns with the boom (a constant angle between them), the boom cylinder's
driving force and the force holding the arm cylinder equal the virtual power of the template's
loads (the loop closure and finite differences: tests/dynamics/test_excavator_arm_loaded.py),
and the key's refusals name ``drive2.hold`` or the key beside it."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

from mechplan.errors import SceneError
from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
sys.path.insert(0, str(Path(__file__).parents[1] / "dynamics"))
from test_cylinder_second_driver import TEMPLATE, arm_angle, boom_angle
from test_excavator_arm_loaded import golden

LAW = 'speed = "0.075 m/s"\nstart = "2700 mm"\n'


def _text(drive2: str = 'hold = "2700 mm"\n') -> str:
    text = TEMPLATE.read_text(encoding="utf-8")
    assert LAW in text
    return text.replace(LAW, drive2)


@pytest.fixture(scope="module")
def held():
    return solve(parse_scene(_text(), str(TEMPLATE)))


def test_the_held_cylinder_keeps_its_length_and_the_arm_turns_with_the_boom(held):
    c, ev = held.construction, held.ev
    for k, l4 in enumerate(held.phi):
        th2 = boom_angle(float(l4))
        th5 = arm_angle(th2, 2.7)                       # the loop closed with l7 = 2700 mm
        assert math.remainder(float(ev[c.link_angle("2")][k]) - th2, 2 * math.pi) == \
            pytest.approx(0.0, abs=1e-12)
        assert math.remainder(float(ev[c.link_angle("5")][k]) - th5, 2 * math.pi) == \
            pytest.approx(0.0, abs=1e-12)
        assert float(ev["pos.q2"][k]) == pytest.approx(2.7, abs=1e-15)
        assert float(ev[c.omega("5")][k]) == pytest.approx(float(ev[c.omega("2")][k]),
                                                           rel=1e-12)
    assert held.scene.mechanism.drive2.omega == 0.0


@pytest.mark.parametrize("k", [0, 2, 4])
def test_driving_and_holding_forces_equal_the_virtual_power(held, k):
    l4 = float(held.phi[k])
    f4, f7 = golden(l4, l7dot=0.0)
    fa = held.extras["forces"]
    assert float(fa.balancing_moment[k]) == pytest.approx(f4, rel=1e-6)
    assert float(fa.second[1][k]) == pytest.approx(f7, rel=1e-6)
    assert float(fa.zhukovsky_moment[k]) == pytest.approx(f4, rel=1e-6)
    # holding the arm changes the boom cylinder's force (not the same machine as W = 2 moving)
    assert abs(f4 - golden(l4)[0]) > 1e-3 * abs(f4) or k == 0


@pytest.mark.parametrize(("drive2", "key"), [
    ('hold = "2700 mm"\nspeed = "0.075 m/s"\n', "drive2.speed"),
    ('hold = "2700 mm"\nstart = "2700 mm"\n', "drive2.start"),
    ('hold = "-5 mm"\n', "drive2.hold"),
    ('hold = "2 kg"\n', "drive2.hold"),
])
def test_refusals_name_the_key(drive2, key):
    with pytest.raises(SceneError) as err:
        parse_scene(_text(drive2), "held.toml")
    assert err.value.key == key


def test_only_a_cylinder_is_held():
    text = _text().replace('kind = "cylinder"\nlink = "7"\nhold',
                           'kind = "crank"\nlink = "7"\nhold')
    with pytest.raises(SceneError) as err:
        parse_scene(text, "held.toml")
    assert err.value.key == "drive2.hold"
    assert "cylinder" in str(err.value)
