"""What loads a mechanism: masses and moments of inertia, gravity, external forces and moments."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from ..errors import SceneError
from ..i18n import Text
from ..model.loads import FrictionSpec, Gravity, LoadKind, LoadSpec, MassSpec, pair_id
from ..model.mechanism import GROUND, Mechanism

if TYPE_CHECKING:
    from ..scene.spec import Scene


@dataclass(frozen=True, slots=True)
class Loading:
    """Masses (link → :class:`MassSpec`), external loads and gravity, in SI units.

    Pass it to ``build_construction(..., plans=(..., "force"), loading=...)``.
    """

    masses: dict[str, MassSpec] = field(default_factory=dict)
    loads: tuple[LoadSpec, ...] = ()
    gravity: Gravity = field(default_factory=Gravity)
    file: str | None = None
    friction: FrictionSpec | None = None

    @classmethod
    def from_scene(cls, scene: Scene) -> Loading:
        """Take the masses, loads and gravity of a parsed scene."""
        return cls(dict(scene.masses), tuple(scene.loads), scene.gravity, scene.path,
                   scene.friction)

    @property
    def is_empty(self) -> bool:
        """True when nothing loads the mechanism (no masses, no loads)."""
        return not self.loads and not any(m.mass or m.inertia for m in self.masses.values())

    def reversed(self) -> Loading:
        """The same loading with every external force, moment and gravity reversed.

        Masses are kept, so reactions reverse only when the masses are zero.
        """
        def flip(spec: LoadSpec) -> LoadSpec:
            return replace(
                spec,
                vector=None if spec.vector is None else (-spec.vector[0], -spec.vector[1]),
                angle=None if spec.angle is None else spec.angle + math.pi,
                pressure=None if spec.pressure is None else -spec.pressure,
                moment=None if spec.moment is None else -spec.moment,
                table=tuple((x, -f) for x, f in spec.table))
        flipped = []
        for spec in self.loads:
            if spec.kind in (LoadKind.SPRING, LoadKind.CYLINDER) or spec.along is not None:
                raise ValueError(f"load {spec.key or spec.point}: a {spec.kind.value} depends on "
                                 "the position and cannot be reversed")
            if spec.kind is LoadKind.FORCE and spec.vector is None and spec.towards is not None:
                # a force "towards a point" keeps its direction; reverse it by its sign instead
                raise ValueError(f"load {spec.key or spec.point}: a force towards a point cannot "
                                 "be reversed; give it as a vector")
            flipped.append(flip(spec))
        gravity = replace(self.gravity, direction=(-self.gravity.direction[0],
                                                   -self.gravity.direction[1]))
        return Loading(self.masses, tuple(flipped), gravity, self.file, self.friction)

    def check(self, mech: Mechanism) -> None:
        """Raise :class:`SceneError` if a mass or load does not fit the mechanism."""
        for link, ms in self.masses.items():
            key = f"links.{link}"
            if link not in mech.links or link == GROUND:
                raise SceneError(
                    Text(
                        "errmsg.dynamics_loading.masses_are_given",
                        {"link": repr(link), "moving": ", ".join(mech.moving)},
                    ),
                    file=self.file,
                    key=key,
                )
            if not (ms.mass >= 0 and math.isfinite(ms.mass)):
                raise SceneError(
                    Text(
                        "errmsg.dynamics_loading.mass_link_link",
                        {"link": str(link), "mass": str(ms.mass)},
                    ),
                    file=self.file,
                    key=f"{key}.mass",
                )
            if not (ms.inertia >= 0 and math.isfinite(ms.inertia)):
                raise SceneError(
                    Text(
                        "errmsg.dynamics_loading.moment_inertia_j",
                        {"link": str(link), "inertia": str(ms.inertia)},
                    ),
                    file=self.file,
                    key=f"{key}.J",
                )
            if ms.centre not in mech.links[link].points:
                raise SceneError(
                    Text(
                        "errmsg.dynamics_loading.centre_mass_centre",
                        {
                            "centre": repr(ms.centre),
                            "link": str(link),
                            "points": ", ".join(mech.links[link].points),
                        },
                    ),
                    file=self.file,
                    key=f"{key}.centre",
                )
        for i, spec in enumerate(self.loads):
            self._check_load(mech, spec, spec.key or f"loads[{i}]")
        if self.friction is not None:
            known = {pair_id(p.a, p.b) for p in mech.pairs}
            for name, _ in self.friction.pairs:
                if name not in known:
                    raise SceneError(
                        Text(
                            "errmsg.dynamics_loading.there_no_pair",
                            {"name": str(name), "known": ", ".join(sorted(known))},
                        ),
                        file=self.file,
                        key=f"{self.friction.key}.pairs.{name}",
                    )

    def _check_load(self, mech: Mechanism, spec: LoadSpec, key: str) -> None:
        def fail(message: str) -> SceneError:
            return SceneError(message, file=self.file, key=key)
        if spec.link not in mech.links or spec.link == GROUND:
            raise fail(Text("errmsg.dynamics_loading.load_acts_moving", {"link": repr(spec.link)}))
        if spec.kind is LoadKind.MOMENT:
            if spec.moment is None:
                raise fail(Text("errmsg.dynamics_loading.moment_load_needs"))
            return
        if spec.kind in (LoadKind.SPRING, LoadKind.CYLINDER):
            olink = spec.other_link or GROUND
            if olink not in mech.links or spec.other not in mech.links[olink].points:
                raise fail(
                    Text(
                        "errmsg.dynamics_loading.unknown_point_other",
                        {"other": repr(spec.other), "olink": str(olink)},
                    )
                )
        if spec.point is None or spec.point not in mech.links[spec.link].points:
            raise fail(
                Text(
                    "errmsg.dynamics_loading.unknown_point_point",
                    {
                        "point": repr(spec.point),
                        "link": str(spec.link),
                        "points": ", ".join(mech.links[spec.link].points),
                    },
                )
            )
        points = {p for link in mech.links.values() for p in link.points}
        if spec.towards is not None and spec.towards not in points:
            raise fail(
                Text(
                    "errmsg.dynamics_loading.unknown_point_towards", {"towards": repr(spec.towards)}
                )
            )
        if spec.kind in (LoadKind.SPRING, LoadKind.CYLINDER):
            return
        if spec.kind is LoadKind.FORCE:
            if spec.along is not None:
                if spec.magnitude is None or not all(q in points for q in spec.along):
                    raise fail(
                        Text(
                            "errmsg.dynamics_loading.force_along_along", {"along": str(spec.along)}
                        )
                    )
                return
            if spec.vector is None and spec.magnitude is None:
                raise fail(Text("errmsg.scene_loads.force_needs_vector"))
            if spec.vector is None and spec.towards is None and spec.angle is None:
                raise fail(Text("errmsg.dynamics_loading.force_given_magnitude"))
            if spec.vector is None and spec.towards == spec.point:
                raise fail(
                    Text(
                        "errmsg.dynamics_loading.force_point_cannot",
                        {"point": str(spec.point), "point2": str(spec.point)},
                    )
                )
            return
        if mech.links[spec.link].slides_on is None:
            raise fail(
                Text(
                    "errmsg.dynamics_loading.value_load_acts",
                    {"value": str(spec.kind.value), "link": str(spec.link)},
                )
            )
        if spec.towards is None:
            raise fail(Text("errmsg.dynamics_loading.give_sense_along"))
        if spec.kind is LoadKind.PRESSURE:
            if spec.bore is None or not spec.bore > 0:
                raise fail(
                    Text("errmsg.dynamics_loading.pressure_needs_piston", {"bore": str(spec.bore)})
                )
            if spec.pressure is None:
                raise fail(Text("errmsg.dynamics_loading.pressure_load_needs"))
            return
        if spec.against not in ("crank_angle", "displacement"):
            raise fail(
                Text("errmsg.dynamics_loading.table_given_against", {"against": repr(spec.against)})
            )
        xs = [x for x, _ in spec.table]
        if len(xs) < 2 or any(b <= a for a, b in itertools.pairwise(xs)):
            raise fail(Text("errmsg.dynamics_loading.table_needs_least"))
        if spec.against == "crank_angle" and xs[-1] - xs[0] > 4 * math.pi * (1 + 1e-12):
            raise fail(
                Text(
                    "errmsg.dynamics_loading.table_against_crank",
                    {"value": f"{math.degrees(xs[-1] - xs[0]):g}"},
                )
            )
