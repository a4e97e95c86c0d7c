"""A gear scene solved: planetary synthesis, the velocity plan of the train, the involute pair,
its answers."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..i18n import message, number, unit
from .answers import Keys, Own, Written

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet
    from ..synthesis.gears.contour import Contour
    from ..synthesis.gears.contour_internal import InternalPair
    from ..synthesis.gears.involute import Pair
    from ..synthesis.gears.solve import GearSolution
    from ..synthesis.gears.train import Conditions


def _conditions_json(c: Conditions) -> dict[str, Any]:
    finite = math.isfinite(c.ratio)          # a differential asks for no ratio
    return {"z": list(c.z), "ratio": c.ratio if finite else None,
            "ratio_error": c.ratio_error if finite else None, "ratio_ok": c.ratio_ok,
            "a_w_m": list(c.a_w), "coaxial": c.coaxial, "assembly_z1u_over_k": c.assembly_value,
            "assembly_p": c.assembly_p, "z_smallest": c.z_smallest, "undercut_ok": c.undercut_ok,
            "ring_difference": c.ring_difference, "ring_ok": c.ring_ok,
            "neighbour_span_m": c.neighbour_span if math.isfinite(c.neighbour_span) else None,
            "planet_tip_diameter_m": c.planet_tip,
            "neighbour_ok": c.neighbour_ok, "size_m": c.size, "valid": c.valid,
            "working_centre_distance_m": c.working,
            "shift_sums": [x if math.isfinite(x) else None for x in c.shift_sums]}


@dataclass(frozen=True)
class GearStudy:
    """A solved gear scene."""

    solution: GearSolution

    def report(self, language: str | None = None) -> str:
        from ..sheet.gearcam import (
            differential_head,
            shifted_lines,
            superposition_lines,
            torque_lines,
        )
        from ..sheet.gears import condition_rows, omega_rows, pair_lines, set_text, verdict

        sol = self.solution
        lang = language or sol.scene.language
        n = (lambda x, d=4: number(x, d, lang))
        out = [message("gears.title", lang, title=sol.scene.title), ""]
        res = sol.planetary
        if res is not None:
            s = res.spec
            if s.speeds is not None:
                out.extend(differential_head(res, lang))
            else:
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
            if res.plan is None:
                out.append(message("gearcam.no_plan", lang))
            else:
                out.extend(shifted_lines(res, lang))
                out.append(message("gears.report.omega", lang))
                per_s = unit("1/s", lang)
                for link, w, rel in omega_rows(res, lang):
                    out.append(f"  {link}:  ω = {w} {per_s};  ω − ω_h = {rel} {per_s}")
                for link, w5 in sol.ordinary_omega.items():
                    out.append(f"  {link}:  ω = {number(w5, 3, lang)} {per_s}")
                if s.speeds is None:
                    out.append(message("gears.report.plan_ratio", lang,
                                       plan=n(res.plan.ratio, 6), willis=n(res.chosen.ratio, 6)))
                else:
                    out.extend(superposition_lines(res, lang))
                out.extend(torque_lines(res, lang))
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
            if sol.contour is not None:
                out.extend(contour_lines(sol.contour, sol.pair, lang))
        if sol.internal is not None:
            from ..sheet.gear_internal import internal_lines

            out.append("")
            out.extend(internal_lines(sol.internal, lang))
        if sol.compound is not None and sol.scene.compound is not None:
            from ..sheet.gear_compound import compound_lines

            out.append("")
            out.extend(compound_lines(sol.scene.compound, sol.compound, lang))
        return "\n".join(out)

    def warnings(self, language: str | None = None) -> list[str]:
        """A warning for each failed check of the pair and of a given planetary set (the
        command then exits with code 3, as for flagged results)."""
        from ..sheet.gears import condition_rows, pair_lines, verdict

        sol = self.solution
        lang = language or sol.scene.language
        failed: list[str] = []
        res = sol.planetary
        if res is not None and res.spec.given is not None and not res.chosen.valid:
            failed += [f"{name}: {numbers} — {verdict(ok, lang)}"
                       for name, numbers, ok in condition_rows(res, lang) if not ok]
        flags = []
        if res is not None and res.plan is None:
            flags.append(message("gearcam.no_plan", lang))
        if sol.pair is not None:
            p = sol.pair
            lines = pair_lines(p, lang)[-5:-1]       # pointed tip and interference, per gear
            bad = [flag for pair in zip(p.pointed, p.interference) for flag in pair]
            failed += [line for line, fails in zip(lines, bad, strict=True) if fails]
        if sol.internal is not None and not sol.internal.admissible:
            from ..sheet.gear_internal import internal_lines
            failed += [line.strip() for line in internal_lines(sol.internal, lang)[4:]
                       if line.strip().endswith(message("internal.fails", lang))]
        return flags + [message("gears.warning.failed", lang, check=c) for c in failed]

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
                "omega_rad_s": res.plan.omega if res.plan else None,
                "omega_relative_rad_s": res.plan.relative if res.plan else None,
                "ratio_from_velocity_plan": (res.plan.ratio if res.plan
                                             and math.isfinite(res.plan.ratio) else None),
                "working_centre_distance_m": res.chosen.working,
                }
            from ..synthesis.gears.forces import train_forces
            if res.partials is not None and s.speeds is not None:
                doc["planetary"]["differential"] = {
                    "speeds_rad_s": dict(s.speeds),
                    "omega_each_input_alone_rad_s": [q.omega for q in res.partials]}
            forces = train_forces(res)
            if forces is not None:
                doc["planetary"]["torques"] = forces.to_json()
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
            if sol.contour is not None:
                doc["pair"]["contour"] = contour_json(sol.contour, p)
        if sol.internal is not None:
            doc["internal_pair"] = internal_json(sol.internal)
        if sol.compound is not None and sol.scene.compound is not None:
            from ..sheet.gear_compound import compound_json

            doc["compound"] = compound_json(sol.scene.compound, sol.compound)
        return doc

    def answers(self) -> Keys:
        """The exact answers: the chosen tooth numbers and their train, the involute pair."""
        sol = self.solution
        k = Keys("gears", study=sol, formulas=_own_gears)
        if sol.planetary is not None:
            c = sol.planetary.chosen
            k.scalars |= {f"z{i}": float(z) for i, z in enumerate(c.z, start=1)}
            k.scalars |= {"k": float(sol.planetary.spec.planets), "u": c.ratio, "a_w": c.a_w[0],
                          "assembly": c.assembly_value}
            if sol.planetary.spec.speeds is not None:     # a differential asks for no ratio
                del k.scalars["u"]
            if c.working is not None:
                k.scalars["a_w"] = c.working
        if sol.pair is not None:
            p = sol.pair
            spec = p.spec
            k.scalars |= {"pair.z1": float(p.gears[0].z), "pair.z2": float(p.gears[1].z),
                          "pair.m": spec.module, "pair.x1": p.x1, "pair.x2": p.x2,
                          "pair.a_w": p.a_w, "pair.alpha_w": p.alpha_w, "pair.eps_alpha": p.eps,
                          "pair.r_b1": p.gears[0].r_b,
                          "pair.r_b2": p.gears[1].r_b, "pair.y": p.y}
        return k

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.gears import gear_sheets

        return gear_sheets(self.solution, size, standard, language, name)


def contour_json(c: Contour, p: Pair) -> dict[str, Any]:
    """The contour's limits, lines (x1, x2 points, null between branches), the chosen shifts and
    the specific sliding along N1N2 (null for ±∞)."""
    from ..synthesis.gears.contour import specific_sliding

    def pts(a: Any) -> list[list[float | None]]:
        return [[float(x) if math.isfinite(x) else None for x in row] for row in a.tolist()]

    def vals(a: Any) -> list[float | None]:
        return [float(x) if math.isfinite(x) else None for x in a.tolist()]
    s = specific_sliding(p.spec, p.x1, p.x2)
    return {"tip_land_modules": c.spec.tip_land, "min_contact_ratio": c.spec.eps_min,
            "lines": {k: pts(v) for k, v in c.lines.items()}, "balanced_sliding": pts(c.balanced),
            "recommended": list(c.recommended), "rule": c.rule, "contact_ratio": c.eps,
            "specific_sliding": {"u_from_N1_m": vals(s.u), "eta1": vals(s.eta1),
                                 "eta2": vals(s.eta2), "B1_m": s.b1, "B2_m": s.b2, "g_m": s.g}}


def internal_json(ip: InternalPair) -> dict[str, Any]:
    """An internal pair: its shifts, quantities, each limit's value and the contour's lines."""
    q = ip.arrays

    def pts(a: Any) -> list[list[float | None]]:
        return [[float(x) if math.isfinite(x) else None for x in row] for row in a.tolist()]

    def f(v: Any) -> float | None:
        x = float(v)
        return x if math.isfinite(x) else None
    c = ip.contour
    return {"module_m": ip.spec.module, "z": [ip.spec.z1, ip.spec.z2], "x": [ip.x1, ip.x2],
            "shift_rule": ip.spec.rule.value, "alpha_w_deg": math.degrees(float(q.alpha_w)),
            "a_w_m": f(q.a_w), "contact_ratio": f(q.eps), "tip_diameters_m":
            [f(2 * q.r_a[0]), f(2 * q.r_a[1])], "tip_lands_m": [f(q.s_a[0]), f(q.s_a[1])],
            "limits": {k: (v if math.isfinite(v) else None) for k, v in ip.limits.items()},
            "admissible": ip.admissible,
            "contour": {"tip_land_modules": c.spec.tip_land, "min_contact_ratio": c.spec.eps_min,
                        "lines": {k: pts(v) for k, v in c.lines.items()},
                        "balanced_sliding": pts(c.balanced), "recommended": list(c.recommended),
                        "rule": c.rule, "contact_ratio": c.eps}}


def contour_lines(c: Contour, p: Pair, lang: str) -> list[str]:
    """The report's lines on the blocking contour."""
    from ..sheet.gear_contour import chosen_line

    return [message("contour.report.limits", lang, k=number(c.spec.tip_land, 2, lang),
                    eps=number(c.spec.eps_min, 2, lang)), chosen_line(c, lang)]


def solve_gear_text(text: str, file: str) -> GearStudy:
    """Parse and solve a gear scene."""
    from ..scene.gears import parse_gears
    from ..synthesis.gears.solve import solve_gears

    return GearStudy(solve_gears(parse_gears(text, file)))


# -- answers ------------------------------------------------------------------------------------
def _own_gears(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    """u (Willis), a_w and the assembly condition from the student's own tooth numbers."""
    from ..synthesis.gears import train

    sol = k.study
    if name.startswith("pair."):
        return _own_pair(sol, name.removeprefix("pair."), w)
    if sol.planetary is None:
        return None
    spec = sol.planetary.spec
    n = len(sol.planetary.chosen.z)
    zs = [w.get((f"z{i}", None)) for i in range(1, n + 1)]
    if any(z is None for z in zs):
        return None
    z = np.array([round(v) for v in zs if v is not None])
    used = tuple(f"z{i}" for i in range(1, n + 1))
    if name == "u":
        if spec.speeds is not None:
            return None
        i = train.willis_i(spec.scheme, z)
        u = float(train.ratio_from_i(i, spec.scheme, spec.fixed, spec.input, spec.output))
        sign = "−" if train.willis_sign(spec.scheme) < 0 else ""
        i_text = "z3/z1" if len(z) == 3 else "z2·z4/(z1·z3)"
        return u, f"Willis: i^h = {sign}{i_text}", used
    if name == "a_w":
        if train.shifted(spec):             # both meshes at the working centre distance
            a_w = train.working_distance(spec, tuple(int(v) for v in z))
            if a_w is not None:
                return a_w, "a_w (shifted gears)", used
        return float(train.centre_distance(spec, z)[0]), "a_w = m(z₁ ± z₂)/2", used
    if name == "assembly":
        a, b = train.assembly_terms(spec, z)
        planets = w.get(("k", None)) or spec.planets
        return float(a) / float(b) / planets, "z₁·u₁ₕ/k", used
    return None


def _own_pair(sol: Any, name: str, w: Written) -> Own | None:
    """r_b, α_w and a_w of the involute pair from the student's own m, z and x."""
    from ..synthesis.gears.involute import inv, inv_inverse

    spec = sol.pair.spec
    m = w.get(("pair.m", None)) or spec.module
    alpha = spec.alpha
    z1, z2 = w.get(("pair.z1", None)), w.get(("pair.z2", None))
    if z1 is None or z2 is None:
        z1, z2 = float(sol.pair.gears[0].z), float(sol.pair.gears[1].z)
    if name in ("r_b1", "r_b2"):
        z = z1 if name == "r_b1" else z2
        return m * z * math.cos(alpha) / 2, "r_b = m·z·cos α/2", ("pair.m",)
    x1, x2 = w.get(("pair.x1", None)), w.get(("pair.x2", None))
    if x1 is None or x2 is None:
        return None
    inv_w = float(inv(alpha)) + 2 * (x1 + x2) * math.tan(alpha) / (z1 + z2)
    alpha_w = inv_inverse(inv_w)
    if name == "alpha_w":
        return alpha_w, "inv α_w = inv α + 2(x₁+x₂)tg α/(z₁+z₂)", ("pair.x1", "pair.x2")
    if name == "a_w":
        return (m * (z1 + z2) / 2 * math.cos(alpha) / math.cos(alpha_w),
                "a_w = m(z₁+z₂)/2·cos α/cos α_w", ("pair.x1", "pair.x2"))
    return None
