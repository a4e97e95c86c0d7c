"""Class III groups whose legs slide on known guides: the position by solving the group, the
velocity and acceleration plans by Assur's special point S.

A leg either has two revolute pairs (A_i on a known link, B_i on the base link: B_i moves on the
arc (A_i, l_i) relative to A_i) or is a slider on a guide of a known link m_i pinned to the base at
B_i (B_i moves on the guide's line relative to m_i). The unknown relative velocity of B_i is ⊥
A_iB_i or ∥ the guide; the leg's line for S is A_iB_i or the normal to the guide at B_i, so that
as a point of the base link S's velocity relative to the known image (a_i, or the image of the
point of m_i under B_i) has that same unknown direction: s is where two lines through known
images meet. Then b_k, the rest of the base link by similarity, the legs. Accelerations likewise
from the ends of the normal (and, on a turning guide, Coriolis) components.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.mechanism import GROUND, Pair, PairKind
from ...model.plans import Plan
from ...model.structure import Triad
from ..builder import Builder, Image, _with, alabel, vlabel
from ..ops import Op
from ..ops.triadp import roots
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import GIVEN, Row, from_to, parallel, perp
from . import images
from .acceleration import _coriolis, _epsilon, _normal, _tangential
from .position import _angle_of, angle_from_pair, complete, locus, locus_id
from .triad import special_name
from .velocity import _omega, _relative

P, V, A = Plan.POSITION, Plan.VELOCITY, Plan.ACCELERATION


@dataclass(frozen=True, slots=True)
class Leg:
    """A leg: its link, outer point (A_i; a slider leg: B_i), inner point B_i, outer pair, the
    known link it joins and whether it slides on that link's guide."""

    link: str
    a: str
    b: str
    pair: Pair
    known: str
    inner: Pair

    @property
    def slides(self) -> bool:
        """A slider on the known link's guide, pinned to the base link at B_i."""
        return self.pair.kind is PairKind.PRISMATIC

    @property
    def block(self) -> bool:
        """A block pinned to the known link at A_i, sliding on a guide of the base link."""
        return self.inner.kind is PairKind.PRISMATIC

    @property
    def guided(self) -> bool:
        return self.slides or self.block

    @property
    def guide_pair(self) -> Pair:
        return self.inner if self.block else self.pair


def legs(g: Triad) -> list[Leg]:
    """The group's legs in its order."""
    return [Leg(leg, o.point, i.point, o, o.other(leg), i)
            for leg, o, i in zip(g.legs, g.outer, g.inner, strict=True)]


def _locus(b: Builder, leg: Leg) -> str:
    return locus_id(leg.link, leg.b, leg.guide_pair.guide)


def base_key(g: Triad, lg: Leg) -> str:
    """The image key of the base link's point under a block leg's pin (``A@3``)."""
    return f"{lg.a}@{g.base}"


def special_legs(b: Builder, g: Triad) -> tuple[int, int, int]:
    """Which legs' lines give S (i, j) and the third one (k), as the position plan chose."""
    have = [n for n, lg in enumerate(legs(g)) if f"pos.line.{g.name}.{lg.b}" in b.c]
    i, j = have
    return i, j, 3 - i - j


# -- position -------------------------------------------------------------------------------------
def emit_position(b: Builder, g: Triad) -> None:
    """Slider legs' guide lines, θ of the base link on the closure, B_1, the rest, and S."""
    mech = b.mech
    ls = legs(g)
    loci: list[str] = []
    for lg in ls:
        if lg.slides:
            angle_from_pair(b, lg.link, lg.pair, lg.known, g.name)
            loci.append(locus(b, lg.link, lg.b, lg.pair, lg.known, g.name))
        else:
            loci.append(b.pos[lg.a])
    # arcs first, then the known guides' lines, a block on the base link's guide last
    order = sorted(range(3), key=lambda n: 2 if ls[n].block else int(ls[n].slides))
    base = mech.links[g.base]
    first = ls[order[0]].b
    (x1, y1) = base.points[first]
    d = [(0.0, 0.0) if ls[n].block else
         (base.points[ls[n].b][0] - x1, base.points[ls[n].b][1] - y1) for n in order]
    lengths = [0.0 if ls[n].guided else mech.links[ls[n].link].distance(ls[n].a, ls[n].b)
               for n in order]
    kinds = "".join("Q" if ls[n].block else "P" if ls[n].slides else "R" for n in order)
    params: dict[str, object] = {"kinds": kinds, "l": tuple(lengths), "d2": d[1], "d3": d[2]}
    if ls[order[2]].block:
        gd = b.guide_of(ls[order[2]].inner)
        params.update(q=(gd.origin[0] - x1, gd.origin[1] - y1), q_angle=gd.angle)
    inputs = tuple(loci[n] for n in order)
    subject = tuple(b.c[s].label for s in inputs)
    sid = b.add(f"pos.angle.{g.base}", Op.TRIADP_ANGLE, inputs, P, Kind.SCALAR, Role.RESULT,
                f"θ{g.base}", g.name, subject=subject, sigma=1, slope=1, theta_ref=0.0,
                **params)
    sigma = _fix_branch(b, g, sid, first)
    b.pos[first] = b.add(f"pos.{first}", Op.TRIADP_POINT, (inputs[0], inputs[1], sid), P,
                         Kind.POINT, Role.RESULT, first, g.name,
                         subject=(subject[0], subject[1], first), sigma=sigma, **params)
    body = b.bodies[g.base]
    body.angle, body.anchor = sid, first
    b.result(f"angle_{g.base}", sid)
    complete(b, g.base, g.name)
    for lg in ls:
        if lg.slides:
            b.bodies[lg.link].anchor = lg.b
        elif lg.block:
            angle_from_pair(b, lg.link, lg.inner, g.base, g.name)
            b.bodies[lg.link].anchor = lg.a
            locus(b, lg.link, lg.a, lg.inner, g.base, g.name)
        else:
            b.bodies[lg.link].anchor = lg.a
            _angle_of(b, lg.link, lg.a, lg.b, g.name)
        complete(b, lg.link, g.name)
    _special_point(b, g)


def _fix_branch(b: Builder, g: Triad, sid: str, first: str) -> int:
    """Choose the assembly among the closure's roots at the assembly angle (the sketch or the
    sides of the base link's points); return the branch of the first two loci's meet."""
    ev = b.c.evaluate(b.assembly_phi)
    step = b.c[sid]
    loci = [ev[i] for i in step.inputs]
    base = b.mech.links[g.base]
    (x1, y1) = base.points[first]
    cands = []
    for sigma in ((1, -1) if "R" in str(step.param("kinds"))[:2] else (1,)):
        for theta, slope in roots(loci[0], loci[1], loci[2], step, sigma):
            b1 = Op.TRIADP_POINT.evaluate(_with(step, sigma=sigma),  # type: ignore[misc]
                                          loci[0], loci[1], np.array([theta]))[0][0]
            c, s = math.cos(theta), math.sin(theta)
            pts = {name: b1 + np.array([c * (x - x1) - s * (y - y1), s * (x - x1) + c * (y - y1)])
                   for name, (x, y) in base.points.items()}
            cands.append((theta, sigma, slope, pts))
    if not cands:
        raise SceneError(Text("errmsg2.plans.triad_unreachable",
                              {"group": g.name, "phi": f"{math.degrees(b.assembly_phi):g}"}),
                         file=b.file, key="assembly")
    mech = b.mech

    def score(pts: dict[str, np.ndarray]) -> float:
        total = 0.0
        for name, at in pts.items():
            if name in mech.sketch:
                total += float(np.linalg.norm(at - np.asarray(mech.sketch[name])))
            elif name in mech.sides:
                p, q, want = mech.sides[name]
                if not p:
                    continue
                ends = {x: (pts[x] if x in pts else ev[b.pos[x]][0]) for x in (p, q)
                        if x in pts or x in b.pos}
                if len(ends) < 2:
                    raise SceneError(Text(
                        "errmsg2.plans.triad_side",
                        {"point": name, "group": g.name, "base": g.base, "p": p, "q": q}),
                        file=b.file, key=f"assembly.{name}")
                u, w = ends[q] - ends[p], at - ends[p]
                total += 0.0 if (u[0] * w[1] - u[1] * w[0]) * want > 0 else 1e6
        return total

    theta, sigma, slope, _ = min(cands, key=lambda c: score(c[3]))
    b.c.steps[sid] = _with(step, sigma=sigma, slope=slope, theta_ref=theta)
    return sigma


def _special_point(b: Builder, g: Triad) -> None:
    """The legs' lines (A_iB_i, or the normal to the guide at B_i) crossing best at the
    assembly, and their meet S."""
    ls = legs(g)
    ev = b.c.evaluate(b.assembly_phi)

    def direction(lg: Leg) -> np.ndarray:
        if lg.guided:
            u = ev[_locus(b, lg)][0][1]
            return np.array([-u[1], u[0]])
        d = ev[b.pos[lg.b]][0] - ev[b.pos[lg.a]][0]
        return np.asarray(d / max(float(np.linalg.norm(d)), 1e-300))

    def crossing(i: int, j: int) -> float:
        u, w = direction(ls[i]), direction(ls[j])
        return abs(float(u[0] * w[1] - u[1] * w[0]))

    i, j = max(itertools.combinations(range(3), 2), key=lambda ij: crossing(*ij))
    lines = []
    for lg in (ls[i], ls[j]):
        sid = f"pos.line.{g.name}.{lg.b}"
        if lg.guided:
            lines.append(b.add(sid, Op.NORMAL_THROUGH, (b.pos[lg.b], _locus(b, lg)), P,
                               Kind.LINE, Role.AUXILIARY, f"n{lg.b}", g.name,
                               subject=(lg.b, b.c[_locus(b, lg)].label)))
        else:
            lines.append(b.add(sid, Op.LINE_THROUGH, (b.pos[lg.a], b.pos[lg.b]), P, Kind.LINE,
                               Role.AUXILIARY, f"{lg.a}{lg.b}", g.name, subject=(lg.a, lg.b)))
    name = special_name(b, g)
    b.pos[name] = b.add(f"pos.{name}", Op.LINE_LINE, tuple(lines), P, Kind.POINT,
                        Role.AUXILIARY, name, g.name,
                        subject=(b.c[lines[0]].label, b.c[lines[1]].label))
    b.bodies[g.base].images.append(Image(name, name, b.pos[name]))


# -- velocity -------------------------------------------------------------------------------------
def _vel_line(b: Builder, lg: Leg, through: str, gn: str) -> str:
    """Through a known image, the line of the leg's unknown relative velocity."""
    if lg.guided:
        return images.parallel_line(b, V, through, _locus(b, lg), gn)
    return images.perp_line(b, V, through, lg.a, lg.b, gn)


def _vel_start(b: Builder, lg: Leg, gn: str) -> str:
    """The known image the leg's relative velocity starts from: a_i, or B_i on the guide's link."""
    if lg.slides:
        return images.coincident(b, lg.known, lg.b, V, gn)
    return b.vel[lg.a]         # a revolute leg's A_i, a block's pin


def _vel_rows(b: Builder, lg: Leg, target: str) -> tuple[str, list[Row]]:
    """The leg's side of a velocity equation for ``target`` (S or B_k) and its table rows; a
    slider on the frame gives B_k's velocity itself (empty side, one row ∥ the guide)."""
    if lg.block:
        guide = b.c[_locus(b, lg)].label
        return (f"v_{lg.a} + v_{target}{lg.a}",
                [(f"v_{lg.a}", GIVEN, "✓"), (f"v_{target}{lg.a}", parallel(guide), "?")])
    if lg.slides:
        guide = b.c[_locus(b, lg)].label
        bb = lg.b
        if lg.known == GROUND:
            if target == bb:
                return ("", [(f"v_{bb}", parallel(guide), "?")])
            side = f"v_{bb} + v_{target}{bb}"
            return (side, [(side, parallel(guide), "?")])
        start = f"{bb}{lg.known}"
        rel = f"v_{bb}{lg.link}{start}" if target == bb else f"v_{target}{start}"
        return (f"v_{start} + {rel}",
                [(f"v_{start}", GIVEN, "✓"), (rel, parallel(guide), "?")])
    return (f"v_{lg.a} + v_{target}{lg.a}",
            [(f"v_{lg.a}", GIVEN, "✓"), (f"v_{target}{lg.a}", perp(f"{lg.a}{lg.b}"), "?")])


def _chain(*sides: str) -> str:
    return " = ".join(x for x in sides if x)


def emit_velocity(b: Builder, g: Triad) -> None:
    """s from the legs i, j; b_k; ω of the base; its other points; the legs (ω, sliding)."""
    ls = legs(g)
    i, j, k = special_legs(b, g)
    name = special_name(b, g)
    gn = g.name
    li, lj, lk = ls[i], ls[j], ls[k]
    s = images.meet_lines(b, V, f"vel.{name}", _vel_line(b, li, _vel_start(b, li, gn), gn),
                          _vel_line(b, lj, _vel_start(b, lj, gn), gn), vlabel(name), gn,
                          Role.AUXILIARY)
    im = b.bodies[g.base].image(name)
    assert im is not None
    im.vel = s
    b.segment(V, images.pole(V), s, f"p{vlabel(name)}", f"v_{name}", SegmentKind.ABSOLUTE, gn)
    bk = lk.b
    start_k = _vel_start(b, lk, gn)
    bk_name = f"{bk}{g.base}" if lk.block else bk
    if lk.block:        # the base link's point under the block's pin
        key = base_key(g, lk)
        label = (vlabel(bk) + g.base) if not any(ch.isdigit() for ch in bk) \
            else f"{vlabel(bk)}_{g.base}"
        vk = images.meet_lines(b, V, f"vel.{key}", images.perp_line(b, V, s, name, bk, gn),
                               _vel_line(b, lk, start_k, gn), label, gn)
        b.bodies[g.base].images.append(Image(key, bk_name, b.pos[bk], vel=vk))
        b.segment(V, images.pole(V), vk, f"p{label}", f"v_{bk_name}", SegmentKind.ABSOLUTE, gn)
    else:
        vk = b.vel[bk] = images.meet_lines(
            b, V, f"vel.{bk}", images.perp_line(b, V, s, name, bk, gn),
            _vel_line(b, lk, start_k, gn), vlabel(bk), gn)
        images.absolute(b, bk, V, gn)
    _omega(b, g.base, name, b.pos[bk], s, vk, gn)
    _relative(b, s, vk, f"v_{bk_name}{name}", SegmentKind.RELATIVE, gn)
    images.complete(b, g.base, V, gn)
    for lg in ls:
        start = _vel_start(b, lg, gn)
        if lg.block:
            images.link_scalar(b, lg.link, g.base, V, gn)
            on_base = images.coincident(b, g.base, lg.a, V, gn)
            if lg is not lk:
                b.segment(V, images.pole(V), on_base, f"p{b.c[on_base].label}",
                          f"v_{lg.a}{g.base}", SegmentKind.ABSOLUTE, gn)
            _relative(b, on_base, start, f"v_{lg.a}{lg.link}{lg.a}{g.base}",
                      SegmentKind.SLIDING, gn)
        elif lg.slides:
            images.link_scalar(b, lg.link, lg.known, V, gn)
            if lg.known != GROUND:
                # the point of the guide's link under B_i: its absolute velocity, then the
                # sliding velocity to b_i
                b.segment(V, images.pole(V), start, f"p{b.c[start].label}",
                          f"v_{lg.b}{lg.known}", SegmentKind.ABSOLUTE, gn)
                _relative(b, start, b.vel[lg.b], f"v_{lg.b}{lg.link}{lg.b}{lg.known}",
                          SegmentKind.SLIDING, gn)
        else:
            _omega(b, lg.link, lg.a, b.pos[lg.b], b.vel[lg.a], b.vel[lg.b], gn)
            _relative(b, start, b.vel[lg.b], f"v_{lg.b}{lg.a}", SegmentKind.RELATIVE, gn)
        images.complete(b, lg.link, V, gn)
    ei, ri = _vel_rows(b, li, name)
    ej, rj = _vel_rows(b, lj, name)
    b.c.equations[(V, f"{gn} {name}")] = (_chain(f"v_{name}", ei, ej), ri + rj)
    ek, rk = _vel_rows(b, lk, bk_name)
    b.c.equations[(V, f"{gn} {bk}")] = (
        _chain(f"v_{bk_name}", f"v_{name} + v_{bk_name}{name}", ek),
        [(f"v_{name}", GIVEN, "✓"), (f"v_{bk_name}{name}", perp(f"{name}{bk}"), "?"), *rk])


# -- acceleration ---------------------------------------------------------------------------------
def _acc_start(b: Builder, lg: Leg, gn: str) -> str:
    """The end of the known components of B_i's acceleration relative to the leg's known link:
    a_i + a^n_{B_iA_i}, or the image of B_i on the guide's link + Coriolis."""
    if lg.block:        # a_A + 2ω_base × (v of the base's point under A − v_A)
        on_base = images.coincident(b, g_base(b, lg), lg.a, V, gn)
        return _coriolis(b, b.acc[lg.a], g_base(b, lg), b.vel[lg.a], on_base,
                         f"{lg.a}{g_base(b, lg)}{lg.a}{lg.link}", gn)
    if lg.slides:
        km = images.coincident(b, lg.known, lg.b, A, gn)
        kv = images.coincident(b, lg.known, lg.b, V, gn)
        return _coriolis(b, km, lg.known, kv, b.vel[lg.b], f"{lg.b}{lg.link}{lg.b}{lg.known}",
                         gn)
    return _normal(b, b.acc[lg.a], lg.link, lg.a, lg.b, lg.b, gn)


def g_base(b: Builder, lg: Leg) -> str:
    """The base link a block leg slides on (the carrier of its guide)."""
    return lg.inner.b


def _acc_line(b: Builder, lg: Leg, through: str, gn: str) -> str:
    if lg.guided:
        return images.parallel_line(b, A, through, _locus(b, lg), gn)
    return images.perp_line(b, A, through, lg.a, lg.b, gn)


def _acc_rows(b: Builder, lg: Leg, target: str) -> tuple[str, list[Row]]:
    """The leg's side of an acceleration equation for ``target`` (B_k, or S with the base link's
    normal component added by the caller); its unknown tangential (or relative) parts, of one
    direction, make one row as the courses write them."""
    if lg.block:
        guide = b.c[_locus(b, lg)].label
        a, leg, base = lg.a, lg.link, g_base(b, lg)
        cor, unknown = f"a^k_{a}{base}{a}{leg}", f"a^r_{target}{a}"
        return (f"a_{a} + {cor} + {unknown}",
                [(f"a_{a}", GIVEN, "✓"), (cor, perp(guide), f"2ω{base}·v_{a}{leg}{a}{base}"),
                 (unknown, parallel(guide), "?")])
    if lg.slides:
        guide = b.c[_locus(b, lg)].label
        m, bb, leg = lg.known, lg.b, lg.link
        unknown = (f"a^r_{target}" if m == GROUND else f"a^r_{target}{leg}{bb}{m}")
        if m == GROUND:
            if target == bb:       # B_k on a frame guide: its acceleration is along it
                return ("", [(f"a_{bb}", parallel(guide), "?")])
            return (unknown, [(unknown, parallel(guide), "?")])
        return (f"a_{bb}{m} + a^k_{bb}{leg}{bb}{m} + {unknown}",
                [(f"a_{bb}{m}", GIVEN, "✓"),
                 (f"a^k_{bb}{leg}{bb}{m}", perp(guide), f"2ω{m}·v_{bb}{leg}{bb}{m}"),
                 (unknown, parallel(guide), "?")])
    a, bb, leg = lg.a, lg.b, lg.link
    return (f"a_{a} + a^n_{bb}{a} + a^t_{target}{a}",
            [(f"a_{a}", GIVEN, "✓"), (f"a^n_{bb}{a}", from_to(bb, a), f"ω{leg}²·l_{a}{bb}"),
             (f"a^t_{target}{a}", perp(f"{a}{bb}"), "?")])


def emit_acceleration(b: Builder, g: Triad) -> None:
    """s′ from the legs i, j (each: its known components, then a^n_{SB}); b_k′; ε."""
    ls = legs(g)
    i, j, k = special_legs(b, g)
    name = special_name(b, g)
    gn = g.name
    starts = {n: _acc_start(b, ls[n], gn) for n in range(3)}
    ends = [_normal(b, starts[n], g.base, ls[n].b, name, name, gn) for n in (i, j)]
    s = images.meet_lines(b, A, f"acc.{name}", _acc_line(b, ls[i], ends[0], gn),
                          _acc_line(b, ls[j], ends[1], gn), alabel(name), gn, Role.AUXILIARY)
    im = b.bodies[g.base].image(name)
    assert im is not None
    im.acc = s
    b.segment(A, images.pole(A), s, f"π{alabel(name)}", f"a_{name}", SegmentKind.ABSOLUTE, gn)
    lk = ls[k]
    bk = lk.b
    bk_name = f"{bk}{g.base}" if lk.block else bk
    n_ks = _normal(b, s, g.base, name, bk, bk, gn)
    if lk.block:
        key = base_key(g, lk)
        label = ((vlabel(bk) + g.base) if not any(ch.isdigit() for ch in bk)
                 else f"{vlabel(bk)}_{g.base}") + "′"
        ak = images.meet_lines(b, A, f"acc.{key}", images.perp_line(b, A, n_ks, name, bk, gn),
                               _acc_line(b, lk, starts[k], gn), label, gn)
        img = b.bodies[g.base].image(key)
        assert img is not None
        img.acc = ak
        b.segment(A, images.pole(A), ak, f"π{label}", f"a_{bk_name}", SegmentKind.ABSOLUTE, gn)
    else:
        ak = b.acc[bk] = images.meet_lines(
            b, A, f"acc.{bk}", images.perp_line(b, A, n_ks, name, bk, gn),
            _acc_line(b, lk, starts[k], gn), alabel(bk), gn)
        images.absolute(b, bk, A, gn)
    _epsilon(b, g.base, name, b.pos[bk], n_ks, ak, gn)
    _tangential(b, n_ks, ak, f"a^t_{bk_name}{name}", gn)
    images.complete(b, g.base, A, gn)
    for n, lg in enumerate(ls):
        if lg.block:
            images.link_scalar(b, lg.link, g.base, A, gn)
        elif lg.slides:
            images.link_scalar(b, lg.link, lg.known, A, gn)
            if lg.known != GROUND:
                b.segment(A, starts[n], b.acc[lg.b],
                          f"{b.c[starts[n]].label} {b.c[b.acc[lg.b]].label}",
                          f"a^r_{lg.b}{lg.link}{lg.b}{lg.known}", SegmentKind.SLIDING, gn)
        else:
            _epsilon(b, lg.link, lg.a, b.pos[lg.b], starts[n], b.acc[lg.b], gn)
            _tangential(b, starts[n], b.acc[lg.b], f"a^t_{lg.b}{lg.a}", gn)
        images.complete(b, lg.link, A, gn)
    rows: list[Row] = []
    eqs = []
    for n in (i, j):
        e, r = _acc_rows(b, ls[n], name)
        bb = ls[n].b
        head, last = e.rsplit(" + ", 1) if " + " in e else ("", e)
        eqs.append(" + ".join(x for x in (head, f"a^n_{name}{bb}", last) if x))
        rows += r[:-1] + [(f"a^n_{name}{bb}", from_to(name, bb), f"ω{g.base}²·l_{bb}{name}"),
                          r[-1]]
    b.c.equations[(A, f"{gn} {name}")] = (f"a_{name} = {eqs[0]} = {eqs[1]}", rows)
    ek, rk = _acc_rows(b, lk, bk_name)
    b.c.equations[(A, f"{gn} {bk}")] = (
        _chain(f"a_{bk_name}", f"a_{name} + a^n_{bk_name}{name} + a^t_{bk_name}{name}", ek),
        [(f"a_{name}", GIVEN, "✓"), (f"a^n_{bk_name}{name}", from_to(bk, name),
                                     f"ω{g.base}²·l_{name}{bk}"),
         (f"a^t_{bk_name}{name}", perp(f"{name}{bk}"), "?"), *rk])


__all__ = ["emit_acceleration", "emit_position", "emit_velocity", "legs", "special_legs"]
