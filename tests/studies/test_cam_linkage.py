"""A four-bar whose crank is a cam's follower lever, against an independent solution: the cam law
written here in closed form, the four-bar closed by two circles, rates by finite differences in
the cam angle; the cam torque by virtual power of the loads and inertia; the contact force by its
moment about the cam's centre."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.scene import parse_scene
from mechplan.scene.cam import parse_cam
from mechplan.studies.cam_linkage import cam_linkage

A, D = np.array([0.0, 0.0]), np.array([0.25, 0.0])
AB, BC, DC = 0.08, 0.26, 0.18
MASS, J2, M3 = 2.0, 0.02, -20.0
SWING = math.radians(20.0)
PHASES = [(120.0, "rise"), (40.0, "far"), (100.0, "return"), (100.0, "near")]


def _cam(sense: str, dynamics: str = "") -> str:
    return f"""kind = "cam"
title = "cam"
[follower]
motion = "oscillating"
contact = "roller"
arm = "100 mm"
pivot_distance = "120 mm"
roller_radius = "8 mm"
[motion]
swing = "20 deg"
speed = "300 rpm"
sense = "{sense}"
phases = [
    {{ kind = "rise", angle = "120 deg", law = "cycloidal" }},
    {{ kind = "far_dwell", angle = "40 deg" }},
    {{ kind = "return", angle = "100 deg", law = "cycloidal" }},
    {{ kind = "near_dwell", angle = "100 deg" }},
]
[limits]
pressure_angle_rise = "45 deg"
pressure_angle_return = "60 deg"
{dynamics}"""


LEVER = f"""title = "lever four-bar"
[ground]
A = ["0 mm", "0 mm"]
D = ["250 mm", "0 mm"]
[links.1]
lengths = {{ AB = "80 mm" }}
[links.2]
lengths = {{ BC = "260 mm" }}
points = {{ S2 = "0.5 of B C" }}
mass = "{MASS} kg"
centre = "S2"
J = "{J2} kg*m^2"
[links.3]
lengths = {{ DC = "180 mm" }}
[drive]
link = "1"
speed = "10 rad/s"
sense = "ccw"
[assembly]
C = "left of B->D"
[[loads]]
type = "torque"
link = "3"
torque = "{M3} N*m"
"""


def _psi(phi: np.ndarray) -> np.ndarray:
    """The cycloidal rise, dwell, cycloidal return, dwell (rad)."""
    deg = np.degrees(np.mod(phi, 2 * math.pi))
    out = np.zeros_like(deg)
    rise = deg < 120
    x = deg[rise] / 120
    out[rise] = SWING * (x - np.sin(2 * math.pi * x) / (2 * math.pi))
    out[(deg >= 120) & (deg < 160)] = SWING
    ret = (deg >= 160) & (deg < 260)
    x = (deg[ret] - 160) / 100
    out[ret] = SWING * (1 - (x - np.sin(2 * math.pi * x) / (2 * math.pi)))
    return out


def _four_bar(theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """B and C of the four-bar with its crank at θ (C left of B → D)."""
    B = A + AB * np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    d = D - B
    L = np.hypot(d[..., 0], d[..., 1])
    a = (BC ** 2 - DC ** 2 + L ** 2) / (2 * L)
    h = np.sqrt(BC ** 2 - a ** 2)
    u = d / L[..., None]
    left = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    return B, B + a[..., None] * u + h[..., None] * left


def _independent(phi: np.ndarray, theta_near: float, sigma: int):
    """θ3, S2 and θ2 at φ (the lever's angle θ = θ_near − σ·ψ)."""
    B, C = _four_bar(theta_near - sigma * _psi(phi))
    theta3 = np.arctan2(C[..., 1] - D[1], C[..., 0] - D[0])
    theta2 = np.arctan2(C[..., 1] - B[..., 1], C[..., 0] - B[..., 0])
    return theta3, (B + C) / 2, theta2


def _fd(f, phi: np.ndarray, h: float = 1e-4):
    """f, f′ and f″ in φ by central differences."""
    fm, f0, fp = f(phi - h), f(phi), f(phi + h)
    return f0, (fp - fm) / (2 * h), (fp - 2 * f0 + fm) / h ** 2


@pytest.mark.parametrize("sense, near_deg", [("cw", 60.0), ("ccw", 100.0)])
def test_plans_and_cam_torque(sense: str, near_deg: float) -> None:
    cam = parse_cam(_cam(sense), "cam.toml")
    sigma = cam.sense
    scene = parse_scene(LEVER, "lever.toml")
    r = cam_linkage(cam, scene, math.radians(near_deg), cam.omega, "lever", "cam", None,
                    "members[1]")
    w = cam.omega
    # away from the phase boundaries (ψ″ jumps nowhere for cycloidal, but finite differences
    # straddling a boundary lose digits)
    deg = np.degrees(r.phi)
    keep = np.all(np.abs(deg[:, None] - np.array([0, 120, 160, 260, 360])) > 0.5, axis=1)
    phi = r.phi[keep]
    th3, th3_1, th3_2 = _fd(lambda p: np.unwrap(_independent(p, math.radians(near_deg),
                                                             sigma)[0]), phi)
    assert r.output == "3" and r.rocker
    assert np.allclose(np.mod(r.out[keep] - th3 + math.pi, 2 * math.pi) - math.pi, 0, atol=1e-12)
    assert np.allclose(r.out_rate[keep], th3_1 * w, rtol=0, atol=1e-6 * np.abs(th3_1 * w).max())
    assert np.allclose(r.out_acc[keep], th3_2 * w * w, rtol=0,
                       atol=2e-5 * np.abs(th3_2 * w * w).max())
    # virtual power: T·ω_cam + M3·ω3 − m·a_S2·v_S2 − J2·ε2·ω2 = 0 (no gravity)
    _, s1, s2 = _fd(lambda p: _independent(p, math.radians(near_deg), sigma)[1], phi)
    _, t2_1, t2_2 = _fd(lambda p: np.unwrap(_independent(p, math.radians(near_deg),
                                                         sigma)[2]), phi)
    power = (MASS * np.einsum("ij,ij->i", s2 * w * w, s1 * w) + J2 * t2_2 * w * w * t2_1 * w
             - M3 * th3_1 * w)
    assert r.torque is not None
    scale = np.abs(power / w).max()
    assert np.allclose(r.torque[keep], power / w, rtol=0, atol=2e-5 * scale)


def test_contact_force_moment_about_the_cam_centre() -> None:
    """T = (B × N·n)·σ with n the pitch curve's outward normal found by finite differences of
    the pitch curve itself; and the follower's own inertia and spring are added by power."""
    dyn = '[dynamics]\ninertia = "0.001 kg*m^2"\nstiffness = "5 N*m/rad"\npreload = "2 N*m"\n'
    cam = parse_cam(_cam("ccw", dyn), "cam.toml")
    scene = parse_scene(LEVER, "lever.toml")
    r = cam_linkage(cam, scene, math.radians(100.0), cam.omega, "lever", "cam", None,
                    "members[1]")
    from mechplan.synthesis.cam import design
    from mechplan.synthesis.cam.profile import sample

    g = design(cam).geometry
    h = 1e-6
    P = lambda p: sample(g, p).pitch          # the pitch curve in the cam frame
    tangent = (P(r.phi + h) - P(r.phi - h)) / (2 * h)
    n_cam = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)     # outward: the curve runs cw
    n_cam /= np.hypot(*n_cam.T)[:, None]
    c, s = np.cos(r.phi), np.sin(r.phi)
    n = np.stack([c * n_cam[:, 0] - s * n_cam[:, 1], s * n_cam[:, 0] + c * n_cam[:, 1]], axis=1)
    B = sample(g, r.phi).follower
    assert r.contact is not None and r.torque is not None
    moment = r.contact * (B[:, 0] * n[:, 1] - B[:, 1] * n[:, 0])
    assert np.allclose(r.torque, moment, rtol=0, atol=1e-6 * np.abs(r.torque).max())
    # the follower's own terms: Q_f = J·ω²·ψ″ + k·ψ + F0, its power Q_f·ψ′ in the torque
    bare = cam_linkage(parse_cam(_cam("ccw"), "cam.toml"), scene, math.radians(100.0),
                       cam.omega, "lever", "cam", None, "members[1]")
    psi = _psi(r.phi)
    _, p1, p2 = _fd(_psi, r.phi, 1e-5)
    q_f = 0.001 * cam.omega ** 2 * p2 + 5.0 * psi + 2.0
    deg = np.degrees(r.phi)
    keep = np.all(np.abs(deg[:, None] - np.array([0, 120, 160, 260, 360])) > 0.5, axis=1)
    assert bare.torque is not None
    assert np.allclose((r.torque - bare.torque)[keep], (q_f * p1)[keep], rtol=0, atol=1e-5)


def test_a_swing_the_linkage_cannot_follow_names_near(tmp_path) -> None:
    """A double-rocker (non-Grashof) whose lever cannot swing 20° from the given near angle."""
    from mechplan.errors import SceneError
    from mechplan.studies import solve_file

    lever = LEVER.replace('AB = "80 mm"', 'AB = "200 mm"').replace('DC = "180 mm"',
                                                                   'DC = "150 mm"').replace(
        'C = "left of B->D"', 'C = "left of B->D"\nat = "60 deg"')
    (tmp_path / "cam.toml").write_text(_cam("ccw"), encoding="utf-8")
    (tmp_path / "lever.toml").write_text(lever, encoding="utf-8")
    (tmp_path / "m.toml").write_text(
        'kind = "cycle"\n[[members]]\nname = "cam"\nscene = "cam.toml"\n'
        '[[members]]\nname = "lever"\nscene = "lever.toml"\ndriven_by = "cam"\n'
        'near = "35 deg"\n', encoding="utf-8")
    with pytest.raises(SceneError) as e:
        solve_file(tmp_path / "m.toml")
    assert e.value.key == "members[1].near"


SLIDER_LINKAGE = f"""title = "slider-driven linkage"
[ground]
G = ["0 mm", "0 mm"]
D = ["250 mm", "0 mm"]
guides.g = {{ through = "G", angle = "90 deg" }}
[links.1]
slides = {{ point = "B", on = "g" }}
[links.2]
lengths = {{ BC = "260 mm" }}
points = {{ S2 = "0.5 of B C" }}
mass = "{MASS} kg"
centre = "S2"
J = "{J2} kg*m^2"
[links.3]
lengths = {{ DC = "180 mm" }}
[drive]
kind = "slider"
link = "1"
speed = "1 m/s"
range = ["40 mm", "80 mm"]
[assembly]
C = "left of B->D"
at = "50 mm"
[[loads]]
type = "torque"
link = "3"
torque = "{M3} N*m"
"""

TRANSLATING = """kind = "cam"
title = "cam"
[follower]
motion = "translating"
contact = "roller"
roller_radius = "8 mm"
[motion]
stroke = "20 mm"
speed = "300 rpm"
phases = [
    { kind = "rise", angle = "120 deg", law = "cycloidal" },
    { kind = "far_dwell", angle = "40 deg" },
    { kind = "return", angle = "100 deg", law = "cycloidal" },
    { kind = "near_dwell", angle = "100 deg" },
]
"""


def test_a_translating_follower_drives_a_slider() -> None:
    """q = q_near + s: the rocker's rate against the loop closed by two circles, the cam torque
    by virtual power (torque on the rocker, the coupler's mass and inertia)."""
    cam = parse_cam(TRANSLATING, "cam.toml")
    scene = parse_scene(SLIDER_LINKAGE, "lever.toml")
    near = 0.05
    r = cam_linkage(cam, scene, near, cam.omega, "lever", "cam", None, "members[1]")
    w = cam.omega
    h = 0.02 / SWING                        # the test's law is the swing's, scaled to 20 mm

    def parts(p: np.ndarray):
        B = np.stack([np.zeros_like(p), near + h * _psi(p)], axis=-1)
        d = D - B
        L = np.hypot(d[..., 0], d[..., 1])
        a = (BC ** 2 - DC ** 2 + L ** 2) / (2 * L)
        hh = np.sqrt(BC ** 2 - a ** 2)
        u = d / L[..., None]
        C = B + a[..., None] * u + hh[..., None] * np.stack([-u[..., 1], u[..., 0]], axis=-1)
        return (np.unwrap(np.arctan2(C[..., 1] - D[1], C[..., 0] - D[0])), (B + C) / 2,
                np.unwrap(np.arctan2(C[..., 1] - B[..., 1], C[..., 0] - B[..., 0])))
    deg = np.degrees(r.phi)
    keep = np.all(np.abs(deg[:, None] - np.array([0, 120, 160, 260, 360])) > 0.5, axis=1)
    phi = r.phi[keep]
    _, th3_1, _ = _fd(lambda p: parts(p)[0], phi)
    _, s1, s2 = _fd(lambda p: parts(p)[1], phi)
    _, t2_1, t2_2 = _fd(lambda p: parts(p)[2], phi)
    assert r.output == "3"
    assert np.allclose(r.out_rate[keep], th3_1 * w, rtol=0, atol=1e-6 * np.abs(th3_1 * w).max())
    power = (MASS * np.einsum("ij,ij->i", s2 * w * w, s1 * w) + J2 * t2_2 * w * w * t2_1 * w
             - M3 * th3_1 * w)
    assert r.torque is not None and r.contact is not None
    assert np.allclose(r.torque[keep], power / w, rtol=0, atol=2e-5 * np.abs(power / w).max())
    # the contact force along the profile's normal carries Q = F_d along the follower
    assert r.moment is not None
    from mechplan.synthesis.cam import design
    from mechplan.synthesis.cam.profile import sample

    alpha = sample(design(cam).geometry, r.phi).alpha
    assert np.allclose(r.contact * np.cos(alpha), r.moment, rtol=1e-12, atol=1e-9)
