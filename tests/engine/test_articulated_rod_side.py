"""Double-acting cylinders on articulated layouts (``[rod_side]`` with master and articulated rods):
each articulated piston's crank end follows its own stroke fraction 1 − x/S′ and its stroke one
behind the head's (its cycle starts at the head's exact BDC). Golden values: the independent
loop-closure solver of test_layouts (travel, acceleration, exact dead centres by brentq) and the
two faces' p–V areas by trapezoids."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from test_layouts import OMEGA, RADIAL, closure, derivatives

from mechplan.studies.engine import solve_engine_text

ROD = '[rod_side]\nrod_diameter = "30 mm"\n'


@pytest.fixture(scope="module")
def study():
    return solve_engine_text(RADIAL.format(n=5, engine_extra="", art_extra="") + ROD, "r.toml")


def _own_dead_centres(sl, gamma, bank):
    def ds(t: float) -> float:
        return derivatives(lambda y: closure(y, gamma, bank), t)[0]

    tdc = brentq(ds, sl.phi_tdc - 0.05, sl.phi_tdc + 0.05, xtol=1e-13)
    bdc = brentq(ds, sl.phi_bdc - 0.05, sl.phi_bdc + 0.05, xtol=1e-13)
    return tdc, bdc


def test_crank_end_of_articulated_pistons(study):
    m = study.model
    spec = m.spec
    F = spec.F_p
    F_rod = F - math.pi * 0.03 ** 2 / 4.0
    assert spec.F_rod_side == pytest.approx(F_rod, rel=1e-14)
    phi = np.radians(np.arange(0.0, 720.0, 13.0) + 0.41)
    for number, art in m.articulated.items():
        bank = 2 * math.pi * (number - 1) / 5
        gamma = math.remainder(bank, 2 * math.pi)
        sl = m.group.slaves[art.slot]
        tdc, bdc = _own_dead_centres(sl, gamma, bank)
        s_tdc, s_bdc = closure(tdc, gamma, bank), closure(bdc, gamma, bank)
        S = s_tdc - s_bdc
        theta = phi - art.offset
        x = np.array([s_tdc - closure(float(t), gamma, bank) for t in theta])
        a = -OMEGA ** 2 * np.array([derivatives(lambda y, g=gamma, b=bank: closure(y, g, b),
                                                float(t))[1] for t in theta])
        # the head's stroke from the exact dead centres: TDC→BDC, BDC→TDC, … in its own cycle
        psi = m.local(number, phi)
        e_T = math.remainder(tdc + art.offset - m.phases[number], 2 * math.pi)
        e_B = math.remainder(bdc + art.offset - m.phases[number] - math.pi, 2 * math.pi)
        starts = np.array([0.0, math.pi + e_B - e_T, 2 * math.pi, 3 * math.pi + e_B - e_T])
        k = np.searchsorted(starts, np.mod(psi - e_T, 4 * math.pi), side="right") - 1
        p = m.diagram.pressure_xi(x / S, k)
        p_rod = m.rod_diagram.pressure_xi(1.0 - x / S, (k - 1) % 4)
        P = (p - 1e5) * F - (p_rod - 1e5) * F_rod - m.m_j[number] * a
        f = m.cylinder(number, phi)
        assert np.allclose(f.p_rod, p_rod, rtol=1e-9)
        assert np.max(np.abs(f.P - P)) < 1e-8 * np.max(np.abs(P))


def test_work_of_both_faces_and_pin_torque(study):
    m, ch = study.model, study.checks
    assert ch.work_error < 1e-9 and ch.pair_torque_error < 1e-9
    # each articulated cylinder's crank-end work by trapezoids of p_rod over −F_rod·x on a fine
    # grid, against the crank-end diagram's area scaled by its own stroke
    g = np.linspace(0.0, 4 * math.pi, 40001)
    for number in m.articulated:
        f = m.cylinder(number, g + m.phases[number])
        W_rod = np.trapezoid(f.p_rod, -m.spec.F_rod_side * f.x)
        assert W_rod == pytest.approx(m.rod_diagram.work() * m.stroke_of(number)
                                      / (2 * m.spec.R), rel=2e-4)
    doc = study.to_json()
    assert doc["rod_side"]["rod_diameter"] == 0.03
    assert "p_rod" in doc["angles"][2]["cylinders"]["3"]
    assert "Double-acting cylinder" in study.report("en")


def test_master_and_articulated_v8_double_acting():
    """Every throw of the cross-plane V8 with articulated rods, double-acting: the work of the
    torque is both faces' areas scaled by each piston's stroke, every pin's R·T is the power of
    its two pistons; the crank end lowers P by (p_rod − p0)·F_rod against the single-acting V8."""
    from test_layouts import V8_ART

    double = solve_engine_text(V8_ART + ROD, "v.toml")
    single = solve_engine_text(V8_ART, "v.toml")
    ch = double.checks
    assert ch.work_error < 1e-9 and ch.pair_torque_error < 1e-9
    phi = np.radians(np.arange(0.0, 720.0, 23.0) + 0.2)
    for number in double.model.articulated:
        f2, f1 = double.model.cylinder(number, phi), single.model.cylinder(number, phi)
        dP = -(f2.p_rod - 1e5) * double.model.spec.F_rod_side
        assert np.allclose(f2.P - f1.P, dP, rtol=1e-12, atol=1e-9)
