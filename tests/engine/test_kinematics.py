"""Piston kinematics against independent references (mpmath derivatives, geometry of the
drawing)."""

from __future__ import annotations

import math

import mpmath
import numpy as np

from mechplan.dynamics.engine.kinematics import SliderCrank

R, L = 0.0235, 0.106
OMEGA = 8500 * math.pi / 30


def _x_mp(phi):
    """Travel from TDC by the geometry of the triangle (crank pin, piston pin, crank axis)."""
    s = (mpmath.mpf(R) * mpmath.cos(phi)
         + mpmath.sqrt(mpmath.mpf(L) ** 2 - (R * mpmath.sin(phi)) ** 2))
    return mpmath.mpf(R + L) - s


def test_exact_travel_velocity_acceleration_match_mpmath_derivatives():
    kin = SliderCrank(R, L)
    with mpmath.workdps(30):
        _check_derivatives(kin)


def _check_derivatives(kin):
    for deg in (0.0, 17.0, 63.0, 90.0, 131.0, 180.0, 222.0, 300.0, 359.0):
        phi = mpmath.radians(deg)
        x = float(_x_mp(phi))
        v = float(mpmath.diff(_x_mp, phi) * OMEGA)
        a = float(mpmath.diff(_x_mp, phi, 2) * OMEGA ** 2)
        f = np.radians(deg)
        assert math.isclose(float(kin.x(f)), x, rel_tol=1e-12, abs_tol=1e-15)
        assert math.isclose(float(kin.v(f, OMEGA)), v, rel_tol=1e-11, abs_tol=1e-9)
        assert math.isclose(float(kin.a(f, OMEGA)), a, rel_tol=1e-11, abs_tol=1e-7)


def test_series_differs_from_exact_by_046_percent_of_a_max():
    """Worked example §3: max |a − a_series| ≈ 0.46 % of a_max (references from mpmath)."""
    lam = R / L
    with mpmath.workdps(20):
        phis = [mpmath.radians(d / 2) for d in range(721)]
        a_exact = [float(mpmath.diff(_x_mp, p, 2)) * OMEGA ** 2 for p in phis]
    a_ser = [R * OMEGA ** 2 * (math.cos(float(p)) + lam * math.cos(2 * float(p))) for p in phis]
    ratio = max(abs(x - y) for x, y in zip(a_exact, a_ser)) / max(abs(x) for x in a_exact)
    assert 0.0045 < ratio < 0.0047
    kin = SliderCrank(R, L)
    f = np.radians(np.arange(721) / 2)
    mine = (np.max(np.abs(kin.a(f, OMEGA) - kin.a_series(f, OMEGA)))
            / np.max(np.abs(kin.a(f, OMEGA))))
    assert math.isclose(mine, ratio, rel_tol=1e-6)


def test_brix_travel_is_the_drawn_construction():
    """Intersect the ray from O′ with the circle (numpy root of the quadratic) and project."""
    kin = SliderCrank(R, L)
    lam = R / L
    for deg in (10.0, 45.0, 90.0, 120.0, 170.0):
        phi = math.radians(deg)
        O = np.array([R, 0.0])                       # x measured from TDC towards BDC
        Op = O + np.array([R * lam / 2.0, 0.0])
        d = np.array([-math.cos(phi), math.sin(phi)])
        # |Op + t d − O|² = R²
        b = 2.0 * d @ (Op - O)
        c = (Op - O) @ (Op - O) - R * R
        t = (-b + math.sqrt(b * b - 4 * c)) / 2.0
        x = (Op + t * d)[0]
        assert math.isclose(float(kin.x_brix(np.asarray(phi))), x, rel_tol=1e-12)
        # the series travel is Brix's to first order in λ
        assert (abs(float(kin.x_brix(np.asarray(phi)) - kin.x_series(np.asarray(phi))))
                < R * lam ** 2)


def test_inverse_travel():
    kin = SliderCrank(R, L)
    f = np.radians([5.0, 60.0, 120.0, 175.0])
    assert np.allclose(kin.phi_of_x(kin.x(f), False), f, atol=1e-10)
    assert np.allclose(kin.phi_of_x(kin.x(2 * np.pi - f), True), 2 * np.pi - f, atol=1e-10)
