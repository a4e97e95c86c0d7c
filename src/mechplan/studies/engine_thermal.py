"""The thermal calculation's part of an engine study: report lines and JSON."""

from __future__ import annotations

import math
from typing import Any

from ..i18n import message, number, scientific
from ..model.engine_heat_balance import HeatBalance, heat_balance
from ..model.engine_thermal import Cycle
from ..sheet.engine_thermal import balance_cells


def cycle_balance(c: Cycle, V_h: float, bore: float) -> HeatBalance:
    """The heat balance of the scene's engine (its bore and cylinders) at the power it gives."""
    return heat_balance(c, c.power(V_h), bore, c.spec.cylinders)


def balance_lines(b: HeatBalance, lang: str) -> list[str]:
    """The heat balance in the report."""
    out = [message("thermal2.report.heat_title", lang, N_e=number(b.N_e * 1e-3, 2, lang),
                   G_T=number(b.G_T, 3, lang), c=number(b.c, 3, lang), m=number(b.m, 3, lang))]
    out += [message("thermal2.report.heat_row", lang, part=r[0], Q=r[1], q=r[2])
            for r in balance_cells(b, lang)[1:]]
    return out


def thermal_lines(c: Cycle, V_h: float, lang: str, bore: float | None = None) -> list[str]:
    """The thermal calculation in the report (pressures in MPa, temperatures in K); with the
    engine's ``bore`` (m), its heat balance."""
    s = c.spec

    def n(x: float, k: int = 4) -> str:
        return number(x, k, lang)

    out = [message("cycle.report.title", lang),
           message("cycle.report.diesel" if s.diesel else "cycle.report.otto", lang),
           message("cycle.report.fuel", lang, C=n(s.C, 3), H=n(s.H, 3), O=n(s.O, 3),
                   H_u=n(s.H_u * 1e-3, 2), L0=n(c.L0), l0=n(c.l0, 3), alpha=n(s.alpha, 3)),
           message("cycle.report.charge", lang, M1=n(c.M1), M2=n(c.M2), mu0=n(c.mu0),
                   dH=n(c.dH_u * 1e-3, 3)),
           message("cycle.report.intake", lang, p_a=n(s.p_a * 1e-6), gamma_r=n(c.gamma_r),
                   T_a=n(c.T_a, 1), eta_v=n(c.eta_v)),
           message("cycle.report.compression", lang, n1=n(s.n1, 3), p_c=n(c.p_c * 1e-6),
                   T_c=n(c.T_c, 1)),
           message("cycle.report.combustion", lang, xi=n(s.xi_z, 3), mu=n(c.mu), T_z=n(c.T_z, 1),
                   p_z=n(c.p_z * 1e-6), lam=n(c.lam, 3), rho=n(c.rho, 3)),
           message("cycle.report.expansion", lang, n2=n(s.n2, 3), p_b=n(c.p_b * 1e-6),
                   T_b=n(c.T_b, 1)),
           message("cycle.report.indicated", lang, p_it=n(c.p_i_theory * 1e-6),
                   phi=n(s.phi_i, 3), p_i=n(c.p_i * 1e-6), eta_i=n(c.eta_i), g_i=n(c.g_i, 1)),
           message("cycle.report.effective", lang, eta_m=n(s.eta_m, 3), p_e=n(c.p_e * 1e-6),
                   eta_e=n(c.eta_e), g_e=n(c.g_e, 1)),
           message("cycle.report.power", lang, N_e=n(c.power(V_h) * 1e-3, 2),
                   V_h=n(V_h * 1e3, 4))]
    out.insert(6, message(f"thermal4.report.fits_{s.heat_capacity}", lang))
    if s.products_fit is not None:
        out.insert(7, message("thermal5.report.products_fit", lang, a=n(s.products_fit[0], 3),
                              b=n(s.products_fit[1] * 1e4, 3)))
    if s.charge_fit is not None:
        out.insert(7, message("thermal5.report.charge_fit", lang, a=n(s.charge_fit[0], 3),
                              b=n(s.charge_fit[1] * 1e3, 3)))
    if (s.clean_out, s.recharge, s.psi_r) != (1.0, 1.0, 1.0):
        out.insert(5, message("thermal4.report.intake", lang, clean=n(s.clean_out, 3),
                              recharge=n(s.recharge, 3), psi=n(s.psi_r, 3)))
    if s.pumping:
        out.append(message("thermal4.report.pumping", lang, dp=n((s.p_r - s.p_a) * 1e-6)))
    if s.power is not None:
        vh, D, S = c.cylinder_for(s.power)
        out.append(message("cycle.report.sizing", lang, N_e=n(s.power * 1e-3, 2),
                           V_h=n(vh * 1e3, 4), D=n(D * 1e3, 2), S=n(S * 1e3, 2),
                           S_D=n(s.S_D, 3)))
    if c.wiebe is not None:
        w = c.wiebe
        p_max, phi_max = w.peak
        out.append(message("thermal2.report.wiebe", lang,
                           start=n(math.degrees(w.spec.start), 1),
                           duration=n(math.degrees(w.spec.duration), 1), m=n(w.spec.m, 3),
                           a=n(w.spec.a, 3), p_max=n(p_max * 1e-6), phi_max=n(
                               math.degrees(phi_max), 1), p_i=n(w.p_i * 1e-6),
                           residual=scientific(w.residual * V_h, 2, lang)))
    if bore is None:
        out.append(message("cycle.report.balance", lang, q_e=n(100 * c.eta_e, 2),
                           q_m=n(100 * (c.eta_i - c.eta_e), 2),
                           q_inc=n(100 * c.dH_u / s.H_u, 2),
                           q_rest=n(100 * (1 - c.eta_i - c.dH_u / s.H_u), 2)))
    else:
        out += balance_lines(cycle_balance(c, V_h, bore), lang)
    return out


def thermal_json(c: Cycle, V_h: float, bore: float | None = None) -> dict[str, Any]:
    """The thermal calculation's results (SI; kmol and kg per kg of fuel); with the engine's
    ``bore`` (m), its heat balance (W and %)."""
    s = c.spec
    doc: dict[str, Any] = {
        "diesel": s.diesel, "heat_capacity": s.heat_capacity,
        "charge_cv": list(s.charge_fit) if s.charge_fit else None,
        "products_cv": list(s.products_fit) if s.products_fit else None,
        "clean_out": s.clean_out, "recharge": s.recharge, "residual_heat": s.psi_r,
        "pumping_loss": "indicated" if s.pumping else "mechanical", "alpha": s.alpha,
        "epsilon": s.epsilon, "L0": c.L0, "l0": c.l0,
        "M1": c.M1, "products": c.products, "M2": c.M2, "mu0": c.mu0, "dH_u": c.dH_u * 1e3,
        "gamma_r": c.gamma_r, "T_a": c.T_a, "eta_v": c.eta_v, "p_a": s.p_a, "p_c": c.p_c,
        "T_c": c.T_c, "mu": c.mu, "T_z": c.T_z, "p_z": c.p_z, "lambda_p": c.lam, "rho": c.rho,
        "p_b": c.p_b, "T_b": c.T_b, "p_i_theory": c.p_i_theory, "p_i": c.p_i, "eta_i": c.eta_i,
        "g_i": c.g_i, "p_e": c.p_e, "eta_e": c.eta_e, "g_e": c.g_e, "N_e": c.power(V_h)}
    if s.power is not None:
        vh, D, S = c.cylinder_for(s.power)
        doc["sizing"] = {"N_e": s.power, "V_h": vh, "D": D, "S": S}
    if c.wiebe is not None:
        w = c.wiebe
        p_max, phi_max = w.peak
        doc["wiebe"] = {"start_deg": math.degrees(w.spec.start),
                        "duration_deg": math.degrees(w.spec.duration), "m": w.spec.m,
                        "a": w.spec.a, "Q": w.Q * V_h, "work": w.work * V_h, "dU": w.dU * V_h,
                        "residual": w.residual * V_h, "p_i": w.p_i, "p_max": p_max,
                        "phi_max_deg": math.degrees(phi_max)}
    if bore is not None:
        b = cycle_balance(c, V_h, bore)
        doc["heat_balance"] = {"N_e": b.N_e, "G_T": b.G_T, "Q0": b.Q0, "c": b.c, "m": b.m,
                               "Q": dict(b.flows), "q": b.shares}
    return doc
