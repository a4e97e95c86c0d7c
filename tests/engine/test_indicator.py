"""Indicator diagrams: closed-form works, tables, and the errors naming their keys."""

from __future__ import annotations

import math

import numpy as np
import pytest
from helpers import moto
from scipy.integrate import quad

from mechplan.dynamics.engine.kinematics import SliderCrank
from mechplan.dynamics.indicator import angle_table_diagram, thermal_diagram, volume_table_diagram
from mechplan.errors import SceneError
from mechplan.model.engine import ThermalSpec
from mechplan.studies import solve_text

R, L, D = 0.0235, 0.106, 0.0565
F_P = math.pi * D * D / 4


def _closed_form_work(eps, p_a, p_r, n1, n2, p_z, rho, V_h):
    """∮p dV of the sharp-cornered diagram, integrated by hand."""
    V_c = V_h / (eps - 1)
    V_a = V_c + V_h
    V_z = rho * V_c
    intake = p_a * V_h
    compression = -p_a * V_a * (eps ** (n1 - 1) - 1) / (n1 - 1)
    expansion = p_z * (V_z - V_c) + p_z * V_z * (1 - (V_z / V_a) ** (n2 - 1)) / (n2 - 1)
    exhaust = -p_r * V_h
    return intake + compression + expansion + exhaust


@pytest.mark.parametrize("rho", [1.0, 1.5])
def test_sharp_diagram_work_matches_closed_form(rho):
    spec = ThermalSpec(9.0, 85e3, 110e3, 1.32, 1.23, 6.98e6, rho, rounding=False)
    kin = SliderCrank(R, L)
    dia = thermal_diagram(spec, 4, kin, F_P)
    expected = _closed_form_work(9.0, 85e3, 110e3, 1.32, 1.23, 6.98e6, rho, F_P * 2 * R)
    assert math.isclose(dia.work(), expected, rel_tol=1e-12)


def test_rounded_diagram_keeps_the_polytropes_away_from_the_corners():
    spec = ThermalSpec(9.0, 85e3, 110e3, 1.32, 1.23, 6.98e6)
    kin = SliderCrank(R, L)
    dia = thermal_diagram(spec, 4, kin, F_P)
    V_h = F_P * 2 * R
    V_c = V_h / 8
    V = V_c + 0.5 * V_h
    assert math.isclose(float(dia.pressure(V, 1)), 85e3 * ((V_c + V_h) / V) ** 1.32, rel_tol=1e-13)
    assert math.isclose(float(dia.pressure(V, 2)), 6.98e6 * (V_c / V) ** 1.23, rel_tol=1e-13)
    # the real peak is 0.85 p_z, at 12° after TDC
    phi = np.radians(np.linspace(360, 400, 4001))
    p = dia.at_phi(phi, kin.x(phi) / (2 * R))
    assert math.isclose(p.max(), 0.85 * 6.98e6, rel_tol=1e-9)
    assert abs(math.degrees(phi[np.argmax(p)]) - 372.0) < 0.02
    assert math.isclose(float(dia.pressure(V_c, 1)), 1.2 * 85e3 * 9 ** 1.32, rel_tol=1e-12)


def test_volume_table_work_is_the_shoelace_area():
    kin = SliderCrank(R, L)
    dia = thermal_diagram(ThermalSpec(9.0, 85e3, 110e3, 1.32, 1.23, 6.98e6), 4, kin, F_P)
    phi = np.radians(np.arange(0, 721, 5.0))
    V = dia.V_c + F_P * kin.x(phi)
    p = dia.at_phi(phi, kin.x(phi) / (2 * R))
    p[-1] = p[0]
    table = volume_table_diagram(list(zip(V, p)), 4, F_P * 2 * R, "f", "indicator.table")
    shoelace = 0.5 * np.sum(V[:-1] * p[1:] - V[1:] * p[:-1])   # counter-clockwise in (V, p)
    assert math.isclose(table.work(), -shoelace, rel_tol=1e-12)


def test_angle_table_work_by_quadrature():
    kin = SliderCrank(R, L)
    lam = R / L
    phi_n = np.radians(np.arange(0, 721, 30.0))
    p_n = 1e5 + 1e6 * np.exp(-((phi_n - 4 * np.pi / 2 - 0.2) ** 2) / 0.3)
    p_n[-1] = p_n[0]
    dia = angle_table_diagram(list(zip(phi_n, p_n)), 4, kin, F_P, 9.0, "f", "indicator.table")

    def dV(f):   # dV/dφ, written out here
        s = math.sin(f)
        return F_P * R * s * (1 + lam * math.cos(f) / math.sqrt(1 - lam * lam * s * s))

    total = 0.0
    for a, b, pa, pb in zip(phi_n, phi_n[1:], p_n, p_n[1:]):
        def integrand(f, a=a, b=b, pa=pa, pb=pb):
            return (pa + (pb - pa) * (f - a) / (b - a)) * dV(f)

        total += quad(integrand, a, b, epsabs=0, epsrel=1e-13)[0]
    assert math.isclose(dia.work(), total, rel_tol=1e-9)


def test_volume_table_not_closed_names_the_key():
    with pytest.raises(SceneError, match=r"indicator\.table.*closed cycle"):
        text = moto(indicator_extra="").replace(
            "[indicator]\nepsilon = 9", '[indicator]\nsource = "volume"\nunits = ["cm^3", "MPa"]\n'
            "table = [[14.73, 0.1], [132.57, 0.1], [14.73, 1.5], [132.57, 0.3], [14.73, 0.2]]\n#")
        text = "\n".join(line for line in text.splitlines()
                         if not line.startswith(("p_a", "p_r", "n1", "n2", "p_z")))
        solve_text(text, "v.toml")


def test_pressure_below_vacuum_is_refused():
    with pytest.raises(SceneError, match=r"indicator\.p_a.*above vacuum"):
        solve_text(moto().replace('p_a = "85 kPa"', 'p_a = "-5 kPa"'), "n.toml")


def _sampled(step_deg):
    base = solve_text(moto(), "m.toml")
    kin, dia = base.model.kin, base.model.diagram
    phi = np.radians(np.arange(0, 720 + step_deg, step_deg))
    V = dia.V_c + F_P * kin.x(phi)
    p = dia.at_phi(phi, kin.x(phi) / (2 * R))
    p[-1] = p[0]
    return phi, V, p


def test_volume_table_from_a_csv_file(tmp_path):
    _, V, p = _sampled(5.0)
    (tmp_path / "pv.csv").write_text("V_cm3,p_MPa\n" + "\n".join(
        f"{float(a) * 1e6!r},{float(b) * 1e-6!r}" for a, b in zip(V, p)), encoding="utf-8")
    text = moto().split("[indicator]")[0] + (
        '[indicator]\nsource = "volume"\nunits = ["cm^3", "MPa"]\nfile = "pv.csv"\n')
    st = solve_text(text, str(tmp_path / "s.toml"))
    shoelace = 0.5 * np.sum(V[:-1] * p[1:] - V[1:] * p[:-1])
    assert math.isclose(st.checks.work_diagram, -shoelace, rel_tol=1e-9)
    assert st.checks.work_error < 1e-9


def test_angle_table_in_a_scene_closes_its_work():
    phi, _, p = _sampled(10.0)
    rows = ", ".join(f"[{math.degrees(float(f))!r}, {float(b) * 1e-6!r}]" for f, b in zip(phi, p))
    text = moto().split("[indicator]")[0] + (
        f'[indicator]\nsource = "crank_angle"\nepsilon = 9\ntable = [{rows}]\n')
    st = solve_text(text, "a.toml")
    assert st.checks.work_error < 1e-9
    # at the table's nodes p(φ) is the table itself
    f = st.model.cylinder(1, phi[:-1])
    assert np.allclose(f.p, p[:-1], rtol=1e-7)   # the dead centres invert through a square root


def test_negative_table_pressure_is_refused():
    text = moto().split("[indicator]")[0] + (
        '[indicator]\nsource = "crank_angle"\nepsilon = 9\n'
        'table = [[0, 0.1], [180, 0.1], [360, -0.2], [540, 0.1], [720, 0.1]]\n')
    with pytest.raises(SceneError, match=r"indicator\.table.*below vacuum"):
        solve_text(text, "a.toml")
