"""The simplified linear heat-capacity fits (``heat_capacity = "linear"``) and the printed numbers
of public course calculations that use them.

Printed numbers reproduced (each at the rounding of its print, the inputs taken within the
rounding of theirs):

- allrefs.net/c35/1x6m5/p3/?full ("ПРОЦЕСС СЖАТИЯ"): mc_v = 20.16 + 1.74·10⁻³·742 = 21.45.
- tracetransport.ru/hons-127-1.html: p_i = 0.93·1.214 − (0.11 − 0.086) = 1.105 MPa (the pumping
  loop in p_i, ``pumping_loss = "indicated"``), p_e = 1.105·0.75 = 0.829 MPa.
- ukrbukva.net/page,4,68638 (Розробка двигуна внутрішнього згоряння, 2.1 "наповнення циліндра",
  a supercharged diesel): γ_r = 0.02 with its clean-out 0.6 and recharge 1.02 coefficients,
  T_a = 397 K with ψ = 1.1, T_c = 1094 K;
- ukrbukva.net/page,6,68638 (2.3 "процес згоряння"):
  (mc_v)_c = 22.1 at T_c = 1094 K; page,7,68638 (2.4 "процес розширення"): ρ = 1.38,
  δ = 11.63; page,8,68638: T_b = 1078 K with n2 = 1.261, p_b = 5.229·10⁵ Pa, p_z = 11.53 MPa.

The same page's T_z (2000 → 2051 → 2045 K by iteration; its heat-capacity formula is an image) is
reproduced with a given products' fit in tests/engine/test_thermal_fits.py; the simplified fits
below give 2035 K with its printed inputs.
"""

from __future__ import annotations

import itertools

import pytest
from helpers import diesel_2600

from mechplan.errors import SceneError
from mechplan.i18n import message, number
from mechplan.model.engine_heat_balance import heat_balance
from mechplan.model.engine_thermal import (
    CycleSpec,
    combustion_linear,
    compression,
    expansion,
    linear_air_cv,
    linear_products_cv,
    mean_indicated,
    pre_expansion,
    thermal_cycle,
)
from mechplan.scene.engine import parse_engine_scene
from mechplan.studies.engine import EngineStudy

#: ukrbukva.net/page,6,68638: the printed inputs of its combustion equation
PAGE = {"alpha": 1.9, "xi": 0.76, "gamma_r": 0.02, "mu": 1.031, "lam": 1.4, "M1": 0.942,
        "H_u": 42530.0, "T_c": 1094.0}


def between(f, printed: float, *ranges: tuple[float, float]) -> bool:
    """Whether ``printed`` lies within f over the corners of the inputs' rounding ranges (f is
    monotonic in each input here, so the corners bound it)."""
    values = [f(*c) for c in itertools.product(*ranges)]
    return min(values) <= printed <= max(values)


def test_fresh_charge_fit_allrefs():
    """allrefs.net/c35/1x6m5/p3/?full: "mcv = 20,16 + 1,74·10⁻³·742 = 21,45" (two decimals)."""
    assert abs(linear_air_cv(742.0) - 21.45) <= 0.005


def test_fresh_charge_fit_ukrbukva():
    """ukrbukva.net/page,6,68638: (mc_v)_c = 22.1 kJ/(kmol·K) at T_c = 1094 K (one decimal);
    Kolchin–Demidov's air 20.6 + 2.638·10⁻³·t would give 22.80."""
    assert abs(linear_air_cv(1094.0) - 22.1) <= 0.05


def test_products_fits_switch_at_alpha_one():
    """α ≥ 1: (20.2 + 0.92/α) + (15.5 + 13.8/α)·10⁻⁴·T; α < 1: (18.4 + 2.6α) + (15.5 + 13.8α)·10⁻⁴·T
    — the two agree at α = 1 (21.12 + 29.3·10⁻⁴·T vs 21.0 + 29.3·10⁻⁴·T, 0.6 % apart)."""
    assert linear_products_cv(1.9) == pytest.approx((20.2 + 0.92 / 1.9, (15.5 + 13.8 / 1.9) * 1e-4))
    assert linear_products_cv(0.9) == pytest.approx((18.4 + 2.6 * 0.9, (15.5 + 13.8 * 0.9) * 1e-4))
    a1, b1 = linear_products_cv(1.0)
    a0, b0 = linear_products_cv(1.0 - 1e-12)
    assert b1 == pytest.approx(b0) and abs(a1 - a0) / a1 < 0.006


def test_combustion_against_a_public_transcription_and_the_iteration():
    """T_z of the diesel equation with these fits: (1) the quadratic as an independent public
    transcription writes it (a C# course program, class ThermalEngine.EndBurnTemperature:
    a = μ(15.5 + 13.8/α)·10⁻⁴, b = (28.514 + 0.92/α)·μ, c = −ξH_u/(αL0(1 + γ_r)) −
    1.74·10⁻³·T_c² − (20.16 + 8.314λ)·T_c), (2) the courses' fixed-point iteration T ← left/(μ·
    (mc″_v(T) + R)) from 2000 K — both to 1e-9 K."""
    p = PAGE
    ours = combustion_linear(True, p["alpha"], p["xi"] * p["H_u"], p["M1"], p["gamma_r"],
                             p["mu"], p["lam"], p["T_c"], R=8.314)
    qa = p["mu"] * (15.5 + 13.8 / p["alpha"]) / 1e4
    qb = (28.514 + 0.92 / p["alpha"]) * p["mu"]
    qc = (-p["xi"] * p["H_u"] / (p["M1"] * (1 + p["gamma_r"])) - 1.74e-3 * p["T_c"] ** 2
          - (20.16 + 8.314 * p["lam"]) * p["T_c"])
    assert ours == pytest.approx((-qb + (qb * qb - 4 * qa * qc) ** 0.5) / (2 * qa), abs=1e-9)
    left = (p["xi"] * p["H_u"] / (p["M1"] * (1 + p["gamma_r"]))
            + (20.16 + 1.74e-3 * p["T_c"] + 8.314 * p["lam"]) * p["T_c"])
    T = 2000.0
    for _ in range(60):
        T = left / (p["mu"] * (20.2 + 0.92 / 1.9 + (15.5 + 13.8 / 1.9) * 1e-4 * T + 8.314))
    assert ours == pytest.approx(T, abs=1e-9)


def test_expansion_of_the_ukrbukva_diesel():
    """ukrbukva.net/page,7,68638 and page,8,68638 (2.4 "Розрахунок процесу розширення"), from its
    T_z = 2045 K, μ = 1.031, λ = 1.4, T_c = 1094 K, ε = 16, p_c = 8.239 MPa and n2 = 1.261 (its
    own iteration for n2 is a different method; its result is taken as given):
    ρ = μT_z/(λT_c) = 1.38 (ours 1.3766), δ = ε/ρ = 11.63 (ours 11.623), p_z = λ·p_c = 11.53 MPa
    (ours 11.5346), T_b = T_z/δ^(n2−1) = 1078 K, p_b = p_z/δ^n2 = 5.229·10⁵ Pa (ours from its
    printed p_z, δ: 5.2252·10⁵) — each inside our formula's range over the inputs' rounding."""
    rho = pre_expansion(1.031, 2045.0, 1.4, 1094.0)
    assert abs(rho - 1.38) <= 0.005
    mu_r, tz_r, tc_r = (1.0305, 1.0315), (2044.5, 2045.5), (1093.5, 1094.5)
    assert between(lambda m, z, c: 16.0 / pre_expansion(m, z, 1.4, c), 11.63, mu_r, tz_r, tc_r)
    _, T_b = expansion(11.53e6, 2045.0, 11.63, 1.261)
    assert abs(T_b - 1078.0) <= 0.5
    assert between(lambda pz, d, n2: expansion(pz, 2045.0, d, n2)[0] * 1e-5, 5.229,
                   (11.525e6, 11.535e6), (11.625, 11.635), (1.2605, 1.2615))


def test_intake_of_the_ukrbukva_diesel():
    """ukrbukva.net/page,4,68638 (2.1 "Наповнення циліндра"; inputs on page,2,68638): the charge
    after the intercooler T_k = 377 K (its supercharger is not modelled: T_k, p_k are given as
    T0, p0), ΔT = 10 K, T_r = 800 K, p_r = 0.2021 MPa, p_a = 0.187 MPa, ε = 16, clean-out
    φ_cl = 0.6, recharge φ_rc = 1.02, ψ = 1.1 → γ_r = 0.02 (ours 0.020016; without the two
    coefficients 0.035) and T_a = 397 K (ours 396.67; with ψ = 1 395.1 K, which the print
    excludes); T_c = 1094 K from its T_a = 397 K and n1 = 1.365 (within n1's rounding)."""
    spec = CycleSpec(True, 0.87, 0.126, 0.004, 42.53e3, 0.0, 1.9, 16.0, 2000, 0.2077e6, 377.0,
                     10.0, 0.187e6, 0.2021e6, 800.0, 1.365, 1.261, 0.76, 1.4, 0.5, 0.95, 0.86, 4,
                     4, air_O2=0.21, heat_capacity="linear", clean_out=0.6, recharge=1.02,
                     psi_r=1.1)
    c = thermal_cycle(spec)
    assert abs(c.gamma_r - 0.02) <= 0.005
    assert c.gamma_r == pytest.approx(387.0 / 800.0 * 0.6 * 0.2021 / (16 * 1.02 * 0.187
                                                                        - 0.6 * 0.2021))
    assert abs(c.T_a - 397.0) <= 0.5
    plain = thermal_cycle(CycleSpec(True, 0.87, 0.126, 0.004, 42.53e3, 0.0, 1.9, 16.0, 2000,
                                    0.2077e6, 377.0, 10.0, 0.187e6, 0.2021e6, 800.0, 1.365,
                                    1.261, 0.76, 1.4, 0.5, 0.95, 0.86, 4, 4, clean_out=0.6,
                                    recharge=1.02))
    assert abs(plain.T_a - 397.0) > 0.5
    assert between(lambda n1: compression(0.187e6, 397.0, 16.0, n1)[1], 1094.0 - 0.5,
                   (1.3645, 1.3655))


SCENE = diesel_2600(alpha=1.6, epsilon=16,
                    thermal_extra="lambda_p = 1.7\n{extra}")


def test_scene_option_runs_the_linear_fits():
    """``heat_capacity = "linear"``: the cycle's T_z is the linear equation's root with the
    cycle's own intermediate values (its residual < 1e-6 of the left side); the report names the
    fits in every language, JSON carries the key; the default stays the table fits."""
    lin = EngineStudy(parse_engine_scene(SCENE.format(extra='heat_capacity = "linear"'), "d.toml"))
    tab = EngineStudy(parse_engine_scene(SCENE.format(extra=""), "d.toml"))
    c, s = lin.scene.cycle, lin.scene.cycle.spec
    assert s.heat_capacity == "linear" and tab.scene.cycle.spec.heat_capacity == "table"
    a, b = linear_products_cv(s.alpha)
    left = (s.xi_z * s.H_u / (c.M1 * (1 + c.gamma_r))
            + (20.16 + 1.74e-3 * c.T_c + 8.315 * s.lambda_p) * c.T_c)
    right = c.mu * (a + b * c.T_z + 8.315) * c.T_z
    assert abs(right - left) < 1e-6 * left
    assert c.p_z == pytest.approx(s.lambda_p * c.p_c)
    assert abs(c.T_z - tab.scene.cycle.T_z) > 1.0       # the two fits really differ
    assert lin.to_json()["thermal"]["heat_capacity"] == "linear"
    for lang in ("en", "ru", "vi", "zh"):
        assert message("thermal4.report.fits_linear", lang) in lin.report(lang)
        assert message("thermal4.report.fits_table", lang) in tab.report(lang)


def test_scene_intake_coefficients():
    """``clean_out``, ``recharge``, ``residual_heat`` reach γ_r, T_a and η_v (Kolchin–Demidov's
    η_v = T0/(T0 + ΔT)·(φ_rc·ε·p_a − φ_cl·p_r)/((ε − 1)·p0))."""
    extra = "clean_out = 0.6\nrecharge = 1.02\nresidual_heat = 1.1"
    c = EngineStudy(parse_engine_scene(SCENE.format(extra=extra), "d.toml")).scene.cycle
    s = c.spec
    Tk = s.T0 + s.dT
    assert c.gamma_r == pytest.approx(Tk / 750.0 * 0.6 * 110e3 / (16 * 1.02 * 88e3 - 0.6 * 110e3))
    assert c.T_a == pytest.approx((Tk + 1.1 * c.gamma_r * 750.0) / (1 + c.gamma_r))
    assert c.eta_v == pytest.approx(s.T0 / Tk * (1.02 * 16 * 88e3 - 0.6 * 110e3)
                                    / (15 * s.p0))
    st = EngineStudy(parse_engine_scene(SCENE.format(extra=extra), "d.toml"))
    for lang in ("en", "ru", "vi", "zh"):
        assert message("thermal4.report.intake", lang, clean=number(0.6, 3, lang),
                       recharge=number(1.02, 3, lang), psi=number(1.1, 3, lang)) in st.report(lang)
    with pytest.raises(SceneError) as e:
        parse_engine_scene(SCENE.format(extra="recharge = 2"), "d.toml")
    assert "recharge" in str(e.value)


def test_pumping_loss_in_the_indicated_pressure_tracetransport():
    """tracetransport.ru/hons-127-1.html ("Среднее индикаторное давление действующего цикла", a
    diesel course work): p_i = φ·p_i′ − (p_r − p_a) = 0.93·1.214 − (0.11 − 0.086) = 1.105 MPa and
    p_e = p_i·η_m = 1.105·0.75 = 0.829 MPa (three decimals each); the scene's
    ``pumping_loss = "indicated"`` takes this variant, the default counts the loop among the
    mechanical losses (Kolchin–Demidov)."""
    p_i = mean_indicated(1.214, 0.93, 0.11 - 0.086)
    assert abs(p_i - 1.105) <= 0.0005
    assert abs(round(p_i, 3) * 0.75 - 0.829) <= 0.0005
    ind = EngineStudy(parse_engine_scene(SCENE.format(extra='pumping_loss = "indicated"'),
                                         "d.toml")).scene.cycle
    mech = EngineStudy(parse_engine_scene(SCENE.format(extra=""), "d.toml")).scene.cycle
    assert ind.p_i == pytest.approx(ind.spec.phi_i * ind.p_i_theory - (110e3 - 88e3))
    assert mech.p_i == pytest.approx(mech.spec.phi_i * mech.p_i_theory)
    assert ind.p_e == pytest.approx(ind.spec.eta_m * ind.p_i)
    assert ind.eta_i / mech.eta_i == pytest.approx(ind.p_i / mech.p_i)
    st = EngineStudy(parse_engine_scene(SCENE.format(extra='pumping_loss = "indicated"'), "d"))
    for lang in ("en", "ru", "vi", "zh"):
        line = message("thermal4.report.pumping", lang, dp=number(0.022, 4, lang))
        assert line in st.report(lang)
    assert st.to_json()["thermal"]["pumping_loss"] == "indicated"


def test_scene_option_refuses_an_unknown_fit():
    with pytest.raises(SceneError) as e:
        parse_engine_scene(SCENE.format(extra='heat_capacity = "nasa"'), "d.toml")
    assert "heat_capacity" in str(e.value)


def test_petrol_linear_is_the_otto_equation():
    """Spark ignition at α = 0.9: ξ_z(H_u − ΔH_u)/(M1(1 + γ_r)) + mc_v(T_c)·T_c =
    μ·mc″_v(T_z)·T_z with the α < 1 fit, to 1e-9 of the left side."""
    spec = CycleSpec(False, 0.855, 0.145, 0.0, 43.93e3, 115.0, 0.9, 8.5, 5600, 0.1e6, 293.0, 8.0,
                     0.085e6, 0.118e6, 1070.0, 1.377, 1.251, 0.91, 0.0, 0.5, 0.96, 0.85, 4, 4,
                     heat_capacity="linear")
    c = thermal_cycle(spec)
    left = 0.91 * (43.93e3 - c.dH_u) / (c.M1 * (1 + c.gamma_r)) + linear_air_cv(c.T_c) * c.T_c
    right = c.mu * (18.4 + 2.6 * 0.9 + (15.5 + 13.8 * 0.9) * 1e-4 * c.T_z) * c.T_z
    assert abs(right - left) < 1e-9 * left
    assert c.p_z == pytest.approx(c.p_c * c.mu * c.T_z / c.T_c)


def test_heat_balance_with_the_linear_fits():
    """The exhaust term takes the linear fits at T = t + 273 K (M2·(mc″_v + R)·t_r −
    M1·(mc_v + R)·t0 per kg of fuel); the shares still sum to 100 %."""
    spec = CycleSpec(True, 0.870, 0.126, 0.004, 42.44e3, 0.0, 1.6, 16.0, 2600, 0.1e6, 293.0,
                     15.0, 0.088e6, 0.11e6, 750.0, 1.37, 1.26, 0.82, 1.7, 0.5, 0.95, 0.8, 4, 4,
                     heat_capacity="linear")
    c = thermal_cycle(spec)
    bal = heat_balance(c, 60e3, 0.11, 4)
    a, b = 20.2 + 0.92 / 1.6, (15.5 + 13.8 / 1.6) * 1e-4
    per_kg = (c.M2 * (a + b * 750.0 + 8.315) * 477.0
              - c.M1 * (20.16 + 1.74e-3 * 293.0 + 8.315) * 20.0)
    assert bal.flows["r"] == pytest.approx(bal.G_T / 3.6 * per_kg, rel=1e-12)
    assert sum(bal.shares.values()) == pytest.approx(100.0)
