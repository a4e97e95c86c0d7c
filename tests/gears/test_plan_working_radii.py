"""The velocity plan of a planetary train uses the working pitch radii of each mesh, so it agrees
with Willis on every set it draws; a set that is not coaxial (and is not made so by a working
centre distance with shifted gears) is refused and flagged, never drawn with wrong velocities.

Willis here is computed independently from the tooth numbers in exact rationals: with the carrier
held, each mesh turns its gears in the ratio −z_driver/z_driven (external) or +z_driver/z_driven
(internal)."""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mechplan.errors import SceneError
from mechplan.model.gears import PlanetarySpec, Scheme
from mechplan.studies.gears import solve_gear_text
from mechplan.synthesis.gears import train
from mechplan.synthesis.gears.plan import velocity_plan

#: (internal of mesh 1, internal of mesh 2), written here rather than read from the code
MESHES = {Scheme.SINGLE_ROW: (False, True), Scheme.EXT_INT: (False, True),
          Scheme.EXT_EXT: (False, False), Scheme.INT_INT: (True, True)}


def relative_turns(scheme: Scheme, z: tuple[int, ...]) -> dict[str, Fraction]:
    """(ω − ω_h)/(ω_a − ω_h) of every gear, from tooth numbers alone."""
    int1, int2 = MESHES[scheme]
    if scheme is Scheme.SINGLE_ROW:
        za, zp, zb = z
        p = Fraction(za, zp) * (1 if int1 else -1)
        b = p * Fraction(zp, zb) * (1 if int2 else -1)
        return {"1": Fraction(1), "2": p, "3": b}
    za, zp1, zp2, zb = z
    p = Fraction(za, zp1) * (1 if int1 else -1)
    b = p * Fraction(zp2, zb) * (1 if int2 else -1)
    return {"1": Fraction(1), "2": p, "3": p, "4": b}


def willis_omega(scheme: Scheme, z, fixed: str, inp: str, w_in: float) -> dict[str, Fraction]:
    """Absolute ω of every link: ω_x = ω_h + t_x·(ω_a − ω_h), with the fixed link at rest."""
    t = relative_turns(scheme, z)
    t["h"] = Fraction(0)
    # ω_x = ω_h·(1 − t_x) + d·t_x with d = ω_a − ω_h + ω_h... write ω_x = H + t_x·D
    # two conditions: ω_fixed = 0, ω_in = w_in
    (a1, b1), (a2, b2) = (Fraction(1), t[fixed]), (Fraction(1), t[inp])
    det = a1 * b2 - a2 * b1
    w = Fraction(w_in)
    H = (-b1 * w) / det
    D = (a1 * w) / det
    return {n: H + t[n] * D for n in t}


SCHEMES = list(Scheme)


@st.composite
def train_sets(draw):
    scheme = draw(st.sampled_from(SCHEMES))
    n = 3 if scheme is Scheme.SINGLE_ROW else 4
    z = list(draw(st.lists(st.integers(12, 120), min_size=n, max_size=n)))
    int1, int2 = MESHES[scheme]
    if int1 and z[0] <= z[1] + 4:
        z[0] = z[1] + draw(st.integers(5, 40))
    if int2 and z[-1] <= z[-2] + 4:
        z[-1] = z[-2] + draw(st.integers(5, 40))
    mode = draw(st.sampled_from(["as_is", "coaxial", "auto", "given_aw"]))
    if mode == "coaxial":             # make the set coaxial without shifts (one module)
        s1 = z[0] - z[1] if int1 else z[0] + z[1]
        if scheme is Scheme.SINGLE_ROW:
            z[2] = z[0] + 2 * z[1]
        else:
            z[3] = s1 + z[2] if int2 else s1 - z[2]
            if z[3] < 5:
                mode = "as_is"
    fixed, inp, out = draw(st.permutations(scheme.links))
    return scheme, tuple(z), mode, (fixed, inp, out), draw(st.floats(0.5, 3.0))


def spec_of(scheme, mode, links, speed, a_w=None):
    fixed, inp, out = links
    return PlanetarySpec(scheme, fixed, inp, out, 1.0, 0.02, 1, (0.002, 0.002), (5, 200),
                         input_speed=speed, centre_auto=mode == "auto",
                         centre_distance=a_w if mode == "given_aw" else None)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(train_sets())
def test_the_plan_agrees_with_willis_or_refuses(case):
    scheme, z, mode, links, speed = case
    int1, int2 = MESHES[scheme]
    s1 = z[0] - z[1] if int1 else z[0] + z[1]
    s2 = (z[2] - z[1]) if scheme is Scheme.SINGLE_ROW else (z[3] - z[2] if int2 else z[3] + z[2])
    a_w = None
    if mode == "given_aw":
        a_w = 0.002 * (s1 + s2) / 4 + 0.0003            # between the two, a little off
    spec = spec_of(scheme, mode, links, speed, a_w)
    cond = train.conditions(spec, z)
    standard_coaxial = s1 == s2
    t = relative_turns(scheme, z) | {"h": Fraction(0)}
    if t[links[0]] == t[links[1]]:            # fixed and input turn alike: no motion is possible
        if cond.coaxial:
            with pytest.raises(SceneError, match="locked"):
                velocity_plan(spec, z)
        return
    if cond.coaxial:
        plan = velocity_plan(spec, z)
        truth = willis_omega(scheme, z, links[0], links[1], speed)
        for name, w in truth.items():
            assert plan.omega[name] == pytest.approx(float(w), rel=1e-12, abs=1e-12 * speed)
        _, inp, out = links
        if truth[out] != 0:
            u = truth[inp] / truth[out]
            assert plan.ratio == pytest.approx(float(u), rel=1e-12)
            assert cond.ratio == pytest.approx(float(u), rel=1e-12)
        # the pitch points are where the plan says: a_w = r_w(a) ± r_w(planet) in each mesh
        r = plan.radius
        ext_a = plan.pitch_points["A"] + (-1 if int1 else 1) * r["2"]
        assert ext_a == pytest.approx(plan.a_w, rel=1e-12)
        planet_b = (plan.a_w * z[1] / abs(z[2] - z[1]) if scheme is Scheme.SINGLE_ROW
                    else r["3"])          # the single row's planet works at two radii
        assert plan.pitch_points["B"] + (-1 if int2 else 1) * planet_b == pytest.approx(
            plan.a_w, rel=1e-12)
    else:
        assert cond.working is None
        assert not standard_coaxial or mode == "given_aw"
        with pytest.raises(SceneError, match="not coaxial"):
            velocity_plan(spec, z)


def test_artobolevsky_ratio_10000():
    """Artobolevsky's train 100/101/100/99 (carrier in, gear 1 out, gear 4 held): u_h1 = 10⁴.
    Unshifted it is not coaxial (100.5 mm against 99.5 mm at m = 1 mm): refused and flagged.
    Built at one working centre distance with shifted gears, its plan gives ω1 = 10⁻⁴ ω_h."""
    base = """kind = "gears"
[planetary]
scheme = "two_row_ext_ext"
fixed = "4"
input = "h"
output = "1"
ratio = 10000
planets = 1
module = "1 mm"
teeth = [10, 200]
given = [100, 101, 100, 99]
"""
    study = solve_gear_text(base, "a.toml")
    assert study.solution.planetary.plan is None
    assert any("coaxial" in w for w in study.warnings("en"))
    assert study.to_json()["planetary"]["omega_rad_s"] is None
    shifted = solve_gear_text(base + 'centre_distance = "auto"\n', "a.toml")
    plan = shifted.solution.planetary.plan
    assert plan.omega["1"] == pytest.approx(1e-4, rel=1e-12)
    assert plan.ratio == pytest.approx(10000, rel=1e-12)
    c = shifted.solution.planetary.chosen
    assert c.working == pytest.approx(0.1005)
    # mesh 3–4 at a_w = 100.5 mm: cos α_w = 99.5·cos 20°/100.5, x_Σ = 199(inv α_w − inv α)/(2 tan α)
    alpha = math.radians(20)
    aw = math.acos(99.5 * math.cos(alpha) / 100.5)
    x = 199 * ((math.tan(aw) - aw) - (math.tan(alpha) - alpha)) / (2 * math.tan(alpha))
    assert c.shift_sums[0] == pytest.approx(0.0, abs=1e-12)
    assert c.shift_sums[1] == pytest.approx(x, rel=1e-12)
    assert not shifted.warnings("en")
    report = shifted.report("en")
    assert "0.0001" in report


def test_a_working_distance_too_far_is_refused():
    spec = spec_of(Scheme.EXT_EXT, "given_aw", ("4", "h", "1"), 1.0, a_w=0.3)
    c = train.conditions(spec, (100, 101, 100, 99))
    assert not c.coaxial and c.working is None and all(x > 2 for x in c.shift_sums)


@pytest.mark.parametrize("scheme", SCHEMES, ids=lambda s: s.value)
def test_every_link_choice_of_a_standard_set(scheme):
    z = {Scheme.SINGLE_ROW: (20, 31, 82), Scheme.EXT_INT: (17, 17, 17, 51),
         Scheme.EXT_EXT: (40, 20, 21, 39), Scheme.INT_INT: (80, 20, 19, 79)}[scheme]
    for links in itertools.permutations(scheme.links):
        plan = velocity_plan(spec_of(scheme, "as_is", links, 1.0), z)
        truth = willis_omega(scheme, z, links[0], links[1], 1.0)
        assert all(plan.omega[n] == pytest.approx(float(w), rel=1e-12, abs=1e-14)
                   for n, w in truth.items())
