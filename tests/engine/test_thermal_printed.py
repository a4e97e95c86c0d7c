"""Printed numbers of public course calculations that our steps must reproduce.

No complete printed worked example of the Kolchin–Demidov thermal calculation (inputs and every
intermediate result) could be read in the sources at hand (see docs/engine.md, "Thermal
calculation: sources"). What could be read are single steps of students' course calculations
printed with all their inputs, and the beginning of a Chinese course's worked diesel example
(fuel chemistry and intake); they check our formulas for those steps at the rounding of the
print. The steps that depend on the heat-capacity fits (T_z, p_z) could not be checked this way:
the pages that print them use other fits (20.16 + 1.74·10⁻³·T) or hide the inputs in images.
"""

from __future__ import annotations

import pytest

from mechplan.model.engine_thermal import CycleSpec, compression, end_of_intake, thermal_cycle


def test_compression_of_a_petrol_engine_allrefs():
    """allrefs.net/c35/1x6m5/p3/?full ("ПРОЦЕСС СЖАТИЯ"): p_a = 0.0893 MPa, ε = 8.2, n1 = 1.37 →
    p_c = 1.595 MPa; T_a = 340.6 K → T_c = 741.918 K (printed to three decimals)."""
    p_c, T_c = compression(0.0893e6, 340.6, 8.2, 1.37)
    assert p_c * 1e-6 == pytest.approx(1.595, abs=0.0005)
    assert T_c == pytest.approx(741.918, abs=0.0005)


def test_compression_of_a_supercharged_diesel_ukrbukva():
    """ukrbukva.net/page,4,68638 (Розробка двигуна внутрішнього згоряння, 2.2): p_a = 0.187 MPa,
    ε = 16, n1 = 1.365 → p_c = 8.239 MPa. We get 8.2312 MPa (−0.09 %): the page's p_a is itself
    0.9·0.2077 = 0.18693 rounded to 0.187, and p_a within the rounding of its print (0.1865 …
    0.1875) covers the printed p_c."""
    lo, _ = compression(0.1865e6, 300.0, 16.0, 1.365)
    hi, _ = compression(0.1875e6, 300.0, 16.0, 1.365)
    assert lo * 1e-6 <= 8.239 <= hi * 1e-6
    p_c, _ = compression(0.187e6, 300.0, 16.0, 1.365)
    assert abs(p_c * 1e-6 / 8.239 - 1.0) < 1e-3


def test_end_of_intake_manytransport():
    """manytransport.ru/maors-355-1.html ("Процесс впуска"): T_a = (288 + 20 + 0.051·1000)/
    (1 + 0.051) = 342 K."""
    assert end_of_intake(288.0 + 20.0, 1000.0, 0.051) == pytest.approx(342.0, abs=0.5)


def test_fuel_chemistry_of_a_diesel_2862():
    """www.2862.com.cn/DoPqXJWv/ ("Z3102增压柴油机热力计算", a Chinese course's worked diesel
    example): g_C = 0.87, g_H = 0.126, g_O = 0.004, Φa = 1.8, φr = 0, O2 in air 0.21 →
    L0 = 0.495 kmol/kg, M2 = M1 + g_H/4 + g_O/32 (0.866 → 0.8974), μ0 = 1.036; T_a = 340 K from
    T_s = 330 K, ΔT = 10 K. The page prints M1 = 1.8·0.495 = 0.866 (the product is 0.891): its μ0
    is M2/M1 of those printed numbers, 1.0363, and ours with M1 = 0.891 is 1.0355 — both 1.036 at
    the print's rounding. With Kolchin–Demidov's 0.208 L0 would be 0.4994 (+0.9 %): the O2
    fraction is a convention of the book (``air_oxygen``)."""
    spec = CycleSpec(True, 0.87, 0.126, 0.004, 42.5e3, 0.0, 1.8, 14.0, 1800, 0.17e6, 330.0,
                     10.0, 0.153e6, 0.0, 900.0, 1.38, 1.25, 0.75, 1.5, 0.5, 0.96, 0.87, 4, 3,
                     air_O2=0.21)
    c = thermal_cycle(spec)
    assert round(c.L0, 3) == 0.495
    assert c.M2 - c.M1 == pytest.approx(0.126 / 4 + 0.004 / 32, abs=1e-12)
    assert abs((0.8974 - 0.866) - (c.M2 - c.M1)) <= 0.0005 + 0.00005   # the print's rounding
    assert round(c.mu0, 3) == 1.036
    assert c.gamma_r == 0.0 and c.T_a == pytest.approx(340.0, abs=1e-12)
    kolchin = thermal_cycle(CycleSpec(True, 0.87, 0.126, 0.004, 42.5e3, 0.0, 1.8, 14.0, 1800,
                                      0.17e6, 330.0, 10.0, 0.153e6, 0.0, 900.0, 1.38, 1.25, 0.75,
                                      1.5, 0.5, 0.96, 0.87, 4, 3))
    assert kolchin.L0 == pytest.approx(0.4994, abs=5e-5)


def test_charge_coefficient_of_the_diesel_2862():
    """www.2862.com.cn/DoPqXJWv/ ("Z3102增压柴油机热力计算", ②进气过程计算 3): the charge
    coefficient φc = εc/(εc − 1)·(p_a/p_s)·(T_s/T_a)·1/(1 + φr) = 14/13 · 0.153/0.17 · 330/340 =
    0.941 (printed to three decimals: tolerance 0.0005). Ours is η_v = T0/(T0 + ΔT)·(ε·p_a −
    p_r)/((ε − 1)·p0) with the page's intake state as T0, p0 (T_s 330 K, p_s = 1.7·100 kPa) and
    no residual gases (p_r = 0): the same formula, 0.94072."""
    spec = CycleSpec(True, 0.87, 0.126, 0.004, 42.5e3, 0.0, 1.8, 14.0, 1800, 0.17e6, 330.0,
                     10.0, 0.153e6, 0.0, 900.0, 1.38, 1.25, 0.75, 1.5, 0.5, 0.96, 0.87, 4, 3,
                     air_O2=0.21)
    c = thermal_cycle(spec)
    assert abs(c.eta_v - 0.941) <= 0.0005
    assert c.eta_v == pytest.approx(14.0 / 13.0 * 0.153 / 0.17 * 330.0 / 340.0, rel=1e-12)
