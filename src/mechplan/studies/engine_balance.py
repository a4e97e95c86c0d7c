"""The balancing part of an engine study: report lines, JSON, table cells (sheet and text)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..dynamics.engine.balance import Balance, extremes, turning
from ..i18n import message, number


def orders_cells(b: Balance, lang: str) -> list[list[str]]:
    """Heading and rows of the orders table: amplitudes exact and by the series, free force and
    moment (maxima over the turn), the parts turning with and against the crank."""
    def n(x: float, k: int = 2) -> str:
        return number(x, k, lang)

    m = "M" if b.spacing_given else "M_a"
    head = [message(f"balance.col.{c}", lang) for c in
            ("order", "A", "A_series", "F", "F_series", "dF", m, m + "_series", "forward",
             "backward")]
    rows = [head]
    for k, o in b.orders.items():
        f, bk = turning(o.F)
        Fs = extremes(o.F_series)[0] if o.F_series is not None else None
        Ms = extremes(o.M_series)[0] if o.M_series is not None else None
        rows.append([str(k), number(o.A, 6, lang),
                     "—" if o.A_series is None else number(o.A_series, 6, lang),
                     n(o.F_max), "—" if Fs is None else n(Fs),
                     "—" if Fs is None else n(o.F_max - Fs), n(o.M_max),
                     "—" if Ms is None else n(Ms), n(abs(f)), n(abs(bk))])
    return rows


def counterweight_cells(b: Balance, lang: str) -> list[list[str]]:
    """Throw, counterweight mass reduced to R, m·r of one cheek, one cheek's mass."""
    cw = b.counterweights
    head = [message(f"balance.col.{c}", lang) for c in ("throw", "z", "reduced", "mr", "mass")]
    rows = [head]
    for p in sorted(cw.reduced):
        rows.append([str(p), number(b.positions[p] * (1e3 if b.spacing_given else 1.0),
                                    1 if b.spacing_given else 0, lang),
                     number(cw.reduced[p], 4, lang), number(cw.per_cheek[p] * 1e3, 3, lang),
                     "—" if cw.mass is None else number(cw.mass[p], 4, lang)])
    return rows


def journal_cells(b: Balance, phi: np.ndarray, lang: str) -> list[list[str]]:
    """Journal, max and mean load (kN) before and after the counterweights."""
    cw = b.counterweights
    head = [message(f"balance.col.{c}", lang) for c in
            ("journal", "max_before", "max_after", "mean_before", "mean_after")]
    rows = [head]
    span = phi[-1] - phi[0]
    for j, (J0, J1) in enumerate(zip(cw.journals_before, cw.journals_after)):
        m0, m1 = np.hypot(J0[:, 0], J0[:, 1]), np.hypot(J1[:, 0], J1[:, 1])
        rows.append([str(j + 1)] + [number(v * 1e-3, 3, lang) for v in (
            float(m0.max()), float(m1.max()), float(np.trapezoid(m0, phi) / span),
            float(np.trapezoid(m1, phi) / span))])
    return rows


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
    out.append(message("balance.report.rotating", lang, F=n(rf), M=n(rm)))
    out.append(message("balance.report.first_before", lang, F=n(extremes(b.before_F)[0]),
                       M=n(extremes(b.before_M)[0])))
    out.append(message("balance.report.first_after", lang, share=n(b.counterweights.share, 2),
                       F=n(extremes(b.after_F)[0]), M=n(extremes(b.after_M)[0])))
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
