"""The gear sheet: the train's kinematic diagram with its velocity plan, the angular velocity plan,
the synthesis tables and the meshing drawing of the involute pair; and the rows shared with the
text report (conditions with their numbers, angular velocities, the pair's dimensions)."""

from __future__ import annotations

import math
from collections.abc import Sequence

from ..drafting.primitives import HAlign, Sheet
from ..i18n import message, number, significant, unit
from ..synthesis.gears.involute import TIP_MIN, Pair
from ..synthesis.gears.solve import GearSolution, PlanetaryResult
from ..synthesis.gears.train import Conditions
from .fit import TableStyle
from .fit import table_panel as fitted_table
from .layout import fitted_sheets
from .panels import Panel

TEXT_H = 2.5
TITLE_H = 3.5
ROW = 6.0
GEAR_TABLE = TableStyle(text_h=TEXT_H, row_h=ROW, pad=4.0, halign=HAlign.LEFT, title_h=TITLE_H)


def _mm(x: float, lang: str, digits: int = 3) -> str:
    return number(x * 1000, digits, lang)


def verdict(ok: bool, lang: str) -> str:
    """"holds" / "fails" in the language."""
    return message("gears.ok" if ok else "gears.fail", lang)


def condition_rows(res: PlanetaryResult, lang: str) -> list[tuple[str, str, bool]]:
    """(condition, its numbers, holds) of the chosen set."""
    c: Conditions = res.chosen
    s = res.spec
    n = (lambda x, d=3: number(x, d, lang))
    mm = unit("mm", lang)
    names = s.scheme.gear_names
    rows = [(message("gears.cond.ratio", lang),
             (f"i_{names[0]}{names[-1]}^h = {n(res.willis_i, 4)};  u_{s.input}{s.output} = "
             f"{n(c.ratio, 4)};  u* = {n(s.ratio, 4)} ± {n(s.deviation * 100, 1)} %;  "
             f"Δu = {n(c.ratio_error * 100, 2)} %"), c.ratio_ok)]
    if s.speeds is not None:          # a differential: Willis' i only
        rows = [(message("gears.cond.ratio", lang),
                 f"i_{names[0]}{names[-1]}^h = {n(res.willis_i, 6)}", True)]
    second = f"{names[-2]}–{names[-1]}"
    coax = (f"a({names[0]}–{names[1]}) = {_mm(c.a_w[0], lang)} {mm};  a({second}) = "
            f"{_mm(c.a_w[1], lang)} {mm}")
    if c.working is not None and any(abs(x) > 1e-12 for x in c.shift_sums):
        coax += (f";  a_w = {_mm(c.working, lang)} {mm}:  x_Σ = {n(c.shift_sums[0], 4)}, "
                 f"{n(c.shift_sums[1], 4)} (|x_Σ| ≤ {n(s.max_shift_sum, 2)})")
    elif c.working is None and s.centre_distance is not None:
        coax += f";  a_w = {_mm(s.centre_distance, lang)} {mm}: |x_Σ| > {n(s.max_shift_sum, 2)}"
    rows.append((message("gears.cond.coaxial", lang), coax, c.coaxial))
    k = s.planets
    if c.assembly_p is not None:
        total = c.assembly_value * (1 + k * c.assembly_p)
        text = (f"z{names[0]}·u/k = {n(c.assembly_value, 4)};  p = {c.assembly_p}:  "
                f"{n(c.assembly_value, 4)}·(1 + {k}·{c.assembly_p}) = {n(total, 3)}")
    else:
        text = f"z{names[0]}·u/k = {n(c.assembly_value, 4)};  p: —"
    rows.append((message("gears.cond.assembly", lang), text, c.assembly_p is not None))
    if k > 1:
        rows.append((message("gears.cond.neighbour", lang),
                     (f"2a_w·sin(π/{k}) = {_mm(c.neighbour_span, lang)} {mm} > d_a = "
                      f"{_mm(c.planet_tip, lang)} {mm}"), c.neighbour_ok))
    rows.append((message("gears.cond.undercut", lang), f"min z = {c.z_smallest} ≥ {s.z_min}",
                 c.undercut_ok))
    if c.ring_difference is not None:
        rows.append((message("gears.cond.ring", lang),
                     f"z_ring − z_planet = {c.ring_difference} ≥ {s.ring_difference}", c.ring_ok))
    return rows


def omega_rows(res: PlanetaryResult, lang: str,
               ordinary: dict[str, float] | None = None) -> list[tuple[str, str, str]]:
    """(link, ω, ω − ω_h) of every gear and the carrier, then the ordinary pair (ω only)."""
    p = res.plan
    assert p is not None, "a train that cannot be drawn has no velocity plan"
    rows = [(name, significant(p.omega[name], 6, lang), significant(p.relative[name], 6, lang))
            for name in p.names]
    return rows + [(name, number(w, 3, lang), "—") for name, w in (ordinary or {}).items()]


def set_text(z: tuple[int, ...]) -> str:
    """"z1 = 17, z2 = 17, …"."""
    return ", ".join(f"z{j + 1} = {v}" for j, v in enumerate(z))


def pair_rows(pair: Pair, lang: str) -> list[tuple[str, str, str]]:
    """(quantity, gear 1, gear 2) of the pair's dimensions, mm."""
    g1, g2 = pair.gears
    rows = [(message("gears.row.x", lang), number(g1.x, 4, lang), number(g2.x, 4, lang))]
    for key in ("r", "r_b", "r_w", "r_a", "r_f", "s", "s_w", "s_a"):
        rows.append((message(f"gears.row.{key}", lang), _mm(getattr(g1, key), lang),
                     _mm(getattr(g2, key), lang)))
    return rows


def pair_lines(pair: Pair, lang: str) -> list[str]:
    """The pair's sentences: shifts, α_w, centre distance, ε_α, the checks."""
    sp = pair.spec
    n = (lambda x, d=4: number(x, d, lang))
    out = [message("gears.report.pair", lang, m=_mm(sp.module, lang), z1=sp.z1, z2=sp.z2,
                   alpha=n(math.degrees(sp.alpha), 2), ha=n(sp.addendum, 2), c=n(sp.clearance, 2)),
           message(f"gears.rule.{sp.rule.value}", lang, x1=n(pair.x1), x2=n(pair.x2)),
           message("gears.report.alpha_w", lang, inv=number(pair.inv_alpha_w, 6, lang),
                   aw=n(math.degrees(pair.alpha_w))),
           message("gears.report.centres", lang, a=_mm(pair.a, lang), aw=_mm(pair.a_w, lang),
                   y=n(pair.y), dy=n(pair.dy)),
           message("gears.report.eps", lang, eps=n(pair.eps, 3), g=_mm(pair.g_active, lang))]
    for j, (g, pointed, interf) in enumerate(zip(pair.gears, pair.pointed, pair.interference)):
        out.append(message("gears.report.pointed", lang, j=j + 1, sa=_mm(g.s_a, lang),
                           lim=_mm(TIP_MIN * sp.module, lang), verdict=verdict(not pointed, lang)))
        out.append(message("gears.report.interference", lang, j=j + 1, rp=_mm(g.rho_p, lang),
                           rl=_mm(max(g.rho_l, 0.0), lang), verdict=verdict(not interf, lang)))
    out.append(message("gears.report.sliding", lang, l1=n(pair.gears[0].sliding, 3),
                       l2=n(pair.gears[1].sliding, 3)))
    return out


def table_panel(name: str, title: str, head: tuple[str, ...], rows: Sequence[tuple[str, ...]],
                notes: tuple[str, ...] = ()) -> Panel:
    """A titled table whose columns fit their texts, with notes under it."""
    return fitted_table(name, title, [head, *rows], GEAR_TABLE, notes=notes)


def gear_sheets(sol: GearSolution, size: str | None, standard: str | None, language: str | None,
                name: str) -> list[Sheet]:
    """Every panel of a gear scene on framed sheets."""
    lang = language or sol.scene.language
    title = sol.scene.title or message("gears.sheet.title", lang)
    return fitted_sheets(lambda scale: _panels(sol, lang, scale), size=size or "A1",
                         standard=standard or "iso", language=lang, name=name,
                         fields={"title": title})


def _panels(sol: GearSolution, lang: str, scale: float) -> list[Panel]:
    """The panels of a gear scene, drawings ``scale`` times their usual size."""
    from .gearcam import shifted_lines
    from .gears_drawing import mesh_panel, pair_56_panel, plan_panels

    panels: list[Panel] = []
    res = sol.planetary
    if res is not None:
        if res.plan is not None:
            panels.extend(plan_panels(res, lang, scale, sol.ordinary_plan))
            if sol.ordinary_plan is not None:
                panels.append(pair_56_panel(sol.ordinary_plan, res.spec.output, lang, scale))
        head = (message("gears.col.condition", lang), message("gears.col.numbers", lang),
                message("gears.col.verdict", lang))
        rows = [(a, b, verdict(ok, lang)) for a, b, ok in condition_rows(res, lang)]
        notes = [set_text(res.chosen.z)]
        if res.plan is None:
            notes.append(message("gearcam.no_plan", lang))
        else:
            notes.extend(shifted_lines(res, lang))
        if sol.ordinary is not None and sol.total_ratio is not None:
            o = sol.ordinary
            notes.append(message("gears.report.ordinary", lang, z5=o.z5, z6=o.z6,
                                 u=number(o.ratio, 4, lang),
                                 total=number(sol.total_ratio, 4, lang)))
        panels.append(table_panel("synthesis", message("gears.sheet.synthesis", lang), head, rows,
                                  tuple(notes)))
        others = [(", ".join(map(str, c.z)), _mm(c.size, lang, 1), number(c.ratio, 4, lang))
                  for c in res.others]
        if others:
            panels.append(table_panel("others",
                                      message("gears.sheet.others", lang, count=res.found),
                                      ("z", f"D, {unit('mm', lang)}", "u"), others))
        per_s = unit("1/s", lang)
        if res.plan is not None:
            panels.append(table_panel("omega", message("gears.report.omega", lang),
                                      (message("gears.col.link", lang), f"ω, {per_s}",
                                       f"ω − ω_h, {per_s}"),
                                      omega_rows(res, lang, sol.ordinary_omega)))
    if sol.pair is not None:
        panels.append(mesh_panel(sol.pair, lang, scale))
        panels.append(table_panel("pair", message("gears.sheet.pair", lang),
                                  (message("gears.col.quantity", lang),
                                   message("gears.col.gear", lang, j=1),
                                   message("gears.col.gear", lang, j=2)),
                                  pair_rows(sol.pair, lang),
                                  tuple(pair_lines(sol.pair, lang)[1:5])))
        if sol.contour is not None:
            from ..synthesis.gears.contour import specific_sliding
            from .gear_contour import contour_panel, sliding_panel
            panels.append(contour_panel(sol.contour, sol.pair, lang, scale))
            panels.append(sliding_panel(specific_sliding(sol.pair.spec, sol.pair.x1, sol.pair.x2),
                                        sol.pair, lang, scale))
    if sol.internal is not None:
        from .gear_internal import internal_panel
        panels.append(internal_panel(sol.internal, lang, scale))
    if sol.compound is not None and sol.scene.compound is not None:
        from ..synthesis.gears.compound import MEMBERS
        from .gear_compound import compound_rows
        spec = sol.scene.compound
        panels.append(table_panel(
            "compound", message(f"compound.sheet.{spec.kind}", lang),
            (message("compound.col.gear", lang), message("compound.col.input", lang),
             message("compound.col.held", lang), message("compound.col.output", lang), "u",
             *(f"n_{m}, {unit('rpm', lang)}" for m in MEMBERS[spec.kind])),
            compound_rows(spec, sol.compound, lang)))
    return panels
