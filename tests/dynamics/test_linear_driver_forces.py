"""The driving force of a cylinder and of a driving slider against virtual power.

Golden values: the positions of the centres of mass and the links' angles come from the loop
closure solved by scipy (tests/construct/test_linear_drivers.py), their velocities and
accelerations from central finite differences; then F_d·q̇ + Σ(G·v_S − m·a_S·v_S − J_S·ε·ω) = 0
gives F_d with no use of the construction. The force polygons and Zhukovsky's lever must both
give it.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.dynamics.loading import Loading
from mechplan.scene import parse_scene
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "construct"))
from test_linear_drivers import _boom_truth, _coulisse_truth, _fd

TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"
G = 9.81
FORCE_PLANS = ("position", "velocity", "acceleration", "force")


def _solve(text):
    if "[gravity]" not in text:
        text = text.replace("[drive]", '[gravity]\ng = "9.81 m/s^2"\n\n[drive]')
    scene = parse_scene(text, "scene.toml")
    assert scene.gravity.enabled and scene.gravity.g == G
    return scene, solve(scene, plans=FORCE_PLANS, loading=Loading.from_scene(scene))


def test_cylinder_driving_force_is_the_virtual_power_of_the_loads():
    # the template: boom 800 kg at D with J = 900 kg·m², barrel 60 kg at C, gravity
    text = (TEMPLATES / "excavator_boom.toml").read_text(encoding="utf-8")
    scene, sol = _solve(text)
    assert {k: (m.mass, m.inertia) for k, m in scene.masses.items()} == {
        "2": (800.0, 900.0), "3": (60.0, 0.0)}
    c, drive = sol.construction, scene.mechanism.drive
    fd, fz = sol.ev[c.driving_force()], sol.ev[c.zhukovsky_force()]
    for k in range(sol.positions):
        truth = _boom_truth(float(sol.phi[k]), drive.omega, drive.epsilon)

        def centres(t, truth=truth):
            x = truth(t)
            b, a = x[0:2], np.array([0.6, -0.4])
            cpt = a + 1.2 * (b - a) / np.hypot(*(b - a))
            return np.concatenate([x[2:4], cpt, x[4:5]])      # D, C, θ2
        _x, v, acc = _fd(centres)
        power = (-800 * G * v[1] - 800 * acc[0:2] @ v[0:2] - 900 * acc[4] * v[4]
                 - 60 * G * v[3] - 60 * acc[2:4] @ v[2:4])
        expected = -power / drive.omega
        assert fd[k] == pytest.approx(expected, rel=1e-6)
        assert fz[k] == pytest.approx(float(fd[k]), rel=1e-9)     # the lever agrees
    assert np.all(fd > 0)                    # the cylinder pushes the boom up
    doc = sol.extras["forces"].json(0)["forces"]
    assert doc["driving_force"] == pytest.approx(float(fd[0]))
    assert "balancing_moment" not in doc and set(doc["guide_reactions"]) == {"34"}


def test_slider_driving_force_is_the_virtual_power_of_the_loads():
    text = (TEMPLATES / "slider_coulisse.toml").read_text(encoding="utf-8")
    text = text.replace('name = "slider block"\n',
                        'name = "slider block"\nmass = "5 kg"\ncentre = "B"\n')
    text = text.replace('name = "slotted link"\n',
                        'name = "slotted link"\nmass = "20 kg"\nJ = "1.5 kg m^2"\n'
                        'centre = "E"\n')
    scene, sol = _solve(text)
    c, drive = sol.construction, scene.mechanism.drive
    fd, fz = sol.ev[c.driving_force()], sol.ev[c.zhukovsky_force()]
    for k in range(sol.positions):
        _x, v, acc = _fd(_coulisse_truth(float(sol.phi[k]), drive.omega, drive.epsilon))
        power = (-5 * acc[0:2] @ v[0:2] - 5 * G * v[1]
                 - 20 * G * v[3] - 20 * acc[2:4] @ v[2:4] - 1.5 * acc[4] * v[4])
        expected = -power / drive.omega
        # the powers (~200 W) nearly cancel at some positions: the finite differences' error
        # (~1e-8 of each term) sets the absolute tolerance
        assert fd[k] == pytest.approx(expected, rel=1e-6, abs=1e-4)
        assert fz[k] == pytest.approx(float(fd[k]), rel=1e-9, abs=1e-9)
    # the frame's reaction on the block is ⊥ its guide: the driving force takes the rest
    r = sol.ev[c.reaction("0", "1")]
    assert np.allclose(r[:, 0], 0.0, atol=1e-9)
