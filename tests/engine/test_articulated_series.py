"""An articulated cylinder's "series" column and Brix's p from its own exact motion.

The series keeps orders 1 and 2 of the articulated piston's exact motion (numerical harmonic
analysis of the linkage solver's travel over a turn, 512 samples); Brix's construction is drawn for
that piston: a circle of radius R′ = |c1|, the pole shifted R′λ′/2 towards BDC with
λ′ = 4|c2|/|c1|, rays from its own exact TDC. Golden values: an independent loop-closure solver
(brentq on each loop, ``closure`` of test_layouts) Fourier-analysed by direct sums on another grid,
and Brix's construction done as geometry (the ray from the pole meets the circle: a quadratic).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from test_layouts import OMEGA, R, closure, derivatives, radial

N_GOLD = 300


def _orders(gamma: float, bank: float) -> tuple[complex, complex]:
    """c1, c2 of the piston's distance from the crank axis, by direct sums over N_GOLD angles."""
    t = np.arange(N_GOLD) * 2 * math.pi / N_GOLD
    s = np.array([closure(float(x), gamma, bank) for x in t])
    return tuple(complex(2.0 / N_GOLD * np.sum(s * np.exp(-1j * k * t))) for k in (1, 2))


def _brix_drawn(psi: np.ndarray, Rb: float, lam: float) -> np.ndarray:
    """Stroke fraction by Brix's construction as geometry: circle of radius Rb about O (TDC side
    +x), pole O′ at −Rb·λ/2 (towards BDC); the ray from O′ at angle ψ from +x meets the circle
    at P (the root ahead of O′); the piston is at P's foot, x = Rb − P_x from TDC."""
    out = []
    for f in psi:
        d = np.array([math.cos(f), math.sin(f)])
        o = np.array([-Rb * lam / 2.0, 0.0])
        # |o + t d|² = Rb²: t² + 2 (o·d) t + |o|² − Rb² = 0, the positive root
        b, c = float(o @ d), float(o @ o) - Rb * Rb
        t = -b + math.sqrt(b * b - c)
        out.append((Rb - (o + t * d)[0]) / (2.0 * Rb))
    return np.array(out)


def test_brix_geometry_is_the_courses_brix_on_a_slider_crank():
    st = radial(5)
    psi = np.radians(np.arange(0.0, 720.0, 17.0) + 0.3)
    assert np.allclose(_brix_drawn(psi, R, st.model.kin.lam),
                       st.model.kin.x_brix(psi) / (2 * R), rtol=0, atol=1e-14)


@pytest.mark.parametrize("n", [5, 7])
def test_series_and_brix_of_articulated_cylinders(n):
    st = radial(n)
    m = st.model
    phi = np.radians(np.arange(0.0, 720.0, 11.0) + 0.17)
    for number, art in m.articulated.items():
        bank = 2 * math.pi * (number - 1) / n
        gamma = math.remainder(bank, 2 * math.pi)
        c1, c2 = _orders(gamma, bank)
        sl = m.group.slaves[art.slot]
        assert abs(sl.c1 - c1) < 1e-13 and abs(sl.c2 - c2) < 1e-13
        theta = phi - art.offset
        a_gold = OMEGA ** 2 * np.real(c1 * np.exp(1j * theta) + 4 * c2 * np.exp(2j * theta))
        f = m.cylinder(number, phi)
        scale = float(np.max(np.abs(a_gold)))
        assert np.max(np.abs(f.a_series - a_gold)) < 1e-11 * scale
        assert np.allclose(f.Pj_series, -m.m_j[number] * a_gold, rtol=1e-11, atol=1e-9)
        # what the series leaves out is orders ≥ 3: the exact acceleration's orders 1 and 2
        # (6th-order differences of the closure, 64 angles) are the series'
        t = np.arange(64) * 2 * math.pi / 64
        a_ex = np.array([OMEGA ** 2 * derivatives(
            lambda y, g=gamma, b=bank: -closure(y, g, b), x)[1] for x in t])
        a_se = OMEGA ** 2 * np.real(c1 * np.exp(1j * t) + 4 * c2 * np.exp(2j * t))
        diff = np.fft.rfft(a_ex - a_se) * 2 / 64
        assert np.max(np.abs(diff[1:3])) < 1e-7 * scale
        # the courses' λ-series of the master's slider-crank is not this piston's series
        lam_series = m.kin.a_series(m.local(number, phi), OMEGA)
        assert np.max(np.abs(lam_series - a_gold)) > 1e-3 * scale
        # Brix's p from the piston's own exact TDC (brentq on the closure's derivative)
        tdc = brentq(lambda x, g=gamma, b=bank: derivatives(lambda y: closure(y, g, b), x)[0],
                     sl.phi_tdc - 0.05, sl.phi_tdc + 0.05, xtol=1e-13)
        psi = m.local(number, phi)
        own = psi - math.remainder(tdc + art.offset - m.phases[number], 2 * math.pi)
        xi = _brix_drawn(own, abs(c1), 4 * abs(c2) / abs(c1))
        p_gold = m.diagram.at_phi(own, xi)
        assert np.allclose(f.p_brix, p_gold, rtol=1e-9)
        # and it transfers the diagram near its exact p: within a few % of p_max here
        assert np.max(np.abs(f.p_brix - f.p)) < 0.05 * np.max(f.p)
