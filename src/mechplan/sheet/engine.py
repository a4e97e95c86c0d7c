"""The engine-dynamics sheets: indicator diagram with Brix's circle, forces, torque, polar and wear
diagrams of the crank pin, the per-angle table — every diagram with its scale factors."""

from __future__ import annotations

import math
from typing import Protocol

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import (
    Arc,
    Circle,
    HAlign,
    Line,
    Polyline,
    Role,
    Sheet,
    Text,
    VAlign,
)
from ..dynamics.engine.analysis import Checks, EngineResult
from ..dynamics.engine.balance import Balance
from ..dynamics.engine.cylinder import CylinderForces
from ..dynamics.engine.extremes import TorqueExtremes
from ..dynamics.engine.model import EngineModel
from ..i18n import message, number
from ..scene.engine import EngineScene
from .diagram import TEXT_H, Axis, Curve, Diagram, Marker, diagram_panel, mu_text
from .fit import TableStyle, table_panel, text_block
from .layout import fitted_sheets
from .panels import Panel


class EngineData(Protocol):
    """What the sheets need of a solved engine (``mechplan.studies.engine.EngineStudy``)."""

    scene: EngineScene
    model: EngineModel

    @property
    def dense(self) -> EngineResult: ...

    @property
    def table(self) -> EngineResult: ...

    @property
    def checks(self) -> Checks: ...

    @property
    def wear(self) -> tuple[np.ndarray, np.ndarray]: ...

    @property
    def balance(self) -> Balance: ...

    @property
    def extremes(self) -> TorqueExtremes: ...


#: per-cylinder columns of the table: (attribute, CSV name, scale to the printed unit)
COLUMNS = (("p", "p_MPa", 1e-6), ("Pk", "Pk_kN", 1e-3), ("Pj", "Pj_kN", 1e-3), ("P", "P_kN", 1e-3),
           ("beta", "beta_deg", 180.0 / math.pi), ("N", "N_kN", 1e-3), ("S", "S_kN", 1e-3),
           ("T", "T_kN", 1e-3), ("Z", "Z_kN", 1e-3), ("M", "M_Nm", 1.0))


def columns_of(f: CylinderForces) -> tuple[tuple[str, str, float], ...]:
    """The table's columns for one cylinder: with p_rod after p for a double-acting one."""
    if f.p_rod is None:
        return COLUMNS
    return (COLUMNS[0], ("p_rod", "p_rod_MPa", 1e-6), *COLUMNS[1:])


def table_cells(t: EngineResult, language: str, number_of: int = 1) -> list[list[str]]:
    """Heading and rows of the per-angle table of one cylinder, with ΣM and the |Q| of the crank
    pin that cylinder's rod turns (named in the heading when the engine has several pins)."""
    f = t.cylinders[number_of]
    pin = t.pin_of(number_of)
    q_head = (message("numbers.engine.col.Q_pin", language, pin=pin) if len(t.pins) > 1
              else message("engine.col.Q", language))
    head = [message("engine.col.phi", language)] + [
        message(f"engine.col.{a}", language) for a, _, _ in COLUMNS] + [
        message("engine.col.M_total", language), q_head]
    digits = {"p": 3, "p_rod": 3, "beta": 2, "M": 2}
    columns = columns_of(f)
    if f.p_rod is not None:                     # a double-acting cylinder: the crank end's p
        head.insert(2, message("layouts.col.p_rod", language))
    rows = [head]
    Q = t.pins[pin].Q
    for k, phi in enumerate(t.phi):
        row = [number(math.degrees(phi), 0, language)]
        for a, _, scale in columns:
            v = float(getattr(f, a)[k]) * scale
            row.append("—" if not math.isfinite(v) else number(v, digits.get(a, 3), language))
        row += [number(float(t.M_total[k]), 2, language), number(float(Q[k]) * 1e-3, 3, language)]
        rows.append(row)
    return rows

W = 150.0        # mm, diagram width
H = 80.0         # mm, diagram height


def engine_sheets(study: EngineData, size: str, standard: str, language: str,
                  name: str) -> list[Sheet]:
    """All panels of an engine study laid out on framed sheets."""
    lang = language

    def panels(scale: float) -> list[Panel]:
        out = [f(study, lang, scale) for f in (indicator_panel, forces_panel, tz_panel,
                                               torque_panel, polar_panel, developed_panel,
                                               wear_panel)]
        out += table_panels(study, lang)
        if study.scene.balance is not None:
            out += _balance_panels(study, lang, scale)
        if study.scene.cycle is not None:
            out += _thermal_panels(study, lang, scale)
        return out

    fields = {"title": study.scene.engine.title or message("engine.sheet.title", lang)}
    fields.update({k: v for k, v in study.scene.drawing.title_block.items() if v})
    return fitted_sheets(panels, size=size, standard=standard, language=lang, name=name,
                         fields=fields)


def _balance_panels(study: EngineData, lang: str, scale: float) -> list[Panel]:
    """The balancing panels (sheet/engine_balance.py) of a scene with a [balance] table."""
    from .engine_balance import balance_panels

    m = study.model
    bank = {c.number: c.bank for c in study.scene.engine.cylinders}
    banks = {n: b - bank[1] for n, b in bank.items()}
    return balance_panels(study.balance, m.phases, banks, study.dense.phi, lang, scale)


def _thermal_panels(study: EngineData, lang: str, scale: float) -> list[Panel]:
    """The thermal calculation's panels (sheet/engine_thermal.py) of a scene with [thermal]."""
    from ..model.engine_heat_balance import cycle_points, heat_balance
    from .engine_thermal import thermal_panels

    c, spec = study.scene.cycle, study.scene.engine
    assert c is not None
    bal = heat_balance(c, c.power(spec.V_h), spec.bore, c.spec.cylinders)
    return thermal_panels(c, cycle_points(c, spec.V_h), study.model.diagram.loop(), bal, lang,
                          scale)


def _deg(phi: np.ndarray) -> np.ndarray:
    return np.degrees(phi)


def _phi_axis(study: EngineData, scale: float) -> Axis:
    cycle = math.degrees(study.scene.engine.cycle)
    mu = round_scale(cycle / (144.0 * scale))
    return Axis("φ", "°", cycle / mu + (W - 144.0) * scale, mu=mu, mu_symbol="μφ")


def indicator_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """p–V diagram with Brix's semicircle (pole O′ shifted by Rλ/2 towards BDC) under it."""
    m, spec = study.model, study.scene.engine
    V, p = m.diagram.loop()
    cm3 = 1e6
    # without ε the clearance volume is unknown: draw against the swept volume V − V_c
    origin = 0.0 if m.diagram.V_c_given else m.diagram.V_c
    v_name = "V" if m.diagram.V_c_given else message("layouts.axis.swept", lang)
    curves = [Curve((V - origin) * cm3, p * 1e-6, closed=True)]
    f1 = study.dense.cylinders[1]
    if f1.p_rod is not None:
        # the crank end's card over the same piston travel (both ends on one base, as indicated)
        curves.append(Curve((m.diagram.V_c - origin + spec.F_p * f1.x) * cm3, f1.p_rod * 1e-6,
                            Role.DASHED, "p_rod", closed=True))
    dia = diagram_panel("indicator", message("engine.diagram.indicator", lang), curves,
                        Axis(v_name, "cm³", 150.0 * scale), Axis("p", "MPa", 130.0 * scale), lang)
    prims = dia.panel.primitives
    Vc, Vh = (m.diagram.V_c - origin) * cm3, m.diagram.V_h * cm3
    r_mm = Vh / 2.0 / dia.mu_x
    cx = (Vc + Vh / 2.0) / dia.mu_x
    cy = -16.0 - r_mm
    shift = spec.F_p * spec.R * spec.lam / 2.0 * cm3 / dia.mu_x
    prims.append(Arc((cx, cy), r_mm, 180.0, 360.0, Role.THIN))
    prims.append(Line((cx - r_mm, cy), (cx + r_mm, cy), Role.THIN))
    ox = cx + shift
    prims.append(Circle((cx, cy), 0.5, Role.OUTLINE))
    prims.append(Circle((ox, cy), 0.5, Role.OUTLINE))
    prims.append(Text((cx - 1.0, cy + 1.0), "O", TEXT_H, halign=HAlign.RIGHT))
    prims.append(Text((ox + 1.0, cy + 1.0), "O′", TEXT_H))
    lam = spec.lam
    for k in range(1, 6):
        phi = math.radians(30.0 * k)
        t = (r_mm / 2.0) * (lam * math.cos(phi) + math.sqrt(4.0 - lam * lam * math.sin(phi) ** 2))
        px, py = ox - t * math.cos(phi), cy - t * math.sin(phi)
        prims.append(Line((ox, cy), (px, py), Role.THIN))
        prims.append(Line((px, py), (px, 0.0), Role.DASHED))
        prims.append(Text((px, py - 1.0), f"{30 * k}°", 1.8, halign=HAlign.CENTER,
                          valign=VAlign.TOP))
    x1 = dia.panel.bounds()[2]
    prims.extend(text_block((cx - r_mm, cy - r_mm - 4.0),
                            message("engine.label.brix", lang,
                                    shift=_num(spec.R * lam / 2.0 * 1e3, lang)),
                            TEXT_H, x1 - (cx - r_mm), valign=VAlign.TOP))
    return dia.panel


def _num(x: float, lang: str, k: int = 2) -> str:
    return number(x, k, lang)


def forces_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """Pk, Pj and P of cylinder 1 against φ."""
    d = study.dense
    f = d.cylinders[1]
    x = _deg(d.phi)
    curves = [Curve(x, f.Pk * 1e-3, Role.THIN, "Pk"), Curve(x, f.Pj * 1e-3, Role.DASHED, "Pj"),
              Curve(x, f.P * 1e-3, Role.OUTLINE, "P")]
    return diagram_panel("forces", message("engine.diagram.forces", lang), curves,
                         _phi_axis(study, scale), Axis("P", "kN", H * scale), lang).panel


def tz_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """T and Z of cylinder 1 (for the articulated pair: T and Z on the shared pin)."""
    d = study.dense
    q = d.pins[1]
    x = _deg(d.phi)
    curves = [Curve(x, q.T * 1e-3, Role.OUTLINE, "T"), Curve(x, q.Z * 1e-3, Role.DASHED, "Z")]
    return diagram_panel("tz", message("engine.diagram.tz", lang), curves, _phi_axis(study, scale),
                         Axis("T, Z", "kN", H * scale), lang).panel


def torque_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """ΣM of the engine (cylinders thin) with its mean."""
    d = study.dense
    x = _deg(d.phi)
    curves = []
    if len(d.cylinders) > 1:
        curves += [Curve(x, f.M, Role.THIN) for f in d.cylinders.values()]
    curves.append(Curve(x, d.M_total, Role.OUTLINE, "ΣM"))
    mean = study.checks.work_torque / study.scene.engine.cycle
    ex = study.extremes                 # found between the grid points
    marks = [Marker(math.degrees(ex.phi_max), ex.M_max, "max"),
             Marker(math.degrees(ex.phi_min), ex.M_min, "min")]
    return diagram_panel("torque", message("engine.diagram.torque", lang), curves,
                         _phi_axis(study, scale),
                         Axis("M", "N·m", H * scale), lang, markers=marks,
                         hlines=[(mean, message("engine.label.mean", lang))]).panel


def polar_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """Polar diagram of the load on crank pin 1: ends of (T, Z); Q is drawn from the pole O_p."""
    d, t = study.dense, study.table
    q = d.pins[1]
    qt = t.pins[1]
    pole = -q.K_r * 1e-3
    dia = diagram_panel("polar", message("engine.diagram.polar", lang),
                        [Curve(q.T * 1e-3, q.Z * 1e-3, Role.OUTLINE, closed=True)],
                        Axis("T", "kN", 150.0 * scale), Axis("Z", "kN", 150.0 * scale), lang,
                        markers=[Marker(0.0, pole, "Oₚ")])
    mu_x, mu_y = dia.mu_x, dia.mu_y
    if abs(mu_x - mu_y) > 1e-12 * mu_x:              # a polar diagram needs one scale
        mu = max(mu_x, mu_y)
        dia = diagram_panel("polar", message("engine.diagram.polar", lang),
                            [Curve(q.T * 1e-3, q.Z * 1e-3, Role.OUTLINE, closed=True)],
                            Axis("T", "kN", 110.0 * scale, mu=mu),
                            Axis("Z", "kN", 110.0 * scale, mu=mu), lang,
                            markers=[Marker(0.0, pole, "Oₚ")])
    prims = dia.panel.primitives
    px, py = dia.to_mm(0.0, pole)
    prims.append(Circle((px, py), 0.8, Role.OUTLINE))
    step = max(1, (len(t.phi) - 1) // 24)
    for k in range(0, len(t.phi) - 1, step):
        x, y = dia.to_mm(float(qt.T[k]) * 1e-3, float(qt.Z[k]) * 1e-3)
        prims.append(Circle((x, y), 0.4, Role.THIN))
        prims.append(Text((x + 0.8, y + 0.8), number(math.degrees(float(t.phi[k])), 0, lang),
                          1.8))
    kmax = int(np.argmax(q.Q))
    x, y = dia.to_mm(float(q.T[kmax]) * 1e-3, float(q.Z[kmax]) * 1e-3)
    prims.append(Line((px, py), (x, y), Role.DASHED))
    prims.append(Text((x + 1.0, y - 3.0), "Qmax", TEXT_H))
    return dia.panel


def developed_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """|Q|(φ) of crank pin 1 with Q_mean."""
    d = study.dense
    Q = d.pins[1].Q * 1e-3
    mean = float(np.trapezoid(Q, d.phi) / study.scene.engine.cycle)
    return diagram_panel("developed", message("engine.diagram.developed", lang),
                         [Curve(_deg(d.phi), Q, Role.OUTLINE, "Q")], _phi_axis(study, scale),
                         Axis("Q", "kN", H * scale), lang,
                         hlines=[(mean, message("engine.label.Q_mean", lang))]).panel


def wear_panel(study: EngineData, lang: str, scale: float = 1.0) -> Panel:
    """Wear diagram of crank pin 1: the circle, 24 rays, the summed loads drawn inwards."""
    rays, sums = study.wear
    radius = 40.0 * scale
    from .diagram import scale_for
    mu = scale_for(sums * 1e-3, radius * 0.8)
    prims: list = [Circle((0.0, 0.0), radius, Role.THIN)]
    ends = []
    for psi, s in zip(rays, sums * 1e-3):
        ux, uy = -math.sin(psi), math.cos(psi)      # crank outward = up, sense of rotation = left
        prims.append(Line((0.0, 0.0), (radius * ux, radius * uy), Role.THIN))
        prims.append(Text((radius * 1.08 * ux, radius * 1.08 * uy),
                          f"{number(math.degrees(psi), 0, lang)}°",
                          1.8, halign=HAlign.CENTER, valign=VAlign.MIDDLE))
        r_in = radius - s / mu
        ends.append((r_in * ux, r_in * uy))
    prims.append(Polyline(tuple(ends), Role.OUTLINE, closed=True))
    best = int(np.argmin(sums))
    ux, uy = -math.sin(rays[best]), math.cos(rays[best])
    prims.append(Line((radius * ux, radius * uy), (radius * 1.25 * ux, radius * 1.25 * uy),
                      Role.OUTLINE))
    x0, _, x1, _ = Panel("", prims).bounds()
    notes: list = []
    y = -radius - 6.0
    for note in (mu_text("μw", mu, "kN", lang),
                 message("engine.label.oil_hole", lang,
                         angle=number(math.degrees(float(rays[best])), 0, lang))):
        block = text_block((x0, y), note, TEXT_H, x1 - x0, valign=VAlign.TOP)
        notes += block
        y = block[-1].position[1] - 5.0
    title = text_block((x0, radius + 14.0), message("engine.diagram.wear", lang), 3.5, x1 - x0,
                       upward=True)
    return Panel("wear", [*prims, *notes, *title])


def table_panels(study: EngineData, lang: str) -> list[Panel]:
    """The per-angle table of every cylinder (φ repeated in each part when it is split)."""
    out = []
    for c in study.scene.engine.cylinders:
        cells = table_cells(study.table, lang, c.number)
        widths = [max(14.0, 2.0 + 1.6 * max(len(r[j]) for r in cells))
                  for j in range(len(cells[0]))]
        out.append(table_panel(f"table{c.number}",
                               message("engine.diagram.table", lang, number=c.number), cells,
                               TableStyle(text_h=1.8, row_h=4.0, head_h=6.0), widths=widths))
    return out


__all__ = ["Diagram", "engine_sheets"]
