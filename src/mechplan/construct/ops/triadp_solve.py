"""The closure of a class III group whose legs may slide on known guides, vectorised over positions.

Each leg constrains a point B_i of the base link to a locus known from the links before the
group: an arc (A_i, l_i) for a leg with two revolute pairs (kind ``R``), or a line (the guide's
line through B_i, kind ``P``) for a slider leg. The legs are taken in the order of ``kinds`` (arcs
first). With the base link's angle θ, B_2 − B_1 = R(θ)·d2 and B_3 − B_1 = R(θ)·d3 (d2, d3 in
the base link's frame), so B_1 is where locus 1 meets locus 2 shifted by −R(θ)·d2 (two circles
or a circle and a line: branch σ; two lines: one meet), and the closure is f(θ) = 0 with
f = |B_3 − A_3| − l_3 (an arc) or f = u_3 × (B_3 − P_3) (a line: the signed distance from it);
a third leg of kind ``Q`` is a block pinned at A_3 sliding on a guide of the base link: f is
A_3's signed distance from that guide, (R(θ)·u) × (A_3 − B_1 − R(θ)·q).

The root of branch σ where f crosses zero with the sign ``slope``, nearest (circularly) to the
assembly's angle ``ref``, is bracketed on a grid of ``GRID`` cells (first the ``WINDOW`` cells on
each side of ``ref``, the whole turn where they hold none); a cell with one end off the loci's
domain (the loci do not meet there) is cut at the domain's edge (in closed form, stepped back
onto the domain by roundings; a bisection where that fails), so that a root beside an edge is
bracketed. The
root is refined by the Illinois secant to the last bit — no neighbouring position is used, so
any position is evaluated alone.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ...geom import meet
from ...geom.vec import Array
from .illinois import illinois

#: the legs' loci: per leg a point A_i (N, 2) or a line (N, 2, 2)
Loci = tuple[Array, ...]
#: cells of the base link's angle over one turn
GRID = 24
#: cells on each side of the assembly's angle searched first (a root there is nearer than any
#: outside, so the rule is the same; the whole turn only where the window has none)
WINDOW = 3
#: bisections that find a domain edge inside a cell (15°/2^50 ≈ 2e-16 rad; only where the
#: closed-form edge, stepped back by roundings, is not on the domain)
EDGE_STEPS = 50
#: cells of the grid on which every root of the assembly's position is sought (0.5°)
FINE = 720
#: iterations of the Illinois secant, at most
ITERATIONS = 100


class Group(NamedTuple):
    """The group's dimensions and assembly: the legs' kinds in the solve order (``"RRP"``), the
    arcs' radii (0 for a line), B_2, B_3 relative to B_1 in the base frame, σ, the sign of f′ at
    the root and the assembly's angle."""

    kinds: str
    l: tuple[float, float, float]
    d2: tuple[float, float]
    d3: tuple[float, float]
    sigma: int
    slope: int
    ref: float
    #: a third leg of kind ``Q`` (a block sliding on a guide of the base link): the guide's
    #: point relative to B_1 and its angle, in the base link's frame
    q: tuple[float, float] = (0.0, 0.0)
    q_angle: float = 0.0

    @property
    def size(self) -> float:
        return sum(self.l) + math.hypot(*self.d2) + math.hypot(*self.d3)


def _rot(d: tuple[float, float], c: Array, s: Array) -> tuple[Array, Array]:
    return c * d[0] - s * d[1], s * d[0] + c * d[1]


def first_point(loci: Loci, theta: Array, g: Group,
                sigma: int | None = None) -> tuple[Array, Array, Array]:
    """B_1 (…, 2), the meet's gap and its sine at base angles θ (loci broadcast against θ).

    ``loci[i]``: A_i (N, 2) for an arc, the line (N, 2, 2) for a slider leg (each with a new axis
    before the last one or two when θ is a grid)."""
    sg = g.sigma if sigma is None else sigma
    c, s = np.cos(theta), np.sin(theta)
    rx, ry = _rot(g.d2, c, s)
    shift = np.stack((rx, ry), axis=-1)
    k1, k2 = g.kinds[0], g.kinds[1]
    if k1 == "R" and k2 == "R":
        return meet.circle_circle(loci[0], g.l[0], loci[1] - shift, g.l[1], sg)
    if k1 == "R":
        line = loci[1]
        return meet.circle_line(loci[0], g.l[0], line[..., 0, :] - shift, line[..., 1, :], sg)
    one, two = loci[0], loci[1]
    return meet.line_line(one[..., 0, :], one[..., 1, :], two[..., 0, :] - shift,
                          two[..., 1, :])


def closure(loci: Loci, theta: Array, g: Group,
            sigma: int | None = None) -> tuple[Array, Array]:
    """f(θ) (NaN where loci 1 and 2 do not meet) and the sine of their meet."""
    b1, _, sine = first_point(loci, theta, g, sigma)
    c, s = np.cos(theta), np.sin(theta)
    rx, ry = _rot(g.d3, c, s)
    bx, by = b1[..., 0] + rx, b1[..., 1] + ry
    third = loci[2]
    if g.kinds[2] == "R":
        f = np.hypot(bx - third[..., 0], by - third[..., 1]) - g.l[2]
    elif g.kinds[2] == "Q":      # A_3 on the base link's guide: (R(θ)·u) × (A_3 − origin)
        ox, oy = _rot(g.q, c, s)
        ux, uy = np.cos(theta + g.q_angle), np.sin(theta + g.q_angle)
        f = (ux * (third[..., 1] - b1[..., 1] - oy)
             - uy * (third[..., 0] - b1[..., 0] - ox))
    else:
        p, u = third[..., 0, :], third[..., 1, :]
        f = u[..., 0] * (by - p[..., 1]) - u[..., 1] * (bx - p[..., 0])
    return f, sine


def _grid_loci(loci: Loci, g: Group) -> Loci:
    """The loci with an axis for the grid's angles."""
    return tuple(p[:, None] for p in loci)


def closed_edges(loci: Loci, g: Group) -> Array:
    """The base angles (N, 4) where loci 1 and 2 touch, in closed form (NaN: none).

    Two arcs: |A_2 − A_1 − R(θ)·d2| = l_1 ± l_2; an arc and a line: the distance of A_1 from
    the shifted line, u_2 × (A_1 − P_2) + u_2 × R(θ)·d2, is ±l_1 (two lines never touch)."""
    one, two = loci[0], loci[1]
    n = one.shape[0]
    d2 = g.d2
    out = []
    with np.errstate(invalid="ignore", divide="ignore"):
        if g.kinds[:2] == "RR":
            ux, uy = two[:, 0] - one[:, 0], two[:, 1] - one[:, 1]
            p, q = ux * d2[0] + uy * d2[1], uy * d2[0] - ux * d2[1]
            rho, alpha = np.hypot(p, q), np.arctan2(q, p)
            base = ux * ux + uy * uy + d2[0] * d2[0] + d2[1] * d2[1]
            for e in (g.l[0] + g.l[1], abs(g.l[0] - g.l[1])):
                t_ = np.arccos((base - e * e) / (2.0 * rho))
                out += [alpha + t_, alpha - t_]
        elif g.kinds[:2] == "RP":
            p2, u = two[:, 0, :], two[:, 1, :]
            w = u[:, 0] * (one[:, 1] - p2[:, 1]) - u[:, 1] * (one[:, 0] - p2[:, 0])
            # u × R(θ)d2 = a·cos θ + b·sin θ
            a = u[:, 0] * d2[1] - u[:, 1] * d2[0]
            b = u[:, 0] * d2[0] + u[:, 1] * d2[1]
            rho, alpha = np.hypot(a, b), np.arctan2(b, a)
            for e in (g.l[0], -g.l[0]):
                t_ = np.arccos((e - w) / rho)
                out += [alpha + t_, alpha - t_]
        else:
            out = [np.full(n, np.nan)] * 4
    return np.stack(out, axis=-1)


def _edges(loci: Loci, lo: Array, hi: Array, finite_lo: Array, g: Group,
           sigma: int) -> Array:
    """The domain's edge in [lo, hi] (one end on the domain, ``finite_lo`` telling which): the
    last angle where loci 1 and 2 meet — the closed-form edge in the cell, stepped back onto the
    domain by roundings; a bisection where that fails."""
    on, off = np.where(finite_lo, lo, hi), np.where(finite_lo, hi, lo)
    e = closed_edges(loci, g)
    e = np.mod(e - lo[:, None], 2 * math.pi) + lo[:, None]
    inside = (e >= lo[:, None]) & (e <= hi[:, None])       # NaN compares False
    edge = np.where(inside, e, np.nan)
    # the edge nearest the finite end (one edge per cell but for a rounding)
    dist = np.where(inside, np.abs(edge - on[:, None]), np.inf)
    pick = edge[np.arange(lo.size), np.argmin(dist, axis=1)]
    step = np.sign(on - off) * 4e-16 * (1.0 + np.abs(pick))
    x = pick
    ok = np.isfinite(closure(loci, x, g, sigma)[0])
    for _ in range(12):
        bad = ~ok & np.isfinite(pick)
        if not bad.any():
            break
        step = np.where(bad, step * 4.0, step)
        x = np.where(bad, pick + step, x)
        ok = np.isfinite(closure(loci, x, g, sigma)[0])
    done = ok & np.isfinite(x) & (np.abs(x - on) <= np.abs(off - on))
    if done.all():
        out: Array = x
        return out
    rest = np.nonzero(~done)[0]
    sub = tuple(p[rest] for p in loci)
    out = np.array(x, dtype=float)
    out[rest] = _bisect(sub, on[rest], off[rest], g, sigma)
    return out


def _bisect(loci: Loci, on: Array, off: Array, g: Group, sigma: int) -> Array:
    """Bisect between a point on the domain and one off it to the domain's edge."""
    for _ in range(EDGE_STEPS):
        mid = 0.5 * (on + off)
        ok = np.isfinite(closure(loci, mid, g, sigma)[0])
        on, off = np.where(ok, mid, on), np.where(ok, off, mid)
    out: Array = on
    return out


class Cells(NamedTuple):
    """Candidate brackets per position (N, M) with f at their ends."""

    lo: Array
    hi: Array
    flo: Array
    fhi: Array
    least: Array    # (N,) the least |f| over the turn (the gap where no root is found)


def cells(loci: Loci, g: Group, sigma: int, half: int = GRID // 2, per_turn: int = GRID
          ) -> Cells:
    """``half`` cells of a grid of ``per_turn`` over the turn on each side of the assembly's angle
    (by default the whole turn), those with one end off the domain cut at the edge (the part on
    the domain kept)."""
    n = loci[0].shape[0]
    th = g.ref + np.arange(-half, half + 1) * (2 * math.pi / per_turn)
    grid = _grid_loci(loci, g)
    f = closure(grid, np.broadcast_to(th, (n, th.size)), g, sigma)[0]
    m = th.size - 1
    lo, hi = np.broadcast_to(th[:-1], (n, m)).copy(), np.broadcast_to(th[1:], (n, m)).copy()
    flo, fhi = f[:, :-1].copy(), f[:, 1:].copy()
    one = np.isfinite(flo) != np.isfinite(fhi)
    if one.any():
        r, k = np.nonzero(one)
        sub = tuple(p[r] for p in loci)
        finite_lo = np.isfinite(flo[r, k])
        e = _edges(sub, lo[r, k], hi[r, k], finite_lo, g, sigma)
        fe = closure(sub, e, g, sigma)[0]
        lo[r, k] = np.where(finite_lo, lo[r, k], e)
        hi[r, k] = np.where(finite_lo, e, hi[r, k])
        flo[r, k] = np.where(finite_lo, flo[r, k], fe)
        fhi[r, k] = np.where(finite_lo, fe, fhi[r, k])
    # a cell whose inside leaves the domain (two edges in it) holds no root
    mid = closure(grid, 0.5 * (lo + hi), g, sigma)[0]
    flo = np.where(np.isfinite(mid), flo, np.nan)
    least = np.min(np.where(np.isfinite(f), np.abs(f), np.inf), axis=1)
    return Cells(lo, hi, flo, fhi, least)


def refine(loci: Loci, lo: Array, hi: Array, flo: Array, fhi: Array, g: Group,
           sigma: int) -> Array:
    """Illinois secant on brackets [lo, hi] where f changes sign, to the last bit."""
    return illinois(lambda x: closure(loci, x, g, sigma)[0], lo, hi, flo, fhi, ITERATIONS,
                    clamp=True)


def _pick(c: Cells, g: Group) -> tuple[Array, Array]:
    """The cell of each position holding a root of the assembly's slope nearest its angle, and
    whether there is one."""
    ok = (c.flo * c.fhi <= 0) & ((c.fhi - c.flo) * g.slope > 0)   # NaN compares False
    dist = np.abs(0.5 * (c.lo + c.hi) - g.ref)
    kk = np.argmin(np.where(ok, dist, np.inf), axis=1)
    found: Array = ok[np.arange(kk.size), kk]
    return kk, found


def solve(loci: Loci, g: Group) -> tuple[Array, Array, Array]:
    """θ of the base link at every position, the gap (−|f| at the root; where the group does
    not close, the least |f| over the turn) and the sine: |f′|·(the loci's meet sine) over the
    group's size (0: the group's Jacobian is singular)."""
    n = loci[0].shape[0]
    lo, hi, flo, fhi = (np.full(n, np.nan) for _ in range(4))
    found = np.zeros(n, bool)
    gap = np.full(n, g.size)
    todo = np.arange(n)
    for half in (WINDOW, GRID // 2):
        if not todo.size:
            break
        sub = tuple(p[todo] for p in loci)
        c = cells(sub, g, g.sigma, half)
        kk, hit = _pick(c, g)
        r = np.arange(todo.size)
        lo[todo], hi[todo], flo[todo], fhi[todo] = (x[r, kk] for x in (c.lo, c.hi, c.flo, c.fhi))
        found[todo] = hit
        if half == GRID // 2:
            gap[todo] = np.where(np.isfinite(c.least), c.least, g.size)
        todo = todo[~hit]
    theta = np.full(n, np.nan)
    sine = np.zeros(n)
    idx = np.nonzero(found)[0]
    if idx.size:
        sub = tuple(p[idx] for p in loci)
        a, b_ = lo[idx], hi[idx]
        x = refine(sub, a, b_, flo[idx], fhi[idx], g, g.sigma)
        f, msine = closure(sub, x, g)
        h = 1e-7
        a, b_ = np.maximum(x - h, a), np.minimum(x + h, b_)
        fp = (closure(sub, b_, g)[0] - closure(sub, a, g)[0]) / (b_ - a)
        theta[idx] = x
        gap[idx] = -np.abs(f)
        with np.errstate(invalid="ignore"):
            sine[idx] = np.nan_to_num(np.minimum(1.0, np.abs(fp) * msine / g.size), nan=0.0)
    return theta, gap, sine


def roots(loci: Loci, g: Group, sigma: int) -> list[tuple[float, int]]:
    """Every root (θ, sign of f′) of branch ``sigma`` at the first position (the assembly)."""
    first = tuple(p[:1] for p in loci)
    c = cells(first, g._replace(ref=0.0), sigma, FINE // 2, FINE)
    f0, f1 = c.flo[0], c.fhi[0]
    k = np.nonzero(np.isfinite(f0) & np.isfinite(f1) & (f0 * f1 <= 0) & (f0 != f1))[0]
    if not k.size:
        return []
    rep = tuple(np.repeat(p, k.size, 0) for p in first)
    x = refine(rep, c.lo[0, k], c.hi[0, k], f0[k], f1[k], g, sigma)
    out = [(math.remainder(float(v), 2 * math.pi), 1 if f1[j] > f0[j] else -1)
           for v, j in zip(x, k, strict=True)]
    # a root on a cell's node is found from both cells: keep one
    uniq: list[tuple[float, int]] = []
    for t, sl in out:
        if not any(abs(math.remainder(t - u, 2 * math.pi)) < 1e-9 and sl == v for u, v in uniq):
            uniq.append((t, sl))
    return uniq


__all__ = ["GRID", "WINDOW", "Group", "closure", "first_point", "roots", "solve"]
