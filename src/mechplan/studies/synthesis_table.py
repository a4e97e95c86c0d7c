"""The conditions of a synthesised linkage as a table (condition, achieved, asked or where):
Grashof, γmin and where, dead centres, K and ψ/H achieved by the analysis against the asked ones,
the defects of guidance and path generation."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ..i18n import message, number, significant

if TYPE_CHECKING:
    from .synthesis import SynthesisStudy


def condition_rows(study: SynthesisStudy, lang: str) -> list[list[str]]:
    """The heading and the rows of the conditions table."""
    d, c, rt, spec = study.design, study.design.conditions, study.check, study.spec
    deg = math.degrees

    def m(key: str, **v: str) -> str:
        return message(f"synth.table.{key}", lang, **v)

    def yes(flag: object) -> str:
        return m("yes" if flag else "no")

    rows = [[m("condition"), m("value"), m("asked")]]
    if "grashof" in c:
        rows.append([m("grashof"), yes(c["grashof"]), number(c["grashof_margin"] * 1e3, 3, lang)])
    if "crank" in c:
        rows.append([m("crank"), yes(c["crank"]), ""])
    if "gamma_min" in c and c["gamma_min"] == c["gamma_min"]:
        where = (m("gamma_at", phi=number(deg(c["gamma_min_at_phi"]), 1, lang))
                 if "gamma_min_at_phi" in c else "")
        if spec.gamma_limit is not None:
            where = (where + "; " if where else "") + m(
                "limit", gamma=number(deg(spec.gamma_limit), 1, lang))
        rows.append([m("gamma"), number(deg(c["gamma_min"]), 3, lang), where])
    if "dead_centres_phi" in c:
        rows.append([m("dead"), ", ".join(number(deg(p), 3, lang)
                                          for p in c["dead_centres_phi"]), ""])
    if d.output_kind in ("angle", "length"):
        rows.append([m("k"), number(rt.k, 6, lang), number(d.k, 6, lang)])
        if d.output_kind == "angle":
            rows.append([m("psi"), number(deg(rt.output), 4, lang),
                         number(deg(d.asked_output), 4, lang)])
        else:
            rows.append([m("stroke"), number(rt.output * 1e3, 4, lang),
                         number(d.asked_output * 1e3, 4, lang)])
    for defect in ("branch_defect", "order_defect", "circuit_defect"):
        if defect in c:
            rows.append([m(defect), yes(c[defect]), ""])
    if d.output_kind in ("guidance", "path"):
        rows.append([m("miss"), significant(rt.output * 1e3, 3, lang), ""])
    if d.output_kind == "function":
        rows.append([m("error"), significant(rt.structural_max, 4, lang), ""])
    return rows
