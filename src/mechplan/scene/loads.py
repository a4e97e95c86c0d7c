"""Masses, gravity and external loads of a scene ([links.N] mass data, [gravity], [[loads]])."""

from __future__ import annotations

import itertools
import math

from ..model.loads import Gravity, LoadKind, LoadSpec, MassSpec
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
                raise t.error("centre", "expected one point, "
                              "e.g. centre = { S2 = \"midpoint B C\" }"
                              f" (got {centre_raw!r})")
            centre = next(iter(centre_raw))
        elif isinstance(centre_raw, str):
            centre = centre_raw
        elif len(links[lid].points) == 1:
            centre = next(iter(links[lid].points))
        else:
            raise t.error(
                "centre",
                'a link with a mass needs its centre of mass, e.g. centre = "S2" '
                'or centre = { S2 = "midpoint B C" }',
            )
        if centre not in links[lid].points:
            raise t.error("centre", f"point {centre!r} is not on link {lid} (it has "
                          f"{', '.join(links[lid].points)})")
        masses[lid] = MassSpec(lid, mass or 0.0, centre, inertia or 0.0)
    return masses


def gravity_of(top: Table) -> Gravity:
    t = top.table("gravity")
    if t is None:
        return Gravity(enabled=False)
    t.check_keys(("g", "direction", "enabled"))
    enabled = t.raw("enabled", True)
    if not isinstance(enabled, bool):
        raise t.error("enabled", "expected true or false")
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
        raise top.error("loads", "expected [[loads]] entries")
    out: list[LoadSpec] = []
    for i, entry in enumerate(raw):
        t = Table(entry, f"loads[{i}]", top.file)
        out.append(_load(t, links, guides))
    return tuple(out)


def _point_link(t: Table, links: dict[str, Link], point: str, link: str | None) -> str:
    owners = [k for k, lk in links.items() if point in lk.points and k != GROUND]
    if link is not None:
        if link not in links or link == GROUND:
            raise t.error("link", f"unknown moving link {link!r}")
        if point not in links[link].points:
            raise t.error("point", f"point {point!r} is not on link {link}")
        return link
    if not owners:
        raise t.error("point", f"unknown point {point!r} (no moving link carries it)")
    return owners[-1]


def _load(t: Table, links: dict[str, Link], guides: dict[str, Guide]) -> LoadSpec:
    if "force" in t.data:
        raise t.error("force", "unknown key; a load of type = \"force\" takes vector = "
                      "[\"0 N\", \"-800 N\"], or magnitude = \"800 N\" with angle = \"90 deg\" "
                      "or towards = \"A\" (see docs/reference.md)")
    t.check_keys(("type", "kind", "link", "point", "vector", "magnitude", "angle", "towards",
                  "toward", "pressure", "bore", "moment", "against", "table", "name"))
    kind_s = t.string("type", t.string("kind"), choices=tuple(k.value for k in LoadKind))
    if kind_s is None:
        raise t.error("type", f"is missing; one of {', '.join(k.value for k in LoadKind)}")
    kind = LoadKind(kind_s)
    link = t.string("link")
    if kind is LoadKind.MOMENT:
        if link is None or link not in links or link == GROUND:
            raise t.error("link", f"a moment acts on a moving link; unknown link {link!r}")
        return LoadSpec(
            kind, link, moment=t.quantity("moment", "moment", required=True), key=t.path
        )
    point = t.string("point", required=True)
    assert point is not None
    owner = _point_link(t, links, point, link)
    towards = t.string("towards") or t.string("toward")
    if towards is not None and not any(towards in lk.points for lk in links.values()):
        raise t.error("towards", f"unknown point {towards!r}")
    if towards is not None and towards == point:
        raise t.error("towards", f"a load at {point} cannot point towards {point} itself; name "
                      "another point on its line of action")
    if kind is LoadKind.FORCE:
        if t.has("vector"):
            v = t.raw("vector")
            if not isinstance(v, list) or len(v) != 2:
                raise t.error("vector", "expected [Fx, Fy] with units, e.g. [\"0 N\", \"-100 N\"]")
            vec = (
                t.value_quantity(v[0], "vector", "force"),
                t.value_quantity(v[1], "vector", "force"),
            )
            return LoadSpec(kind, owner, point, vector=vec, key=t.path)
        mag = t.quantity("magnitude", "force", required=True, nonnegative=True)
        if towards is None and not t.has("angle"):
            raise t.error(None, "a force needs 'vector', or 'magnitude' with 'angle' or 'towards'")
        return LoadSpec(kind, owner, point, magnitude=mag, angle=t.quantity("angle", "angle"),
                        towards=towards, key=t.path)
    if links[owner].slides_on is None:
        raise t.error("point", f"a {kind.value} load acts on a slider along its guide; link "
                      f"{owner} does not slide")
    if towards is None:
        raise t.error("towards", "give the sense along the cylinder axis, e.g. towards = \"A\"")
    if kind is LoadKind.PRESSURE:
        if not t.has("bore"):
            raise t.error(
                "bore", 'a pressure needs the piston\'s bore diameter, e.g. bore = "100 mm"'
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
        raise t.error("table", "expected at least two rows [x, F]")
    xdim = "angle" if against == "crank_angle" else "length"
    parsed = []
    for j, row in enumerate(rows):
        if not isinstance(row, list) or len(row) != 2:
            raise t.error(f"table[{j}]", "expected a row [x, F]")
        parsed.append((t.value_quantity(row[0], f"table[{j}]", xdim),
                       t.value_quantity(row[1], f"table[{j}]", "force")))
    xs = [r[0] for r in parsed]
    if any(b <= a for a, b in itertools.pairwise(xs)):
        raise t.error("table", "the first column must increase strictly")
    if against == "crank_angle" and xs[-1] - xs[0] > 4 * math.pi + 1e-9:
        raise t.error("table", "a table against crank angle spans at most two crank turns "
                      f"(720°, a four-stroke cycle; got {math.degrees(xs[-1] - xs[0]):g}°)")
    return LoadSpec(kind, owner, point, towards=towards, against=against, table=tuple(parsed),
                    key=t.path)
