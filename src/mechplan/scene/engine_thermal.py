"""Parse an engine scene's ``[thermal]`` table (the thermal calculation of the cycle) and turn its
result into the indicator diagram's thermal parameters."""

from __future__ import annotations

import dataclasses
import math

from ..i18n import Text
from ..model.engine import IndicatorKind, IndicatorSpec, ThermalSpec
from ..model.engine_thermal import FUELS, HEAT_CAPACITY, Cycle, CycleSpec, thermal_cycle
from ..model.engine_wiebe import WiebeSpec, fuel_heat, wiebe_cycle
from .reader import Table

KEYS = ("cycle", "fuel", "C", "H", "O", "heating_value", "fuel_molar_mass", "alpha", "epsilon",
        "p0", "T0", "dT", "p_a", "p_r", "T_r", "n1", "n2", "xi_z", "lambda_p", "K", "phi_i",
        "eta_m", "power_kW", "stroke_bore", "intake_losses", "intake_velocity", "coolant_c",
        "coolant_m", "combustion", "combustion_start", "combustion_duration", "wiebe_m",
        "wiebe_a", "air_oxygen", "heat_capacity", "clean_out", "recharge", "residual_heat",
        "pumping_loss", "charge_cv", "products_cv")


def _number(t: Table, name: str, default: float | None, lo: float, hi: float,
            what: str) -> float:
    """A plain number ``name`` (``what`` it is, for the reader of the code) within [lo, hi]."""
    v = t.quantity(name, "dimensionless", default, required=default is None)
    assert v is not None
    if not lo <= v <= hi:
        raise t.error(name, Text("cycle.error.range", {"lo": lo, "hi": hi, "value": v}))
    return v


def _intake(t: Table, p0: float, T0: float) -> float:
    """p_a given, or p0 − Δp_a with Δp_a = (β² + ξ)·w²·ρ_k/2 (Kolchin–Demidov, at the rated
    speed) from ``intake_losses`` (β² + ξ) and ``intake_velocity`` w."""
    if t.has("p_a"):
        if t.has("intake_losses") or t.has("intake_velocity"):
            raise t.error("p_a", Text("cycle.error.intake_both"))
        v = t.quantity("p_a", "pressure", required=True, positive=True)
        assert v is not None
        return v
    if not (t.has("intake_losses") and t.has("intake_velocity")):
        raise t.error("p_a", Text("cycle.error.intake_missing"))
    k = _number(t, "intake_losses", None, 1.0, 10.0, "β² + ξ of the intake")
    w = t.quantity("intake_velocity", "velocity", required=True, positive=True)
    assert w is not None
    p_a = p0 - k * w * w * p0 / (287.0 * T0) / 2.0
    if not p_a > 0.3 * p0:
        raise t.error("intake_velocity", Text("cycle.error.intake_loss", {"p_a": p_a * 1e-3}))
    return p_a


def _fit(t: Table, name: str, fits: str, lo: float, hi: float) -> tuple[float, float] | None:
    """A linear heat-capacity fit given by its coefficients ``[a, b]`` (mc_v = a + b·T,
    kJ/(kmol·K), T in K): only with ``heat_capacity = "linear"``; a within [lo, hi], b within
    0 … 0.01."""
    if not t.has(name):
        return None
    raw = t.raw(name)
    if fits != "linear":
        raise t.error(name, Text("thermal5.error.fit_table"))
    ok = (isinstance(raw, list) and len(raw) == 2
          and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in raw))
    if not ok or not (lo <= raw[0] <= hi and 0.0 <= raw[1] <= 0.01):
        raise t.error(name, Text("thermal5.error.fit", {"lo": lo, "hi": hi}))
    return float(raw[0]), float(raw[1])


def _wiebe(t: Table, c: Cycle, strokes: int, lam: float) -> Cycle:
    """The optional single-zone Wiebe model (``combustion = "wiebe"``) attached to the cycle, for a
    four- or two-stroke engine."""
    start = t.quantity("combustion_start", "angle", math.radians(10.0))
    duration = t.quantity("combustion_duration", "angle", math.radians(60.0), positive=True)
    assert start is not None and duration is not None
    m = _number(t, "wiebe_m", 1.5, 0.0, 6.0, "the Wiebe shape exponent m")
    a = _number(t, "wiebe_a", 6.908, 1.0, 12.0, "the Wiebe completeness a")
    late = duration - start
    if not -math.pi / 2 < start < math.pi / 2 or not late < 0.9 * math.pi:
        raise t.error("combustion_start",
                      Text("thermal3.error.wiebe", {"start": f"{math.degrees(start):g}",
                                                    "duration": f"{math.degrees(duration):g}"}))
    s = c.spec
    V_h = 1.0        # m³: the model scales with V_h; the scene's cylinder is applied below
    Q = fuel_heat(s.p_a, c.T_a, s.epsilon * V_h / (s.epsilon - 1.0), c.gamma_r, c.M1, s.xi_z,
                  s.H_u, c.dH_u)
    w = wiebe_cycle(V_h, s.epsilon, lam, s.p_a, c.T_a, s.p_r, s.n1, s.n2, Q,
                    WiebeSpec(start, duration, m, a), strokes=strokes)
    return dataclasses.replace(c, wiebe=w)


def parse_thermal(t: Table, *, strokes: int, cylinders: int, speed: float, p0: float,
                  stroke_bore: float, lam: float = 0.0) -> tuple[Cycle, IndicatorSpec]:
    """The thermal calculation and the indicator diagram it gives (rounded as the courses do, or
    the optional Wiebe model's)."""
    t.check_keys(KEYS)
    fuel = t.string("fuel", "petrol", choices=tuple(FUELS)) or "petrol"
    C0, H0, O0, Hu0, m0 = FUELS[fuel]
    diesel = (t.string("cycle", "diesel" if fuel == "diesel" else "otto",
                       choices=("otto", "diesel")) == "diesel")
    C = _number(t, "C", C0, 0.0, 1.0, "the carbon mass fraction")
    H = _number(t, "H", H0, 0.0, 1.0, "the hydrogen mass fraction")
    O = _number(t, "O", O0, 0.0, 1.0, "the oxygen mass fraction")
    if abs(C + H + O - 1.0) > 0.02:
        raise t.error("C", Text("cycle.error.sum", {"value": C + H + O}))
    Hu = _number(t, "heating_value", Hu0 * 1e-3, 10.0, 150.0, "the lower heating value in MJ/kg")
    m_f = _number(t, "fuel_molar_mass", m0, 0.0, 1000.0, "the fuel's molar mass in kg/kmol")
    alpha = _number(t, "alpha", None, 0.5, 5.0, "the excess-air ratio α")
    if diesel and alpha < 1.0:
        raise t.error("alpha", Text("cycle.error.diesel_alpha", {"value": alpha}))
    eps = _number(t, "epsilon", None, 2.0, 30.0, "the compression ratio ε")
    p_amb = t.quantity("p0", "pressure", p0, positive=True)
    p_r = t.quantity("p_r", "pressure", required=True, positive=True)
    assert p_amb is not None and p_r is not None
    T0 = _number(t, "T0", 293.0, 200.0, 400.0, "the ambient temperature in K")
    p_a = _intake(t, p_amb, T0)
    if not eps * p_a > p_r:
        raise t.error("p_r", Text("cycle.error.residual"))
    dT = _number(t, "dT", 10.0 if not diesel else 15.0, 0.0, 60.0, "the charge heating in K")
    T_r = _number(t, "T_r", None, 500.0, 1300.0, "the residual-gas temperature in K")
    n1 = _number(t, "n1", None, 1.2, 1.45, "the compression polytrope n1")
    n2 = _number(t, "n2", None, 1.1, 1.4, "the expansion polytrope n2")
    xi = _number(t, "xi_z", None, 0.5, 1.0, "the heat-use coefficient ξ_z")
    lam_p = _number(t, "lambda_p", 1.7 if diesel else 0.0, 0.0, 3.0,
                    "the pressure-rise ratio λ_p") if diesel else 0.0
    if diesel and lam_p < 1.0:
        raise t.error("lambda_p", Text("cycle.error.lambda_p", {"value": lam_p}))
    K = _number(t, "K", 0.5, 0.0, 1.0, "H2/CO in the products K")
    phi_i = _number(t, "phi_i", 0.96 if not diesel else 0.95, 0.8, 1.0,
                    "the fullness of the diagram φ_i")
    eta_m = _number(t, "eta_m", 0.8, 0.3, 1.0, "the mechanical efficiency η_m")
    power = t.quantity("power_kW", "dimensionless", positive=True)
    S_D = _number(t, "stroke_bore", stroke_bore, 0.3, 3.0, "the stroke-to-bore ratio S/D")
    c_w = _number(t, "coolant_c", 0.5, 0.3, 0.7, "c of the coolant's heat (heat balance)")
    m_w = _number(t, "coolant_m", 0.65, 0.5, 0.8, "m of the coolant's heat (heat balance)")
    o2 = _number(t, "air_oxygen", 0.208, 0.2, 0.22, "O2 in air by volume")
    fits = t.string("heat_capacity", "table", choices=HEAT_CAPACITY) or "table"
    charge_fit = _fit(t, "charge_cv", fits, 15.0, 30.0)
    products_fit = _fit(t, "products_cv", fits, 15.0, 35.0)
    clean = _number(t, "clean_out", 1.0, 0.0, 1.0, "the clean-out coefficient φ_cl")
    recharge = _number(t, "recharge", 1.0, 0.9, 1.2, "the recharge coefficient φ_rc")
    psi = _number(t, "residual_heat", 1.0, 0.8, 1.3, "ψ of T_a (residual gases' heat capacity)")
    pumping = t.string("pumping_loss", "mechanical",
                       choices=("mechanical", "indicated")) == "indicated"
    if not eps * recharge * p_a > clean * p_r:
        raise t.error("p_r", Text("cycle.error.residual"))
    spec = CycleSpec(diesel, C, H, O, Hu * 1e3, m_f if not diesel else 0.0, alpha, eps,
                     speed * 30.0 / 3.141592653589793, p_amb, T0, dT, p_a, p_r, T_r, n1, n2, xi,
                     lam_p, K, phi_i, eta_m, strokes, cylinders,
                     power * 1e3 if power is not None else None, S_D, c_w, m_w, o2, fits, clean,
                     recharge, psi, pumping, charge_fit, products_fit)
    cycle = thermal_cycle(spec)
    if not cycle.rho < eps:
        raise t.error("xi_z", Text("cycle.error.rho", {"rho": cycle.rho}))
    if t.string("combustion", "schematic", choices=("schematic", "wiebe")) == "wiebe":
        cycle = _wiebe(t, cycle, strokes, lam)
        assert cycle.wiebe is not None
        return cycle, IndicatorSpec(IndicatorKind.CRANK_ANGLE, rows=cycle.wiebe.rows,
                                    epsilon=eps)
    thermal = ThermalSpec(eps, p_a, p_r, n1, n2, cycle.p_z, cycle.rho)
    if 1.2 * cycle.p_c > 0.85 * cycle.p_z:
        thermal = ThermalSpec(eps, p_a, p_r, n1, n2, cycle.p_z, cycle.rho, rounding=False)
    return cycle, IndicatorSpec(IndicatorKind.THERMAL, thermal=thermal, epsilon=eps)
