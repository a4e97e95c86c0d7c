"""Masses, gravity and external loads of a scene ([links.N] mass data, [gravity], [[loads]])."""

from __future__ import annotations

import itertools
import math

from ..i18n import Text
from ..model.loads import (
    FrictionSpec,
    Gravity,
    LoadKind,
    LoadSpec,
    MassSpec,
    PairFriction,
    pair_id,
)
from ..model.mechanism import GROUND, Guide, Link
from .reader import Table


def masses_of(top: Table, links: dict[str, Link]) -> dict[str, MassSpec]:
    lt = top.table("links")
    assert lt is not None
    masses: dict[str, MassSpec] = {}
    for lid in lt.data:
        t = lt.table(lid)
        assert t is not None
        mass = t.quantity("mass", "mass", nonnegative=True)
        inertia = t.quantity("J", "inertia", nonnegative=True)
        if inertia is None:
            inertia = t.quantity("inertia", "inertia", nonnegative=True)
        centre_raw = t.raw("centre", t.raw("center"))
        if mass is None and inertia is None:
            continue
        if isinstance(centre_raw, dict):
            if len(centre_raw) != 1:
                raise t.error(
                    "centre",
                    Text("errmsg.scene_loads.expected_one_point", {"centre_raw": repr(centre_raw)}),
                )
            centre = next(iter(centre_raw))
        elif isinstance(centre_raw, str):
            centre = centre_raw
        elif len(links[lid].points) == 1:
            centre = next(iter(links[lid].points))
        else:
            raise t.error(
                "centre",
                Text("errmsg.scene_loads.link_mass_needs"),
            )
        if centre not in links[lid].points:
            raise t.error(
                "centre",
                Text(
                    "errmsg.scene_loads.point_centre_not",
                    {
                        "centre": repr(centre),
                        "lid": str(lid),
                        "points": ", ".join(links[lid].points),
                    },
                ),
            )
        masses[lid] = MassSpec(lid, mass or 0.0, centre, inertia or 0.0)
    return masses


def gravity_of(top: Table) -> Gravity:
    t = top.table("gravity")
    if t is None:
        return Gravity(enabled=False)
    t.check_keys(("g", "direction", "enabled"))
    enabled = t.raw("enabled", True)
    if not isinstance(enabled, bool):
        raise t.error("enabled", Text("errmsg.scene_loads.expected_true_false"))
    g = t.quantity("g", "acceleration", 9.81, nonnegative=True) or 0.0
    direction = t.string("direction", "-y") or "-y"
    axes = {"-y": (0.0, -1.0), "+y": (0.0, 1.0), "y": (0.0, 1.0), "-x": (-1.0, 0.0),
            "+x": (1.0, 0.0), "x": (1.0, 0.0)}
    if direction in axes:
        vec = axes[direction]
    else:
        ang = t.value_quantity(direction, "direction", "angle")
        vec = (math.cos(ang), math.sin(ang))
    return Gravity(g=g, direction=vec, enabled=enabled)


def loads_of(top: Table, links: dict[str, Link], guides: dict[str, Guide],
           masses: dict[str, MassSpec]) -> tuple[LoadSpec, ...]:
    raw = top.raw("loads", [])
    if not isinstance(raw, list):
        raise top.error("loads", Text("errmsg.scene_loads.expected_loads_entries"))
    out: list[LoadSpec] = []
    for i, entry in enumerate(raw):
        t = Table(entry, f"loads[{i}]", top.file)
        out.append(_load(t, links, guides))
    return tuple(out)


def _point_link(t: Table, links: dict[str, Link], point: str, link: str | None) -> str:
    owners = [k for k, lk in links.items() if point in lk.points and k != GROUND]
    if link is not None:
        if link not in links or link == GROUND:
            raise t.error(
                "link", Text("errmsg.scene_loads.unknown_moving_link", {"link": repr(link)})
            )
        if point not in links[link].points:
            raise t.error("point", Text("errmsg.scene_loads.point_point_not", {"point": repr(point),
                                                                               "link": str(link)}))
        return link
    if not owners:
        raise t.error(
            "point", Text("errmsg.scene_loads.unknown_point_point", {"point": repr(point)})
        )
    return owners[-1]


def _load(t: Table, links: dict[str, Link], guides: dict[str, Guide]) -> LoadSpec:
    if "force" in t.data:
        raise t.error("force", Text("errmsg.scene_loads.unknown_key_load"))
    t.check_keys(("type", "kind", "link", "point", "vector", "magnitude", "angle", "towards",
                  "toward", "pressure", "bore", "moment", "against", "table", "name", "along",
                  "between", "links", "stiffness", "free_length", "preload", "rod",
                  "pressure_rod", "torque"))
    kinds = (*(k.value for k in LoadKind), "torque")
    kind_s = t.string("type", t.string("kind"), choices=kinds)
    if kind_s is None:
        raise t.error(
            "type", Text("errmsg.scene_loads.missing_one_kinds", {"kinds": ", ".join(kinds)})
        )
    kind = LoadKind.MOMENT if kind_s == "torque" else LoadKind(kind_s)
    _only_own_keys(t, kind_s)
    link = t.string("link")
    name = t.string("name")
    if kind is LoadKind.MOMENT:
        if link is None or link not in links or link == GROUND:
            raise t.error(
                "link", Text("errmsg.scene_loads.moment_acts_moving", {"link": repr(link)})
            )
        key = "torque" if t.has("torque") else "moment"
        return LoadSpec(kind, link, moment=t.quantity(key, "moment", required=True), key=t.path,
                        name=name)
    if kind in (LoadKind.SPRING, LoadKind.CYLINDER):
        return _two_point(t, kind, links, name)
    point = t.string("point", required=True)
    assert point is not None
    owner = _point_link(t, links, point, link)
    towards = t.string("towards") or t.string("toward")
    if towards is not None and not any(towards in lk.points for lk in links.values()):
        raise t.error(
            "towards", Text("errmsg.scene_loads.unknown_point_towards", {"towards": repr(towards)})
        )
    if towards is not None and towards == point:
        raise t.error(
            "towards",
            Text(
                "errmsg.scene_loads.load_point_cannot", {"point": str(point), "point2": str(point)}
            ),
        )
    if kind is LoadKind.FORCE and t.has("along"):
        along = t.raw("along")
        if (not isinstance(along, list) or len(along) != 2
                or not all(isinstance(x, str) for x in along) or along[0] == along[1]):
            raise t.error("along", Text("errmsg.scene_loads.expected_two_different2"))
        for q in along:
            if not any(q in lk.points for lk in links.values()):
                raise t.error("along", Text("errmsg.scene_loads.unknown_point_q", {"q": repr(q)}))
        mag = t.quantity("magnitude", "force", required=True)
        return LoadSpec(kind, owner, point, magnitude=mag,
                        angle=t.quantity("angle", "angle", 0.0), along=(along[0], along[1]),
                        key=t.path, name=name)
    if kind is LoadKind.FORCE:
        if t.has("vector"):
            v = t.raw("vector")
            if not isinstance(v, list) or len(v) != 2:
                raise t.error("vector", Text("errmsg.scene_loads.expected_fx_fy"))
            vec = (
                t.value_quantity(v[0], "vector", "force"),
                t.value_quantity(v[1], "vector", "force"),
            )
            return LoadSpec(kind, owner, point, vector=vec, key=t.path)
        mag = t.quantity("magnitude", "force", required=True, nonnegative=True)
        if towards is None and not t.has("angle"):
            raise t.error(None, Text("errmsg.scene_loads.force_needs_vector"))
        return LoadSpec(kind, owner, point, magnitude=mag, angle=t.quantity("angle", "angle"),
                        towards=towards, key=t.path)
    if links[owner].slides_on is None:
        raise t.error("point", Text("errmsg.scene_loads.value_load_acts", {"value": str(kind.value),
                                                                           "owner": str(owner)}))
    if towards is None:
        raise t.error("towards", Text("errmsg.scene_loads.give_sense_along"))
    if kind is LoadKind.PRESSURE:
        if not t.has("bore"):
            raise t.error(
                "bore", Text("errmsg.scene_loads.pressure_needs_piston")
            )
        return LoadSpec(
            kind,
            owner,
            point,
            pressure=t.quantity("pressure", "pressure", required=True),
            bore=t.quantity("bore", "length", positive=True),
            towards=towards,
            key=t.path,
        )
    against = t.string("against", "crank_angle", choices=("crank_angle", "displacement"))
    rows = t.raw("table", required=True)
    if not isinstance(rows, list) or len(rows) < 2:
        raise t.error("table", Text("errmsg.scene_loads.expected_least_two"))
    xdim = "angle" if against == "crank_angle" else "length"
    parsed = []
    for j, row in enumerate(rows):
        if not isinstance(row, list) or len(row) != 2:
            raise t.error(f"table[{j}]", Text("errmsg.scene_loads.expected_row_x"))
        parsed.append((t.value_quantity(row[0], f"table[{j}]", xdim),
                       t.value_quantity(row[1], f"table[{j}]", "force")))
    xs = [r[0] for r in parsed]
    if any(b <= a for a, b in itertools.pairwise(xs)):
        raise t.error("table", Text("errmsg.scene_loads.first_column_increase"))
    if against == "crank_angle" and xs[-1] - xs[0] > 4 * math.pi + 1e-9:
        raise t.error(
            "table",
            Text(
                "errmsg.scene_loads.table_against_crank",
                {"value": f"{math.degrees(xs[-1] - xs[0]):g}"},
            ),
        )
    return LoadSpec(kind, owner, point, towards=towards, against=against, table=tuple(parsed),
                    key=t.path)


#: keys that belong to some load types only (the older types keep their own checks)
_OWN_KEYS = {"along": ("force",), "torque": ("torque", "moment"),
             **{k: ("spring", "cylinder") for k in ("between", "links")},
             **{k: ("spring",) for k in ("stiffness", "free_length", "preload")},
             **{k: ("cylinder",) for k in ("rod", "pressure_rod")}}


def _only_own_keys(t: Table, kind: str) -> None:
    for key, kinds in _OWN_KEYS.items():
        if t.has(key) and kind not in kinds:
            raise t.error(
                key,
                Text(
                    "errmsg.scene_loads.not_key_load",
                    {"kind": repr(kind), "kinds": " and ".join(kinds)},
                ),
            )
    if kind in ("spring", "cylinder"):
        for key in ("point", "link", "vector", "magnitude", "angle", "towards", "toward",
                    "moment", "table", "against") + (("pressure", "bore") if kind == "spring"
                                                      else ()):
            if t.has(key):
                raise t.error(key, Text("errmsg.scene_loads.not_key_kind", {"kind": str(kind)}))


def _end_link(t: Table, links: dict[str, Link], point: str, link: str | None, j: int) -> str:
    """The link carrying one end of a spring or cylinder (``"0"``: the frame)."""
    if link is not None:
        if link not in links:
            raise t.error(
                f"links[{j}]", Text("errmsg.scene_loads.unknown_link_link", {"link": repr(link)})
            )
        if point not in links[link].points:
            raise t.error(
                f"links[{j}]",
                Text(
                    "errmsg.scene_loads.point_point_not2", {"point": repr(point), "link": str(link)}
                ),
            )
        return link
    owners = [k for k, lk in links.items() if point in lk.points]
    if not owners:
        raise t.error(
            f"between[{j}]", Text("errmsg.scene_loads.unknown_point_point2", {"point": repr(point)})
        )
    moving = [k for k in owners if k != GROUND]
    if len(moving) > 1:
        raise t.error(
            "links",
            Text(
                "errmsg.scene_loads.point_point_links",
                {"point": repr(point), "moving": ", ".join(moving)},
            ),
        )
    return moving[0] if moving else GROUND


def _two_point(t: Table, kind: LoadKind, links: dict[str, Link], name: str | None) -> LoadSpec:
    """A spring or a double-acting cylinder between two points."""
    between = t.raw("between", required=True)
    if (not isinstance(between, list) or len(between) != 2
            or not all(isinstance(x, str) for x in between) or between[0] == between[1]):
        raise t.error("between", Text("errmsg.scene_loads.expected_two_different"))
    given = t.raw("links", [None, None])
    if not isinstance(given, list) or len(given) != 2:
        raise t.error("links", Text("errmsg.scene_loads.expected_two_links"))
    ends = [_end_link(t, links, between[j], None if given[j] is None else str(given[j]), j)
            for j in range(2)]
    if ends[0] == ends[1]:
        raise t.error(
            "between",
            Text(
                "errmsg.scene_loads.both_ends_are", {"ends": str(ends[0]), "value": str(kind.value)}
            ),
        )
    if GROUND == ends[0]:
        between, ends = between[::-1], ends[::-1]
    common = {"link": ends[0], "point": between[0], "other": between[1],
              "other_link": ends[1], "key": t.path, "name": name}
    if kind is LoadKind.SPRING:
        return LoadSpec(kind, stiffness=t.quantity("stiffness", "stiffness", required=True,
                                                   nonnegative=True),
                        free_length=t.quantity("free_length", "length", required=True,
                                               nonnegative=True),
                        preload=t.quantity("preload", "force", 0.0), **common)  # type: ignore[arg-type]
    bore = t.quantity("bore", "length", required=True, positive=True)
    rod = t.quantity("rod", "length", 0.0, nonnegative=True) or 0.0
    if bore is not None and rod >= bore:
        raise t.error(
            "rod",
            Text(
                "errmsg.scene_loads.rod_diameter_smaller",
                {"value": f"{rod * 1000.0:g}", "value2": f"{bore * 1000.0:g}"},
            ),
        )
    return LoadSpec(kind, bore=bore, rod=rod, pressure=t.quantity("pressure", "pressure", 0.0),
                    pressure_rod=t.quantity("pressure_rod", "pressure", 0.0),
                    **common)  # type: ignore[arg-type]


def friction_of(top: Table) -> FrictionSpec | None:
    """The ``[friction]`` table: default coefficient and pin radius, per-pair values."""
    t = top.table("friction")
    if t is None:
        return None
    t.check_keys(("f", "pin_radius", "pairs", "tolerance", "max_iterations", "diagram"))
    f = t.quantity("f", "dimensionless", 0.0, nonnegative=True) or 0.0
    radius = t.quantity("pin_radius", "length", 0.0, nonnegative=True) or 0.0
    diagram = t.raw("diagram", False)
    if not isinstance(diagram, bool):
        raise t.error("diagram", Text("errmsg.scene_loads.expected_true_false2"))
    iterations = t.raw("max_iterations", 50)
    if (not isinstance(iterations, int) or isinstance(iterations, bool)
            or not 1 <= iterations <= 1000):
        raise t.error(
            "max_iterations",
            Text("errmsg.scene_loads.expected_whole_number", {"iterations": repr(iterations)}),
        )
    tol = t.quantity("tolerance", "dimensionless", 1e-10, positive=True) or 1e-10
    pairs: list[tuple[str, PairFriction]] = []
    pt = t.table("pairs")
    if pt is not None:
        for name in pt.data:
            parts = str(name).split("-")
            if len(parts) != 2 or not all(parts):
                raise pt.error(name, Text("errmsg.scene_loads.pair_named_two"))
            entry = pt.table(name) if isinstance(pt.raw(name), dict) else None
            if entry is None:
                raise pt.error(name, Text("errmsg.scene_loads.expected_f_radius"))
            entry.check_keys(("f", "radius"))
            pairs.append((pair_id(*parts), PairFriction(
                entry.quantity("f", "dimensionless", f, nonnegative=True) or 0.0,
                entry.quantity("radius", "length", radius, nonnegative=True) or 0.0)))
    return FrictionSpec(PairFriction(f, radius), tuple(pairs), tol, iterations, diagram, t.path)
