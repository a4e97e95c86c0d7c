"""Kinetostatics of a class III group with legs sliding on known guides, by Assur's special point.

A revolute leg's reaction at A_i is split into R^t_i (⊥ A_iB_i, from the leg's moments about B_i)
and R^n_i (along A_iB_i). A slider leg's reaction from the guide is ⊥ the guide, its magnitude
unknown; placed at B_i it goes with the couple M_i = −ΣM_{B_i}(the leg's loads) (the pin at B_i
has no moment there), which fixes where its line of action crosses the guide. The lines of R^n_i,
R^n_j (or of the guide reactions, placed at B_i, B_j) pass through the special point S, so the
moments of the whole group about S give the third leg's unknown (R^n_k along A_kB_k, or the guide
reaction ⊥ its guide at B_k). The group's force polygon — known forces head to tail, closed by
lines of the two remaining unknown directions — gives the rest, the legs' polygons the inner
reactions.
"""

from __future__ import annotations

from ...errors import SceneError
from ...i18n import Text
from ...model.plans import Plan
from ...model.structure import Triad
from ..ops import Op
from ..step import Kind, Role
from ..terms import Row
from ..terms import parallel as parallel_to
from ..terms import perp as perp_to
from .force import (
    _between,
    _chain,
    _close,
    _guide_angle,
    _guide_couple,
    _line,
    _moment_sum,
    _pole,
    _reaction,
    _rows,
    _tangential,
    pair_key,
)
from .force_loads import State, Term
from .triad import special_name
from .triadp import Leg, legs, special_legs

F = Plan.FORCE


def _unknown_line(st: State, gn: str, lg: Leg, through: str, tag: str) -> str:
    """Through a vertex of the polygon, the line of the leg's unknown: ∥ A_iB_i or ⊥ the guide."""
    b = st.b
    if lg.guided:
        guide = lg.guide_pair
        return _line(st, gn, through, tag, f"⊥{guide.guide}", _guide_angle(st, guide), turn=90)
    return _line(st, gn, through, tag, f"∥{lg.a}{lg.b}", b.pos[lg.a], b.pos[lg.b], turn=0)


def _unknown_row(lg: Leg, label: str, known: str) -> Row:
    if lg.guided:
        return (label, perp_to(f"{lg.guide_pair.guide}"), known)
    return (label, parallel_to(f"{lg.a}{lg.b}"), known)


def emit(st: State, g: Triad) -> None:
    """Force plan of one group: R^t of the revolute legs, the guide couples of the slider legs,
    the third leg's unknown about S, the polygon, the inner reactions."""
    b, gn = st.b, g.name
    ls = legs(g)
    i, j, k = special_legs(b, g)
    name = special_name(b, g)
    rt: dict[int, str] = {}
    couples: dict[int, str] = {}
    group_terms: list[Term] = []
    for n, lg in enumerate(ls):
        if lg.block:
            # a block without forces of its own: its pin's reaction is the guide's, ⊥ it
            if any(t.force is not None for t in st.terms[lg.link]):
                raise SceneError(Text("triadp.force.block_loads",
                                      {"link": lg.link, "group": gn, "base": g.base}),
                                 file=b.file, key=f"links.{lg.link}")
            continue
        if lg.slides:
            couples[n] = _guide_couple(st, gn, lg.link, lg.pair, st.terms[lg.link],
                                       f"M_{pair_key(lg.known, lg.link)}")
            group_terms.append(Term(st.label(couples[n]), couple=couples[n]))
        else:
            rt[n] = _tangential(st, gn, lg.link, lg.known, lg.b, lg.a)
            group_terms.append(Term(st.label(rt[n]), rt[n], b.pos[lg.a]))
    for link in g.links:
        group_terms += st.terms[link]
    total = _moment_sum(st, gn, g.base, name, group_terms, "special")
    lk = ls[k]
    nk_label = (f"R_{pair_key(lk.known, lk.link)}" if lk.guided
                else f"R^n_{pair_key(lk.known, lk.link)}")
    if lk.guided:
        rn_k = st.add(f"force.{gn}.N.{lk.known}{lk.link}", Op.LEG_NORMAL_FORCE,
                      (b.pos[name], b.pos[lk.b], _guide_angle(st, lk.guide_pair), total),
                      Kind.POINT,
                      Role.RESULT, nk_label, gn, subject=(lk.b, name, st.label(total)))
    else:
        rn_k = st.add(f"force.{gn}.Rn.{lk.known}{lk.link}", Op.MOMENT_ALONG,
                      (b.pos[name], b.pos[lk.a], b.pos[lk.b], total), Kind.POINT, Role.RESULT,
                      nk_label, gn, subject=(lk.a, name, st.label(total)))

    def own(n: int) -> list[Term]:
        return [Term(st.label(rt[n]), rt[n])] if n in rt else []

    o = _pole(st, gn)
    a_i = _chain(st, gn, o, own(i))
    v_i = _chain(st, gn, a_i, st.terms[ls[i].link])
    v_b = _chain(st, gn, v_i, st.terms[g.base])
    t_k = _chain(st, gn, v_b, own(k))
    n_k = _chain(st, gn, t_k, [Term(st.label(rn_k), rn_k)])
    v_k = _chain(st, gn, n_k, st.terms[lk.link])
    w_j = _chain(st, gn, v_k, st.terms[ls[j].link])
    e = _chain(st, gn, w_j, own(j))
    li, lj = ls[i], ls[j]
    f = _close(st, gn, _unknown_line(st, gn, lj, e, "nj"), _unknown_line(st, gn, li, o, "ni"))
    lab = {n: f"{'R' if ls[n].guided else 'R^n'}_{pair_key(ls[n].known, ls[n].link)}"
           for n in (i, j)}
    if j in rt:
        _between(st, gn, e, f, lab[j], "Rnj", Role.AUXILIARY)
    if i in rt:
        _between(st, gn, f, o, lab[i], "Rni", Role.AUXILIARY)
    outer = {i: _between(st, gn, f, a_i, f"R_{pair_key(li.known, li.link)}", "Ri"),
             k: _between(st, gn, v_b, n_k, f"R_{pair_key(lk.known, lk.link)}", "Rk"),
             j: _between(st, gn, w_j, f, f"R_{pair_key(lj.known, lj.link)}", "Rj")}
    inner = {i: _between(st, gn, v_i, f, f"R_{pair_key(g.base, li.link)}", "Rbi"),
             k: _between(st, gn, v_k, v_b, f"R_{pair_key(g.base, lk.link)}", "Rbk"),
             j: _between(st, gn, f, v_k, f"R_{pair_key(g.base, lj.link)}", "Rbj")}
    for n, lg in enumerate(ls):
        if lg.slides:
            _reaction(st, gn, lg.pair, lg.known, lg.link, outer[n], couples[n], b.pos[lg.b])
        else:
            _reaction(st, gn, lg.pair, lg.known, lg.link, outer[n])
        if lg.block:        # the base link's guide on the block: the force at A and a couple
            couple = _guide_couple(st, gn, lg.link, lg.inner, st.terms[lg.link],
                                   f"M_{pair_key(g.base, lg.link)}")
            _reaction(st, gn, g.inner[n], g.base, lg.link, inner[n], couple, b.pos[lg.a])
        else:
            _reaction(st, gn, g.inner[n], g.base, lg.link, inner[n])
    rows: list[Row] = []
    if i in rt:
        rows.append((st.label(rt[i]), perp_to(f"{li.a}{li.b}"), "✓"))
    rows += [*_rows(st.terms[li.link]), *_rows(st.terms[g.base])]
    if k in rt:
        rows.append((st.label(rt[k]), perp_to(f"{lk.a}{lk.b}"), "✓"))
    rows += [_unknown_row(lk, st.label(rn_k), "✓"), *_rows(st.terms[lk.link]),
             *_rows(st.terms[lj.link])]
    if j in rt:
        rows.append((st.label(rt[j]), perp_to(f"{lj.a}{lj.b}"), "✓"))
    rows += [_unknown_row(lj, lab[j], "?"), _unknown_row(li, lab[i], "?")]
    b.c.equations[(F, gn)] = (f"{rows[0][0]} + … + {rows[-2][0]} + {rows[-1][0]} = 0", rows)


__all__ = ["emit"]
