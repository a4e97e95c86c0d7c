"""Kinetostatics group by group against an independent global Newton–Euler solution, virtual
power, Zhukovsky's lever, closed forms and the V-engine of worked example §1."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from scenes import TEMPLATES as LINKAGE_TEMPLATES

from mechplan.construct.builder import build_construction
from mechplan.construct.plans.force import pair_key
from mechplan.dynamics import Loading
from mechplan.dynamics.kinetostatics import analyse_forces, balancing_force
from mechplan.model.loads import Gravity, LoadKind, LoadSpec, MassSpec
from mechplan.model.mechanism import GROUND, PairKind
from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene

from .dyad_scenes import CYCLE, PINNED_SLIDERS, SCOTCH_YOKE
from .newton_euler import Kinematics, applied_loads, rich_loading, solve_global

ROOT = Path(__file__).resolve().parents[2]
TEMPLATES = sorted(p.stem for p in LINKAGE_TEMPLATES)          # kind = "mechanism" only
ALL_PLANS = ("position", "velocity", "acceleration", "force")
TOL = 1e-9


def scene_of(name: str):
    if name == "scotch_yoke":
        return parse_scene(SCOTCH_YOKE, "scotch_yoke.toml")
    if name == "pinned_sliders":
        return parse_scene(PINNED_SLIDERS, "pinned_sliders.toml")
    return load_scene(ROOT / "templates" / f"{name}.toml")


def solved(scene, loading, phi=CYCLE):
    c = build_construction(scene.mechanism, analyse(scene.mechanism), ALL_PLANS,
                           scene.assembly_phi, scene.path, loading)
    return c, c.evaluate(phi)


SCENES = TEMPLATES + ["scotch_yoke", "pinned_sliders"]


def test_every_dyad_kind_is_covered():
    kinds = {g.kind for name in SCENES for g in analyse(scene_of(name).mechanism).groups}
    # and the triads (class III): six revolute pairs, and a leg that is a slider on a guide
    assert kinds == {"RRR", "RRP", "RPR", "PRP", "RPP", "RRR-RRR", "RRP-RRR"}


#: the scene's own loading where it has one, and a rich test loading (every load kind) for all
CASES = [(name, "scene") for name in SCENES if not Loading.from_scene(scene_of(name)).is_empty] + \
    [(name, "rich") for name in SCENES]


def test_loaded_templates():
    assert {n for n, w in CASES if w == "scene"} >= {"v_engine", "machine_unit", "slider_crank"}


def _second_key(mech) -> str:
    """The result of the second driver's load: a crank's M_b<link>, a slider's F_d<link>."""
    return f"{'F_d' if mech.drive2.linear else 'M_b'}{mech.drive2.link}"


@pytest.mark.parametrize(("name", "which"), CASES)
def test_reactions_match_global_newton_euler(name, which):
    scene = scene_of(name)
    mech = scene.mechanism
    # the global solution is linear: friction (its own tests) is left out of the comparison
    loading = (replace(Loading.from_scene(scene), friction=None) if which == "scene"
               else rich_loading(mech))
    c, ev = solved(scene, loading)
    ref = solve_global(mech, loading, c, ev)
    scale = max(float(np.abs(f).max()) for f in ref.force.values())
    assert scale > 1.0
    for (i, j), f in ref.force.items():
        got = ev[c.results[f"R_{pair_key(i, j)}"]]
        # each reaction to 1e-9 of its own magnitude (or of the largest force where it vanishes)
        size = np.maximum(np.hypot(f[:, 0], f[:, 1]), 1e-6 * scale)
        err = np.hypot(*(got - f).T) / size
        assert err.max() < TOL, (i, j, err.max())
    for (i, j), couple in ref.couple.items():
        key = pair_key(i, j)
        force, d = ev[c.results[f"R_{key}"]], ev[c.results[f"d_{key}"]]
        pair = next(p for p in mech.pairs if {p.a, p.b} == {i, j})
        u = Kinematics(mech, c, ev).guide_dir(pair.guide)
        normal = u[:, 0] * force[:, 1] - u[:, 1] * force[:, 0]
        moment = np.where(normal != 0, d * normal, 0.0)     # moment about the pair point
        lever = max(float(np.abs(couple).max()), 1e-3 * scale)
        assert np.abs(moment - couple).max() < TOL * lever, (i, j)
    mb = ev[c.results["M_b"]]
    size = max(float(np.abs(ref.balancing).max()), 1e-30)
    assert np.abs(mb - ref.balancing).max() < TOL * size
    if mech.drive2 is not None:         # W = 2: the second crank's M_b (a slider's F_d)
        m2 = ev[c.results[_second_key(mech)]]
        assert ref.second is not None
        assert np.abs(m2 - ref.second).max() < TOL * max(float(np.abs(ref.second).max()), 1e-30)


@pytest.mark.parametrize("name", SCENES)
def test_virtual_power_and_zhukovsky(name):
    scene = scene_of(name)
    mech = scene.mechanism
    loading = rich_loading(mech)
    c, ev = solved(scene, loading)
    kin = Kinematics(mech, c, ev)
    power = np.zeros(ev.n)
    for link, point, _, force, couple in applied_loads(mech, loading, kin, ev.phi):
        if force is not None:
            power += np.sum(force * kin.vel(point), axis=-1)
        if couple is not None:
            power += couple * kin.scalar("omega", link)
    omega1 = kin.scalar("omega", mech.drive.link)
    mb, mz = ev[c.results["M_b"]], ev[c.results["M_b_zhukovsky"]]
    if mech.drive2 is not None:         # W = 2: the second driver's M_b (or F_d) works too
        rate = (ev["vel.rate2"] if mech.drive2.linear
                else kin.scalar("omega", mech.drive2.link))
        power += ev[c.results[_second_key(mech)]] * rate
    scale = np.abs(mb * omega1).max() + np.abs(power).max()
    assert np.abs(mb * omega1 + power).max() < TOL * scale
    assert np.abs(mz - mb).max() < TOL * np.abs(mb).max()
    fa = analyse_forces(c, ev, mech, loading)
    assert np.abs(fa.difference_percent).max() < 1e-7     # percent, i.e. 1e-9 relative


@pytest.mark.parametrize("name", SCENES)
def test_every_force_polygon_closes(name):
    scene = scene_of(name)
    mech = scene.mechanism
    loading = rich_loading(mech)
    c, ev = solved(scene, loading)
    kin = Kinematics(mech, c, ev)
    # each moving link: its loads plus the reactions of its pairs sum to zero (forces and moments)
    loads = applied_loads(mech, loading, kin, ev.phi)
    mb = ev[c.results["M_b"]]
    for link in mech.moving:
        force = np.zeros((ev.n, 2))
        moment = np.zeros(ev.n)
        scale = 1.0
        for lk, _, p, f, m in loads:
            if lk != link:
                continue
            if f is not None:
                force += f
                moment += p[:, 0] * f[:, 1] - p[:, 1] * f[:, 0]
                scale = max(scale, float(np.abs(f).max()))
            if m is not None:
                moment += m
        for pair in mech.pairs_of(link):
            other = pair.other(link)
            r = ev[c.results[f"R_{pair_key(other, link)}"]]
            scale = max(scale, float(np.abs(r).max()))
            force += r
            if pair.kind is PairKind.REVOLUTE:
                p = kin.pos(pair.point)
                moment += p[:, 0] * r[:, 1] - p[:, 1] * r[:, 0]
            else:
                d = ev[c.results[f"d_{pair_key(other, link)}"]]
                u = kin.guide_dir(pair.guide)
                p = kin.pos(pair.point) + np.where(np.isfinite(d), d, 0.0)[:, None] * u
                moment += p[:, 0] * r[:, 1] - p[:, 1] * r[:, 0]
        if link == mech.drive.link:
            moment += mb
        if mech.drive2 is not None and link == mech.drive2.link:     # W = 2
            if mech.drive2.linear:      # a slider's F_d along its guide, through its point
                fd = ev[c.results[_second_key(mech)]][:, None] * kin.guide_dir(mech.drive2.guide)
                p = kin.pos(mech.drive2.pivot)
                force += fd
                moment += p[:, 0] * fd[:, 1] - p[:, 1] * fd[:, 0]
            else:
                moment += ev[c.results[f"M_b{link}"]]
        assert np.abs(force).max() < TOL * scale, link
        assert np.abs(moment).max() < TOL * scale, link     # lengths here are below 1 m


def test_polygon_vertices_close_on_both_lines():
    scene = scene_of("v_engine")
    c, ev = solved(scene, Loading.from_scene(scene))
    closes = [s for s in c if s.op.name == "FORCE_CLOSE"]
    assert {s.group for s in closes} == {"II(2,3)", "II(4,5)"}
    for s in closes:
        point = ev[s.id]
        for line_id in s.inputs:
            line = ev[line_id]
            off = point - line[:, 0]
            dist = np.abs(off[:, 0] * line[:, 1, 1] - off[:, 1] * line[:, 1, 0])
            assert dist.max() < 1e-9 * np.abs(point).max()


def slider_crank_text(extra: str = "") -> str:
    return f"""
[ground]
O = ["0 mm", "0 mm"]
guides.x = {{ through = "O", angle = "0 deg" }}
[links.1]
lengths = {{ OA = "100 mm" }}
[links.2]
lengths = {{ AB = "350 mm" }}
[links.3]
slides = {{ point = "B", on = "x" }}
[drive]
link = "1"
speed = "50 rad/s"
sense = "ccw"
{extra}
"""


def test_slider_crank_closed_form():
    """Massless links, a force P on the piston towards O: S = P/cos β, N = −S sin β,
    M_b = P r sin(β − θ)/cos β with sin β = −(r/l) sin θ."""
    p_force, r, l = 5000.0, 0.1, 0.35
    scene = parse_scene(slider_crank_text(f"""
[[loads]]
type = "force"
point = "B"
magnitude = "{p_force} N"
towards = "O"
"""))
    theta = np.radians(np.arange(5.0, 360.0, 10.0))
    c, ev = solved(scene, Loading.from_scene(scene), theta)
    beta = np.arcsin(-r / l * np.sin(theta))
    s = p_force / np.cos(beta)
    e_ab = np.stack((np.cos(beta), np.sin(beta)), axis=-1)
    np.testing.assert_allclose(ev[c.results["R_23"]], s[:, None] * e_ab, rtol=0,
                               atol=1e-9 * p_force)
    np.testing.assert_allclose(ev[c.results["R_12"]], s[:, None] * e_ab, rtol=0,
                               atol=1e-9 * p_force)
    np.testing.assert_allclose(ev[c.results["R_03"]][:, 1], -s * np.sin(beta), atol=1e-9 * p_force)
    np.testing.assert_allclose(ev[c.results["R_03"]][:, 0], 0.0, atol=1e-9 * p_force)
    np.testing.assert_allclose(ev[c.results["R_01"]], s[:, None] * e_ab, atol=1e-9 * p_force)
    mb = p_force * r * np.sin(beta - theta) / np.cos(beta)
    np.testing.assert_allclose(ev[c.results["M_b"]], mb, atol=1e-9 * p_force * r)
    np.testing.assert_allclose(ev[c.results["M_b_zhukovsky"]], mb, atol=1e-9 * p_force * r)
    # the piston is a point mass-free slider: the guide reaction passes through B
    np.testing.assert_allclose(ev[c.results["d_03"]], 0.0, atol=1e-12)


@pytest.mark.parametrize("name", SCENES)
def test_load_free_massless_mechanism_has_zero_reactions(name):
    scene = scene_of(name)
    c, ev = solved(scene, Loading())
    for pair in scene.mechanism.pairs:
        r = ev[c.results[f"R_{pair_key(pair.a, pair.b)}"]]
        assert np.all(r == 0.0)
    assert np.all(ev[c.results["M_b"]] == 0.0)
    assert np.all(ev[c.results["M_b_zhukovsky"]] == 0.0)


@pytest.mark.parametrize("name", SCENES)
def test_reversing_all_loads_reverses_all_reactions(name):
    scene = scene_of(name)
    rich = rich_loading(scene.mechanism)
    massless = Loading({k: MassSpec(k, 0.0, m.centre, 0.0) for k, m in rich.masses.items()},
                       tuple(s for s in rich.loads
                             if s.towards is None or s.kind is not LoadKind.FORCE),
                       Gravity(enabled=False))
    c1, ev1 = solved(scene, massless)
    c2, ev2 = solved(scene, massless.reversed())
    for pair in scene.mechanism.pairs:
        key = f"R_{pair_key(pair.a, pair.b)}"
        r1, r2 = ev1[c1.results[key]], ev2[c2.results[key]]
        assert np.abs(r1).max() > 0 or pair.kind is PairKind.PRISMATIC
        np.testing.assert_allclose(r2, -r1, rtol=0, atol=1e-12 * np.abs(r1).max())
        if pair.kind is PairKind.PRISMATIC:
            d = f"d_{pair_key(pair.a, pair.b)}"
            np.testing.assert_allclose(ev2[c2.results[d]], ev1[c1.results[d]], rtol=1e-9)
    np.testing.assert_allclose(ev2[c2.results["M_b"]], -ev1[c1.results["M_b"]], rtol=1e-12,
                               atol=1e-12)


# -- the V-engine of worked example §1 ----------------------------------------------------------
def v_engine():
    scene = load_scene(ROOT / "templates" / "v_engine.toml")
    return scene, Loading.from_scene(scene)


def test_v_engine_gas_forces_and_weights():
    scene, loading = v_engine()
    assert {k: (m.mass, m.inertia) for k, m in loading.masses.items()} == {
        "2": (3.1, 0.1), "3": (2.0, 0.0), "5": (2.0, 0.0)}
    c, ev = solved(scene, loading, np.radians([180.0]))
    area_force = 1e6 * math.pi * 0.1 ** 2 / 4
    fc, fe = ev[c.results["load_0"]][0], ev[c.results["load_1"]][0]
    assert math.isclose(np.hypot(*fc), area_force, rel_tol=1e-12)
    assert round(area_force) == 7854
    # both act along their cylinder axes towards A (Ax at 60°, Ay at 120°)
    np.testing.assert_allclose(fc / area_force, [-0.5, -math.sqrt(3) / 2], atol=1e-12)
    np.testing.assert_allclose(fe / area_force, [0.5, -math.sqrt(3) / 2], atol=1e-12)
    np.testing.assert_allclose(ev[c.results["G_2"]][0], [0.0, -3.1 * 9.81], atol=1e-12)


def test_v_engine_at_its_position():
    scene, loading = v_engine()
    c, ev = solved(scene, loading, np.radians([180.0]))
    ref = solve_global(scene.mechanism, loading, c, ev)
    fa = analyse_forces(c, ev, scene.mechanism, loading)
    doc = fa.json(0)
    forces = doc["forces"]
    assert set(forces) == {"inertia", "reactions", "guide_reactions", "balancing_moment",
                           "zhukovsky_balancing_moment"}
    assert set(forces["reactions"]) == {"01", "12", "23", "24", "45"}
    assert set(forces["guide_reactions"]) == {"03", "05"}
    assert set(forces["inertia"]) == {"2", "3", "5"}
    assert set(doc["reduced"]) == {"moment", "inertia"}
    for key, value in forces["reactions"].items():
        i, j = key
        np.testing.assert_allclose(value, ref.force[(i, j)][0], rtol=1e-9)
    mb = forces["balancing_moment"]
    assert math.isclose(mb, float(ref.balancing[0]), rel_tol=1e-9)
    assert math.isclose(forces["zhukovsky_balancing_moment"], mb, rel_tol=1e-9)
    # at the dead centre of C (v_C = 0) the gas force on C does no work: M_red from E and weights
    assert math.isclose(mb, -527.994, rel_tol=1e-6)
    json.dumps(doc, allow_nan=False)


def test_v_engine_over_the_cycle():
    scene, loading = v_engine()
    phi = np.radians(np.arange(0.0, 360.0, 5.0))
    c, ev = solved(scene, loading, phi)
    fa = analyse_forces(c, ev, scene.mechanism, loading)
    assert np.isfinite(fa.balancing_moment).all()
    assert np.abs(fa.difference_percent).max() < 1e-7
    json.dumps([fa.json(i) for i in range(phi.size)], allow_nan=False)


def test_only_the_asked_force_steps_are_evaluated():
    scene, loading = v_engine()
    c, _ = solved(scene, loading)
    ev = c.evaluate(np.radians([180.0]))
    ev.get(c.results["R_05"])
    assert c.results["R_12"] not in ev.values
    assert not any(sid.startswith("force.I(0,1)") for sid in ev.values)


def test_no_loading_no_force_plan():
    scene, _ = v_engine()
    c = build_construction(scene.mechanism, analyse(scene.mechanism), ALL_PLANS,
                           scene.assembly_phi, scene.path, None)
    assert not any(s.plan.value == "force" for s in c)


def test_loads_of_a_moving_guide_carrier_reach_earlier_links():
    """A guide reaction with its couple passes from the shaper's ram group to the coulisse."""
    scene = scene_of("shaper")
    loading = Loading(loads=(LoadSpec(LoadKind.FORCE, "5", "C", vector=(-800.0, 0.0)),))
    c, ev = solved(scene, loading)
    ref = solve_global(scene.mechanism, loading, c, ev)
    for (i, j), f in ref.force.items():
        np.testing.assert_allclose(ev[c.results[f"R_{pair_key(i, j)}"]], f, rtol=0,
                                   atol=1e-9 * np.abs(f).max())
    assert GROUND in {i for i, _ in ref.force}


def test_balancing_force_is_equivalent_to_the_balancing_moment():
    scene, loading = v_engine()
    c, ev = solved(scene, loading, np.radians([30.0, 180.0, 250.0]))
    mb = ev[c.results["M_b"]]
    r = ev["pos.B"] - ev["pos.A"]
    for angle in (None, math.radians(10.0)):
        fb = balancing_force(c, ev, scene.mechanism, "B", angle)
        np.testing.assert_allclose(r[:, 0] * fb[:, 1] - r[:, 1] * fb[:, 0], mb, rtol=1e-12)
    fb = balancing_force(c, ev, scene.mechanism, "B")
    np.testing.assert_allclose(np.sum(fb * r, axis=1), 0.0, atol=1e-9)
    np.testing.assert_allclose(np.hypot(*fb.T), np.abs(mb) / 0.08, rtol=1e-12)
    with pytest.raises(ValueError):
        balancing_force(c, ev, scene.mechanism, "A")
