"""The oscillating flat-faced follower's cam against an independent envelope: the face lines turned
onto the cam (each the line through the turned pivot at the angle δ0 + ψ to the line of centres),
intersected pairwise at neighbouring cam angles, and the circle through three envelope points for
the radius of curvature. ψ(φ) of the cycloidal law is written here."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.errors import SceneError
from mechplan.studies.cam import solve_cam

A = 0.100
PSI = math.radians(15)
RISE, FAR, RET = (math.radians(v) for v in (120, 30, 120))


def scene(extra_limits: str = 'min_curvature_radius = "5 mm"', sense: str = "ccw",
          rise: str = "120 deg", ret: str = "120 deg", near: str = "90 deg") -> str:
    return f"""kind = "cam"
title = "t"
[follower]
motion = "oscillating"
contact = "flat"
pivot_distance = "100 mm"
[motion]
swing = "15 deg"
speed = "300 rpm"
sense = "{sense}"
phases = [
    {{ kind = "rise", angle = "{rise}", law = "cycloidal" }},
    {{ kind = "far_dwell", angle = "30 deg" }},
    {{ kind = "return", angle = "{ret}", law = "cycloidal" }},
    {{ kind = "near_dwell", angle = "{near}" }},
]
[limits]
{extra_limits}
"""


def psi(phi: float) -> float:
    phi = phi % (2 * math.pi)
    if phi < RISE:
        x = phi / RISE
        return PSI * (x - math.sin(2 * math.pi * x) / (2 * math.pi))
    if phi < RISE + FAR:
        return PSI
    if phi < RISE + FAR + RET:
        x = (phi - RISE - FAR) / RET
        return PSI * (1 - x + math.sin(2 * math.pi * x) / (2 * math.pi))
    return 0.0


def face_line(phi: float, r0: float) -> tuple[np.ndarray, float]:
    """(unit normal, distance) of the face turned by −φ onto the cam."""
    delta = math.asin(r0 / A) + psi(phi)
    n = np.array([math.sin(delta), math.cos(delta)])
    c, s = math.cos(-phi), math.sin(-phi)
    return np.array([c * n[0] - s * n[1], s * n[0] + c * n[1]]), A * math.sin(delta)


def envelope(phi: float, r0: float, h: float = 1e-5) -> np.ndarray:
    (n1, p1), (n2, p2) = face_line(phi - h, r0), face_line(phi + h, r0)
    return np.linalg.solve(np.array([n1, n2]), np.array([p1, p2]))


def circle_radius(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> float:
    a, b, c = np.linalg.norm(q - r), np.linalg.norm(p - r), np.linalg.norm(p - q)
    area2 = abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))
    return a * b * c / (2 * area2)


def test_profile_and_curvature_match_the_envelope():
    d = solve_cam(scene(), "c.toml").design
    r0 = d.geometry.r0
    for j in range(0, d.dense.phi.size, 450):
        phi = float(d.dense.phi[j])
        assert np.allclose(d.dense.profile[j], envelope(phi, r0), atol=2e-8)
        if RISE * 0.05 < phi < RISE * 0.95:               # away from the ends of the law
            h = 2e-3
            rho = circle_radius(envelope(phi - h, r0), envelope(phi, r0), envelope(phi + h, r0))
            assert d.dense.radius[j] == pytest.approx(rho, rel=2e-4)


def test_least_base_radius_gives_the_least_curvature():
    d = solve_cam(scene(), "c.toml").design
    assert float(np.min(d.dense.radius)) == pytest.approx(0.005, rel=1e-6)
    assert d.geometry.r0 == pytest.approx(d.r0_min)
    # the contact point is on the turned face, L = a·cos δ/(1 + ψ′) from the pivot
    lo, hi = d.face
    along = np.hypot(*(d.dense.follower - np.array([A, 0.0])).T)
    assert lo == pytest.approx(along.min() - 0.005) and hi == pytest.approx(along.max() + 0.005)
    assert np.all(np.abs(d.dense.alpha) == 0)


def test_clockwise_cam_is_the_mirror_image():
    ccw = solve_cam(scene(), "c.toml").design
    cw = solve_cam(scene(sense="cw"), "c.toml").design
    assert np.allclose(cw.dense.profile, ccw.dense.profile * np.array([-1.0, 1.0]))


def test_given_base_radius_below_the_least_is_refused():
    with pytest.raises(SceneError) as err:
        solve_cam(scene('min_curvature_radius = "5 mm"\nbase_radius = "20 mm"'), "c.toml")
    assert err.value.key == "limits.base_radius"


def test_oscillating_follower_spring_torque_gives_back_its_work():
    text = scene() + '[dynamics]\ninertia = "0.002 kg*m^2"\nspeed_max = "400 rpm"\n' \
                     'margin = "0.5 N*m"\n'
    st = solve_cam(text, "c.toml")
    r = st.design.dynamics
    assert abs(r.torque_mean) < 1e-9 * max(abs(r.torque_extremes[0]), 1.0)
    assert r.contact_max_speed.min() == pytest.approx(0.5, rel=1e-6)
    assert "pivot" in st.report("en")
    st.sheets(None, None, "en", "t")
