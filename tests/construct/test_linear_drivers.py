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


@pytest.mark.parametrize("k", range(5))
def test_slider_driven_coulisse(k):
    scene = load_scene(TEMPLATES / "slider_coulisse.toml")
    sol = solve(scene)
    c, ev = sol.construction, sol.ev
    drive = scene.mechanism.drive
    assert (drive.omega, drive.epsilon) == (1.0, 2.5)
    x, v, acc = _fd(_coulisse_truth(float(sol.phi[k]), drive.omega, drive.epsilon))
    assert np.allclose(ev[c.position("E")][k], x[2:4], atol=1e-12)
    assert np.allclose(ev[c.velocity_image("B")][k], v[0:2], rtol=1e-7, atol=1e-9)
    assert np.allclose(ev[c.velocity_image("E")][k], v[2:4], rtol=1e-6, atol=1e-8)
    assert ev[c.omega("3")][k] == pytest.approx(v[4], rel=1e-6)
    assert np.allclose(ev[c.acceleration_image("E")][k], acc[2:4], rtol=1e-4, atol=1e-5)
    assert ev[c.epsilon("3")][k] == pytest.approx(acc[4], rel=1e-4, abs=1e-5)
