"""Balancing of engines against the classical closed-form results, the λ-series of the exact
piston acceleration, quadrature of the exact piston position and finite differences."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad

from mechplan.dynamics.engine.balance import N_FFT, extremes, harmonics
from mechplan.errors import SceneError
from mechplan.model.engine import CylinderSpec, firing_phases
from mechplan.scene.engine import parse_engine_scene
from mechplan.studies.engine import EngineStudy

R, L, RPM = 0.04, 0.16, 3000.0
W = RPM * math.pi / 30.0
RW2 = R * W * W
LAM = R / L
PISTON, ROD, SMALL, EXTRA, CRANK = 0.5, 0.6, 0.2, 0.05, 0.3
MJ = PISTON + SMALL                 # reciprocating mass per cylinder
MR = ROD - SMALL + EXTRA            # rotating mass per rod
A = 0.09                            # throw spacing


def _deg(xs) -> str:
    return "[" + ", ".join(f'"{x} deg"' for x in xs) + "]"


def _order(throws, banks, strokes=4) -> list[int]:
    """Any firing order the throws admit (balance does not depend on it)."""
    n = len(throws)
    cyl = tuple(CylinderSpec(i + 1, math.radians(t), math.radians(b), False)
                for i, (t, b) in enumerate(zip(throws, banks)))
    for rest in itertools.permutations(range(2, n + 1)):
        try:
            firing_phases(cyl, (1, *rest), strokes)
            return [1, *rest]
        except ValueError:
            continue
    raise AssertionError("no firing order")


def scene(throws, banks=None, layout="inline", balance='throw_spacing = "90 mm"') -> str:
    n = len(throws)
    banks = banks or [0] * n
    return f"""
kind = "engine"
title = "test"
[engine]
strokes = 4
speed = "{RPM} rpm"
bore = "80 mm"
crank_radius = "{R * 1e3} mm"
rod_length = "{L * 1e3} mm"
layout = "{layout}"
cylinders = {n}
firing_order = {_order(throws, banks)}
throws = {_deg(throws)}
banks = {_deg(banks)}
[masses]
piston = "{PISTON} kg"
rod = "{ROD} kg"
rod_small_end = "{SMALL} kg"
rotating_extra = "{EXTRA} kg"
crank = "{CRANK} kg"
[indicator]
epsilon = 9
p_a = "85 kPa"
p_r = "110 kPa"
n1 = 1.32
n2 = 1.23
p_z = "6 MPa"
[balance]
{balance}
"""


def solved(text: str) -> EngineStudy:
    return EngineStudy(parse_engine_scene(text, "test.toml"))


def close(x: float, y: float, scale: float, tol: float = 1e-9) -> None:
    assert abs(x - y) <= tol * scale, (x, y)


# -- the exact piston motion ----------------------------------------------------------------------
def _x(psi: float) -> float:
    """Exact piston travel from TDC, written out here (not the code's)."""
    return R * (1 - math.cos(psi)) + L * (1 - math.sqrt(1 - (LAM * math.sin(psi)) ** 2))


def test_exact_acceleration_against_finite_differences():
    st = solved(scene([0]))
    psi = np.linspace(0.0, 2 * math.pi, 73)
    h = 1e-4
    fd = np.array([(_x(p + h) - 2 * _x(p) + _x(p - h)) / h ** 2 for p in psi]) * W * W
    a = st.model.kin.a(psi, W)
    assert np.max(np.abs(a - fd)) < 1e-5 * RW2


def test_harmonics_against_quadrature_of_the_position():
    """A_k = −k²·x_k/R with x_k the cosine coefficient of the exact travel (quadrature)."""
    st = solved(scene([0]))
    psi = np.arange(N_FFT) * 2 * math.pi / N_FFT
    c = harmonics(st.model.kin.a(psi, W)) / RW2
    for k in range(1, 9):
        x_k = quad(lambda p, k=k: _x(p) * math.cos(k * p), 0, 2 * math.pi, epsabs=1e-14,
                   limit=200)[0] / math.pi
        close(c[k].real, -k * k * x_k / R, 1.0, 1e-10)
        assert abs(c[k].imag) < 1e-12


@pytest.mark.parametrize("lam", [0.1, 0.2, 0.3])
def test_harmonics_against_the_closed_lambda_series(lam):
    """a/(Rω²) = cos φ + A2 cos 2φ − A4 cos 4φ + A6 cos 6φ …,
    A2 = λ + λ³/4 + 15λ⁵/128, A4 = λ³/4 + 3λ⁵/16, A6 = 9λ⁵/128 (to O(λ⁷))."""
    from mechplan.dynamics.engine.kinematics import SliderCrank

    kin = SliderCrank(1.0, 1.0 / lam)
    psi = np.arange(N_FFT) * 2 * math.pi / N_FFT
    c = harmonics(kin.a(psi, 1.0)).real
    tol = 2 * lam ** 7
    close(c[1], 1.0, 1.0, 1e-12)
    close(c[2], lam + lam ** 3 / 4 + 15 * lam ** 5 / 128, 1.0, tol)
    close(c[4], -(lam ** 3 / 4 + 3 * lam ** 5 / 16), 1.0, tol)
    close(c[6], 9 * lam ** 5 / 128, 1.0, tol)
    assert np.max(np.abs(c[3::2][:10])) < 1e-12          # no odd orders above the first


# -- classical layouts ----------------------------------------------------------------------------
def test_inline_four():
    st = solved(scene([0, 180, 180, 0], balance='throw_spacing = "90 mm"\nbalance_shafts = true'))
    b = st.balance
    A2 = b.orders[2].A
    scale = MJ * RW2
    for k in (1, 3, 5):
        close(b.orders[k].F_max, 0.0, scale)
    for k in range(1, 7):
        close(b.orders[k].M_max, 0.0, scale * A)
    close(b.orders[2].F_max, 4 * MJ * RW2 * A2, scale)
    close(extremes(b.orders[2].F_series)[0], 4 * MJ * RW2 * LAM, scale)
    close(b.orders[4].F_max, 4 * MJ * RW2 * b.orders[4].A, scale)
    # the 2nd-order force is along the cylinders: 4·m_j·R·ω²·A2·cos 2φ
    F = b.orders[2].F
    close(abs(F[1]), 0.0, scale)
    close(F[0].real, 4 * MJ * RW2 * A2, scale)
    # rotating masses and the 1st order balanced by the crank's symmetry
    close(extremes(b.rotating_F)[0], 0.0, scale)
    close(extremes(b.rotating_M)[0], 0.0, scale * A)
    # Lanchester: two shafts at 2ω, each m·r = m_j·R·A2/2, masses pointing away from the cylinders
    s = b.shafts
    close(s.mr_with, MJ * R * A2 / 2, MJ * R)
    close(s.mr_against, MJ * R * A2 / 2, MJ * R)
    close(math.cos(s.angle_with), -1.0, 1.0)
    close(math.cos(s.angle_against), -1.0, 1.0)
    # with the series: m·r = m_j·R·λ/2 (the textbook figure)
    assert abs(b.orders[2].A_series - LAM) < 1e-15


def test_inline_six_balanced_in_the_first_and_second_order():
    st = solved(scene([0, 240, 120, 120, 240, 0]))
    b = st.balance
    scale = MJ * RW2
    for k in (1, 2, 4, 5):
        close(b.orders[k].F_max, 0.0, scale)
        close(b.orders[k].M_max, 0.0, scale * A)
    close(b.orders[6].F_max, 6 * MJ * RW2 * b.orders[6].A, scale)
    close(b.orders[6].A, 9 * LAM ** 5 / 128, 1.0, 2 * LAM ** 7)
    close(extremes(b.rotating_F)[0], 0.0, scale)
    close(extremes(b.rotating_M)[0], 0.0, scale * A)


def test_cross_plane_v8():
    """90° V8, throws 0-90-270-180: a rotating 1st-order couple √10·a·(2m_r + m_crank + m_j)·Rω²,
    cancelled by counterweights for the rotating masses and half the reciprocating ones."""
    throws = [0, 0, 90, 90, 270, 270, 180, 180]
    banks = [0, 90] * 4
    st = solved(scene(throws, banks, layout="v"))
    b = st.balance
    scale = MJ * RW2
    couple = math.sqrt(10) * A * (2 * MR + CRANK + MJ) * RW2
    hi, lo = extremes(b.before_M)
    close(hi, couple, couple)
    close(lo, couple, couple)                      # constant magnitude: it turns with the crank
    close(extremes(b.before_F)[0], 0.0, scale)
    close(b.orders[2].F_max, 0.0, scale)
    close(b.orders[2].M_max, 0.0, scale * A)
    close(extremes(b.after_F)[0], 0.0, scale)
    close(extremes(b.after_M)[0], 0.0, scale * A)
    for p in range(1, 5):
        close(b.counterweights.per_cheek[p], (2 * MR + CRANK + MJ) * R / 2, MJ * R)


def test_boxer_twin_first_order_couple():
    st = solved(scene([0, 180], [0, 180]))
    b = st.balance
    scale = MJ * RW2
    close(b.orders[1].F_max, 0.0, scale)
    close(b.orders[2].F_max, 0.0, scale)
    close(b.orders[1].M_max, MJ * RW2 * A, scale * A)
    close(b.orders[2].M_max, MJ * RW2 * b.orders[2].A * A, scale * A)
    close(extremes(b.orders[2].M_series)[0], MJ * RW2 * LAM * A, scale * A)
    close(extremes(b.rotating_M)[0], (MR + CRANK) * RW2 * A, scale * A)


def test_single_cylinder_counterweight_halves_the_first_order():
    st = solved(scene([0], balance='counterweight_radius = "50 mm"'))
    b = st.balance
    close(b.orders[1].F_max, MJ * RW2, MJ * RW2)
    hi, lo = extremes(b.after_F)
    close(hi, MJ * RW2 / 2, MJ * RW2)              # what is left turns against the crank
    close(lo, MJ * RW2 / 2, MJ * RW2)
    cw = b.counterweights
    close(cw.per_cheek[1], (MR + CRANK + MJ / 2) * R / 2, MJ * R)
    close(cw.mass[1], (MR + CRANK + MJ / 2) * R / 2 / 0.05, MJ)
    assert not b.spacing_given


def test_ninety_degree_v_twin_fully_balanced_by_half_the_reciprocating_mass():
    st = solved(scene([0, 0], [0, 90], layout="v"))
    b = st.balance
    hi, lo = extremes(b.orders[1].F)
    close(hi, MJ * RW2, MJ * RW2)
    close(lo, MJ * RW2, MJ * RW2)
    close(extremes(b.after_F)[0], 0.0, MJ * RW2)


def test_series_difference_is_the_higher_orders():
    b = solved(scene([0])).balance
    phi = np.arange(N_FFT) * 2 * math.pi / N_FFT
    exact = MJ * RW2 * (np.cos(phi) + b.orders[2].A * np.cos(2 * phi))
    series = MJ * RW2 * (np.cos(phi) + LAM * np.cos(2 * phi))
    assert np.max(np.abs(b.total_series[:, 0] - series)) < 1e-9 * MJ * RW2
    assert np.max(np.abs(b.total_exact[:, 0] - exact)) < 0.02 * MJ * RW2


def test_journals_unloaded_by_the_counterweights():
    b = solved(scene([0])).balance
    before = np.hypot(*b.counterweights.journals_before[0].T)
    after = np.hypot(*b.counterweights.journals_after[0].T)
    assert after.mean() < before.mean()


def test_articulated_pair_has_odd_orders():
    from pathlib import Path

    import mechplan
    from mechplan.studies import solve_file

    st = solve_file(Path(mechplan.__file__).parent / "templates" / "v_engine_dynamics.toml")
    b = st.balance
    assert b.orders[3].F_max > 1e-6 * b.orders[1].F_max


# -- scene ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("extra, key", [
    ('throw_positions = ["0 mm"]', "balance.throw_positions"),
    ('throw_spacing = "90 mm"\nthrow_positions = ["0 mm", "1 mm"]', "balance.throw_positions"),
    ("counterweight_share = 1.5", "balance.counterweight_share"),
    ("orders = 1", "balance.orders"),
    ('balance_shafts = "yes"', "balance.balance_shafts"),
    ("colour = 1", "balance"),
])
def test_scene_errors(extra, key):
    with pytest.raises(SceneError) as e:
        parse_engine_scene(scene([0, 180], balance=extra), "test.toml")
    assert key in str(e.value)


def test_report_and_json():
    st = solved(scene([0, 180, 180, 0], balance='throw_spacing = "90 mm"\nbalance_shafts = true'))
    doc = st.to_json()["balance"]
    assert set(doc["orders"]) == {str(k) for k in range(1, 7)}
    assert doc["balance_shafts"]["mr_with"] > 0
    from mechplan.i18n import message, number

    for lang in ("en", "ru", "vi", "zh"):
        text = st.report(lang)
        assert message("balance.report.title", lang) in text
        assert number(doc["balance_shafts"]["mr_with"] * 1e3, 3, lang) in text


LAYOUTS = {
    "I3": ([0, 240, 120], None, "inline"),
    "I5": ([0, 144, 288, 72, 216], None, "inline"),
    "boxer4": ([0, 180, 180, 0], [0, 180, 0, 180], "inline"),
    "V6_60": ([0, 0, 120, 120, 240, 240], [0, 60] * 3, "v"),
    "V6_90_split": ([0, 30, 120, 150, 240, 270], [0, 90] * 3, "v"),
    "V8_flat": ([0, 0, 180, 180, 180, 180, 0, 0], [0, 90] * 4, "v"),
    "V2_45": ([0, 0], [0, 45], "v"),
}


@pytest.mark.parametrize("name", LAYOUTS)
def test_orders_against_direct_summation_over_the_turn(name):
    """Each cylinder's force summed over the turn (the λ-series and the exact acceleration
    written out here, 4096 angles), its maximum over the turn against the amplitudes' ellipse."""
    throws, banks, layout = LAYOUTS[name]
    st = solved(scene(throws, banks, layout=layout))
    b = st.balance
    banks = banks or [0] * len(throws)
    phi = np.arange(8 * N_FFT) * 2 * math.pi / (8 * N_FFT)
    pin = {i: (i // 2 if layout == "v" else i) for i in range(len(throws))}
    z = {i: pin[i] * A for i in range(len(throws))}
    z0 = (min(z.values()) + max(z.values())) / 2
    F1 = np.zeros((phi.size, 2))
    F2 = np.zeros((phi.size, 2))
    M1 = np.zeros((phi.size, 2))
    M2 = np.zeros((phi.size, 2))
    Fx = np.zeros((phi.size, 2))
    for i, (t, g) in enumerate(zip(throws, banks)):
        psi = phi - math.radians(t + g)
        u = np.array([math.cos(math.radians(g)), math.sin(math.radians(g))])
        f1 = MJ * RW2 * np.cos(psi)[:, None] * u
        f2 = MJ * RW2 * LAM * np.cos(2 * psi)[:, None] * u
        F1 += f1
        F2 += f2
        M1 += f1 * (z[i] - z0)
        M2 += f2 * (z[i] - z0)
        sb = LAM * np.sin(psi)
        cb = np.sqrt(1 - sb ** 2)
        a = RW2 * ((np.cos(psi) * cb - np.sin(psi) * sb) / cb + LAM * np.cos(psi) ** 2 / cb ** 3)
        Fx += MJ * a[:, None] * u
    scale = MJ * RW2
    for got, want, s in ((extremes(b.orders[1].F_series)[0], F1, scale),
                         (extremes(b.orders[2].F_series)[0], F2, scale),
                         (extremes(b.orders[1].M_series)[0], M1, scale * A),
                         (extremes(b.orders[2].M_series)[0], M2, scale * A),
                         (b.orders[1].F_max, F1, scale), (b.orders[1].M_max, M1, scale * A)):
        close(got, float(np.max(np.hypot(*want.T))), s, 1e-5)
    assert np.max(np.abs(b.total_exact - Fx[::8])) < 1e-9 * scale


def test_star_panels_polygons_close_where_the_order_is_balanced():
    """In-line four: the 1st-order force polygon closes (no resultant drawn); the 2nd-order one
    has a dashed resultant along the cylinders (at φ = 0 the order's force points outwards)."""
    from mechplan.drafting.primitives import Line, Role
    from mechplan.sheet.engine_balance import star_panel

    st = solved(scene([0, 180, 180, 0]))
    b = st.balance
    banks = {n: 0.0 for n in range(1, 5)}

    def resultants(k):
        panel = star_panel(b, st.model.phases, banks, k, "en")
        return [p for p in panel.primitives if isinstance(p, Line) and p.role is Role.DASHED]

    assert resultants(1) == []
    (r2,) = resultants(2)
    assert r2.end[0] - r2.start[0] > 10.0
    assert abs(r2.end[1] - r2.start[1]) < 1e-9
    # the star of the 2nd order has all four cranks on one ray
    from mechplan.drafting.primitives import Text
    panel = star_panel(b, st.model.phases, banks, 2, "en")
    assert any(isinstance(p, Text) and p.string == "1,2,3,4" for p in panel.primitives)


def test_sixty_degree_v6_on_three_pins():
    """60° V6, pins at 0/120/240° (two rods per pin): per pin the 1st order is m_jRω² turning with
    the crank plus ½m_jRω² turning against it; over the pins (z = −a, 0, a) each gives a couple
    √3·a times that. Counterweights for the rotating masses and half the reciprocating ones leave
    only the couple √3/2·a·m_jRω² turning against the crank (the balance shaft's job)."""
    st = solved(scene([0, 0, 120, 120, 240, 240], [0, 60] * 3, layout="v"))
    b = st.balance
    s = MJ * RW2 * A
    hi, lo = extremes(b.orders[1].M)
    close(hi, 1.5 * math.sqrt(3) * s, s)
    close(lo, 0.5 * math.sqrt(3) * s, s)
    close(b.orders[1].F_max, 0.0, MJ * RW2)
    hi, lo = extremes(b.after_M)
    close(hi, math.sqrt(3) / 2 * s, s)
    close(lo, math.sqrt(3) / 2 * s, s)
    close(extremes(b.rotating_M)[0], math.sqrt(3) * A * (2 * MR + CRANK) * RW2, s)
