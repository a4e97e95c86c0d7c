"""Friction in the pairs as known loads of the force plan (the courses' iteration).

A revolute pair with friction coefficient f and pin radius r carries a friction couple
M_f = f·r·|R| (the reaction is tangent to the friction circle ρ = f·r) against the relative
rotation; a prismatic pair a friction force f·|N| along the guide against the sliding velocity
relative to the guide's link, and the opposite force on that link when it moves (the total
reaction is tilted by the friction angle φ = atan f). The sizes come from the reactions of the
previous pass (:func:`~mechplan.construct.ops.force.friction_iterate`): the first pass is
friction-free.

A linear first driver (cylinder, slider on a frame guide) likewise: the passes close on its
driving force F_d, and the driving cylinder's own sliding pair (rod in barrel) takes friction
against l̇, read on the velocity plan as the segment of the rod's sliding.

Results: ``M_b0`` (the friction-free balancing moment; a linear driver's F_d⁰), ``M_b0_second``
(W = 2: the second driver's M_b⁰ or F_d⁰ of the same friction-free pass), ``Mf_<ij>``
(the friction couple on link j from link i of a revolute pair, the frame first), ``Ff_<ij>`` (the
friction force on the slider j from the guide's link i of a prismatic pair).
"""

from __future__ import annotations

from ...errors import SceneError
from ...i18n import Text
from ...model.loads import pair_id
from ...model.mechanism import GROUND, Pair, PairKind
from ...model.plans import Plan
from ..builder import Builder
from ..graph import Construction, Evaluation, reaction_key
from ..ops import Op
from ..ops.force import FrictionLoop
from ..step import Kind, Role
from ..terms import Direction, Relation
from .drivers import cylinders, first_group
from .force_loads import State, Term, add_load, group_of
from .laws import first_step

F = Plan.FORCE
#: a relative rate below this share of the drivers' speeds leaves friction's sense open
UNDEFINED = 1e-9
#: the result of a second driver's friction-free M_b⁰ or F_d⁰ (W = 2)
SECOND_FREE = "M_b0_second"


def friction_loads(st: State) -> None:
    """Emit the friction iteration and each pair's friction load (pairs with f > 0)."""
    spec = getattr(st.loading, "friction", None)
    if spec is None:
        return
    b = st.b
    drive = b.mech.drive
    pairs = [p for p in b.mech.pairs if spec.of(p.a, p.b).f > 0
             and (p.kind is PairKind.PRISMATIC or spec.of(p.a, p.b).radius > 0)]
    carriers: dict[int, str | tuple[str, str]] = {}
    for index, p in enumerate(pairs):
        if p.kind is PairKind.PRISMATIC and p.b != GROUND:
            sliding = _cylinder_sliding(b, p)
            if sliding is not None:
                carriers[index] = sliding
                continue
            image = b.bodies[p.b].image(f"{p.point}@{p.b}")
            if image is None or image.vel is None or p.a == GROUND:
                raise SceneError(
                    Text("errmsg2.plans.friction_carrier",
                         {"pair": pair_id(p.a, p.b), "link": p.b, "point": p.point}),
                    file=b.file, key=f"{spec.key}.pairs.{pair_id(p.a, p.b)}")
            carriers[index] = image.vel
    # a linear driver (cylinder, slider): the passes close on its driving force F_d; a second
    # driver (W = 2) on its own M_b or F_d, found in the same passes
    drive2 = b.mech.drive2
    second = None if drive2 is None else f"{'F_d' if drive2.linear else 'M_b'}{drive2.link}"
    loop = FrictionLoop(b.c, tuple(f"R_{reaction_key(p.a, p.b)}" for p in pairs),
                        balancing="F_d" if drive.linear else "M_b",
                        tolerance=spec.tolerance, max_iterations=spec.max_iterations,
                        others=() if second is None else (second,))
    # a relative rate this small against the drivers' speeds has no sense (friction zero there,
    # as the analysis flags it): two links turning alike, a held cylinder's rod in its barrel
    still = UNDEFINED * max(abs(drive.omega), abs(drive2.omega) if drive2 is not None else 0.0)
    gn = first_group(b) if drive.linear else f"I({GROUND},{drive.link})"
    it = st.add("force.friction", Op.FRICTION_ITERATE, (first_step(b),), Kind.SCALAR,
                Role.RESULT, "F_d⁰" if drive.linear else "M_b⁰", gn, subject=(), loop=loop)
    b.result("M_b0", it)
    if drive2 is not None and second is not None:   # its M_b⁰ or F_d⁰ of the friction-free pass
        free2 = st.add("force.friction.second", Op.FRICTION_FREE, (it,), Kind.SCALAR,
                       Role.RESULT, f"{second}⁰", group_of(b, drive2.link), subject=(),
                       result=second)
        b.result(SECOND_FREE, free2)
    for index, p in enumerate(pairs):
        fr = spec.of(p.a, p.b)
        key = reaction_key(p.a, p.b)
        if p.kind is PairKind.REVOLUTE:
            # the couple on b from a; a frame side gets none (the frame does not move)
            if p.b == GROUND:
                first, second = p.b, p.a
            else:
                first, second = p.a, p.b
            omegas = [w for w in (b.bodies[second].omega,
                                  None if first == GROUND else b.bodies[first].omega)
                      if w is not None]
            label = f"M^f_{reaction_key(first, second)}"
            m = st.add(f"force.friction.M.{key}", Op.FRICTION_COUPLE, (it, *omegas), Kind.SCALAR,
                       Role.GIVEN, label, group_of(b, second), subject=(p.point, first, second),
                       index=index, rho=fr.rho, still=still)
            b.result(f"Mf_{reaction_key(first, second)}", m)
            add_load(st, second, Term(label, couple=m,
                                      direction=Direction(Relation.AGAINST,
                                                          f"ω{second}−ω{first}"),
                                      magnitude="f·r·|R|"))
            if first != GROUND:
                back = st.add(f"force.friction.M.{key}.back", Op.FORCE_REVERSE, (m,),
                              Kind.SCALAR, Role.GIVEN, f"M^f_{reaction_key(second, first)}",
                              group_of(b, first), subject=(label,))
                add_load(st, first, Term(f"M^f_{reaction_key(second, first)}", couple=back,
                                         magnitude="f·r·|R|"))
            continue
        slider, carrier = p.a, p.b
        theta = b.bodies[p.a].angle
        assert theta is not None
        label = f"F^f_{reaction_key(carrier, slider)}"
        held = carriers.get(index)
        # a driving cylinder's own pair: the rod's sliding in the barrel, l̇ along the axis, is
        # the segment between two images of the velocity plan (v_E and the end of l̇ from it)
        velocity = held[0] if isinstance(held, tuple) else b.vel[p.point]
        moving: tuple[str, ...] = ((held[1],) if isinstance(held, tuple) else
                                   (held,) if held is not None else ())
        f = st.add(f"force.friction.F.{key}", Op.FRICTION_FORCE,
                   (it, velocity, theta, *moving), Kind.POINT, Role.GIVEN, label,
                   group_of(b, slider), subject=(p.point, p.guide or ""), index=index, f=fr.f,
                   still=still)
        b.result(f"Ff_{reaction_key(carrier, slider)}", f)
        relative = f"v_{p.point}{slider}{carrier}" if moving else f"v_{p.point}"
        add_load(st, slider, Term(label, f, b.pos[p.point],
                                  direction=Direction(Relation.SYMBOL,
                                                      f"∥ {p.guide}, −{relative}"),
                                  magnitude="f·|N|", where=p.point))
        if moving:
            back_label = f"F^f_{reaction_key(slider, carrier)}"
            back = st.add(f"force.friction.F.{key}.back", Op.FORCE_REVERSE, (f,), Kind.POINT,
                          Role.GIVEN, back_label, group_of(b, carrier), subject=(label,))
            add_load(st, carrier, Term(back_label, back, b.pos[p.point],
                                       direction=Direction(Relation.OPPOSITE, label),
                                       magnitude="f·|N|", where=p.point,
                                       velocity=moving[0]))


def _cylinder_sliding(b: Builder, p: Pair) -> tuple[str, str] | None:
    """A driving cylinder's pair (rod p.a in barrel p.b): the two images of the velocity plan
    whose difference is the rod's velocity relative to the barrel, l̇ from the barrel's pin
    towards the rod's (the step ``vel.r.<K><E>`` is v_E + l̇ along E→K), else None."""
    if not any(c.rod == p.a and c.barrel == p.b for c in cylinders(b)):
        return None
    pin = p.point                                       # the rod's pin
    pivot = b.mech.guides[p.guide or ""].through        # the barrel's
    if f"vel.r.{pin}{pivot}" in b.c.steps:              # the rod's pin is K: r − v_E
        return f"vel.r.{pin}{pivot}", b.vel[pivot]
    if f"vel.r.{pivot}{pin}" in b.c.steps:              # the barrel's pin is K: v_E − r
        return b.vel[pin], f"vel.r.{pivot}{pin}"
    return None


def unsettled(c: Construction, ev: Evaluation, k: int) -> str | None:
    """Why position k has no force plan if the friction passes did not settle there, else None."""
    sid = c.results.get("M_b0")
    info = ev.shared.get(("friction", sid)) if sid is not None else None
    if info is None or not info["residual"][k] > info["tolerance"]:
        return None
    return (f"the friction iteration does not settle (after {info['passes']} passes the reactions "
            f"still change by {float(info['residual'][k]):.1e} of themselves): with these friction "
            "coefficients the mechanism self-locks here, the driving link cannot move it; choose "
            "another position or smaller friction coefficients")
