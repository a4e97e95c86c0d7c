"""Reduced moment of forces and reduced moment of inertia against independent truths."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from independent import closed_form

from mechplan.construct.builder import build_construction
from mechplan.dynamics import Loading, reduced_inertia, reduced_moment
from mechplan.dynamics.reduced import reduced_of
from mechplan.model.loads import Gravity
from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene

from .dyad_scenes import CYCLE, PINNED_SLIDERS, SCOTCH_YOKE

ROOT = Path(__file__).resolve().parents[2]
PLANS = ("position", "velocity", "acceleration", "force")


def solved(scene, loading, phi):
    c = build_construction(scene.mechanism, analyse(scene.mechanism), PLANS, scene.assembly_phi,
                           scene.path, loading)
    return c, c.evaluate(phi)


def test_pure_functions_are_vectorised():
    n = 5
    f = np.tile([[2.0, 3.0]], (n, 1))
    v = np.tile([[1.0, -1.0]], (n, 1))
    m = np.full(n, 4.0)
    w = np.linspace(1.0, 2.0, n)
    w1 = np.full(n, 2.0)
    np.testing.assert_allclose(reduced_moment([f], [v], [m], [w], w1), (-1.0 + 4.0 * w) / 2.0)
    np.testing.assert_allclose(reduced_inertia([3.0], [v], [0.5], [w], w1),
                               (3.0 * 2.0 + 0.5 * w * w) / 4.0)
    assert reduced_moment([], [], [], [], w1).shape == (n,)


def test_slider_crank_reduced_inertia_closed_form():
    scene = load_scene(ROOT / "templates" / "slider_crank.toml")
    loading = Loading.from_scene(scene)
    phi = np.radians(np.arange(0.0, 360.0, 7.5))
    c, ev = solved(scene, loading, phi)
    _, j_red = reduced_of(c, ev, scene.mechanism, loading)
    omega = 1500 * 2 * math.pi / 60
    cf = closed_form.slider_crank(0.1, 0.4, 0.0, omega, phi, 0.0, 0.3)
    v_s2, v_b, w2 = cf["S2"][:, 2:4], cf["B"][:, 2:4], cf["2"][:, 1]
    expected = (4.0 * np.sum(v_s2 ** 2, axis=1) + 0.06 * w2 ** 2 + 3.0 * np.sum(v_b ** 2, axis=1)) \
        / omega ** 2
    np.testing.assert_allclose(j_red, expected, rtol=1e-12)


@pytest.mark.parametrize("text", [SCOTCH_YOKE, PINNED_SLIDERS], ids=["rpp", "prp"])
def test_balancing_moment_of_inertia_is_half_omega_squared_dj_dphi(text):
    """Constant ω1, inertia loads only: M_b·ω1 = dT/dt, so M_b = ½·ω1²·dJ_red/dθ1."""
    scene = parse_scene(text.replace('epsilon = "15 rad/s^2"', ""))
    base = Loading.from_scene(scene)
    loading = Loading(base.masses, (), Gravity(enabled=False))
    h = 1e-5
    c, ev = solved(scene, loading, np.concatenate((CYCLE - h, CYCLE + h, CYCLE)))
    _, j_red = reduced_of(c, ev, scene.mechanism, loading)
    n = CYCLE.size
    sense = scene.mechanism.drive.sense
    dj = sense * (j_red[n:2 * n] - j_red[:n]) / (2 * h)          # d/dθ1 (θ1 counter-clockwise)
    omega1 = scene.mechanism.drive.omega
    mb = ev[c.results["M_b"]][2 * n:]
    np.testing.assert_allclose(mb, 0.5 * omega1 ** 2 * dj, rtol=2e-5,
                               atol=2e-5 * np.abs(mb).max())


def test_reduced_moment_is_minus_balancing_moment_without_masses():
    scene = load_scene(ROOT / "templates" / "v_engine.toml")
    full = Loading.from_scene(scene)
    massless = Loading({}, full.loads, full.gravity)
    c, ev = solved(scene, massless, CYCLE)
    m_red, j_red = reduced_of(c, ev, scene.mechanism, massless)
    np.testing.assert_allclose(m_red, -ev[c.results["M_b"]], rtol=1e-12, atol=1e-9)
    assert np.all(j_red == 0.0)


def test_v_engine_reduced_values_at_its_position():
    scene = load_scene(ROOT / "templates" / "v_engine.toml")
    loading = Loading.from_scene(scene)
    c, ev = solved(scene, loading, np.radians([180.0]))
    m_red, j_red = reduced_of(c, ev, scene.mechanism, loading)
    # independent: powers of the gas forces and weights, kinetic energy of the masses
    omega1 = -800 * 2 * math.pi / 60
    v = {p: ev[c.results[f"v_{p}"]][0] for p in ("S2", "C", "E")}
    w2 = ev[c.results["omega_2"]][0]
    f_c, f_e = ev[c.results["load_0"]][0], ev[c.results["load_1"]][0]
    g = np.array([0.0, -9.81])
    power = f_c @ v["C"] + f_e @ v["E"] + g @ (3.1 * v["S2"] + 2.0 * v["C"] + 2.0 * v["E"])
    assert math.isclose(m_red[0], power / omega1, rel_tol=1e-12)
    energy = 3.1 * v["S2"] @ v["S2"] + 0.1 * w2 ** 2 + 2.0 * v["C"] @ v["C"] + 2.0 * v["E"] @ v["E"]
    assert math.isclose(j_red[0], energy / omega1 ** 2, rel_tol=1e-12)
    assert abs(v["C"]).max() < 1e-12      # bottom dead centre of piston C
