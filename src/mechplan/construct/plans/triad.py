"""Class III groups (triads): the position by solving the group, the velocity and acceleration plans
by Assur's special point S (the course's method).

S is where the lines of two legs, A_iB_i and A_jB_j, meet; as a point of the base link its velocity
relative to A_i is ⊥ A_iB_i (both v_{B_iA_i} and v_{SB_i} are) and relative to A_j ⊥ A_jB_j, so its
image s is where two lines through a_i and a_j meet. Then b_k = (through s ⊥ SB_k) ∩ (through a_k
⊥ A_kB_k), and the rest of the base link by similarity. Accelerations likewise, each line drawn
from the end of the normal components (a^n_{B_iA_i} then a^n_{SB_i}).
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.plans import Plan
from ...model.structure import Triad
from ..builder import Builder, Image, _with, alabel, vlabel
from ..ops import Op
from ..ops.triad import roots
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import GIVEN, from_to, perp
from . import images
from .acceleration import _epsilon, _normal, _tangential
from .position import _angle_of, complete
from .velocity import _omega, _relative

P, V, A = Plan.POSITION, Plan.VELOCITY, Plan.ACCELERATION


def special_name(b: Builder, g: Triad) -> str:
    """The name of the triad's special point: S, or S* when a link already has a point S."""
    taken = {p for lk in b.mech.links.values() for p in lk.points}
    return "S" if "S" not in taken else f"S*{g.base}"


def _legs(g: Triad) -> list[tuple[str, str, str]]:
    return [(leg, o.point, i.point) for leg, o, i in zip(g.legs, g.outer, g.inner, strict=True)]


def special_legs(b: Builder, g: Triad) -> tuple[int, int, int]:
    """Which legs' lines give S (i, j) and the third one (k), as chosen by the position plan."""
    legs = _legs(g)
    have = [n for n, (_, a, bb) in enumerate(legs) if f"pos.line.{a}{bb}" in b.c]
    i, j = have
    return i, j, 3 - i - j


# -- position -------------------------------------------------------------------------------------
def emit_position(b: Builder, g: Triad) -> None:
    """θ of the base link on the group's closure, B_1, the other points, and S."""
    mech = b.mech
    legs = _legs(g)
    base = mech.links[g.base]
    (x1, y1) = base.points[legs[0][2]]
    d = [(base.points[bb][0] - x1, base.points[bb][1] - y1) for _, _, bb in legs]
    lengths = [mech.links[leg].distance(a, bb) for leg, a, bb in legs]
    params = {"l1": lengths[0], "l2": lengths[1], "l3": lengths[2], "d2": d[1], "d3": d[2]}
    a_ids = tuple(b.pos[a] for _, a, _ in legs)
    sid = b.add(f"pos.angle.{g.base}", Op.TRIAD_ANGLE, a_ids, P, Kind.SCALAR, Role.RESULT,
                f"θ{g.base}", g.name, subject=tuple(a for _, a, _ in legs), sigma=1, slope=1,
                theta_ref=0.0, **params)
    sigma = _fix_branch(b, g, sid)
    b1 = legs[0][2]
    b.pos[b1] = b.add(f"pos.{b1}", Op.TRIAD_POINT, (a_ids[0], a_ids[1], sid), P, Kind.POINT,
                      Role.RESULT, b1, g.name, subject=(legs[0][1], legs[1][1], b1), sigma=sigma,
                      **params)
    body = b.bodies[g.base]
    body.angle, body.anchor = sid, b1
    b.result(f"angle_{g.base}", sid)
    complete(b, g.base, g.name)
    for leg, a, bb in legs:
        b.bodies[leg].anchor = a
        _angle_of(b, leg, a, bb, g.name)
        complete(b, leg, g.name)
    _special_point(b, g)


Candidate = tuple[float, int, int, dict[str, np.ndarray]]


def _candidates(b: Builder, g: Triad, sid: str) -> list[Candidate]:
    ev = b.c.evaluate(b.assembly_phi)
    step = b.c[sid]
    a = [ev[i] for i in step.inputs]
    legs = _legs(g)
    base = b.mech.links[g.base]
    (x1, y1) = base.points[legs[0][2]]
    out = []
    for sigma in (1, -1):
        for theta, slope in roots(a[0], a[1], a[2], step, sigma):
            b1 = Op.TRIAD_POINT.evaluate(_with(step, sigma=sigma), a[0], a[1],  # type: ignore[misc]
                                         np.array([theta]))[0][0]
            c, s = math.cos(theta), math.sin(theta)
            pts = {name: b1 + np.array([c * (x - x1) - s * (y - y1), s * (x - x1) + c * (y - y1)])
                   for name, (x, y) in base.points.items()}
            out.append((theta, sigma, slope, pts))
    return out


def _fix_branch(b: Builder, g: Triad, sid: str) -> int:
    """Choose the assembly among the closure's roots at the assembly angle from the sketch or the
    sides of the base link's points; return its arcs' branch."""
    cands = _candidates(b, g, sid)
    where = f"{math.degrees(b.assembly_phi):g}"
    if not cands:
        raise SceneError(Text(
            "errmsg2.plans.triad_unreachable",
            {"group": g.name, "phi": where}),
                         file=b.file, key="assembly")
    mech = b.mech
    base_pts = list(mech.links[g.base].points)
    ev = b.c.evaluate(b.assembly_phi)

    def score(pts: dict[str, np.ndarray]) -> float:
        total = 0.0
        for name in base_pts:
            if name in mech.sketch:
                total += float(np.linalg.norm(pts[name] - np.asarray(mech.sketch[name])))
            elif name in mech.sides:
                p, q, want = mech.sides[name]
                if not p:
                    continue
                at = {x: (pts[x] if x in pts else ev[b.pos[x]][0]) for x in (p, q)
                      if x in pts or x in b.pos}
                if len(at) < 2:
                    raise SceneError(Text(
                        "errmsg2.plans.triad_side",
                        {"point": name, "group": g.name, "base": g.base, "p": p, "q": q}),
                        file=b.file, key=f"assembly.{name}")
                u, w = at[q] - at[p], pts[name] - at[p]
                total += 0.0 if (u[0] * w[1] - u[1] * w[0]) * want > 0 else 1e6
        return total

    best = min(cands, key=lambda c: score(c[3]))
    theta, sigma, slope, _ = best
    b.c.steps[sid] = _with(b.c[sid], sigma=sigma, slope=slope, theta_ref=theta)
    return sigma


def _special_point(b: Builder, g: Triad) -> None:
    """Lines of the two legs crossing best at the assembly angle, and their meet S."""
    legs = _legs(g)
    ev = b.c.evaluate(b.assembly_phi)

    def crossing(i: int, j: int) -> float:
        u = [ev[b.pos[legs[n][2]]][0] - ev[b.pos[legs[n][1]]][0] for n in (i, j)]
        return abs(float(u[0][0] * u[1][1] - u[0][1] * u[1][0])) / max(
            float(np.linalg.norm(u[0]) * np.linalg.norm(u[1])), 1e-300)

    i, j = max(itertools.combinations(range(3), 2), key=lambda ij: crossing(*ij))
    lines = []
    for n in (i, j):
        _, a, bb = legs[n]
        lines.append(b.add(f"pos.line.{a}{bb}", Op.LINE_THROUGH, (b.pos[a], b.pos[bb]), P,
                           Kind.LINE, Role.AUXILIARY, f"{a}{bb}", g.name, subject=(a, bb)))
    name = special_name(b, g)
    b.pos[name] = b.add(f"pos.{name}", Op.LINE_LINE, tuple(lines), P, Kind.POINT, Role.AUXILIARY,
                        name, g.name, subject=(b.c[lines[0]].label, b.c[lines[1]].label))
    b.bodies[g.base].images.append(Image(name, name, b.pos[name]))


# -- velocity -------------------------------------------------------------------------------------
def emit_velocity(b: Builder, g: Triad) -> None:
    """s from a_i ⊥ A_iB_i and a_j ⊥ A_jB_j; b_k; ω of the base; its other points; ω of the legs."""
    legs = _legs(g)
    i, j, k = special_legs(b, g)
    name = special_name(b, g)
    gn = g.name
    (_, ai, bi), (_, aj, bj), (_, ak, bk) = legs[i], legs[j], legs[k]
    s = images.meet_lines(b, V, f"vel.{name}", images.perp_line(b, V, b.vel[ai], ai, bi, gn),
                          images.perp_line(b, V, b.vel[aj], aj, bj, gn), vlabel(name), gn,
                          Role.AUXILIARY)
    im = b.bodies[g.base].image(name)
    assert im is not None
    im.vel = s
    b.segment(V, images.pole(V), s, f"p{vlabel(name)}", f"v_{name}", SegmentKind.ABSOLUTE, gn)
    b.vel[bk] = images.meet_lines(b, V, f"vel.{bk}", images.perp_line(b, V, s, name, bk, gn),
                                  images.perp_line(b, V, b.vel[ak], ak, bk, gn), vlabel(bk), gn)
    _omega(b, g.base, name, b.pos[bk], s, b.vel[bk], gn)
    _relative(b, s, b.vel[bk], f"v_{bk}{name}", SegmentKind.RELATIVE, gn)
    _relative(b, b.vel[ak], b.vel[bk], f"v_{bk}{ak}", SegmentKind.RELATIVE, gn)
    images.absolute(b, bk, V, gn)
    images.complete(b, g.base, V, gn)
    for leg, a, bb in legs:
        _omega(b, leg, a, b.pos[bb], b.vel[a], b.vel[bb], gn)
        images.complete(b, leg, V, gn)
    b.c.equations[(V, f"{gn} {name}")] = (
        f"v_{name} = v_{ai} + v_{name}{ai} = v_{aj} + v_{name}{aj}", [
            (f"v_{ai}", GIVEN, "✓"), (f"v_{name}{ai}", perp(f"{ai}{bi}"), "?"),
            (f"v_{aj}", GIVEN, "✓"), (f"v_{name}{aj}", perp(f"{aj}{bj}"), "?")])
    b.c.equations[(V, f"{gn} {bk}")] = (
        f"v_{bk} = v_{name} + v_{bk}{name} = v_{ak} + v_{bk}{ak}", [
            (f"v_{name}", GIVEN, "✓"), (f"v_{bk}{name}", perp(f"{name}{bk}"), "?"),
            (f"v_{ak}", GIVEN, "✓"), (f"v_{bk}{ak}", perp(f"{ak}{bk}"), "?")])


# -- acceleration ---------------------------------------------------------------------------------
def emit_acceleration(b: Builder, g: Triad) -> None:
    """s′ from the ends of a^n_{B_iA_i} + a^n_{SB_i} (⊥ A_iB_i) and of the same for j; b_k′; ε."""
    legs = _legs(g)
    i, j, k = special_legs(b, g)
    name = special_name(b, g)
    gn = g.name
    normals: dict[str, str] = {}
    ends = []
    for n in (i, j):
        leg, a, bb = legs[n]
        normals[leg] = _normal(b, b.acc[a], leg, a, bb, bb, gn)
        ends.append(_normal(b, normals[leg], g.base, bb, name, name, gn))
    (_, ai, bi), (_, aj, bj), (lk, ak, bk) = legs[i], legs[j], legs[k]
    s = images.meet_lines(b, A, f"acc.{name}", images.perp_line(b, A, ends[0], ai, bi, gn),
                          images.perp_line(b, A, ends[1], aj, bj, gn), alabel(name), gn,
                          Role.AUXILIARY)
    im = b.bodies[g.base].image(name)
    assert im is not None
    im.acc = s
    b.segment(A, images.pole(A), s, f"π{alabel(name)}", f"a_{name}", SegmentKind.ABSOLUTE, gn)
    n_ks = _normal(b, s, g.base, name, bk, bk, gn)
    normals[lk] = _normal(b, b.acc[ak], lk, ak, bk, bk, gn)
    b.acc[bk] = images.meet_lines(b, A, f"acc.{bk}", images.perp_line(b, A, n_ks, name, bk, gn),
                                  images.perp_line(b, A, normals[lk], ak, bk, gn), alabel(bk), gn)
    _epsilon(b, g.base, name, b.pos[bk], n_ks, b.acc[bk], gn)
    _tangential(b, n_ks, b.acc[bk], f"a^t_{bk}{name}", gn)
    _tangential(b, normals[lk], b.acc[bk], f"a^t_{bk}{ak}", gn)
    images.absolute(b, bk, A, gn)
    images.complete(b, g.base, A, gn)
    for leg, a, bb in legs:
        _epsilon(b, leg, a, b.pos[bb], normals[leg], b.acc[bb], gn)
        images.complete(b, leg, A, gn)
    rows = []
    for n in (i, j):
        leg, a, bb = legs[n]
        rows += [(f"a_{a}", GIVEN, "✓"), (f"a^n_{bb}{a}", from_to(bb, a), f"ω{leg}²·l_{a}{bb}"),
                 (f"a^n_{name}{bb}", from_to(name, bb), f"ω{g.base}²·l_{bb}{name}"),
                 (f"a^t_{name}{a}", perp(f"{a}{bb}"), "?")]
    b.c.equations[(A, f"{gn} {name}")] = (
        (f"a_{name} = a_{ai} + a^n_{bi}{ai} + a^n_{name}{bi} + a^t_{name}{ai} = a_{aj} + "
        f"a^n_{bj}{aj} + a^n_{name}{bj} + a^t_{name}{aj}"), rows)
    b.c.equations[(A, f"{gn} {bk}")] = (
        (f"a_{bk} = a_{name} + a^n_{bk}{name} + a^t_{bk}{name} = a_{ak} + a^n_{bk}{ak} + "
        f"a^t_{bk}{ak}"), [
            (f"a_{name}", GIVEN, "✓"), (f"a^n_{bk}{name}", from_to(bk, name),
                                        f"ω{g.base}²·l_{name}{bk}"),
            (f"a^t_{bk}{name}", perp(f"{name}{bk}"), "?"), (f"a_{ak}", GIVEN, "✓"),
            (f"a^n_{bk}{ak}", from_to(bk, ak), f"ω{lk}²·l_{ak}{bk}"),
            (f"a^t_{bk}{ak}", perp(f"{ak}{bk}"), "?")])


__all__ = ["emit_acceleration", "emit_position", "emit_velocity", "special_legs",
           "special_name"]
