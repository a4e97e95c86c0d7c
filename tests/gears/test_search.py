"""Planetary synthesis: the worked example's set, the search against a brute force written here from
the course formulas, the fast search against the plain enumeration, and the errors."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.errors import SceneError
from mechplan.model.gears import PlanetarySpec, Scheme
from mechplan.synthesis.gears import search, train
from mechplan.synthesis.gears.solve import solve_planetary

M = 0.002


def worked(**kw) -> PlanetarySpec:
    base = {"scheme": Scheme.EXT_INT, "fixed": "4", "input": "1", "output": "h", "ratio": 4.0,
            "deviation": 0.02, "planets": 4, "modules": (M, M), "z_range": (17, 120)}
    base.update(kw)
    return PlanetarySpec(**base)


def test_worked_example_set_is_the_best_with_its_conditions():
    res = solve_planetary(worked())
    c = res.chosen
    assert c.z == (17, 17, 17, 51)
    assert c.valid and c.ratio == pytest.approx(4.0)
    assert c.a_w[0] == pytest.approx(M * (17 + 17) / 2) == pytest.approx(M * (51 - 17) / 2)
    assert c.assembly_value == pytest.approx(17 * 4 / 4) and c.assembly_p == 0
    assert c.neighbour_span == pytest.approx((17 + 17) * M * math.sin(math.pi / 4))
    assert c.planet_tip == pytest.approx(M * (17 + 2))
    assert c.ring_difference == 51 - 17
    assert res.plan.ratio == pytest.approx(1 + 17 * 51 / (17 * 17))


def _brute(scheme: Scheme, lo: int, hi: int, u_t: float, dev: float, k: int, z_min: int = 17,
           ring: int = 8, ha: float = 1.0) -> set[tuple[int, ...]]:
    """Every set by nested loops and the course formulas (ring fixed, sun input, carrier output)."""
    out = set()
    rng = range(lo, hi + 1)
    if scheme is Scheme.SINGLE_ROW:
        for z1 in rng:
            for z2 in rng:
                z3 = z1 + 2 * z2
                if z3 > hi:
                    continue
                u = 1 + z3 / z1
                ok = (abs(u - u_t) <= dev * u_t + 1e-12 and (z1 + z3) % k == 0
                      and (z1 + z2) * math.sin(math.pi / k) > z2 + 2 * ha
                      and min(z1, z2) >= z_min and z3 - z2 >= ring)
                if ok:
                    out.add((z1, z2, z3))
        return out
    for z1 in rng:
        for z2 in rng:
            for z3 in rng:
                z4 = z1 + z2 + z3                        # coaxiality of the ext-int scheme
                if z4 > hi:
                    continue
                u = 1 + z2 * z4 / (z1 * z3)
                if abs(u - u_t) > dev * u_t + 1e-12:
                    continue
                # (z1·u/k)(1 + k·p) an integer for some p: try p = 0 … k·z3
                num = z1 * z3 + z2 * z4
                assembles = any(num * (1 + k * p) % (k * z3) == 0 for p in range(k * z3 + 1))
                if (assembles and (z1 + z2) * math.sin(math.pi / k) > max(z2, z3) + 2 * ha
                        and min(z1, z2, z3) >= z_min and z4 - z3 >= ring):
                    out.add((z1, z2, z3, z4))
    return out


@pytest.mark.parametrize(("scheme", "u", "k", "hi"), [(Scheme.EXT_INT, 4.0, 3, 66),
                                                      (Scheme.EXT_INT, 7.0, 4, 70),
                                                      (Scheme.SINGLE_ROW, 5.0, 3, 160)])
def test_search_equals_brute_force(scheme, u, k, hi):
    fixed = scheme.links[1]
    sp = worked(scheme=scheme, fixed=fixed, ratio=u, planets=k, z_range=(17, hi))
    got = {tuple(int(v) for v in z) for z in search.search(sp).sets}
    assert got == _brute(scheme, 17, hi, u, 0.02, k)
    assert got


@pytest.mark.parametrize(("scheme", "fixed", "inp", "out", "u"), [
    (Scheme.EXT_EXT, "4", "h", "1", 15.0),
    (Scheme.INT_INT, "4", "h", "1", -20.0),
    (Scheme.EXT_INT, "h", "1", "4", -3.0),
    (Scheme.EXT_EXT, "1", "h", "4", 10.0),
])
def test_fast_search_equals_plain_enumeration(scheme, fixed, inp, out, u):
    sp = worked(scheme=scheme, fixed=fixed, input=inp, output=out, ratio=u, planets=3,
                z_range=(17, 90), deviation=0.03)
    fast, plain = search.search(sp), search.search(sp, plain=True)
    assert fast.sets.shape[0] > 0
    assert np.array_equal(fast.sets, plain.sets)
    ratios = train.ratio_from_i(train.willis_i(scheme, fast.sets), scheme, fixed, inp, out)
    assert np.all(np.abs(ratios - u) <= 0.03 * abs(u) + 1e-12)


def test_two_modules_keep_coaxiality():
    sp = worked(modules=(0.002, 0.0025), z_range=(17, 150), planets=3)
    res = solve_planetary(sp)
    a12, a34 = res.chosen.a_w
    assert a12 == pytest.approx(a34, rel=1e-12)
    z1, z2, z3, z4 = res.chosen.z
    assert 0.002 * (z1 + z2) == pytest.approx(0.0025 * (z4 - z3))


def test_unreachable_ratio_names_the_key_and_the_nearest():
    sp = worked(ratio=1000.0, z_range=(17, 60))
    with pytest.raises(SceneError) as err:
        search.best_or_error(sp)
    assert err.value.key == "planetary.ratio"
    assert "nearest" in str(err.value)
    # the nearest a brute force finds: the largest u = 1 + z2·z4/(z1·z3) with z4 = z1 + z2 + z3
    best = max(1 + z2 * (z1 + z2 + z3) / (z1 * z3) for z1 in range(17, 61)
               for z2 in range(17, 61) for z3 in range(17, 61) if z1 + z2 + z3 <= 60)
    assert f"{best:.4g}" in str(err.value)


def test_planets_that_cannot_be_assembled():
    sp = worked(z_range=(17, 51), deviation=0.0, planets=3)      # only 17, 17, 17, 51 gives 4
    with pytest.raises(SceneError) as err:
        search.best_or_error(sp)
    assert err.value.key == "planetary.planets"
    assert "assembled" in str(err.value) and "k = 2, 4" in str(err.value)


def test_planets_that_do_not_fit_side_by_side():
    sp = worked(z_range=(17, 51), deviation=0.0, planets=4, ring_difference=8)
    assert search.best_or_error(sp).sets.shape[0] == 1
    # k = 17 assembles (z1·u/k = 68/17 = 4) but 34·sin(π/17) = 6.2 < z2 + 2 = 19
    sp17 = worked(z_range=(17, 51), deviation=0.0, planets=17)
    with pytest.raises(SceneError) as err:
        search.best_or_error(sp17)
    assert err.value.key == "planetary.planets" and "side by side" in str(err.value)
