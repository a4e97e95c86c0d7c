"""Engines of any layout (issue 36): radial engines and master/articulated rods on every throw
against an independent loop-closure solver, their dynamics and balancing; the double-acting
cylinder; a p(φ) table without ε; the torque's extremes between grid points."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.dynamics.engine.balance import extremes, turning
from mechplan.dynamics.engine.extremes import total_torque
from mechplan.dynamics.engine.layouts import ideal_orders
from mechplan.errors import SceneError
from mechplan.studies.engine import EngineStudy, solve_engine_text

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"

RADIAL = """
kind = "engine"
title = "radial"
[engine]
strokes = 4
speed = "1650 rpm"
bore = "125 mm"
crank_radius = "70 mm"
rod_length = "250 mm"
p0 = "100 kPa"
layout = "radial"
cylinders = {n}
{engine_extra}
[articulated]
lug_radius = "60 mm"
rod_length = "190 mm"
piston = "1.5 kg"
rod = "0.9 kg"
rod_small_end = "0.6 kg"
{art_extra}
[masses]
piston = "1.5 kg"
rod = "2.5 kg"
rod_small_end = "0.6 kg"
[indicator]
epsilon = 5
p_a = "90 kPa"
p_r = "110 kPa"
n1 = 1.35
n2 = 1.25
p_z = "3.5 MPa"
[balance]
orders = 8
counterweight_share = 0.5
"""

R, L, r_lug, l_art = 0.070, 0.250, 0.060, 0.190
OMEGA = 1650 * math.pi / 30


def radial(n: int = 5, engine_extra: str = "", art_extra: str = "") -> EngineStudy:
    return solve_engine_text(RADIAL.format(n=n, engine_extra=engine_extra, art_extra=art_extra),
                             "radial.toml")


# -- an independent loop-closure solver --------------------------------------------------------
def closure(theta: float, gamma: float, bank: float, R_: float = R, L_: float = L,
            r_: float = r_lug, l_: float = l_art) -> float:
    """Distance from the crank axis of an articulated piston (scipy's brentq on each loop).

    Crank AB at θ from the master cylinder's axis (+x); master piston C on +x with BC = L;
    lug D on the master rod at r, ∠CBD = γ; piston E on the axis at ``bank`` with DE = l.
    """
    B = np.array([R_ * math.cos(theta), R_ * math.sin(theta)])
    x_C = brentq(lambda x: (x - B[0]) ** 2 + B[1] ** 2 - L_ ** 2, B[0], B[0] + L_ + R_,
                 xtol=1e-16, rtol=8.9e-16)
    alpha = math.atan2(-B[1], x_C - B[0])
    D = B + r_ * np.array([math.cos(alpha + gamma), math.sin(alpha + gamma)])
    u = np.array([math.cos(bank), math.sin(bank)])
    s0 = float(D @ u)
    return brentq(lambda s: float(np.sum((s * u - D) ** 2)) - l_ ** 2, s0, s0 + l_ + 1e-9,
                  xtol=1e-16, rtol=8.9e-16)


def derivatives(f, theta: float, h: float = 1e-2) -> tuple[float, float]:
    """ds/dθ and d²s/dθ² by the 6th-order central stencils."""
    s = {k: f(theta + k * h) for k in range(-3, 4)}
    d1 = (-s[-3] + 9 * s[-2] - 45 * s[-1] + 45 * s[1] - 9 * s[2] + s[3]) / (60 * h)
    d2 = (2 * s[-3] - 27 * s[-2] + 270 * s[-1] - 490 * s[0] + 270 * s[1] - 27 * s[2]
          + 2 * s[3]) / (180 * h * h)
    return d1, d2


ANGLES = np.radians(np.arange(0.0, 360.0, 13.0) + 0.37)


@pytest.mark.parametrize("n", [5, 7])
def test_radial_pistons_against_an_independent_loop_closure(n):
    st = radial(n)
    group = st.model.group
    assert group is not None and len(group.slaves) == n - 1
    state = group.state(ANGLES)
    for k, sl in enumerate(group.slaves):
        bank = 2 * math.pi * (k + 1) / n
        gamma = math.remainder(bank, 2 * math.pi)
        s = np.array([closure(t, gamma, bank) for t in ANGLES])
        d = [derivatives(lambda t, g=gamma, b=bank: closure(t, g, b), t) for t in ANGLES]
        v = OMEGA * np.array([x[0] for x in d])
        a = OMEGA ** 2 * np.array([x[1] for x in d])
        got_s = state.E[k] @ sl.u
        got_v = state.v_E[k] @ sl.u
        got_a = state.a_E[k] @ sl.u
        assert np.max(np.abs(got_s - s)) < 1e-12 * L
        assert np.max(np.abs(got_v - v)) < 1e-9 * np.max(np.abs(v))
        assert np.max(np.abs(got_a - a)) < 1e-9 * np.max(np.abs(a))
    # the master piston is the closed-form slider-crank
    s_C = R * np.cos(ANGLES) + np.sqrt(L ** 2 - (R * np.sin(ANGLES)) ** 2)
    assert np.allclose(state.C[:, 0], s_C, rtol=0, atol=1e-13)


def test_radial_cylinder_travel_and_dead_centres():
    st = radial(5)
    m = st.model
    for number, art in m.articulated.items():
        sl = m.group.slaves[art.slot]
        bank = 2 * math.pi * (number - 1) / 5
        gamma = math.remainder(bank, 2 * math.pi)
        # exact TDC: the closure's maximum, found independently by brentq on its derivative
        guess = sl.phi_tdc
        tdc = brentq(lambda t, g=gamma, b=bank: derivatives(lambda x: closure(x, g, b), t)[0],
                     guess - 0.05, guess + 0.05, xtol=1e-12)
        assert math.remainder(tdc - sl.phi_tdc, 2 * math.pi) == pytest.approx(0.0, abs=1e-8)
        s_tdc = closure(tdc, gamma, bank)
        phi = np.radians(np.arange(0.0, 720.0, 31.0))
        f = m.cylinder(number, phi)
        s = np.array([closure(float(t), gamma, bank) for t in phi])
        assert np.allclose(f.x, s_tdc - s, rtol=0, atol=1e-11)
        assert sl.stroke != pytest.approx(2 * R, rel=1e-3)   # the articulated stroke is not 2R


def test_radial_dynamics_close_their_work_and_pin_torque():
    st = radial(7)
    ch = st.checks
    assert ch.work_error < 1e-9
    assert ch.pair_torque_error < 1e-9
    # the pin load's torque equals Σ P·v/ω of the seven pistons at every angle
    d = st.dense
    assert np.allclose(d.pins[1].T * R, d.M_total, rtol=1e-9, atol=1e-9 * np.abs(d.M_total).max())


def _first_order_from_closure(st: EngineStudy, n: int) -> np.ndarray:
    """C of the 1st-order reciprocating free force from the loop closure (trapezoid quadrature
    of the periodic, analytic force: spectrally exact)."""
    m = st.model
    N = 256
    theta = np.arange(N) * 2 * math.pi / N
    F = np.zeros((N, 2))
    for c in st.scene.engine.cylinders:
        u = np.array([math.cos(c.bank), math.sin(c.bank)])
        if c.number == 1:
            acc = np.array([derivatives(lambda t: R * math.cos(t) + math.sqrt(
                L ** 2 - (R * math.sin(t)) ** 2), t)[1] for t in theta])
        else:
            g = math.remainder(c.bank, 2 * math.pi)
            acc = np.array([derivatives(lambda t, g=g, b=c.bank: closure(t, g, b), t)[1]
                            for t in theta])
        # d²x/dt² with x towards the crankshaft is −d²s/dt²; the force on the engine m_j·a·u
        F += np.outer(-OMEGA ** 2 * acc * m.m_j[c.number], u)
    e = np.exp(-1j * theta)
    return 2.0 / N * np.array([np.sum(F[:, 0] * e), np.sum(F[:, 1] * e)])


def test_radial_first_order_against_closure_and_the_idealised_radial():
    n = 5
    # equal reciprocating masses: articulated rods put nothing on the big end (m2 = 0) and
    # carry the master's m1 at the pin
    text = RADIAL.format(n=n, engine_extra="", art_extra="").replace(
        'rod = "0.9 kg"\nrod_small_end = "0.6 kg"', 'rod = "0.6 kg"\nrod_small_end = "0.6 kg"')
    st = solve_engine_text(text, "radial.toml")
    m = st.model
    m_j = 1.5 + 0.6
    assert all(m.m_j[c] == pytest.approx(m_j) for c in range(1, n + 1))
    b = st.balance
    rw2 = R * OMEGA ** 2
    # the idealised radial (equal rods): n/2·m_j·Rω² turning with the crank, nothing against it
    ideal = ideal_orders(m, 8)
    f, bk = turning(ideal[1])
    assert abs(f) == pytest.approx(n / 2 * m_j * rw2, rel=1e-12)
    assert abs(bk) < 1e-9 * abs(f)
    # and order k only where n | k ∓ 1 (n = 5: forward 6, backward 4)
    for k in range(2, 9):
        fk, bk_ = turning(ideal[k])
        assert (abs(fk) > 1e-6 * abs(f)) == ((k - 1) % n == 0), k
        assert (abs(bk_) > 1e-6 * abs(f)) == ((k + 1) % n == 0), k
    # the real radial's 1st order from the independent loop closure
    C1 = _first_order_from_closure(st, n)
    assert np.allclose(b.orders[1].F, C1, rtol=0, atol=1e-7 * abs(f))
    # the counterweight with k = 0.5 leaves the 1st order the articulated rods add
    C_cw = -0.5 * n * m_j * rw2 * np.array([1.0, -1j])          # opposite the crank
    assert extremes(b.after_F)[0] == pytest.approx(extremes(C1 + C_cw)[0], rel=1e-7, abs=1e-6)
    # ... which is small against the idealised first order (the deviation is reported)
    assert extremes(b.after_F)[0] < 0.05 * abs(f)
    report = st.report("en")
    assert "idealised engine" in report and "order 1: with the crank" in report
    doc = st.to_json()
    assert doc["balance"]["ideal"][0]["forward_ideal"] == pytest.approx(abs(f), rel=1e-12)


V8_ART = """
kind = "engine"
title = "V8 with master and articulated rods"
[engine]
strokes = 4
speed = "2600 rpm"
bore = "120 mm"
crank_radius = "60 mm"
rod_length = "225 mm"
p0 = "100 kPa"
layout = "v_articulated"
cylinders = 8
throws = ["0 deg", "0 deg", "90 deg", "90 deg", "270 deg", "270 deg", "180 deg", "180 deg"]
firing_order = [1, 2, 4, 5, 6, 3, 7, 8]
[articulated]
bank_angle = "90 deg"
lug_radius = "55 mm"
lug_angle = "80 deg"
rod_length = "170 mm"
piston = "2.6 kg"
rod = "1.5 kg"
rod_small_end = "0.8 kg"
[masses]
piston = "2.6 kg"
rod = "3.2 kg"
rod_small_end = "0.9 kg"
[indicator]
epsilon = 17
p_a = "90 kPa"
p_r = "110 kPa"
n1 = 1.37
n2 = 1.25
p_z = "8 MPa"
rho = 1.4
[balance]
throw_spacing = "150 mm"
"""


def test_master_and_articulated_rods_on_every_throw():
    st = solve_engine_text(V8_ART, "v8.toml")
    m = st.model
    assert sorted(m.articulated) == [2, 4, 6, 8]
    assert m.pins == {1: (1, 2), 2: (3, 4), 3: (5, 6), 4: (7, 8)}
    throws = {1: 0.0, 2: 90.0, 3: 270.0, 4: 180.0}
    phi = np.radians(np.arange(0.0, 720.0, 23.0) + 0.5)
    for pin, (master, art) in m.pins.items():
        f = m.cylinder(art, phi)
        theta = phi - math.radians(throws[pin])            # the pin's crank from bank 1
        s = np.array([closure(float(t), math.radians(80.0), math.pi / 2, 0.060, 0.225, 0.055, 0.170)
                      for t in theta])
        sl = m.group.slaves[0]
        assert np.allclose(f.x, sl.s_tdc - s, rtol=0, atol=1e-11)
        assert m.articulated[art].pin == pin
    ch = st.checks
    assert ch.work_error < 1e-9 and ch.pair_torque_error < 1e-9
    # every pin carries its pair's statics: R·T of each pin is the power of its two pistons
    d = st.dense
    for pin, (c1, c2) in m.pins.items():
        total = d.cylinders[c1].M + d.cylinders[c2].M
        assert np.allclose(d.pins[pin].T * 0.060, total, rtol=0, atol=1e-9 * np.abs(total).max())
    # the balancing sees the articulated pistons' odd orders (a central slider-crank has none);
    # the cross-plane crank cancels them between the throws
    b = st.balance
    for art in (2, 4, 6, 8):
        assert abs(b.terms[art][3]) > 1e-3 * abs(b.terms[art][1])
        assert abs(b.terms[art - 1][3]) < 1e-12 * abs(b.terms[art - 1][1])
    report = st.report("ru")
    assert "Прицепной цилиндр 8" in report


# -- double-acting cylinder, p(φ) tables without ε ---------------------------------------------
STEAM = """
kind = "engine"
title = "double-acting steam engine"
[engine]
strokes = 2
speed = "300 rpm"
bore = "200 mm"
crank_radius = "150 mm"
rod_length = "750 mm"
p0 = "100 kPa"
[masses]
piston = "40 kg"
rod = "30 kg"
rod_small_end = "12 kg"
[indicator]
source = "crank_angle"
units = ["deg", "MPa"]
table = {head}
{rod_side}
"""
HEAD = [[0, 1.0], [40, 1.0], [90, 0.55], [150, 0.3], [180, 0.25], [200, 0.12], [300, 0.12],
        [340, 0.4], [360, 1.0]]
CRANK = [[0, 0.9], [50, 0.9], [100, 0.45], [160, 0.28], [180, 0.22], [210, 0.11], [320, 0.11],
         [345, 0.35], [360, 0.9]]


def steam(rod_side: str) -> EngineStudy:
    return solve_engine_text(STEAM.format(head=HEAD, rod_side=rod_side), "steam.toml")


def _interp(table, deg):
    t = np.array(table, float)
    return np.interp(np.mod(deg, 360.0), t[:, 0], t[:, 1]) * 1e6


@pytest.mark.parametrize("own", [False, True])
def test_double_acting_cylinder_forces_from_both_faces(own):
    extra = ('[rod_side]\nrod_diameter = "50 mm"\n' + (
        f'[rod_side.indicator]\nsource = "crank_angle"\nunits = ["deg", "MPa"]\ntable = {CRANK}\n'
        if own else ""))
    st = steam(extra)
    R_, L_, w = 0.15, 0.75, 300 * math.pi / 30
    F = math.pi * 0.2 ** 2 / 4
    F_rod = F - math.pi * 0.05 ** 2 / 4
    deg = np.arange(0.0, 360.0, 7.5) + 0.25
    phi = np.radians(deg)
    f = st.model.cylinder(1, phi)
    p_head = _interp(HEAD, deg)
    # the crank end's own cycle starts at its TDC, the head end's BDC (half a turn later)
    p_crank = _interp(CRANK if own else HEAD, deg - 180.0)
    lam = R_ / L_
    beta = np.arcsin(lam * np.sin(phi))
    a = R_ * w * w * (np.cos(phi + beta) / np.cos(beta) + lam * np.cos(phi) ** 2
                      / np.cos(beta) ** 3)
    P = (p_head - 1e5) * F - (p_crank - 1e5) * F_rod - (40 + 12) * a
    T = P * np.sin(phi + beta) / np.cos(beta)
    assert np.allclose(f.p_rod, p_crank, rtol=1e-12)
    assert np.allclose(f.P, P, rtol=1e-10, atol=1e-6)
    assert np.allclose(f.T, T, rtol=1e-10, atol=1e-6)
    # the work of the torque is the two faces' p–V areas: ∮p dV_head + ∮p_rod dV_rod
    ch = st.checks
    assert ch.work_error < 1e-9
    # independent: the two faces' areas by trapezoids in V on a fine crank-angle grid
    g = np.radians(np.linspace(0.0, 360.0, 400001))
    x = R_ * (1 - np.cos(g)) + L_ * (1 - np.sqrt(1 - (lam * np.sin(g)) ** 2))
    gd = np.degrees(g)
    W = np.trapezoid(_interp(HEAD, gd), F * x) + np.trapezoid(
        _interp(CRANK if own else HEAD, gd - 180.0), -F_rod * x)
    assert ch.work_expected == pytest.approx(W, rel=1e-6)
    report = st.report("en")
    assert "Double-acting cylinder" in report and "swept volume" in report
    doc = st.to_json()
    assert doc["engine"]["V_c"] is None and doc["rod_side"]["rod_diameter"] == 0.05
    assert "p_rod" in doc["angles"][3]["cylinders"]["1"]
    assert st.sheets(None, None, "en", "steam")


def test_p_phi_table_without_epsilon_gives_the_same_forces():
    without = steam("")
    with_eps = solve_engine_text(STEAM.format(head=HEAD, rod_side="epsilon = 12"), "s.toml")
    a, b = without.dense, with_eps.dense
    assert np.allclose(a.M_total, b.M_total, rtol=1e-12, atol=1e-9)
    assert without.checks.work_torque == pytest.approx(with_eps.checks.work_torque, rel=1e-12)
    assert without.model.diagram.V_c_given is False and with_eps.model.diagram.V_c_given
    # the p–V panel is drawn against the swept volume, from 0
    from mechplan.drafting.primitives import Text
    from mechplan.sheet.engine import indicator_panel
    texts = [p.string for p in indicator_panel(without, "en").primitives if isinstance(p, Text)]
    assert any("V − V_c" in t for t in texts)


def test_a_compressor_absorbs_torque():
    comp = [[0, 0.15], [30, 0.1], [60, 0.09], [180, 0.09], [230, 0.2], [300, 0.55], [330, 0.6],
            [360, 0.15]]
    st = solve_engine_text(STEAM.format(head=comp, rod_side="") , "c.toml")
    assert st.checks.work_torque < 0 and st.checks.work_error < 1e-9


@pytest.mark.parametrize(("edit", "key"), [
    ('[rod_side]\nrod_diameter = "250 mm"\n', "rod_side.rod_diameter"),
])
def test_rod_side_errors(edit, key):
    with pytest.raises(SceneError, match=key.replace(".", r"\.")):
        steam(edit)


def test_layout_errors_name_the_key():
    with pytest.raises(SceneError, match=r"engine\.throws"):
        solve_engine_text(RADIAL.format(n=5, engine_extra='throws = ["0 deg", "0 deg", "0 deg", '
                                                          '"0 deg", "0 deg"]', art_extra=""),
                          "r.toml")
    with pytest.raises(SceneError, match=r"articulated\.lug_radius"):
        solve_engine_text(RADIAL.format(n=5, engine_extra="", art_extra="").replace(
            'lug_radius = "60 mm"', 'lug_radius = "260 mm"'), "r.toml")
    with pytest.raises(SceneError, match=r"articulated\.rod_length.*cylinder 2 cannot reach"):
        solve_engine_text(RADIAL.format(n=5, engine_extra="", art_extra="").replace(
            'rod_length = "190 mm"', 'rod_length = "20 mm"'), "r.toml")
    with pytest.raises(SceneError, match=r"engine\.banks"):
        solve_engine_text(V8_ART.replace("cylinders = 8", "cylinders = 8\nbanks = "
                                         '["0 deg", "90 deg"]'), "v.toml")
    with pytest.raises(SceneError, match=r"engine\.cylinders"):
        solve_engine_text(V8_ART.replace("cylinders = 8", "cylinders = 7"), "v.toml")
    with pytest.raises(SceneError, match=r"engine\.throws"):
        solve_engine_text(V8_ART.replace('"0 deg", "0 deg", "90 deg"', '"0 deg", "10 deg", '
                                         '"90 deg"'), "v.toml")


# -- torque extremes between grid points -------------------------------------------------------
@pytest.mark.parametrize("which", ["moto", "radial", "steam"])
def test_torque_extremes_against_a_dense_evaluation(which):
    from mechplan.studies import solve_file
    st = {"moto": lambda: solve_file(TEMPLATES / "motorcycle_engine.toml"),
          "radial": lambda: radial(5),
          "steam": lambda: steam('[rod_side]\nrod_diameter = "50 mm"\n')}[which]()
    ex = st.extremes
    m = st.model
    scale = float(np.abs(st.dense.M_total).max())
    step = st.scene.engine.cycle / st.scene.engine.grid
    for phi_x, M_x, sign in ((ex.phi_max, ex.M_max, 1.0), (ex.phi_min, ex.M_min, -1.0)):
        # a dense independent pass (every cylinder through analyse) around the refined angle
        fine = np.linspace(phi_x - step, phi_x + step, 20001)
        from mechplan.dynamics.engine.analysis import analyse
        dense = analyse(m, fine).M_total
        k = int(np.argmax(sign * dense))
        assert sign * M_x >= sign * dense[k] - 1e-12 * scale
        assert abs(fine[k] - phi_x) <= 2 * step / 20000 + 1e-9
        assert M_x == pytest.approx(float(total_torque(m, np.array([phi_x]))[0]), rel=1e-14)
    # and the refined values bound the whole grid
    assert ex.M_max >= st.dense.M_total.max() - 1e-12 * scale
    assert ex.M_min <= st.dense.M_total.min() + 1e-12 * scale
    doc = st.to_json()["torque"]
    assert doc["max"] == ex.M_max and doc["phi_max_deg"] == pytest.approx(math.degrees(ex.phi_max))


# -- side-by-side rods: their planes' axial offset ---------------------------------------------
def test_side_by_side_rods_axial_offset_makes_a_couple():
    from helpers import moto

    text = moto(engine_extra='layout = "v"\ncylinders = 2\nthrows = ["0 deg", "0 deg"]\n'
                             'banks = ["0 deg", "90 deg"]\nfiring_order = [1, 2]') + (
        '[balance]\nthrow_spacing = "80 mm"\nrod_offset = "24 mm"\n')
    st = solve_engine_text(text, "v2.toml")
    b = st.balance
    m = st.model
    R_, L_, w = 0.0235, 0.106, 8500 * math.pi / 30
    N = 720
    phi = np.arange(N) * 2 * math.pi / N
    moment = np.zeros((N, 2))
    for number, bank, arm in ((1, 0.0, -0.012), (2, math.pi / 2, 0.012)):
        t = phi - m.phases[number]
        beta = np.arcsin(R_ / L_ * np.sin(t))
        a = R_ * w * w * (np.cos(t + beta) / np.cos(beta)
                          + R_ / L_ * np.cos(t) ** 2 / np.cos(beta) ** 3)
        moment += np.outer(m.m_j[number] * a * arm, [math.cos(bank), math.sin(bank)])
    for k in (1, 2):
        e = np.exp(-1j * k * phi)
        C = 2.0 / N * np.array([np.sum(moment[:, 0] * e), np.sum(moment[:, 1] * e)])
        assert np.allclose(b.orders[k].M, C, rtol=0, atol=1e-9 * np.abs(C).max())
    # both rods' rotating masses turn with the one crank at ∓offset/2: no rotating couple
    assert extremes(b.rotating_M)[0] < 1e-9 * extremes(b.rotating_F)[0]
    with pytest.raises(SceneError, match=r"balance\.rod_offset"):
        solve_engine_text(text.replace('throw_spacing = "80 mm"\n', ""), "v2.toml")
    with pytest.raises(SceneError, match=r"balance\.rod_offset"):
        solve_engine_text(RADIAL.format(n=5, engine_extra="", art_extra="")
                          + 'throw_spacing = "80 mm"\nrod_offset = "20 mm"\n', "r.toml")


def test_side_by_side_rods_equal_the_linkage_solver():
    """A 60° V pin with two rods side by side, built as a mechanism (crank, two rods on one pin B,
    two pistons) and solved by mechplan's construction: the closed forms of the `v` layout are
    its exact kinematics."""
    from helpers import moto

    from mechplan.construct.builder import build_construction
    from mechplan.model.structure import analyse
    from mechplan.scene.loader import parse_scene

    st = solve_engine_text(moto(engine_extra='layout = "v"\ncylinders = 2\n'
                                             'throws = ["0 deg", "0 deg"]\n'
                                             'banks = ["0 deg", "60 deg"]\nfiring_order = [1, 2]'),
                           "v.toml")
    text = """
[ground]
A = ["0 mm", "0 mm"]
guides.Ax = { through = "A", angle = "0 deg" }
guides.Ay = { through = "A", angle = "60 deg" }
[links.1]
lengths = { AB = "23.5 mm" }
[links.2]
lengths = { BC = "106 mm" }
[links.3]
slides = { point = "C", on = "Ax" }
[links.4]
lengths = { BE = "106 mm" }
[links.5]
slides = { point = "E", on = "Ay" }
[drive]
link = "1"
speed = "8500 rpm"
sense = "ccw"
from = "Ax"
[assembly]
C = "+"
E = "+"
"""
    scene = parse_scene(text, "pair.toml")
    c = build_construction(scene.mechanism, analyse(scene.mechanism),
                           ("position", "velocity", "acceleration"), scene.assembly_phi,
                           scene.path, None)
    phi = np.radians(np.arange(0.0, 720.0, 11.0) + 0.3)
    ev = c.evaluate(np.mod(phi, 2 * math.pi))
    for number, point, bank in ((1, "C", 0.0), (2, "E", math.pi / 3)):
        u = np.array([math.cos(bank), math.sin(bank)])
        f = st.model.cylinder(number, phi)
        s = ev[c.position(point)] @ u
        assert np.allclose(f.x, 0.0235 + 0.106 - s, rtol=0, atol=1e-13)
        assert np.allclose(f.v, -(ev[c.velocity_image(point)] @ u), rtol=0,
                           atol=1e-12 * np.abs(f.v).max())
        assert np.allclose(f.a, -(ev[c.acceleration_image(point)] @ u), rtol=0,
                           atol=1e-12 * np.abs(f.a).max())


def test_double_acting_table_and_csv_carry_the_crank_end_pressure():
    import csv
    import io

    st = steam('[rod_side]\nrod_diameter = "50 mm"\n')
    rows = list(csv.DictReader(io.StringIO(st.to_csv())))
    doc = st.to_json()
    for r, a in zip(rows, doc["angles"]):
        assert float(r["p_rod_MPa_1"]) * 1e6 == pytest.approx(a["cylinders"]["1"]["p_rod"],
                                                             rel=1e-8)
    from mechplan.sheet.engine import table_cells
    cells = table_cells(st.table, "en")
    assert cells[0][2] == "p_rod, MPa" and len(cells[1]) == len(cells[0])
    assert "p_rod, MPa" in st.report("en")


def test_double_acting_thermal_diagram_on_the_crank_end():
    """The head end's thermal diagram on the crank end (four-stroke, sharp corners: p a function
    of V on each stroke): at every angle the crank end's pressure is the head end's at the same
    stroke fraction of the same stroke, and the work check closes over the knots of both faces.
    (Rounded, the corners sit at crank angles of the crank end's own kinematics, so they differ.)"""
    from helpers import moto

    rounded = solve_engine_text(moto() + '[rod_side]\nrod_diameter = "20 mm"\n', "da.toml")
    assert rounded.checks.work_error < 1e-9
    st = solve_engine_text(moto(indicator_extra="rounding = false")
                           + '[rod_side]\nrod_diameter = "20 mm"\n', "da.toml")
    m = st.model
    S = 2 * 0.0235
    phi = np.radians(np.arange(0.0, 720.0, 9.0) + 0.4)
    f = m.cylinder(1, phi)
    xi_rod = 1.0 - f.x / S                          # the crank end's own stroke fraction
    own = np.mod(phi - math.pi, 4 * math.pi)        # its own cycle angle
    k = np.floor(own / math.pi).astype(int)
    # the head end's angle with that stroke fraction on that stroke
    head = m.kin.phi_of_x(xi_rod * S, False)
    head = np.where(k % 2 == 1, 2 * math.pi - head, head) + 2 * math.pi * (k // 2)
    assert np.allclose(m.cylinder(1, head).x / S, xi_rod, atol=1e-12)
    assert np.allclose(f.p_rod, m.cylinder(1, head).p, rtol=1e-12)
    assert st.checks.work_error < 1e-9
    F = math.pi * 0.0565 ** 2 / 4
    ratio = (F - math.pi * 0.02 ** 2 / 4) / F
    assert st.checks.work_expected == pytest.approx(st.checks.work_diagram * (1 + ratio), rel=1e-9)


def test_radial_lug_angles_given():
    lugs = [72.0 + 5.0, 144.0, -144.0, -72.0]
    st = radial(5, art_extra="lug_angles = [" + ", ".join(f'"{a} deg"' for a in lugs) + "]")
    group = st.model.group
    state = group.state(ANGLES)
    for k, sl in enumerate(group.slaves):
        bank = 2 * math.pi * (k + 1) / 5
        s = np.array([closure(t, math.radians(lugs[k]), bank) for t in ANGLES])
        assert np.max(np.abs(state.E[k] @ sl.u - s)) < 1e-12 * L
    same = radial(5, art_extra='lug_angles = ["72 deg", "144 deg", "216 deg", "288 deg"]')
    assert np.allclose(same.dense.M_total, radial(5).dense.M_total, rtol=1e-12, atol=1e-9)
