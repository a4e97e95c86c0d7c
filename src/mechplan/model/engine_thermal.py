"""The thermal calculation of an engine's working cycle (Grinevetsky–Mazing as in Kolchin–Demidov):
fuel → air and products, intake with residual gases, compression, combustion, expansion, the mean
indicated pressure, efficiencies, power and the cylinder for a given power.

Choices stated: p_a (or the intake losses at the rated speed), n1, n2, ξ_z (and λ_p of a
diesel) are given, not read off the courses'
nomograms; the mean molar heat capacities (kJ/(kmol·K), t in °C) are Kolchin–Demidov's fits of
the individual gases — fresh charge (air) 20.6 + 2.638·10⁻³t, products at t_c from the 0–1500 °C
fits, at t_z from the 1501–2800 °C fits — mixed by the products' mole fractions
(``heat_capacity = "table"``), or the simplified linear fits many course works use
(``"linear"``, T in K: see :func:`linear_air_cv`, :func:`linear_products_cv`); p_k = p0,
T_k = T0 (no supercharging: a supercharged engine's p_k, T_k are given as p0, T0); the clean-out
and recharge coefficients and ψ of T_a are 1 unless given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .engine_wiebe import Wiebe

R_MU = 8.315                 # kJ/(kmol·K)
AIR_O2 = 0.208               # O2 in air by volume
R_AIR = 287.0                # J/(kg·K)

#: 0–1500 °C: a + b·t + c·t² (t in °C)
LOW = {"CO2": (27.941, 0.019, -5.487e-6), "CO": (20.597, 0.00267, 0.0),
       "H2O": (24.953, 0.005359, 0.0), "H2": (20.684, 0.000206, 5.88e-7),
       "N2": (20.398, 0.0025, 0.0), "O2": (20.93, 0.004641, -8.4e-7)}
#: 1501–2800 °C: a + b·t
HIGH = {"CO2": (39.123, 0.003349), "CO": (22.49, 0.00143), "H2O": (26.67, 0.004438),
        "H2": (19.678, 0.001758), "N2": (21.951, 0.001457), "O2": (23.723, 0.00155)}

#: the fresh charge's simplified linear fit a + b·T (kJ/(kmol·K), T in K)
CHARGE_LINEAR = (20.16, 1.74e-3)

#: the heat-capacity fits of the combustion equation (scene key ``heat_capacity``)
HEAT_CAPACITY = ("table", "linear")

FUELS = {"petrol": (0.855, 0.145, 0.0, 43.93e3, 115.0), "diesel": (0.870, 0.126, 0.004, 42.44e3,
                                                                  0.0)}


@dataclass(frozen=True)
class CycleSpec:
    """Inputs of the thermal calculation (SI units except H_u in kJ/kg)."""

    diesel: bool
    C: float
    H: float
    O: float
    H_u: float                   # lower heating value, kJ/kg
    m_fuel: float                # molar mass of the fuel vapour, kg/kmol (0: not counted)
    alpha: float
    epsilon: float
    speed_rpm: float
    p0: float
    T0: float
    dT: float
    p_a: float
    p_r: float
    T_r: float
    n1: float
    n2: float
    xi_z: float
    lambda_p: float              # diesel: p_z/p_c
    K: float                     # H2/CO in the products of a rich mixture
    phi_i: float                 # fullness of the rounded diagram
    eta_m: float
    strokes: int
    cylinders: int
    power: float | None = None   # W: size the cylinder for this effective power
    S_D: float = 1.0
    coolant_c: float = 0.5       # heat balance: c and m of the coolant's empirical formula
    coolant_m: float = 0.65
    air_O2: float = AIR_O2       # O2 in air by volume (Kolchin–Demidov 0.208; 0.21 in others)
    heat_capacity: str = "table"  # HEAT_CAPACITY: Kolchin–Demidov's per-gas table fits | linear
    clean_out: float = 1.0       # φ_cl of the residual gases (scavenging < 1)
    recharge: float = 1.0        # φ_rc, the recharge coefficient
    psi_r: float = 1.0           # ψ of T_a: residual gases' to charge's heat capacity
    pumping: bool = False        # p_i less the pumping loop p_r − p_a (else in the mech. losses)
    charge_fit: tuple[float, float] | None = None    # linear: the charge's a + b·T (else 20.16…)
    products_fit: tuple[float, float] | None = None  # linear: the products' a + b·T at this α


@dataclass(frozen=True)
class Cycle:
    """Results (SI; kmol per kg of fuel)."""

    spec: CycleSpec
    L0: float
    l0: float
    M1: float
    products: dict[str, float]
    M2: float
    mu0: float
    dH_u: float                  # heat lost to incomplete combustion, kJ/kg
    gamma_r: float
    T_a: float
    eta_v: float
    p_c: float
    T_c: float
    mu: float
    T_z: float
    p_z: float
    lam: float                   # pressure-rise ratio p_z/p_c
    rho: float                   # pre-expansion ratio
    p_b: float
    T_b: float
    p_i_theory: float
    p_i: float
    eta_i: float
    g_i: float                   # g/(kW·h)
    p_e: float
    eta_e: float
    g_e: float
    wiebe: Wiebe | None = None   # the optional Wiebe model's diagram (when the scene asks)

    def power(self, V_h: float, cylinders: int | None = None) -> float:
        """Effective power (W) of cylinders of displacement V_h (m³)."""
        s = self.spec
        i = cylinders or s.cylinders
        return self.p_e * V_h * i * s.speed_rpm / 60.0 * 2.0 / s.strokes

    def cylinder_for(self, power: float) -> tuple[float, float, float]:
        """(V_h m³, bore m, stroke m) for an effective power (W)."""
        s = self.spec
        V_h = power / (self.p_e * s.cylinders * s.speed_rpm / 60.0 * 2.0 / s.strokes)
        D = (4.0 * V_h / (math.pi * s.S_D)) ** (1.0 / 3.0)
        return V_h, D, D * s.S_D


def _mix(fractions: dict[str, float], t: float, high: bool) -> tuple[float, float]:
    """Mixture (a, b[, c folded in]) of the mean molar heat capacity at t: returns (value, slope)
    so that mc_v(t) = value and, for the high range, mc_v = a + b·t exactly."""
    total = sum(fractions.values())
    if high:
        a = sum(HIGH[g][0] * m for g, m in fractions.items()) / total
        b = sum(HIGH[g][1] * m for g, m in fractions.items()) / total
        return a, b
    v = sum((LOW[g][0] + LOW[g][1] * t + LOW[g][2] * t * t) * m
            for g, m in fractions.items()) / total
    return v, 0.0


def linear_air_cv(T: float) -> float:
    """Mean molar heat capacity at constant volume of the fresh charge (air), the simplified
    linear fit 20.16 + 1.74·10⁻³·T, kJ/(kmol·K), T in K."""
    return CHARGE_LINEAR[0] + CHARGE_LINEAR[1] * T


def linear_products_cv(alpha: float) -> tuple[float, float]:
    """(a, b) of the products' simplified linear fit mc″_v = a + b·T (kJ/(kmol·K), T in K):
    α ≥ 1 (diesel) a = 20.2 + 0.92/α, b = (15.5 + 13.8/α)·10⁻⁴; α < 1 (spark ignition)
    a = 18.4 + 2.6α, b = (15.5 + 13.8α)·10⁻⁴."""
    if alpha >= 1.0:
        return 20.2 + 0.92 / alpha, (15.5 + 13.8 / alpha) * 1e-4
    return 18.4 + 2.6 * alpha, (15.5 + 13.8 * alpha) * 1e-4


def linear_fits(s: CycleSpec) -> tuple[tuple[float, float], tuple[float, float]]:
    """((a, b) of the fresh charge, (a, b) of the products) of the linear fits mc_v = a + b·T
    (T in K) for a spec: the scene's own coefficients where given (``charge_cv``,
    ``products_cv``), else the simplified fits above."""
    return s.charge_fit or CHARGE_LINEAR, s.products_fit or linear_products_cv(s.alpha)


def combustion_linear(diesel: bool, alpha: float, heat: float, M1: float, gamma_r: float,
                      mu: float, lam: float, T_c: float, R: float = R_MU,
                      charge: tuple[float, float] | None = None,
                      products: tuple[float, float] | None = None) -> float:
    """T_z (K) of the combustion equation with the linear fits, in kelvin as the course works
    write it: heat/(M1(1 + γ_r)) + mc_v(T_c)·T_c [+ R·λ·T_c] = μ·(mc″_v(T_z) [+ R])·T_z, the
    bracketed terms for a diesel; ``heat`` = ξ_z·(H_u − ΔH_u) in kJ/kg, mc_v of the fresh
    charge alone (the residual gases' share is not counted, as the sources print it). The
    quadratic's positive root, which the courses' fixed-point iteration converges to.
    ``charge`` and ``products`` (a, b) replace the simplified fits (a textbook's own)."""
    a, b = products or linear_products_cv(alpha)
    cv_c = charge[0] + charge[1] * T_c if charge else linear_air_cv(T_c)
    left = heat / (M1 * (1.0 + gamma_r)) + cv_c * T_c
    if diesel:
        left += R * lam * T_c
        a += R
    return (-a + math.sqrt(a * a + 4.0 * b * left / mu)) / (2.0 * b)


def pre_expansion(mu: float, T_z: float, lam: float, T_c: float) -> float:
    """A diesel's pre-expansion ratio ρ = μ·T_z/(λ·T_c)."""
    return mu * T_z / (lam * T_c)


def expansion(p_z: float, T_z: float, delta: float, n2: float) -> tuple[float, float]:
    """End of the polytropic expansion: (p_b, T_b) = (p_z/δ^n2, T_z/δ^(n2−1))."""
    return p_z / delta ** n2, T_z / delta ** (n2 - 1.0)


def mean_indicated_theory(p_c: float, epsilon: float, lam: float, rho: float, n1: float,
                          n2: float) -> float:
    """The mean indicated pressure of the sharp-cornered cycle, δ = ε/ρ:
    p_c/(ε − 1)·[λ(ρ − 1) + λρ/(n2 − 1)·(1 − δ^(1−n2)) − (1 − ε^(1−n1))/(n1 − 1)]."""
    delta = epsilon / rho
    return float(p_c / (epsilon - 1.0) * (lam * (rho - 1.0)
                                          + lam * rho / (n2 - 1.0) * (1.0 - delta ** (1.0 - n2))
                                          - (1.0 - epsilon ** (1.0 - n1)) / (n1 - 1.0)))


def mean_indicated(p_it: float, phi_i: float, pumping: float = 0.0) -> float:
    """The mean indicated pressure of the rounded diagram p_i = φ_i·p_i′ − Δp_pump; the pumping
    loop Δp_pump = p_r − p_a subtracted here in some courses, among the mechanical losses (0
    here) in Kolchin–Demidov's."""
    return phi_i * p_it - pumping


def products_of(s: CycleSpec, L0: float) -> dict[str, float]:
    """kmol of each combustion product per kg of fuel."""
    if s.alpha < 1.0:
        co = 2.0 * (1.0 - s.alpha) / (1.0 + s.K) * s.air_O2 * L0
        h2 = s.K * co
        return {"CO2": s.C / 12.0 - co, "CO": co, "H2O": s.H / 2.0 - h2, "H2": h2,
                "N2": (1.0 - s.air_O2) * s.alpha * L0}
    return {"CO2": s.C / 12.0, "H2O": s.H / 2.0, "O2": s.air_O2 * (s.alpha - 1.0) * L0,
            "N2": (1.0 - s.air_O2) * s.alpha * L0}


def end_of_intake(T_k: float, T_r: float, gamma_r: float, psi: float = 1.0) -> float:
    """Temperature at the end of intake T_a = (T_k + ψ·γ_r·T_r)/(1 + γ_r), T_k = T0 + ΔT; ψ the
    ratio of the residual gases' heat capacity to the charge's (1 in Kolchin–Demidov)."""
    return (T_k + psi * gamma_r * T_r) / (1.0 + gamma_r)


def residual_fraction(T_k: float, T_r: float, p_a: float, p_r: float, epsilon: float,
                      clean_out: float = 1.0, recharge: float = 1.0) -> float:
    """The residual-gas coefficient γ_r = T_k/T_r·φ_cl·p_r/(ε·φ_rc·p_a − φ_cl·p_r), T_k = T0 + ΔT,
    with Kolchin–Demidov's clean-out (φ_cl, 1 without scavenging) and recharge (φ_rc)
    coefficients."""
    return T_k / T_r * clean_out * p_r / (epsilon * recharge * p_a - clean_out * p_r)


def compression(p_a: float, T_a: float, epsilon: float, n1: float) -> tuple[float, float]:
    """End of the polytropic compression: (p_c, T_c) = (p_a·ε^n1, T_a·ε^(n1−1))."""
    return p_a * epsilon ** n1, T_a * epsilon ** (n1 - 1.0)


def _combustion_table(s: CycleSpec, prod: dict[str, float], M1: float, gamma_r: float,
                      mu: float, T_c: float, dH: float) -> float:
    """T_z (K) of Kolchin–Demidov's combustion equation (t in °C) with the per-gas table fits:
    the charge at t_c a mixture of air and residual products, the products at t_z from the
    1501–2800 °C fits."""
    t_c = T_c - 273.0
    cv_air = 20.6 + 2.638e-3 * t_c
    cv_res, _ = _mix(prod, t_c, high=False)
    a, b = _mix(prod, 0.0, high=True)
    if s.diesel:
        a += R_MU
        left = (s.xi_z * s.H_u / (M1 * (1.0 + gamma_r))
                + ((cv_air + gamma_r * cv_res) / (1.0 + gamma_r) + R_MU * s.lambda_p) * t_c
                + R_MU * 273.0 * (s.lambda_p - mu))
    else:
        left = (s.xi_z * (s.H_u - dH) / (M1 * (1.0 + gamma_r))
                + (cv_air + gamma_r * cv_res) / (1.0 + gamma_r) * t_c)
    # μ·(a + b·t_z)·t_z = left
    t_z = (-a + math.sqrt(a * a + 4.0 * b * left / mu)) / (2.0 * b)
    return t_z + 273.0


def thermal_cycle(s: CycleSpec) -> Cycle:
    """Run the calculation."""
    L0 = (s.C / 12.0 + s.H / 4.0 - s.O / 32.0) / s.air_O2
    l0 = (8.0 / 3.0 * s.C + 8.0 * s.H - s.O) / 0.23
    M1 = s.alpha * L0 + (1.0 / s.m_fuel if s.m_fuel > 0 else 0.0)
    prod = products_of(s, L0)
    M2 = sum(prod.values())
    mu0 = M2 / M1
    dH = 119950.0 * (1.0 - s.alpha) * L0 if s.alpha < 1.0 else 0.0
    eps = s.epsilon
    Tk = s.T0 + s.dT
    gamma_r = residual_fraction(Tk, s.T_r, s.p_a, s.p_r, eps, s.clean_out, s.recharge)
    T_a = end_of_intake(Tk, s.T_r, gamma_r, s.psi_r)
    eta_v = (s.T0 / Tk * (s.recharge * eps * s.p_a - s.clean_out * s.p_r)
             / ((eps - 1.0) * s.p0))
    p_c, T_c = compression(s.p_a, T_a, eps, s.n1)
    mu = (mu0 + gamma_r) / (1.0 + gamma_r)
    if s.heat_capacity == "linear":
        charge, products = linear_fits(s)
        T_z = combustion_linear(s.diesel, s.alpha, s.xi_z * (s.H_u - dH), M1, gamma_r, mu,
                                s.lambda_p, T_c, charge=charge, products=products)
    else:
        T_z = _combustion_table(s, prod, M1, gamma_r, mu, T_c, dH)
    if s.diesel:
        lam = s.lambda_p
        p_z = lam * p_c
        rho = pre_expansion(mu, T_z, lam, T_c)
        delta = eps / rho
    else:
        p_z = p_c * mu * T_z / T_c
        lam = p_z / p_c
        rho = 1.0
        delta = eps
    p_b, T_b = expansion(p_z, T_z, delta, s.n2)
    p_it = mean_indicated_theory(p_c, eps, lam, rho, s.n1, s.n2)
    p_i = mean_indicated(p_it, s.phi_i, s.p_r - s.p_a if s.pumping else 0.0)
    rho_k = s.p0 / (R_AIR * s.T0)
    eta_i = p_i * l0 * s.alpha / (s.H_u * 1e3 * rho_k * eta_v)
    g_i = 3.6e6 / (s.H_u * eta_i)
    p_e = s.eta_m * p_i
    eta_e = eta_i * s.eta_m
    return Cycle(s, L0, l0, M1, prod, M2, mu0, dH, gamma_r, T_a, eta_v, p_c, T_c, mu, T_z, p_z,
                 lam, rho, p_b, T_b, p_it, p_i, eta_i, g_i, p_e, eta_e, 3.6e6 / (s.H_u * eta_e))
