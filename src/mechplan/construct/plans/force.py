"""Force plan (kinetostatics): inertia loads, force polygons group by group, balancing moment.

The groups are taken from the one farthest from the drive back to the crank. In each group the
unknown reactions come from moment equations of single links (arms from the position plan) and a
force polygon: the known forces laid head to tail from a pole, closed by two lines of known
direction. The driving link gives the balancing moment and the frame reaction; Zhukovsky's lever
(the velocity plan turned by 90°) gives the balancing moment a second, independent way.

Values: forces are vectors (N, 2) in N, couples and moments (N,) in N·m counter-clockwise
positive, polygon vertices are points of the force plan in N (drawn at μF N/mm).

Results named in ``Construction.results`` (see :func:`pair_key`):
``Q_<link>``, ``M_q<link>``, ``h_<link>`` (inertia force, couple, offset of the single equivalent
force), ``G_<link>`` (weight), ``load_<j>`` (the j-th external load of the loading: a force vector
or a moment), ``R_<ij>`` (force of link i on link j at their pair), ``d_<ij>`` (prismatic pairs:
where the line of action of R_ij crosses the guide, measured along the guide from the pair's
point), ``K_<ij>`` (that crossing point), ``M_b`` (balancing moment on the driving link),
``M_b_zhukovsky`` (the same from Zhukovsky's lever), ``K_q<link>`` (a point of the line of
action of the single equivalent inertia force, |S K| = |h|).
"""

from __future__ import annotations

from ...model.mechanism import GROUND, Pair, PairKind
from ...model.plans import Plan
from ...model.structure import Group, GroupKind, Triad
from ..builder import Builder
from ..graph import reaction_key
from ..ops import Op
from ..segments import SegmentKind
from ..step import Kind, Role
from ..terms import UNKNOWN, Row
from ..terms import parallel as parallel_to
from ..terms import perp as perp_to
from .force_friction import friction_loads
from .force_loads import (
    LoadingLike,
    State,
    Term,
    external_loads,
    group_of,
    inertia_and_weights,
)

F = Plan.FORCE

#: key of the reaction of link i on link j (``"12"``, ``"10,12"``)
pair_key = reaction_key


def emit(b: Builder) -> None:
    """Emit the force plan: loads, groups from the last to the first, the crank, the lever."""
    loading: LoadingLike = b.loading
    loading.check(b.mech)
    st = State(b, loading, {k: [] for k in b.mech.moving})
    inertia_and_weights(st)
    external_loads(st)
    friction_loads(st)
    from . import drivers, force_drivers  # a cylinder or a slider (plans/force_drivers.py)

    for g in reversed(b.structure.groups):
        if isinstance(g, Triad):
            from .triad_force import emit as emit_triad
            emit_triad(st, g)
            continue
        if drivers.cylinder_in(b, g):
            force_drivers.cylinder_group(st, g)
            continue
        {GroupKind.RRR: _rrr, GroupKind.RRP: _rrp, GroupKind.RPR: _rpr, GroupKind.PRP: _prp,
         GroupKind.RPP: _rpp}[g.kind](st, g)
    second = None
    drive2 = b.mech.drive2
    if drive2 is not None:      # W = 2: the second driver's own equilibrium first
        if drive2.kind.value == "slider":       # its polygon closed by the frame's force
            force_drivers.slider_driver(st, second=True)
        second = (b.c.results[f"F_d{drive2.link}"] if drive2.linear
                  else _driving_link(st, second=True))
    if b.mech.drive.linear:
        if b.mech.drive.kind.value == "slider":
            force_drivers.slider_driver(st)
        force_drivers.lever(st, second)
        return
    _driving_link(st)
    _lever(st, second)


def _segment(st: State, start: str, end: str, quantity: str, group: str,
             reaction: bool = False) -> None:
    kind = getattr(SegmentKind, "REACTION" if reaction else "FORCE", None)
    if kind is None:     # the segment kinds of the force plan are not declared yet
        return
    st.b.segment(F, start, end, f"{st.label(start)}{st.label(end)}", quantity, kind, group)


def _moment_sum(st: State, group: str, link: str, about: str, terms: list[Term],
                tag: str) -> str:
    """ΣM about a point of the known loads on a link (forces by their arms, couples)."""
    b = st.b
    inputs: list[str] = [b.pos[about]]
    layout = ""
    for t in terms:
        if t.force is not None:
            assert t.point is not None
            inputs += [t.point, t.force]
            layout += "F"
        if t.couple is not None:
            inputs.append(t.couple)
            layout += "M"
    return st.add(f"force.{group}.sum.{tag}", Op.MOMENT_SUM, tuple(inputs), Kind.SCALAR,
                  Role.AUXILIARY, f"ΣM_{about}({link})", group,
                  subject=(about, link, *[t.label for t in terms]), layout=layout)


def _chain(st: State, group: str, start: str, terms: list[Term]) -> str:
    """Lay the forces of ``terms`` head to tail from ``start``; return the last vertex."""
    vertex = start
    for t in terms:
        if t.force is None:
            continue
        letter = st.letter(group)
        nxt = st.add(f"force.{group}.v.{letter}", Op.FORCE_SUM, (vertex, t.force), Kind.POINT,
                     Role.AUXILIARY, letter, group, subject=(st.label(vertex), t.label))
        _segment(st, vertex, nxt, t.label, group)
        vertex = nxt
    return vertex


def _pole(st: State, group: str) -> str:
    letter = st.letter(group)
    return st.add(f"force.{group}.v.{letter}", Op.POLE, (), Kind.POINT, Role.GIVEN, letter, group)


def _line(st: State, group: str, through: str, tag: str, label: str, *direction_from: str,
          turn: int) -> str:
    return st.add(f"force.{group}.line.{tag}", Op.FORCE_LINE, (through, *direction_from),
                  Kind.LINE, Role.AUXILIARY, label, group,
                  subject=(st.label(through), label), turn=turn)


def _close(st: State, group: str, l1: str, l2: str) -> str:
    letter = st.letter(group)
    return st.add(f"force.{group}.v.{letter}", Op.FORCE_CLOSE, (l1, l2), Kind.POINT, Role.RESULT,
                  letter, group, subject=(st.label(l1), st.label(l2)))


def _between(st: State, group: str, start: str, end: str, label: str, tag: str,
             role: Role = Role.RESULT) -> str:
    """A force read off the polygon: the vector from ``start`` to ``end``."""
    sid = st.add(f"force.{group}.{tag}", Op.DIFFERENCE, (start, end), Kind.POINT, role, label,
                 group, subject=(st.label(start), st.label(end)))
    _segment(st, start, end, label, group, reaction=True)
    return sid


def _guide_angle(st: State, pair: Pair) -> str:
    theta = st.b.bodies[pair.a].angle
    assert theta is not None
    return theta


def _reaction(st: State, group: str, pair: Pair, i: str, j: str, force: str,
              couple: str | None = None, at: str | None = None) -> str:
    """Record R_ij (force of link i on link j) and R_ji; pass R_ji to link i if it is earlier.

    For a prismatic pair ``couple`` is the couple that goes with the force placed at ``at``.
    Returns the step of R_ji.
    """
    b = st.b
    at = at or b.pos[pair.point]
    key, rkey = pair_key(i, j), pair_key(j, i)
    b.result(f"R_{key}", force)
    back = st.add(f"force.R.{rkey}", Op.FORCE_REVERSE, (force,), Kind.POINT, Role.RESULT,
                  f"R_{rkey}", group, subject=(f"R_{key}",))
    b.result(f"R_{rkey}", back)
    back_couple = None
    if couple is not None:
        back_couple = st.add(f"force.M.{rkey}", Op.FORCE_REVERSE, (couple,), Kind.SCALAR,
                             Role.AUXILIARY, f"M_{rkey}", group, subject=(f"M_{key}",))
        theta = _guide_angle(st, pair)
        o = b.pos[pair.point]
        d = st.add(f"force.d.{key}", Op.GUIDE_OFFSET, (o, at, couple, force, theta),
                   Kind.SCALAR, Role.RESULT, f"d_{key}", group,
                   subject=(pair.point, f"R_{key}", pair.guide or ""))
        point = st.add(f"force.K.{key}", Op.LINE_OF_ACTION, (at, force, couple), Kind.POINT,
                       Role.RESULT, f"K_{key}", group, subject=(f"R_{key}", pair.guide or ""))
        for k in (key, rkey):
            b.result(f"d_{k}", d)
            b.result(f"K_{k}", point)
    if i != GROUND and i in st.terms and group_of(b, i) != group:
        st.terms[i].append(Term(f"R_{rkey}", back, at, back_couple))
    return back


def _guide_couple(st: State, group: str, link: str, pair: Pair, terms: list[Term],
                  label: str) -> str:
    """Couple of a guide reaction on ``link`` (force at the pair point) from ΣM = 0 there."""
    total = _moment_sum(st, group, link, pair.point, terms, f"guide.{link}")
    return st.add(f"force.{group}.couple.{link}", Op.MOMENT_CLOSE, (total,), Kind.SCALAR,
                  Role.RESULT, label, group, subject=(st.label(total),))


def _tangential(st: State, group: str, link: str, partner: str, about: str, at: str) -> str:
    """R^t of the outer pair at ``at`` from the moment equation of the link about ``about``."""
    b = st.b
    total = _moment_sum(st, group, link, about, st.terms[link], f"t.{link}")
    return st.add(f"force.{group}.Rt.{partner}{link}", Op.MOMENT_ARM_TANGENTIAL,
                  (b.pos[about], b.pos[at], total), Kind.POINT, Role.RESULT,
                  f"R^t_{pair_key(partner, link)}", group, subject=(at, about, st.label(total)))


def _rows(terms: list[Term]) -> list[Row]:
    return [(t.label, t.direction, t.magnitude) for t in terms if t.force is not None]


def _equation(st: State, group: str, rows: list[Row]) -> None:
    st.b.c.equations[(F, group)] = (" + ".join(r[0] for r in rows) + " = 0", rows)


# -- the five dyads --------------------------------------------------------------------------
def _rrr(st: State, g: Group) -> None:
    b, gn = st.b, g.name
    l1, l2 = g.links
    p1, p2, k = g.outer1.point, g.outer2.point, g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    t1 = _tangential(st, gn, l1, m1, k, p1)
    t2 = _tangential(st, gn, l2, m2, k, p2)
    o = _pole(st, gn)
    a = _chain(st, gn, o, [Term(st.label(t1), t1)])
    v1 = _chain(st, gn, a, st.terms[l1])
    v2 = _chain(st, gn, v1, st.terms[l2])
    e = _chain(st, gn, v2, [Term(st.label(t2), t2)])
    f = _close(st, gn, _line(st, gn, e, "n2", f"∥{p2}{k}", b.pos[p2], b.pos[k], turn=0),
               _line(st, gn, o, "n1", f"∥{p1}{k}", b.pos[p1], b.pos[k], turn=0))
    _between(st, gn, e, f, f"R^n_{pair_key(m2, l2)}", "Rn2", Role.AUXILIARY)
    _between(st, gn, f, o, f"R^n_{pair_key(m1, l1)}", "Rn1", Role.AUXILIARY)
    r1 = _between(st, gn, f, a, f"R_{pair_key(m1, l1)}", "R1")
    r2 = _between(st, gn, v2, f, f"R_{pair_key(m2, l2)}", "R2")
    r21 = _between(st, gn, v1, f, f"R_{pair_key(l2, l1)}", "Rin")
    _reaction(st, gn, g.outer1, m1, l1, r1)
    _reaction(st, gn, g.outer2, m2, l2, r2)
    _reaction(st, gn, g.inner, l2, l1, r21)
    _equation(st, gn, [(st.label(t1), perp_to(f"{p1}{k}"), "✓"), *_rows(st.terms[l1]),
                       *_rows(st.terms[l2]), (st.label(t2), perp_to(f"{p2}{k}"), "✓"),
                       (f"R^n_{pair_key(m2, l2)}", parallel_to(f"{p2}{k}"), "?"),
                       (f"R^n_{pair_key(m1, l1)}", parallel_to(f"{p1}{k}"), "?")])


def _rrp(st: State, g: Group) -> None:
    b, gn = st.b, g.name
    l1, l2 = g.links
    p1, k = g.outer1.point, g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    guide = g.outer2.guide or ""
    t1 = _tangential(st, gn, l1, m1, k, p1)
    o = _pole(st, gn)
    a = _chain(st, gn, o, [Term(st.label(t1), t1)])
    v1 = _chain(st, gn, a, st.terms[l1])
    e = _chain(st, gn, v1, st.terms[l2])
    f = _close(st, gn, _line(st, gn, e, "g2", f"⊥{guide}", _guide_angle(st, g.outer2), turn=90),
               _line(st, gn, o, "n1", f"∥{p1}{k}", b.pos[p1], b.pos[k], turn=0))
    _between(st, gn, f, o, f"R^n_{pair_key(m1, l1)}", "Rn1", Role.AUXILIARY)
    r1 = _between(st, gn, f, a, f"R_{pair_key(m1, l1)}", "R1")
    r2 = _between(st, gn, e, f, f"R_{pair_key(m2, l2)}", "R2")
    r21 = _between(st, gn, v1, f, f"R_{pair_key(l2, l1)}", "Rin")
    _reaction(st, gn, g.outer1, m1, l1, r1)
    r12 = _reaction(st, gn, g.inner, l2, l1, r21)
    couple = _guide_couple(st, gn, l2, g.outer2,
                           [*st.terms[l2], Term(f"R_{pair_key(l1, l2)}", r12, b.pos[k])],
                           f"M_{pair_key(m2, l2)}")
    _reaction(st, gn, g.outer2, m2, l2, r2, couple)
    _equation(st, gn, [(st.label(t1), perp_to(f"{p1}{k}"), "✓"), *_rows(st.terms[l1]),
                       *_rows(st.terms[l2]), (f"R_{pair_key(m2, l2)}", perp_to(f"{guide}"), "?"),
                       (f"R^n_{pair_key(m1, l1)}", parallel_to(f"{p1}{k}"), "?")])


def _rpr(st: State, g: Group) -> None:
    b, gn = st.b, g.name
    s, c = g.inner.a, g.inner.b
    outer = {g.links[0]: g.outer1, g.links[1]: g.outer2}
    ps, pc = outer[s].point, outer[c].point
    ms, mc = outer[s].other(s), outer[c].other(c)
    guide = g.inner.guide or ""
    theta = _guide_angle(st, g.inner)
    # the slider: ΣM about its pin gives the couple of the guide reaction placed at the pin
    m_total = _moment_sum(st, gn, s, ps, st.terms[s], f"guide.{s}")
    m_cs = st.add(f"force.{gn}.couple.{s}", Op.MOMENT_CLOSE, (m_total,), Kind.SCALAR,
                  Role.RESULT, f"M_{pair_key(c, s)}", gn, subject=(st.label(m_total),))
    m_sc = st.add(f"force.{gn}.couple.{c}", Op.FORCE_REVERSE, (m_cs,), Kind.SCALAR,
                  Role.AUXILIARY, f"M_{pair_key(s, c)}", gn, subject=(f"M_{pair_key(c, s)}",))
    # the guide carrier: ΣM about its pivot gives the reaction ⊥ the guide (arm along the guide)
    c_total = _moment_sum(st, gn, c, pc, [*st.terms[c], Term(f"M_{pair_key(s, c)}", couple=m_sc)],
                          f"t.{c}")
    r_sc = st.add(f"force.{gn}.Rt.{s}{c}", Op.MOMENT_ARM_TANGENTIAL,
                  (b.pos[pc], b.pos[ps], c_total, theta), Kind.POINT, Role.RESULT,
                  f"R_{pair_key(s, c)}", gn, subject=(ps, pc, st.label(c_total), guide))
    o = _pole(st, gn)
    x = _chain(st, gn, o, st.terms[s])
    z = _chain(st, gn, x, st.terms[c])
    back = _reaction(st, gn, g.inner, s, c, r_sc, m_sc, b.pos[ps])
    y = _chain(st, gn, x, [Term(f"R_{pair_key(c, s)}", back)])
    r_s = _between(st, gn, y, o, f"R_{pair_key(ms, s)}", "Rs")
    r_c = _between(st, gn, z, y, f"R_{pair_key(mc, c)}", "Rc")
    _reaction(st, gn, outer[s], ms, s, r_s)
    _reaction(st, gn, outer[c], mc, c, r_c)
    _equation(st, gn, [*_rows(st.terms[s]), (f"R_{pair_key(c, s)}", perp_to(f"{guide}"), "✓"),
                       (f"R_{pair_key(ms, s)}", UNKNOWN, "?")])


def _prp(st: State, g: Group) -> None:
    b, gn = st.b, g.name
    l1, l2 = g.links
    k = g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    g1, g2 = g.outer1.guide or "", g.outer2.guide or ""
    o = _pole(st, gn)
    v1 = _chain(st, gn, o, st.terms[l1])
    e = _chain(st, gn, v1, st.terms[l2])
    f = _close(st, gn, _line(st, gn, e, "g2", f"⊥{g2}", _guide_angle(st, g.outer2), turn=90),
               _line(st, gn, o, "g1", f"⊥{g1}", _guide_angle(st, g.outer1), turn=90))
    r1 = _between(st, gn, f, o, f"R_{pair_key(m1, l1)}", "R1")
    r2 = _between(st, gn, e, f, f"R_{pair_key(m2, l2)}", "R2")
    r21 = _between(st, gn, v1, f, f"R_{pair_key(l2, l1)}", "Rin")
    r12 = _reaction(st, gn, g.inner, l2, l1, r21)
    c1 = _guide_couple(st, gn, l1, g.outer1,
                       [*st.terms[l1], Term(f"R_{pair_key(l2, l1)}", r21, b.pos[k])],
                       f"M_{pair_key(m1, l1)}")
    c2 = _guide_couple(st, gn, l2, g.outer2,
                       [*st.terms[l2], Term(f"R_{pair_key(l1, l2)}", r12, b.pos[k])],
                       f"M_{pair_key(m2, l2)}")
    _reaction(st, gn, g.outer1, m1, l1, r1, c1)
    _reaction(st, gn, g.outer2, m2, l2, r2, c2)
    _equation(st, gn, [*_rows(st.terms[l1]), *_rows(st.terms[l2]),
                       (f"R_{pair_key(m2, l2)}", perp_to(f"{g2}"), "?"),
                       (f"R_{pair_key(m1, l1)}", perp_to(f"{g1}"), "?")])


def _rpp(st: State, g: Group) -> None:
    b, gn = st.b, g.name
    l1, l2 = g.links
    p1, oi = g.outer1.point, g.inner.point
    m1, m2 = g.outer1.other(l1), g.outer2.other(l2)
    gi, go = g.inner.guide or "", g.outer2.guide or ""
    o = _pole(st, gn)
    e = _chain(st, gn, o, st.terms[l2])
    f = _close(st, gn, _line(st, gn, e, "g2", f"⊥{go}", _guide_angle(st, g.outer2), turn=90),
               _line(st, gn, o, "gi", f"⊥{gi}", _guide_angle(st, g.inner), turn=90))
    r2 = _between(st, gn, e, f, f"R_{pair_key(m2, l2)}", "R2")
    r12 = _between(st, gn, f, o, f"R_{pair_key(l1, l2)}", "Rin")
    gv = _chain(st, gn, f, st.terms[l1])
    r1 = _between(st, gn, gv, o, f"R_{pair_key(m1, l1)}", "R1")
    r21 = st.add(f"force.{gn}.Rin.back", Op.FORCE_REVERSE, (r12,), Kind.POINT, Role.AUXILIARY,
                 f"R_{pair_key(l2, l1)}", gn, subject=(f"R_{pair_key(l1, l2)}",))
    # link 1 about its pin: the couple of the inner guide reaction (force at the pair point)
    total1 = _moment_sum(st, gn, l1, p1, [*st.terms[l1], Term(f"R_{pair_key(l2, l1)}", r21,
                                                              b.pos[oi])], f"guide.{l1}")
    c21 = st.add(f"force.{gn}.couple.{l1}", Op.MOMENT_CLOSE, (total1,), Kind.SCALAR,
                 Role.RESULT, f"M_{pair_key(l2, l1)}", gn, subject=(st.label(total1),))
    c12 = st.add(f"force.{gn}.couple.{l1}.back", Op.FORCE_REVERSE, (c21,), Kind.SCALAR,
                 Role.AUXILIARY, f"M_{pair_key(l1, l2)}", gn, subject=(f"M_{pair_key(l2, l1)}",))
    c2 = _guide_couple(st, gn, l2, g.outer2,
                       [*st.terms[l2], Term(f"R_{pair_key(l1, l2)}", r12, b.pos[oi], c12)],
                       f"M_{pair_key(m2, l2)}")
    _reaction(st, gn, g.inner, l1, l2, r12, c12)
    _reaction(st, gn, g.outer1, m1, l1, r1)
    _reaction(st, gn, g.outer2, m2, l2, r2, c2)
    _equation(st, gn, [*_rows(st.terms[l2]), (f"R_{pair_key(m2, l2)}", perp_to(f"{go}"), "?"),
                       (f"R_{pair_key(l1, l2)}", perp_to(f"{gi}"), "?")])


# -- the driving link and Zhukovsky's lever --------------------------------------------------
def _driving_link(st: State, second: bool = False) -> str:
    """A driving crank's own equilibrium: M_b from ΣM about its pivot, R_0k closing its polygon.

    ``second``: the second crank of a mechanism with W = 2 (its moment ``M_b{link}``)."""
    b = st.b
    drive = b.mech.drive2 if second else b.mech.drive
    assert drive is not None
    link, pivot = drive.link, drive.pivot
    gn = f"I({GROUND},{link})"
    terms = st.terms[link]
    total = _moment_sum(st, gn, link, pivot, terms, "drive")
    sid, label = ("force.M_b", "M_b") if not second else (f"force.M_b.{link}", f"M_b{link}")
    mb = st.add(sid, Op.BALANCING_MOMENT, (total,), Kind.SCALAR, Role.RESULT, label, gn,
                subject=(pivot, link, st.label(total)))
    b.result(label, mb)
    o = _pole(st, gn)
    e = _chain(st, gn, o, terms)
    r01 = _between(st, gn, e, o, f"R_{pair_key(GROUND, link)}", "R01")
    pair = next(p for p in b.mech.pairs_of(link)
                if p.other(link) == GROUND and p.kind is PairKind.REVOLUTE)
    _reaction(st, gn, pair, GROUND, link, r01)
    _equation(st, gn, [*_rows(terms), (f"R_{pair_key(GROUND, link)}", UNKNOWN, "?")])
    return mb


def lever_loads(st: State) -> tuple[list[str], str, list[str]]:
    """Every applied load as Zhukovsky's lever takes it: its step inputs (a force with the
    velocity image of its point, a couple with its link's ω), their layout ("F"/"M") and labels."""
    b = st.b
    inputs: list[str] = []
    layout, labels = "", []
    for link, t in st.applied:
        if t.force is not None:
            inputs += [t.velocity or b.vel[t.where], t.force]
            layout += "F"
            labels.append(t.label)
        if t.couple is not None:
            omega = b.bodies[link].omega
            assert omega is not None
            inputs += [t.couple, omega]
            layout += "M"
            labels.append(t.label)
    return inputs, layout, labels


def second_on_lever(st: State, second: str | None, inputs: list[str], layout: str,
                    labels: list[str]) -> tuple[list[str], str, list[str]]:
    """The second driver's known load as one more term of the lever (W = 2): a crank's M_b by its
    ω (``M``: −M·ω), a cylinder's F_d by its l̇ (its power F_d·l̇, the same form)."""
    drive2 = st.b.mech.drive2
    if second is None or drive2 is None:
        return inputs, layout, labels
    rate = "vel.rate2" if drive2.linear else st.b.bodies[drive2.link].omega
    assert rate is not None
    return [*inputs, second, rate], layout + "M", [*labels, st.label(second)]


def _lever(st: State, second: str | None = None) -> None:
    """Zhukovsky's lever: every load at its velocity image turned by 90°, moments about p.

    With a second crank (W = 2) its balancing moment ``second`` (from its own polygon) is one
    more couple on the lever: the lever then gives the first crank's M_b.
    """
    b = st.b
    drive = b.mech.drive
    omega1 = b.bodies[drive.link].omega
    assert omega1 is not None
    loads, layout, labels = lever_loads(st)
    inputs: list[str] = [omega1, *loads]
    inputs, layout, labels = second_on_lever(st, second, inputs, layout, labels)
    sid = st.add("force.M_b.zhukovsky", Op.ZHUKOVSKY, tuple(inputs), Kind.SCALAR, Role.RESULT,
                 "M_b", "lever", subject=tuple(labels), layout=layout)
    b.result("M_b_zhukovsky", sid)


__all__ = ["LoadingLike", "Term", "emit", "pair_key"]
