"""The machine over its steady cycle: reduced moment of the given loads, J_red and dJ_red/dφ.

The cycle angle θ runs from the cycle's start (the scene's first position φ0) through Φ = 2π or 4π
in the sense of rotation; the scene's crank angle is φ = φ0 + θ. Loads that depend on the position
only (forces, pressures, moments, displacement tables, weights) come from the construction's force
plan; loads tabulated against the crank angle (including an indicator diagram) are a unit force from
the construction times the tabulated value at θ, so a table may span the whole 720° cycle.
Reduction by the equality of powers with the crank's speed |ω1| (the drive's speed, constant):
M = P/|ω1| is positive where the loads drive (power > 0); J_red = Σ(m v_S² + J_S ω²)/ω1²;
dJ_red/dφ = 2 Σ(m v_S·a_S + J_S ω ε)/(ω1²·|ω1|).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..construct.builder import build_construction
from ..errors import SceneError
from ..geom.vec import Array, dot
from ..i18n import Text
from ..model.dynamics import DynamicsSpec, IndicatorSpec
from ..model.loads import LoadKind, LoadSpec
from ..model.mechanism import GROUND
from ..model.structure import analyse
from ..scene.spec import PLANS, Scene
from .loading import Loading

_UNIT_TABLE = ((0.0, 1.0), (2.0 * math.pi, 1.0))


@dataclass(frozen=True)
class CycleState:
    """Given loads reduced to the crank and the reduced inertia at cycle angles ``theta`` (N,)."""

    theta: Array          # rad, from the cycle's start
    M_given: Array        # N·m, positive where the given loads drive
    M_lever: Array        # N·m, the same from Zhukovsky's lever (moments about the pole)
    J_red: Array          # kg·m², of the mechanism's links
    dJ_red: Array         # kg·m²/rad
    J_crank: float        # kg·m², the driving link's own (constant) part of J_red


@dataclass(frozen=True)
class _Tabled:
    """A load tabulated against the crank angle: its index among the loads, its table, its
    period."""

    index: int
    xs: Array
    fs: Array
    period: float


class MachineCycle:
    """Evaluate a mechanism scene's dynamics inputs at any cycle angles (vectorised)."""

    def __init__(self, scene: Scene, spec: DynamicsSpec, phi0: float) -> None:
        mech = scene.mechanism
        if mech.drive.epsilon != 0.0:
            raise SceneError(
                Text(
                    "errmsg.dynamics_cycle.drive_s_angular", {"epsilon": f"{mech.drive.epsilon:g}"}
                ),
                file=scene.path,
                key="drive.epsilon",
            )
        self.scene, self.spec, self.phi0 = scene, spec, phi0
        self.omega1 = abs(mech.drive.omega)
        base = Loading.from_scene(scene)
        loads: list[LoadSpec] = []
        self.tabled: list[_Tabled] = []
        for i, load in enumerate(base.loads):
            if load.kind is LoadKind.TABLE and load.against == "crank_angle":
                self.tabled.append(self._tabled(i, load, spec.cycle))
                load = replace(load, table=_UNIT_TABLE)
            loads.append(load)
        self.indicator_index: int | None = None
        if spec.indicator is not None:
            ind = spec.indicator
            self.indicator_index = len(loads)
            loads.append(LoadSpec(LoadKind.TABLE, ind.link, ind.point, towards=ind.towards,
                                  against="crank_angle", table=_UNIT_TABLE, key=ind.key))
        self.loading = Loading(base.masses, tuple(loads), base.gravity, scene.path)
        self.loading.check(mech)
        self.c = build_construction(mech, analyse(mech), PLANS, scene.assembly_phi, scene.path,
                                    self.loading)
        self._indicator_table: tuple[Array, Array] | None = None
        if spec.indicator is not None:
            self._indicator_table = self._indicator(spec.indicator)

    def _tabled(self, i: int, load: LoadSpec, cycle: float) -> _Tabled:
        xs = np.array([x for x, _ in load.table])
        fs = np.array([f for _, f in load.table])
        span = xs[-1] - xs[0]
        key = load.key or f"loads[{i}]"
        if abs(span - 2 * math.pi) < 1e-6:
            period = 2 * math.pi
        elif abs(span - cycle) < 1e-6:
            period = cycle
        else:
            raise SceneError(
                Text(
                    "errmsg.dynamics_cycle.load_table_against",
                    {"cycle": f"{math.degrees(cycle):g}", "span": f"{math.degrees(span):g}"},
                ),
                file=self.scene.path,
                key=f"{key}.table",
            )
        if abs(fs[-1] - fs[0]) > 1e-6 * max(float(np.abs(fs).max()), 1e-300):
            raise SceneError(Text("errmsg.dynamics_cycle.load_table_over", {"fs": f'{fs[0]:g}',
                                                                            "fs2": f'{fs[-1]:g}'}),
                             file=self.scene.path, key=f"{key}.table")
        return _Tabled(i, xs, fs, period)

    def _indicator(self, ind: IndicatorSpec) -> tuple[Array, Array]:
        """The indicator as a force (N) tabulated against the cycle angle θ."""
        area = math.pi * ind.bore ** 2 / 4.0
        cycle = self.spec.cycle
        if ind.table:
            xs = np.array([x for x, _ in ind.table])
            ps = np.array([p for _, p in ind.table])
            if abs(xs[0]) > 1e-6 or abs(xs[-1] - cycle) > 1e-6:
                raise SceneError(
                    Text(
                        "errmsg.dynamics_cycle.indicator_diagram_cover",
                        {
                            "cycle": f"{math.degrees(cycle):g}",
                            "xs": f"{math.degrees(xs[0]):g}",
                            "xs2": f"{math.degrees(xs[-1]):g}",
                        },
                    ),
                    file=self.scene.path,
                    key=f"{ind.key}.table",
                )
            if abs(ps[-1] - ps[0]) > 1e-6 * float(np.abs(ps).max()):
                raise SceneError(
                    Text(
                        "errmsg.dynamics_cycle.indicator_diagram_periodic",
                        {
                            "cycle": f"{math.degrees(cycle):g}",
                            "ps": f"{ps[0]:g}",
                            "ps2": f"{ps[-1]:g}",
                        },
                    ),
                    file=self.scene.path,
                    key=f"{ind.key}.table",
                )
            return xs, (ps - ind.ambient) * area
        # per stroke: pressure against the piston's displacement from the starting dead centre,
        # evaluated exactly at each θ (see _stroke_force); here only checked
        probe = self.c.evaluate(self.phi0 + np.linspace(0.0, 2 * math.pi, 73))
        speeds = np.hypot(*self._velocity(probe, ind.point, 73).T)
        self._r0 = probe[self.c.position(ind.point)][0]
        if speeds[0] > 1e-6 * speeds.max():
            raise SceneError(
                Text(
                    "errmsg.dynamics_cycle.indicator_diagram_strokes",
                    {
                        "point": str(ind.point),
                        "speeds": f"{speeds[0]:.3g}",
                        "point2": str(ind.point),
                    },
                ),
                file=self.scene.path,
                key="positions.start",
            )
        travel = float(np.hypot(*(probe[self.c.position(ind.point)] - self._r0).T).max())
        self._strokes: list[tuple[Array, Array]] = []
        for stroke, rows in ind.strokes:
            xs = np.array([x for x, _ in rows])
            order = np.argsort(xs)
            xs, ps = xs[order], np.array([p for _, p in rows])[order]
            if xs[0] > 1e-3 * travel or xs[-1] < travel * (1 - 1e-3):
                raise SceneError(
                    Text(
                        "errmsg.dynamics_cycle.value_stroke_s",
                        {
                            "value": str(stroke.value),
                            "value2": f"{travel * 1000:.1f}",
                            "value3": f"{xs[0] * 1000:g}",
                            "value4": f"{xs[-1] * 1000:g}",
                        },
                    ),
                    file=self.scene.path,
                    key=f"{ind.key}.strokes.{stroke.value}",
                )
            self._strokes.append((xs, (ps - ind.ambient) * area))
        return np.zeros(0), np.zeros(0)

    def _stroke_force(self, theta: Array, r_point: Array) -> Array:
        """Gas force by strokes: stroke k covers θ in [kπ, (k+1)π), p from s = |r − r_TDC|."""
        s = np.hypot(*(r_point - self._r0).T)
        k = np.minimum(np.floor(np.mod(theta, self.spec.cycle) / math.pi).astype(int),
                       len(self._strokes) - 1)
        out = np.zeros_like(s)
        for j, (xs, fs) in enumerate(self._strokes):
            sel = k == j
            out[sel] = np.interp(s[sel], xs, fs)
        return out

    def _velocity(self, ev: object, point: str, n: int) -> Array:
        if point in self.scene.mechanism.links[GROUND].points:
            return np.zeros((n, 2))
        return ev[self.c.velocity_image(point)]  # type: ignore[index]

    def _acceleration(self, ev: object, point: str, n: int) -> Array:
        if point in self.scene.mechanism.links[GROUND].points:
            return np.zeros((n, 2))
        return ev[self.c.acceleration_image(point)]  # type: ignore[index]

    def indicator_force(self, theta: Array, r_point: Array) -> Array:
        """Gas force (N, positive towards ``towards``) at cycle angles θ, piston at ``r_point``."""
        if self.spec.indicator is None or self._indicator_table is None:
            return np.zeros_like(theta)
        if self.spec.indicator.strokes:
            return self._stroke_force(theta, r_point)
        xs, fs = self._indicator_table
        return np.interp(np.mod(theta, self.spec.cycle), xs, fs)

    def evaluate(self, theta: Array) -> CycleState:
        """Return the given loads' reduced moment and J_red, dJ_red/dφ at cycle angles θ (rad)."""
        theta = np.asarray(theta, dtype=float)
        phi = self.phi0 + theta
        c, mech, n = self.c, self.scene.mechanism, theta.shape[0]
        ev = c.evaluate(phi)
        power = np.zeros(n)
        lever = np.zeros(n)
        for link, ms in self.loading.masses.items():
            weight = c.weight(link)
            if weight is not None:
                G, v = ev[weight], self._velocity(ev, ms.centre, n)
                power += dot(G, v)
                lever += _lever(G, v)
        factors = {t.index: np.interp(t.xs[0] + np.mod(phi - t.xs[0], t.period), t.xs, t.fs)
                   for t in self.tabled}
        if self.indicator_index is not None:
            point = self.loading.loads[self.indicator_index].point
            assert point is not None
            factors[self.indicator_index] = self.indicator_force(theta, ev[c.position(point)])
        for j, load in enumerate(self.loading.loads):
            load_id = c.load(j)
            if load_id is None:
                raise KeyError(f"the construction has no load {j}")
            value = ev[load_id]
            factor = factors.get(j, 1.0)
            if load.point is None:
                p = value * ev[c.omega(load.link)]
                lever += p * factor          # a couple's moment times ω_i/ω1 on the lever
            else:
                v = self._velocity(ev, load.point, n)
                p = dot(value, v)
                lever += _lever(value, v) * factor
            other = c.results.get(f"load_{j}_other")     # the far end of a spring or cylinder
            if other is not None and load.other is not None:
                v2 = self._velocity(ev, load.other, n)
                p = p + dot(ev[other], v2)
                lever += _lever(ev[other], v2) * factor
            power += p * factor
        w1 = mech.drive.omega
        energy = np.zeros(n)
        d_energy = np.zeros(n)
        crank = 0.0
        for link, ms in self.loading.masses.items():
            v = self._velocity(ev, ms.centre, n)
            a = self._acceleration(ev, ms.centre, n)
            w = ev[c.omega(link)]
            e = ev[c.epsilon(link)]
            energy += ms.mass * dot(v, v) + ms.inertia * w * w
            d_energy += ms.mass * dot(v, a) + ms.inertia * w * e
            if link == mech.drive.link:
                crank = float(np.mean(ms.mass * dot(v, v) + ms.inertia * w * w)) / w1 ** 2
        return CycleState(theta, power / self.omega1, lever / self.omega1, energy / w1 ** 2,
                          2.0 * d_energy / (w1 ** 2 * self.omega1), crank)


def _lever(force: Array, v: Array) -> Array:
    """Moment about the pole of ``force`` applied at the velocity image turned 90° clockwise."""
    r = np.stack([v[:, 1], -v[:, 0]], axis=-1)
    return r[:, 0] * force[:, 1] - r[:, 1] * force[:, 0]
