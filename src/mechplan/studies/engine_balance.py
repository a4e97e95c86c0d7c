"""The balancing part of an engine study: report lines, JSON, table cells (sheet and text)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..dynamics.engine.balance import Balance, extremes, turning
from ..i18n import message, number
from ..sheet.engine_balance import counterweight_cells, journal_cells, orders_cells


def report_lines(b: Balance, phi: np.ndarray, lang: str) -> list[str]:
    """The balancing section of the text report."""
    def n(x: float, k: int = 2) -> str:
        return number(x, k, lang)

    def table(rows: list[list[str]]) -> list[str]:
        w = [max(len(r[j]) for r in rows) for j in range(len(rows[0]))]
        return ["  ".join(s.rjust(x) for s, x in zip(r, w)) for r in rows]

    out = ["", message("balance.report.title", lang)]
    out.append(message("balance.report.positions" if b.spacing_given else
                       "balance.report.unit_spacing", lang))
    out.append(message("balance.report.orders", lang))
    out += table(orders_cells(b, lang))
    rf, rm = extremes(b.rotating_F)[0], extremes(b.rotating_M)[0]
    unit = message("balance.unit.Nm" if b.spacing_given else "balance.unit.Na", lang)
    out.append(message("balance.report.rotating", lang, F=n(rf), M=n(rm), unit=unit))
    out.append(message("balance.report.first_before", lang, F=n(extremes(b.before_F)[0]),
                       M=n(extremes(b.before_M)[0]), unit=unit))
    out.append(message("balance.report.first_after", lang, share=n(b.counterweights.share, 2),
                       F=n(extremes(b.after_F)[0]), M=n(extremes(b.after_M)[0]), unit=unit))
    dif = float(np.max(np.hypot(*(b.total_exact - b.total_series).T)))
    top = float(np.max(np.hypot(*b.total_exact.T)))
    out.append(message("balance.report.series", lang, dF=n(dif), F=n(top),
                       percent=n(100.0 * dif / top if top > 0 else 0.0, 3)))
    out.append(message("balance.report.residual", lang, orders=max(b.orders), dF=n(b.residual, 4)))
    out.append(message("balance.report.counterweights", lang))
    out += table(counterweight_cells(b, lang))
    out.append(message("balance.report.journals", lang))
    out += table(journal_cells(b, phi, lang))
    if b.shafts is not None:
        s = b.shafts
        out.append(message("balance.report.shafts", lang, mr_with=n(s.mr_with * 1e3, 3),
                           angle_with=n(math.degrees(s.angle_with) % 360.0, 1),
                           mr_against=n(s.mr_against * 1e3, 3),
                           angle_against=n(math.degrees(s.angle_against) % 360.0, 1)))
    return out


def _c(C: np.ndarray | None) -> dict[str, Any] | None:
    if C is None:
        return None
    f, b = turning(C)
    hi, lo = extremes(C)
    return {"x": [float(C[0].real), float(C[0].imag)], "y": [float(C[1].real), float(C[1].imag)],
            "max": hi, "min": lo, "forward": abs(f), "backward": abs(b)}


def balance_json(b: Balance, phi: np.ndarray) -> dict[str, Any]:
    """The balancing results (SI units; complex amplitudes as [re, im] of F(φ) = Re(e^{ikφ}C))."""
    cw = b.counterweights
    span = phi[-1] - phi[0]

    def loads(J: np.ndarray) -> list[dict[str, float]]:
        out = []
        for L in J:
            m = np.hypot(L[:, 0], L[:, 1])
            out.append({"max": float(m.max()), "mean": float(np.trapezoid(m, phi) / span)})
        return out

    doc: dict[str, Any] = {
        "positions": {str(p): z for p, z in b.positions.items()},
        "spacing_given": b.spacing_given, "z0": b.z0,
        "orders": {str(k): {"A": o.A, "A_series": o.A_series, "F": _c(o.F), "M": _c(o.M),
                            "F_series": _c(o.F_series), "M_series": _c(o.M_series)}
                   for k, o in b.orders.items()},
        "rotating": {"F": _c(b.rotating_F), "M": _c(b.rotating_M)},
        "first_before": {"F": _c(b.before_F), "M": _c(b.before_M)},
        "first_after": {"F": _c(b.after_F), "M": _c(b.after_M)},
        "counterweights": {"share": cw.share,
                           "reduced": {str(p): v for p, v in cw.reduced.items()},
                           "mr_per_cheek": {str(p): v for p, v in cw.per_cheek.items()},
                           "mass_per_cheek": (None if cw.mass is None else
                                              {str(p): v for p, v in cw.mass.items()}),
                           "journals_before": loads(cw.journals_before),
                           "journals_after": loads(cw.journals_after)},
        "series_dF_max": float(np.max(np.hypot(*(b.total_exact - b.total_series).T))),
        "residual": b.residual}
    if b.shafts is not None:
        s = b.shafts
        doc["balance_shafts"] = {"mr_with": s.mr_with, "angle_with_deg": math.degrees(s.angle_with),
                                 "mr_against": s.mr_against,
                                 "angle_against_deg": math.degrees(s.angle_against)}
    return doc
