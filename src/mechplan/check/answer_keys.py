"""The exact answers of a study and the student's own arithmetic between their answers.

``keys_for(study)`` gives a :class:`Keys` of one kind (dynamics, engine, cam, gears): ``exact(name,
phi)`` is the study's value (SI) and the magnitude a diagram of it spans (for the tolerance floor);
``own(name, phi, written)`` is what the student's own other answers give by the course's formula
(δ = (ω_max − ω_min)/ω_m, P = P_г + P_j, T = P·sin(φ+β)/cos β, M = T·R, tan α = s′/(s₀ + s),
u by Willis from their own tooth numbers …), with the formula and the names it uses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

Written = dict[tuple[str, float | None], float]     # (canonical, φ deg) → SI value
Own = tuple[float, str, tuple[str, ...]]           # value, formula, the names it uses


@dataclass
class Keys:
    """The exact answers of one study."""

    kind: str                                       # dynamics | engine | cam | gears
    scalars: dict[str, float] = field(default_factory=dict)
    columns: dict[str, dict[float, float]] = field(default_factory=dict)   # name → φ → value
    spans: dict[str, float] = field(default_factory=dict)
    any_angle: Any = None                           # cam: φ (deg) → {name: value}
    dimensions: dict[str, str] = field(default_factory=dict)   # where the catalogue's differs
    study: Any = None
    geometry: Any = None                            # cam: the synthesised geometry

    def exact(self, name: str, phi: float | None) -> float | None:
        """The exact value of ``name`` (at ``phi`` degrees for a per-angle quantity)."""
        if phi is None:
            return self.scalars.get(name)
        if self.any_angle is not None:
            return self.any_angle(phi).get(name)
        col = self.columns.get(name, {})
        return next((v for a, v in col.items() if abs(a - phi) < 1e-6), None)

    def angles(self, name: str) -> list[float]:
        """The angles a per-angle quantity is known at."""
        return sorted(self.columns.get(name, {}))

    def own(self, name: str, phi: float | None, w: Written) -> Own | None:
        """What the student's own other answers give for ``name``, or None."""
        fn = _OWN.get(self.kind)
        return fn(self, name, phi, w) if fn else None


def keys_for(study: Any) -> Keys:
    """The exact answers of a solved study (a MechanismStudy with dynamics, an engine, a cam or a
    gear study)."""
    from ..studies.cam import CamStudy
    from ..studies.engine import EngineStudy
    from ..studies.gears import GearStudy

    if isinstance(study, EngineStudy):
        return _engine(study)
    if isinstance(study, CamStudy):
        return _cam(study)
    if isinstance(study, GearStudy):
        return _gears(study)
    return _dynamics(study)


def _span(col: dict[float, float]) -> float:
    return max((abs(v) for v in col.values()), default=0.0)


# -- machine dynamics ---------------------------------------------------------------------------
def _dynamics(study: Any) -> Keys:
    d = study.to_json()["dynamics"]
    fly, motion = d["flywheel"], d["motion"]
    k = Keys("dynamics", study=d)
    k.scalars = {"J_fly": fly["exact"]["J"], "J_W": fly["wittenbauer"]["J"],
                 "J_Mer": fly["merkalov"]["J"], "J_I": fly["merkalov"]["J_I"],
                 "delta": d["delta"], "omega_m": d["omega_m"],
                 "omega_max": motion["omega_max"], "omega_min": motion["omega_min"],
                 "M_const": d["constant_moment"], "A_d": d["work_driving"],
                 "A_c": d["work_resisting"],
                 "dT_max": fly["exact"]["J"] * d["delta"] * d["omega_m"] ** 2}
    for name, key in (("J_red", "J_red"), ("M_d", "M_d"), ("M_c", "M_c"), ("A_d_phi", "A_d"),
                      ("A_c_phi", "A_c"), ("dT", "dT"), ("omega", "omega")):
        k.columns[name] = {float(p["phi_deg"]): float(p[key]) for p in d["positions"]}
        k.spans[name] = _span(k.columns[name])
    k.spans["omega"] = motion["omega_max"] - motion["omega_min"]
    return k


def _all(w: Written, phi: float | None, *names: str) -> list[float] | None:
    """The student's values of ``names`` (at ``phi``), or None when one is missing."""
    vals = [w.get((n, phi)) for n in names]
    return [v for v in vals if v is not None] if all(v is not None for v in vals) else None


def _own_dynamics(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    d = k.study
    wm = w.get(("omega_m", None)) or d["omega_m"]
    extremes = _all(w, None, "omega_max", "omega_min")
    if name == "delta" and extremes:
        return ((extremes[0] - extremes[1]) / wm, "δ = (ω_max − ω_min)/ω_m",
                ("omega_max", "omega_min"))
    if name == "omega_m" and extremes:
        return ((extremes[0] + extremes[1]) / 2, "ω_m = (ω_max + ω_min)/2",
                ("omega_max", "omega_min"))
    dT = _all(w, None, "dT_max")
    if name in ("J_fly", "J_W") and dT:            # δ and ω_m are given data
        return (dT[0] / (d["delta"] * d["omega_m"] ** 2), "J = ΔT_max/(δ·ω_m²)", ("dT_max",))
    j1 = _all(w, None, "J_I")
    if name in ("J_fly", "J_Mer") and j1:
        return j1[0] - d["J_present"], "J = J_I − J_const", ("J_I",)
    work_name = "A_c" if d["unknown"] == "driving" else "A_d"
    work = _all(w, None, work_name)
    if name == "M_const" and work:
        return work[0] / math.radians(d["cycle_deg"]), "M = A/φ_cycle", (work_name,)
    return None


# -- engine -------------------------------------------------------------------------------------
_ENGINE_COLUMNS = ("p", "Pk", "Pj", "P", "N", "S", "T", "Z", "M", "beta")


def _engine(study: Any) -> Keys:
    doc = study.to_json()
    k = Keys("engine", study=doc)
    first = str(doc["cylinders"][0]["number"])
    for name in _ENGINE_COLUMNS:
        k.columns[name] = {float(a["phi_deg"]): float(a["cylinders"][first][name])
                           for a in doc["angles"]}
    k.columns["M_total"] = {float(a["phi_deg"]): float(a["M_total"]) for a in doc["angles"]}
    for name, col in k.columns.items():
        k.spans[name] = _span(col)
    k.scalars = {"M_mean": doc["torque"]["mean"], "M_max": doc["torque"]["max"],
                 "M_min": doc["torque"]["min"]}
    return k


def _own_engine(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    if phi is None:
        return None
    e = k.study["engine"]
    pressure = _all(w, phi, "p")
    if name == "Pk" and pressure:
        return (pressure[0] - e["p0"]) * e["F_p"], "P_г = (p − p₀)·F_п", ("p",)
    parts = _all(w, phi, "Pk", "Pj")
    if name == "P" and parts:
        return parts[0] + parts[1], "P = P_г + P_j", ("Pk", "Pj")
    tangential = _all(w, phi, "T")
    if name == "M" and tangential:
        return tangential[0] * e["R"], "M = T·R", ("T",)
    beta = w.get(("beta", phi))
    if beta is None:
        beta = k.exact("beta", phi)
    if beta is None or len(k.study["cylinders"]) > 1:
        return None                 # the formulas below are those of a central slider-crank
    a = math.radians(phi)
    force = _all(w, phi, "P")
    rule = {"N": (math.tan(beta), "N = P·tg β"), "S": (1 / math.cos(beta), "S = P/cos β"),
            "T": (math.sin(a + beta) / math.cos(beta), "T = P·sin(φ+β)/cos β"),
            "Z": (math.cos(a + beta) / math.cos(beta), "Z = P·cos(φ+β)/cos β")}.get(name)
    if rule and force:
        return force[0] * rule[0], rule[1], ("P",)
    return None


# -- cam ----------------------------------------------------------------------------------------
def _cam(study: Any) -> Keys:
    from ..synthesis.cam.profile import sample

    g = study.design.geometry
    doc = study.to_json()
    k = Keys("cam", study=doc, geometry=g)
    base, pa, rho = doc["base_radius"], doc["pressure_angle_max"], doc["radius_of_curvature_min"]
    k.scalars = {"r0": base["used"], "e": base["offset"], "r_profile": base["working_profile"],
                 "alpha_max_rise": pa["rise"][0], "alpha_max_return": pa["return"][0],
                 "alpha_max": max(pa["rise"][0], pa["return"][0]),
                 "rho_min": abs(rho["profile"][0]), "rho_min_pitch": abs(rho["pitch"][0])}
    for name in ("s1", "s2"):
        k.spans[name] = max(abs(r[name]) for r in doc["table"])
    k.spans["s"], k.spans["alpha"] = g.stroke, math.radians(50.0)

    def at(phi_deg: float) -> dict[str, float]:
        m = sample(g, math.radians(phi_deg))
        out = {"s": float(m.s[0]), "s1": float(m.s1[0]), "s2": float(m.s2[0])}
        return out | ({"alpha": abs(float(m.alpha[0]))} if _has_alpha(doc) else {})

    k.any_angle = at
    if doc["follower"]["motion"] != "translating":       # the follower's s is an angle ψ
        k.dimensions = {"s": "angle", "s1": "dimensionless", "s2": "dimensionless"}
    return k


def _has_alpha(doc: dict[str, Any]) -> bool:
    """Pressure angles per angle are graded for a translating knife or roller follower."""
    return doc["follower"]["motion"] == "translating" and doc["follower"]["contact"] != "flat"


def _own_cam(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    from ..synthesis.cam.profile import pressure_angle

    doc = k.study
    r0 = w.get(("r0", None)) or doc["base_radius"]["used"]
    if name == "r_profile" and ("r0", None) in w and doc["follower"]["contact"] == "roller":
        return w[("r0", None)] - doc["follower"]["roller_radius"], "r = r₀ − r_р", ("r0",)
    s, s1 = w.get(("s", phi)), w.get(("s1", phi))
    if name == "alpha" and phi is not None and _has_alpha(doc) and s is not None and \
            s1 is not None:       # the engine's pressure angle at the student's own r₀, e, s, s′
        g = replace(k.geometry, r0=r0, e=w.get(("e", None), doc["base_radius"]["offset"]))
        alpha = pressure_angle(g, np.array([s]), np.array([s1]), np.zeros(1))
        return abs(float(alpha[0])), "tg α = (s′ ∓ e)/(√(r₀² − e²) + s)", ("s", "s1")
    return None


# -- gears --------------------------------------------------------------------------------------
def _gears(study: Any) -> Keys:
    sol = study.solution
    k = Keys("gears", study=sol)
    if sol.planetary is not None:
        c = sol.planetary.chosen
        k.scalars |= {f"z{i}": float(z) for i, z in enumerate(c.z, start=1)}
        k.scalars |= {"k": float(sol.planetary.spec.planets), "u": c.ratio, "a_w": c.a_w[0],
                      "assembly": c.assembly_value}
    if sol.pair is not None:
        p = sol.pair
        spec = p.spec
        k.scalars |= {"pair.z1": float(p.gears[0].z), "pair.z2": float(p.gears[1].z),
                      "pair.m": spec.module, "pair.x1": p.x1, "pair.x2": p.x2,
                      "pair.a_w": p.a_w, "pair.alpha_w": p.alpha_w, "pair.eps_alpha": p.eps,
                      "pair.r_b1": p.gears[0].r_b,
                      "pair.r_b2": p.gears[1].r_b, "pair.y": p.y}
    return k


def valid_sets(k: Keys) -> dict[tuple[int, ...], Any]:
    """The tooth-number sets that meet every condition of the planetary scene."""
    pl = k.study.planetary
    if pl is None:
        return {}
    return {tuple(int(z) for z in c.z): c for c in (pl.chosen, *pl.others) if c.valid}


def _own_gears(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
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
        i = train.willis_i(spec.scheme, z)
        u = float(train.ratio_from_i(i, spec.scheme, spec.fixed, spec.input, spec.output))
        sign = "−" if train.willis_sign(spec.scheme) < 0 else ""
        i_text = "z3/z1" if len(z) == 3 else "z2·z4/(z1·z3)"
        return u, f"Willis: i^h = {sign}{i_text}", used
    if name == "a_w":
        return float(train.centre_distance(spec, z)[0]), "a_w = m(z₁ ± z₂)/2", used
    if name == "assembly":
        a, b = train.assembly_terms(spec, z)
        planets = w.get(("k", None)) or spec.planets
        return float(a) / float(b) / planets, "z₁·u₁ₕ/k", used
    return None


def _own_pair(sol: Any, name: str, w: Written) -> Own | None:
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


_OWN = {"dynamics": _own_dynamics, "engine": _own_engine, "cam": _own_cam, "gears": _own_gears}
