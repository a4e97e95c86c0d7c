"""Instant centres of a linkage: primary ones from its pairs, the rest by Kennedy's theorem.

The search runs over links and pairs, not over kinds of groups: a centre I_ij is found as soon as
two other links k, l have both their centres with i and j known (the line I_ik–I_jk meets the line
I_il–I_jl at I_ij), in the order a student fills the circle diagram — always the centre with the
most triangles closed first (ties in the order of the links). Which centres a position needs is the
same at every position (the topology decides), so the order is found once and evaluated for all
positions at once. A centre no pair of triangles reaches (a class III group can leave such) is
listed as not found.

At every position the two lines of the drawn construction are the first two triangles; where those
lines coincide (the centre is indeterminate on them, e.g. four centres in line at a dead centre)
the best conditioned other pair of triangles is used, and the position records it.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ...geom.vec import Array
from ...model.mechanism import GROUND, Mechanism, Pair, PairKind
from ..estimate import length_scale
from ..graph import Construction, Evaluation
from ..ops import centres as H

#: rounding of one homogeneous operation, in units of the float epsilon
ROUNDINGS = 4.0


@dataclass(frozen=True, slots=True)
class Centre:
    """One instant centre I_ij of the circle diagram (topology only).

    ``pair``: the pair it is the primary centre of; otherwise ``via`` are the links k whose
    triangles (i, j, k) were closed when it was found (the first two give the drawn lines)."""

    i: str
    j: str
    order: int
    pair: Pair | None = None
    via: tuple[str, ...] = ()

    @property
    def key(self) -> str:
        """``"13"`` (``"1,13"`` when a link id has more than one character)."""
        return f"{self.i}{self.j}" if len(self.i) == len(self.j) == 1 else f"{self.i},{self.j}"

    @property
    def primary(self) -> bool:
        """Whether it is given by a pair."""
        return self.pair is not None


@dataclass(frozen=True, slots=True)
class CircleDiagram:
    """The links as the vertices of a polygon, the centres as its sides and diagonals, in the
    order they were found; ``missing`` the pairs of links Kennedy's theorem does not reach."""

    links: tuple[str, ...]
    centres: tuple[Centre, ...]
    missing: tuple[tuple[str, str], ...] = ()

    def centre(self, i: str, j: str) -> Centre:
        """The centre of links i and j (either order)."""
        a, b = ordered(self.links, i, j)
        for c in self.centres:
            if (c.i, c.j) == (a, b):
                return c
        raise KeyError(f"no instant centre of links {i} and {j} was found")

    @property
    def count(self) -> int:
        """N(N−1)/2 for N links."""
        n = len(self.links)
        return n * (n - 1) // 2


def ordered(links: tuple[str, ...], i: str, j: str) -> tuple[str, str]:
    """The two links in the order of the diagram."""
    return (i, j) if links.index(i) < links.index(j) else (j, i)


def circle_diagram(mech: Mechanism) -> CircleDiagram:
    """Find the order of the centres: the pairs first, then Kennedy's theorem, the centre with the
    most closed triangles first."""
    links = (GROUND, *mech.moving)
    known: dict[tuple[str, str], Centre] = {}
    for pair in mech.pairs:
        key = ordered(links, pair.a, pair.b)
        if key not in known:
            known[key] = Centre(*key, order=len(known), pair=pair)
    while True:
        best: tuple[int, tuple[str, str], tuple[str, ...]] | None = None
        for i, j in itertools.combinations(links, 2):
            if (i, j) in known:
                continue
            via = tuple(k for k in links if k not in (i, j)
                        and ordered(links, i, k) in known and ordered(links, j, k) in known)
            if len(via) >= 2 and (best is None or len(via) > best[0]):
                best = (len(via), (i, j), via)
        if best is None:
            break
        known[best[1]] = Centre(*best[1], order=len(known), via=best[2])
    missing = tuple(p for p in itertools.combinations(links, 2) if p not in known)
    return CircleDiagram(links, tuple(sorted(known.values(), key=lambda c: c.order)), missing)


@dataclass
class CentreValues:
    """One centre at every position: ``h`` (N, 3) in normal form (see ``ops/centres.py``),
    ``size`` the conditioning |l1 × l2| of its meet (1 for a primary one), ``sine`` of the lines'
    crossing angle (0: at infinity), ``triangles`` (N, 2) the indices in ``via`` of the two
    triangles used, ``error`` the estimated error of its homogeneous direction (relative)."""

    h: Array
    size: Array
    sine: Array
    triangles: Array
    error: Array


@dataclass
class Centres:
    """All the instant centres of a mechanism at N positions (``length``: the scale L, m)."""

    diagram: CircleDiagram
    length: float
    values: dict[tuple[str, str], CentreValues] = field(default_factory=dict)

    def of(self, i: str, j: str) -> CentreValues:
        """The values of I_ij (either order)."""
        return self.values[ordered(self.diagram.links, i, j)]

    def point(self, i: str, j: str) -> Array:
        """(N, 2) positions in metres (NaN at infinity)."""
        return H.point(self.of(i, j).h, self.length)

    def direction(self, i: str, j: str) -> Array:
        """(N, 2) unit directions of the centre where it is at infinity (NaN where finite)."""
        return H.direction(self.of(i, j).h)


def label(centre: Centre | tuple[str, str], symbol: str = "I",
          links: tuple[str, ...] | None = None) -> str:
    """``I13`` (``I1,13`` for link ids longer than one character); a pair of links is written in
    the order of ``links`` (the diagram's: the frame first)."""
    i, j = (centre.i, centre.j) if isinstance(centre, Centre) else centre
    if links is not None and i in links and j in links:
        i, j = ordered(links, i, j)
    return f"{symbol}{i}{j}" if len(i) == len(j) == 1 else f"{symbol}{i},{j}"


def centres_at(c: Construction, ev: Evaluation, mech: Mechanism,
               position_error: Array | None = None) -> Centres:
    """All the instant centres at an evaluation's positions."""
    return evaluate_centres(mech, lambda p: ev[c.position(p)], lambda lk: ev[c.link_angle(lk)],
                            length_scale(c), ev.n, position_error)


def evaluate_centres(mech: Mechanism, position: Callable[[str], Array],
                     link_angle: Callable[[str], Array], length: float, n: int,
                     position_error: Array | None = None) -> Centres:
    """Evaluate every centre at n positions.

    ``position(point)`` gives (n, 2) world positions (m), ``link_angle(link)`` (n,) the angle of
    a link's frame (rad); ``position_error`` (n,) the relative error of the position plan."""
    diagram = circle_diagram(mech)
    base = np.full(n, np.finfo(float).eps * ROUNDINGS)
    if position_error is not None:
        base = np.fmax(base, np.asarray(position_error, dtype=float))
    out = Centres(diagram, length)
    for c in diagram.centres:
        if c.pair is not None:
            out.values[(c.i, c.j)] = CentreValues(
                _primary(mech, c.pair, position, link_angle, length), np.ones(n), np.ones(n),
                np.zeros((n, 2), dtype=int), base.copy())
        else:
            out.values[(c.i, c.j)] = _kennedy(out, c, n)
    return out


def _primary(mech: Mechanism, pair: Pair, position: Callable[[str], Array],
             link_angle: Callable[[str], Array], length: float) -> Array:
    if pair.kind is PairKind.REVOLUTE:
        return H.finite(np.asarray(position(pair.point), dtype=float), length)
    assert pair.guide is not None
    guide = mech.guides[pair.guide]
    theta = guide.angle + (np.asarray(link_angle(guide.link), dtype=float)
                           if guide.link != GROUND else 0.0)
    theta = np.broadcast_to(theta, position(pair.point).shape[:1])
    # the slider translates along its guide: the centre is at infinity ⊥ the guide (it turns
    # with the link that carries the guide)
    return H.normalised(H.infinite(np.stack([-np.sin(theta), np.cos(theta)], axis=-1)))


def _line(out: Centres, a: str, b: str, k: str) -> tuple[Array, Array, Array]:
    """The line through I_ak and I_bk, its conditioning and the error of its direction."""
    p, q = out.of(a, k), out.of(b, k)
    line, size = H.join(p.h, q.h)
    with np.errstate(divide="ignore", invalid="ignore"):
        err = (p.error + q.error) / size
    return line, size, err


def _kennedy(out: Centres, c: Centre, n: int) -> CentreValues:
    lines = [_line(out, c.i, c.j, k) for k in c.via]
    combos = list(itertools.combinations(range(len(c.via)), 2))
    best: CentreValues | None = None
    for a, b in combos:
        (l1, _, e1), (l2, _, e2) = lines[a], lines[b]
        h, size, sine = H.meet(l1, l2)
        with np.errstate(divide="ignore", invalid="ignore"):
            err = (e1 + e2) / size + np.finfo(float).eps * ROUNDINGS
        err = np.where(np.isfinite(err), err, np.inf)
        tri = np.tile([a, b], (n, 1))
        if best is None:
            best = CentreValues(h, size, sine, tri, err)
            continue
        # the drawn construction (the first triangles) unless its lines (nearly) coincide
        better = (err < best.error) & (best.error > 1e-9)
        if better.any():
            best.h[better], best.size[better] = h[better], size[better]
            best.sine[better], best.triangles[better] = sine[better], tri[better]
            best.error[better] = err[better]
    assert best is not None
    return best
