"""Build the construction of a mechanism: plans emitted group by group in attachment order."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import SceneError
from ..i18n import Text
from ..model.mechanism import GROUND, Guide, Link, Mechanism, Pair, PairKind
from ..model.plans import Plan
from ..model.structure import Structure
from .graph import Construction, DriveMap
from .ops import OpSpec
from .segments import Segment, SegmentKind
from .step import Kind, Role, Step


def vlabel(point: str) -> str:
    """Velocity-plan label of a point's image: B → b, S2 → s2."""
    return point[0].lower() + point[1:]


def alabel(point: str) -> str:
    """Acceleration-plan label of a point's image: B → b′."""
    return vlabel(point) + "′"


@dataclass
class Image:
    """A point of a link whose position, velocity and acceleration images are steps."""

    key: str                 # point name, or "A@3" for the point of link 3 under A
    label: str               # "A" or "A3"
    pos: str
    vel: str | None = None
    acc: str | None = None


@dataclass
class Body:
    """What the builder knows of a link so far."""

    link: Link
    angle: str | None = None
    anchor: str | None = None        # a named point with a position step
    omega: str | None = None
    epsilon: str | None = None
    images: list[Image] = field(default_factory=list)

    def image(self, key: str) -> Image | None:
        """Return the image record of a key, if known."""
        return next((im for im in self.images if im.key == key), None)


class Builder:
    """Emit steps for the requested plans into one :class:`Construction`."""

    def __init__(self, mech: Mechanism, structure: Structure, assembly_phi: float = 0.0,
                 file: str | None = None, loading: Any = None) -> None:
        self.mech = mech
        self.loading = loading          # a Loading (masses, loads, gravity) for the force plan
        self.structure = structure
        self.file = file
        self.assembly_phi = assembly_phi
        drive = mech.drive
        self.c = Construction(DriveMap(drive.ref_angle, drive.sense, drive.linear, drive.q_range))
        self.pos: dict[str, str] = {}
        self.vel: dict[str, str] = {}
        self.acc: dict[str, str] = {}
        self.bodies: dict[str, Body] = {k: Body(link) for k, link in mech.links.items()}

    # -- step helpers ------------------------------------------------------------------------
    def add(self, id: str, op: OpSpec, inputs: tuple[str, ...], plan: Plan, kind: Kind, role: Role,
            label: str, group: str = "", subject: tuple[str, ...] = (), **params: Any) -> str:
        """Add a step (or return the existing one with the same id)."""
        if id in self.c:
            return id
        return self.c.add(Step(id, op, inputs, plan, kind, role, label, group,
                               tuple(sorted(params.items())), subject))

    def segment(self, plan: Plan, start: str, end: str, name: str, quantity: str,
                kind: SegmentKind, group: str = "") -> None:
        """Record a measured segment."""
        if not any(s.start == start and s.end == end for s in self.c.segments):
            self.c.segments.append(Segment(plan, start, end, name, quantity, kind, group))

    def result(self, key: str, step_id: str) -> None:
        """Name a step as a result quantity."""
        self.c.results.setdefault(key, step_id)

    def guide_of(self, pair: Pair) -> Guide:
        """The guide of a prismatic pair."""
        assert pair.guide is not None
        return self.mech.guides[pair.guide]

    # -- branch (assembly mode) --------------------------------------------------------------
    def resolve_branch(self, step_id: str, point: str, group: str, probe: str) -> None:
        """Fix the sign of a two-solution meet from the scene's assembly data, once."""
        self.resolve_branch_probe(step_id, point, probe, group)

    def resolve_branch_probe(self, step_id: str, point: str, probe: str, group: str) -> None:
        """Fix the sign of ``step_id`` so that the point computed by ``probe`` is where asked."""
        step = self.c[step_id]
        mech = self.mech
        if point in mech.sketch:
            target = np.asarray(mech.sketch[point])
            dist = {}
            for sigma in (1, -1):
                self.c.steps[step_id] = _with(step, sigma=sigma)
                ev = self.c.evaluate(self.assembly_phi)
                dist[sigma] = float(np.linalg.norm(ev[probe][0] - target))
            if all(math.isnan(d) for d in dist.values()):
                raise SceneError(Text(
                    "errmsg2.builder.sketch_unreachable",
                    {"phi": f"{math.degrees(self.assembly_phi):g}", "point": point,
                     "group": group}), file=self.file, key=f"assembly.{point}")
            best = min(dist, key=lambda s: (math.inf if math.isnan(dist[s]) else dist[s]))
            self.c.steps[step_id] = _with(step, sigma=best)
            return
        if point not in mech.sides:
            return
        p, q, want = mech.sides[point]
        if not p:
            self.c.steps[step_id] = _with(step, sigma=want)
            return
        missing = [x for x in (p, q) if x not in self.pos]
        if missing:
            raise SceneError(Text(
                "errmsg2.builder.side_too_early",
                {"point": point, "group": group, "missing": ", ".join(missing),
                 "known": ", ".join(sorted(self.pos))}),
                file=self.file,
                key=f"assembly.{point}",
            )
        sides = []
        for sigma in (1, -1):
            self.c.steps[step_id] = _with(step, sigma=sigma)
            ev = self.c.evaluate(self.assembly_phi)
            a, b, k = ev[self.pos[p]][0], ev[self.pos[q]][0], ev[probe][0]
            side = (b[0] - a[0]) * (k[1] - a[1]) - (b[1] - a[1]) * (k[0] - a[0])
            if side * want > 0:
                return
            sides.append(abs(side) / max(float(np.hypot(*(b - a)) * np.hypot(*(k - a))), 1e-300))
        if all(math.isnan(x) or x < 1e-8 for x in sides):
            raise SceneError(Text(
                "errmsg2.builder.side_undecided",
                {"point": point, "p": p, "q": q,
                 "phi": f'{math.degrees(self.assembly_phi):g}'}), file=self.file,
                             key=f"assembly.{point}")
        raise SceneError(Text(
            "errmsg2.builder.neither_side",
            {"point": point,
             "side": Text('errmsg2.builder.left') if want > 0 else Text('errmsg2.builder.right'),
             "p": p, "q": q, "phi": f'{math.degrees(self.assembly_phi):g}'}),
                         file=self.file, key=f"assembly.{point}")

    # -- build -------------------------------------------------------------------------------
    def build(self, plans: tuple[str, ...]) -> Construction:
        """Emit the position plan and, as asked, velocity and acceleration plans."""
        from ..model.structure import Triad
        from .plans import acceleration, drivers, position, second_crank, triad, triadp, velocity

        position.emit_frame_and_drive(self)
        second_crank.emit_position(self)      # W = 2: the second crank (plans/second_crank.py)
        for group in self.structure.groups:
            if isinstance(group, Triad):
                (triadp if group.sliding else triad).emit_position(self, group)
            else:
                drivers.position_group(self, group)
        if "velocity" in plans or "acceleration" in plans or "force" in plans:
            velocity.emit_drive(self)
            second_crank.emit_velocity(self)
            for group in self.structure.groups:
                if isinstance(group, Triad):
                    (triadp if group.sliding else triad).emit_velocity(self, group)
                else:
                    drivers.velocity_group(self, group)
        if "acceleration" in plans or "force" in plans:
            acceleration.emit_drive(self)
            second_crank.emit_acceleration(self)
            for group in self.structure.groups:
                if isinstance(group, Triad):
                    (triadp if group.sliding else triad).emit_acceleration(self, group)
                else:
                    drivers.acceleration_group(self, group)
        if "force" in plans and self.loading is not None:
            from .plans import force
            force.emit(self)
        return self.c


def _with(step: Step, **changes: Any) -> Step:
    params = dict(step.params)
    params.update(changes)
    return Step(step.id, step.op, step.inputs, step.plan, step.kind, step.role, step.label,
                step.group, tuple(sorted(params.items())), step.subject)


def build_construction(mech: Mechanism, structure: Structure,
                       plans: tuple[str, ...] = ("position", "velocity", "acceleration"),
                       assembly_phi: float = 0.0, file: str | None = None,
                       loading: Any = None) -> Construction:
    """Build the construction of a mechanism for the requested plans."""
    return Builder(mech, structure, assembly_phi, file, loading).build(plans)


__all__ = [
    "GROUND",
    "Body",
    "Builder",
    "Image",
    "PairKind",
    "alabel",
    "build_construction",
    "vlabel",
]
