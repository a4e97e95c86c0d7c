"""Operations of class III groups (triads): the base link's angle solved on the group's closure,
its first inner point, and the line of a leg on the position plan (for Assur's special point).

A triad RRR-RRR: legs i = 1, 2, 3 join known points A_i to the base link's points B_i
(|A_i B_i| = l_i). With the base link's angle θ, B_2 − B_1 = R(θ)·d2 and B_3 − B_1 = R(θ)·d3 (d2,
d3 in the base link's frame), so B_1 is where the arc (A_1, l_1) meets the arc (A_2 − R(θ)·d2, l_2)
(branch ``sigma``), and the closure is f(θ) = |B_1 − (A_3 − R(θ)·d3)| − l_3 = 0. It has up to six
roots; the assembly is the root of branch ``sigma`` where f crosses zero with the sign ``slope``,
nearest (circularly) to the angle ``theta_ref`` of the assembly position — a rule that needs no
neighbouring position, so any position is evaluated alone.
"""

from __future__ import annotations

import math

import numpy as np

from ...geom import meet
from ...geom.vec import Array
from ..step import Step
from .spec import Drawn, Grade, Hint, HintView, Line, OpSpec, Result, Written, hint, line, measured

#: grid of base-link angles on which the closure's roots are bracketed
GRID = 24
#: cells on each side of the reference angle searched first
WINDOW = 3
#: iterations of the bracketing secant (Illinois) refinement, at most
ITERATIONS = 60


def _rot(d: tuple[float, float], c: Array, s: Array) -> Array:
    return np.stack((c * d[0] - s * d[1], s * d[0] + c * d[1]), axis=-1)


def closure(a1: Array, a2: Array, a3: Array, theta: Array, l1: float, l2: float, l3: float,
            d2: tuple[float, float], d3: tuple[float, float],
            sigma: int) -> tuple[Array, Array, Array]:
    """f(θ), B_1(θ) and the arcs' sine at base angles θ (points broadcast against θ's shape).

    The arcs meet by Heron's product form (exact near tangency); a square of the half-chord
    negative by rounding only (at a domain edge taken as a grid node) counts as zero.
    """
    c, s = np.cos(theta), np.sin(theta)
    dx = a2[..., 0] - (c * d2[0] - s * d2[1]) - a1[..., 0]
    dy = a2[..., 1] - (s * d2[0] + c * d2[1]) - a1[..., 1]
    dd = dx * dx + dy * dy
    with np.errstate(invalid="ignore", divide="ignore"):
        along = (l1 * l1 - l2 * l2 + dd) / (2.0 * dd)
        h2 = ((l1 + l2) ** 2 - dd) * (dd - (l1 - l2) ** 2) / (4.0 * dd * dd)
        h2 = np.where((h2 < 0.0) & (h2 > -1e-12), 0.0, h2)
        h = np.sqrt(h2) * sigma
        bx = a1[..., 0] + along * dx - h * dy
        by = a1[..., 1] + along * dy + h * dx
        rx = bx - a3[..., 0] + (c * d3[0] - s * d3[1])
        ry = by - a3[..., 1] + (s * d3[0] + c * d3[1])
        f = np.sqrt(rx * rx + ry * ry) - l3
        sine = np.abs(h) * dd / (l1 * l2)
    return f, np.stack((bx, by), axis=-1), sine


def edges(a1: Array, a2: Array, step: Step) -> Array:
    """The base angles (N, 4) where the arcs about A_1 and A_2 − R(θ)·d2 touch (NaN: none).

    |A_2 − A_1 − R(θ)·d2|² = |u|² + |d2|² − 2ρ·cos(θ − α) equals (l_1 ± l_2)² in closed form.
    """
    l1, l2, _, d2, _ = _params(step)
    ux, uy = a2[..., 0] - a1[..., 0], a2[..., 1] - a1[..., 1]
    p, q = ux * d2[0] + uy * d2[1], uy * d2[0] - ux * d2[1]
    rho, alpha = np.hypot(p, q), np.arctan2(q, p)
    base = ux * ux + uy * uy + d2[0] * d2[0] + d2[1] * d2[1]
    out = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for e in (l1 + l2, abs(l1 - l2)):
            t = np.arccos((base - e * e) / (2.0 * rho))
            out += [alpha + t, alpha - t]
    return np.stack(out, axis=-1)


def _params(step: Step) -> tuple[float, float, float, tuple[float, float], tuple[float, float]]:
    return (float(step.param("l1")), float(step.param("l2")), float(step.param("l3")),
            tuple(step.param("d2")), tuple(step.param("d3")))


def _brackets(a1: Array, a2: Array, a3: Array, th: Array, step: Step,
              sigma: int) -> tuple[Array, Array, Array, Array, Array]:
    """Grid cells (N, M) of θ with the closure's values at their ends, and the values.

    The grid ``th`` (ascending, spanning one turn) gets, per position, the edges of the arcs'
    domain as further nodes (:func:`edges`, put into the same turn), so that no cell straddles an
    edge where the two branches of the arcs join: a root beside an edge is bracketed.
    """
    l1, l2, l3, d2, d3 = _params(step)
    lo = th[0]
    e = np.mod(edges(a1, a2, step) - lo, 2 * math.pi) + lo
    e[e > th[-1]] = np.nan                                 # outside a window of less than a turn
    nodes = np.sort(np.concatenate((np.broadcast_to(th, (a1.shape[0], th.size)), e), axis=1),
                    axis=1)                                # NaN edges sort last
    f, _, _ = closure(a1[:, None, :], a2[:, None, :], a3[:, None, :], nodes, l1, l2, l3, d2, d3,
                      sigma)
    return nodes[:, :-1], nodes[:, 1:], f[:, :-1], f[:, 1:], f


def _refine(a1: Array, a2: Array, a3: Array, lo: Array, hi: Array, flo: Array, fhi: Array,
            active: Array, step: Step, sigma: int) -> tuple[Array, Array, Array]:
    """Illinois secant on brackets [lo, hi] (f changes sign) to the last bit: (θ, lo, hi)."""
    l1, l2, l3, d2, d3 = _params(step)
    side = np.zeros(lo.shape)
    x = lo.copy()
    active = active.copy()
    for _ in range(ITERATIONS):
        if not active.any():
            break
        with np.errstate(invalid="ignore", divide="ignore"):
            x = np.where(active, hi - fhi * (hi - lo) / (fhi - flo), x)
        fx, _, _ = closure(a1, a2, a3, x, l1, l2, l3, d2, d3, sigma)
        fx = np.where(np.isfinite(fx), fx, 0.0)
        same_hi = np.sign(fx) == np.sign(fhi)
        upd_hi, upd_lo = active & same_hi, active & ~same_hi
        # Illinois: halve the stale end's value when the same end moves twice
        flo = np.where(upd_hi & (side == 1), 0.5 * flo, flo)
        fhi = np.where(upd_lo & (side == -1), 0.5 * fhi, fhi)
        hi, fhi = np.where(upd_hi, x, hi), np.where(upd_hi, fx, fhi)
        lo, flo = np.where(upd_lo, x, lo), np.where(upd_lo, fx, flo)
        side = np.where(upd_hi, 1, np.where(upd_lo, -1, side))
        active &= (fx != 0) & (np.abs(hi - lo) > 4e-16 * (1 + np.abs(x)))
    return x, lo, hi


def _crossing(f0: Array, f1: Array) -> Array:
    out: Array = np.isfinite(f0) & np.isfinite(f1) & (f0 * f1 <= 0) & (f0 != f1)
    return out


def roots(a1: Array, a2: Array, a3: Array, step: Step, sigma: int) -> list[tuple[float, int]]:
    """Every root (θ, sign of f′) of branch ``sigma`` at the first position (assembly)."""
    th = np.linspace(-math.pi, math.pi, 721)
    t0, t1, f0, f1, _ = _brackets(a1[:1], a2[:1], a3[:1], th, step, sigma)
    k = np.nonzero(_crossing(f0[0], f1[0]))[0]
    n = k.size
    x, _, _ = _refine(np.repeat(a1[:1], n, 0), np.repeat(a2[:1], n, 0), np.repeat(a3[:1], n, 0),
                      t0[0, k], t1[0, k], f0[0, k], f1[0, k], np.ones(n, bool), step, sigma)
    return [(math.remainder(float(t), 2 * math.pi), 1 if f1[0, j] > f0[0, j] else -1)
            for t, j in zip(x, k, strict=True)]


def triad_angle(step: Step, a1: Array, a2: Array, a3: Array) -> Result:
    """The base link's angle θ: the root of the closure f(θ) on the assembly's branch.

    Bracketed on a grid of ``GRID`` angles centred on the assembly's angle (vectorised over
    positions; the edges of the arcs' domain added as nodes), refined by the Illinois secant to
    the last bit. NaN with gap > 0 (min |f| over the branch) where the group does not close; the
    sine is |f′|·(the arcs' sine) over the group's size (0: the triad's Jacobian is singular).
    """
    l1, l2, l3, d2, d3 = _params(step)
    sigma, slope, ref = int(step.param("sigma")), int(step.param("slope")), step.param("theta_ref")
    dt = 2 * math.pi / GRID
    n = a1.shape[0]
    t0, t1 = np.full((n, 1), np.nan), np.full((n, 1), np.nan)
    f0, f1 = np.full((n, 1), np.nan), np.full((n, 1), np.nan)
    miss = np.full(n, np.inf)        # min |f| over the branch where no root was found
    found = np.zeros(n, bool)
    todo = np.arange(n)
    # first the cells next to the reference, then the whole turn where no root was there: a
    # root inside the window is nearer than any outside, so the rule is the same
    for half in (WINDOW, GRID // 2):
        if not todo.size:
            break
        th = np.arange(-half, half + 1) * dt + ref
        c0, c1, g0, g1, g = _brackets(a1[todo], a2[todo], a3[todo], th, step, sigma)
        ok = _crossing(g0, g1) & (np.sign(g1 - g0) == slope)
        dist = np.abs(0.5 * (c0 + c1) - ref)
        kk = np.argmin(np.where(ok, dist, np.inf), axis=1)
        r = np.arange(todo.size)
        hit = ok[r, kk]
        t0[todo, 0], t1[todo, 0] = c0[r, kk], c1[r, kk]
        f0[todo, 0], f1[todo, 0] = g0[r, kk], g1[r, kk]
        found[todo] = hit
        if half == GRID // 2:
            miss[todo] = np.min(np.where(np.isfinite(g), np.abs(g), np.inf), axis=1)
        todo = todo[~hit]
    rows, k = np.arange(n), np.zeros(n, int)
    x, _, _ = _refine(a1, a2, a3, t0[rows, k], t1[rows, k], f0[rows, k], f1[rows, k], found,
                      step, sigma)
    theta = np.where(found, x, np.nan)
    fb, _, cc_sine = closure(a1, a2, a3, theta, l1, l2, l3, d2, d3, sigma)
    h = 1e-6                       # f′ by a central difference: for the conditioning only
    fp = (closure(a1, a2, a3, theta + h, l1, l2, l3, d2, d3, sigma)[0]
          - closure(a1, a2, a3, theta - h, l1, l2, l3, d2, d3, sigma)[0]) / (2 * h)
    size = l1 + l2 + l3 + math.hypot(*d2) + math.hypot(*d3)
    with np.errstate(invalid="ignore"):
        sine = np.minimum(1.0, np.abs(fp) * cc_sine / size)
    gap = np.where(found, -np.abs(fb), np.where(np.isfinite(miss), miss, size))
    sine = np.where(found, np.nan_to_num(sine, nan=0.0), 0.0)
    return theta, gap, sine


def triad_point(step: Step, a1: Array, a2: Array, angle: Array) -> Result:
    """B_1: the arc (A_1, l_1) meets the arc (A_2 − R(θ)·d2, l_2), branch ``sigma``."""
    l1, l2, _, d2, _ = _params(step)
    c, s = np.cos(angle), np.sin(angle)
    return meet.circle_circle(a1, l1, a2 - _rot(d2, c, s), l2, int(step.param("sigma")))


def line_through(step: Step, p: Array, q: Array) -> Result:
    """The line of a leg on the position plan: through P and Q."""
    d = q - p
    n = np.sqrt(d[..., 0] * d[..., 0] + d[..., 1] * d[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        u = d / n[..., None]
    return line(p, u), None, None


def moment_along(step: Step, centre: Array, at: Array, toward: Array, total: Array) -> Result:
    """Force at ``at`` along (toward − at) whose moment about the centre is −total (a leg's R^n
    from the moments of the whole triad about its special point); sine: |arm| / |at − centre|."""
    r = at - centre
    u = toward - at
    n = np.sqrt(u[..., 0] * u[..., 0] + u[..., 1] * u[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        u = u / n[..., None]
        arm = r[..., 0] * u[..., 1] - r[..., 1] * u[..., 0]
        lam = -total / arm
        sine = np.abs(arm) / np.sqrt(r[..., 0] * r[..., 0] + r[..., 1] * r[..., 1])
    return lam[..., None] * u, None, sine


# -- check rules ----------------------------------------------------------------------------------
def triad_point_hint(step: Step, view: HintView, at: Array, tol_mm: float) -> Hint:
    """A point of a triad: where the three legs close the group."""
    return measured(hint("rule.triad_point", label=view.labels(step.id)))


# -- the operations -------------------------------------------------------------------------------
TRIAD_ANGLE = OpSpec("triad_angle", triad_angle, "protocol.op.triad_angle",
                     written=Written.ANGLE)
TRIAD_POINT = OpSpec("triad_point", triad_point, "protocol.op.triad_point", Drawn.POINT,
                     Line.OUTLINE, Grade.POINT, hint_rule=triad_point_hint)
LINE_THROUGH = OpSpec("line_through", line_through, "protocol.op.line_through",
                      Drawn.CONSTRUCTION_LINE, Line.DASHED, Grade.DIRECTION, lever=("p", "q"),
                      through="p")

MOMENT_ALONG = OpSpec("moment_along", moment_along, "protocol.op.moment_along", Drawn.VECTOR,
                      Line.OUTLINE, Grade.VALUE)

__all__ = ["LINE_THROUGH", "MOMENT_ALONG", "TRIAD_ANGLE", "TRIAD_POINT"]
