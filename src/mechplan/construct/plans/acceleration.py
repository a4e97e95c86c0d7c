"""Acceleration plan from pole π: normal, Coriolis and relative components, meets, similarity."""

from __future__ import annotations

from ...model.mechanism import GROUND
from ...model.plans import Plan
from ...model.structure import Group, GroupKind
from ..builder import Builder, alabel
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import GIVEN, from_to, parallel, perp
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

A = Plan.ACCELERATION


def emit_drive(b: Builder) -> None:
    """Pole π, frame images, ε1 and the driving vector π b′."""
    if b.mech.drive.linear:     # a cylinder or a slider: see plans/drivers.py
        from .drivers import emit_linear_plan
        emit_linear_plan(b, A)
        return
    tip, group = start_plan(b, A)
    drive = b.mech.drive
    body = b.bodies[drive.link]
    by_law, rates = law_rate(b, drive, A, group), (drive.omega, drive.epsilon)
    if by_law is None:
        body.epsilon = b.add(f"acc.epsilon.{drive.link}", Op.CONSTANT, (), A, Kind.SCALAR,
                             Role.GIVEN, f"ε{drive.link}", value=drive.epsilon)
        extra: tuple[str, ...] = ()
    else:                   # a law by a table: ω and ε of each position (plans/crank_law.py)
        assert body.omega is not None
        body.epsilon, rates, extra = by_law, law_sizes(drive), (body.omega, by_law)
    b.result(f"epsilon_{drive.link}", body.epsilon)
    b.acc[tip] = b.add(f"acc.{tip}", Op.DRIVE_ACCELERATION,
                       (b.pos[drive.pivot], b.pos[tip], *extra), A,
                       Kind.POINT, Role.RESULT, alabel(tip), group, subject=(drive.pivot, tip),
                       omega=rates[0], epsilon=rates[1])
    rows = [(f"a^n_{tip}", from_to(tip, drive.pivot), f"ω{drive.link}²·l_{drive.pivot}{tip}")]
    if rates[1]:
        rows.append(
            (f"a^t_{tip}", perp(f"{drive.pivot}{tip}"), f"ε{drive.link}·l_{drive.pivot}{tip}")
        )
    b.c.equations[(A, group)] = (f"a_{tip} = a^n_{tip} + a^t_{tip}", rows)
    absolute(b, tip, A, group)
    complete(b, drive.link, A, group)


def emit_group(b: Builder, g: Group) -> None:
    """Acceleration construction of one group, then images of all its points."""
    {GroupKind.RRR: _rrr, GroupKind.RRP: _rrp, GroupKind.RPR: _rpr, GroupKind.PRP: _prp,
     GroupKind.RPP: _rpp}[g.kind](b, g)
    for link in g.links:
        complete(b, link, A, g.name)


def _normal(b: Builder, start: str, link: str, p: str, q: str, q_name: str, group: str) -> str:
    """n_QP: from the image of P, ∥ QP towards P, of length ω²·l_PQ."""
    omega = b.bodies[link].omega
    assert omega is not None
    sid = b.add(f"acc.n.{q_name}{p}", Op.NORMAL, (start, omega, b.pos[p], b.pos[q]), A, Kind.POINT,
                Role.AUXILIARY, f"n_{q_name}{p}", group, subject=(b.c[start].label, q_name, p))
    b.segment(A, start, sid, f"{b.c[start].label}n_{q_name}{p}", f"a^n_{q_name}{p}",
              SegmentKind.NORMAL, group)
    return sid


def _coriolis(b: Builder, start: str, frame_link: str, v_from: str, v_to: str, name: str,
              group: str) -> str:
    """k: from ``start``, 2ω × v_rel where v_rel = v_to − v_from and ω of the guide's link."""
    if frame_link == GROUND:
        return start
    omega = b.bodies[frame_link].omega
    assert omega is not None
    sid = b.add(f"acc.k.{name}", Op.CORIOLIS, (start, omega, v_from, v_to), A, Kind.POINT,
                Role.AUXILIARY, f"k_{name}", group,
                subject=(b.c[start].label, b.c[omega].label, b.c[v_from].label, b.c[v_to].label))
    b.segment(A, start, sid, f"{b.c[start].label}k_{name}", f"a^k_{name}", SegmentKind.CORIOLIS,
              group)
    return sid


def _epsilon(b: Builder, link: str, p: str, q_pos: str, n: str, aq: str, group: str) -> str:
    body = b.bodies[link]
    body.epsilon = b.add(f"acc.epsilon.{link}", Op.EPSILON, (b.pos[p], q_pos, n, aq), A,
                         Kind.SCALAR, Role.RESULT, f"ε{link}", group, subject=(p, b.c[q_pos].label))
    b.result(f"epsilon_{link}", body.epsilon)
    return body.epsilon


def _tangential(b: Builder, n: str, end: str, quantity: str, group: str) -> None:
    b.segment(
        A, n, end, f"{b.c[n].label} {b.c[end].label}", quantity, SegmentKind.TANGENTIAL, group
    )


def _rrr(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    p1, p2, k = g.outer1.point, g.outer2.point, g.inner.point
    n1 = _normal(b, b.acc[p1], l1, p1, k, k, g.name)
    n2 = _normal(b, b.acc[p2], l2, p2, k, k, g.name)
    meet = meet_lines(
        b,
        A,
        f"acc.{k}",
        perp_line(b, A, n1, p1, k, g.name),
        perp_line(b, A, n2, p2, k, g.name),
        alabel(k),
        g.name,
    )
    b.acc[k] = meet
    _epsilon(b, l1, p1, b.pos[k], n1, meet, g.name)
    _epsilon(b, l2, p2, b.pos[k], n2, meet, g.name)
    _tangential(b, n1, meet, f"a^t_{k}{p1}", g.name)
    _tangential(b, n2, meet, f"a^t_{k}{p2}", g.name)
    absolute(b, k, A, g.name)
    b.c.equations[(A, g.name)] = (
        f"a_{k} = a_{p1} + a^n_{k}{p1} + a^t_{k}{p1} = a_{p2} + a^n_{k}{p2} + a^t_{k}{p2}",
        [
            (f"a_{p1}", GIVEN, "✓"),
            (f"a^n_{k}{p1}", from_to(k, p1), f"ω{l1}²·l_{p1}{k}"),
            (f"a^t_{k}{p1}", perp(f"{p1}{k}"), "?"),
            (f"a_{p2}", GIVEN, "✓"),
            (f"a^n_{k}{p2}", from_to(k, p2), f"ω{l2}²·l_{p2}{k}"),
            (f"a^t_{k}{p2}", perp(f"{p2}{k}"), "?"),
        ],
    )


def _rrp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    p1, k = g.outer1.point, g.inner.point
    m = g.outer2.other(l2)
    locus = locus_id(l2, k, g.outer2.guide)
    n1 = _normal(b, b.acc[p1], l1, p1, k, k, g.name)
    km_v = coincident(b, m, k, Plan.VELOCITY, g.name)
    km = coincident(b, m, k, A, g.name)
    kk = _coriolis(b, km, m, km_v, b.vel[k], f"{k}{l2}{k}{m}", g.name)
    meet = meet_lines(
        b,
        A,
        f"acc.{k}",
        perp_line(b, A, n1, p1, k, g.name),
        parallel_line(b, A, kk, locus, g.name),
        alabel(k),
        g.name,
    )
    b.acc[k] = meet
    _epsilon(b, l1, p1, b.pos[k], n1, meet, g.name)
    link_scalar(b, l2, m, A, g.name)
    _tangential(b, n1, meet, f"a^t_{k}{p1}", g.name)
    guide = b.c[locus].label
    if m != GROUND:
        b.segment(A, kk, meet, f"{b.c[kk].label} {b.c[meet].label}", f"a^r_{k}{l2}{k}{m}",
                  SegmentKind.SLIDING, g.name)
    absolute(b, k, A, g.name)
    rows = [(f"a_{p1}", GIVEN, "✓"), (f"a^n_{k}{p1}", from_to(k, p1), f"ω{l1}²·l_{p1}{k}"),
            (f"a^t_{k}{p1}", perp(f"{p1}{k}"), "?")]
    if m == GROUND:
        eq = f"a_{k} = a_{p1} + a^n_{k}{p1} + a^t_{k}{p1}"
        rows.append((f"a_{k}", parallel(f"{guide}"), "?"))
    else:
        eq = (f"a_{k} = a_{p1} + a^n_{k}{p1} + a^t_{k}{p1} = a_{k}{m} + a^k_{k}{l2}{k}{m} + "
              f"a^r_{k}{l2}{k}{m}")
        rows += [
            (f"a_{k}{m}", GIVEN, "✓"),
            (f"a^k_{k}{l2}{k}{m}", perp(f"{guide}"), f"2ω{m}·v_{k}{l2}{k}{m}"),
            (f"a^r_{k}{l2}{k}{m}", parallel(f"{guide}"), "?"),
        ]
    b.c.equations[(A, g.name)] = (eq, rows)


def _rpr(b: Builder, g: Group) -> None:
    s, c = g.inner.a, g.inner.b
    outer = {g.links[0]: g.outer1, g.links[1]: g.outer2}
    ps, pc = outer[s].point, outer[c].point
    guide = b.guide_of(g.inner)
    gline = f"pos.guide.{guide.name}"
    im = b.bodies[c].image(f"{ps}@{c}")
    assert im is not None and im.vel is not None
    n = _normal(b, b.acc[pc], c, pc, ps, f"{ps}{c}", g.name)
    kk = _coriolis(b, b.acc[ps], c, b.vel[ps], im.vel, f"{ps}{c}{ps}{s}", g.name)
    label = b.c[im.vel].label + "′"
    meet = meet_lines(
        b,
        A,
        f"acc.{ps}@{c}",
        perp_line(b, A, n, pc, ps, g.name),
        parallel_line(b, A, kk, gline, g.name),
        label,
        g.name,
    )
    im.acc = meet
    _epsilon(b, c, pc, b.pos[ps], n, meet, g.name)
    link_scalar(b, s, c, A, g.name)
    _tangential(b, n, meet, f"a^t_{ps}{c}{pc}", g.name)
    b.segment(A, kk, meet, f"{b.c[kk].label} {label}", f"a^r_{ps}{c}{ps}{s}", SegmentKind.SLIDING,
              g.name)
    b.segment(A, "acc.pi", meet, f"π{label}", f"a_{ps}{c}", SegmentKind.ABSOLUTE, g.name)
    b.result(f"a_{ps}{c}", meet)
    b.c.equations[(A, g.name)] = (
        (
            f"a_{ps}{c} = a_{ps}{s} + a^k_{ps}{c}{ps}{s} + a^r_{ps}{c}{ps}{s} = "
            f"a_{pc} + a^n_{ps}{c}{pc} + a^t_{ps}{c}{pc}"
        ),
        [
            (f"a_{ps}{s}", GIVEN, "✓"),
            (f"a^k_{ps}{c}{ps}{s}", perp(f"{guide.name}"), f"2ω{c}·v_{ps}{c}{ps}{s}"),
            (f"a^r_{ps}{c}{ps}{s}", parallel(f"{guide.name}"), "?"),
            (f"a_{pc}", GIVEN, "✓"),
            (f"a^n_{ps}{c}{pc}", from_to(ps, pc), f"ω{c}²·l_{pc}{ps}"),
            (f"a^t_{ps}{c}{pc}", perp(f"{pc}{ps}"), "?"),
        ],
    )


def _prp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    k = g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    lines = []
    for link, m, outer in ((l1, m1, g.outer1), (l2, m2, g.outer2)):
        locus = locus_id(link, k, outer.guide)
        kv = coincident(b, m, k, Plan.VELOCITY, g.name)
        ka = coincident(b, m, k, A, g.name)
        kk = _coriolis(b, ka, m, kv, b.vel[k], f"{k}{link}{k}{m}", g.name)
        lines.append(parallel_line(b, A, kk, locus, g.name))
    b.acc[k] = meet_lines(b, A, f"acc.{k}", lines[0], lines[1], alabel(k), g.name)
    link_scalar(b, l1, m1, A, g.name)
    link_scalar(b, l2, m2, A, g.name)
    absolute(b, k, A, g.name)
    b.c.equations[(A, g.name)] = (
        (
            f"a_{k} = a_{k}{m1} + a^k_{k}{l1}{k}{m1} + a^r_{k}{l1}{k}{m1} = "
            f"a_{k}{m2} + a^k_{k}{l2}{k}{m2} + a^r_{k}{l2}{k}{m2}"
        ),
        [
            (f"a_{k}{m1}", GIVEN, "✓"),
            (f"a^k_{k}{l1}{k}{m1}", perp(), f"2ω{m1}·v_{k}{l1}{k}{m1}"),
            (f"a^r_{k}{l1}{k}{m1}", parallel(), "?"),
            (f"a_{k}{m2}", GIVEN, "✓"),
            (f"a^k_{k}{l2}{k}{m2}", perp(), f"2ω{m2}·v_{k}{l2}{k}{m2}"),
            (f"a^r_{k}{l2}{k}{m2}", parallel(), "?"),
        ],
    )


def _rpp(b: Builder, g: Group) -> None:
    l1, l2 = g.links
    m = g.outer2.other(l2)
    link_scalar(b, l2, m, A, g.name)
    link_scalar(b, l1, l2, A, g.name)
    complete(b, l1, A, g.name)
    x = next(iter(b.mech.links[l2].points))
    lines = []
    for partner, guide in ((m, g.outer2.guide), (l1, g.inner.guide)):
        locus = locus_id(l2, x, guide)
        xv = coincident(b, partner, x, Plan.VELOCITY, g.name)
        xa = coincident(b, partner, x, A, g.name)
        kk = _coriolis(b, xa, partner, xv, b.vel[x], f"{x}{l2}{x}{partner}", g.name)
        lines.append(parallel_line(b, A, kk, locus, g.name))
    b.acc[x] = meet_lines(b, A, f"acc.{x}", lines[0], lines[1], alabel(x), g.name)
    absolute(b, x, A, g.name)
    b.c.equations[(A, g.name)] = (
        f"a_{x} = a_{x}{m} + a^k + a^r_{x}{l2}{x}{m} = a_{x}{l1} + a^k + a^r_{x}{l2}{x}{l1}", [
            (f"a_{x}{m}", GIVEN, "✓"), (f"a^r_{x}{l2}{x}{m}", parallel(), "?"),
            (f"a_{x}{l1}", GIVEN, "✓"), (f"a^r_{x}{l2}{x}{l1}", parallel(), "?")])
