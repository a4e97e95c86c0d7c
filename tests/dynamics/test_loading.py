"""Loading: built from scenes, validated against the mechanism; bad load input in scene files."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from mechplan.dynamics import Loading
from mechplan.errors import SceneError
from mechplan.model.loads import LoadKind, LoadSpec, MassSpec
from mechplan.scene import load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[2]
BASE = (ROOT / "templates" / "slider_crank.toml").read_text(encoding="utf-8")


def test_from_scene_takes_masses_loads_and_gravity():
    scene = load_scene(ROOT / "templates" / "v_engine.toml")
    loading = Loading.from_scene(scene)
    assert set(loading.masses) == {"2", "3", "5"}
    assert [s.kind for s in loading.loads] == [LoadKind.PRESSURE, LoadKind.PRESSURE]
    assert loading.gravity.enabled and loading.gravity.direction == (0.0, -1.0)
    assert not loading.is_empty
    loading.check(scene.mechanism)
    assert Loading().is_empty


@pytest.mark.parametrize(("text", "key", "words"), [
    (BASE.replace('mass = "4 kg"', 'mass = "-4 kg"'), "links.2.mass", "must not be negative"),
    (BASE.replace('J = "0.06 kg*m^2"', 'J = "-0.06 kg*m^2"'), "links.2.J", "must not be negative"),
    (BASE + '[[loads]]\ntype = "force"\npoint = "Z"\nvector = ["0 N", "-10 N"]\n',
     "loads[0].point", "unknown point 'Z'"),
    (BASE + '[[loads]]\ntype = "pressure"\npoint = "B"\npressure = "1 MPa"\ntowards = "O"\n',
     "loads[0].bore", "bore diameter"),
    (BASE + '[[loads]]\ntype = "pressure"\npoint = "A"\npressure = "1 MPa"\nbore = "90 mm"\n'
     'towards = "O"\n', "loads[0].point", "does not slide"),
    (BASE + '[[loads]]\ntype = "moment"\nlink = "7"\nmoment = "10 N*m"\n', "loads[0].link",
     "unknown link"),
])
def test_bad_load_input_in_a_scene(text, key, words):
    with pytest.raises(SceneError) as info:
        parse_scene(text, "bad.toml")
    assert info.value.key == key
    assert words in str(info.value)
    assert "bad.toml" in str(info.value)


def test_check_rejects_what_does_not_fit_the_mechanism():
    mech = load_scene(ROOT / "templates" / "slider_crank.toml").mechanism
    cases = [
        (Loading({"2": MassSpec("2", -1.0, "S2", 0.0)}), "must not be negative"),
        (Loading({"2": MassSpec("2", 1.0, "S2", -0.1)}), "must not be negative"),
        (Loading({"9": MassSpec("9", 1.0, "S2", 0.0)}), "not a moving link"),
        (Loading({"2": MassSpec("2", 1.0, "B9", 0.0)}), "not a point of link 2"),
        (Loading(loads=(LoadSpec(LoadKind.FORCE, "2", "Q", vector=(1.0, 0.0)),)), "unknown point"),
        (Loading(loads=(LoadSpec(LoadKind.PRESSURE, "3", "B", pressure=1e5, towards="O"),)),
         "bore diameter"),
        (Loading(loads=(LoadSpec(LoadKind.PRESSURE, "2", "A", pressure=1e5, bore=0.1,
                                 towards="O"),)), "does not slide"),
        (Loading(loads=(LoadSpec(LoadKind.FORCE, "3", "B", magnitude=5.0, towards="B"),)),
         "cannot point towards B"),
        (Loading(loads=(LoadSpec(LoadKind.TABLE, "3", "B", towards="O", against="crank_angle",
                                 table=((0.0, 1.0), (5 * math.pi, 2.0))),)), "two turns at most"),
    ]
    for loading, words in cases:
        with pytest.raises(SceneError, match=words):
            loading.check(mech)


def test_reversed_negates_every_load():
    spec = (LoadSpec(LoadKind.FORCE, "3", "B", vector=(1.0, -2.0)),
            LoadSpec(LoadKind.FORCE, "3", "B", magnitude=3.0, angle=0.5),
            LoadSpec(LoadKind.PRESSURE, "3", "B", pressure=2.0, bore=0.1, towards="O"),
            LoadSpec(LoadKind.MOMENT, "2", moment=4.0),
            LoadSpec(LoadKind.TABLE, "3", "B", towards="O", against="displacement",
                     table=((0.0, 1.0), (1.0, -2.0))))
    r = Loading(loads=spec).reversed()
    assert r.loads[0].vector == (-1.0, 2.0)
    assert math.isclose(r.loads[1].angle, 0.5 + math.pi)
    assert r.loads[2].pressure == -2.0
    assert r.loads[3].moment == -4.0
    assert r.loads[4].table == ((0.0, -1.0), (1.0, 2.0))
    with pytest.raises(ValueError):
        Loading(loads=(LoadSpec(LoadKind.FORCE, "3", "B", magnitude=1.0, towards="O"),)).reversed()
