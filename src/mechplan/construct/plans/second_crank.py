"""The second driver of a mechanism with W = 2 (``[drive2]``): its first-class mechanism.

A second cylinder (crank + cylinder, two cylinders) is a coordinate only: its length l2 follows
the first driver's coordinate by its law (``SECOND_DRIVER_LENGTH``), its rates l̇2, l̈2 are given
(``DRIVER_RATE``, steps ``pos.q2``, ``vel.rate2``, ``acc.rate2``); the group it closes is then
built like the first cylinder's (``plans/drivers.py``). A second crank:

Built after the first crank and before the groups, as the course does with I(0,1), I(0,4) →
II(2,3): its angle θ2 follows the common parameter by its law (``SECOND_CRANK_ANGLE``), its points
are laid off at their lengths (``POLAR_POINT``); on the velocity plan its pin's image is
ω2 × l ⊥ the crank (``DRIVE_VELOCITY``), on the acceleration plan ω2²·l towards the pivot plus
ε2·l ⊥ the crank (``DRIVE_ACCELERATION``). The groups between the two cranks then close as usual.
"""

from __future__ import annotations

from ...model.mechanism import GROUND, Drive, DriverKind
from ...model.plans import Plan
from ..builder import Builder, alabel, vlabel
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import from_to, perp
from .images import absolute, complete
from .position import _local_angle

P, V, A = Plan.POSITION, Plan.VELOCITY, Plan.ACCELERATION


def group_name(drive: Drive) -> str:
    """The second crank's first-class mechanism, ``I(0,4)``."""
    return f"I({GROUND},{drive.link})"


def _tip(b: Builder, drive: Drive) -> str:
    return next(p for p in b.mech.links[drive.link].points if p != drive.pivot)


def law(first: Drive, second: Drive) -> tuple[float, float]:
    """(offset, ratio) of the second driver's step value = offset + ratio·(the first's step value).

    The first's step value x is θ1 (a crank, rad) or q1 (a linear driver, m); its progress
    u1 = s1·(θ1 − ref1) or q1 − q1⁰ (the range's start) at its rate r1 = |ω1| or q̇1, so at
    constant rates the time from the reference is u1/r1. The second's coordinate there is
    φ2 = phase + |ω2|·t (a crank: θ2 = ref2 + s2·φ2) or l2 = start + l̇2·t (a cylinder).
    """
    if first.linear:
        rate1, sense1 = first.omega, 1.0
        ref1 = first.q_range[0] if first.q_range is not None else 0.0
    else:
        rate1, sense1, ref1 = abs(first.omega), float(first.sense), first.ref_angle
    if second.linear:
        k = second.omega / rate1
        return second.phase - k * sense1 * ref1, k * sense1
    speed = abs(second.omega) / rate1
    ratio = second.sense * speed * sense1
    offset = second.ref_angle + second.sense * (second.phase - speed * sense1 * ref1)
    return offset, ratio


def _first_step(b: Builder) -> str:
    return "pos.q" if b.mech.drive.linear else "pos.phi1"


def _linear_group(b: Builder) -> str:
    cyl = b.structure.cylinder2
    if cyl is None:         # a slider on a frame guide: I(0,k) (plans/second_slider.py)
        assert b.mech.drive2 is not None
        return group_name(b.mech.drive2)
    return f"I({cyl[0]},{cyl[1]})"


def _emit_linear(b: Builder, plan: Plan) -> None:
    """A second cylinder: its length by its law, or its given rate l̇2 / l̈2."""
    drive = b.mech.drive2
    assert drive is not None
    group = _linear_group(b)
    from .laws import by_table, law_step
    from .second_slider import emit as emit_slider

    slider = drive.kind is DriverKind.SLIDER
    symbol = "s" if slider else "l"
    if plan is P:
        b.c.second_driver = drive.link
        if by_table(b):     # a law by a table: the length at the position's time
            sid = law_step(b, "pos.q2", drive, 0, P, f"{symbol}{drive.link}", group)
        else:
            offset, ratio = law(b.mech.drive, drive)
            op = Op.SECOND_SLIDER_POSITION if slider else Op.SECOND_DRIVER_LENGTH
            sid = b.add("pos.q2", op, (_first_step(b),), P, Kind.SCALAR,
                        Role.GIVEN, f"{symbol}{drive.link}", group,
                        subject=(b.mech.drive.link, drive.link), offset=offset, ratio=ratio)
        b.result(f"q_{drive.link}", sid)
    else:
        dot = "̇" if plan is V else "̈"
        value = drive.omega if plan is V else drive.epsilon
        prefix = "vel" if plan is V else "acc"
        if drive.law is not None:
            law_step(b, f"{prefix}.rate2", drive, 1 if plan is V else 2, plan,
                     f"{symbol}{dot}{drive.link}", group)
        else:
            b.add(f"{prefix}.rate2", Op.DRIVER_RATE, (), plan, Kind.SCALAR, Role.GIVEN,
                  f"{symbol}{dot}{drive.link}", group, value=value)
    if slider:              # its point on the frame guide and its images
        emit_slider(b, plan, group)


def emit_position(b: Builder) -> None:
    """The second crank's angle from the first's, and its points."""
    drive = b.mech.drive2
    if drive is None:
        return
    if drive.linear:
        _emit_linear(b, P)
        return
    group = group_name(drive)
    b.c.second_driver = drive.link
    offset, ratio = law(b.mech.drive, drive)
    crank = b.mech.links[drive.link]
    pivot = drive.pivot
    tip = _tip(b, drive)
    from .crank_law import angle

    theta = angle(b, drive, group) or b.add(
        f"pos.phi.{drive.link}", Op.SECOND_CRANK_ANGLE, (_first_step(b),), P, Kind.SCALAR,
        Role.GIVEN, f"θ{drive.link}", group, subject=(b.mech.drive.link, drive.link),
        offset=offset, ratio=ratio)
    base = _local_angle(b, drive.link, pivot, tip)
    for name in crank.points:
        if name == pivot:
            continue
        b.pos[name] = b.add(f"pos.{name}", Op.POLAR_POINT, (b.pos[pivot], theta), P, Kind.POINT,
                            Role.RESULT, name, group=group, subject=(pivot, name),
                            length=crank.distance(pivot, name),
                            offset=_local_angle(b, drive.link, pivot, name) - base)
        b.segment(P, b.pos[pivot], b.pos[name], f"{pivot}{name}", f"l_{pivot}{name}",
                  SegmentKind.LINK, group)
    body = b.bodies[drive.link]
    body.anchor = pivot
    body.angle = theta if base == 0.0 else b.add(
        f"pos.angle.{drive.link}", Op.ANGLE_PLUS, (theta,), P, Kind.SCALAR, Role.AUXILIARY,
        f"θ{drive.link}", group, delta=-base)
    b.result(f"angle_{drive.link}", body.angle)


def emit_velocity(b: Builder) -> None:
    """ω2 (given by its law) and the image of its pin: pc ⊥ the crank."""
    drive = b.mech.drive2
    if drive is None:
        return
    if drive.linear:
        _emit_linear(b, V)
        return
    group, tip = group_name(drive), _tip(b, drive)
    body = b.bodies[drive.link]
    from .crank_law import rate, sizes

    by_law, omega = rate(b, drive, V, group), drive.omega
    if by_law is None:
        body.omega = b.add(f"vel.omega.{drive.link}", Op.CONSTANT, (), V, Kind.SCALAR,
                           Role.GIVEN, f"ω{drive.link}", group, value=drive.omega)
    else:                   # a law by a table: ω2 of each position (plans/crank_law.py)
        body.omega, omega = by_law, sizes(drive)[0]
    b.result(f"omega_{drive.link}", body.omega)
    b.vel[tip] = b.add(f"vel.{tip}", Op.DRIVE_VELOCITY,
                       (b.pos[drive.pivot], b.pos[tip], *(() if by_law is None else (by_law,))),
                       V, Kind.POINT, Role.RESULT, vlabel(tip), group, subject=(drive.pivot, tip),
                       omega=omega)
    b.c.equations[(V, group)] = (
        f"v_{tip} = ω{drive.link} × l_{drive.pivot}{tip}",
        [(f"v_{tip}", perp(f"{drive.pivot}{tip}"), f"ω{drive.link}·l_{drive.pivot}{tip}")])
    absolute(b, tip, V, group)
    complete(b, drive.link, V, group)


def emit_acceleration(b: Builder) -> None:
    """ε2 (given by its law) and the image of its pin: normal and tangential parts."""
    drive = b.mech.drive2
    if drive is None:
        return
    if drive.linear:
        _emit_linear(b, A)
        return
    group, tip = group_name(drive), _tip(b, drive)
    body = b.bodies[drive.link]
    from .crank_law import rate, sizes

    by_law, rates = rate(b, drive, A, group), (drive.omega, drive.epsilon)
    extra: tuple[str, ...] = ()
    if by_law is None:
        body.epsilon = b.add(f"acc.epsilon.{drive.link}", Op.CONSTANT, (), A, Kind.SCALAR,
                             Role.GIVEN, f"ε{drive.link}", group, value=drive.epsilon)
    else:                   # a law by a table: ω2 and ε2 of each position
        assert body.omega is not None
        body.epsilon, rates, extra = by_law, sizes(drive), (body.omega, by_law)
    b.result(f"epsilon_{drive.link}", body.epsilon)
    b.acc[tip] = b.add(f"acc.{tip}", Op.DRIVE_ACCELERATION,
                       (b.pos[drive.pivot], b.pos[tip], *extra), A,
                       Kind.POINT, Role.RESULT, alabel(tip), group, subject=(drive.pivot, tip),
                       omega=rates[0], epsilon=rates[1])
    rows = [(f"a^n_{tip}", from_to(tip, drive.pivot), f"ω{drive.link}²·l_{drive.pivot}{tip}")]
    if rates[1]:
        rows.append((f"a^t_{tip}", perp(f"{drive.pivot}{tip}"),
                     f"ε{drive.link}·l_{drive.pivot}{tip}"))
    b.c.equations[(A, group)] = (f"a_{tip} = a^n_{tip} + a^t_{tip}", rows)
    absolute(b, tip, A, group)
    complete(b, drive.link, A, group)
