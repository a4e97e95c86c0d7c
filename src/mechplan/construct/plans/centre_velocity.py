"""The velocities by instant centres as a drawn construction: one step per line a student draws.

The links are reached from the driver one at a time (the order is the topology's, the same at
every position), each through a centre it shares with a link already known — a pin first, then a
centre found by Kennedy's theorem, last a centre at infinity (a prismatic pair: ω is carried over).
Through a finite common centre I = I_mj the *line of centres* method is drawn (a known point of m
carried by an arc about I_0m to the line, similar triangles to I, then to a point B of j carried by
an arc about I_0j, and back); ω_j and the velocities of j's other points follow by its instant
centre (МЦС): ω_j = v_B / I_0jB, v_X = ω_j · I_0jX. The operations are ``ops/centre_velocity.py``;
the positions, centres and ω of the driver are given by the solved mechanism (overrides).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from ...geom.vec import Array
from ...model.mechanism import GROUND, DriverKind, Mechanism, PairKind
from ...model.plans import Plan
from ..graph import Construction, DriveMap, Evaluation
from ..ops import Op
from ..segments import Segment, SegmentKind
from ..step import Kind, Role, Step
from .centres import Centres, CircleDiagram, label, ordered

#: how a link is reached from a known one through their common centre (the preferred first)
PIN, KENNEDY, SLIDE = 0, 1, 2
#: the token of a centre's name in labels and subjects (written with the language's letter)
CENTRE = "@"


@dataclass(frozen=True, slots=True)
class Route:
    """How link ``link`` is reached: from ``source`` through their centre ``centre`` (keys of the
    diagram), by ``kind`` (PIN, KENNEDY or SLIDE); ``carried`` the point of j drawn by the line
    of centres (None: only the centre, or a centre at infinity)."""

    link: str
    source: str
    centre: tuple[str, str]
    kind: int
    carried: str | None


@dataclass
class CentreVelocity:
    """The construction and where its results are: ω per link and v per named point (step ids);
    ``given`` the overrides it needs (step id → what: ``("r", point)``, ``("h", i, j)``,
    ``("p", i, j)`` or ``("omega", link)``)."""

    construction: Construction
    length: float
    driver: str
    omega: dict[str, str] = field(default_factory=dict)
    v: dict[str, str] = field(default_factory=dict)
    routes: list[Route] = field(default_factory=list)
    given: dict[str, tuple[str, ...]] = field(default_factory=dict)


def centre_token(i: str, j: str, links: tuple[str, ...]) -> str:
    """``@13``: a centre in a label, written later with the language's letter."""
    return CENTRE + label(ordered(links, i, j), "", links)


class _Builder:
    def __init__(self, mech: Mechanism, diagram: CircleDiagram, length: float) -> None:
        self.mech, self.diagram, self.length = mech, diagram, length
        self.c = Construction(DriveMap(0.0, 1))
        self.out = CentreVelocity(self.c, length, mech.drive.link)
        self.ground_points = set(mech.links[GROUND].points)
        self.origin = self._add("ic.origin", Op.IC_ORIGIN, (), Plan.VELOCITY, Kind.POINT,
                                Role.AUXILIARY, "0")

    def _add(self, sid: str, op, inputs: tuple[str, ...], plan: Plan,  # type: ignore[no-untyped-def]
             kind: Kind, role: Role, lbl: str, subject: tuple[str, ...] = (),
             **params: object) -> str:
        if sid in self.c:
            return sid
        ps = tuple(params.items()) + (("length", self.length),)
        return self.c.add(Step(sid, op, inputs, plan, kind, role, lbl, "centres", ps, subject))

    def given(self, sid: str, what: tuple[str, ...], kind: Kind, width: int) -> str:
        self.out.given[sid] = what
        plan = Plan.VELOCITY if what[0] == "omega" else Plan.POSITION
        return self._add(sid, Op.IC_GIVEN, (), plan, kind, Role.GIVEN, sid, width=width)

    def r(self, point: str) -> str:
        return self.given(f"ic.r.{point}", ("r", point), Kind.POINT, 2)

    def h(self, i: str, j: str) -> str:
        a, b = ordered(self.diagram.links, i, j)
        return self.given(f"ic.h.{a},{b}", ("h", a, b), Kind.POINT, 3)

    def p(self, i: str, j: str) -> str:
        a, b = ordered(self.diagram.links, i, j)
        return self.given(f"ic.p.{a},{b}", ("p", a, b), Kind.POINT, 2)

    def tok(self, i: str, j: str) -> str:
        return centre_token(i, j, self.diagram.links)

    def velocity(self, sid: str, op, inputs: tuple[str, ...], lbl: str,  # type: ignore[no-untyped-def]
                 subject: tuple[str, ...], role: Role = Role.RESULT) -> str:
        self._add(sid, op, inputs, Plan.VELOCITY, Kind.POINT, role, lbl, subject)
        self.c.segments.append(Segment(Plan.VELOCITY, self.origin, sid, lbl, lbl,
                                       SegmentKind.ABSOLUTE, "centres"))
        return sid

    def points(self, link: str) -> list[str]:
        return [p for p in self.mech.links[link].points if p not in self.ground_points]


def _has(diagram: CircleDiagram, i: str, j: str) -> bool:
    try:
        diagram.centre(i, j)
    except KeyError:
        return False
    return True


def _kind(diagram: CircleDiagram, i: str, j: str) -> int:
    ctr = diagram.centre(i, j)
    if ctr.pair is None:
        return KENNEDY
    return PIN if ctr.pair.kind is PairKind.REVOLUTE else SLIDE


def build_centre_velocity(mech: Mechanism, diagram: CircleDiagram,
                          length: float) -> CentreVelocity:
    """The construction of the velocities by instant centres of a crank-driven mechanism.

    A link no centre reaches (a centre Kennedy's theorem leaves out) is left out; a linear
    driver has no ω to start from, so nothing is built for it (the caller says so)."""
    b = _Builder(mech, diagram, length)
    lt = diagram.links
    known: list[str] = []
    for drive in mech.drivers:          # W = 2: both cranks are known from the start
        if drive.kind is not DriverKind.CRANK or not _has(diagram, GROUND, drive.link):
            continue
        d = drive.link
        w = b.given(f"ic.omega.{d}", ("omega", d), Kind.SCALAR, 0)
        b.out.omega[d] = w
        for x in b.points(d):
            if x not in b.out.v:
                b.out.v[x] = b.velocity(f"ic.v.{x}", Op.IC_DRIVE_VELOCITY,
                                        (b.h(GROUND, d), b.r(x), w), f"v_{x}",
                                        (x, b.tok(GROUND, d), d))
        known.append(d)
    pending = [lk for lk in mech.moving if lk not in known and _has(diagram, GROUND, lk)]
    while pending:
        best: tuple[int, int, str, str] | None = None
        for n, j in enumerate(pending):
            for m in known:
                if _has(diagram, m, j):
                    cand = (_kind(diagram, m, j), n, j, m)
                    if best is None or cand[:2] < best[:2]:
                        best = cand
        if best is None:
            break
        kind, _n, j, m = best
        _reach(b, j, m, kind, lt)
        known.append(j)
        pending.remove(j)
    return b.out


def _reach(b: _Builder, j: str, m: str, kind: int, lt: tuple[str, ...]) -> None:
    """The steps that find link j from the known link m through their common centre."""
    out, h0j, tok0j = b.out, b.h(GROUND, j), b.tok(GROUND, j)
    todo = [x for x in b.points(j) if x not in out.v]
    if kind == SLIDE:
        out.omega[j] = b._add(f"ic.omega.{j}", Op.IC_SAME_OMEGA, (out.omega[m],), Plan.VELOCITY,
                              Kind.SCALAR, Role.RESULT, f"ω{j}", (f"ω{m}", m, j))
        nan = b._add("ic.none", Op.IC_GIVEN, (), Plan.VELOCITY, Kind.POINT, Role.GIVEN, "?")
        for x in todo:
            out.v[x] = b.velocity(f"ic.v.{x}", Op.IC_POLE_VELOCITY,
                                  (h0j, out.omega[j], b.r(x), nan), f"v_{x}", (x, tok0j, j))
        out.routes.append(Route(j, m, ordered(lt, m, j), kind, None))
        return
    ctr = b.diagram.centre(m, j)
    tok = b.tok(m, j)
    if kind == PIN:
        assert ctr.pair is not None
        at_i, v_i = b.r(ctr.pair.point), out.v[ctr.pair.point]
    else:
        at_i = b.p(m, j)
        h0m, tok0m = b.h(GROUND, m), b.tok(GROUND, m)
        a = next(x for x in b.points(m) if x in out.v)
        carried = b._add(f"ic.c.{a}.{j}", Op.IC_CARRY, (h0m, b.r(a), b.h(m, j)), Plan.POSITION,
                         Kind.POINT, Role.AUXILIARY, f"{a}*", (a, tok0m, tok))
        v_c = b.velocity(f"ic.vc.{a}.{j}", Op.IC_ARC_VELOCITY,
                         (h0m, b.r(a), out.v[a], carried), f"v_{a}*", (a, tok0m, f"{a}*"),
                         Role.AUXILIARY)
        v_i = b.velocity(f"ic.vi.{m}.{j}", Op.IC_SIMILAR_VELOCITY, (h0m, carried, v_c, at_i),
                         f"v_{tok}", (f"{a}*", tok0m, tok))
    first = todo[0] if todo else None
    if first is not None:
        carried = b._add(f"ic.c.{first}.{j}", Op.IC_CARRY, (h0j, b.r(first), b.h(m, j)),
                         Plan.POSITION, Kind.POINT, Role.AUXILIARY, f"{first}*",
                         (first, tok0j, tok))
        v_c = b.velocity(f"ic.vc.{first}.{j}", Op.IC_SIMILAR_VELOCITY,
                         (h0j, at_i, v_i, carried), f"v_{first}*", (tok, tok0j, f"{first}*"),
                         Role.AUXILIARY)
        out.v[first] = b.velocity(f"ic.v.{first}", Op.IC_ARC_VELOCITY,
                                  (h0j, carried, v_c, b.r(first)), f"v_{first}",
                                  (f"{first}*", tok0j, first))
    # МЦС: ω_j from the common centre (its distance from I_0j vanishes only where the
    # construction is indeterminate), then every other point of j
    out.omega[j] = b._add(f"ic.omega.{j}", Op.IC_POLE_OMEGA, (h0j, at_i, v_i), Plan.VELOCITY,
                          Kind.SCALAR, Role.RESULT, f"ω{j}", (tok, tok0j, j))
    for x in todo[1:]:
        out.v[x] = b.velocity(f"ic.v.{x}", Op.IC_POLE_VELOCITY, (h0j, out.omega[j], b.r(x), v_i),
                              f"v_{x}", (x, tok0j, j))
    out.routes.append(Route(j, m, ordered(lt, m, j), kind, first))


def evaluate_centre_velocity(cv: CentreVelocity, cs: Centres,
                             position: Callable[[str], Array],
                             omega: Mapping[str, Array]) -> Evaluation:
    """Evaluate the construction on a solved mechanism's positions, centres and driver's ω."""
    n = next(iter(cs.values.values())).h.shape[0]
    over: dict[str, Array] = {}
    for sid, what in cv.given.items():
        if what[0] == "r":
            over[sid] = np.asarray(position(what[1]), dtype=float)
        elif what[0] == "h":
            over[sid] = cs.of(what[1], what[2]).h
        elif what[0] == "p":
            over[sid] = cs.point(what[1], what[2])
        else:
            over[sid] = np.broadcast_to(np.asarray(omega[what[1]], dtype=float), (n,))
    ev = cv.construction.evaluate(np.zeros(n), overrides=over)
    ev.evaluate_all([*cv.omega.values(), *cv.v.values()])
    return ev


def crank_driven(mech: Mechanism) -> bool:
    """Whether the velocities by centres can start from the driver (a crank)."""
    return mech.drive.kind is DriverKind.CRANK


__all__ = ["CENTRE", "KENNEDY", "PIN", "SLIDE", "CentreVelocity", "Route",
           "build_centre_velocity", "centre_token", "crank_driven", "evaluate_centre_velocity"]
