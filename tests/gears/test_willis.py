"""Willis ratios of every scheme checked against direct kinematics written here: the velocities of
the pitch points and of the planet axis, equated gear by gear, solved as a linear system."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from mechplan.model.gears import PlanetarySpec, Scheme
from mechplan.synthesis.gears import train
from mechplan.synthesis.gears.plan import velocity_plan

SETS = {
    Scheme.SINGLE_ROW: (20, 31, 82),
    Scheme.EXT_INT: (17, 17, 17, 51),
    Scheme.EXT_EXT: (40, 20, 21, 39),
    Scheme.INT_INT: (80, 20, 19, 79),
}


def direct(scheme: Scheme, z, fixed: str, inp: str, out: str) -> float:
    """ω_in/ω_out by rolling without slip at the pitch points (one module, m = 2)."""
    m = 2.0
    r = [m * v / 2 for v in z]
    central_a, central_b = r[0], r[-1]
    planet_a, planet_b = (r[1], r[1]) if scheme is Scheme.SINGLE_ROW else (r[1], r[2])
    int_a, int_b = scheme.internal
    e = central_a - planet_a if int_a else central_a + planet_a          # planet axis radius
    # velocity of the planet at a radius y from the central axis: v = ω_h·e + ω_p·(y − e)
    names = ("a", "p", "b", "h")
    y_b = e + planet_b if int_b else e - planet_b                       # contact with b
    assert y_b == pytest.approx(central_b)                                # the set is coaxial
    rows = [
        [central_a, -(central_a - e), 0.0, -e],      # contact with a at y = r_a
        [0.0, -(y_b - e), y_b, -e],                  # contact with b
    ]
    link = dict(zip(scheme.links, ("a", "b", "h")))
    fix = [0.0] * 4
    fix[names.index(link[fixed])] = 1.0
    drive = [0.0] * 4
    drive[names.index(link[inp])] = 1.0
    w = np.linalg.solve(np.array(rows + [fix, drive]), np.array([0.0, 0.0, 0.0, 1.0]))
    return float(w[names.index(link[inp])] / w[names.index(link[out])])


def spec_for(scheme: Scheme, fixed: str, inp: str, out: str) -> PlanetarySpec:
    return PlanetarySpec(scheme, fixed, inp, out, 1.0, 0.02, 3, (0.002, 0.002), (10, 100))


@pytest.mark.parametrize("scheme", list(Scheme), ids=lambda s: s.value)
def test_willis_equals_direct_kinematics_for_every_link_choice(scheme):
    z = SETS[scheme]
    for fixed, inp, out in itertools.permutations(scheme.links):
        sp = spec_for(scheme, fixed, inp, out)
        u = float(train.ratio_from_i(train.willis_i(scheme, np.array([z])), scheme, fixed, inp,
                                     out)[0])
        assert u == pytest.approx(direct(scheme, z, fixed, inp, out), rel=1e-12)
        assert velocity_plan(sp, z).ratio == pytest.approx(u, rel=1e-12)
        i = float(train.willis_i(scheme, np.array([z]))[0])
        assert train.i_from_ratio(u, scheme, fixed, inp, out) == pytest.approx(i, rel=1e-12)


def test_closed_forms_of_the_course():
    z1, z2, z3, z4 = 17, 17, 17, 51
    u = train.ratio_from_i(train.willis_i(Scheme.EXT_INT, np.array([(z1, z2, z3, z4)])),
                           Scheme.EXT_INT, "4", "1", "h")[0]
    assert u == pytest.approx(1 + z2 * z4 / (z1 * z3)) and u == pytest.approx(4.0)
    u1 = train.ratio_from_i(train.willis_i(Scheme.SINGLE_ROW, np.array([(20, 31, 82)])),
                            Scheme.SINGLE_ROW, "3", "1", "h")[0]
    assert u1 == pytest.approx(1 + 82 / 20)


def test_plan_velocities_of_the_worked_example():
    sp = PlanetarySpec(Scheme.EXT_INT, "4", "1", "h", 4.0, 0.02, 4, (0.002, 0.002), (17, 60),
                       input_speed=100.0)
    p = velocity_plan(sp, (17, 17, 17, 51))
    # v_A = ω1·r1 = 100·0.017; the planet block turns about its contact B with the fixed ring:
    # ω_p = −v_A/(r_B − r_A) and the carrier ω_h = v_O/a_w with v_O = v_A/2 (O halfway from B to A)
    v_a = 100.0 * 0.017
    assert p.omega["2"] == pytest.approx(-v_a / (0.051 - 0.017))
    assert p.omega["h"] == pytest.approx(v_a * (0.051 - 0.034) / (0.051 - 0.017) / 0.034)
    assert p.relative["1"] == pytest.approx(100.0 - 25.0)
    assert p.omega["4"] == pytest.approx(0.0, abs=1e-12)
