"""Read the ``[dynamics]`` section of a mechanism scene into a :class:`DynamicsSpec`."""

from __future__ import annotations

import itertools
import math
from typing import Any

from ..i18n import Text
from ..model.dynamics import (
    FOUR_STROKE,
    TWO_STROKE,
    DynamicsSpec,
    FlywheelShape,
    FlywheelSpec,
    IndicatorSpec,
    Unknown,
)
from ..model.mechanism import GROUND, Mechanism
from .reader import Table

KEYS = ("unknown", "delta", "cycle", "constant_moment", "J_const", "indicator", "flywheel",
        "dense", "pole_distance", "balance_tolerance")
INDICATOR_KEYS = ("point", "towards", "bore", "ambient", "table", "strokes")
FLYWHEEL_KEYS = ("shape", "density", "diameter", "width_ratio", "section_ratio")


def parse_dynamics(data: dict[str, Any], file: str, mech: Mechanism) -> DynamicsSpec | None:
    """Return the dynamics spec of a parsed scene, or None when it has no ``[dynamics]``."""
    if "dynamics" not in data:
        return None
    t = Table(data["dynamics"], "dynamics", file)
    t.check_keys(KEYS)
    unknown = Unknown(t.string("unknown", required=True,
                               choices=tuple(u.value for u in Unknown)))
    delta = t.quantity("delta", "dimensionless", required=True)
    assert delta is not None
    if not 0.0 < delta < 1.0:
        raise t.error(
            "delta",
            Text(
                "errmsg.scene_dynamics.coefficient_speed_fluctuation",
                {"value": repr(t.raw("delta"))},
            ),
        )
    it = t.table("indicator")
    indicator = _indicator(it, mech) if it is not None else None
    four = indicator is not None and (len(indicator.strokes) == 4 or bool(
        indicator.table and indicator.table[-1][0] > 2 * math.pi + 1e-6))
    default_cycle = 4 * math.pi if four else 2 * math.pi
    cycle = t.quantity("cycle", "angle", default_cycle)
    assert cycle is not None
    turns = cycle / (2 * math.pi)
    if abs(turns - round(turns)) > 1e-9 or round(turns) not in (1, 2):
        raise t.error(
            "cycle", Text("errmsg.scene_dynamics.cycle_one_two", {"value": repr(t.raw("cycle"))})
        )
    cycle = 2 * math.pi * round(turns)
    if indicator and indicator.strokes and abs(len(indicator.strokes) * math.pi - cycle) > 1e-9:
        raise t.error(
            "cycle",
            Text(
                "errmsg.scene_dynamics.strokes_strokes_make",
                {
                    "strokes": str(len(indicator.strokes)),
                    "value": str(len(indicator.strokes) * 180),
                    "cycle": f"{math.degrees(cycle):g}",
                },
            ),
        )
    dense = t.raw("dense", 5760)
    if not isinstance(dense, int) or isinstance(dense, bool) or not 36 <= dense <= 100_000:
        raise t.error(
            "dense", Text("errmsg.scene_dynamics.number_exact_points", {"dense": repr(dense)})
        )
    ft = t.table("flywheel")
    tol = t.quantity("balance_tolerance", "dimensionless", 0.02, positive=True)
    pole = t.quantity("pole_distance", "length", positive=True)
    return DynamicsSpec(
        unknown=unknown, delta=delta, cycle=cycle,
        constant_moment=t.quantity("constant_moment", "moment", nonnegative=True),
        inertia_const=t.quantity("J_const", "inertia", 0.0, nonnegative=True) or 0.0,
        indicator=indicator, flywheel=_flywheel(ft) if ft is not None else None,
        dense=dense, pole_distance_mm=None if pole is None else pole * 1000.0,
        balance_tolerance=tol or 0.02)


def _rows(t: Table, name: str, xdim: str, ydim: str) -> tuple[tuple[float, float], ...]:
    rows = t.raw(name)
    if not isinstance(rows, list) or len(rows) < 2:
        raise t.error(name, Text("errmsg.scene_dynamics.expected_least_two"))
    out = []
    for j, row in enumerate(rows):
        if not isinstance(row, list) or len(row) != 2:
            raise t.error(f"{name}[{j}]", Text("errmsg.scene_dynamics.expected_row_x"))
        out.append((t.value_quantity(row[0], f"{name}[{j}]", xdim),
                    t.value_quantity(row[1], f"{name}[{j}]", ydim)))
    return tuple(out)


def _indicator(t: Table, mech: Mechanism) -> IndicatorSpec:
    t.check_keys(INDICATOR_KEYS)
    point = t.string("point", required=True)
    owners = [k for k, lk in mech.links.items() if k != GROUND and point in lk.points
              and lk.slides_on is not None]
    if not owners:
        raise t.error(
            "point", Text("errmsg.scene_dynamics.indicator_s_gas", {"point": repr(point)})
        )
    towards = t.string("towards", required=True)
    if not any(towards in lk.points for lk in mech.links.values()) or towards == point:
        raise t.error(
            "towards", Text("errmsg.scene_dynamics.gas_force_points", {"towards": repr(towards)})
        )
    bore = t.quantity("bore", "length", required=True, positive=True)
    ambient = t.quantity("ambient", "pressure", 0.0, nonnegative=True)
    if t.has("table") == t.has("strokes"):
        raise t.error(None, Text("errmsg.scene_dynamics.give_either_table"))
    if t.has("table"):
        table = _rows(t, "table", "angle", "pressure")
        xs = [x for x, _ in table]
        if any(b <= a for a, b in itertools.pairwise(xs)):
            raise t.error("table", Text("errmsg.scene_dynamics.crank_angles_increase"))
        return IndicatorSpec(str(point), owners[-1], str(towards), float(bore or 0.0),
                             float(ambient or 0.0), table=table)
    st = t.table("strokes")
    assert st is not None
    names = tuple(st.data)
    order = FOUR_STROKE if len(names) == 4 else TWO_STROKE
    if set(names) != {s.value for s in order}:
        raise st.error(
            None,
            Text(
                "errmsg.scene_dynamics.four_stroke_cycle",
                {"value": ", ".join(names) or "none"},
            ),
        )
    strokes = tuple((s, _rows(st, s.value, "length", "pressure")) for s in order)
    for s, rows in strokes:
        if any(x < 0 for x, _ in rows):
            raise st.error(s.value, Text("errmsg.scene_dynamics.piston_displacement_measured"))
    return IndicatorSpec(str(point), owners[-1], str(towards), float(bore or 0.0),
                         float(ambient or 0.0), strokes=strokes)


def _flywheel(t: Table) -> FlywheelSpec:
    t.check_keys(FLYWHEEL_KEYS)
    shape = FlywheelShape(t.string("shape", "disc", choices=tuple(s.value for s in FlywheelShape)))
    diameter = t.quantity("diameter", "length", positive=True)
    ratio = t.quantity("width_ratio", "dimensionless", positive=True)
    if (diameter is None) == (ratio is None):
        raise t.error(None, Text("errmsg.scene_dynamics.give_flywheel_s"))
    return FlywheelSpec(shape, t.quantity("density", "density", 7800.0, positive=True) or 7800.0,
                        diameter, ratio,
                        t.quantity("section_ratio", "dimensionless", 1.0, positive=True) or 1.0)


__all__ = ["parse_dynamics"]
