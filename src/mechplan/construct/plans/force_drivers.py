"""Force plan of the linear drivers: the cylinder's group and the driving force.

The cylinder's group (a link and the cylinder, barrel and rod) is solved as an RRR dyad whose one
side is the cylinder taken whole: R^t at each outer pair from the moments about the inner pin (the
cylinder's loads are the barrel's and the rod's), then the polygon closed by lines ∥ the two
sides. The rod alone then gives the force of the barrel on it: its polygon (its loads and the force
at its pin) closes with R_barrel→rod, whose component along the cylinder is the **driving force**
F_d (the pressure's force, + pushing the rod out) and whose rest, ⊥ the axis, is the reaction of
the pair (with its couple, from the rod's moments about its pin). A slider driven on a frame guide
likewise: the frame's force closes the slider's polygon; along the guide it is F_d.

Zhukovsky's lever checks F_d: −ΣP/q̇ of the loads at their velocity images (the virtual power of
the loads and F_d·q̇ sum to zero).
"""

from __future__ import annotations

from ...model.mechanism import GROUND, DriverKind, Pair, PairKind
from ...model.structure import Group
from ..ops import Op
from ..step import Kind, Role
from ..terms import UNKNOWN, parallel
from ..terms import perp as perp_to
from . import force as fp
from .drivers import Cylinder, _sides, cylinder_of, first_group
from .force_loads import State, Term


def cylinder_group(st: State, g: Group) -> None:
    """The group closed by the cylinder, then the rod's polygon and the driving force."""
    b, gn = st.b, g.name
    cyl = cylinder_of(b, g)
    assert cyl is not None
    partner, p1, e, k, barrel = _sides(b, g)
    rod = cyl.rod
    rod_loads = list(st.terms[rod])             # before the reactions are passed to it
    pairs = {p.point: p for p in (g.outer1, g.inner, g.outer2)}
    outer_p, outer_e, inner = pairs[p1], pairs[e], pairs[k]
    m1 = outer_p.other(partner)
    at_e = barrel if outer_e.joins(barrel) else rod     # the cylinder's part at each end
    at_k = rod if at_e == barrel else barrel
    m2 = outer_e.other(at_e)
    cylinder = st.terms[barrel] + st.terms[rod]
    if outer_p.kind is PairKind.PRISMATIC:      # the partner slides on a guide: RRP
        pin_force = _cylinder_rrp(st, g, partner, outer_p, outer_e, inner, at_e, at_k, k, e,
                                  cylinder, rod)
        _rod_polygon(st, cyl, rod, barrel, rod_loads, pin_force, k if at_k == rod else e)
        return
    t1 = fp._tangential(st, gn, partner, m1, k, p1)
    total = fp._moment_sum(st, gn, f"{barrel},{rod}", k, cylinder, "t.cyl")
    t2 = st.add(f"force.{gn}.Rt.{m2}{at_e}", Op.MOMENT_ARM_TANGENTIAL,
                (b.pos[k], b.pos[e], total), Kind.POINT, Role.RESULT,
                f"R^t_{fp.pair_key(m2, at_e)}", gn, subject=(e, k, st.label(total)))
    o = fp._pole(st, gn)
    a = fp._chain(st, gn, o, [Term(st.label(t1), t1)])
    v1 = fp._chain(st, gn, a, st.terms[partner])
    v2 = fp._chain(st, gn, v1, cylinder)
    end = fp._chain(st, gn, v2, [Term(st.label(t2), t2)])
    f = fp._close(st, gn, fp._line(st, gn, end, "n2", f"∥{e}{k}", b.pos[e], b.pos[k], turn=0),
                  fp._line(st, gn, o, "n1", f"∥{p1}{k}", b.pos[p1], b.pos[k], turn=0))
    fp._between(st, gn, end, f, f"R^n_{fp.pair_key(m2, at_e)}", "Rn2", Role.AUXILIARY)
    fp._between(st, gn, f, o, f"R^n_{fp.pair_key(m1, partner)}", "Rn1", Role.AUXILIARY)
    r1 = fp._between(st, gn, f, a, f"R_{fp.pair_key(m1, partner)}", "R1")
    r2 = fp._between(st, gn, v2, f, f"R_{fp.pair_key(m2, at_e)}", "R2")
    r_in = fp._between(st, gn, v1, f, f"R_{fp.pair_key(at_k, partner)}", "Rin")
    fp._reaction(st, gn, outer_p, m1, partner, r1)
    fp._reaction(st, gn, outer_e, m2, at_e, r2)
    on_k = fp._reaction(st, gn, inner, at_k, partner, r_in)
    fp._equation(st, gn, [(st.label(t1), perp_to(f"{p1}{k}"), "✓"),
                          *fp._rows(st.terms[partner]), *fp._rows(cylinder),
                          (st.label(t2), perp_to(f"{e}{k}"), "✓"),
                          (f"R^n_{fp.pair_key(m2, at_e)}", parallel(f"{e}{k}"), "?"),
                          (f"R^n_{fp.pair_key(m1, partner)}", parallel(f"{p1}{k}"), "?")])
    # the rod alone: its loads and the force at its pin, closed by the barrel's force on it
    _rod_polygon(st, cyl, rod, barrel, rod_loads, on_k if at_k == rod else r2,
                 k if at_k == rod else e)


def _rod_polygon(st: State, cyl: Cylinder, rod: str, barrel: str, rod_loads: list[Term],
                 pin_force: str, pin: str) -> None:
    """The rod's polygon: its loads and the force at its pin, closed by the barrel's force on
    it (F_d along the cylinder, the pair's reaction ⊥ it)."""
    b = st.b
    drive_pair = next(p for p in b.mech.pairs if p.kind is PairKind.PRISMATIC and p.a == rod
                      and p.b == barrel)
    pivot = b.mech.guides[drive_pair.guide or ""].through      # the barrel's pivot
    _driver_polygon(st, cyl.group, rod, barrel, drive_pair,
                    [*rod_loads, Term(st.label(pin_force), pin_force, b.pos[pin])],
                    (b.pos[pivot], b.pos[drive_pair.point]), second=bool(cyl.tag))


def _cylinder_rrp(st: State, g: Group, partner: str, outer_p: Pair, outer_e: Pair, inner: Pair,
                  at_e: str, at_k: str, k: str, e: str, cylinder: list[Term], rod: str) -> str:
    """The cylinder's RRP group (the partner slides on a guide): R^t at the cylinder's outer pin
    from its moments about K, the polygon closed by R^n ∥ EK and the guide's reaction ⊥ the
    guide, the guide's couple from the partner's moments. Returns the force on the rod's pin."""
    b, gn = st.b, g.name
    m1, m2 = outer_e.other(at_e), outer_p.other(partner)
    guide = outer_p.guide or ""
    total = fp._moment_sum(st, gn, f"{at_e},{at_k}", k, cylinder, "t.cyl")
    t1 = st.add(f"force.{gn}.Rt.{m1}{at_e}", Op.MOMENT_ARM_TANGENTIAL,
                (b.pos[k], b.pos[e], total), Kind.POINT, Role.RESULT,
                f"R^t_{fp.pair_key(m1, at_e)}", gn, subject=(e, k, st.label(total)))
    o = fp._pole(st, gn)
    a = fp._chain(st, gn, o, [Term(st.label(t1), t1)])
    v1 = fp._chain(st, gn, a, cylinder)
    end = fp._chain(st, gn, v1, st.terms[partner])
    f = fp._close(st, gn, fp._line(st, gn, end, "g2", f"⊥{guide}",
                                   fp._guide_angle(st, outer_p), turn=90),
                  fp._line(st, gn, o, "n1", f"∥{e}{k}", b.pos[e], b.pos[k], turn=0))
    fp._between(st, gn, f, o, f"R^n_{fp.pair_key(m1, at_e)}", "Rn1", Role.AUXILIARY)
    r1 = fp._between(st, gn, f, a, f"R_{fp.pair_key(m1, at_e)}", "R1")
    r2 = fp._between(st, gn, end, f, f"R_{fp.pair_key(m2, partner)}", "R2")
    r_in = fp._between(st, gn, v1, f, f"R_{fp.pair_key(partner, at_k)}", "Rin")
    fp._reaction(st, gn, outer_e, m1, at_e, r1)
    on_partner = fp._reaction(st, gn, inner, partner, at_k, r_in)
    couple = fp._guide_couple(st, gn, partner, outer_p,
                              [*st.terms[partner],
                               Term(f"R_{fp.pair_key(at_k, partner)}", on_partner, b.pos[k])],
                              f"M_{fp.pair_key(m2, partner)}")
    fp._reaction(st, gn, outer_p, m2, partner, r2, couple)
    fp._equation(st, gn, [(st.label(t1), perp_to(f"{e}{k}"), "✓"), *fp._rows(cylinder),
                          *fp._rows(st.terms[partner]),
                          (f"R_{fp.pair_key(m2, partner)}", perp_to(guide), "?"),
                          (f"R^n_{fp.pair_key(m1, at_e)}", parallel(f"{e}{k}"), "?")])
    return r_in if at_k == rod else r1


def _driver_polygon(st: State, gn: str, link: str, carrier: str, pair: Pair, terms: list[Term],
                    axis: tuple[str, ...], second: bool = False, **params: float) -> None:
    """The driven link's polygon, closed by the force of ``carrier`` on it, split into the
    driving force along ``axis`` and the pair's reaction ⊥ it (with its couple).

    ``second``: the second driver's cylinder (W = 2): its force is the result ``F_d<rod>``."""
    b = st.b
    o = fp._pole(st, gn)
    end = fp._chain(st, gn, o, terms)
    whole = fp._between(st, gn, end, o, f"F_{fp.pair_key(carrier, link)}", "Fwhole",
                        Role.AUXILIARY)
    driver = b.mech.drive2 if second else b.mech.drive
    symbol = "l" if driver is None or driver.kind is DriverKind.CYLINDER else "s"
    sid, label = (f"force.F_d.{link}", f"F_d{link}") if second else ("force.F_d", "F_d")
    fd = st.add(sid, Op.DRIVING_FORCE, (whole, *axis), Kind.SCALAR, Role.RESULT, label,
                gn, subject=(st.label(whole), f"{symbol}{link}"), **params)
    b.result(label, fd)
    normal = st.add(f"force.{gn}.Rn", Op.NORMAL_FORCE, (whole, *axis), Kind.POINT, Role.RESULT,
                    f"R_{fp.pair_key(carrier, link)}", gn,
                    subject=(st.label(whole), f"{symbol}{link}"), **params)
    couple = fp._guide_couple(st, gn, link, pair, terms, f"M_{fp.pair_key(carrier, link)}")
    fp._reaction(st, gn, pair, carrier, link, normal, couple, b.pos[pair.point])
    fp._equation(st, gn, [*fp._rows(terms), (f"F_{fp.pair_key(carrier, link)}", UNKNOWN, "?")])


def slider_driver(st: State, second: bool = False) -> None:
    """The driving slider: its polygon closed by the frame's force; F_d along the guide.

    ``second``: the second driver (W = 2), its force the result ``F_d<link>``."""
    b = st.b
    drive = b.mech.drive2 if second else b.mech.drive
    assert drive is not None and drive.guide is not None
    pair = next(p for p in b.mech.pairs_of(drive.link) if p.other(drive.link) == GROUND)
    guide = b.mech.guides[drive.guide]
    group = f"I({GROUND},{drive.link})" if second else first_group(b)
    _driver_polygon(st, group, drive.link, GROUND, pair, st.terms[drive.link], (),
                    second=second, dir_angle=guide.angle)


def lever(st: State, second: str | None = None) -> None:
    """Zhukovsky's lever for a linear driver: F_d = −ΣP / q̇ (the loads at their images).

    ``second``: the second driver's M_b or F_d (W = 2), one more term of the power balance."""
    b = st.b
    loads, layout, labels = fp.lever_loads(st)
    loads, layout, labels = fp.second_on_lever(st, second, loads, layout, labels)
    inputs: list[str] = ["vel.rate", *loads]
    sid = st.add("force.F_d.zhukovsky", Op.ZHUKOVSKY, tuple(inputs), Kind.SCALAR, Role.RESULT,
                 "F_d", "lever", subject=tuple(labels), layout=layout)
    b.result("F_d_zhukovsky", sid)
