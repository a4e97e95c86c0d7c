"""The default call at one crank angle (``m.solve(10.0)``) takes its own short path (issue 35,
latency): it must answer exactly what the general path answers — values bit for bit, flags,
errors."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mechplan
from mechplan import api
from mechplan.construct.estimate import DEFAULT_TOLERANCE
from mechplan.errors import MechplanError
from mechplan.limits import MAX_ANGLE_DEG

ROOT = Path(__file__).resolve().parents[2]
KINEMATIC = ("position", "velocity", "acceleration")


def test_the_short_paths_constants_are_the_librarys():
    assert api._MAX_ANGLE_DEG == MAX_ANGLE_DEG and api._TOLERANCE == DEFAULT_TOLERANCE


@pytest.mark.parametrize("name", ["four_bar", "quick_return", "shaper", "offset_slider_crank"])
def test_one_angle_equals_the_general_path_bit_for_bit(name):
    m = mechplan.load(ROOT / "templates" / f"{name}.toml")
    plans = m._plans(None)
    for phi in np.linspace(-725.0, 725.0, 59):
        one = m.solve(float(phi))
        general = m.solve(np.array([phi]), plans=plans)   # an array: not the short path
        many = m.solve([float(phi), 3.0])
        assert one.phi_deg.tolist() == [float(phi)] and one.flags == general.flags
        for q in ("r", "v", "a", "angle", "omega", "epsilon"):
            for k in getattr(general, q):
                assert np.array_equal(getattr(one, q)[k], getattr(general, q)[k]), (q, k, phi)
                assert np.array_equal(getattr(one, q)[k][0], getattr(many, q)[k][0]), (q, k)
        with pytest.raises(ValueError):
            one.r[m.points[0]][0, 0] = 1.0
        kinematic = m.solve(float(phi), plans=KINEMATIC)  # the short path with plans named
        for q in ("r", "v", "a", "angle", "omega", "epsilon"):
            for k in getattr(general, q):
                assert np.array_equal(getattr(kinematic, q)[k], getattr(general, q)[k])


def test_one_angle_refuses_what_the_general_path_refuses():
    m = mechplan.load(ROOT / "templates" / "four_bar.toml")
    for bad in (float("nan"), float("inf"), 2e6):
        with pytest.raises(MechplanError) as one:
            m.solve(bad)
        with pytest.raises(MechplanError) as general:
            m.solve(np.array([bad]))                    # the general path at one angle
        assert type(one.value) is type(general.value)
        assert str(one.value).split("(got")[0] == str(general.value).split("(got")[0]


def test_one_angle_where_the_mechanism_cannot_close_raises_as_the_general_path():
    text = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")
    text = text.replace('AB = "80 mm"', 'AB = "200 mm"').replace(
        'C = "left of B->D"', 'C = "left of B->D"\nat = "90 deg"')
    m = mechplan.loads(text)
    assert np.isfinite(m.solve(90.0).r["C"]).all()
    with pytest.raises(MechplanError) as one:
        m.solve(0.0)
    with pytest.raises(MechplanError) as general:
        m.solve([0.0])
    assert str(one.value) == str(general.value) and "cannot be assembled" in str(one.value)
