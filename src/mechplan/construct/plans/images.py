"""Images of points on velocity and acceleration plans: similarity theorem and rigid motion."""

from __future__ import annotations

from ...model.mechanism import GROUND
from ...model.plans import Plan
from ..builder import Builder, Image, alabel, vlabel
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role


def known_images(b: Builder, link: str, plan: Plan) -> list[tuple[str, str]]:
    """(position step, image step) pairs of a link known so far on a plan."""
    table = b.vel if plan is Plan.VELOCITY else b.acc
    out = [(b.pos[p], table[p]) for p in b.mech.links[link].points if p in table]
    for im in b.bodies[link].images:
        img = im.vel if plan is Plan.VELOCITY else im.acc
        if img is not None:
            out.append((im.pos, img))
    return out


def start_plan(b: Builder, plan: Plan) -> tuple[str, str]:
    """Put the pole (p or π) at the images of the frame points; return (crank tip, group name)."""
    sid = pole(plan)
    b.add(sid, Op.POLE, (), plan, Kind.POINT, Role.GIVEN, "p" if plan is Plan.VELOCITY else "π")
    table, sym = (b.vel, "v") if plan is Plan.VELOCITY else (b.acc, "a")
    for name in b.mech.links[GROUND].points:
        table[name] = sid
        b.result(f"{sym}_{name}", sid)
    drive = b.mech.drive
    tip = next(p for p in b.mech.links[drive.link].points if p != drive.pivot)
    return tip, f"I(0,{drive.link})"


def pole(plan: Plan) -> str:
    """Step id of the pole of a plan."""
    return "vel.p" if plan is Plan.VELOCITY else "acc.pi"


def image_on(b: Builder, link: str, key: str, pos: str, label: str, plan: Plan, group: str,
             role: Role = Role.RESULT) -> str:
    """Image of the point at ``pos`` considered as a point of ``link`` (similarity theorem)."""
    if link == GROUND:
        return pole(plan)
    prefix = "vel" if plan is Plan.VELOCITY else "acc"
    sid = f"{prefix}.{key}"
    if sid in b.c:
        return sid
    known = known_images(b, link, plan)
    body = b.bodies[link]
    if len(known) >= 2:
        (pa, ia), (pb, ib) = known[0], known[1]
        return b.add(sid, Op.SIMILAR_IMAGE, (ia, ib, pa, pb, pos), plan, Kind.POINT, role, label,
                     group, subject=(b.c[pa].label, b.c[pb].label, b.c[pos].label))
    (pa, ia) = known[0]
    assert body.omega is not None
    if plan is Plan.VELOCITY:
        return b.add(sid, Op.RIGID_VELOCITY, (ia, body.omega, pa, pos), plan, Kind.POINT, role,
                     label, group, subject=(b.c[pa].label, b.c[pos].label))
    assert body.epsilon is not None
    return b.add(sid, Op.RIGID_ACCELERATION, (ia, body.omega, body.epsilon, pa, pos), plan,
                 Kind.POINT, role, label, group, subject=(b.c[pa].label, b.c[pos].label))


def coincident(b: Builder, link: str, point: str, plan: Plan, group: str) -> str:
    """Image of the point of ``link`` under the named point (e.g. A3: A on the coulisse 3)."""
    if link == GROUND:
        return pole(plan)
    label = (
        (vlabel(point) + link)
        if not any(ch.isdigit() for ch in point)
        else f"{vlabel(point)}_{link}"
    )
    if plan is Plan.ACCELERATION:
        label += "′"
    key = f"{point}@{link}"
    sid = image_on(b, link, key, b.pos[point], label, plan, group, Role.AUXILIARY)
    body = b.bodies[link]
    im = body.image(key)
    if im is None:
        im = Image(key, f"{point}{link}", b.pos[point])
        body.images.append(im)
    if plan is Plan.VELOCITY:
        im.vel = sid
    else:
        im.acc = sid
    return sid


def complete(b: Builder, link: str, plan: Plan, group: str) -> None:
    """Images of every named point of a link, with their absolute segments from the pole."""
    table = b.vel if plan is Plan.VELOCITY else b.acc
    for name in b.mech.links[link].points:
        if name in table:
            continue
        label = vlabel(name) if plan is Plan.VELOCITY else alabel(name)
        table[name] = image_on(b, link, name, b.pos[name], label, plan, group)
        absolute(b, name, plan, group)


def absolute(b: Builder, name: str, plan: Plan, group: str) -> None:
    """Record pole → image of a named point as its absolute velocity/acceleration."""
    table = b.vel if plan is Plan.VELOCITY else b.acc
    pole_label = "p" if plan is Plan.VELOCITY else "π"
    sym = "v" if plan is Plan.VELOCITY else "a"
    sid = table[name]
    if sid == pole(plan):
        return
    b.segment(plan, pole(plan), sid, f"{pole_label}{b.c[sid].label}", f"{sym}_{name}",
              SegmentKind.ABSOLUTE, group)
    b.result(f"{sym}_{name}", sid)


def link_scalar(b: Builder, link: str, source_link: str, plan: Plan, group: str) -> str:
    """ω or ε of a link that turns with another (sliding pair): a copy, or 0 for the frame."""
    attr = "omega" if plan is Plan.VELOCITY else "epsilon"
    sym = "ω" if plan is Plan.VELOCITY else "ε"
    prefix = "vel.omega" if plan is Plan.VELOCITY else "acc.epsilon"
    body = b.bodies[link]
    if getattr(body, attr) is not None:
        known: str = getattr(body, attr)
        return known
    src = getattr(b.bodies[source_link], attr) if source_link != GROUND else None
    if source_link == GROUND:
        sid = b.add(f"{prefix}.{link}", Op.CONSTANT, (), plan, Kind.SCALAR, Role.RESULT,
                    f"{sym}{link}", group, value=0.0)
    else:
        assert src is not None
        sid = b.add(f"{prefix}.{link}", Op.COPY, (src,), plan, Kind.SCALAR, Role.RESULT,
                    f"{sym}{link}", group, subject=(b.c[src].label,))
    setattr(body, attr, sid)
    b.result(f"{attr}_{link}", sid)
    return sid


def perp_line(b: Builder, plan: Plan, through: str, p: str, q: str, group: str) -> str:
    """A line through an image, ⊥ to the link segment PQ."""
    prefix = "vel" if plan is Plan.VELOCITY else "acc"
    return b.add(f"{prefix}.line.{b.c[through].label}.perp.{p}{q}", Op.LINE_PERP,
                 (through, b.pos[p], b.pos[q]), plan, Kind.LINE, Role.AUXILIARY, f"⊥{p}{q}", group,
                 subject=(b.c[through].label, f"{p}{q}"))


def parallel_line(b: Builder, plan: Plan, through: str, locus: str, group: str) -> str:
    """A line through an image, ∥ to a guide (the direction of a locus line)."""
    prefix = "vel" if plan is Plan.VELOCITY else "acc"
    return b.add(f"{prefix}.line.{b.c[through].label}.par.{b.c[locus].label}", Op.LINE_PARALLEL,
                 (through, locus), plan, Kind.LINE, Role.AUXILIARY, f"∥{b.c[locus].label}", group,
                 subject=(b.c[through].label, b.c[locus].label))


def meet_lines(b: Builder, plan: Plan, id: str, l1: str, l2: str, label: str, group: str,
         role: Role = Role.RESULT) -> str:
    """The image where two construction lines meet."""
    return b.add(id, Op.LINE_LINE, (l1, l2), plan, Kind.POINT, role, label, group,
                 subject=(b.c[l1].label, b.c[l2].label))
