"""The dynamics sheet: M_red, works, ΔT, J_red, the energy–mass diagram, ω(φ) and a table."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..drafting.primitives import Role, VAlign
from ..i18n import message, number, scale_factor, unit
from .diagram import Axis, Curve, Marker, diagram_panel, mu_text, scale_for
from .fit import TableStyle, table_panel, text_block
from .layout import enlargement, fitted_sheets
from .panels import Panel

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet
    from ..dynamics.machine import MachineDynamics
    from ..scene.spec import Scene

PHI_MM = 180.0        # length of the φ axis for the whole cycle (at enlargement 1)


@dataclass(frozen=True)
class DynamicsScales:
    """Scale factors of the dynamics sheet: μφ (rad/mm), μM, μA = μM·μφ·H, μT, μJ, H (mm)."""

    mu_phi: float
    mu_M: float
    H_mm: float
    mu_A: float
    mu_T: float
    mu_J: float

    def tangent_tans(self, d: MachineDynamics) -> tuple[float, float]:
        """tan ψ_max, tan ψ_min of Wittenbauer's tangents on paper: μJ/(2μT)·ω_m²(1 ± δ)."""
        k = self.mu_J / (2 * self.mu_T) * d.omega_m ** 2
        return k * (1 + d.spec.delta), k * (1 - d.spec.delta)


def dynamics_scales(d: MachineDynamics, k: float = 1.0) -> DynamicsScales:
    """Round scale factors for the diagrams of ``d`` drawn at enlargement ``k``."""
    mu_phi = math.radians(scale_for([0.0, math.degrees(d.spec.cycle)], PHI_MM * k))
    mu_M = scale_for(np.concatenate([d.M_d, d.M_c]), 60.0 * k)
    H = d.spec.pole_distance_mm or pole_distance(d, mu_M, mu_phi, 60.0 * k)
    return DynamicsScales(mu_phi, mu_M, H, mu_M * mu_phi * H, scale_for(d.dT, 50.0 * k),
                          scale_for(d.J_red, 60.0 * k))


def pole_distance(d: MachineDynamics, mu_M: float, mu_phi: float, height_mm: float = 60.0) -> float:
    """A round pole distance H (mm) for which the work diagram is at most ``height_mm`` tall."""
    largest = float(max(np.abs(d.A_d_drawn).max(), np.abs(d.A_c_drawn).max()))
    H = largest / (mu_M * mu_phi * height_mm)
    for step in (10.0, 5.0, 1.0):
        if H >= 2 * step:
            return step * math.ceil(H / step)
    return max(1.0, math.ceil(H * 10) / 10)


def _note(panel: Panel, text: str) -> None:
    """A note under a diagram, wrapped to the diagram's width."""
    x0, y0, x1, _ = panel.bounds()
    panel.primitives.extend(text_block((x0, y0 - 2.0), text, 2.5, x1 - x0, valign=VAlign.TOP))


def dynamics_panels(d: MachineDynamics, lang: str, scale: float = 1.0) -> list[Panel]:
    """The panels of the dynamics sheet at enlargement ``scale``, in reading order."""
    sc = dynamics_scales(d, scale)
    # the curves at ≤ 4 points per mm of the φ axis (the dense grid is finer than the pen)
    q = np.unique(np.concatenate([np.arange(0, d.theta.size, max(1, d.theta.size // 720)),
                                  d.drawn, [d.theta.size - 1]]))
    deg = np.degrees(d.theta)
    k = d.drawn
    phi_axis = Axis("φ", "°", math.degrees(d.spec.cycle) / math.degrees(sc.mu_phi),
                    mu=math.degrees(sc.mu_phi), mu_symbol="μφ")
    given = d.M_d if d.spec.unknown.value == "resisting" else d.M_c     # the variable side
    marks = [Marker(float(deg[i]), float(given[i]), str(j)) for j, i in enumerate(k[:-1])]
    moments = diagram_panel("dynamics.moments", message("dynamics.diagram.moments", lang),
                            [Curve(deg[q], d.M_d[q], label="M_d"),
                             Curve(deg[q], d.M_c[q], Role.DASHED, label="M_c")],
                            phi_axis, Axis("M", "N·m", 60.0 * scale, mu=sc.mu_M, mu_symbol="μM"),
                            lang,
                            markers=marks)
    works = diagram_panel("dynamics.works", message("dynamics.diagram.works", lang),
                          [Curve(deg[k], d.A_d_drawn, label="A_d"),
                           Curve(deg[k], d.A_c_drawn, Role.DASHED, label="A_c")],
                          phi_axis, Axis("A", "J", 60.0 * scale, mu=sc.mu_A, mu_symbol="μA"), lang)
    _note(works.panel, message("dynamics.sheet.pole", lang, H=number(sc.H_mm, 0, lang),
                               muA=scale_factor(sc.mu_A, lang)))
    energy = diagram_panel("dynamics.energy", message("dynamics.diagram.energy", lang),
                           [Curve(deg[q], d.dT[q]), Curve(deg[k], d.dT_drawn, Role.THIN)], phi_axis,
                           Axis("ΔT", "J", 50.0 * scale, mu=sc.mu_T, mu_symbol="μT"), lang)
    inertia = diagram_panel("dynamics.inertia", message("dynamics.diagram.inertia", lang),
                            [Curve(deg[q], d.J_red[q])], phi_axis,
                            Axis("J", "kg·m²", 60.0 * scale, mu=sc.mu_J, mu_symbol="μJ"), lang)
    w = d.witt
    j_hi = float(d.J_red.max()) * 1.1
    tangents = [Curve(np.array([0.0, j_hi]), np.array([w.b_max, w.b_max + w.k_max * j_hi]),
                      Role.THIN, label="ψ_max"),
                Curve(np.array([0.0, j_hi]), np.array([w.b_min, w.b_min + w.k_min * j_hi]),
                      Role.THIN, label="ψ_min")]
    witt = diagram_panel("dynamics.wittenbauer", message("dynamics.diagram.wittenbauer", lang),
                         [Curve(d.J_red[q], d.dT[q]), *tangents],
                         Axis("J", "kg·m²", 60.0 * scale, mu=sc.mu_J, mu_symbol="μJ"),
                         Axis("ΔT", "J", 50.0 * scale, mu=sc.mu_T, mu_symbol="μT"), lang,
                         markers=[Marker(0.0, w.b_max, "k"), Marker(0.0, w.b_min, "l")])
    _note(witt.panel, message("dynamics.sheet.kl", lang,
                              kl=number((w.b_max - w.b_min) / sc.mu_T, 1, lang),
                              J=number(w.J_flywheel, 4, lang)))
    omega = diagram_panel("dynamics.omega", message("dynamics.diagram.omega", lang),
                          [Curve(deg[q], d.omega[q]),
                           Curve(deg[q], d.merk.omega[q], Role.THIN,
                                 label=message("dynamics.curve.merkalov", lang))],
                          phi_axis, Axis("ω", "rad/s", 50.0 * scale), lang,
                          hlines=[(d.omega_m, "ω_m")], y_zero=False)
    _note(omega.panel, message(
        "dynamics.sheet.flywheels", lang, witt=number(w.J_flywheel, 4, lang),
        merk=number(d.merk.J_flywheel, 4, lang), exact=number(d.J_exact, 4, lang),
        wmax=number(d.ext.omega_max, 3, lang), wmin=number(d.ext.omega_min, 3, lang)))
    return [moments.panel, works.panel, energy.panel, inertia.panel, witt.panel, omega.panel,
            _table(d, lang, sc)]


def table_rows(d: MachineDynamics, lang: str) -> list[tuple[str, ...]]:
    """Heading and rows of values at the drawn positions (the last row closes the cycle)."""
    head = (message("dynamics.col.no", lang), *(
        f"{symbol}, {unit(si_unit, lang)}" for symbol, si_unit in (
            ("φ", "°"), ("M_d", "N·m"), ("M_c", "N·m"), ("A_d", "J"), ("A_c", "J"), ("ΔT", "J"),
            ("ΔT*", "J"), ("J_red", "kg·m²"), ("dJ/dφ", "kg·m²"), ("ω", "rad/s"), ("ε", "rad/s²"))))
    rows: list[tuple[str, ...]] = [head]
    for j, i in enumerate(d.drawn):
        rows.append((str(j), number(math.degrees(d.theta[i]), 0, lang),
                     number(d.M_d[i], 1, lang), number(d.M_c[i], 1, lang),
                     number(d.A_d_drawn[j], 1, lang), number(d.A_c_drawn[j], 1, lang),
                     number(d.dT_drawn[j], 1, lang), number(d.dT[i], 1, lang),
                     number(d.J_red[i], 4, lang), number(d.dJ_red[i], 4, lang),
                     number(d.omega[i], 3, lang), number(d.epsilon[i], 1, lang)))
    return rows


def _table(d: MachineDynamics, lang: str, sc: DynamicsScales) -> Panel:
    """The table of values at the drawn positions, № and φ repeated in each part when split."""
    return table_panel("dynamics.table", mu_text("μM", sc.mu_M, "N·m", lang), table_rows(d, lang),
                       TableStyle(title_h=2.5, key_columns=2))


def dynamics_sheets(d: MachineDynamics, scene: Scene, size: str, standard: str, lang: str,
                    name: str) -> list[Sheet]:
    """The dynamics sheet(s) ``name`` (``name-2`` … when the panels need more)."""
    fields = {"title": scene.title, "document_type": message("dynamics.sheet.title", lang)}
    fields.update({k: v for k, v in scene.drawing.title_block.items() if v})
    return fitted_sheets(lambda scale: dynamics_panels(d, lang, scale), size=size,
                         standard=standard, language=lang, name=name, fields=fields,
                         split=True)


def dynamics_enlargement(d: MachineDynamics, scene: Scene) -> float:
    """The enlargement of the dynamics diagrams on the scene's own sheet (size, language)."""
    lang = scene.language
    fields = {"title": scene.title, "document_type": message("dynamics.sheet.title", lang)}
    fields.update({k: v for k, v in scene.drawing.title_block.items() if v})
    return enlargement(lambda scale: dynamics_panels(d, lang, scale), size=scene.drawing.sheet,
                       standard=scene.drawing.standard, language=lang, fields=fields,
                       split=True)
