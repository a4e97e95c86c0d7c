"""Velocity plan from pole p: lines ⊥ links and ∥ guides through known images, and their meets."""

from __future__ import annotations

from ...model.mechanism import GROUND
from ...model.plans import Plan
from ...model.structure import Group, GroupKind
from ..builder import Builder, Image, vlabel
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import GIVEN, parallel, perp
from .crank_law import rate as law_rate
from .crank_law import sizes as law_sizes
from .images import (
    absolute,
    coincident,
    complete,
    link_scalar,
    meet_lines,
    parallel_line,
    perp_line,
    start_plan,
)
from .position import locus_id

V = Plan.VELOCITY


def emit_drive(b: Builder) -> None:
    """Pole, frame images, ω1 and the driving vector pb ⊥ AB."""
    if b.mech.drive.linear:     # a cylinder or a slider: see plans/drivers.py
        from .drivers import emit_linear_plan
        emit_linear_plan(b, V)
        return
    tip, group = start_plan(b, V)
    drive = b.mech.drive
    body = b.bodies[drive.link]
    by_law, omega = law_rate(b, drive, V, group), drive.omega
    if by_law is None:
        body.omega = b.add(f"vel.omega.{drive.link}", Op.CONSTANT, (), V, Kind.SCALAR,
                           Role.GIVEN, f"ω{drive.link}", value=drive.omega)
    else:                   # a law by a table: ω of each position (plans/crank_law.py)
        body.omega, omega = by_law, law_sizes(drive)[0]
    b.result(f"omega_{drive.link}", body.omega)
    b.vel[tip] = b.add(f"vel.{tip}", Op.DRIVE_VELOCITY,
                       (b.pos[drive.pivot], b.pos[tip], *(() if by_law is None else (by_law,))),
                       V, Kind.POINT, Role.RESULT, vlabel(tip), group, subject=(drive.pivot, tip),
                       omega=omega)
    b.c.equations[(V, group)] = (
        f"v_{tip} = ω{drive.link} × l_{drive.pivot}{tip}",
        [(f"v_{tip}", perp(f"{drive.pivot}{tip}"), f"ω{drive.link}·l_{drive.pivot}{tip}")],
    )
    absolute(b, tip, V, group)
    complete(b, drive.link, V, group)


def emit_group(b: Builder, g: Group) -> None:
    """Velocity construction of one group, then images of all its points."""
    {GroupKind.RRR: _rrr, GroupKind.RRP: _rrp, GroupKind.RPR: _rpr, GroupKind.PRP: _prp,
     GroupKind.RPP: _rpp}[g.kind](b, g)
    for link in g.links:
        complete(b, link, V, g.name)


def _omega(b: Builder, link: str, p: str, q_pos: str, vp: str, vq: str, group: str) -> str:
    body = b.bodies[link]
    body.omega = b.add(f"vel.omega.{link}", Op.OMEGA, (b.pos[p], q_pos, vp, vq), V, Kind.SCALAR,
                       Role.RESULT, f"ω{link}", group, subject=(p, b.c[q_pos].label))
    b.result(f"omega_{link}", body.omega)
    return body.omega


def _relative(
    b: Builder, start: str, end: str, quantity: str, kind: SegmentKind, group: str
) -> None:
    if start == "vel.p":        # relative to a frame point: the absolute segment says it
        return
    b.segment(V, start, end, f"{b.c[start].label}{b.c[end].label}", quantity, kind, group)


def _rrr(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    p1, p2, k = g.outer1.point, g.outer2.point, g.inner.point
    meet = meet_lines(b, V, f"vel.{k}", perp_line(b, V, b.vel[p1], p1, k, g.name),
                 perp_line(b, V, b.vel[p2], p2, k, g.name), vlabel(k), g.name)
    b.vel[k] = meet
    _omega(b, l1, p1, b.pos[k], b.vel[p1], meet, g.name)
    _omega(b, l2, p2, b.pos[k], b.vel[p2], meet, g.name)
    _relative(b, b.vel[p1], meet, f"v_{k}{p1}", SegmentKind.RELATIVE, g.name)
    _relative(b, b.vel[p2], meet, f"v_{k}{p2}", SegmentKind.RELATIVE, g.name)
    absolute(b, k, V, g.name)
    b.c.equations[(V, g.name)] = (f"v_{k} = v_{p1} + v_{k}{p1} = v_{p2} + v_{k}{p2}", [
        (f"v_{p1}", GIVEN, "✓"), (f"v_{k}{p1}", perp(f"{p1}{k}"), "?"),
        (f"v_{p2}", GIVEN, "✓"), (f"v_{k}{p2}", perp(f"{p2}{k}"), "?")])


def _rrp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    p1, k = g.outer1.point, g.inner.point
    m = g.outer2.other(l2)
    locus = locus_id(l2, k, g.outer2.guide)
    km = coincident(b, m, k, V, g.name)
    meet = meet_lines(
        b,
        V,
        f"vel.{k}",
        perp_line(b, V, b.vel[p1], p1, k, g.name),
        parallel_line(b, V, km, locus, g.name),
        vlabel(k),
        g.name,
    )
    b.vel[k] = meet
    _omega(b, l1, p1, b.pos[k], b.vel[p1], meet, g.name)
    link_scalar(b, l2, m, V, g.name)
    _relative(b, b.vel[p1], meet, f"v_{k}{p1}", SegmentKind.RELATIVE, g.name)
    km_name = k if m == GROUND else f"{k}{m}"
    if m != GROUND:
        _relative(b, km, meet, f"v_{k}{l2}{km_name}", SegmentKind.SLIDING, g.name)
    absolute(b, k, V, g.name)
    guide = b.c[locus].label
    b.c.equations[(V, g.name)] = (
        f"v_{k} = v_{p1} + v_{k}{p1} = v_{km_name} + v_{k}{l2}{km_name}" if m != GROUND
        else f"v_{k} = v_{p1} + v_{k}{p1}", [
            (f"v_{p1}", GIVEN, "✓"), (f"v_{k}{p1}", perp(f"{p1}{k}"), "?"),
            *([(f"v_{km_name}", GIVEN, "✓")] if m != GROUND else []),
            (f"v_{k}{l2}{km_name}" if m != GROUND else f"v_{k}", parallel(f"{guide}"), "?")])


def _rpr(b: Builder, g: Group) -> None:
    s, c = g.inner.a, g.inner.b
    outer = {g.links[0]: g.outer1, g.links[1]: g.outer2}
    ps, pc = outer[s].point, outer[c].point
    guide = b.guide_of(g.inner)
    gline = f"pos.guide.{guide.name}"
    label = (vlabel(ps) + c) if not any(ch.isdigit() for ch in ps) else f"{vlabel(ps)}_{c}"
    meet = meet_lines(b, V, f"vel.{ps}@{c}", perp_line(b, V, b.vel[pc], pc, ps, g.name),
                 parallel_line(b, V, b.vel[ps], gline, g.name), label, g.name)
    body = b.bodies[c]
    body.images.append(Image(f"{ps}@{c}", f"{ps}{c}", b.pos[ps], vel=meet))
    _omega(b, c, pc, b.pos[ps], b.vel[pc], meet, g.name)
    link_scalar(b, s, c, V, g.name)
    _relative(b, b.vel[pc], meet, f"v_{ps}{c}{pc}", SegmentKind.RELATIVE, g.name)
    _relative(b, b.vel[ps], meet, f"v_{ps}{c}{ps}{s}", SegmentKind.SLIDING, g.name)
    b.segment(V, "vel.p", meet, f"p{label}", f"v_{ps}{c}", SegmentKind.ABSOLUTE, g.name)
    b.result(f"v_{ps}{c}", meet)
    b.result(f"v_rel_{s}{c}", meet)
    b.c.equations[(V, g.name)] = (
        f"v_{ps}{c} = v_{ps}{s} + v_{ps}{c}{ps}{s} = v_{pc} + v_{ps}{c}{pc}",
        [
            (f"v_{ps}{s}", GIVEN, "✓"),
            (f"v_{ps}{c}{ps}{s}", parallel(f"{guide.name}"), "?"),
            (f"v_{pc}", GIVEN, "✓"),
            (f"v_{ps}{c}{pc}", perp(f"{pc}{ps}"), "?"),
        ],
    )


def _prp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    k = g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    loc1, loc2 = locus_id(l1, k, g.outer1.guide), locus_id(l2, k, g.outer2.guide)
    k1, k2 = coincident(b, m1, k, V, g.name), coincident(b, m2, k, V, g.name)
    meet = meet_lines(
        b,
        V,
        f"vel.{k}",
        parallel_line(b, V, k1, loc1, g.name),
        parallel_line(b, V, k2, loc2, g.name),
        vlabel(k),
        g.name,
    )
    b.vel[k] = meet
    link_scalar(b, l1, m1, V, g.name)
    link_scalar(b, l2, m2, V, g.name)
    _relative(b, k1, meet, f"v_{k}{l1}{k}{m1}", SegmentKind.SLIDING, g.name)
    _relative(b, k2, meet, f"v_{k}{l2}{k}{m2}", SegmentKind.SLIDING, g.name)
    absolute(b, k, V, g.name)
    b.c.equations[(V, g.name)] = (
        f"v_{k} = v_{k}{m1} + v_{k}{l1}{k}{m1} = v_{k}{m2} + v_{k}{l2}{k}{m2}",
        [
            (f"v_{k}{m1}", GIVEN, "✓"),
            (f"v_{k}{l1}{k}{m1}", parallel(f"{b.c[loc1].label}"), "?"),
            (f"v_{k}{m2}", GIVEN, "✓"),
            (f"v_{k}{l2}{k}{m2}", parallel(f"{b.c[loc2].label}"), "?"),
        ],
    )


def _rpp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    m = g.outer2.other(l2)
    link_scalar(b, l2, m, V, g.name)
    link_scalar(b, l1, l2, V, g.name)
    complete(b, l1, V, g.name)
    x = next(iter(b.mech.links[l2].points))
    loc_ext, loc_in = locus_id(l2, x, g.outer2.guide), locus_id(l2, x, g.inner.guide)
    xm, x1 = coincident(b, m, x, V, g.name), coincident(b, l1, x, V, g.name)
    meet = meet_lines(
        b,
        V,
        f"vel.{x}",
        parallel_line(b, V, xm, loc_ext, g.name),
        parallel_line(b, V, x1, loc_in, g.name),
        vlabel(x),
        g.name,
    )
    b.vel[x] = meet
    _relative(b, x1, meet, f"v_{x}{l2}{x}{l1}", SegmentKind.SLIDING, g.name)
    if m != GROUND:
        _relative(b, xm, meet, f"v_{x}{l2}{x}{m}", SegmentKind.SLIDING, g.name)
    absolute(b, x, V, g.name)
    b.c.equations[(V, g.name)] = (
        f"v_{x} = v_{x}{m} + v_{x}{l2}{x}{m} = v_{x}{l1} + v_{x}{l2}{x}{l1}",
        [
            (f"v_{x}{m}", GIVEN, "✓"),
            (f"v_{x}{l2}{x}{m}", parallel(f"{b.c[loc_ext].label}"), "?"),
            (f"v_{x}{l1}", GIVEN, "✓"),
            (f"v_{x}{l2}{x}{l1}", parallel(f"{b.c[loc_in].label}"), "?"),
        ],
    )
