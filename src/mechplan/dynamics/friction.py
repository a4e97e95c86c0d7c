"""Friction in the pairs: the iteration's outcome, the balancing moment with friction, η(φ).

The force plan built with a loading that has ``friction`` lays the friction couples and forces
as known loads (:mod:`mechplan.construct.plans.force_friction`); this module reads them back.
Instantaneous efficiency η = M_b⁰/M_b (friction-free over with friction, where the balancing
moment drives) and by powers η = 1 − |P_f|/(M_b·ω1), P_f the power of every friction load
(the two agree: the friction-free plan balances the same loads without P_f). A linear first
driver (cylinder, slider): its driving force F_d and its rate q̇ in place of M_b and ω1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation, reaction_key
from ..geom.vec import Array, dot
from ..model.loads import pair_id
from ..model.mechanism import GROUND, Mechanism, PairKind

#: a relative velocity below this share of the drive's speed scale leaves friction's sense open
UNDEFINED = 1e-9


@dataclass(frozen=True, slots=True)
class PairFrictionResult:
    """One pair's friction over N positions: its load (couple N·m or force N, 2), its power (W),
    the relative speed (rad/s or m/s) and where the sense of friction is undefined."""

    pair: str
    kind: str                 # "revolute" | "prismatic"
    load: Array
    power: Array
    relative: Array
    undefined: Array          # (N,) bool


@dataclass(frozen=True, slots=True)
class FrictionAnalysis:
    """Balancing moment without (M_b⁰) and with friction (M_b), efficiency, the iteration."""

    free_moment: Array
    moment: Array
    efficiency: Array         # (N,) M_b⁰/M_b where M_b drives, else NaN
    efficiency_power: Array   # (N,) 1 − |ΣP_f|/(M_b·ω1) where M_b drives, else NaN
    passes: int
    residual: Array           # (N,) last relative change of the reactions
    pairs: tuple[PairFrictionResult, ...]
    tolerance: float = 1e-10
    #: a linear first driver: ``free_moment`` and ``moment`` are its driving force F_d⁰, F_d (N)
    linear: bool = False

    @property
    def converged(self) -> Array:
        """(N,) True where the iteration settled (it diverges where the mechanism self-locks)."""
        return np.asarray(self.residual <= self.tolerance)

    @property
    def undefined(self) -> Array:
        """(N,) True where the sense of some pair's friction is undefined (no relative motion)."""
        if not self.pairs:
            return np.zeros(self.moment.shape, dtype=bool)
        return np.any(np.stack([p.undefined for p in self.pairs]), axis=0)

    def json(self, i: int) -> dict[str, Any]:
        """The ``friction`` entry of position i."""
        name = "driving_force" if self.linear else "balancing_moment"
        return {
            name: _num(self.moment[i]),
            f"{name}_without_friction": _num(self.free_moment[i]),
            "efficiency": _num(self.efficiency[i]),
            "efficiency_by_powers": _num(self.efficiency_power[i]),
            "iterations": self.passes,
            "residual": _num(self.residual[i]),
            "converged": bool(self.converged[i]),
            "undefined_sense": [p.pair for p in self.pairs if p.undefined[i]],
            "pairs": {p.pair: ({"moment": _num(p.load[i])} if p.kind == "revolute" else
                               {"force": [_num(p.load[i][0]), _num(p.load[i][1])]})
                      | {"power": _num(p.power[i])} for p in self.pairs},
        }


def _num(x: Any) -> float | None:
    x = float(x)
    return x + 0.0 if math.isfinite(x) else None


def analyse_friction(c: Construction, ev: Evaluation, mech: Mechanism) -> FrictionAnalysis | None:
    """Read the friction of an evaluated force plan (None when the scene has no friction)."""
    it = c.results.get("M_b0")
    if it is None:
        return None
    free = ev[it]
    info = ev.shared[("friction", it)]
    linear = mech.drive.linear      # a cylinder or slider: F_d (N) and its rate q̇ (m/s)
    moment = ev[c.driving_force() if linear else c.balancing_moment()]
    omega1 = ev["vel.rate" if linear else c.omega(mech.drive.link)]
    scale = np.max(np.abs(omega1)) if omega1.size else 1.0
    pairs: list[PairFrictionResult] = []
    for p in mech.pairs:
        if p.kind is PairKind.REVOLUTE:
            first, second = (p.b, p.a) if p.b == GROUND else (p.a, p.b)
            sid = c.results.get(f"Mf_{reaction_key(first, second)}")
            if sid is None:
                continue
            rel = ev[c.omega(second)] - (0.0 if first == GROUND else ev[c.omega(first)])
            load = ev[sid]
            pairs.append(PairFrictionResult(pair_id(p.a, p.b), "revolute", load, load * rel,
                                            rel, np.abs(rel) <= UNDEFINED * scale))
        else:
            sid = c.results.get(f"Ff_{reaction_key(p.b, p.a)}")
            if sid is None:
                continue
            load = ev[sid]
            step = c[sid]
            v, angle = ev[step.input("velocity")], ev[step.input("angle")]
            for carrier in step.rest():          # the guide's link moves: sliding relative to it
                v = v - ev[carrier]
            rel = dot(v, np.stack((np.cos(angle), np.sin(angle)), axis=-1))
            # speeds against |ω1|·(1 m): a sliding speed this small has no sense
            pairs.append(PairFrictionResult(pair_id(p.a, p.b), "prismatic", load, dot(load, v),
                                            rel, np.abs(rel) <= UNDEFINED * scale))
    lost = sum((q.power for q in pairs), np.zeros_like(moment))
    drives = moment * omega1 > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        eta = np.where(drives, free / moment, np.nan)
        eta_p = np.where(drives, 1.0 + lost / (moment * omega1), np.nan)
    converged = np.asarray(info["residual"]) <= float(info["tolerance"])
    # where the iteration did not settle no moment with friction can be trusted
    moment = np.where(converged, moment, np.nan)
    eta = np.where(converged, eta, np.nan)
    eta_p = np.where(converged, eta_p, np.nan)
    return FrictionAnalysis(free, moment, eta, eta_p, int(info["passes"]),
                            np.asarray(info["residual"]), tuple(pairs),
                            float(info["tolerance"]), linear)


__all__ = ["FrictionAnalysis", "PairFrictionResult", "analyse_friction"]


def report_lines(fa: FrictionAnalysis, k: int, lang: str) -> list[str]:
    """The text report's friction block at position k (catalogue ``forces.report.*``)."""
    from ..construct.protocol import vector_text
    from ..i18n import message, scientific, unit
    from ..i18n import number as fmt

    nm = unit("N·m", lang)
    # a linear driver: its driving force F_d (N) in place of the balancing moment
    area, force = ("frictionlin", unit("N", lang)) if fa.linear else ("forces", nm)
    out = [f"### {message('forces.report.title', lang)}",
           "  " + message(f"{area}.report.{'forces' if fa.linear else 'moments'}", lang,
                          free=f"{fmt(float(fa.free_moment[k]), 3, lang)} {force}",
                          friction=f"{fmt(float(fa.moment[k]), 3, lang)} {force}"),
           "  " + message("forces.report.iteration", lang, passes=fa.passes,
                          residual=scientific(float(fa.residual[k]), 2, lang))]
    eta, eta_p = float(fa.efficiency[k]), float(fa.efficiency_power[k])
    if math.isfinite(eta):
        out.append("  " + message(f"{area}.report.efficiency", lang, eta=fmt(eta, 4, lang),
                                  power=fmt(eta_p, 4, lang)))
    else:
        out.append("  " + message(f"{area}.report.no_efficiency", lang))
    for p in fa.pairs:
        if p.kind == "revolute":
            text = f"M_f = {fmt(float(p.load[k]), 3, lang)} {nm}"
        else:
            text = f"F_f = {vector_text(p.load[k], lang, 2)}"
        out.append("  " + message("forces.report.pair", lang, pair=p.pair, load=text,
                                  power=f"{fmt(float(p.power[k]), 2, lang)} {unit('W', lang)}"))
    if not fa.converged[k]:
        out.append("  " + message("forces.report.diverged", lang, passes=fa.passes))
    undefined = [p.pair for p in fa.pairs if p.undefined[k]]
    if undefined:
        out.append("  " + message("forces.report.undefined", lang, pairs=", ".join(undefined)))
    return out
