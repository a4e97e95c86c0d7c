"""Instant centres: Kennedy's theorem over links and pairs, centres at infinity, velocities by
centres against the velocity plan (a second method), and the limits at dead centres."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechplan.construct.centre_kinematics import velocities_by_centres
from mechplan.construct.plans.centres import circle_diagram
from mechplan.errors import SingularError, UnreachableError
from mechplan.geom.vec import cross
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import solve
from mechplan.studies.centres import agreement, centres_at
from tests.scenes import (
    SCOTCH_YOKE,
    SLOTTED_CRANK_PRP,
    TEMPLATES,
    TWO_INPUT_TEMPLATES,
    four_bar_text,
)

#: W = 2 templates have centres Kennedy's theorem does not reach (see the five-bar's test)
SCENES = {p.stem: p for p in TEMPLATES if p not in TWO_INPUT_TEMPLATES}
TEXTS = {"scotch_yoke": SCOTCH_YOKE, "slotted_crank_prp": SLOTTED_CRANK_PRP}


def _scene(name):
    return load_scene(SCENES[name]) if name in SCENES else parse_scene(TEXTS[name])


def _solved(scene, count=360, at_deg=None):
    sol = solve(scene, at_deg=at_deg, count=None if at_deg is not None else count,
                plans=("position", "velocity"), scales=False)
    c, ev, mech = sol.construction, sol.ev, scene.mechanism
    return sol, centres_at(c, ev, mech)


def _by_centres(sol, cs):
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    return velocities_by_centres(cs, mech, ev[c.omega(mech.drive.link)],
                                 lambda p: ev[c.position(p)])


# -- the circle diagram ---------------------------------------------------------------------------
def test_a_five_bar_has_only_its_pairs_centres_by_kennedy():
    """W = 2: no two links k, l close triangles for I_02 etc.; they are listed as not found."""
    path = next(p for p in TWO_INPUT_TEMPLATES if p.stem == "five_bar_two_cranks")
    d = circle_diagram(load_scene(path).mechanism)
    assert {(c.i, c.j) for c in d.centres} == {("0", "1"), ("1", "2"), ("2", "3"), ("3", "4"),
                                               ("0", "4")}
    assert set(d.missing) == {("0", "2"), ("0", "3"), ("1", "3"), ("1", "4"), ("2", "4")}


def test_every_centre_of_every_template_is_found_once():
    for name in [*SCENES, *TEXTS]:
        mech = _scene(name).mechanism
        d = circle_diagram(mech)
        n = len(mech.links)
        assert len(d.centres) == n * (n - 1) // 2 == d.count, name
        assert not d.missing, name
        keys = [(c.i, c.j) for c in d.centres]
        assert len(set(keys)) == len(keys)
        # each centre found by Kennedy uses only centres found before it
        seen: set[tuple[str, str]] = set()
        for c in d.centres:
            if not c.primary:
                for k in c.via[:2]:
                    for a in (c.i, c.j):
                        assert tuple(sorted((a, k), key=d.links.index)) in seen, (name, c.key)
            seen.add((c.i, c.j))


def test_four_bar_order_is_the_textbooks():
    d = circle_diagram(_scene("four_bar").mechanism)
    assert [c.key for c in d.centres if c.primary] == ["01", "03", "12", "23"]
    assert {(c.key, c.via) for c in d.centres if not c.primary} == {("02", ("1", "3")),
                                                                     ("13", ("0", "2"))}


# -- Kennedy's theorem as a property: I_ij, I_ik, I_jk in line for every k ------------------------
def _collinear_defect(cs, i, j, k):
    rows = [cs.of(*p).h for p in ((i, j), (i, k), (j, k))]
    rows = [r / np.linalg.norm(r, axis=1)[:, None] for r in rows]
    with np.errstate(invalid="ignore"):      # NaN at positions not built
        return np.abs(np.linalg.det(np.stack(rows, axis=1)))


@pytest.mark.parametrize("name", [*SCENES, *TEXTS])
def test_every_three_centres_are_in_line(name):
    sol, cs = _solved(_scene(name), count=72)
    ok = np.ones(sol.positions, bool)
    ok[[f.k for f in sol.failures]] = False
    worst = 0.0
    for i, j, k in itertools.combinations(cs.diagram.links, 3):
        worst = max(worst, float(np.nanmax(_collinear_defect(cs, i, j, k)[ok])))
    assert worst < 1e-12, worst


@settings(max_examples=25, deadline=None)
@given(ab=st.floats(40, 90), bc=st.floats(200, 300), cd=st.floats(150, 220),
       ad=st.floats(230, 270), phi=st.floats(0, 360))
def test_random_four_bars_have_centres_in_line_and_agree(ab, bc, cd, ad, phi):
    text = four_bar_text(d=(ad, 0.0), ab=ab, bc=bc, cd=cd)
    scene = parse_scene(text)
    try:
        sol, cs = _solved(scene, at_deg=[phi])
    except (UnreachableError, SingularError):   # not assemblable here: no centres to test
        return
    for i, j, k in itertools.combinations(cs.diagram.links, 3):
        assert _collinear_defect(cs, i, j, k)[0] < 1e-12
    by = _by_centres(sol, cs)
    assert agreement(sol.construction, sol.ev, scene.mechanism, by)[0] < 1e-12


# -- the second method: velocities by centres agree with the velocity plan ------------------------
@pytest.mark.parametrize("name", [*SCENES, *TEXTS])
def test_velocities_by_centres_agree_with_the_plan_at_360_positions(name):
    sol, cs = _solved(_scene(name))
    by = _by_centres(sol, cs)
    agree = agreement(sol.construction, sol.ev, sol.scene.mechanism, by)
    skip = {f.k for f in sol.failures} | {f.k for f in sol.flags if hasattr(f, "k")}
    keep = np.array([k not in skip for k in range(sol.positions)])
    assert keep.sum() >= 300, name
    assert float(np.max(agree[keep])) < 1e-12, (name, float(np.max(agree[keep])))
    # every named point: the same velocity from every link that carries it
    mech = sol.scene.mechanism
    for p in by.v:
        carriers = [lk for lk in mech.moving if p in mech.links[lk].points]
        assert carriers


def test_omega_from_the_relative_centre_is_the_ratio_of_distances():
    # ω3 = ω1 · I01I13 / I03I13 (signed along the line of centres), written out for the four-bar
    sol, cs = _solved(_scene("four_bar"), count=36)
    ev, c = sol.ev, sol.construction
    i01, i03, i13 = cs.point("0", "1"), cs.point("0", "3"), cs.point("1", "3")
    u = (i13 - i01)
    s1 = np.einsum("ij,ij->i", i13 - i01, u)
    s3 = np.einsum("ij,ij->i", i13 - i03, u)
    np.testing.assert_allclose(ev[c.omega("1")] * s1 / s3, ev[c.omega("3")], rtol=0,
                               atol=1e-12 * np.max(np.abs(ev[c.omega("3")])))


# -- centres at infinity -------------------------------------------------------------------------
def test_a_slider_on_the_frame_has_its_centre_at_infinity_normal_to_the_guide():
    sol, cs = _solved(_scene("offset_slider_crank"), count=24)
    v = cs.of("0", "3")
    assert np.all(v.h[:, 2] == 0.0)
    guide = sol.scene.mechanism.guides[next(iter(sol.scene.mechanism.guides))]
    along = np.array([math.cos(guide.angle), math.sin(guide.angle)])
    np.testing.assert_allclose(cs.direction("0", "3") @ along, 0.0, atol=1e-15)
    assert np.all(np.isnan(cs.point("0", "3")))


def test_the_centre_of_a_slider_in_a_turning_slot_turns_with_it():
    sol, cs = _solved(_scene("quick_return"), count=24)
    c, ev = sol.construction, sol.ev
    slot = ev[c.position("A")] - ev[c.position("O3")]
    np.testing.assert_allclose(np.einsum("ij,ij->i", cs.direction("2", "3"), slot), 0.0,
                               atol=1e-15)


def test_scotch_yoke_centres_at_infinity_and_the_line_at_infinity():
    # the block translates (its slot translates): I02 = the crank line ∩ the line at infinity
    sol, cs = _solved(parse_scene(SCOTCH_YOKE), count=12)
    c, ev = sol.construction, sol.ev
    crank = ev[c.position("A")] - ev[c.position("O")]
    assert np.all(cs.of("0", "2").h[:, 2] == 0.0)
    np.testing.assert_allclose(np.abs(cross(cs.direction("0", "2"), crank)), 0.0,
                               atol=1e-15)
    by = _by_centres(sol, cs)
    np.testing.assert_allclose(by.omega["2"], 0.0, atol=1e-12)


def _quick_return_extreme_deg(scene, c):
    # the coulisse is at an extreme where the crank is ⊥ the slot: (A − O1)·(A − O3) = 0, i.e.
    # r² − r·|O1O3|·sin θ·(−1) = 0 with O3 below O1: sin θ = −r/|O1O3|
    r, d = 0.1, 0.3
    thetas = np.array([-math.asin(r / d), math.pi + math.asin(r / d)])
    return np.degrees(c.drive.scene(thetas))


def test_at_the_dead_centres_of_the_quick_return_the_block_centre_is_a_direction():
    scene = _scene("quick_return")
    sol, _ = _solved(scene, count=12)
    at = _quick_return_extreme_deg(scene, sol.construction)
    sol, cs = _solved(scene, at_deg=list(np.mod(at, 360.0)))
    c, ev = sol.construction, sol.ev
    h02 = cs.of("0", "2").h
    assert np.all(h02[:, 2] == 0.0)           # at infinity: a direction, not a huge number
    crank = ev[c.position("A")] - ev[c.position("O1")]
    np.testing.assert_allclose(np.abs(cross(cs.direction("0", "2"), crank)) /
                               np.hypot(*crank.T), 0.0, atol=1e-12)
    np.testing.assert_allclose(cs.point("1", "3"), ev[c.position("O1")], atol=1e-15)
    by = _by_centres(sol, cs)
    np.testing.assert_allclose(by.omega["3"], 0.0, atol=1e-12)
    np.testing.assert_allclose(by.omega["2"], 0.0, atol=1e-12)
    # the limit: beside the dead centre I02 is finite, far, in the same direction, receding
    # like 1/δ, and ω2 → 0 like δ
    for delta in (1e-2, 1e-3, 1e-4):
        near, ncs = _solved(scene, at_deg=list(np.mod(at + delta, 360.0)))
        p = ncs.point("0", "2") - near.ev[near.construction.position("O1")]
        assert np.all(np.isfinite(p))
        dist = np.hypot(*p.T)
        u = p / dist[:, None]
        assert np.all(np.abs(cross(u, cs.direction("0", "2"))) < 10 * math.radians(delta))
        assert np.all(dist > 0.5 / math.radians(delta) * 0.1)
        w2 = _by_centres(near, ncs).omega["2"]
        assert np.all(np.abs(w2) < 40 * math.radians(delta))


def test_slider_crank_dead_centres_put_i13_on_the_crank_pivot():
    scene = _scene("slider_crank")
    sol, _ = _solved(scene, count=4)
    guide = next(iter(scene.mechanism.guides.values()))
    # with no offset the dead centres are where the crank lies along the guide
    at = np.degrees(sol.construction.drive.scene(np.array([guide.angle, guide.angle + math.pi])))
    sol, cs = _solved(scene, at_deg=list(np.mod(at, 360.0)))
    mech = scene.mechanism
    o = next(p.point for p in mech.pairs if {p.a, p.b} == {"0", mech.drive.link})
    np.testing.assert_allclose(cs.point("1", "3"), sol.ev[sol.construction.position(o)],
                               atol=1e-12)
    by = _by_centres(sol, cs)
    slider = next(p for p in scene.mechanism.links["3"].points)
    np.testing.assert_allclose(by.v[slider], 0.0, atol=1e-12)


def test_coupler_translating_has_its_centre_at_infinity():
    # a centred slider-crank with the crank ⊥ the guide: the rod translates, ω2 = 0
    scene = _scene("slider_crank")
    sol, _ = _solved(scene, count=4)
    guide = next(iter(scene.mechanism.guides.values()))
    at = np.degrees(sol.construction.drive.scene(np.array([guide.angle + math.pi / 2])))
    sol, cs = _solved(scene, at_deg=list(np.mod(at, 360.0)))
    # the case needs a centred slider-crank, which the template is (an offset would fail here)
    assert scene.mechanism.guides and abs(_offset(sol)) <= 1e-12
    assert cs.of("0", "2").h[0, 2] == 0.0
    assert abs(_by_centres(sol, cs).omega["2"][0]) < 1e-12


def _offset(sol):
    mech = sol.scene.mechanism
    g = next(iter(mech.guides.values()))
    o = sol.ev[sol.construction.position(next(p.point for p in mech.pairs
                                             if {p.a, p.b} == {"0", mech.drive.link}))][0]
    n = np.array([-math.sin(g.angle), math.cos(g.angle)])
    return float((o - np.array(g.origin)) @ n)


def test_indeterminate_and_far_centres_are_not_huge_numbers():
    for name in SCENES:
        _, cs = _solved(_scene(name), count=360)
        for val in cs.values.values():
            fin = val.h[:, 2] == 1.0
            assert np.all(np.abs(val.h[fin, :2]) < 1e15), name
