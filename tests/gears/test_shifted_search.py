"""The search with a working centre distance: sets coaxial only with shifted gears are found (both
enumerations alike), every one passes the scalar conditions, and Artobolevsky's 100/101/100/99
train comes out for u = 10 000."""

from __future__ import annotations

import numpy as np
import pytest

from mechplan.model.gears import PlanetarySpec, Scheme
from mechplan.synthesis.gears import search, train


def spec(**kw) -> PlanetarySpec:
    base = {"scheme": Scheme.EXT_EXT, "fixed": "4", "input": "h", "output": "1",
            "ratio": 10000.0, "deviation": 1e-6, "planets": 1, "modules": (0.001, 0.001),
            "z_range": (95, 105), "z_min": 17, "centre_auto": True}
    base.update(kw)
    return PlanetarySpec(**base)


def test_artobolevsky_train_is_found_with_shifted_gears():
    s = spec()
    found = search.search(s)
    sets = {tuple(int(v) for v in z) for z in found.sets}
    assert (100, 101, 100, 99) in sets
    for z in sets:
        c = train.conditions(s, z)
        assert c.valid and c.working is not None
        assert all(abs(x) <= s.max_shift_sum + 1e-9 for x in c.shift_sums)
    unshifted = search.search(spec(centre_auto=False))
    assert (100, 101, 100, 99) not in {tuple(int(v) for v in z) for z in unshifted.sets}


@pytest.mark.parametrize("kw", [
    {},
    {"scheme": Scheme.EXT_INT, "fixed": "4", "input": "1", "output": "h", "ratio": 4.0,
     "deviation": 0.02, "planets": 3, "z_range": (17, 70)},
    {"scheme": Scheme.SINGLE_ROW, "fixed": "3", "input": "1", "output": "h", "ratio": 5.0,
     "deviation": 0.02, "planets": 3, "z_range": (17, 150), "centre_auto": False,
     "centre_distance": 0.0405},
])
def test_both_enumerations_agree(kw):
    s = spec(**kw)
    a = search.search(s).sets
    b = search.search(s, plain=True).sets
    assert np.array_equal(a, b) and a.shape[0] > 0
