"""The thermal calculation's panels: the calculated indicator diagram (theoretical cycle with its
points a, c, z′, z, b and the rounded diagram the dynamic calculation uses), the table of the
calculation's results and the heat balance. Numbers come from the model; this module only draws."""

from __future__ import annotations

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import Circle, HAlign, Role, Text, VAlign
from ..i18n import message, number, unit
from ..model.engine_heat_balance import PARTS, CyclePoints, HeatBalance
from ..model.engine_thermal import Cycle
from ..model.engine_wiebe import Wiebe
from .diagram import TEXT_H, Axis, Curve, Marker, diagram_panel
from .fit import TableStyle, table_panel
from .panels import Panel

STYLE = TableStyle(text_h=1.8, row_h=4.0, head_h=6.0)
CM3 = 1e6


def indicator_panel(points: CyclePoints, rounded: tuple[np.ndarray, np.ndarray], lang: str,
                    scale: float = 1.0) -> Panel:
    """p–V: the theoretical cycle dashed, the rounded diagram (V, p in m³, Pa) thick, the points
    labelled."""
    cV, cp = points.compression
    eV, ep = points.expansion
    pts = points.points
    theory_V = [*cV, *([pts["z′"][0]] if "z′" in pts else []), *eV, cV[0]]
    theory_p = [*cp, *([pts["z′"][1]] if "z′" in pts else []), *ep, cp[0]]
    V, p = rounded
    curves = [Curve(np.asarray(theory_V) * CM3, np.asarray(theory_p) * 1e-6, Role.DASHED),
              Curve(np.asarray(V) * CM3, np.asarray(p) * 1e-6, Role.OUTLINE, closed=True)]
    dia = diagram_panel("thermal_indicator", message("thermal2.diagram.indicator", lang), curves,
                        Axis("V", "cm³", 150.0 * scale), Axis("p", "MPa", 130.0 * scale), lang)
    prims = dia.panel.primitives
    for name, (v, pp) in pts.items():
        x, y = v * CM3 / dia.mu_x, pp * 1e-6 / dia.mu_y
        prims.append(Circle((x, y), 0.6, Role.OUTLINE))
        # a, b, z to the right of their points; c to the left; z′ above (z is beside it)
        dx, ha = {"c": (-1.5, HAlign.RIGHT), "z′": (0.0, HAlign.CENTER)}.get(
            name, (1.5, HAlign.LEFT))
        prims.append(Text((x + dx, y + (2.0 if name == "z′" else 1.0)), name, TEXT_H,
                          halign=ha, valign=VAlign.BOTTOM))
    return dia.panel


def results_cells(c: Cycle, N_e: float, lang: str) -> list[list[str]]:
    """Quantity, value, unit of the calculation's main results."""
    s = c.spec
    rows: list[tuple[str, float, int, str]] = [
        ("L0", c.L0, 4, "kmol/kg"), ("M1", c.M1, 4, "kmol/kg"), ("M2", c.M2, 4, "kmol/kg"),
        ("mu0", c.mu0, 4, ""), ("p_a", s.p_a * 1e-6, 4, "MPa"), ("gamma_r", c.gamma_r, 4, ""),
        ("T_a", c.T_a, 1, "K"), ("eta_v", c.eta_v, 4, ""), ("p_c", c.p_c * 1e-6, 4, "MPa"),
        ("T_c", c.T_c, 1, "K"), ("mu", c.mu, 4, ""), ("T_z", c.T_z, 1, "K"),
        ("p_z", c.p_z * 1e-6, 4, "MPa"), ("lam", c.lam, 3, ""), ("rho", c.rho, 3, ""),
        ("p_b", c.p_b * 1e-6, 4, "MPa"), ("T_b", c.T_b, 1, "K"),
        ("p_it", c.p_i_theory * 1e-6, 4, "MPa"), ("p_i", c.p_i * 1e-6, 4, "MPa"),
        ("eta_i", c.eta_i, 4, ""), ("g_i", c.g_i, 1, "g/(kW·h)"), ("eta_m", s.eta_m, 3, ""),
        ("p_e", c.p_e * 1e-6, 4, "MPa"), ("eta_e", c.eta_e, 4, ""),
        ("g_e", c.g_e, 1, "g/(kW·h)"), ("N_e", N_e * 1e-3, 2, "kW")]
    out = [[message(f"thermal2.col.{k}", lang) for k in ("quantity", "value", "unit")]]
    out += [[message(f"thermal2.row.{k}", lang), number(v, d, lang), unit(u, lang) if u else "—"]
            for k, v, d, u in rows]
    return out


def balance_cells(b: HeatBalance, lang: str) -> list[list[str]]:
    """Heading and rows of the heat-balance table: Q0, then each part in kW and % of Q0."""
    rows = [[message(f"thermal2.col.{k}", lang) for k in ("part", "Q", "q")],
            [message("thermal2.part.total", lang), number(b.Q0 * 1e-3, 2, lang),
             number(100.0, 2, lang)]]
    shares = b.shares
    rows += [[message(f"thermal2.part.{k}", lang), number(b.flows[k] * 1e-3, 2, lang),
              number(shares[k], 2, lang)] for k in PARTS]
    return rows


def _widths(cells: list[list[str]]) -> list[float]:
    return [max(12.0, 2.0 + 1.6 * max(len(r[j]) for r in cells)) for j in range(len(cells[0]))]


def wiebe_panel(w: Wiebe, lang: str, scale: float = 1.0) -> Panel:
    """p(φ) of the Wiebe model over the closed part, the start and end of combustion marked."""
    deg = np.degrees(w.phi_cycle)
    span = float(deg[-1] - deg[0])
    mu = round_scale(span / (144.0 * scale))
    start = float(np.degrees(w.phi_cycle[0] - w.phi[0])) + 360.0 - float(np.degrees(w.spec.start))
    end = start + float(np.degrees(w.spec.duration))
    p_s, p_e = (float(np.interp(a, deg, w.p)) * 1e-6 for a in (start, end))
    title = message("thermal2.diagram.wiebe", lang, start=number(np.degrees(w.spec.start), 1,
                                                                    lang),
                    duration=number(np.degrees(w.spec.duration), 1, lang),
                    m=number(w.spec.m, 3, lang))
    return diagram_panel("thermal_wiebe", title, [Curve(deg, w.p * 1e-6)],
                         Axis("φ", "°", span / mu, mu=mu, mu_symbol="μφ"),
                         Axis("p", "MPa", 110.0 * scale), lang, x_zero=False,
                         markers=[Marker(start, p_s, "φs"), Marker(end, p_e, "φe")]).panel


def thermal_panels(c: Cycle, points: CyclePoints, rounded: tuple[np.ndarray, np.ndarray],
                   balance: HeatBalance, lang: str, scale: float = 1.0) -> list[Panel]:
    """The diagram, the results table and the heat-balance table."""
    res = results_cells(c, balance.N_e, lang)
    bal = balance_cells(balance, lang)
    extra = [wiebe_panel(c.wiebe, lang, scale)] if c.wiebe is not None else []
    return [*extra, indicator_panel(points, rounded, lang, scale),
            table_panel("thermal_results", message("thermal2.diagram.results", lang), res, STYLE,
                        widths=_widths(res)),
            table_panel("thermal_balance", message("thermal2.diagram.balance", lang),
                        bal, STYLE, widths=_widths(bal))]
