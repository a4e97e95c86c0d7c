"""An engine scene solved: report, JSON, CSV of the per-angle table, the sheets and its answers."""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import __version__
from ..dynamics.engine.analysis import (
    Checks,
    EngineResult,
    analyse,
    consistency_checks,
    grids,
    wear,
)
from ..dynamics.engine.balance import Balance, balance
from ..dynamics.engine.extremes import TorqueExtremes, torque_extremes
from ..dynamics.engine.model import EngineModel
from ..i18n import message, number, scientific
from ..model.engine_balance import BalanceSpec
from ..scene.engine import EngineScene, parse_engine_scene
from ..sheet.engine import columns_of, table_cells
from .answers import Keys, Own, Written, span, written_all
from .engine_balance import balance_json, report_lines
from .engine_layout import (
    articulated_lines,
    deviation_json,
    deviation_lines,
    layout_json,
    layout_lines,
)
from .engine_thermal import thermal_json, thermal_lines

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet

def solve_engine_text(text: str, file: str, *,
                      data_dir: str | Path | None = None) -> EngineStudy:
    """Parse and solve an engine scene; write its CSV if the scene's [output] asks for one
    (``data_dir``: where the data files it names are, default the scene's folder)."""
    study = EngineStudy(parse_engine_scene(text, file, data_dir=data_dir))
    if study.scene.engine.csv:
        study.write_csv(study.scene.engine.csv)
    return study


@dataclass
class EngineStudy:
    """An engine's dynamic calculation over its cycle."""

    scene: EngineScene
    model: EngineModel = field(init=False)

    def __post_init__(self) -> None:
        s = self.scene
        self.model = EngineModel.build(s.engine, s.path, s.linkage)

    @cached_property
    def dense(self) -> EngineResult:
        """All quantities on the dense grid."""
        return analyse(self.model, grids(self.model)[0])

    @cached_property
    def table(self) -> EngineResult:
        """All quantities at the table's angles."""
        return analyse(self.model, grids(self.model)[1])

    @cached_property
    def checks(self) -> Checks:
        """Consistency checks."""
        return consistency_checks(self.model, grids(self.model)[0])

    @cached_property
    def balance(self) -> Balance:
        """Free forces and moments, counterweights, balance shafts (the scene's [balance] or the
        defaults)."""
        d = self.dense
        return balance(self.model, self.scene.balance or BalanceSpec(), d.phi, d.pins)

    @cached_property
    def extremes(self) -> TorqueExtremes:
        """ΣM's largest and smallest values found between the grid points."""
        return torque_extremes(self.model, self.dense)

    @cached_property
    def wear(self) -> tuple[np.ndarray, np.ndarray]:
        """Wear diagram of pin 1 at the table's angles (the last angle repeats the first)."""
        t = self.table.pins[1]
        return wear(type(t)(t.T[:-1], t.Z[:-1], t.K_r))

    # -- text ---------------------------------------------------------------------------------
    def report(self, language: str | None = None) -> str:
        lang = language or self.scene.engine.language
        spec, m, d, ch = self.scene.engine, self.model, self.dense, self.checks

        def n(x: float, k: int = 3) -> str:
            return number(x, k, lang)

        lines = [message("engine.report.title", lang, title=spec.title), ""]
        if self.scene.cycle is not None:
            lines += [*thermal_lines(self.scene.cycle, spec.V_h, lang, spec.bore), ""]
        lines.append(message("engine.report.geometry", lang, strokes=spec.strokes,
                             cylinders=len(spec.cylinders), n=n(spec.speed * 30 / math.pi, 0),
                             D=n(spec.bore * 1e3, 1), R=n(spec.R * 1e3, 2), L=n(spec.L * 1e3, 2),
                             lam=n(spec.lam, 4)))
        if m.diagram.V_c_given:
            lines.append(message("engine.report.volumes", lang, F_p=n(spec.F_p * 1e4, 3),
                                 V_h=n(spec.V_h * 1e6, 2), V_c=n(m.diagram.V_c * 1e6, 2),
                                 p0=n(spec.p0 * 1e-3, 1)))
        else:
            lines.append(message("layouts.report.volumes_no_eps", lang, F_p=n(spec.F_p * 1e4, 3),
                                 V_h=n(spec.V_h * 1e6, 2), p0=n(spec.p0 * 1e-3, 1)))
        lines.append(message("engine.report.layout." + spec.layout.value, lang))
        lines += layout_lines(m, lang)
        lines.append(message("engine.report.firing", lang,
                             order="–".join(str(k) for k in spec.firing_order)))
        for c in spec.cylinders:
            lines.append(message("engine.report.cylinder", lang, number=c.number,
                                 throw=n(math.degrees(c.throw), 1), bank=n(math.degrees(c.bank), 1),
                                 phase=n(math.degrees(m.phases[c.number]), 1),
                                 m_j=n(m.m_j[c.number], 4), m_r=n(m.m_rot[c.number], 4)))
        lines += articulated_lines(m, lang)
        lines += ["", message("engine.report.indicator", lang, W=n(ch.work_diagram, 2),
                              p_i=n(ch.work_diagram / spec.V_h * 1e-6, 4),
                              p_max=n(ch.p_max * 1e-6, 3))]
        lines += ["", message("engine.report.table", lang,
                              step=n(math.degrees(spec.table_step), 0))]
        lines += self._table_text(lang)
        ex = self.extremes
        lines += ["", message("engine.report.torque", lang, mean=n(ch.work_torque / spec.cycle, 3),
                              max=n(ex.M_max, 2), min=n(ex.M_min, 2),
                              mu=n(ex.non_uniformity(ch.work_torque / spec.cycle), 3))]
        lines.append(message("layouts.report.torque_extremes", lang,
                             phi_max=n(math.degrees(ex.phi_max), 3),
                             phi_min=n(math.degrees(ex.phi_min), 3),
                             grid_max=n(float(d.M_total.max()), 2),
                             grid_min=n(float(d.M_total.min()), 2)))
        for pin, q in d.pins.items():
            Q = q.Q
            lines.append(message("engine.report.pin", lang, pin=pin, K_r=n(q.K_r * 1e-3, 4),
                                 mean=n(float(np.trapezoid(Q, d.phi) / spec.cycle) * 1e-3, 4),
                                 max=n(float(Q.max()) * 1e-3, 4), min=n(float(Q.min()) * 1e-3, 4)))
        for j, J in enumerate(d.journals):
            mag = np.hypot(J[:, 0], J[:, 1])
            lines.append(message("engine.report.journal", lang, journal=j + 1,
                                 mean=n(float(np.trapezoid(mag, d.phi) / spec.cycle) * 1e-3, 4),
                                 max=n(float(mag.max()) * 1e-3, 4)))
        rays, sums = self.wear
        lines.append(message("engine.report.wear", lang,
                             angle=n(math.degrees(float(rays[np.argmin(sums)])), 0)))
        lines += ["", message("engine.report.checks", lang)]
        lines.append(message("engine.check.work", lang, torque=n(ch.work_torque, 6),
                             work=n(ch.work_expected, 6), error=scientific(ch.work_error, 2, lang)))
        lines.append(message("engine.check.inertia", lang,
                             mean=scientific(ch.inertia_mean, 2, lang), peak=n(ch.inertia_peak, 2)))
        lines.append(message("engine.check.brix", lang, dp=n(ch.brix_dp_max * 1e-3, 2),
                             percent=n(ch.brix_dp_max / ch.p_max * 100, 3)))
        lines.append(message("engine.check.series", lang, da=n(ch.da_max, 2),
                             percent=n(ch.da_max / ch.a_max * 100, 3), dPj=n(ch.dPj_max, 2)))
        if ch.two_mass_dM_max is not None:
            lines.append(message("engine.check.two_mass", lang, dM=n(ch.two_mass_dM_max, 4)))
        else:
            lines.append(message("engine.check.two_mass_exact", lang))
        if ch.pair_torque_error is not None:
            lines.append(message("engine.check.pair", lang,
                                 error=scientific(ch.pair_torque_error, 2, lang)))
        if self.scene.balance is not None:
            lines += report_lines(self.balance, d.phi, lang)
            lines += deviation_lines(m, self.balance, lang)
        return "\n".join(lines) + "\n"

    def _table_text(self, lang: str) -> list[str]:
        out = []
        for c in self.scene.engine.cylinders:
            if len(self.scene.engine.cylinders) > 1:
                out.append(message("engine.report.table_cylinder", lang, number=c.number))
            rows = table_cells(self.table, lang, c.number)
            widths = [max(len(r[j]) for r in rows) for j in range(len(rows[0]))]
            out += ["  ".join(s.rjust(w) for s, w in zip(r, widths)) for r in rows]
        return out

    # -- data ---------------------------------------------------------------------------------
    def to_json(self) -> dict[str, Any]:
        spec, m, t, ch = self.scene.engine, self.model, self.table, self.checks
        d = self.dense
        angles = []
        for k, phi in enumerate(t.phi):
            angles.append({
                "phi_deg": round(math.degrees(float(phi)), 9),
                "cylinders": {str(c): _clean(f.json_row(k)) for c, f in t.cylinders.items()},
                "M_total": float(t.M_total[k]),
                "pins": {str(p): {"T": float(q.T[k]), "Z": float(q.Z[k]), "Q_T": float(q.Q_T[k]),
                                  "Q_Z": float(q.Q_Z[k]), "Q": float(q.Q[k])}
                         for p, q in t.pins.items()},
                "journals": [[float(J[k, 0]), float(J[k, 1])] for J in t.journals]})
        rays, sums = self.wear
        extra = ({"balance": balance_json(self.balance, d.phi)}
                 if self.scene.balance is not None else {})
        if self.scene.balance is not None and m.articulated:
            extra["balance"]["ideal"] = deviation_json(m, self.balance)
        if self.scene.cycle is not None:
            extra["thermal"] = thermal_json(self.scene.cycle, spec.V_h, spec.bore)
        return {
            "mechplan": __version__, "kind": "engine", "title": spec.title,
            "engine": {"strokes": spec.strokes, "omega": spec.speed, "bore": spec.bore, "R": spec.R,
                       "L": spec.L, "lambda": spec.lam, "F_p": spec.F_p, "V_h": spec.V_h,
                       "V_c": m.diagram.V_c if m.diagram.V_c_given else None, "p0": spec.p0,
                       "layout": spec.layout.value,
                       "firing_order": list(spec.firing_order)},
            "cylinders": [{"number": c.number, "throw_deg": math.degrees(c.throw),
                           "bank_deg": math.degrees(c.bank),
                           "phase_deg": math.degrees(m.phases[c.number]),
                           "m_j": m.m_j[c.number], "m_r": m.m_rot[c.number]}
                          for c in spec.cylinders],
            "angles": angles,
            "torque": {"mean": ch.work_torque / spec.cycle, "max": self.extremes.M_max,
                       "min": self.extremes.M_min,
                       "phi_max_deg": math.degrees(self.extremes.phi_max),
                       "phi_min_deg": math.degrees(self.extremes.phi_min),
                       "grid_max": float(d.M_total.max()), "grid_min": float(d.M_total.min()),
                       "non_uniformity": self.extremes.non_uniformity(ch.work_torque
                                                                      / spec.cycle)},
            **layout_json(m),
            "pins": {str(p): {"K_r": q.K_r, "Q_max": float(q.Q.max()), "Q_min": float(q.Q.min()),
                              "Q_mean": float(np.trapezoid(q.Q, d.phi) / spec.cycle)}
                     for p, q in d.pins.items()},
            "wear": {"ray_deg": [math.degrees(float(r)) for r in rays],
                     "load": [float(s) for s in sums]},
            "checks": {"work_diagram": ch.work_diagram, "work_expected": ch.work_expected,
                       "work_torque": ch.work_torque, "work_error": ch.work_error,
                       "inertia_torque_mean": ch.inertia_mean, "brix_dp_max": ch.brix_dp_max,
                       "p_max": ch.p_max, "series_da_max": ch.da_max, "a_max": ch.a_max,
                       "series_dPj_max": ch.dPj_max, "two_mass_dM_max": ch.two_mass_dM_max,
                       "pair_torque_error": ch.pair_torque_error}, **extra}

    def to_csv(self, dense: bool = False) -> str:
        """The per-angle table as CSV (comma-separated, decimal point, units in the headings)."""
        r = self.dense if dense else self.table
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        head = ["phi_deg"]
        for c, f in r.cylinders.items():
            head += [f"{name}_{c}" for _, name, _ in columns_of(f)]
        head += ["M_total_Nm"]
        for p in r.pins:
            head += [f"Q_T_kN_pin{p}", f"Q_Z_kN_pin{p}", f"Q_kN_pin{p}"]
        w.writerow(head)
        for k, phi in enumerate(r.phi):
            row = [f"{math.degrees(float(phi)):.6g}"]
            for f in r.cylinders.values():
                row += [_g(float(getattr(f, a)[k]) * s) for a, _, s in columns_of(f)]
            row.append(_g(float(r.M_total[k])))
            for q in r.pins.values():
                row += [_g(float(q.Q_T[k]) * 1e-3), _g(float(q.Q_Z[k]) * 1e-3),
                        _g(float(q.Q[k]) * 1e-3)]
            w.writerow(row)
        return buf.getvalue()

    def write_csv(self, path: str | Path, dense: bool = False) -> None:
        """Write :meth:`to_csv` to a file (atomically: never a half-written file)."""
        from ..render.atomic import write_atomic

        write_atomic(path, self.to_csv(dense).encode("utf-8"))

    def answers(self) -> Keys:
        """The exact answers: the first cylinder's per-angle table, the total torque."""
        doc = self.to_json()
        k = Keys("engine", study=doc, formulas=_own_engine)
        first = str(doc["cylinders"][0]["number"])
        for name in _ANSWER_COLUMNS:
            k.columns[name] = {float(a["phi_deg"]): float(a["cylinders"][first][name])
                               for a in doc["angles"]}
        k.columns["M_total"] = {float(a["phi_deg"]): float(a["M_total"]) for a in doc["angles"]}
        for name, col in k.columns.items():
            k.spans[name] = span(col)
        k.scalars = {"M_mean": doc["torque"]["mean"], "M_max": doc["torque"]["max"],
                     "M_min": doc["torque"]["min"]}
        return k

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.engine import engine_sheets

        return engine_sheets(self, size or self.scene.drawing.sheet,
                             standard or self.scene.drawing.standard,
                             language or self.scene.engine.language, name)


def _g(v: float) -> str:
    return f"{v:.9g}" if math.isfinite(v) else ""


def _clean(d: dict[str, float]) -> dict[str, float | None]:
    return {k: (v if math.isfinite(v) else None) for k, v in d.items()}


# -- answers ------------------------------------------------------------------------------------
_ANSWER_COLUMNS = ("p", "Pk", "Pj", "P", "N", "S", "T", "Z", "M", "beta")


def _own_engine(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    """P_г, P, M and (central slider-crank) N, S, T, Z from the student's own values at φ."""
    if phi is None:
        return None
    e = k.study["engine"]
    pressure = written_all(w, phi, "p")
    if name == "Pk" and pressure:
        return (pressure[0] - e["p0"]) * e["F_p"], "P_г = (p − p₀)·F_п", ("p",)
    parts = written_all(w, phi, "Pk", "Pj")
    if name == "P" and parts:
        return parts[0] + parts[1], "P = P_г + P_j", ("Pk", "Pj")
    tangential = written_all(w, phi, "T")
    if name == "M" and tangential:
        return tangential[0] * e["R"], "M = T·R", ("T",)
    beta = w.get(("beta", phi))
    if beta is None:
        beta = k.exact("beta", phi)
    if beta is None or len(k.study["cylinders"]) > 1:
        return None                 # the formulas below are those of a central slider-crank
    a = math.radians(phi)
    force = written_all(w, phi, "P")
    rule = {"N": (math.tan(beta), "N = P·tg β"), "S": (1 / math.cos(beta), "S = P/cos β"),
            "T": (math.sin(a + beta) / math.cos(beta), "T = P·sin(φ+β)/cos β"),
            "Z": (math.cos(a + beta) / math.cos(beta), "Z = P·cos(φ+β)/cos β")}.get(name)
    if rule and force:
        return force[0] * rule[0], rule[1], ("P",)
    return None
