"""The follower's dynamics against independent computations: the jump speed of a harmonic (cosine)
law with a spring in closed form, of a cycloidal law and of a damped follower by scipy's root
finding on a contact force written here; the cam torque by virtual power with finite differences
of s(φ) written here; the chosen spring is the least that holds (the jump speed equals the top
speed)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from mechplan.errors import SceneError
from mechplan.studies.cam import solve_cam

H = 0.010
BETA = math.radians(80)
BETA_RET = math.radians(60)


def scene(law: str = "cosine", dynamics: str = "", follower: str = "flat",
          motion: str = "translating") -> str:
    foll = {"flat": 'contact = "flat"\noffset = "0 mm"',
            "roller": 'contact = "roller"\noffset = "0 mm"\nroller_radius = "5 mm"'}[follower]
    lim = 'base_radius = "60 mm"' if follower == "flat" else 'pressure_angle_rise = "30 deg"'
    return f"""kind = "cam"
title = "t"
[follower]
motion = "{motion}"
{foll}
[motion]
stroke = "10 mm"
speed = "1000 rpm"
phases = [
    {{ kind = "rise", angle = "80 deg", law = "{law}" }},
    {{ kind = "far_dwell", angle = "20 deg" }},
    {{ kind = "return", angle = "60 deg", law = "{law}" }},
    {{ kind = "near_dwell", angle = "200 deg" }},
]
[limits]
{lim}
[dynamics]
{dynamics}
"""


def dyn(text: str):
    return solve_cam(text, "c.toml").design.dynamics


def test_harmonic_jump_speed_closed_form():
    """Cosine law: N = m·ω²·s″ + k·s + F0 is least where the deceleration is largest, at the far
    position (s = h, s″ = −(h/2)(π/β)²) of the shorter phase: ω_j² = (k·h + F0)/(m·(h/2)(π/β)²)."""
    m, k, f0 = 0.3, 8000.0, 40.0
    r = dyn(scene(dynamics=f'mass = "{m} kg"\nstiffness = "{k} N/m"\npreload = "{f0} N"'))
    expected = math.sqrt((k * H + f0) / (m * H / 2 * (math.pi / BETA_RET) ** 2))
    assert r.jump_speed == pytest.approx(expected, rel=1e-9)
    assert not r.chosen


def _cycloid(x):
    s = H * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    s1 = H * (1 - np.cos(2 * np.pi * x))                # ds/dx
    s2 = H * 2 * np.pi * np.sin(2 * np.pi * x)          # d²s/dx²
    return s, s1, s2


def _least_contact(omega, m, k, f0, c, beta, ret):
    """min over the phase of N(x) for the cycloidal rise (ret False) or return (ret True)."""
    def n(x):
        s, s1, s2 = _cycloid(x)
        if ret:
            s, s1, s2 = H - s, -s1, -s2
        return (m * omega ** 2 * s2 / beta ** 2 + c * omega * s1 / beta + k * s + f0)
    best = min((minimize_scalar(n, bounds=(a, a + 0.25), method="bounded",
                                options={"xatol": 1e-13}) for a in (0.0, 0.25, 0.5, 0.75)),
               key=lambda r: r.fun)
    return best.fun


@pytest.mark.parametrize("c", [0.0, 15.0])
def test_cycloidal_jump_speed_by_root_finding(c):
    m, k, f0 = 0.3, 8000.0, 40.0
    r = dyn(scene("cycloidal", f'mass = "{m} kg"\nstiffness = "{k} N/m"\npreload = "{f0} N"\n'
                               f'damping = "{c} N*s/m"'))
    roots = []
    for beta, ret in ((BETA, False), (BETA_RET, True)):
        g = (lambda w, beta=beta, ret=ret: _least_contact(w, m, k, f0, c, beta, ret))
        roots.append(brentq(g, 1.0, 5000.0, xtol=1e-12))
    assert r.jump_speed == pytest.approx(min(roots), rel=1e-7)


def test_cam_torque_by_virtual_power():
    """T·ω = N·v: T(φ) = N(φ)·ds/dφ with ds/dφ by central differences of the cosine law."""
    m, k, f0, c = 0.3, 8000.0, 40.0, 10.0
    r = dyn(scene(dynamics=f'mass = "{m} kg"\nstiffness = "{k} N/m"\npreload = "{f0} N"\n'
                           f'damping = "{c} N*s/m"'))
    w = 1000 * math.pi / 30

    def s_of(phi):
        phi = np.mod(phi, 2 * math.pi)
        rise = H / 2 * (1 - np.cos(math.pi * phi / BETA))
        t0 = BETA + math.radians(20)
        ret = H / 2 * (1 + np.cos(math.pi * (phi - t0) / BETA_RET))
        return np.where(phi < BETA, rise, np.where(phi < t0, H, np.where(
            phi < t0 + BETA_RET, ret, 0.0)))

    phi = r.phi[::97]
    d = 1e-6
    v = (s_of(phi + d) - s_of(phi - d)) / (2 * d)
    a = (s_of(phi + d) - 2 * s_of(phi) + s_of(phi - d)) / d ** 2
    n = m * w ** 2 * a + c * w * v + k * s_of(phi) + f0
    torque = r.torque[::97]
    inside = np.abs(np.diff(np.sign(a), prepend=0)) < 2       # away from acceleration jumps
    assert np.allclose(torque[inside], (n * v)[inside], rtol=1e-4, atol=1e-4)
    # work over a turn: the damper's loss only (the spring and the mass give back what they take)
    assert r.torque_mean * 2 * math.pi == pytest.approx(
        c * w * np.trapezoid(np.gradient(s_of(r.phi), r.phi) ** 2, r.phi), rel=1e-3)


def test_chosen_spring_is_just_enough():
    r = dyn(scene("cycloidal", 'mass = "0.3 kg"\nspeed_max = "1800 rpm"\nmargin = "10 N"'))
    assert r.chosen and r.stiffness > 0
    w_max = 1800 * math.pi / 30
    assert r.contact_max_speed.min() == pytest.approx(10.0, rel=1e-6)
    assert r.preload == pytest.approx(10.0, rel=1e-9)        # at rest: the margin alone
    # the spring holds up to the top speed and not beyond (with the margin kept: above it)
    assert r.jump_speed > w_max
    bare = dyn(scene("cycloidal", f'mass = "0.3 kg"\nstiffness = "{r.stiffness} N/m"\n'
                                  f'preload = "{r.preload - 10.0 + 1e-9} N"\nload = "0 N"'))
    assert bare.jump_speed < r.jump_speed


def test_spring_with_given_stiffness_gets_the_least_preload():
    r = dyn(scene("cosine", 'mass = "0.3 kg"\nstiffness = "2000 N/m"\nspeed_max = "1500 rpm"'))
    assert r.jump_speed == pytest.approx(1500 * math.pi / 30, rel=1e-7)
    w = 1500 * math.pi / 30
    need = 0.3 * w ** 2 * H / 2 * (math.pi / BETA_RET) ** 2
    assert r.preload == pytest.approx(need - 2000 * H, rel=1e-6)


def test_roller_normal_force_is_the_contact_over_cos_alpha():
    st = solve_cam(scene("cycloidal", 'mass = "0.3 kg"\nstiffness = "5 N/mm"\npreload = "30 N"',
                         follower="roller"), "c.toml")
    r = st.design.dynamics
    alpha = st.design.dense.alpha
    assert np.allclose(r.normal, r.contact / np.cos(alpha))
    assert "Jump speed" in st.report("en")
    assert st.to_json()["dynamics"]["jump_speed"] == pytest.approx(r.jump_speed)


@pytest.mark.parametrize("body, key", [
    ('stiffness = "5 N/mm"', "dynamics.mass"),
    ('mass = "0.3 kg"\ninertia = "1 kg*m^2"', "dynamics.inertia"),
    ('mass = "0.3 kg"\nspeed_max = "10 rpm"', "dynamics.speed_max"),
    ('mass = "0.3 kg"\nstiffness = "5 N"', "dynamics.stiffness"),
    ('mass = "0.3 kg"\npreload = "0 N"\nspeed_max = "3000 rpm"\nmargin = "5 N"',
     "dynamics.preload"),
])
def test_errors_name_the_key(body, key):
    with pytest.raises(SceneError) as err:
        solve_cam(scene(dynamics=body), "c.toml")
    assert err.value.key == key and err.value.file == "c.toml"
