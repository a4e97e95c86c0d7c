"""The energy (heat) balance of an engine as the courses write it (Kolchin–Demidov, "тепловой
баланс"; "cân bằng nhiệt"; 热平衡): the heat of the fuel burnt per second split into effective work,
the coolant, the exhaust gases, incomplete combustion and the remainder.

Per second (W), with G_T = g_e·N_e the fuel consumption (kg/h) and H_u in kJ/kg:

- Q0 = H_u·G_T/3.6, Q_e = N_e;
- coolant Q_w = c·i·D^(1+2m)·n^m·(H_u − ΔH_u)/(α·H_u) (spark ignition) or c·i·D^(1+2m)·n^m/α
  (diesel), D in cm, n in rpm: the courses' empirical formula, c and m given (courses: c = 0.45 …
  0.53, m = 0.6 … 0.7);
- exhaust Q_r = G_T/3.6·{M2·[(mc_v)″(t_r) + 8.315]·t_r − M1·[(mc_v)(t0) + 8.315]·t0} with the
  products' mean heat capacity at t_r = T_r − 273 (the 0–1500 °C fits of the calculation) and the
  fresh charge's (air, 20.6 + 2.638·10⁻³t) at the ambient t0 = T0 − 273; with the linear fits
  (``heat_capacity = "linear"``) those fits at T = t + 273 K instead (a choice: no printed
  balance with them was found);
- incomplete combustion Q_ic = ΔH_u·G_T/3.6;
- the remainder Q_rest = Q0 − (Q_e + Q_w + Q_r + Q_ic) (radiation, friction heat not carried by
  the coolant, unaccounted losses). The shares q_x = Q_x/Q0 sum to 100 % by construction.
"""

from __future__ import annotations

from dataclasses import dataclass

from .engine_thermal import LOW, R_MU, Cycle, linear_air_cv, linear_fits

#: the parts of the balance, in the order the courses print them
PARTS = ("e", "w", "r", "ic", "rest")


@dataclass(frozen=True, slots=True)
class HeatBalance:
    """Heat flows in W and their shares of Q0 in %."""

    N_e: float                   # W, effective power the balance is made for
    G_T: float                   # kg/h, fuel consumption
    Q0: float
    flows: dict[str, float]      # PARTS → W
    c: float
    m: float

    @property
    def shares(self) -> dict[str, float]:
        """Each part's share of Q0 in % (they sum to 100)."""
        return {k: 100.0 * v / self.Q0 for k, v in self.flows.items()}


def products_cv(cycle: Cycle, t: float) -> float:
    """Mean molar heat capacity at constant volume of the products at t (°C), kJ/(kmol·K), from
    0 °C: the mixture of the 0–1500 °C fits by mole fractions (or the linear fit at t + 273 K)."""
    if cycle.spec.heat_capacity == "linear":
        a, b = linear_fits(cycle.spec)[1]
        return a + b * (t + 273.0)
    prod = cycle.products
    total = sum(prod.values())
    return sum((LOW[g][0] + LOW[g][1] * t + LOW[g][2] * t * t) * v
               for g, v in prod.items()) / total


def air_cv(t: float, heat_capacity: str = "table",
           fit: tuple[float, float] | None = None) -> float:
    """Mean molar heat capacity at constant volume of air at t (°C), from 0 °C, kJ/(kmol·K)
    (or the linear fit at t + 273 K: ``fit`` (a, b) where the scene gives its own)."""
    if heat_capacity == "linear":
        return fit[0] + fit[1] * (t + 273.0) if fit else linear_air_cv(t + 273.0)
    return 20.6 + 2.638e-3 * t


def heat_balance(cycle: Cycle, N_e: float, bore: float, cylinders: int) -> HeatBalance:
    """The balance at effective power N_e (W) of ``cylinders`` cylinders of bore ``bore`` (m);
    c and m of the coolant's formula from the cycle's spec."""
    s = cycle.spec
    c, m = s.coolant_c, s.coolant_m
    G_T = cycle.g_e * N_e * 1e-3 * 1e-3          # g/(kW·h) · kW → kg/h
    Q0 = s.H_u * G_T / 3.6
    D_cm = bore * 100.0
    Q_w = c * cylinders * D_cm ** (1.0 + 2.0 * m) * s.speed_rpm ** m / s.alpha
    if not s.diesel:
        Q_w *= (s.H_u - cycle.dH_u) / s.H_u
    t_r, t0 = s.T_r - 273.0, s.T0 - 273.0
    Q_r = G_T / 3.6 * (cycle.M2 * (products_cv(cycle, t_r) + R_MU) * t_r
                       - cycle.M1 * (air_cv(t0, s.heat_capacity, s.charge_fit) + R_MU) * t0)
    Q_ic = cycle.dH_u * G_T / 3.6
    flows = {"e": N_e, "w": Q_w, "r": Q_r, "ic": Q_ic}
    flows["rest"] = Q0 - sum(flows.values())
    return HeatBalance(N_e, G_T, Q0, flows, c, m)


@dataclass(frozen=True, slots=True)
class CyclePoints:
    """The sharp-cornered cycle of the calculation in volume (m³) and pressure (Pa): the
    compression a→c and expansion z→b polytropes sampled, and the named points a, c, z′ (end of
    the constant-volume rise: z itself for a spark-ignition engine), z, b."""

    compression: tuple[list[float], list[float]]
    expansion: tuple[list[float], list[float]]
    points: dict[str, tuple[float, float]]


def cycle_points(cycle: Cycle, V_h: float, samples: int = 60) -> CyclePoints:
    """The points and polytropes of the calculated cycle for a cylinder of displacement V_h."""
    s = cycle.spec
    V_c = V_h / (s.epsilon - 1.0)
    V_a, V_z = s.epsilon * V_c, cycle.rho * V_c
    comp_V = [V_a + (V_c - V_a) * k / samples for k in range(samples + 1)]
    comp_p = [s.p_a * (V_a / v) ** s.n1 for v in comp_V]
    exp_V = [V_z + (V_a - V_z) * k / samples for k in range(samples + 1)]
    exp_p = [cycle.p_z * (V_z / v) ** s.n2 for v in exp_V]
    pts = {"a": (V_a, s.p_a), "c": (V_c, cycle.p_c)}
    if s.diesel:
        pts["z′"] = (V_c, cycle.p_z)
    pts["z"] = (V_z, cycle.p_z)
    pts["b"] = (V_a, cycle.p_b)
    return CyclePoints((comp_V, comp_p), (exp_V, exp_p), pts)
