"""The thermal calculation against independent computations: the mass balance of the combustion,
the theoretical mean indicated pressure by quadrature of the p–V cycle, the combustion equation
solved by root-finding, power and cylinder size inverse to each other, and the diagram it feeds."""

from __future__ import annotations

import math

import pytest
from helpers import diesel_2600
from scipy.integrate import quad
from scipy.optimize import brentq

from mechplan.errors import SceneError
from mechplan.model.engine_thermal import HIGH, LOW, CycleSpec, thermal_cycle
from mechplan.scene.engine import parse_engine_scene
from mechplan.studies.engine import EngineStudy

MOLAR = {"CO2": 44.01, "CO": 28.01, "H2O": 18.015, "H2": 2.016, "N2": 28.013, "O2": 31.999}


def petrol(alpha=0.96) -> CycleSpec:
    return CycleSpec(False, 0.855, 0.145, 0.0, 43.93e3, 115.0, alpha, 8.5, 5600, 0.1e6, 293.0,
                     8.0, 0.085e6, 0.118e6, 1070.0, 1.377, 1.251, 0.91, 0.0, 0.5, 0.96, 0.85, 4, 4,
                     60e3, 0.9)


def diesel(alpha=1.4) -> CycleSpec:
    return CycleSpec(True, 0.870, 0.126, 0.004, 42.44e3, 0.0, alpha, 17.0, 2600, 0.1e6, 293.0,
                     15.0, 0.088e6, 0.11e6, 750.0, 1.37, 1.26, 0.82, 1.7, 0.5, 0.95, 0.8, 4, 8)


@pytest.mark.parametrize("spec", [petrol(0.9), petrol(1.0), petrol(1.1), diesel(1.4), diesel(2.0)])
def test_mass_of_the_products_is_air_plus_fuel(spec):
    """Σ M_i·μ_i = α·l0 + 1 kg per kg of fuel (air by mass 23 % O2, by volume 20.8 %: the
    courses' rounded composition, so to 0.5 %)."""
    c = thermal_cycle(spec)
    mass = sum(MOLAR[g] * m for g, m in c.products.items())
    assert abs(mass - (spec.alpha * c.l0 + 1.0)) < 5e-3 * mass
    # carbon and hydrogen atoms are conserved exactly
    assert abs(c.products.get("CO2", 0) + c.products.get("CO", 0) - spec.C / 12) < 1e-12
    assert abs(c.products["H2O"] + c.products.get("H2", 0) - spec.H / 2) < 1e-12


def _p_theory_quad(c) -> float:
    """∮p dV / V_h of the sharp-cornered cycle by quadrature (V in units of V_c)."""
    s = c.spec
    eps, Vz = s.epsilon, c.rho
    expansion = quad(lambda v: c.p_z * (Vz / v) ** s.n2, Vz, eps, epsabs=1e-6)[0]
    compression = quad(lambda v: c.p_c * (1.0 / v) ** s.n1, 1.0, eps, epsabs=1e-6)[0]
    constant_p = c.p_z * (Vz - 1.0)
    return (expansion + constant_p - compression) / (eps - 1.0)


@pytest.mark.parametrize("spec", [petrol(), diesel()])
def test_mean_indicated_pressure_by_quadrature(spec):
    c = thermal_cycle(spec)
    assert abs(c.p_i_theory - _p_theory_quad(c)) < 1e-9 * c.p_i_theory
    # end of compression and of expansion lie on the polytropes through a and z
    assert abs(c.p_c - spec.p_a * spec.epsilon ** spec.n1) < 1e-6
    assert abs(c.p_b * (spec.epsilon / c.rho) ** spec.n2 - c.p_z) < 1e-6 * c.p_z


def _cv(fr: dict[str, float], t: float, table: dict) -> float:
    tot = sum(fr.values())
    return sum(sum(k * t ** i for i, k in enumerate(table[g])) * m for g, m in fr.items()) / tot


@pytest.mark.parametrize("spec", [petrol(), diesel()])
def test_combustion_equation_by_root_finding(spec):
    c = thermal_cycle(spec)
    t_c = c.T_c - 273.0
    cv_c = ((20.6 + 2.638e-3 * t_c) + c.gamma_r * _cv(c.products, t_c, LOW)) / (1 + c.gamma_r)
    if spec.diesel:
        left = (spec.xi_z * spec.H_u / (c.M1 * (1 + c.gamma_r)) + (cv_c + 8.315 * spec.lambda_p)
                * t_c + 2270.0 * (spec.lambda_p - c.mu))

        def f(t):
            return c.mu * (_cv(c.products, t, HIGH) + 8.315) * t - left
    else:
        left = (spec.xi_z * (spec.H_u - c.dH_u) / (c.M1 * (1 + c.gamma_r)) + cv_c * t_c)

        def f(t):
            return c.mu * _cv(c.products, t, HIGH) * t - left
    t_z = brentq(f, 500.0, 4000.0, xtol=1e-10)
    assert abs(c.T_z - (t_z + 273.0)) < 1e-3      # the courses round 8.315·273 to 2270
    assert 1500 < c.T_z < 3200
    # diesel: ρ from the state equation at z, p_z = λ_p·p_c
    if spec.diesel:
        assert abs(c.rho - c.mu * c.T_z / (spec.lambda_p * c.T_c)) < 1e-12


def test_heat_capacity_fits_meet_at_1500_degrees():
    """The low- and high-temperature fits of each gas agree where they join (within 2 %)."""
    for g in HIGH:
        low = sum(k * 1500.0 ** i for i, k in enumerate(LOW[g]))
        high = HIGH[g][0] + HIGH[g][1] * 1500.0
        assert abs(low - high) < 0.02 * high, g


def test_power_and_cylinder_size_are_inverse():
    c = thermal_cycle(petrol())
    V_h, D, S = c.cylinder_for(60e3)
    assert abs(c.power(V_h) - 60e3) < 1e-6
    assert abs(S / D - 0.9) < 1e-12
    assert abs(math.pi * D * D / 4 * S - V_h) < 1e-15
    # N_e = p_e·V_h·i·n/(30·τ) with τ = 4 (the courses' formula, kW, MPa, l)
    assert abs(c.power(V_h) * 1e-3 - c.p_e * 1e-6 * V_h * 1e3 * 4 * 5600 / 120) < 1e-9


def test_eta_i_from_the_fuel_per_cycle():
    """η_i = indicated work / heat of the fuel of one cycle, fuel = air charge / (α·l0)."""
    s = petrol()
    c = thermal_cycle(s)
    V_h = 1e-3
    air = c.eta_v * V_h * s.p0 / (287.0 * s.T0)
    fuel = air / (s.alpha * c.l0)
    assert abs(c.p_i * V_h / (fuel * s.H_u * 1e3) - c.eta_i) < 1e-12


SCENE = diesel_2600(alpha="{alpha}", epsilon="{epsilon}", thermal_extra="{extra}")


def test_the_cycle_feeds_the_indicator_diagram():
    st = EngineStudy(parse_engine_scene(SCENE.format(extra="", alpha=1.4, epsilon=17), "d.toml"))
    c = st.scene.cycle
    th = st.scene.engine.indicator.thermal
    assert th.p_z == c.p_z and th.rho == c.rho and th.epsilon == 17
    # the unrounded diagram's area is the theoretical p_i less the pumping loop (p_r − p_a)·V_h,
    # which the courses count among the mechanical losses
    import dataclasses

    from mechplan.dynamics.engine.model import diagram_of
    sharp = dataclasses.replace(st.scene.engine, indicator=dataclasses.replace(
        st.scene.engine.indicator, thermal=dataclasses.replace(th, rounding=False)))
    W = diagram_of(sharp, "d.toml").work()
    th_p = c.p_i_theory - (th.p_r - th.p_a)
    assert abs(W / st.scene.engine.V_h - th_p) < 1e-6 * c.p_i_theory
    doc = st.to_json()["thermal"]
    assert doc["p_z"] == c.p_z
    for lang in ("en", "ru", "vi", "zh"):
        assert "T_z" in st.report(lang)


@pytest.mark.parametrize("extra, key", [
    ("epsilon = 40", "thermal.epsilon"),
    ('C = 0.5', "thermal.C"),
    ("alpha = 0.9", "thermal.alpha"),
    ("lambda_p = 0.5", "thermal.lambda_p"),
    ("colour = 1", "thermal"),
])
def test_thermal_errors(extra, key):
    values = {"alpha": 1.4, "epsilon": 17, "extra": extra}
    name = extra.split()[0]
    if name in values:
        values[name] = extra.split()[-1]
        values["extra"] = ""
    text = SCENE.format(**values)
    with pytest.raises(SceneError) as e:
        parse_engine_scene(text, "d.toml")
    assert key in str(e.value)


def test_thermal_and_indicator_together_refused():
    text = SCENE.format(extra="", alpha=1.4, epsilon=17) + '[indicator]\nepsilon = 9\n'
    with pytest.raises(SceneError) as e:
        parse_engine_scene(text, "d.toml")
    assert "indicator" in str(e.value)


def test_end_of_intake_from_the_losses():
    """Δp_a = (β² + ξ)·w²·ρ_k/2 with ρ_k = p0/(287·T0): 3.0 × 90² × 1.2063/2 = 14.66 kPa."""
    text = SCENE.format(extra="", alpha=1.4, epsilon=17).replace(
        'p_a = "88 kPa"',
        'intake_losses = 3.0\nintake_velocity = "90 m/s"\nT0 = 293\np0 = "100 kPa"')
    st = EngineStudy(parse_engine_scene(text, "d.toml"))
    rho_k = 100e3 / (287.0 * 293.0)
    assert abs(st.scene.cycle.spec.p_a - (100e3 - 3.0 * 8100.0 * rho_k / 2)) < 1e-6
    both = SCENE.format(extra="intake_losses = 3.0", alpha=1.4, epsilon=17)
    with pytest.raises(SceneError, match="thermal.p_a"):
        parse_engine_scene(both, "d.toml")
    none = SCENE.format(extra="", alpha=1.4, epsilon=17).replace('p_a = "88 kPa"', "")
    with pytest.raises(SceneError, match="thermal.p_a"):
        parse_engine_scene(none, "d.toml")
