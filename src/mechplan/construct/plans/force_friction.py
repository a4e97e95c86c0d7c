"""Friction in the pairs as known loads of the force plan (the courses' iteration).

A revolute pair with friction coefficient f and pin radius r carries a friction couple
M_f = f·r·|R| (the reaction is tangent to the friction circle ρ = f·r) against the relative
rotation; a prismatic pair a friction force f·|N| along the guide against the sliding velocity
relative to the guide's link, and the opposite force on that link when it moves (the total
reaction is tilted by the friction angle φ = atan f). The sizes come from the reactions of the
previous pass (:func:`~mechplan.construct.ops.force.friction_iterate`): the first pass is
friction-free.

Results: ``M_b0`` (the friction-free balancing moment), ``Mf_<ij>`` (the friction couple on link
j from link i of a revolute pair, the frame first), ``Ff_<ij>`` (the friction force on the slider
j from the guide's link i of a prismatic pair).
"""

from __future__ import annotations

from ...errors import SceneError
from ...i18n import Text
from ...model.loads import pair_id
from ...model.mechanism import GROUND, PairKind
from ...model.plans import Plan
from ..graph import Construction, Evaluation, reaction_key
from ..ops import Op
from ..ops.force import FrictionLoop
from ..step import Kind, Role
from ..terms import Direction, Relation
from .force_loads import State, Term, add_load, group_of

F = Plan.FORCE


def friction_loads(st: State) -> None:
    """Emit the friction iteration and each pair's friction load (pairs with f > 0)."""
    spec = getattr(st.loading, "friction", None)
    if spec is None:
        return
    b = st.b
    drive = b.mech.drive
    if drive.linear:        # the iteration closes on the first crank's balancing moment only
        raise SceneError(Text("excavload.friction.linear_driver",
                              {"kind": drive.kind.value, "link": drive.link}),
                         file=b.file, key=spec.key)
    pairs = [p for p in b.mech.pairs if spec.of(p.a, p.b).f > 0
             and (p.kind is PairKind.PRISMATIC or spec.of(p.a, p.b).radius > 0)]
    carriers: dict[int, str] = {}
    for index, p in enumerate(pairs):
        if p.kind is PairKind.PRISMATIC and p.b != GROUND:
            image = b.bodies[p.b].image(f"{p.point}@{p.b}")
            if image is None or image.vel is None or p.a == GROUND:
                raise SceneError(
                    Text("errmsg2.plans.friction_carrier",
                         {"pair": pair_id(p.a, p.b), "link": p.b, "point": p.point}),
                    file=b.file, key=f"{spec.key}.pairs.{pair_id(p.a, p.b)}")
            carriers[index] = image.vel
    loop = FrictionLoop(b.c, tuple(f"R_{reaction_key(p.a, p.b)}" for p in pairs),
                        tolerance=spec.tolerance, max_iterations=spec.max_iterations)
    gn = f"I({GROUND},{drive.link})"
    it = st.add("force.friction", Op.FRICTION_ITERATE, ("pos.phi1",), Kind.SCALAR, Role.RESULT,
                "M_b⁰", gn, subject=(), loop=loop)
    b.result("M_b0", it)
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
                       index=index, rho=fr.rho)
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
        moving = (carriers[index],) if index in carriers else ()
        f = st.add(f"force.friction.F.{key}", Op.FRICTION_FORCE,
                   (it, b.vel[p.point], theta, *moving), Kind.POINT, Role.GIVEN, label,
                   group_of(b, slider), subject=(p.point, p.guide or ""), index=index, f=fr.f)
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
                                       velocity=carriers[index]))


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
