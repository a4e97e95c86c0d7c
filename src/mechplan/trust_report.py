"""Error estimates and flags of a solution, as the report, the warnings and the JSON present
them."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .construct.trust import Flag
from .i18n import message, scientific, trimmed
from .model.mechanism import GROUND
from .solve import Solution

WARNING_LIMIT = 20
KNOWN_QUANTITIES = ("r", "v", "a", "angle", "omega", "epsilon")


def _sci(value: float, language: str) -> str:
    if not math.isfinite(value):
        return message("estimate.unbounded", language)
    return scientific(value, 2, language)


def _quantity(quantity: str, language: str) -> str:
    key = quantity if quantity in KNOWN_QUANTITIES else "other"
    return message(f"estimate.q.{key}", language)


def _phi(phi_deg: float, language: str) -> str:
    return trimmed(phi_deg, 6, language)


def flag_line(f: Flag, tolerance: float, language: str) -> str:
    """One warning line for a flagged result."""
    return message("estimate.flag", language, phi=_phi(f.phi_deg, language),
                   quantity=_quantity(f.quantity, language), subject=f.subject or f.label,
                   group=f.group or "I", estimate=_sci(f.estimate, language),
                   tolerance=_sci(tolerance, language))


def warning_lines(sol: Solution, language: str | None = None,
                  limit: int = WARNING_LIMIT) -> list[str]:
    """Warnings for failed positions and flagged results (at most ``limit`` of each, then a
    count)."""
    lang = language or sol.scene.language
    out = [message("estimate.failure", lang, phi=_phi(f.phi_deg, lang), reason=f.reason)
           for f in sol.failures[:limit]]
    if len(sol.failures) > limit:
        out.append(message("estimate.more", lang, count=len(sol.failures) - limit))
    out += [flag_line(f, sol.tolerance, lang) for f in sol.flags[:limit]]
    if len(sol.flags) > limit:
        out.append(message("estimate.more", lang, count=len(sol.flags) - limit))
    return out


def summary_lines(sol: Solution, language: str | None = None) -> list[str]:
    """The report's section on error estimates."""
    lang = language or sol.scene.language
    title = message("estimate.title", lang)
    out = ["", f"## {title}"]
    worst, where = -1.0, None
    failed = {f.k for f in sol.failures}
    for sid in sol.targets:
        if sid not in sol.estimate:
            continue
        rel = sol.estimate.relative(sid).copy()
        if failed:
            rel[list(failed)] = 0.0
        k = int(np.argmax(rel))
        if rel[k] > worst:
            worst, where = float(rel[k]), (sid, k)
    if where is not None:
        sid, k = where
        q = sol.construction.quantity_of(sid) or ("", sol.construction[sid].label)
        out.append(message("estimate.worst", lang, estimate=_sci(worst, lang),
                           quantity=_quantity(q[0], lang), subject=q[1],
                           phi=_phi(math.degrees(float(sol.phi[k])), lang),
                           tolerance=_sci(sol.tolerance, lang)))
    if sol.flags:
        out.append(message("estimate.flagged_count", lang, count=len(sol.flags),
                           positions=len({f.k for f in sol.flags})))
    else:
        out.append(message("estimate.none_flagged", lang))
    if sol.failures:
        out.append(message("estimate.failed_count", lang, count=len(sol.failures)))
    return out


def _json_number(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def position_json(sol: Solution, k: int) -> dict[str, Any]:
    """Relative error estimates of one position's results (null: no bound)."""
    c, est = sol.construction, sol.estimate
    points: dict[str, dict[str, float | None]] = {}
    links: dict[str, dict[str, float | None]] = {}
    for sid in sol.targets:
        if sid not in est:
            continue
        q = c.quantity_of(sid)
        if q is None:
            continue
        quantity, subject = q
        value = _json_number(float(est.relative(sid)[k]))
        if quantity in ("r", "v", "a"):
            points.setdefault(subject, {})[quantity] = value
        elif quantity in ("angle", "omega", "epsilon") and subject != GROUND:
            links.setdefault(subject, {})[quantity] = value
        else:
            links.setdefault("forces", {})[f"{quantity}_{subject}"] = value
    return {"points": points, "links": links}


def trust_json(sol: Solution) -> dict[str, Any]:
    """Tolerance, flagged results and failed positions of the whole solution."""
    return {
        "tolerance": sol.tolerance,
        "flags": [{"position": f.k, "phi_deg": f.phi_deg, "quantity": f.quantity,
                   "subject": f.subject, "group": f.group, "estimate": _json_number(f.estimate)}
                  for f in sol.flags],
        "failures": [{"position": f.k, "phi_deg": f.phi_deg, "reason": f.reason}
                     for f in sol.failures],
    }
