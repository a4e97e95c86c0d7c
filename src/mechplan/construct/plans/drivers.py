"""The linear drivers' plans: a slider driven on a frame guide and a cylinder of driven length.

A slider driver is a first-class mechanism I(0,k) like a crank: its point at q along the guide,
its velocity q̇ and acceleration q̈ along the guide. A cylinder (barrel and rod, their prismatic
pair driven) is a link of known length l = q between its two pins; the group it closes with the
link it drives is built like an RRR dyad whose one side is the cylinder:

* position: arcs of radius l_{P1K} about P1 and of radius l(q) about the cylinder's known end E
  meet at K;
* velocity: v_K = v_E + v_rel + v_KE (⊥ EK) = v_P1 + v_KP1 (⊥ P1K), v_rel = l̇ along E→K;
* acceleration: a_K = a_E + a^n_KE + a^k + a^r + a^t_KE (⊥ EK) = a_P1 + a^n_KP1 + a^t_KP1
  (⊥ P1K), a^k = 2ω_c × v_rel (Coriolis), a^r = l̈ along E→K,

where ω_c is the cylinder's angular velocity (barrel and rod turn together). Whichever end is the
barrel's pivot, the rod extending by l̇ moves K away from E: the rates are laid along E→K.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...i18n import Text
from ...model.mechanism import GROUND, Drive, DriverKind, Pair, PairKind
from ...model.plans import Plan
from ...model.structure import Group, GroupKind
from ..builder import Builder, alabel, vlabel
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import GIVEN, Row, from_to, parallel, perp
from . import acceleration, images, position, velocity

P, V, A = Plan.POSITION, Plan.VELOCITY, Plan.ACCELERATION


@dataclass(frozen=True, slots=True)
class Cylinder:
    """A driving cylinder: its barrel, rod, driver and the suffix of its steps ("" or "2")."""

    barrel: str
    rod: str
    drive: Drive
    tag: str

    @property
    def group(self) -> str:
        """Its first-class mechanism in the structure formula, ``I(barrel,rod)``."""
        return f"I({self.barrel},{self.rod})"


def cylinders(b: Builder) -> list[Cylinder]:
    """The driving cylinders: the first driver's and (W = 2) the second's."""
    out = []
    if b.structure.cylinder is not None:
        out.append(Cylinder(*b.structure.cylinder, b.mech.drive, ""))
    if b.structure.cylinder2 is not None and b.mech.drive2 is not None:
        out.append(Cylinder(*b.structure.cylinder2, b.mech.drive2, "2"))
    return out


def cylinder_of(b: Builder, g: Group) -> Cylinder | None:
    """The driving cylinder that closes a group (None for a usual dyad)."""
    return next((c for c in cylinders(b) if c.barrel in g.links), None)


def cylinder_in(b: Builder, g: Group) -> bool:
    """Tell whether a group is closed by a cylinder driver."""
    return cylinder_of(b, g) is not None


def first_group(b: Builder) -> str:
    """The name of the first-class mechanism in the structure formula: I(0,k) or I(barrel,rod)."""
    cyl = b.structure.cylinder
    return f"I({cyl[0]},{cyl[1]})" if cyl else f"I({GROUND},{b.mech.drive.link})"


def _sides(b: Builder, g: Group) -> tuple[str, str, str, str, str]:
    """(partner link, its outer point P1, the cylinder's known end E, the inner point K, barrel).

    The cylinder (barrel and rod, pinned at both ends) is the group's R–R side of driven length;
    the partner's outer pair is a revolute (RRR: P1 its pin) or a prismatic pair (RRP: the
    partner slides on a known link's guide, P1 its sliding point) — see :func:`partner_pair`.
    """
    cyl = cylinder_of(b, g)
    assert cyl is not None
    barrel = cyl.barrel
    if g.kind not in (GroupKind.RRR, GroupKind.RRP):
        raise _unsupported(b, g)
    if g.links[1] == barrel:
        return g.links[0], g.outer1.point, g.outer2.point, g.inner.point, barrel
    return g.links[1], g.outer2.point, g.outer1.point, g.inner.point, barrel


def partner_pair(g: Group, partner: str) -> Pair:
    """The outer pair of the link a cylinder drives in its group (revolute or prismatic)."""
    return g.outer1 if g.links[0] == partner else g.outer2


def _unsupported(b: Builder, g: Group) -> Exception:
    from ...errors import TopologyError

    cyl = cylinder_of(b, g)
    assert cyl is not None
    return TopologyError(Text(
        "errmsg2.plans.cylinder_group",
        {"barrel": cyl.barrel, "rod": cyl.rod, "group": g.name, "kind": g.kind.value}),
                         key="drive.link" if not cyl.tag else "drive2.link")


# -- the driver itself ----------------------------------------------------------------------------
def emit_linear_position(b: Builder) -> None:
    """The driver's coordinate and, for a slider, its points on the frame guide."""
    drive = b.mech.drive
    symbol = "l" if drive.kind is DriverKind.CYLINDER else "s"
    b.add("pos.q", Op.DRIVER_COORDINATE, (), P, Kind.SCALAR, Role.GIVEN,
          f"{symbol}{drive.link}", first_group(b))
    if drive.kind is not DriverKind.SLIDER:
        return
    assert drive.guide is not None
    guide = b.mech.guides[drive.guide]
    group = first_group(b)
    pair = next(p for p in b.mech.pairs_of(drive.link) if p.other(drive.link) == GROUND)
    b.pos[drive.pivot] = b.add(f"pos.{drive.pivot}", Op.GUIDE_POINT,
                               (b.pos[guide.through], "pos.q"), P, Kind.POINT, Role.RESULT,
                               drive.pivot, group, subject=(guide.through, drive.pivot),
                               dir_angle=guide.angle)
    position.angle_from_pair(b, drive.link, pair, GROUND, group)
    b.bodies[drive.link].anchor = drive.pivot
    position.complete(b, drive.link, group)


def _rate(b: Builder, plan: Plan) -> str:
    drive = b.mech.drive
    dot = "̇" if plan is V else "̈"
    symbol = ("l" if drive.kind is DriverKind.CYLINDER else "s") + dot
    value = drive.omega if plan is V else drive.epsilon
    prefix = "vel" if plan is V else "acc"
    if drive.law is not None:       # by a table over time: its spline at the position's time
        from .laws import law_step

        return law_step(b, f"{prefix}.rate", drive, 1 if plan is V else 2, plan,
                        f"{symbol}{drive.link}", first_group(b))
    return b.add(f"{prefix}.rate", Op.DRIVER_RATE, (), plan, Kind.SCALAR, Role.GIVEN,
                 f"{symbol}{drive.link}", first_group(b), value=value)


def emit_linear_plan(b: Builder, plan: Plan) -> None:
    """Pole, frame images, the driver's rate and (a slider) the image of its point."""
    sid = images.pole(plan)
    b.add(sid, Op.POLE, (), plan, Kind.POINT, Role.GIVEN, "p" if plan is V else "π")
    table, sym = (b.vel, "v") if plan is V else (b.acc, "a")
    for name in b.mech.links[GROUND].points:
        table[name] = sid
        b.result(f"{sym}_{name}", sid)
    rate = _rate(b, plan)
    drive = b.mech.drive
    if drive.kind is not DriverKind.SLIDER:
        return
    assert drive.guide is not None
    guide = b.mech.guides[drive.guide]
    group = first_group(b)
    x = drive.pivot
    label = vlabel(x) if plan is V else alabel(x)
    prefix = "vel" if plan is V else "acc"
    table[x] = b.add(f"{prefix}.{x}", Op.GUIDE_VECTOR, (sid, rate), plan, Kind.POINT,
                     Role.RESULT, label, group, subject=(guide.name, x), dir_angle=guide.angle)
    images.link_scalar(b, drive.link, GROUND, plan, group)
    images.absolute(b, x, plan, group)
    what = "v" if plan is V else "a"
    b.c.equations[(plan, group)] = (f"{what}_{x} = {b.c[rate].label}",
                                    [(f"{what}_{x}", parallel(guide.name), b.c[rate].label)])
    images.complete(b, drive.link, plan, group)


# -- the groups: the cylinder's, or the usual dyads ---------------------------------------------
def position_group(b: Builder, g: Group) -> None:
    """Position construction of a group (the cylinder's group by two compass arcs)."""
    if not cylinder_in(b, g):
        position.emit_group(b, g)
        return
    cyl = cylinder_of(b, g)
    assert cyl is not None
    partner, p1, e, k, barrel = _sides(b, g)
    rod, drive = cyl.rod, cyl.drive
    outer = partner_pair(g, partner)
    if outer.kind is PairKind.REVOLUTE:     # two arcs: about P1 and of the driven length
        r1 = b.mech.links[partner].distance(p1, k)
        sid = b.add(f"pos.{k}", Op.CIRCLE_CIRCLE_DRIVEN, (b.pos[p1], b.pos[e],
                                                          f"pos.q{cyl.tag}"), P,
                    Kind.POINT, Role.RESULT, k, g.name, subject=(p1, e, k), r1=r1, sigma=1)
    else:           # the partner slides on a guide: the arc of driven length cuts K's line
        carrier = outer.other(partner)
        position.angle_from_pair(b, partner, outer, carrier, g.name)
        line = position.locus(b, partner, k, outer, carrier, g.name)
        sid = b.add(f"pos.{k}", Op.CIRCLE_LINE_DRIVEN, (b.pos[e], line, f"pos.q{cyl.tag}"), P,
                    Kind.POINT, Role.RESULT, k, g.name,
                    subject=(e, b.c[line].label, k), sigma=1)
    b.pos[k] = sid
    b.resolve_branch(sid, k, g.name, sid)
    if outer.kind is PairKind.REVOLUTE:
        b.bodies[partner].anchor = p1
        _angle_of(b, partner, p1, k, g.name)
    else:
        b.bodies[partner].anchor = k
    # the barrel's axis runs from its pivot to the rod's pin along its guide
    assert drive.guide is not None
    guide = b.mech.guides[drive.guide]
    pivot, pin = guide.through, drive.pivot
    body = b.bodies[barrel]
    body.anchor = pivot
    body.angle = b.add(f"pos.angle.{barrel}", Op.ANGLE_OF, (b.pos[pivot], b.pos[pin]), P,
                       Kind.SCALAR, Role.AUXILIARY, f"θ{barrel}", g.name, subject=(pivot, pin),
                       minus=guide.angle)
    b.result(f"angle_{barrel}", body.angle)
    pair = next(p for p in b.mech.pairs_of(rod) if p.kind.value == "P" and p.b == barrel)
    position.angle_from_pair(b, rod, pair, barrel, g.name)
    b.bodies[rod].anchor = pin
    for link in (partner, barrel, rod):
        position.complete(b, link, g.name)


def _angle_of(b: Builder, link: str, p: str, q: str, group: str) -> None:
    (x1, y1), (x2, y2) = b.mech.links[link].points[p], b.mech.links[link].points[q]
    body = b.bodies[link]
    body.angle = b.add(f"pos.angle.{link}", Op.ANGLE_OF, (b.pos[p], b.pos[q]), P, Kind.SCALAR,
                       Role.AUXILIARY, f"θ{link}", group, subject=(p, q),
                       minus=math.atan2(y2 - y1, x2 - x1))
    b.result(f"angle_{link}", body.angle)


def velocity_group(b: Builder, g: Group) -> None:
    """Velocity construction of a group (the cylinder's with the rod's sliding velocity l̇)."""
    if not cylinder_in(b, g):
        velocity.emit_group(b, g)
        return
    cyl = cylinder_of(b, g)
    assert cyl is not None
    partner, p1, e, k, barrel = _sides(b, g)
    rod = cyl.rod
    rate = f"vel.rate{cyl.tag}"
    rel = b.add(f"vel.r.{k}{e}", Op.SLIDE_VECTOR, (b.vel[e], rate, b.pos[e], b.pos[k]), V,
                Kind.POINT, Role.AUXILIARY, f"r_{k}{e}", g.name,
                subject=(b.c[b.vel[e]].label, e, k))
    b.segment(V, b.vel[e], rel, f"{b.c[b.vel[e]].label}r_{k}{e}", f"v_{k}{rod}{k}{barrel}",
              SegmentKind.SLIDING, g.name)
    outer = partner_pair(g, partner)
    side, rows = _partner_velocity(b, g, partner, outer, p1, k)
    meet = images.meet_lines(b, V, f"vel.{k}", side,
                             images.perp_line(b, V, rel, e, k, g.name), vlabel(k), g.name)
    b.vel[k] = meet
    turning = [(barrel, e, b.vel[e])]
    if outer.kind is PairKind.REVOLUTE:
        turning.insert(0, (partner, p1, b.vel[p1]))
    else:           # the partner turns with the link whose guide it slides on
        images.link_scalar(b, partner, outer.other(partner), V, g.name)
    for link, p, vp in turning:
        body = b.bodies[link]
        body.omega = b.add(f"vel.omega.{link}", Op.OMEGA, (b.pos[p], b.pos[k], vp, meet), V,
                           Kind.SCALAR, Role.RESULT, f"ω{link}", g.name, subject=(p, k))
        b.result(f"omega_{link}", body.omega)
    images.link_scalar(b, rod, barrel, V, g.name)
    images.absolute(b, k, V, g.name)
    b.c.equations[(V, g.name)] = (
        f"v_{k} = v_{e} + v_{k}{rod}{k}{barrel} + v_{k}{e} = " + " + ".join(r[0] for r in rows),
        [(f"v_{e}", GIVEN, "✓"), (f"v_{k}{rod}{k}{barrel}", parallel(f"{e}{k}"), b.c[rate].label),
         (f"v_{k}{e}", perp(f"{e}{k}"), "?"), *rows])
    for link in (partner, barrel, rod):
        images.complete(b, link, V, g.name)


def acceleration_group(b: Builder, g: Group) -> None:
    """Acceleration construction of a group (the cylinder's with its Coriolis and l̈ terms)."""
    if not cylinder_in(b, g):
        acceleration.emit_group(b, g)
        return
    cyl = cylinder_of(b, g)
    assert cyl is not None
    partner, p1, e, k, barrel = _sides(b, g)
    rod, rate = cyl.rod, f"acc.rate{cyl.tag}"
    outer = partner_pair(g, partner)
    side, n1, rows = _partner_acceleration(b, g, partner, outer, p1, k)
    nc = acceleration._normal(b, b.acc[e], barrel, e, k, k, g.name)
    kor = acceleration._coriolis(b, nc, barrel, b.vel[e], f"vel.r.{k}{e}", f"{k}{e}", g.name)
    rel = b.add(f"acc.r.{k}{e}", Op.SLIDE_VECTOR, (kor, rate, b.pos[e], b.pos[k]), A,
                Kind.POINT, Role.AUXILIARY, f"r_{k}{e}", g.name,
                subject=(b.c[kor].label, e, k))
    b.segment(A, kor, rel, f"{b.c[kor].label}r_{k}{e}", f"a^r_{k}{rod}{k}{barrel}",
              SegmentKind.SLIDING, g.name)
    meet = images.meet_lines(b, A, f"acc.{k}", side,
                             images.perp_line(b, A, rel, e, k, g.name), alabel(k), g.name)
    b.acc[k] = meet
    if n1 is not None:
        acceleration._epsilon(b, partner, p1, b.pos[k], n1, meet, g.name)
        acceleration._tangential(b, n1, meet, f"a^t_{k}{p1}", g.name)
    else:           # the partner turns with the link whose guide it slides on
        m = outer.other(partner)
        images.link_scalar(b, partner, m, A, g.name)
        if m != GROUND:         # the relative acceleration along the guide, measured
            kk = side_start(b, side)
            b.segment(A, kk, meet, f"{b.c[kk].label} {alabel(k)}", f"a^r_{k}{partner}{k}{m}",
                      SegmentKind.SLIDING, g.name)
    acceleration._epsilon(b, barrel, e, b.pos[k], rel, meet, g.name)
    acceleration._tangential(b, rel, meet, f"a^t_{k}{e}", g.name)
    images.link_scalar(b, rod, barrel, A, g.name)
    images.absolute(b, k, A, g.name)
    b.c.equations[(A, g.name)] = (
        (f"a_{k} = a_{e} + a^n_{k}{e} + a^k_{k}{e} + a^r_{k}{e} + a^t_{k}{e} = "
         + " + ".join(r[0] for r in rows)),
        [(f"a_{e}", GIVEN, "✓"), (f"a^n_{k}{e}", from_to(k, e), f"ω{barrel}²·l_{e}{k}"),
         (f"a^k_{k}{e}", perp(f"{e}{k}"), f"2ω{barrel}·v_{k}{rod}{k}{barrel}"),
         (f"a^r_{k}{e}", parallel(f"{e}{k}"), b.c[rate].label),
         (f"a^t_{k}{e}", perp(f"{e}{k}"), "?"), *rows])
    for link in (partner, barrel, rod):
        images.complete(b, link, A, g.name)


# -- the partner's side of a cylinder's group, by its outer pair ----------------------------------
def _partner_velocity(b: Builder, g: Group, partner: str, outer: Pair, p1: str, k: str
                      ) -> tuple[str, list[Row]]:
    """The line of v_K through the partner's known image: ⊥ P1K from v_P1 (a revolute), or ∥ the
    guide from the image of K on the guide's link (a prismatic pair); its equation's rows."""
    if outer.kind is PairKind.REVOLUTE:
        return (images.perp_line(b, V, b.vel[p1], p1, k, g.name),
                [(f"v_{p1}", GIVEN, "✓"), (f"v_{k}{p1}", perp(f"{p1}{k}"), "?")])
    m = outer.other(partner)
    locus = position.locus_id(partner, k, outer.guide)
    km = images.coincident(b, m, k, V, g.name)
    guide = b.c[locus].label
    if m == GROUND:
        rows = [(f"v_{k}", parallel(guide), "?")]
    else:
        rows = [(f"v_{k}{m}", GIVEN, "✓"), (f"v_{k}{partner}{k}{m}", parallel(guide), "?")]
    return images.parallel_line(b, V, km, locus, g.name), rows


def _partner_acceleration(b: Builder, g: Group, partner: str, outer: Pair, p1: str, k: str
                          ) -> tuple[str, str | None, list[Row]]:
    """The line of a_K through the partner's known vectors: the normal a^n_KP1 then ⊥ P1K (a
    revolute; its end returned), or the image of K on the guide's link and the Coriolis
    2ω × v_rel, then ∥ the guide (a prismatic pair); its equation's rows."""
    if outer.kind is PairKind.REVOLUTE:
        n1 = acceleration._normal(b, b.acc[p1], partner, p1, k, k, g.name)
        return (images.perp_line(b, A, n1, p1, k, g.name), n1,
                [(f"a_{p1}", GIVEN, "✓"),
                 (f"a^n_{k}{p1}", from_to(k, p1), f"ω{partner}²·l_{p1}{k}"),
                 (f"a^t_{k}{p1}", perp(f"{p1}{k}"), "?")])
    m = outer.other(partner)
    locus = position.locus_id(partner, k, outer.guide)
    km_v = images.coincident(b, m, k, V, g.name)
    km = images.coincident(b, m, k, A, g.name)
    kk = acceleration._coriolis(b, km, m, km_v, b.vel[k], f"{k}{partner}{k}{m}", g.name)
    guide = b.c[locus].label
    if m == GROUND:
        rows = [(f"a_{k}", parallel(guide), "?")]
    else:
        rows = [(f"a_{k}{m}", GIVEN, "✓"),
                (f"a^k_{k}{partner}{k}{m}", perp(guide), f"2ω{m}·v_{k}{partner}{k}{m}"),
                (f"a^r_{k}{partner}{k}{m}", parallel(guide), "?")]
    return images.parallel_line(b, A, kk, locus, g.name), None, rows


def side_start(b: Builder, line: str) -> str:
    """The image a construction line is drawn through."""
    return b.c[line].input("through")
