"""Cylinder- and slider-driven mechanisms against loop-closure equations solved by scipy.

Golden values: for each driver coordinate q(t) = q0 + q̇·t + q̈·t²/2 the loop-closure equations
are solved by a root-finder (scipy.optimize.brentq) independently of the construction; velocities
and accelerations are central finite differences in t of those positions.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.scene.loader import load_scene
from mechplan.solve import solve

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"
H = 1e-4  # s, finite-difference step


def _fd(f, t0=0.0):
    """Value, first and second derivative of f at t0 (central differences)."""
    fm, f0, fp = np.asarray(f(t0 - H)), np.asarray(f(t0)), np.asarray(f(t0 + H))
    return f0, (fp - fm) / (2 * H), (fp - 2 * f0 + fm) / (H * H)


def _boom_truth(l0: float, ldot: float, lddot: float):
    """Boom angle θ2 with |O + 1.5 e(θ2) − A| = l, B above the line AO (the scene's assembly)."""
    o, a, r = np.array([0.0, 0.0]), np.array([0.6, -0.4]), 1.5

    def theta(t):
        length = l0 + ldot * t + lddot * t * t / 2

        def gap(th):
            b = o + r * np.array([math.cos(th), math.sin(th)])
            return float(np.hypot(*(b - a)) - length)
        # the boom points up from O: θ2 in (0, π) where the distance grows with θ2 from AO's side
        return brentq(gap, math.atan2(-0.4, 0.6) + 1e-9, math.pi - 1e-9, xtol=1e-15)

    def points(t):
        th = theta(t)
        b = o + r * np.array([math.cos(th), math.sin(th)])
        c, s = math.cos(th), math.sin(th)
        d = o + np.array([c * 4.0 - s * 0.6, s * 4.0 + c * 0.6])
        th3 = math.atan2(*(b - a)[::-1])
        return np.concatenate([b, d, [th, th3]])
    return points


@pytest.mark.parametrize("k", range(5))
def test_cylinder_boom_positions_velocities_accelerations(k):
    scene = load_scene(TEMPLATES / "excavator_boom.toml")
    sol = solve(scene)
    c, ev = sol.construction, sol.ev
    drive = scene.mechanism.drive
    l0 = float(sol.phi[k])
    x, v, acc = _fd(_boom_truth(l0, drive.omega, drive.epsilon))
    assert np.allclose(ev[c.position("B")][k], x[0:2], atol=1e-12)
    assert np.allclose(ev[c.position("D")][k], x[2:4], atol=1e-12)
    assert np.allclose(ev[c.velocity_image("B")][k], v[0:2], rtol=1e-6, atol=1e-8)
    assert np.allclose(ev[c.velocity_image("D")][k], v[2:4], rtol=1e-6, atol=1e-8)
    assert ev[c.omega("2")][k] == pytest.approx(v[4], rel=1e-6)
    assert ev[c.omega("3")][k] == pytest.approx(v[5], rel=1e-6)
    assert ev[c.omega("4")][k] == pytest.approx(v[5], rel=1e-6)
    assert np.allclose(ev[c.acceleration_image("B")][k], acc[0:2], rtol=1e-4, atol=1e-6)
    assert np.allclose(ev[c.acceleration_image("D")][k], acc[2:4], rtol=1e-4, atol=1e-6)
    assert ev[c.epsilon("2")][k] == pytest.approx(acc[4], rel=1e-4, abs=1e-6)
    assert ev[c.epsilon("3")][k] == pytest.approx(acc[5], rel=1e-4, abs=1e-6)


def test_cylinder_length_is_the_driver_coordinate():
    scene = load_scene(TEMPLATES / "excavator_boom.toml")
    sol = solve(scene)
    c, ev = sol.construction, sol.ev
    ab = np.hypot(*(ev[c.position("B")] - ev[c.position("A")]).T)
    assert np.allclose(ab, sol.phi, atol=1e-14)
    assert np.allclose(sol.phi, np.linspace(1.45, 1.9, 5))
    assert sol.structure.formula == "I(3,4) → II(2,3)"


def _coulisse_truth(s0: float, sdot: float, sddot: float):
    o3 = np.array([0.1, -0.3])

    def points(t):
        s = s0 + sdot * t + sddot * t * t / 2
        b = np.array([s, 0.0])
        th = math.atan2(*(b - o3)[::-1])
        e = o3 + 0.5 * np.array([math.cos(th), math.sin(th)])
        return np.concatenate([b, e, [th]])
    return points


@pytest.mark.parametrize("k", range(6))
def test_slider_driven_coulisse(k):
    scene = load_scene(TEMPLATES / "slider_coulisse.toml")
    sol = solve(scene)
    c, ev = sol.construction, sol.ev
    drive = scene.mechanism.drive
    assert (drive.omega, drive.epsilon) == (1.0, 2.5)
    x, v, acc = _fd(_coulisse_truth(float(sol.phi[k]), drive.omega, drive.epsilon))
    assert np.allclose(ev[c.position("E")][k], x[2:4], atol=1e-12)
    assert np.allclose(ev[c.velocity_image("B")][k], v[0:2], rtol=1e-7, atol=1e-9)
    assert np.allclose(ev[c.velocity_image("E")][k], v[2:4], rtol=1e-6, atol=1e-6)
    assert ev[c.omega("3")][k] == pytest.approx(v[4], rel=1e-6)
    assert np.allclose(ev[c.acceleration_image("E")][k], acc[2:4], rtol=1e-4, atol=1e-5)
    assert ev[c.epsilon("3")][k] == pytest.approx(acc[4], rel=1e-4, abs=1e-5)


# -- the fused kernel and the error estimates -----------------------------------------------------
KINEMATIC = ("position", "velocity", "acceleration")


def _sweep(scene, n=181):
    lo, hi = scene.mechanism.drive.q_range
    return np.linspace(lo, hi, n)


@pytest.mark.parametrize("stem", ["excavator_boom", "slider_coulisse"])
def test_kernel_equals_the_numpy_path_and_estimates_are_tiny(stem):
    from mechplan.construct.estimate import estimate_errors
    from mechplan.construct.kernel import compile_kernel
    from mechplan.solve import build, targets_for

    scene = load_scene(TEMPLATES / f"{stem}.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    q = _sweep(scene)
    ev = c.evaluate(q)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    values, rel, bad = compile_kernel(c, targets, jit=False)(q)
    assert not bad.any()
    for sid in targets:
        # within a few roundings of the value's size: math.atan2 in the loop and np.arctan2
        # outside it may differ in the last bit, and what is built on an angle inherits that
        size = max(float(np.max(np.abs(ev[sid]))), est.scale[sid])
        assert np.max(np.abs(values[sid] - ev[sid])) <= 4e-16 * size * 4, sid
        assert np.allclose(rel[sid], est.relative(sid), rtol=1e-5, atol=0), sid
    # measured against the driver's rate (|q̇|, |q̈| + q̇²/L): the boom's tip moves ~8× faster
    # than the rod, so the bound is looser than a crank template's 1e-12
    assert max(float(np.max(est.relative(sid))) for sid in targets) < 1e-11


def test_numba_kernel_handles_the_cylinder(tmp_path, monkeypatch):
    pytest.importorskip("numba", reason="the fast extra (numba) is optional")
    from mechplan.construct.kernel import compile_kernel
    from mechplan.solve import build, targets_for

    monkeypatch.setenv("MECHPLAN_CACHE", str(tmp_path))
    scene = load_scene(TEMPLATES / "excavator_boom.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    q = _sweep(scene, 50)
    ev = c.evaluate(q)
    values, _rel, bad = compile_kernel(c, targets, jit=True)(q)
    assert not bad.any()
    for sid in targets:
        assert np.allclose(values[sid], ev[sid], rtol=1e-14, atol=1e-14), sid


# -- what cannot be built is said, never returned -------------------------------------------------
def test_a_cylinder_too_short_to_reach_is_refused_naming_the_group():
    from mechplan.errors import UnreachableError

    scene = load_scene(TEMPLATES / "excavator_boom.toml")
    # |OA| = 0.721 m and |OB| = 1.5 m: the cylinder must be at least 0.779 m long
    with pytest.raises(UnreachableError, match=r"II\(2,3\)"):
        solve(scene, at_deg=[700.0])
    ok = solve(scene, at_deg=[800.0])
    assert ok.positions == 1


@pytest.mark.parametrize("d", [1e-3, 1e-6, 1e-9, 1e-12])
def test_near_the_stretched_toggle_the_estimate_bounds_the_true_error(d):
    """ω2 → ∞ as the cylinder nears its full reach |OA| + |OB|: each value is checked against a
    60-digit closed form, and its estimated error must cover the true one (never silently wrong)."""
    import mpmath as mp

    from mechplan.errors import SingularError, UnreachableError

    mp.mp.dps = 60
    scene = load_scene(TEMPLATES / "excavator_boom.toml")
    oa, r = mp.sqrt(mp.mpf(0.6) ** 2 + mp.mpf(0.4) ** 2), mp.mpf("1.5")
    length_mm = 1000 * (float(oa + r) - d)
    try:
        sol = solve(scene, at_deg=[length_mm], plans=KINEMATIC)
    except SingularError as exc:           # too close to tell: refused, and said where
        assert d <= 1e-9 and "the driver's coordinate" in str(exc) and "mm" in str(exc)
        return
    c = sol.construction
    length = mp.mpf(float(sol.phi[0]))      # the length the construction was given, exactly
    # B by the law of cosines in triangle OAB, on the side the scene assembles it (θ2 > θ_OA)
    gamma = mp.acos((oa ** 2 + r ** 2 - length ** 2) / (2 * oa * r))
    theta = mp.atan2(mp.mpf(-0.4), mp.mpf(0.6)) + gamma
    b = mp.matrix([r * mp.cos(theta), r * mp.sin(theta)])
    ba = b - mp.matrix([mp.mpf(0.6), mp.mpf(-0.4)])
    # d|AB|/dθ2 = (B − A)·(r e⊥)/l, so ω2 = l̇·l / ((B − A)·(−r sin θ, r cos θ))
    rate = ba[0] * (-r * mp.sin(theta)) + ba[1] * (r * mp.cos(theta))
    omega = mp.mpf(scene.mechanism.drive.omega) * length / rate
    got = float(sol.ev[c.omega("2")][0])
    true_error = abs(mp.mpf(got) - omega) / abs(omega)
    estimate = float(sol.estimate.relative(c.omega("2"))[0])
    assert true_error <= max(estimate, 1e-15), (true_error, estimate)
    assert abs(got) > 1.0 / math.sqrt(d) * 0.05           # it does grow without bound
    with pytest.raises(UnreachableError, match=r"II\(2,3\)"):
        solve(scene, at_deg=[1000 * (float(oa + r) + 0.01)], plans=KINEMATIC)


def test_a_cylinder_mounted_the_other_way_moves_the_boom_alike():
    """Barrel pinned to the boom at B, rod to the frame at A: the same length law moves the boom
    exactly as the template's cylinder (barrel on the frame) does; the barrel's own point C, now
    at 1.2 m from B towards A, follows the finite differences of its position."""
    from mechplan.scene import parse_scene

    text = (TEMPLATES / "excavator_boom.toml").read_text(encoding="utf-8")
    flipped = text.replace(
        'points = { A = ["0 mm", "0 mm"], C = ["1200 mm", "0 mm"] }\n'
        'guides.bore = { through = "A", toward = "C" }',
        'points = { B = ["0 mm", "0 mm"], C = ["1200 mm", "0 mm"] }\n'
        'guides.bore = { through = "B", toward = "C" }').replace(
        'slides = { point = "B", on = "bore" }', 'slides = { point = "A", on = "bore" }')
    assert flipped != text
    a, b = solve(load_scene(TEMPLATES / "excavator_boom.toml")), solve(parse_scene(flipped, "f"))
    assert b.structure.formula == "I(3,4) → II(2,3)"
    for of, key in (("position", "D"), ("velocity_image", "D"), ("acceleration_image", "D"),
                    ("omega", "2"), ("epsilon", "2"), ("omega", "3"), ("epsilon", "3")):
        assert np.allclose(b.ev[getattr(b.construction, of)(key)],
                           a.ev[getattr(a.construction, of)(key)], rtol=1e-13, atol=1e-14)
    drive = b.scene.mechanism.drive
    for k in range(b.positions):
        truth = _boom_truth(float(b.phi[k]), drive.omega, drive.epsilon)

        def c_point(t, truth=truth):
            x = truth(t)
            bb, aa = x[0:2], np.array([0.6, -0.4])
            return bb + 1.2 * (aa - bb) / np.hypot(*(aa - bb))
        x, v, acc = _fd(c_point)
        c = b.construction
        assert np.allclose(b.ev[c.position("C")][k], x, atol=1e-12)
        assert np.allclose(b.ev[c.velocity_image("C")][k], v, rtol=1e-6, atol=1e-8)
        assert np.allclose(b.ev[c.acceleration_image("C")][k], acc, rtol=1e-4, atol=1e-6)


def test_the_api_takes_a_linear_drivers_positions_in_mm():
    from mechplan import api

    m = api.load(TEMPLATES / "excavator_boom.toml")
    every = m.solve()                               # with its masses: the force plan too
    assert np.allclose(every.phi_deg, [1450, 1562.5, 1675, 1787.5, 1900])
    one = m.solve(1562.5)                           # the quick path at one position
    two = m.solve([1562.5], plans=["position", "velocity"])
    assert one.phi_deg[0] == two.phi_deg[0] == 1562.5
    assert one.omega["2"][0] == pytest.approx(every.omega["2"][1], rel=1e-14)
    assert two.omega["2"][0] == pytest.approx(every.omega["2"][1], rel=1e-14)
    sol = solve(load_scene(TEMPLATES / "excavator_boom.toml"))
    assert np.allclose(every.forces.M_b, sol.ev[sol.construction.driving_force()], rtol=1e-14)
