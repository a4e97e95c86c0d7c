"""Results of the force plan, vectorised over positions: JSON-ready dicts and a text summary.

Build the construction with the ``"force"`` plan and a :class:`~mechplan.dynamics.loading.Loading`,
evaluate it at the positions wanted, then :func:`analyse_forces` gathers every reaction, the
balancing moment (group by group and by Zhukovsky's lever) and the reduced moment and inertia.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..construct.graph import Construction, Evaluation
from ..construct.plans.force import pair_key
from ..construct.step import Op, Plan, Step
from ..geom.vec import Array, cross, norm, perp
from ..model.mechanism import Mechanism, PairKind
from .reduced import link_omega, reduced_of

#: ids of the force plan's load steps (inertia, weights, external loads)
LOAD_PREFIXES = ("force.Q.", "force.Mq.", "force.h.", "force.Kq.", "force.G.", "force.load.")


@dataclass(frozen=True, slots=True)
class Reaction:
    """R_ij, the force of link i on link j at their pair, over N positions.

    Prismatic pairs: ``guide`` names the guide and ``offset`` (N,) is where the line of action
    crosses the guide, in metres along the guide from the pair's point ``point`` (NaN where the
    force is zero and the reaction is a pure couple).
    """

    key: str
    i: str
    j: str
    point: str
    force: Array
    guide: str | None = None
    offset: Array | None = None


@dataclass(frozen=True, slots=True)
class ForceAnalysis:
    """Kinetostatics of a mechanism at N positions (SI units, moments counter-clockwise +)."""

    phi: Array                                  # (N,) crank angle, scene convention, rad
    omega1: Array                               # (N,) angular velocity of the driving link
    inertia: dict[str, tuple[Array, Array]]     # link → (Q (N, 2), M_q (N,))
    reactions: dict[str, Reaction]              # revolute pairs, key "ij" (i before j)
    guide_reactions: dict[str, Reaction]        # prismatic pairs
    balancing_moment: Array                     # (N,) from the force polygons
    zhukovsky_moment: Array                     # (N,) from Zhukovsky's lever
    reduced_moment: Array                       # (N,)
    reduced_inertia: Array                      # (N,)

    @property
    def difference_percent(self) -> Array:
        """(M_b − M_b,Zhukovsky)/max(|M_b|, |M_b,Zhukovsky|)·100 (0 where both vanish)."""
        a, b = self.balancing_moment, self.zhukovsky_moment
        scale = np.maximum(np.abs(a), np.abs(b))
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(scale > 0, (a - b) / np.where(scale > 0, scale, 1.0) * 100.0, 0.0)

    def driving(self, i: int) -> bool:
        """True if the balancing moment drives (M_b·ω1 > 0) at position i."""
        return bool(self.balancing_moment[i] * self.omega1[i] > 0)

    def json(self, i: int) -> dict[str, Any]:
        """The ``forces`` and ``reduced`` entries of position i, ready for ``json.dumps``."""
        return {
            "forces": {
                "inertia": {link: {"force": _vec(q[i]), "moment": _num(m[i])}
                            for link, (q, m) in self.inertia.items()},
                "reactions": {k: _vec(r.force[i]) for k, r in self.reactions.items()},
                "guide_reactions": {
                    k: {"force": _vec(r.force[i]),
                        "offset": _num(r.offset[i]) if r.offset is not None else None}
                    for k, r in self.guide_reactions.items()},
                "balancing_moment": _num(self.balancing_moment[i]),
                "zhukovsky_balancing_moment": _num(self.zhukovsky_moment[i]),
            },
            "reduced": {"moment": _num(self.reduced_moment[i]),
                        "inertia": _num(self.reduced_inertia[i])},
        }


def _num(x: Any) -> float | None:
    x = float(x)
    if not math.isfinite(x):
        return None
    return x + 0.0    # no negative zero in the output


def _vec(v: Array) -> list[float | None]:
    return [_num(v[0]), _num(v[1])]


def _order(mech: Mechanism) -> dict[str, int]:
    return {link: n for n, link in enumerate(mech.links)}


def analyse_forces(c: Construction, ev: Evaluation, mech: Mechanism, loading: Any) -> ForceAnalysis:
    """Gather the force plan's results at the evaluated positions (one vectorised pass)."""
    order = _order(mech)
    inertia: dict[str, tuple[Array, Array]] = {}
    zero_v, zero_s = np.zeros((ev.n, 2)), np.zeros(ev.n)
    for link, ms in loading.masses.items():
        if ms.mass > 0 or ms.inertia > 0:
            q = ev[c.results[f"Q_{link}"]] if f"Q_{link}" in c.results else zero_v
            m = ev[c.results[f"M_q{link}"]] if f"M_q{link}" in c.results else zero_s
            inertia[link] = (q, m)
    reactions: dict[str, Reaction] = {}
    guides: dict[str, Reaction] = {}
    for pair in mech.pairs:
        i, j = sorted((pair.a, pair.b), key=order.__getitem__)
        key = pair_key(i, j)
        force = ev[c.results[f"R_{key}"]]
        if pair.kind is PairKind.REVOLUTE:
            reactions[key] = Reaction(key, i, j, pair.point, force)
        else:
            guides[key] = Reaction(key, i, j, pair.point, force, pair.guide,
                                   ev[c.results[f"d_{key}"]])
    reactions = dict(sorted(reactions.items(), key=lambda kv: (order[kv[1].i], order[kv[1].j])))
    guides = dict(sorted(guides.items(), key=lambda kv: (order[kv[1].i], order[kv[1].j])))
    m_red, j_red = reduced_of(c, ev, mech, loading)
    return ForceAnalysis(
        phi=ev.phi, omega1=link_omega(c, ev, mech.drive.link), inertia=inertia,
        reactions=reactions, guide_reactions=guides,
        balancing_moment=ev[c.results["M_b"]], zhukovsky_moment=ev[c.results["M_b_zhukovsky"]],
        reduced_moment=m_red, reduced_inertia=j_red)


def balancing_force(c: Construction, ev: Evaluation, mech: Mechanism, point: str,
                    angle: float | None = None) -> Array:
    """The balancing force (N, 2) at a point of the driving link, equivalent to M_b.

    Its line of action is ⊥ to the crank line from the pivot to ``point`` (the textbook case,
    F_b = M_b/l) or, given ``angle`` (rad, counter-clockwise from +x), along that fixed direction;
    NaN where that line passes through the pivot.
    """
    drive = mech.drive
    if point not in mech.links[drive.link].points or point == drive.pivot:
        raise ValueError(f"point {point!r} is not a point of the driving link {drive.link} other "
                         f"than its pivot {drive.pivot}")
    r = ev[f"pos.{point}"] - ev[f"pos.{drive.pivot}"]
    if angle is None:
        d = perp(r) / norm(r)[:, None]
    else:
        d = np.broadcast_to(np.array([math.cos(angle), math.sin(angle)]), r.shape)
    with np.errstate(invalid="ignore", divide="ignore"):
        magnitude = ev[c.results["M_b"]] / cross(r, d)
    return magnitude[:, None] * d


# -- text --------------------------------------------------------------------------------------
def _f(x: float, unit: str = "", digits: int = 6) -> str:
    if not math.isfinite(x):
        return "undefined"
    text = f"{x + 0.0:.{digits}g}"
    return f"{text} {unit}".rstrip()


def _deg(angle: float) -> str:
    return f"{math.degrees(angle) + 0.0:.6g}°"


def _polar(v: Array) -> str:
    mag = float(norm(v))
    if mag == 0.0:
        return "0 N"
    return f"{_f(mag, 'N')} at {_deg(math.atan2(v[1], v[0]))}"


def force_text(c: Construction, ev: Evaluation, mech: Mechanism, loading: Any, i: int,
               mu_F: float | None = None, result: ForceAnalysis | None = None) -> list[str]:
    """Lines of the kinetostatic analysis at position i (English; the protocol translates)."""
    fa = result or analyse_forces(c, ev, mech, loading)
    link1 = mech.drive.link
    head = (f"Kinetostatic analysis at φ{link1} = {_deg(float(fa.phi[i]))} "
            f"(ω{link1} = {_f(float(fa.omega1[i]), 'rad/s')})")
    lines = [head]
    steps = c.of_plan(Plan.FORCE)
    loads = [s for s in steps if s.id.startswith(LOAD_PREFIXES)]
    if loads:
        lines.append("Loads (inertia loads Q = −m·a_S, M_q = −J_S·ε; weights; external loads):")
    for s in loads:
        v = ev[s.id][i]
        if s.op is Op.LINE_OF_ACTION:
            continue
        if s.kind.value == "point":
            lines.append(f"  {s.label} = {_polar(v)} at {s.subject[0]}")
        elif s.op is Op.INERTIA_OFFSET:
            lines.append(f"  {s.label} = |M_q|/|Q| = {_f(abs(float(v)) * 1000, 'mm')} "
                         "(offset of the single equivalent inertia force)")
        else:
            lines.append(f"  {s.label} = {_f(float(v), 'N·m')}")
    groups: list[str] = []
    for s in steps:
        if s not in loads and s.group != "lever" and s.group not in groups:
            groups.append(s.group)
    for group in groups:
        lines.append(f"Group {group}:")
        eq = c.equations.get((Plan.FORCE, group))
        for s in steps:
            if s.group == group and s not in loads:
                lines.extend("  " + x for x in _step_text(c, ev, s, i, mu_F, eq))
    lines.append("Reactions R_ij (force of link i on link j):")
    for r in fa.reactions.values():
        lines.append(f"  R_{r.key} = {_polar(r.force[i])} at {r.point}")
    if fa.guide_reactions:
        lines.append("Guide reactions (perpendicular to the guide):")
    for r in fa.guide_reactions.values():
        assert r.offset is not None
        d = float(r.offset[i])
        where = (f"its line of action crosses {r.guide} {_f(d * 1000, 'mm')} from {r.point} "
                 f"along {r.guide}" if math.isfinite(d) else "it is a pure couple (no force)")
        lines.append(f"  R_{r.key} = {_polar(r.force[i])}; {where}")
    mb, mz = float(fa.balancing_moment[i]), float(fa.zhukovsky_moment[i])
    sense = "counter-clockwise" if mb > 0 else "clockwise"
    role = "driving" if fa.driving(i) else "resisting"
    if mb == 0:
        sense, role = "zero", "neither driving nor resisting"
    lines.append(f"Balancing moment on link {mech.drive.link}: M_b = {_f(mb, 'N·m')} ({sense}; "
                 f"{role}, M_b·ω{mech.drive.link} {'>' if fa.driving(i) else '≤'} 0)")
    lever = c[c.results["M_b_zhukovsky"]]
    applied = ", ".join(lever.subject) or "no loads"
    lines.append(f"Zhukovsky's lever (the velocity plan turned by 90°, {applied} at their images, "
                 f"couples as M·ω/ω{link1}): M_b = {_f(mz, 'N·m')}; difference "
                 f"{float(fa.difference_percent[i]):.3g} %")
    lines.append(f"Reduced moment of forces M_red = {_f(float(fa.reduced_moment[i]), 'N·m')}; "
                 f"reduced moment of inertia J_red = {_f(float(fa.reduced_inertia[i]), 'kg·m²')}")
    return lines


def _step_text(c: Construction, ev: Evaluation, s: Step, i: int, mu_F: float | None,
               eq: tuple[str, list[tuple[str, str, str]]] | None) -> list[str]:
    v = ev[s.id][i]
    lab = {sid: c[sid].label for sid in s.inputs}

    def drawn(x: Array) -> str:
        return f", drawn {_f(float(norm(x)) / mu_F, 'mm', 4)}" if mu_F else ""

    if s.op is Op.MOMENT_SUM:
        about, link = s.subject[:2]
        centre = ev[s.inputs[0]][i]
        parts, k = [], 1
        for kind in s.param("layout"):
            if kind == "F":
                p, f = ev[s.inputs[k]][i], ev[s.inputs[k + 1]][i]
                m = float(cross(p - centre, f))
                h = abs(m) / float(norm(f)) if float(norm(f)) > 0 else 0.0
                parts.append(f"{c[s.inputs[k + 1]].label}·h = {_f(float(norm(f)), 'N', 5)}·"
                             f"{_f(h * 1000, 'mm', 5)} → {_f(m, 'N·m', 5)}")
                k += 2
            else:
                parts.append(f"{c[s.inputs[k]].label} = {_f(float(ev[s.inputs[k]][i]), 'N·m', 5)}")
                k += 1
        total = f"{s.label}: moments about {about} of the known loads on link {link} = " \
            f"{_f(float(v), 'N·m')}"
        return [total, *(f"    {p}" for p in parts)]
    if s.op is Op.MOMENT_ARM_TANGENTIAL:
        centre, at = ev[s.inputs[0]][i], ev[s.inputs[1]][i]
        arm = float(norm(at - centre))
        how = (f"⊥ {s.subject[3]}" if len(s.inputs) == 4 else f"⊥ {s.subject[0]}{s.subject[1]}")
        text = f"{s.label} = −{lab[s.inputs[2]]}/arm ({how}, arm from {s.subject[1]} to " \
            f"{s.subject[0]} = {_f(arm * 1000, 'mm', 5)}) = {_polar(v)}"
        return [text]
    if s.op in (Op.MOMENT_CLOSE, Op.BALANCING_MOMENT):
        return [f"{s.label} = −{lab[s.inputs[0]]} = {_f(float(v), 'N·m')}"]
    if s.op is Op.POLE:
        out = []
        if eq is not None:
            scale = f" (μF = {_f(mu_F, 'N/mm')})" if mu_F else ""
            out.append(f"Force polygon{scale}: {eq[0]}")
            out += [f"    {t}: {d}, {m}" for t, d, m in eq[1]]
        return out + [f"pole {s.label}"]
    if s.op is Op.FORCE_SUM:
        f = ev[s.inputs[1]][i]
        return [f"{lab[s.inputs[0]]}{s.label} = {lab[s.inputs[1]]} = {_polar(f)}{drawn(f)}"]
    if s.op is Op.FORCE_LINE:
        return [f"through {lab[s.inputs[0]]} draw {s.label}"]
    if s.op is Op.FORCE_CLOSE:
        return [f"the lines {lab[s.inputs[0]]} and {lab[s.inputs[1]]} meet at {s.label}"]
    if s.op is Op.DIFFERENCE:
        return [f"{s.label} = {lab[s.inputs[0]]}{lab[s.inputs[1]]} = {_polar(v)}{drawn(v)}"]
    if s.op is Op.GUIDE_OFFSET:
        d = float(v)
        text = f"{s.label} = {_f(d * 1000, 'mm')} (line of action of R_{s.label[2:]} along " \
            f"{s.subject[2]} from {s.subject[0]})"
        return [text]
    return []


def force_json(c: Construction, ev: Evaluation, mech: Mechanism, loading: Any) -> list[dict[str, Any]]:
    """The ``forces``/``reduced`` entries of every evaluated position, in order."""
    fa = analyse_forces(c, ev, mech, loading)
    return [fa.json(i) for i in range(ev.n)]


__all__ = ["ForceAnalysis", "Reaction", "analyse_forces", "balancing_force", "force_json",
           "force_text"]
