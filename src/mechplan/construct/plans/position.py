"""Position plan: compass arcs, arcs across guides, line meets, triangles on known sides."""

from __future__ import annotations

import math

from ...model.mechanism import GROUND, Pair
from ...model.plans import Plan
from ...model.structure import Group, GroupKind
from ..builder import Builder
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role

P = Plan.POSITION


def _local_angle(b: Builder, link: str, p: str, q: str) -> float:
    (x1, y1), (x2, y2) = b.mech.links[link].points[p], b.mech.links[link].points[q]
    return math.atan2(y2 - y1, x2 - x1)


def emit_frame_and_drive(b: Builder) -> None:
    """Frame points, the crank angle and the crank's points."""
    ground = b.mech.links[GROUND]
    for name, xy in ground.points.items():
        b.pos[name] = b.add(f"pos.{name}", Op.FIXED_POINT, (), P, Kind.POINT, Role.GIVEN, name,
                            xy=xy)
    drive = b.mech.drive
    if drive.linear:        # a cylinder or a slider: see plans/drivers.py
        from .drivers import emit_linear_position
        emit_linear_position(b)
        return
    crank = b.mech.links[drive.link]
    pivot = drive.pivot
    tip = next(p for p in crank.points if p != pivot)
    theta = b.add("pos.phi1", Op.CRANK_ANGLE, (), P, Kind.SCALAR, Role.GIVEN, f"φ{drive.link}")
    base = _local_angle(b, drive.link, pivot, tip)
    for name in crank.points:
        if name == pivot:
            continue
        b.pos[name] = b.add(f"pos.{name}", Op.POLAR_POINT, (b.pos[pivot], theta), P, Kind.POINT,
                            Role.RESULT, name, group=f"I(0,{drive.link})", subject=(pivot, name),
                            length=crank.distance(pivot, name),
                            offset=_local_angle(b, drive.link, pivot, name) - base)
        b.segment(
            P, b.pos[pivot], b.pos[name], f"{pivot}{name}", f"l_{pivot}{name}", SegmentKind.LINK
        )
    body = b.bodies[drive.link]
    body.anchor = pivot
    body.angle = theta if base == 0.0 else b.add(
        f"pos.angle.{drive.link}", Op.ANGLE_PLUS, (theta,), P, Kind.SCALAR, Role.AUXILIARY,
        f"θ{drive.link}", delta=-base)
    b.result(f"angle_{drive.link}", body.angle)


def place_point(b: Builder, link: str, name: str, group: str) -> str:
    """Position of a named point of a link whose pose is known."""
    if name in b.pos:
        return b.pos[name]
    lk = b.mech.links[link]
    known = [p for p in lk.points if p in b.pos]
    body = b.bodies[link]
    if len(known) >= 2:
        (ax, ay), (bx, by), (x, y) = lk.points[known[0]], lk.points[known[1]], lk.points[name]
        z = complex(x - ax, y - ay) / complex(bx - ax, by - ay)
        sid = b.add(f"pos.{name}", Op.SIMILAR_POSITION, (b.pos[known[0]], b.pos[known[1]]), P,
                    Kind.POINT, Role.RESULT, name, group, subject=(known[0], known[1], name), z=z)
    else:
        assert body.anchor is not None and body.angle is not None
        (ox, oy), (x, y) = lk.points[body.anchor], lk.points[name]
        sid = b.add(f"pos.{name}", Op.PLACE, (b.pos[body.anchor], body.angle), P, Kind.POINT,
                    Role.RESULT, name, group, subject=(body.anchor, name), offset=(x - ox, y - oy))
    b.pos[name] = sid
    return sid


def complete(b: Builder, link: str, group: str) -> None:
    """Place every point of a link and record its drawn segments."""
    lk = b.mech.links[link]
    for name in lk.points:
        place_point(b, link, name, group)
    joints = [p for p in lk.points if any(pr.point == p for pr in b.mech.pairs_of(link))]
    for i, p in enumerate(joints):
        for q in joints[i + 1:]:
            b.segment(P, b.pos[p], b.pos[q], f"{p}{q}", f"l_{p}{q}", SegmentKind.LINK, group)
    for q in lk.points:
        if q not in joints and joints:
            b.segment(P, b.pos[joints[0]], b.pos[q], f"{joints[0]}{q}", f"l_{joints[0]}{q}",
                      SegmentKind.LINK, group)


def angle_from_pair(b: Builder, link: str, pair: Pair, partner: str, group: str) -> str:
    """Angle of a link that slides with (or carries the guide of) a link of known angle."""
    body = b.bodies[link]
    if body.angle is not None:
        return body.angle
    gamma = b.guide_of(pair).angle
    delta = gamma if pair.a == link else -gamma
    sid = f"pos.angle.{link}"
    other = b.bodies[partner].angle
    if partner == GROUND:
        body.angle = b.add(sid, Op.CONSTANT, (), P, Kind.SCALAR, Role.GIVEN, f"θ{link}", group,
                           value=delta)
    else:
        assert other is not None
        body.angle = b.add(sid, Op.ANGLE_PLUS, (other,), P, Kind.SCALAR, Role.AUXILIARY,
                           f"θ{link}", group, delta=delta)
    b.result(f"angle_{link}", body.angle)
    return body.angle


def locus_id(link: str, point: str, guide: str | None) -> str:
    """Step id of the line a point of a sliding link lies on (see :func:`locus`)."""
    return f"pos.locus.{link}.{point}.{guide}"


def locus(b: Builder, link: str, point: str, pair: Pair, partner: str, group: str) -> str:
    """Line on which a point of a sliding link lies, given the partner link's pose."""
    g = b.guide_of(pair)
    x, y = b.mech.links[link].points[point]
    sid = locus_id(link, point, g.name)
    cg, sg = math.cos(g.angle), math.sin(g.angle)
    if pair.a == link:      # the link slides on the partner's guide
        rx, ry = cg * x - sg * y, sg * x + cg * y
        label = g.name if (x, y) == (0.0, 0.0) else f"{g.name}({point})"
        if partner == GROUND:
            return b.add(sid, Op.LOCUS_LINE, (b.pos[g.through],), P, Kind.LINE, Role.AUXILIARY,
                         label, group, subject=(g.name, point), offset=(rx, ry), dir_angle=g.angle)
        pb = b.bodies[partner]
        assert pb.anchor is not None and pb.angle is not None
        ax, ay = b.mech.links[partner].points[pb.anchor]
        ox, oy = g.origin
        return b.add(sid, Op.LOCUS_LINE, (b.pos[pb.anchor], pb.angle), P, Kind.LINE,
                     Role.AUXILIARY, label, group, subject=(g.name, point),
                     offset=(ox - ax + rx, oy - ay + ry), dir_angle=g.angle)
    # the link carries the guide, the partner is the slider with its origin at pair.point
    dx, dy = x - g.origin[0], y - g.origin[1]
    offset = (cg * dx + sg * dy, -sg * dx + cg * dy)
    pa = b.bodies[partner].angle
    assert pa is not None
    return b.add(sid, Op.LOCUS_LINE, (b.pos[pair.point], pa), P, Kind.LINE, Role.AUXILIARY,
                 f"{g.name}({point})", group, subject=(g.name, point), offset=offset, dir_angle=0.0)


def emit_group(b: Builder, g: Group) -> None:
    """Emit the position construction of one class II group."""
    kind = g.kind
    {GroupKind.RRR: _rrr, GroupKind.RRP: _rrp, GroupKind.RPR: _rpr, GroupKind.PRP: _prp,
     GroupKind.RPP: _rpp}[kind](b, g)
    for link in g.links:
        complete(b, link, g.name)


def _angle_of(b: Builder, link: str, p: str, q: str, group: str) -> str:
    body = b.bodies[link]
    body.angle = b.add(f"pos.angle.{link}", Op.ANGLE_OF, (b.pos[p], b.pos[q]), P, Kind.SCALAR,
                       Role.AUXILIARY, f"θ{link}", group, subject=(p, q),
                       minus=_local_angle(b, link, p, q))
    b.result(f"angle_{link}", body.angle)
    return body.angle


def _rrr(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    p1, p2, k = g.outer1.point, g.outer2.point, g.inner.point
    r1, r2 = b.mech.links[l1].distance(p1, k), b.mech.links[l2].distance(p2, k)
    sid = b.add(f"pos.{k}", Op.CIRCLE_CIRCLE, (b.pos[p1], b.pos[p2]), P, Kind.POINT, Role.RESULT,
                k, g.name, subject=(p1, p2, k), r1=r1, r2=r2, sigma=1)
    b.pos[k] = sid
    b.resolve_branch(sid, k, g.name, sid)
    b.bodies[l1].anchor, b.bodies[l2].anchor = p1, p2
    _angle_of(b, l1, p1, k, g.name)
    _angle_of(b, l2, p2, k, g.name)


def _rrp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    p1, k = g.outer1.point, g.inner.point
    m = g.outer2.other(l2)
    angle_from_pair(b, l2, g.outer2, m, g.name)
    line = locus(b, l2, k, g.outer2, m, g.name)
    sid = b.add(f"pos.{k}", Op.CIRCLE_LINE, (b.pos[p1], line), P, Kind.POINT, Role.RESULT, k,
                g.name, subject=(p1, k), r=b.mech.links[l1].distance(p1, k), sigma=1)
    b.pos[k] = sid
    b.resolve_branch(sid, k, g.name, sid)
    b.bodies[l1].anchor, b.bodies[l2].anchor = p1, k
    _angle_of(b, l1, p1, k, g.name)


def _rpr(b: Builder, g: Group) -> None:
    s, c = g.inner.a, g.inner.b
    outer = {g.links[0]: g.outer1, g.links[1]: g.outer2}
    ps, pc = outer[s].point, outer[c].point
    guide = b.guide_of(g.inner)
    gam = guide.angle
    (pcx, pcy), (psx, psy) = b.mech.links[c].points[pc], b.mech.links[s].points[ps]
    rx, ry = math.cos(gam) * psx - math.sin(gam) * psy, math.sin(gam) * psx + math.cos(gam) * psy
    q0 = (guide.origin[0] - pcx + rx, guide.origin[1] - pcy + ry)
    body_c, body_s = b.bodies[c], b.bodies[s]
    sid = b.add(f"pos.angle.{c}", Op.CARRIER_ANGLE, (b.pos[pc], b.pos[ps]), P, Kind.SCALAR,
                Role.RESULT, f"θ{c}", g.name, subject=(pc, ps, guide.name), q0=q0, dir_angle=gam,
                sigma=1)
    body_c.angle, body_c.anchor = sid, pc
    b.result(f"angle_{c}", sid)
    probe = next((p for p in b.mech.links[c].points if p != pc and
                  (p in b.mech.sides or p in b.mech.sketch)), None)
    if probe is not None:
        probe_id = place_point(b, c, probe, g.name)
        b.resolve_branch_probe(sid, probe, probe_id, g.name)
    angle_from_pair(b, s, g.inner, c, g.name)
    body_s.anchor = ps
    (ox, oy) = guide.origin
    b.add(f"pos.guide.{guide.name}", Op.LOCUS_LINE, (b.pos[pc], sid), P, Kind.LINE,
          Role.AUXILIARY, guide.name, g.name, subject=(guide.name, guide.through),
          offset=(ox - pcx, oy - pcy), dir_angle=gam)


def _prp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    k = g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    angle_from_pair(b, l1, g.outer1, m1, g.name)
    angle_from_pair(b, l2, g.outer2, m2, g.name)
    a = locus(b, l1, k, g.outer1, m1, g.name)
    c = locus(b, l2, k, g.outer2, m2, g.name)
    b.pos[k] = b.add(f"pos.{k}", Op.LINE_LINE, (a, c), P, Kind.POINT, Role.RESULT, k, g.name,
                     subject=(k,))
    b.bodies[l1].anchor = b.bodies[l2].anchor = k


def _rpp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    m = g.outer2.other(l2)
    angle_from_pair(b, l2, g.outer2, m, g.name)
    angle_from_pair(b, l1, g.inner, l2, g.name)
    b.bodies[l1].anchor = g.outer1.point
    complete(b, l1, g.name)
    x = next(iter(b.mech.links[l2].points))
    a = locus(b, l2, x, g.outer2, m, g.name)
    c = locus(b, l2, x, g.inner, l1, g.name)
    b.pos[x] = b.add(f"pos.{x}", Op.LINE_LINE, (a, c), P, Kind.POINT, Role.RESULT, x, g.name,
                     subject=(x,))
    b.bodies[l2].anchor = x
