"""Kinetostatics of a class III group (triad) by Assur's special point, as the courses teach.

Each leg's reaction at its outer pair A_i is split into R^n_i (along A_iB_i) and R^t_i (⊥ A_iB_i);
R^t_i follows from the moments of leg i about B_i. The lines of R^n_i and R^n_j pass through the
special point S (the meet of the lines A_iB_i, A_jB_j), so the moments of the whole group about S
give R^n_k. The force polygon of the group — known forces head to tail, closed by lines ∥ A_iB_i
and ∥ A_jB_j — gives R^n_i and R^n_j, and the polygons of the legs the inner reactions.
"""

from __future__ import annotations

from ...model.plans import Plan
from ...model.structure import Triad
from ..ops import Op
from ..step import Kind, Role
from ..terms import parallel as parallel_to
from ..terms import perp as perp_to
from .force import (
    _between,
    _chain,
    _close,
    _line,
    _moment_sum,
    _pole,
    _reaction,
    _rows,
    _tangential,
    pair_key,
)
from .force_loads import State, Term
from .triad import _legs, special_legs, special_name

F = Plan.FORCE


def emit(st: State, g: Triad) -> None:
    """Force plan of one triad: R^t of the legs, R^n_k about S, the polygon, inner reactions."""
    b, gn = st.b, g.name
    legs = _legs(g)
    i, j, k = special_legs(b, g)
    name = special_name(b, g)
    known = {n: g.outer[n].other(legs[n][0]) for n in range(3)}
    rt = {n: _tangential(st, gn, legs[n][0], known[n], legs[n][2], legs[n][1]) for n in range(3)}
    group_terms = [Term(st.label(rt[n]), rt[n], b.pos[legs[n][1]]) for n in range(3)]
    for link in g.links:
        group_terms += st.terms[link]
    total = _moment_sum(st, gn, g.base, name, group_terms, "special")
    lk, ak, bk = legs[k]
    rn_k = st.add(f"force.{gn}.Rn.{known[k]}{lk}", Op.MOMENT_ALONG,
                  (b.pos[name], b.pos[ak], b.pos[bk], total), Kind.POINT, Role.RESULT,
                  f"R^n_{pair_key(known[k], lk)}", gn, subject=(ak, name, st.label(total)))
    o = _pole(st, gn)
    a_i = _chain(st, gn, o, [Term(st.label(rt[i]), rt[i])])
    v_i = _chain(st, gn, a_i, st.terms[legs[i][0]])
    v_b = _chain(st, gn, v_i, st.terms[g.base])
    t_k = _chain(st, gn, v_b, [Term(st.label(rt[k]), rt[k])])
    n_k = _chain(st, gn, t_k, [Term(st.label(rn_k), rn_k)])
    v_k = _chain(st, gn, n_k, st.terms[lk])
    w_j = _chain(st, gn, v_k, st.terms[legs[j][0]])
    e = _chain(st, gn, w_j, [Term(st.label(rt[j]), rt[j])])
    (li, ai, bi), (lj, aj, bj) = legs[i], legs[j]
    f = _close(st, gn, _line(st, gn, e, "nj", f"∥{aj}{bj}", b.pos[aj], b.pos[bj], turn=0),
               _line(st, gn, o, "ni", f"∥{ai}{bi}", b.pos[ai], b.pos[bi], turn=0))
    _between(st, gn, e, f, f"R^n_{pair_key(known[j], lj)}", "Rnj", Role.AUXILIARY)
    _between(st, gn, f, o, f"R^n_{pair_key(known[i], li)}", "Rni", Role.AUXILIARY)
    outer = {i: _between(st, gn, f, a_i, f"R_{pair_key(known[i], li)}", "Ri"),
             k: _between(st, gn, v_b, n_k, f"R_{pair_key(known[k], lk)}", "Rk"),
             j: _between(st, gn, w_j, f, f"R_{pair_key(known[j], lj)}", "Rj")}
    # the base link on each leg: minus the leg's other forces
    inner = {i: _between(st, gn, v_i, f, f"R_{pair_key(g.base, li)}", "Rbi"),
             k: _between(st, gn, v_k, v_b, f"R_{pair_key(g.base, lk)}", "Rbk"),
             j: _between(st, gn, f, v_k, f"R_{pair_key(g.base, lj)}", "Rbj")}
    for n in range(3):
        leg = legs[n][0]
        _reaction(st, gn, g.outer[n], known[n], leg, outer[n])
        _reaction(st, gn, g.inner[n], g.base, leg, inner[n])
    rows = [(st.label(rt[i]), perp_to(f"{ai}{bi}"), "✓"), *_rows(st.terms[li]),
            *_rows(st.terms[g.base]), (st.label(rt[k]), perp_to(f"{ak}{bk}"), "✓"),
            (st.label(rn_k), parallel_to(f"{ak}{bk}"), "✓"), *_rows(st.terms[lk]),
            *_rows(st.terms[lj]), (st.label(rt[j]), perp_to(f"{aj}{bj}"), "✓"),
            (f"R^n_{pair_key(known[j], lj)}", parallel_to(f"{aj}{bj}"), "?"),
            (f"R^n_{pair_key(known[i], li)}", parallel_to(f"{ai}{bi}"), "?")]
    # the terms are listed in the table under it: the caption names the first and the unknowns
    b.c.equations[(F, gn)] = (f"{rows[0][0]} + … + {rows[-2][0]} + {rows[-1][0]} = 0", rows)
