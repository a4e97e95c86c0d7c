"""Friction in the pairs: the iteration's outcome, the balancing moment with friction, η(φ).

The force plan built with a loading that has ``friction`` lays the friction couples and forces
as known loads (:mod:`mechplan.construct.plans.force_friction`); this module reads them back.
Instantaneous efficiency η = M_b⁰/M_b (friction-free over with friction, where the balancing
moment drives) and by powers η = 1 − |P_f|/(M_b·ω1), P_f the power of every friction load
(the two agree: the friction-free plan balances the same loads without P_f). A linear first
driver (cylinder, slider): its driving force F_d and its rate q̇ in place of M_b and ω1.

Two drivers (W = 2): each driver's M_b or F_d comes from the same passes (its friction-free
value from the first), and the machine's efficiency is the ratio of the drivers' input powers
without and with friction, η = P⁰/P with P = Q1·q̇1 + Q2·q̇2 (Q a balancing moment or driving
force, q̇ its ω or rate), defined where P > 0; by powers η = 1 − |ΣP_f|/P (the two agree: the
friction-free plan balances the same loads without P_f). With one driver it is M_b⁰/M_b.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation, reaction_key
from ..construct.plans.force_friction import UNDEFINED as _UNDEFINED
from ..geom.vec import Array, dot
from ..model.loads import pair_id
from ..model.mechanism import GROUND, Mechanism, PairKind

#: a relative velocity below this share of the drivers' speed scale leaves friction's sense open
#: (the friction steps take it as zero below the same share: plans/force_friction.py)
UNDEFINED = _UNDEFINED


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
class DriverFriction:
    """A second driver (W = 2) with friction: its link, its balancing moment (a crank, N·m) or
    driving force (a cylinder or slider, N) without (``free``) and with friction (``value``),
    its rate (ω rad/s or q̇ m/s) over N positions."""

    link: str
    linear: bool
    free: Array
    value: Array
    rate: Array

    @property
    def power(self) -> Array:
        """(N,) its input power with friction Q·q̇ (W)."""
        return np.asarray(self.value * self.rate)

    @property
    def free_power(self) -> Array:
        """(N,) its input power without friction Q⁰·q̇ (W)."""
        return np.asarray(self.free * self.rate)


@dataclass(frozen=True, slots=True)
class FrictionAnalysis:
    """Balancing moment without (M_b⁰) and with friction (M_b), efficiency, the iteration."""

    free_moment: Array
    moment: Array
    efficiency: Array         # (N,) M_b⁰/M_b (W = 2: P⁰/P) where it drives, else NaN
    efficiency_power: Array   # (N,) 1 − |ΣP_f|/(M_b·ω1) (W = 2: /P) where it drives, else NaN
    passes: int
    residual: Array           # (N,) last relative change of the reactions
    pairs: tuple[PairFrictionResult, ...]
    tolerance: float = 1e-10
    #: a linear first driver: ``free_moment`` and ``moment`` are its driving force F_d⁰, F_d (N)
    linear: bool = False
    #: the first driver's rate (ω1 or q̇1) and the second driver (W = 2)
    rate: Array | None = None
    second: DriverFriction | None = None
    first_link: str = ""

    @property
    def first_power(self) -> Array:
        """(N,) the first driver's input power with friction M_b·ω1 (or F_d·q̇1), W."""
        return np.asarray(self.moment * self.rate)

    @property
    def first_free_power(self) -> Array:
        """(N,) the first driver's input power without friction, W."""
        return np.asarray(self.free_moment * self.rate)

    @property
    def input_power(self) -> Array:
        """(N,) the drivers' input power with friction P (W), NaN where not settled."""
        extra = 0.0 if self.second is None else self.second.power
        return np.asarray(self.first_power + extra)

    @property
    def free_input_power(self) -> Array:
        """(N,) the drivers' input power without friction P⁰ (W)."""
        extra = 0.0 if self.second is None else self.second.free_power
        return np.asarray(self.first_free_power + extra)

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
        return self._pair_json(i, name) | self._drivers_json(i)

    def _drivers_json(self, i: int) -> dict[str, Any]:
        """W = 2: each driver's own values and input power, the machine's input power."""
        s = self.second
        if s is None or self.rate is None:
            return {}
        name = "driving_force" if s.linear else "balancing_moment"
        return {
            "first_driver": {"link": self.first_link, "ratio": _num(_ratio(
                self.free_moment[i], self.moment[i], self.rate[i])),
                "power": _num(self.first_power[i]),
                "power_without_friction": _num(self.first_free_power[i])},
            "second_driver": {"link": s.link, name: _num(s.value[i]),
                              f"{name}_without_friction": _num(s.free[i]),
                              "ratio": _num(_ratio(s.free[i], s.value[i], s.rate[i])),
                              "power": _num(s.power[i]),
                              "power_without_friction": _num(s.free_power[i])},
            "input_power": _num(self.input_power[i]),
            "input_power_without_friction": _num(self.free_input_power[i]),
        }

    def _pair_json(self, i: int, name: str) -> dict[str, Any]:
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


def _ratio(free: float, value: float, rate: float) -> float:
    """One driver's own Q⁰/Q where it drives (Q·q̇ > 0), else NaN."""
    return float(free / value) if value * rate > 0 else math.nan


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
    if mech.drive2 is not None and omega1.size:     # W = 2: the faster driver sets the scale
        rate2 = ev["vel.rate2" if mech.drive2.linear else c.omega(mech.drive2.link)]
        scale = max(scale, float(np.max(np.abs(rate2))))
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
    converged = np.asarray(info["residual"]) <= float(info["tolerance"])
    driver2 = _second(c, ev, mech, converged)
    # the drivers' input power with and without friction (one driver: M_b·ω1 and M_b⁰·ω1)
    power = moment * omega1 + (0.0 if driver2 is None else driver2.value * driver2.rate)
    power0 = free * omega1 + (0.0 if driver2 is None else driver2.free * driver2.rate)
    drives = power > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        eta = np.where(drives, power0 / power, np.nan)
        eta_p = np.where(drives, 1.0 + lost / power, np.nan)
    # where the iteration did not settle no moment with friction can be trusted
    moment = np.where(converged, moment, np.nan)
    eta = np.where(converged, eta, np.nan)
    eta_p = np.where(converged, eta_p, np.nan)
    return FrictionAnalysis(free, moment, eta, eta_p, int(info["passes"]),
                            np.asarray(info["residual"]), tuple(pairs),
                            float(info["tolerance"]), linear, np.asarray(omega1), driver2,
                            mech.drive.link)


def _second(c: Construction, ev: Evaluation, mech: Mechanism,
            converged: Array) -> DriverFriction | None:
    """The second driver's M_b or F_d without and with friction and its rate (W = 2)."""
    from ..construct.plans.force_friction import SECOND_FREE

    drive2 = mech.drive2
    sid = c.results.get(SECOND_FREE)
    if drive2 is None or sid is None:
        return None
    link, linear = drive2.link, drive2.linear
    value = ev[c.second_driving_force(link) if linear else c.second_balancing_moment(link)]
    rate = ev["vel.rate2" if linear else c.omega(link)]
    return DriverFriction(link, linear, np.asarray(ev[sid]),
                          np.where(converged, value, np.nan), np.asarray(rate))


__all__ = ["DriverFriction", "FrictionAnalysis", "PairFrictionResult", "analyse_friction"]


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
    if fa.second is not None:   # W = 2: the second driver, the input powers, η of the machine
        out += _second_lines(fa, fa.second, k, lang)
        area = "frictionw2"
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


def _second_lines(fa: FrictionAnalysis, s: DriverFriction, k: int, lang: str) -> list[str]:
    """W = 2: the second driver's value without and with friction, the drivers' input powers."""
    from ..i18n import message, unit
    from ..i18n import number as fmt

    force = unit("N" if s.linear else "N·m", lang)
    w = unit("W", lang)

    def watts(x: Array) -> str:
        return f"{fmt(float(x[k]), 2, lang)} {w}"
    return ["  " + message("frictionw2.report.second", lang, link=s.link,
                           symbol=f"{'F_d' if s.linear else 'M_b'}{s.link}",
                           free=f"{fmt(float(s.free[k]), 3, lang)} {force}",
                           friction=f"{fmt(float(s.value[k]), 3, lang)} {force}"),
            "  " + message("frictionw2.report.powers", lang, free=watts(fa.free_input_power),
                           friction=watts(fa.input_power), first=fa.first_link,
                           second=s.link, p1=watts(fa.first_power), p2=watts(s.power))]
