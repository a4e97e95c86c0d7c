"""Centrodes, acceleration poles and inflection circles against finite differences of positions."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.construct.centre_kinematics import link_origin
from mechplan.geom.vec import cross, rotate
from mechplan.scene import parse_scene
from mechplan.solve import solve
from mechplan.studies.centres import analyse_centres
from tests.scenes import ROOT

ASK = '\n[centres]\nlinks = ["2"]\ninflection = true\npositions = 3600\n'


def _template(name):
    """A template's text without its own [centres] table."""
    text = (ROOT / "templates" / f"{name}.toml").read_text(encoding="utf-8")
    return text[:text.index("[centres]")] if "[centres]" in text else text


def _scene(name):
    return parse_scene(_template(name) + ASK)


def _tracker(sol, link, dtheta):
    """World position of material points of a link (given in the world at the solution's first
    position) at crank angles θ0 − δ, θ0, θ0 + δ, and the time step of δ."""
    c, mech = sol.construction, sol.scene.mechanism
    theta0 = float(c.drive.absolute(sol.phi[:1])[0])
    ev = c.evaluate(c.drive.scene(theta0 + np.array([-dtheta, 0.0, dtheta])))
    angle = ev[c.link_angle(link)]
    origin = link_origin(mech, link, lambda p: ev[c.position(p)], angle)

    def track(world0):
        local = rotate(world0 - origin[1], -angle[1])
        return origin + rotate(np.broadcast_to(local, (3, 2)), angle)

    dt = dtheta / abs(mech.drive.omega)
    return track, dt


def _fd(x, dt):
    return (x[2] - x[0]) / (2 * dt), (x[2] - 2 * x[1] + x[0]) / dt ** 2


@pytest.mark.parametrize("name", ["four_bar", "slider_crank", "quick_return"])
@pytest.mark.parametrize("phi", [20.0, 100.0, 250.0])
def test_acceleration_pole_is_the_point_with_no_acceleration(name, phi):
    sol = solve(_scene(name), at_deg=[phi], scales=False)
    an = analyse_centres(sol)
    q = an.poles["2"][0]
    track, dt = _tracker(sol, "2", 1e-3)
    w = abs(sol.scene.mechanism.drive.omega)
    scale = w * w * 0.1                      # ω1²·(a length of the mechanism)
    _, a_q = _fd(track(q), dt)
    assert np.hypot(*a_q) < 1e-4 * scale
    _, a_off = _fd(track(q + np.array([0.05, 0.0])), dt)
    assert np.hypot(*a_off) > 1e-3 * scale   # a point beside it does accelerate


@pytest.mark.parametrize("name", ["four_bar", "slider_crank"])
@pytest.mark.parametrize("phi", [30.0, 140.0, 290.0])
def test_points_of_the_inflection_circle_move_without_curvature(name, phi):
    sol = solve(_scene(name), at_deg=[phi], scales=False)
    an = analyse_centres(sol)
    centre, radius, pole_j = (x[0] for x in an.inflection["2"])
    p = an.centres.point("0", "2")[0]
    track, dt = _tracker(sol, "2", 1e-4)
    base = math.atan2(*(p - centre)[::-1])
    for turn in (math.pi / 2, math.pi, 3 * math.pi / 2):
        x = centre + radius * np.array([math.cos(base + turn), math.sin(base + turn)])
        v, a = _fd(track(x), dt)
        kappa = cross(v, a) / np.hypot(*v) ** 3
        assert abs(kappa) * radius < 1e-4, (turn, kappa)
    # the inflection pole J is on the circle, opposite P
    np.testing.assert_allclose(pole_j, 2 * centre - p, atol=1e-12)
    # the centre of the circle is not on it: by the Euler–Savary relation (κ = (ρ − D·cos ψ)/ρ²,
    # ρ = R, D = 2R, ψ = 0) its path curves with κ = −1/R (the sign: seen from the pole)
    v, a = _fd(track(centre), dt)
    assert abs(abs(cross(v, a) / np.hypot(*v) ** 3) * radius - 1.0) < 1e-3


def test_the_moving_centrode_rolls_on_the_fixed_one_without_slipping():
    sol = solve(_scene("four_bar"), at_deg=[0.0], scales=False)
    phi, fixed, moving = analyse_centres(sol).centrodes["2"]
    assert len(phi) == 3600
    ok = np.all(np.isfinite(fixed), axis=1) & (np.hypot(*fixed.T) < 2.0)
    # a stretch of consecutive finite, bounded samples
    runs = np.split(np.arange(len(phi)), np.where(~ok)[0])
    run = max((r[1:] if len(r) and not ok[r[0]] else r for r in runs), key=len)
    assert len(run) > 500
    s_fixed = np.sum(np.hypot(*np.diff(fixed[run], axis=0).T))
    s_moving = np.sum(np.hypot(*np.diff(moving[run], axis=0).T))
    assert s_fixed > 0.05
    assert s_moving == pytest.approx(s_fixed, rel=1e-3)


def test_a_link_pinned_to_the_frame_has_a_point_centrode():
    sol = solve(parse_scene(_template("four_bar") + '\n[centres]\nlinks = ["3"]\npositions = 36\n'),
                at_deg=[10.0], scales=False)
    _, fixed, moving = analyse_centres(sol).centrodes["3"]
    d = np.array(sol.scene.mechanism.links["0"].points["D"])
    np.testing.assert_allclose(fixed, np.broadcast_to(d, fixed.shape), atol=1e-15)
    np.testing.assert_allclose(moving, 0.0, atol=1e-15)
