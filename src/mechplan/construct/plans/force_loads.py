"""Loads of the force plan: inertia forces and couples, weights and the external loads.

Each load becomes a step and a :class:`Term` of the link it acts on; the groups' polygons
(:mod:`.force`) lay the terms head to tail.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from string import ascii_lowercase
from typing import Any, Protocol

from ...model.mechanism import GROUND
from ...model.plans import Plan
from ..builder import Builder, alabel
from ..ops import Op, OpSpec
from ..step import Kind, Role
from ..terms import GIVEN, Direction, Relation, from_to
from ..terms import parallel as parallel_to

F = Plan.FORCE


class LoadingLike(Protocol):
    """What the force plan needs of a loading (see :class:`mechplan.dynamics.loading.Loading`)."""

    masses: Mapping[str, Any]
    loads: tuple[Any, ...]
    gravity: Any

    def check(self, mech: Any) -> None:
        """Raise SceneError if the loading does not fit the mechanism."""



@dataclass(frozen=True, slots=True)
class Term:
    """A known load on a link: a force at a point, a couple, or both (a guide reaction).

    ``direction``/``magnitude`` are the entries of the vector-equation table ("⊥ BC", "m2·g").
    """

    label: str
    force: str | None = None
    point: str | None = None      # position step of the point of application
    couple: str | None = None
    direction: Direction = GIVEN
    magnitude: str = "✓"
    where: str = ""               # name of the point of application (for its velocity image)
    velocity: str | None = None   # its velocity image's step when ``where`` is not enough


@dataclass
class State:
    b: Builder
    loading: LoadingLike
    terms: dict[str, list[Term]] = field(default_factory=dict)
    #: loads (not reactions) with the link they act on, for Zhukovsky's lever
    applied: list[tuple[str, Term]] = field(default_factory=list)
    letters: dict[str, int] = field(default_factory=dict)

    def add(self, id: str, op: OpSpec, inputs: tuple[str, ...], kind: Kind, role: Role, label: str,
            group: str, subject: tuple[str, ...] = (), **params: Any) -> str:
        return self.b.add(id, op, inputs, F, kind, role, label, group, subject, **params)

    def label(self, sid: str) -> str:
        return self.b.c[sid].label

    def letter(self, group: str) -> str:
        n = self.letters.get(group, 0)
        self.letters[group] = n + 1
        return ascii_lowercase[n % 26] + (str(n // 26) if n >= 26 else "")


def group_of(b: Builder, link: str) -> str:
    for g in b.structure.groups:
        if link in g.links:
            return g.name
    for cyl in (b.structure.cylinder, b.structure.cylinder2):      # a cylinder's rod
        if cyl is not None and link == cyl[1]:
            return f"I({cyl[0]},{cyl[1]})"
    if b.mech.drive2 is not None and link == b.mech.drive2.link:    # W = 2: the second crank
        return f"I({GROUND},{link})"
    return f"I({GROUND},{b.mech.drive.link})"


def add_load(st: State, link: str, term: Term) -> None:
    st.terms[link].append(term)
    st.applied.append((link, term))


def inertia_and_weights(st: State) -> None:
    b, grav = st.b, st.loading.gravity
    for link, ms in st.loading.masses.items():
        group = group_of(b, link)
        s_pos = b.pos[ms.centre]
        q = mq = None
        if ms.mass > 0:
            q = st.add(f"force.Q.{link}", Op.FORCE_INERTIA, (b.acc[ms.centre],), Kind.POINT,
                       Role.RESULT, f"Q{link}", group, subject=(ms.centre, link), mass=ms.mass)
            b.result(f"Q_{link}", q)
            add_load(
                st,
                link,
                Term(
                    f"Q{link}",
                    q,
                    s_pos,
                    direction=Direction(Relation.OPPOSITE, f"π{alabel(ms.centre)}"),
                    magnitude=f"m{link}·a_{ms.centre}",
                    where=ms.centre,
                ),
            )
        if ms.inertia > 0:
            eps = b.bodies[link].epsilon
            assert eps is not None
            mq = st.add(f"force.Mq.{link}", Op.MOMENT_INERTIA, (eps,), Kind.SCALAR, Role.RESULT,
                        f"M_q{link}", group, subject=(link,), inertia=ms.inertia)
            b.result(f"M_q{link}", mq)
            add_load(
                st,
                link,
                Term(
                    f"M_q{link}",
                    couple=mq,
                    direction=Direction(Relation.AGAINST, f"ε{link}"),
                    magnitude=f"J_{ms.centre}·ε{link}",
                ),
            )
        if q is not None and mq is not None:
            h = st.add(f"force.h.{link}", Op.INERTIA_OFFSET, (q, mq), Kind.SCALAR,
                       Role.AUXILIARY, f"h_q{link}", group, subject=(f"M_q{link}", f"Q{link}"))
            b.result(f"h_{link}", h)
            k = st.add(f"force.Kq.{link}", Op.LINE_OF_ACTION, (s_pos, q, mq), Kind.POINT,
                       Role.AUXILIARY, f"K{link}", group,
                       subject=(ms.centre, f"Q{link}", f"M_q{link}"))
            b.result(f"K_q{link}", k)
        if grav.enabled and ms.mass > 0 and grav.g > 0:
            gx, gy = grav.direction
            vec = (ms.mass * grav.g * gx, ms.mass * grav.g * gy)
            w = st.add(f"force.G.{link}", Op.FORCE_LOAD, (s_pos,), Kind.POINT, Role.GIVEN,
                       f"G{link}", group, subject=(ms.centre, link), mode="vector", vector=vec)
            b.result(f"G_{link}", w)
            arrow = {(0.0, -1.0): "↓", (0.0, 1.0): "↑", (1.0, 0.0): "→", (-1.0, 0.0): "←"}
            gdir = (Direction(Relation.SYMBOL, arrow[(gx, gy)]) if (gx, gy) in arrow
                    else parallel_to("g"))
            add_load(st, link, Term(f"G{link}", w, s_pos, direction=gdir,
                                 magnitude=f"m{link}·g", where=ms.centre))


def external_loads(st: State) -> None:
    b = st.b
    seen: dict[str, int] = {}
    for j, spec in enumerate(st.loading.loads):
        link = spec.link
        group = group_of(b, link)
        kind = spec.kind.value
        sid = f"force.load.{j}"
        if kind == "moment":
            m = st.add(sid, Op.CONSTANT, (), Kind.SCALAR, Role.GIVEN, spec.name or f"M{link}",
                       group, subject=(link,), value=float(spec.moment))
            b.result(f"load_{j}", m)
            add_load(st, link, Term(spec.name or f"M{link}", couple=m))
            continue
        if kind in ("spring", "cylinder"):
            _two_point_load(st, j, spec, seen)
            continue
        point = spec.point
        label = _label(seen, point, spec.name)
        p = b.pos[point]
        direction_text, magnitude_text = GIVEN, "✓"
        if kind == "force":
            if spec.along is not None:
                start, to = spec.along
                f = st.add(sid, Op.FORCE_LOAD, (p, b.pos[start], b.pos[to]), Kind.POINT,
                           Role.GIVEN, label, group, subject=(point, start, to), mode="along",
                           magnitude=float(spec.magnitude), turn=float(spec.angle or 0.0))
                direction_text = (from_to(start, to) if not spec.angle
                                  else Direction(Relation.SYMBOL, f"∠({start}{to}, F)"))
            elif spec.vector is not None:
                f = st.add(sid, Op.FORCE_LOAD, (p,), Kind.POINT, Role.GIVEN, label, group,
                           subject=(point,), mode="vector", vector=tuple(spec.vector))
            elif spec.towards is not None:
                f = st.add(sid, Op.FORCE_LOAD, (p, b.pos[spec.towards]), Kind.POINT, Role.GIVEN,
                           label, group, subject=(point, spec.towards), mode="towards",
                           magnitude=float(spec.magnitude))
                direction_text = from_to(point, spec.towards)
            else:
                vec = (spec.magnitude * math.cos(spec.angle), spec.magnitude * math.sin(spec.angle))
                f = st.add(sid, Op.FORCE_LOAD, (p,), Kind.POINT, Role.GIVEN, label, group,
                           subject=(point,), mode="vector", vector=vec)
        else:
            slides_on = b.mech.links[link].slides_on
            theta = b.bodies[link].angle
            assert slides_on is not None and theta is not None    # Loading.check made sure
            guide = b.mech.guides[slides_on]
            towards = b.pos[spec.towards]
            direction_text = Direction(Relation.PARALLEL, guide.name,
                                       then=Direction(Relation.TOWARDS, spec.towards))
            if kind == "pressure":
                area = math.pi * spec.bore ** 2 / 4.0
                f = st.add(sid, Op.FORCE_LOAD, (p, towards, theta), Kind.POINT, Role.GIVEN,
                           label, group, subject=(point, spec.towards, guide.name), mode="guide",
                           value=float(spec.pressure) * area)
                magnitude_text = "p·πd²/4"
            elif spec.against == "displacement":
                xs, fs = zip(*spec.table)
                f = st.add(sid, Op.FORCE_LOAD, (p, b.pos[guide.through], towards, theta),
                           Kind.POINT, Role.GIVEN, label, group,
                           subject=(point, spec.towards, guide.name), mode="table_s",
                           xs=tuple(xs), fs=tuple(fs))
                magnitude_text = f"F(s_{point})"
            else:
                xs, fs = zip(*spec.table)
                drive = b.mech.drive
                f = st.add(sid, Op.FORCE_LOAD, ("pos.phi1", p, towards, theta), Kind.POINT,
                           Role.GIVEN, label, group, subject=(point, spec.towards, guide.name),
                           mode="table_phi", xs=tuple(xs), fs=tuple(fs), ref=drive.ref_angle,
                           sense=drive.sense)
                magnitude_text = f"F(φ{drive.link})"
        b.result(f"load_{j}", f)
        add_load(st, link, Term(label, f, p, direction=direction_text, magnitude=magnitude_text,
                             where=point))


def _label(seen: dict[str, int], point: str, name: str | None) -> str:
    """``F_B``, ``F_B′``, … (or the load's own name) for the n-th load at a point."""
    n = seen.get(point, 0)
    seen[point] = n + 1
    return (name or f"F_{point}") + "′" * (n if name is None else 0)


def _two_point_load(st: State, j: int, spec: Any, seen: dict[str, int]) -> None:
    """A spring or cylinder: a force at each end on a moving link, equal and opposite."""
    b = st.b
    if spec.kind.value == "spring":
        t0, k, l0 = float(spec.preload or 0.0), float(spec.stiffness), float(spec.free_length)
        magnitude = "c·Δl"
    else:
        t0, k, l0 = -spec.cylinder_push(), 0.0, 0.0
        magnitude = "p·A − p′·A′"
    ends = ((spec.point, spec.link, spec.other), (spec.other, spec.other_link, spec.point))
    for n, (at, link, other) in enumerate(ends):
        if link is None or link == GROUND:
            continue
        group = group_of(b, link)
        label = _label(seen, at, None if spec.name is None else spec.name + "′" * n)
        f = st.add(f"force.load.{j}" + ("" if n == 0 else ".other"), Op.FORCE_LOAD,
                   (b.pos[at], b.pos[other]), Kind.POINT, Role.GIVEN, label, group,
                   subject=(at, other), mode="pull", t0=t0, k=k, l0=l0)
        b.result(f"load_{j}" + ("" if n == 0 else "_other"), f)
        add_load(st, link, Term(label, f, b.pos[at], direction=parallel_to(f"{at}{other}"),
                                magnitude=magnitude, where=at))


# -- building blocks of the group constructions ----------------------------------------------
