"""A gear scene solved: planetary synthesis, the velocity plan of the train, the involute pair."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..i18n import message, number, unit

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet
    from ..synthesis.gears.solve import GearSolution
    from ..synthesis.gears.train import Conditions


def _conditions_json(c: Conditions) -> dict[str, Any]:
    return {"z": list(c.z), "ratio": c.ratio, "ratio_error": c.ratio_error, "ratio_ok": c.ratio_ok,
            "a_w_m": list(c.a_w), "coaxial": c.coaxial, "assembly_z1u_over_k": c.assembly_value,
            "assembly_p": c.assembly_p, "z_smallest": c.z_smallest, "undercut_ok": c.undercut_ok,
            "ring_difference": c.ring_difference, "ring_ok": c.ring_ok,
            "neighbour_span_m": c.neighbour_span, "planet_tip_diameter_m": c.planet_tip,
            "neighbour_ok": c.neighbour_ok, "size_m": c.size, "valid": c.valid}


@dataclass(frozen=True)
class GearStudy:
    """A solved gear scene."""

    solution: GearSolution

    def report(self, language: str | None = None) -> str:
        from ..sheet.gears import condition_rows, omega_rows, pair_lines, set_text, verdict

        sol = self.solution
        lang = language or sol.scene.language
        n = (lambda x, d=4: number(x, d, lang))
        out = [message("gears.title", lang, title=sol.scene.title), ""]
        res = sol.planetary
        if res is not None:
            s = res.spec
            out.append(message("gears.report.scheme", lang,
                               scheme=message(f"gears.scheme.{s.scheme.value}", lang),
                               fixed=s.fixed, input=s.input, output=s.output, k=s.planets))
            out.append(message("gears.report.target", lang, io=f"{s.input}{s.output}",
                               u=n(s.ratio), dev=n(s.deviation * 100, 1), lo=s.z_range[0],
                               hi=s.z_range[1], zmin=s.z_min))
            if s.given is not None:
                out.append(message("gears.report.given", lang, z=set_text(res.chosen.z),
                                   verdict=verdict(res.chosen.valid, lang)))
            else:
                out.append(message("gears.report.found", lang, count=res.found,
                                   z=set_text(res.chosen.z)))
            for name, numbers, ok in condition_rows(res, lang):
                out.append(f"  {name}: {numbers} — {verdict(ok, lang)}")
            out.append(message("gears.report.others", lang))
            for c in res.others:
                out.append(f"  {', '.join(map(str, c.z))};  D = {number(c.size * 1000, 1, lang)} "
                           f"{unit('mm', lang)};  u = {n(c.ratio)}")
            if not res.others:
                out.append("  " + message("gears.report.none_other", lang))
            out.append(message("gears.report.omega", lang))
            per_s = unit("1/s", lang)
            for link, w, rel in omega_rows(res, lang):
                out.append(f"  {link}:  ω = {w} {per_s};  ω − ω_h = {rel} {per_s}")
            for link, w5 in sol.ordinary_omega.items():
                out.append(f"  {link}:  ω = {number(w5, 3, lang)} {per_s}")
            out.append(message("gears.report.plan_ratio", lang, plan=n(res.plan.ratio, 6),
                               willis=n(res.chosen.ratio, 6)))
        o = sol.ordinary
        if o is not None:
            if sol.total_ratio is not None:
                out.append(message("gears.report.ordinary", lang, z5=o.z5, z6=o.z6, u=n(o.ratio),
                                   total=n(sol.total_ratio)))
            else:
                out.append(message("gears.report.ordinary_only", lang, z5=o.z5, z6=o.z6,
                                   u=n(o.ratio)))
        if sol.pair is not None:
            out.append("")
            out.extend(pair_lines(sol.pair, lang))
        return "\n".join(out)

    def to_json(self) -> dict[str, Any]:
        sol = self.solution
        doc: dict[str, Any] = {"kind": "gears", "title": sol.scene.title}
        res = sol.planetary
        if res is not None:
            s = res.spec
            doc["planetary"] = {
                "scheme": s.scheme.value, "fixed": s.fixed, "input": s.input, "output": s.output,
                "planets": s.planets, "target_ratio": s.ratio, "deviation": s.deviation,
                "willis_i": res.willis_i, "chosen": _conditions_json(res.chosen),
                "found": res.found, "survivors_by_condition": res.counts,
                "others": [_conditions_json(c) for c in res.others],
                "omega_rad_s": res.plan.omega, "omega_relative_rad_s": res.plan.relative,
                "ratio_from_velocity_plan": res.plan.ratio,
            }
        if sol.ordinary is not None:
            o = sol.ordinary
            doc["ordinary"] = {"z5": o.z5, "z6": o.z6, "ratio": o.ratio,
                               "total_ratio": sol.total_ratio, "omega_rad_s": sol.ordinary_omega}
        if sol.pair is not None:
            p = sol.pair
            doc["pair"] = {
                "module_m": p.spec.module, "z": [p.spec.z1, p.spec.z2], "alpha_deg":
                math.degrees(p.spec.alpha), "shift_rule": p.spec.rule.value, "x": [p.x1, p.x2],
                "inv_alpha_w": p.inv_alpha_w, "alpha_w_deg": math.degrees(p.alpha_w), "a_m": p.a,
                "a_w_m": p.a_w, "y": p.y, "delta_y": p.dy, "contact_ratio": p.eps,
                "active_line_m": p.g_active, "pointed_tip": list(p.pointed),
                "interference": list(p.interference),
                "gears": [{k: getattr(g, k) for k in ("z", "x", "r", "r_b", "r_w", "r_a", "r_f",
                                                      "s", "s_w", "s_a", "rho_l", "rho_p",
                                                      "sliding")} for g in p.gears],
            }
        return doc

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.gears import gear_sheets

        return gear_sheets(self.solution, size, standard, language, name)


def solve_gear_text(text: str, file: str) -> GearStudy:
    """Parse and solve a gear scene."""
    from ..scene.gears import parse_gears
    from ..synthesis.gears.solve import solve_gears

    return GearStudy(solve_gears(parse_gears(text, file)))
