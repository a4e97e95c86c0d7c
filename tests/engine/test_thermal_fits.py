"""A textbook's own linear heat-capacity fits (``charge_cv``, ``products_cv`` with
``heat_capacity = "linear"``), and the printed T_z of ukrbukva.net/page,6,68638.

The page ("Розробка двигуна внутрішнього згоряння", 2.3 "Розрахунок процесу згоряння", a
supercharged diesel) prints the inputs of its combustion equation (α 1.9, ξ_z 0.76, γ_r 0.02,
μ 1.031, λ 1.4, (mc_v)_c 22.1 kJ/(kmol·K), M1 0.942 kmol/kg, H_u 42 530 kJ/kg, T_c 1094 K) and its
iterations "T_z = 2000 K → T_z1 = 2051 K → T_z2 = 2045 K"; the products' heat-capacity formula is
an image. With the products' fit (20.2 + 0.92/α) + (15.5 + 13.8/α)·10⁻⁴·T the root is 2034.8 K;
with the same fit but the constant 20.0 (i.e. (20.0 + 0.92/α) + (15.5 + 13.8/α)·10⁻⁴·T, given
here as ``products_cv``) the root is 2045.5 K and the fixed-point iterates from 2000 K and from
2051 K are 2051.8 K and 2044.7 K. Each printed number is checked inside the range our equation
takes over the corners of its printed inputs' rounding (μ, M1 ±0.0005; (mc_v)_c ±0.05;
T_c ±0.5 K; γ_r ±0.0005: printed "0,02", and its page 4 inputs give 0.020016, see
test_thermal_linear.test_intake_of_the_ukrbukva_diesel); the root at the printed inputs
themselves is within the print's rounding (±0.5 K). This identifies a fit consistent with the
print; which fit the page used is not readable from it.
"""

from __future__ import annotations

import itertools

import pytest
from helpers import diesel_2600

from mechplan.errors import SceneError
from mechplan.i18n import message, number
from mechplan.model.engine_heat_balance import heat_balance
from mechplan.model.engine_thermal import CycleSpec, combustion_linear, thermal_cycle
from mechplan.scene.engine import parse_engine_scene
from mechplan.studies.engine import EngineStudy

R = 8.315
ALPHA, XI, H_U, LAM = 1.9, 0.76, 42530.0, 1.4
#: the page's rounded inputs: (printed value, half its last digit)
GAMMA, MU, CV_C, M1, T_C = (0.02, 0.0005), (1.031, 0.0005), (22.1, 0.05), (0.942, 0.0005), \
    (1094.0, 0.5)
#: the products' fit (20.0 + 0.92/α) + (15.5 + 13.8/α)·10⁻⁴·T at α = 1.9, T in K
PRODUCTS = (20.0 + 0.92 / ALPHA, (15.5 + 13.8 / ALPHA) * 1e-4)


def left_side(gamma: float, cv_c: float, M1: float, T_c: float) -> float:
    """The diesel equation's left side in kelvin: ξ_zH_u/(M1(1 + γ_r)) + ((mc_v)_c + Rλ)·T_c."""
    return XI * H_U / (M1 * (1.0 + gamma)) + (cv_c + R * LAM) * T_c


def iterate(T: float, gamma: float, mu: float, cv_c: float, M1: float, T_c: float) -> float:
    """One step of the courses' fixed-point iteration T ← left/(μ(mc″_v(T) + R)), written out."""
    a, b = PRODUCTS
    return left_side(gamma, cv_c, M1, T_c) / (mu * (a + b * T + R))


def corners(f) -> list[float]:
    """f over the corners of the rounding ranges of (γ_r, μ, (mc_v)_c, M1, T_c)."""
    ranges = [(v - h, v + h) for v, h in (GAMMA, MU, CV_C, M1, T_C)]
    return [f(*c) for c in itertools.product(*ranges)]


def root(gamma: float, mu: float, cv_c: float, M1: float, T_c: float) -> float:
    """Ours: the scene-level function with the fresh charge's heat capacity fixed at the
    printed (mc_v)_c (b = 0) and the products' fit given."""
    return combustion_linear(True, ALPHA, XI * H_U, M1, gamma, mu, LAM, T_c, R=R,
                             charge=(cv_c, 0.0), products=PRODUCTS)


def test_ukrbukva_T_z_with_a_given_products_fit():
    """Printed T_z = 2045 K (±0.5): ours 2045.47 K at the printed inputs; the printed value lies
    in our root's range over the inputs' rounding (2041.9 … 2049.0 K); our root solves the
    equation written out (residual < 1e-9 of the left side) and is the iteration's limit."""
    nominal = root(GAMMA[0], MU[0], CV_C[0], M1[0], T_C[0])
    assert abs(nominal - 2045.0) <= 0.5
    values = corners(root)
    assert min(values) <= 2045.0 <= max(values)
    a, b = PRODUCTS
    left = left_side(GAMMA[0], CV_C[0], M1[0], T_C[0])
    assert abs(MU[0] * (a + b * nominal + R) * nominal - left) < 1e-9 * left
    T = 2000.0
    for _ in range(80):
        T = iterate(T, GAMMA[0], MU[0], CV_C[0], M1[0], T_C[0])
    assert T == pytest.approx(nominal, abs=1e-9)


def test_ukrbukva_iterates_with_a_given_products_fit():
    """Printed iterates: from 2000 K → 2051 K, from 2051 K → 2045 K; ours at the printed inputs
    2051.82 and 2044.70 (the second within the print's ±0.5 K); each printed value lies in our
    step's range over the inputs' rounding (2047.7 … 2055.9 K and 2040.6 … 2048.8 K)."""
    first = corners(lambda *c: iterate(2000.0, *c))
    second = corners(lambda *c: iterate(2051.0, *c))
    assert min(first) <= 2051.0 <= max(first)
    assert min(second) <= 2045.0 <= max(second)
    assert abs(iterate(2051.0, GAMMA[0], MU[0], CV_C[0], M1[0], T_C[0]) - 2045.0) <= 0.5


SCENE = diesel_2600(alpha=1.6, epsilon=16, thermal_extra="lambda_p = 1.7\n{extra}")
FITS = 'heat_capacity = "linear"\ncharge_cv = [20.6, 2.638e-3]\nproducts_cv = [20.5, 2.4e-3]'


def test_scene_fits_reach_the_combustion_equation():
    """``charge_cv``, ``products_cv``: the cycle's T_z solves ξ_zH_u/(M1(1 + γ_r)) + (a_c +
    b_c·T_c + Rλ)·T_c = μ(a_p + b_p·T_z + R)·T_z with the scene's coefficients (residual
    < 1e-9 of the left side); without them the simplified fits stay (a different T_z)."""
    st = EngineStudy(parse_engine_scene(SCENE.format(extra=FITS), "d.toml"))
    c, s = st.scene.cycle, st.scene.cycle.spec
    assert s.charge_fit == (20.6, 2.638e-3) and s.products_fit == (20.5, 2.4e-3)
    left = (s.xi_z * s.H_u / (c.M1 * (1 + c.gamma_r))
            + (20.6 + 2.638e-3 * c.T_c + R * s.lambda_p) * c.T_c)
    assert abs(c.mu * (20.5 + 2.4e-3 * c.T_z + R) * c.T_z - left) < 1e-9 * left
    plain = EngineStudy(parse_engine_scene(SCENE.format(extra='heat_capacity = "linear"'),
                                           "d.toml")).scene.cycle
    assert abs(plain.T_z - c.T_z) > 1.0
    doc = st.to_json()["thermal"]
    assert doc["charge_cv"] == [20.6, 2.638e-3] and doc["products_cv"] == [20.5, 2.4e-3]
    for lang in ("en", "ru", "vi", "zh"):
        report = st.report(lang)
        assert message("thermal5.report.charge_fit", lang, a=number(20.6, 3, lang),
                       b=number(2.638, 3, lang)) in report
        assert message("thermal5.report.products_fit", lang, a=number(20.5, 3, lang),
                       b=number(24.0, 3, lang)) in report


def test_scene_fits_reach_the_heat_balance():
    """The exhaust term M2·(a_p + b_p·T_r + R)·t_r − M1·(a_c + b_c·T0 + R)·t0 per kg of fuel
    takes the given fits (t in °C, T = t + 273 K); the shares sum to 100 %."""
    spec = CycleSpec(True, 0.870, 0.126, 0.004, 42.44e3, 0.0, 1.6, 16.0, 2600, 0.1e6, 293.0,
                     15.0, 0.088e6, 0.11e6, 750.0, 1.37, 1.26, 0.82, 1.7, 0.5, 0.95, 0.8, 4, 4,
                     heat_capacity="linear", charge_fit=(20.6, 2.638e-3),
                     products_fit=(20.5, 2.4e-3))
    c = thermal_cycle(spec)
    bal = heat_balance(c, 60e3, 0.11, 4)
    per_kg = (c.M2 * (20.5 + 2.4e-3 * 750.0 + R) * 477.0
              - c.M1 * (20.6 + 2.638e-3 * 293.0 + R) * 20.0)
    assert bal.flows["r"] == pytest.approx(bal.G_T / 3.6 * per_kg, rel=1e-12)
    assert sum(bal.shares.values()) == pytest.approx(100.0)


@pytest.mark.parametrize("extra", [
    "products_cv = [20.5, 2.4e-3]",                                  # table fits
    'heat_capacity = "linear"\nproducts_cv = [20.5]',                # one number
    'heat_capacity = "linear"\nproducts_cv = [50.0, 2.4e-3]',        # a out of range
    'heat_capacity = "linear"\ncharge_cv = [20.6, 0.5]',             # b out of range
    'heat_capacity = "linear"\ncharge_cv = "20.6 + 0.002T"',         # not a list
])
def test_scene_fits_refused(extra):
    with pytest.raises(SceneError) as e:
        parse_engine_scene(SCENE.format(extra=extra), "d.toml")
    key = "charge_cv" if "charge_cv" in extra else "products_cv"
    assert key in str(e.value)
