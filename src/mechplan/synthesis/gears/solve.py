"""Solve a gear scene: the planetary set (best or given), its velocity plan, the ordinary stage and
the involute pair."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import GearScene, OrdinarySpec, PlanetarySpec
from . import search, train
from .compound import Shift
from .contour import Contour, ContourSpec, blocking_contour
from .contour_internal import InternalPair
from .involute import Pair, pair_layout
from .plan import TrainPlan, velocity_plan

LISTED = 12          # other sets listed after the chosen one


@dataclass(frozen=True)
class PlanetaryResult:
    """The chosen set with its conditions, the others found, and the velocity plan."""

    spec: PlanetarySpec
    chosen: train.Conditions
    others: tuple[train.Conditions, ...]
    found: int
    counts: dict[str, int]
    plan: TrainPlan | None      # None: the set is not coaxial and cannot be drawn
    willis_i: float
    partials: tuple[TrainPlan, TrainPlan] | None = None   # differential: each input alone


@dataclass(frozen=True)
class OrdinaryResult:
    """The external pair after the planetary stage."""

    spec: OrdinarySpec
    z5: int
    z6: int
    ratio: float          # u56 = ω5/ω6 = −z6/z5


@dataclass(frozen=True)
class OrdinaryPlan:
    """The ordinary pair 5–6 on the train's velocity plan: gear 5 on the planetary output shaft
    (the central axis), gear 6 on a parallel axis at a56; v = ω·(y − y_axis) along the radius."""

    r5: float
    r6: float
    a56: float
    omega5: float
    omega6: float
    lines: dict[str, tuple[tuple[float, float], tuple[float, float]]]


@dataclass(frozen=True)
class GearSolution:
    """Everything a gear scene asks for."""

    scene: GearScene
    planetary: PlanetaryResult | None
    ordinary: OrdinaryResult | None
    pair: Pair | None
    contour: Contour | None = None        # the blocking contour, when the scene asks for it
    internal: InternalPair | None = None  # an internal pair (``[pair] internal = true``)
    compound: list[Shift] | None = None   # a Simpson or Ravigneaux set's gears

    @property
    def total_ratio(self) -> float | None:
        """u of the planetary stage times u56 (signed), or None without both stages."""
        if self.planetary is None or self.ordinary is None:
            return None
        return self.planetary.chosen.ratio * self.ordinary.ratio

    @property
    def ordinary_plan(self) -> OrdinaryPlan | None:
        """Gear 5 and gear 6 on the velocity plan (None without both stages and a plan)."""
        if self.planetary is None or self.ordinary is None or self.planetary.plan is None:
            return None
        o = self.ordinary
        r5, r6 = o.spec.module * o.z5 / 2, o.spec.module * o.z6 / 2
        a56 = r5 + r6
        w5 = self.planetary.plan.omega[self.planetary.spec.output]
        w6 = -w5 * r5 / r6                    # the pitch point: ω5·r5 = ω6·(r5 − a56)
        lines = {"5": ((0.0, 0.0), (r5, w5 * r5)),
                 "6": ((r5, w5 * r5), (a56 + r6, w6 * r6))}
        return OrdinaryPlan(r5, r6, a56, w5, w6, lines)

    @property
    def ordinary_omega(self) -> dict[str, float]:
        """ω5 (on the planetary output shaft) and ω6 = ω5/u56, rad/s (empty without both stages)."""
        if self.planetary is None or self.ordinary is None or self.planetary.plan is None:
            return {}
        w5 = self.planetary.plan.omega[self.planetary.spec.output]
        return {"5": w5, "6": w5 / self.ordinary.ratio}


def solve_planetary(spec: PlanetarySpec) -> PlanetaryResult:
    """Search the sets (or check the given one) and draw up the plan of the chosen set."""
    train.check_links(spec)
    if spec.speeds is not None:
        return solve_differential(spec)
    if spec.given is not None:
        chosen = train.conditions(spec, spec.given)
        result = search.search(spec)
    else:
        result = search.best_or_error(spec)
        chosen = train.conditions(spec, tuple(int(v) for v in result.sets[0]))
    others = tuple(train.conditions(spec, tuple(int(v) for v in z))
                   for z in result.sets[:LISTED + 1] if tuple(int(v) for v in z) != chosen.z)
    i = float(train.willis_exact(spec.scheme, chosen.z))
    plan = velocity_plan(spec, chosen.z, chosen.working) if chosen.coaxial else None
    return PlanetaryResult(spec, chosen, others[:LISTED], int(result.sets.shape[0]),
                           result.counts, plan, i)


def solve_differential(spec: PlanetarySpec) -> PlanetaryResult:
    """A differential (two links turning as given): the plan of both inputs, and of each input
    with the other held — the plan of both is their superposition."""
    assert spec.given is not None and spec.speeds is not None
    chosen = train.conditions(spec, spec.given)
    i = float(train.willis_exact(spec.scheme, chosen.z))
    plan = partials = None
    if chosen.coaxial:
        (l1, w1), (l2, w2) = spec.speeds
        plan = velocity_plan(spec, chosen.z, chosen.working, speeds={l1: w1, l2: w2})
        partials = (velocity_plan(spec, chosen.z, chosen.working, speeds={l1: w1, l2: 0.0}),
                    velocity_plan(spec, chosen.z, chosen.working, speeds={l1: 0.0, l2: w2}))
    return PlanetaryResult(spec, chosen, (), 0, {}, plan, i, partials)


def solve_ordinary(spec: OrdinarySpec, z_min: int = 17, deviation: float = 0.02) -> OrdinaryResult:
    """Given teeth, or the smallest z5 ≥ z_min with z6 = round(u·z5) within the deviation."""
    if spec.teeth is not None:
        z5, z6 = spec.teeth
    else:
        u = float(spec.ratio or 1.0)
        z5s = np.arange(z_min, 201)
        z6s = np.rint(u * z5s)
        err = np.abs(z6s / z5s - u) / u
        ok = np.flatnonzero(err <= deviation)
        if ok.size == 0:
            j = int(np.argmin(err))
            raise SceneError(
                Text(
                    "errmsg.synthesis_gears_solve.no_pair_z",
                    {
                        "z_min": str(z_min),
                        "u": f"{u:g}",
                        "value": f"{deviation * 100:g}",
                        "z6s": str(int(z6s[j])),
                        "z5s": str(int(z5s[j])),
                    },
                ),
                key="ordinary.ratio",
            )
        z5, z6 = int(z5s[ok[0]]), int(z6s[ok[0]])
    return OrdinaryResult(spec, z5, z6, -z6 / z5)


def solve_gears(scene: GearScene) -> GearSolution:
    """Solve every part of a gear scene; errors name the file and key."""
    try:
        planetary = solve_planetary(scene.planetary) if scene.planetary else None
        ordinary = None
        if scene.ordinary:
            p = scene.planetary
            ordinary = solve_ordinary(scene.ordinary, p.z_min if p else 17,
                                      p.deviation if p else 0.02)
        pair = None
        contour: Contour | None = None
        internal: InternalPair | None = None
        if scene.pair:
            spec = scene.pair
            if spec.z1 == 0 and ordinary is not None:
                spec = dataclasses.replace(spec, z1=ordinary.z5, z2=ordinary.z6)
            if spec.internal:
                from .contour_internal import internal_pair

                internal = internal_pair(spec)
            else:
                if spec.contour:
                    contour = blocking_contour(spec, ContourSpec(spec.tip_land, spec.eps_min))
                pair = pair_layout(spec, contour.recommended if contour else None)
        compound = None
        if scene.compound is not None:
            from .compound import solve_compound

            compound = solve_compound(scene.compound)
    except SceneError as exc:
        if exc.file:
            raise
        raise SceneError(exc.detail, file=scene.file, key=exc.key) from None
    return GearSolution(scene, planetary, ordinary, pair, contour, internal, compound)
