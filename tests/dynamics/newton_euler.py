"""An independent force solver: every link's equilibrium (d'Alembert) as one linear system.

It uses only the mechanism, the loading specs and the kinematics of the construction (positions,
accelerations, angles) — none of the force plan — and solves all joint reactions and the
balancing moment at once with numpy, position by position in one batched call.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mechplan.dynamics import Loading
from mechplan.model.loads import Gravity, LoadKind, LoadSpec, MassSpec
from mechplan.model.mechanism import GROUND, DriverKind, Mechanism, PairKind


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _perp(v):
    return np.stack((-v[..., 1], v[..., 0]), axis=-1)


def _dir(angle):
    return np.stack((np.cos(angle), np.sin(angle)), axis=-1)


@dataclass
class Global:
    """Reactions of the global solution: force of link a on link b for each pair (a, b)."""

    force: dict[tuple[str, str], np.ndarray]      # (a, b) → (N, 2), both orders
    # prismatic: couple with the force at the pair point
    couple: dict[tuple[str, str], np.ndarray]
    balancing: np.ndarray
    #: W = 2: the second crank's balancing moment
    second: np.ndarray | None = None


class Kinematics:
    """Positions, velocities, accelerations from an evaluated construction."""

    def __init__(self, mech: Mechanism, c, ev):
        self.mech, self.c, self.ev, self.n = mech, c, ev, ev.n

    def pos(self, p):
        return self.ev[f"pos.{p}"]

    def _point(self, sym, p):
        if p in self.mech.links[GROUND].points:
            return np.zeros((self.n, 2))
        return self.ev[self.c.results[f"{sym}_{p}"]]

    def vel(self, p):
        return self._point("v", p)

    def acc(self, p):
        return self._point("a", p)

    def scalar(self, key, link):
        if link == GROUND:
            return np.zeros(self.n)
        return self.ev[self.c.results[f"{key}_{link}"]]

    def guide_dir(self, guide_name):
        g = self.mech.guides[guide_name]
        return _dir(self.scalar("angle", g.link) + g.angle)


def applied_loads(mech: Mechanism, loading: Loading, kin: Kinematics, phi: np.ndarray,
                  inertia: bool = True):
    """(link, point xy | None, force (N,2) | None, couple (N,) | None) of every load."""
    out = []
    g = loading.gravity
    for link, ms in loading.masses.items():
        s = kin.pos(ms.centre)
        if inertia:
            out.append((link, ms.centre, s, -ms.mass * kin.acc(ms.centre), None))
            out.append((link, None, None, None, -ms.inertia * kin.scalar("epsilon", link)))
        if g.enabled:
            w = ms.mass * g.g * np.asarray(g.direction, dtype=float)
            out.append((link, ms.centre, s, np.broadcast_to(w, s.shape), None))
    for spec in loading.loads:
        if spec.kind is LoadKind.MOMENT:
            out.append((spec.link, None, None, None, np.full(kin.n, spec.moment)))
            continue
        p = kin.pos(spec.point)
        if spec.kind in (LoadKind.SPRING, LoadKind.CYLINDER):
            # tension positive pulls the ends together; a cylinder pushes them apart
            d = kin.pos(spec.other) - p
            length = np.hypot(d[:, 0], d[:, 1])
            if spec.kind is LoadKind.SPRING:
                tension = spec.preload + spec.stiffness * (length - spec.free_length)
            else:
                area = math.pi * spec.bore ** 2 / 4
                rod_area = math.pi * spec.rod ** 2 / 4
                tension = -(spec.pressure * area - spec.pressure_rod * (area - rod_area)) \
                    * np.ones_like(length)
            f = tension[:, None] * d / length[:, None]
            out.append((spec.link, spec.point, p, f, None))
            if spec.other_link not in (None, GROUND):
                out.append((spec.other_link, spec.other, kin.pos(spec.other), -f, None))
            continue
        if spec.kind is LoadKind.FORCE and spec.along is not None:
            d = kin.pos(spec.along[1]) - kin.pos(spec.along[0])
            ang = np.arctan2(d[:, 1], d[:, 0]) + (spec.angle or 0.0)
            f = spec.magnitude * np.stack((np.cos(ang), np.sin(ang)), axis=-1)
            out.append((spec.link, spec.point, p, f, None))
            continue
        if spec.kind is LoadKind.FORCE:
            if spec.vector is not None:
                f = np.broadcast_to(np.asarray(spec.vector, dtype=float), p.shape)
            elif spec.towards is not None:
                d = kin.pos(spec.towards) - p
                f = spec.magnitude * d / np.hypot(d[:, 0], d[:, 1])[:, None]
            else:
                f = np.broadcast_to(spec.magnitude * np.array([math.cos(spec.angle),
                                                               math.sin(spec.angle)]), p.shape)
        else:
            u = kin.guide_dir(mech.links[spec.link].slides_on)
            sign = np.sign(np.sum((kin.pos(spec.towards) - p) * u, axis=-1))
            if spec.kind is LoadKind.PRESSURE:
                value = np.full(kin.n, spec.pressure * math.pi * spec.bore ** 2 / 4)
            else:
                xs = np.array([r[0] for r in spec.table])
                fs = np.array([r[1] for r in spec.table])
                if spec.against == "crank_angle":
                    x = xs[0] + np.mod(phi - xs[0], 2 * math.pi)
                else:
                    through = kin.pos(mech.guides[mech.links[spec.link].slides_on].through)
                    x = np.sum((p - through) * u, axis=-1)
                value = np.interp(x, xs, fs)
            f = (value * sign)[:, None] * u
        out.append((spec.link, spec.point, p, np.array(f), None))
    return out


def solve_global(mech: Mechanism, loading: Loading, c, ev) -> Global:
    """Solve all reactions and the balancing moment from the 3·n equilibrium equations."""
    kin = Kinematics(mech, c, ev)
    n = ev.n
    moving = mech.moving
    row = {link: 3 * k for k, link in enumerate(moving)}
    size = 3 * len(moving)
    a = np.zeros((n, size, size))
    known = np.zeros((n, size))

    def put(target, link, force, point, couple, col=None):
        if link == GROUND:
            return
        r = row[link]
        if col is None:
            if force is not None:
                target[:, r] += force[:, 0]
                target[:, r + 1] += force[:, 1]
                target[:, r + 2] += _cross(point, force)
            if couple is not None:
                target[:, r + 2] += couple
        else:
            if force is not None:
                target[:, r, col] += force[:, 0]
                target[:, r + 1, col] += force[:, 1]
                target[:, r + 2, col] += _cross(point, force)
            if couple is not None:
                target[:, r + 2, col] += couple

    ones, zeros2 = np.ones(n), np.zeros((n, 2))
    col = 0
    layout = []
    for pair in mech.pairs:
        p = kin.pos(pair.point)
        if pair.kind is PairKind.REVOLUTE:
            for e in (np.array([1.0, 0.0]), np.array([0.0, 1.0])):
                f = np.broadcast_to(e, (n, 2))
                put(a, pair.b, f, p, None, col)
                put(a, pair.a, -f, p, None, col)
                col += 1
        else:
            nrm = _perp(kin.guide_dir(pair.guide))     # force of carrier b on slider a: N·n + C
            put(a, pair.a, nrm, p, None, col)
            put(a, pair.b, -nrm, p, None, col)
            put(a, pair.a, None, p, ones, col + 1)
            put(a, pair.b, None, p, -ones, col + 1)
            col += 2
        layout.append(pair)
    first = col
    for drive in mech.drivers:          # one balancing moment per crank (W = 2: two)
        if drive.kind is DriverKind.SLIDER:     # a driving force along its frame guide
            put(a, drive.link, kin.guide_dir(drive.guide), kin.pos(drive.pivot), None, col)
        else:
            put(a, drive.link, None, zeros2, ones, col)
        col += 1
    assert col == size
    for link, _, point, force, couple in applied_loads(mech, loading, kin, ev.phi):
        put(known, link, force, point, couple)
    x = np.linalg.solve(a, -known[..., None])[..., 0]
    forces, couples = {}, {}
    col = 0
    for pair in layout:
        if pair.kind is PairKind.REVOLUTE:
            f = x[:, col:col + 2]
            col += 2
            forces[(pair.a, pair.b)] = f
            forces[(pair.b, pair.a)] = -f
        else:
            nrm = _perp(kin.guide_dir(pair.guide))
            f = x[:, col, None] * nrm
            forces[(pair.b, pair.a)] = f
            forces[(pair.a, pair.b)] = -f
            couples[(pair.b, pair.a)] = x[:, col + 1]
            couples[(pair.a, pair.b)] = -x[:, col + 1]
            col += 2
    return Global(forces, couples, x[:, first],
                  x[:, first + 1] if mech.drive2 is not None else None)


def rich_loading(mech: Mechanism) -> Loading:
    """Masses on every moving link (centre at its last point), a J, gravity, and external loads of
    every kind that fits the mechanism."""
    masses = {}
    for k, link in enumerate(mech.moving):
        points = list(mech.links[link].points)
        masses[link] = MassSpec(link, 1.5 + k, points[-1], 0.02 * (k + 1))
    last = mech.moving[-1]
    loads = [LoadSpec(LoadKind.FORCE, last, next(iter(mech.links[last].points)),
                      vector=(30.0, -50.0), key="test.force"),
             LoadSpec(LoadKind.MOMENT, mech.moving[len(mech.moving) // 2], moment=7.0,
                      key="test.moment")]
    pivot = mech.drive.pivot
    for link in mech.moving:
        lk = mech.links[link]
        if lk.slides_on is None:
            continue
        point = next(iter(lk.points))
        loads.append(LoadSpec(LoadKind.PRESSURE, link, point, pressure=2.0e5, bore=0.05,
                              towards=pivot, key=f"test.pressure.{link}"))
        loads.append(LoadSpec(LoadKind.TABLE, link, point, towards=pivot, against="crank_angle",
                              table=((0.0, 10.0), (math.pi, 200.0), (2 * math.pi, 10.0)),
                              key=f"test.table.phi.{link}"))
        loads.append(LoadSpec(LoadKind.TABLE, link, point, towards=pivot, against="displacement",
                              table=((-1.0, -40.0), (0.0, 15.0), (1.0, 80.0)),
                              key=f"test.table.s.{link}"))
    others = [lk for lk in mech.moving if lk != last and len(mech.links[lk].points) >= 2]
    if others:
        lk = others[0]
        p, q = list(mech.links[lk].points)[:2]
        loads.append(LoadSpec(LoadKind.FORCE, lk, q, magnitude=25.0, towards=p, key="test.towards"))
        loads.append(LoadSpec(LoadKind.FORCE, lk, p, magnitude=12.0, angle=math.radians(200),
                              key="test.angle"))
    return Loading(masses, tuple(loads), Gravity(9.81, (0.0, -1.0), True))
