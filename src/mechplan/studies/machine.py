"""The machine-dynamics part of a mechanism study: solve ``[dynamics]``, report, JSON, answers."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import SceneError
from ..i18n import Text, message, number, scientific
from ..model.dynamics import DynamicsSpec, Unknown
from .answers import Keys, Own, Written, span, written_all

if TYPE_CHECKING:
    from ..dynamics.machine import MachineDynamics
    from ..solve import Solution


def solve_dynamics(sol: Solution, spec: DynamicsSpec) -> MachineDynamics:
    """Solve the dynamics with the scene's drawn positions (equal steps from its first one)."""
    from ..dynamics.machine import machine_dynamics
    from ..solve import crank_positions

    scene = sol.scene
    phi = crank_positions(scene, sol.construction)
    steps = np.diff(np.unwrap(phi))
    if phi.shape[0] < 4 or not np.allclose(steps, 2 * math.pi / phi.shape[0], atol=1e-9):
        raise SceneError(
            Text("errmsg.studies_machine.dynamics_needs_positions", {"shape": str(phi.shape[0])}),
            file=scene.path,
            key="positions",
        )
    return machine_dynamics(scene, spec, float(phi[0]), int(phi.shape[0]))


def _f(x: float, digits: int, lang: str) -> str:
    return number(x, digits, lang)


def dynamics_report(d: MachineDynamics, lang: str, k: float = 1.0) -> str:
    """The text report of the dynamics in ``lang`` (paper values for diagrams at enlargement
    ``k``)."""
    from ..sheet.dynamics import dynamics_scales, table_rows

    spec = d.spec
    lines = [message("dynamics.report.title", lang, cycle=_f(math.degrees(spec.cycle), 0, lang)),
             message("dynamics.report.sign", lang),
             message("dynamics.report.mean", lang, omega=_f(d.omega_m, 3, lang),
                     delta=_f(spec.delta, 5, lang), jconst=_f(spec.inertia_const, 4, lang),
                     jcrank=_f(d.J_present - spec.inertia_const, 4, lang))]
    side = spec.unknown.value
    if spec.constant_moment is None:
        lines.append(message(f"dynamics.report.found.{side}", lang, value=_f(d.M_const, 3, lang)))
    else:
        lines.append(message(f"dynamics.report.given.{side}", lang, value=_f(d.M_const, 3, lang),
                             work=_f(d.net_work, 3, lang)))
    lines.append(message("dynamics.report.works", lang, exact=_f(d.A_d[-1], 3, lang),
                         dense=str(d.theta.shape[0] - 1), drawn=_f(d.A_d_drawn[-1], 3, lang),
                         n=str(d.drawn.shape[0] - 1)))
    lines.append(message("dynamics.report.lever", lang, n=str(d.drawn.shape[0] - 1),
                         diff=scientific(float(np.abs(d.M_lever - d.M_given).max()), 3, lang)))
    lines.append(message("dynamics.report.flywheel", lang))
    for method, J, delta in (("wittenbauer", d.witt.J_flywheel, d.delta_witt),
                             ("merkalov", d.merk.J_flywheel, d.delta_merk),
                             ("exact", d.J_exact, d.delta_exact)):
        lines.append(message("dynamics.report.method", lang,
                             method=message(f"dynamics.method.{method}", lang),
                             J=_f(J, 5, lang), delta=_f(delta, 6, lang)))
    tmax, tmin = dynamics_scales(d, k).tangent_tans(d)
    lines.append(message("dynamics.report.tangents", lang, tmax=_f(tmax, 4, lang),
                         tmin=_f(tmin, 4, lang), kl=_f(d.witt.b_max - d.witt.b_min, 3, lang)))
    lines.append(message("dynamics.report.motion", lang, wmax=_f(d.ext.omega_max, 4, lang),
                         pmax=_f(math.degrees(d.ext.theta_max), 1, lang),
                         wmin=_f(d.ext.omega_min, 4, lang),
                         pmin=_f(math.degrees(d.ext.theta_min), 1, lang)))
    lines.append(message("dynamics.report.motion_merkalov", lang,
                         wmin=_f(float(d.merk.omega.min()), 4, lang),
                         wmax=_f(float(d.merk.omega.max()), 4, lang),
                         err=_f(d.merk_omega_error, 4, lang)))
    if d.size is not None:
        s = d.size
        lines.append(message(f"dynamics.report.size.{s.shape.value}", lang,
                             D=_f(s.diameter * 1000, 1, lang), b=_f(s.width * 1000, 1, lang),
                             h=_f(s.height * 1000, 1, lang), m=_f(s.mass, 2, lang)))
    lines.append(message("dynamics.report.table", lang))
    rows = table_rows(d, lang)
    widths = [max(len(r[c]) for r in rows) for c in range(len(rows[0]))]
    lines += ["  " + "  ".join(cell.rjust(w) for cell, w in zip(r, widths)) for r in rows]
    return "\n".join(lines)


def dynamics_json(d: MachineDynamics, k: float = 1.0) -> dict[str, Any]:
    """The ``"dynamics"`` object of ``mechplan solve --json`` (SI units; angles in ``*_deg``;
    scale factors of the diagrams at enlargement ``k``)."""
    from ..sheet.dynamics import dynamics_scales

    spec, sc = d.spec, dynamics_scales(d, k)
    tmax, tmin = sc.tangent_tans(d)
    positions = []
    for j, i in enumerate(d.drawn):
        positions.append({
            "number": j, "phi_deg": round(math.degrees(float(d.theta[i])), 10),
            "M_d": float(d.M_d[i]), "M_c": float(d.M_c[i]),
            "M_given_lever": float(d.M_lever[j]),
            "A_d": float(d.A_d_drawn[j]), "A_c": float(d.A_c_drawn[j]),
            "A_d_exact": float(d.A_d[i]), "A_c_exact": float(d.A_c[i]),
            "dT": float(d.dT_drawn[j]), "dT_exact": float(d.dT[i]),
            "J_red": float(d.J_red[i]), "dJ_red": float(d.dJ_red[i]),
            "omega": float(d.omega[i]), "epsilon": float(d.epsilon[i]),
            "omega_merkalov": float(d.merk.omega[i])})
    out: dict[str, Any] = {
        "cycle_deg": math.degrees(spec.cycle),
        "start_crank_angle_deg": math.degrees(d.phi0),
        "unknown": spec.unknown.value,
        "constant_moment": d.M_const, "constant_moment_found": spec.constant_moment is None,
        "net_work": d.net_work,
        "work_driving": float(d.A_d[-1]), "work_driving_trapezoids": float(d.A_d_drawn[-1]),
        "work_resisting": float(d.A_c[-1]),
        "work_resisting_trapezoids": float(d.A_c_drawn[-1]),
        "omega_m": d.omega_m, "delta": spec.delta, "J_const": spec.inertia_const,
        "J_present": d.J_present, "dense_points": int(d.theta.shape[0] - 1),
        "scales": {"mu_phi": sc.mu_phi, "mu_M": sc.mu_M, "H_mm": sc.H_mm, "mu_A": sc.mu_A,
                   "mu_T": sc.mu_T, "mu_J": sc.mu_J},
        "flywheel": {
            "wittenbauer": {"J": d.witt.J_flywheel, "delta_actual": d.delta_witt,
                            "kl": d.witt.b_max - d.witt.b_min,
                            "kl_mm": (d.witt.b_max - d.witt.b_min) / sc.mu_T,
                            "tan_psi_max": tmax, "tan_psi_min": tmin,
                            "psi_max_deg": math.degrees(math.atan(tmax)),
                            "psi_min_deg": math.degrees(math.atan(tmin))},
            "merkalov": {"J": d.merk.J_flywheel, "J_I": d.merk.J_I,
                         "delta_actual": d.delta_merk,
                         "omega_min": float(d.merk.omega.min()),
                         "omega_max": float(d.merk.omega.max()),
                         "omega_error_max": d.merk_omega_error},
            "exact": {"J": d.J_exact, "delta_actual": d.delta_exact}},
        "motion": {"omega_max": d.ext.omega_max,
                   "phi_max_deg": math.degrees(d.ext.theta_max),
                   "omega_min": d.ext.omega_min,
                   "phi_min_deg": math.degrees(d.ext.theta_min)},
        "positions": positions}
    if d.size is not None:
        out["flywheel"]["size"] = {"shape": d.size.shape.value, "diameter": d.size.diameter,
                                   "width": d.size.width, "height": d.size.height,
                                   "mass": d.size.mass}
    return out


def dynamics_answers(d: dict[str, Any]) -> Keys:
    """The exact answers of the dynamics from its ``"dynamics"`` JSON object."""
    fly, motion = d["flywheel"], d["motion"]
    k = Keys("dynamics", study=d, formulas=_own_dynamics)
    k.scalars = {"J_fly": fly["exact"]["J"], "J_W": fly["wittenbauer"]["J"],
                 "J_Mer": fly["merkalov"]["J"], "J_I": fly["merkalov"]["J_I"],
                 "delta": d["delta"], "omega_m": d["omega_m"],
                 "omega_max": motion["omega_max"], "omega_min": motion["omega_min"],
                 "M_const": d["constant_moment"], "A_d": d["work_driving"],
                 "A_c": d["work_resisting"],
                 "dT_max": fly["exact"]["J"] * d["delta"] * d["omega_m"] ** 2}
    for name, key in (("J_red", "J_red"), ("M_d", "M_d"), ("M_c", "M_c"), ("A_d_phi", "A_d"),
                      ("A_c_phi", "A_c"), ("dT", "dT"), ("omega", "omega")):
        k.columns[name] = {float(p["phi_deg"]): float(p[key]) for p in d["positions"]}
        k.spans[name] = span(k.columns[name])
    k.spans["omega"] = motion["omega_max"] - motion["omega_min"]
    return k


def _own_dynamics(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    """δ, ω_m, J, M from the student's own ω_max/ω_min, ΔT_max, J_I and works."""
    d = k.study
    wm = w.get(("omega_m", None)) or d["omega_m"]
    extremes = written_all(w, None, "omega_max", "omega_min")
    if name == "delta" and extremes:
        return ((extremes[0] - extremes[1]) / wm, "δ = (ω_max − ω_min)/ω_m",
                ("omega_max", "omega_min"))
    if name == "omega_m" and extremes:
        return ((extremes[0] + extremes[1]) / 2, "ω_m = (ω_max + ω_min)/2",
                ("omega_max", "omega_min"))
    dT = written_all(w, None, "dT_max")
    if name in ("J_fly", "J_W") and dT:            # δ and ω_m are given data
        return (dT[0] / (d["delta"] * d["omega_m"] ** 2), "J = ΔT_max/(δ·ω_m²)", ("dT_max",))
    j1 = written_all(w, None, "J_I")
    if name in ("J_fly", "J_Mer") and j1:
        return j1[0] - d["J_present"], "J = J_I − J_const", ("J_I",)
    work_name = "A_c" if d["unknown"] == "driving" else "A_d"
    work = written_all(w, None, work_name)
    if name == "M_const" and work:
        return work[0] / math.radians(d["cycle_deg"]), "M = A/φ_cycle", (work_name,)
    return None


__all__ = ["Unknown", "dynamics_answers", "dynamics_json", "dynamics_report", "solve_dynamics"]
