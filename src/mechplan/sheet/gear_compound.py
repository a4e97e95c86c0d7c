"""A Simpson or Ravigneaux set in the report and on the gear sheet: each gear's members (input,
held, locked, output), its exact ratio and every member's speed."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from ..i18n import message, number
from ..model.gears import CompoundSpec
from ..synthesis.gears.compound import MEMBERS, Shift


def fraction_text(u: Fraction, lang: str) -> str:
    """"−33/20 (≈ −1.6500)" or "1"."""
    sign = "−" if u < 0 else ""
    if u.denominator == 1:
        return f"{sign}{abs(u.numerator)}"
    return f"{sign}{abs(u.numerator)}/{u.denominator} (≈ {number(float(u), 4, lang)})"


def compound_lines(spec: CompoundSpec, shifts: list[Shift], lang: str) -> list[str]:
    """The set's teeth, then one sentence per gear."""
    teeth = ", ".join(f"z_{k} = {v}" for k, v in spec.teeth.items())
    out = [message(f"compound.report.{spec.kind}", lang, teeth=teeth)]
    rpm = spec.input_speed * 30 / math.pi
    for s in shifts:
        fixed = ", ".join(s.held) or "—"
        locked = " = ".join(s.locked) or "—"
        speeds = "; ".join(f"{m} {number(float(w) * rpm, 1, lang)}" for m, w in s.speeds.items())
        out.append(message("compound.report.gear", lang, name=s.name, input=s.input, held=fixed,
                           locked=locked, output=s.output, u=fraction_text(s.ratio, lang),
                           speeds=speeds))
    return out


def compound_rows(spec: CompoundSpec, shifts: list[Shift], lang: str) -> list[tuple[str, ...]]:
    """Rows of the gear table: name, input, held / locked, output, u, each member's n (rpm)."""
    rpm = spec.input_speed * 30 / math.pi
    return [(s.name, s.input, ", ".join(s.held) + (" " + "=".join(s.locked) if s.locked else ""),
             s.output, fraction_text(s.ratio, lang),
             *(number(float(s.speeds[m]) * rpm, 1, lang) for m in MEMBERS[spec.kind]))
            for s in shifts]


def compound_json(spec: CompoundSpec, shifts: list[Shift]) -> dict[str, Any]:
    """Each gear's ratio (an exact "p/q" and its value) and members' speeds (rad/s)."""
    return {"type": spec.kind, "teeth": dict(spec.teeth), "input_speed_rad_s": spec.input_speed,
            "gears": [{"name": s.name, "input": s.input, "held": list(s.held),
                       "locked": list(s.locked), "output": s.output, "ratio": str(s.ratio),
                       "ratio_value": float(s.ratio),
                       "omega_rad_s": {m: float(w) * spec.input_speed
                                       for m, w in s.speeds.items()}} for s in shifts]}
