"""The profile by inversion against independent computations: the pressure-angle formula, normals
and curvature by finite differences of the profile, the envelope condition (shapely), the minimum
base radius by brute force, the chord error of the profile polyline."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar
from shapely.geometry import LinearRing, Point, Polygon

from mechplan.scene.cam import parse_cam
from mechplan.synthesis.cam import design, sample
from mechplan.synthesis.cam.chords import chord_deviation
from mechplan.synthesis.cam.motion import motion

from .scenes import cam_text, oscillating_text


def _rot(v, ang):
    c, s = np.cos(ang), np.sin(ang)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


@pytest.fixture(scope="module")
def offset_cam():
    return design(parse_cam(cam_text(offset="6 mm", sense="cw", law="poly345")))


@pytest.fixture(scope="module")
def central_cam():
    return design(parse_cam(cam_text()))


PHI = np.radians(np.array([5.0, 33.0, 61.0, 100.0, 125.0, 150.0, 170.0, 200.0, 230.0, 271.0,
                          300.0]))


@pytest.mark.parametrize("name", ["offset_cam", "central_cam"])
def test_pressure_angle_formula_and_finite_difference_normal(name, request):
    d = request.getfixturevalue(name)
    g = d.geometry
    smp = sample(g, PHI)
    m = motion(g.phases, g.stroke, PHI)
    s0 = math.sqrt(g.r0 ** 2 - g.e ** 2)
    formula = np.arctan((m.s1 - g.e) / (m.s + s0))
    assert np.allclose(np.abs(smp.alpha), np.abs(formula), atol=1e-12)
    # independent: the pitch curve's normal by central differences, against the follower's axis
    h = 1e-6
    tangent = (sample(g, PHI + h).pitch - sample(g, PHI - h).pitch) / (2 * h)
    normal = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)
    sigma = g.sense
    axis = _rot(np.tile([0.0, 1.0], (PHI.size, 1)), -sigma * PHI)   # follower axis, turned by −φ
    cosang = np.abs(np.einsum("ij,ij->i", normal, axis)) / np.hypot(*normal.T)
    assert np.allclose(np.arccos(np.clip(cosang, -1, 1)), np.abs(formula), atol=1e-6)


def test_radius_of_curvature_by_three_points(offset_cam):
    g = offset_cam.geometry
    h = 1e-4
    for phi in PHI:
        a, b, c = sample(g, np.array([phi - h, phi, phi + h])).pitch
        # circle through three points
        ab, bc, ca = np.linalg.norm(b - a), np.linalg.norm(c - b), np.linalg.norm(a - c)
        area2 = abs((b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0])
        R = ab * bc * ca / (2 * area2) if area2 > 1e-18 else math.inf
        R_code = abs(float(sample(g, phi).radius_pitch[0]))
        if R < 1.0:
            assert R == pytest.approx(R_code, rel=1e-4)


def test_envelope_touches_each_roller_once(central_cam):
    d = central_cam
    g = d.geometry
    ring = LinearRing(sample(g, np.linspace(0, 2 * math.pi, 72000, endpoint=False)).profile)
    poly = Polygon(ring)
    assert poly.is_valid                              # no loops: no undercut
    phis = np.radians(np.arange(0.0, 360.0, 7.5))
    smp = sample(g, phis)
    for c, w in zip(smp.pitch, smp.profile):
        centre = Point(c)
        dist = ring.distance(centre)
        assert dist == pytest.approx(g.roller, abs=2e-7)             # touches …
        assert not poly.contains(centre.buffer(g.roller - 1e-6))     # … without cutting into it
        near = np.asarray(ring.coords)
        close = near[np.abs(np.hypot(*(near - c).T) - g.roller) < 1e-6]
        # … at one point: every ring vertex that close to the roller is next to the contact point
        assert np.max(np.hypot(*(close - w).T)) < 5e-4


def test_flat_faced_radius_is_r0_plus_s_plus_s2():
    d = design(parse_cam(cam_text(contact="flat", law="cosine", extra_limits=
                                  'min_curvature_radius = "3 mm"')))
    g = d.geometry
    inside = PHI[np.abs(np.degrees(PHI) - 150.0) > 1]    # not across the jump of s″ at 150°
    m = motion(g.phases, g.stroke, inside)
    h = 1e-4
    for i, phi in enumerate(inside):
        a, b, c = sample(g, np.array([phi - h, phi, phi + h])).profile
        ab, bc, ca = np.linalg.norm(b - a), np.linalg.norm(c - b), np.linalg.norm(a - c)
        area2 = abs((b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0])
        assert ab * bc * ca / (2 * area2) == pytest.approx(g.r0 + m.s[i] + m.s2[i], rel=1e-4)
    # the minimum base radius from convexity: ρ = r0 + s + s″ ≥ 3 mm, with equality somewhere
    dense = motion(g.phases, g.stroke, np.linspace(0, 2 * math.pi, 36000, endpoint=False))
    assert d.r0_min == pytest.approx(np.max(0.003 - dense.s - dense.s2), abs=1e-12)
    assert float(np.min(d.dense.radius)) == pytest.approx(0.003, abs=1e-9)


def _central_r0(m, t_rise, t_ret, e=0.0):
    """s0 from tan α = (s′ − e)/(s + s0) ≤ tan L on both sides, by brute force."""
    t = np.where(m.s1 >= 0, t_rise, t_ret)
    s0 = np.max(np.maximum((m.s1 - e) / t, -(m.s1 - e) / t) - m.s)
    return math.hypot(e, s0)


def test_minimum_base_radius_central_and_best_offset():
    text = cam_text(alpha_rise="30 deg", alpha_return="45 deg", offset=None, far="0.0001 deg",
                    near="119.9999 deg")
    phi = np.linspace(0, 2 * math.pi, 36000, endpoint=False)
    spec = parse_cam(text.replace('offset = "None"', ""))
    m = motion(spec.phases, spec.stroke, phi)
    tr, td = math.tan(math.radians(30)), math.tan(math.radians(45))
    central = design(parse_cam(cam_text(alpha_rise="30 deg", alpha_return="45 deg",
                                        far="0.0001 deg", near="119.9999 deg")))
    assert central.r0_min == pytest.approx(_central_r0(m, tr, td), rel=1e-9)
    assert central.alpha_rise.value == pytest.approx(math.radians(30), abs=1e-6)
    best = design(parse_cam(cam_text(alpha_rise="30 deg", alpha_return="45 deg", offset="best",
                                     far="0.0001 deg", near="119.9999 deg")))
    res = minimize_scalar(lambda e: _central_r0(m, tr, td, e), bounds=(-0.02, 0.02),
                          method="bounded", options={"xatol": 1e-10})
    assert best.r0_min == pytest.approx(res.fun, rel=1e-6)
    assert best.geometry.e == pytest.approx(res.x, abs=1e-6)
    assert best.r0_min < central.r0_min


def test_given_base_radius_meets_the_limit():
    d = design(parse_cam(cam_text(base="60 mm", offset="5 mm")))
    assert d.geometry.r0 == pytest.approx(0.06)
    assert d.alpha_rise.value <= math.radians(30) + 1e-12


@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_oscillating_minimum_base_radius_and_pressure_angle(sense):
    d = design(parse_cam(oscillating_text(sense=sense)))
    g = d.geometry
    phi = d.dense.phi
    # independent pressure angle: normal of the pitch curve (finite differences) vs the roller's
    # velocity direction (⊥ arm), both in the cam frame
    sel = phi[::97]
    hh = 1e-6
    tangent = (sample(g, sel + hh).pitch - sample(g, sel - hh).pitch) / (2 * hh)
    normal = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)
    normal /= np.hypot(*normal.T)[:, None]
    smp = sample(g, sel)
    pivot = _rot(np.tile([g.sense * g.pivot, 0.0], (sel.size, 1)), -g.sense * sel)
    arm = smp.pitch - pivot
    vel = np.stack([-arm[:, 1], arm[:, 0]], axis=1) / np.hypot(*arm.T)[:, None]
    alpha = np.arccos(np.clip(np.abs(np.einsum("ij,ij->i", normal, vel)), 0, 1))
    assert np.allclose(alpha, np.abs(smp.alpha), atol=1e-6)
    # the arm length and the swing are kept
    assert np.allclose(np.hypot(*arm.T), g.arm, atol=1e-12)
    # minimum: at r0 the worst |α|/[α] is 1, a hair below it exceeds
    lim = np.where(np.isin(np.arange(phi.size), np.flatnonzero(d.dense.s1 < 0)),
                   math.radians(60), math.radians(45))
    ratio = np.abs(d.dense.alpha) / lim
    assert ratio.max() <= 1 + 1e-9 and ratio.max() > 1 - 1e-5


def test_profile_polyline_chord_error_is_within_one_micrometre(central_cam):
    d = central_cam
    g = d.geometry
    phi = np.append(d.profile_phi, 2 * math.pi)
    dev = chord_deviation(lambda p: sample(g, p).profile, phi, inner=40)
    assert dev.max() <= 1e-6
    assert dev.max() > 0.2e-6                   # and the point count is not wastefully high
    assert np.allclose(d.profile_points, sample(g, d.profile_phi).profile)
