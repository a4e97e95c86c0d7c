"""Read the linear drivers of ``[drive]``: a cylinder (barrel and rod) or a slider on a frame guide.

A linear driver's coordinate q is a length (m): a cylinder's length between its two pins, or a
slider's displacement along its guide from the guide's ``through`` point. Its law is the rate and
the acceleration of q, ``speed`` (signed: + extends or moves towards the guide's direction) and
``acceleration``, given at every position like a crank's ω1 and ε1. Positions are values of q:
``[positions] at = ["1.2 m", …]``, or ``count`` values spread evenly over ``[drive] range``
(both ends included, see ``solve.crank_positions``).
"""

from __future__ import annotations

import math

from ..i18n import Text
from ..model.mechanism import GROUND, Drive, DriverKind, Guide, Link, Pair, PairKind
from .reader import Table
from .spec import Positions

#: keys of [drive] for a linear driver
LINEAR_KEYS = ("kind", "link", "speed", "acceleration", "range", "law")


def linear_drive(d: Table, kind: DriverKind, links: dict[str, Link], guides: dict[str, Guide],
                 pairs: list[Pair], extra_keys: tuple[str, ...] = (), first: bool = True) -> Drive:
    """The cylinder or slider named by ``[drive] link`` (or ``[drive2]``), with its law and range.

    ``extra_keys``: keys the table may hold besides the linear driver's (``[drive2] start``);
    ``first``: the first driver, whose law by a table must be monotonic (its q names the time).
    """
    d.check_keys(LINEAR_KEYS + extra_keys)
    link = d.string("link", required=True)
    assert link is not None
    if link not in links or link == GROUND:
        known = ", ".join(k for k in links if k != GROUND)
        raise d.error("link", Text(
            "errmsg2.scene_drivers.unknown_link",
            {"link": repr(link), "links": known}))
    slides = [p for p in pairs if p.kind is PairKind.PRISMATIC and p.a == link]
    what = (Text("errmsg2.scene_drivers.what_rod") if kind is DriverKind.CYLINDER
            else Text("errmsg2.scene_drivers.what_slider"))
    if len(slides) != 1:
        raise d.error("link", Text(
            "errmsg2.scene_drivers.one_guide",
            {"what": what, "link": link, "count": str(len(slides))}))
    pair = slides[0]
    assert pair.guide is not None
    guide = guides[pair.guide]
    if kind is DriverKind.SLIDER and pair.b != GROUND:
        raise d.error("link", Text(
            "errmsg2.scene_drivers.frame_guide",
            {"link": link, "guide": guide.name, "owner": pair.b}))
    if kind is DriverKind.CYLINDER:
        _check_cylinder(d, link, pair, guide, links, pairs)
    q_range = _range(d) if d.has("range") else None
    law = None
    speed: float | None
    if d.has("law"):        # q(t) by a table: the rates come from its spline (scene/law.py)
        from .law import read_law

        for key in ("speed", "acceleration"):
            if d.has(key):
                raise d.error(key, Text("drives2.law.not_both", {"key": key}))
        law = read_law(d)
        speed, accel = law.mean_rate(), 0.0
        if q_range is None:
            q_range = law.q_range
        lo, hi = sorted(law.q_range)
        if not all(lo <= q <= hi for q in q_range):
            raise d.error("range", Text("drives2.law.range_outside", {
                "lo": f"{lo * 1000:.6g}", "hi": f"{hi * 1000:.6g}"}))
    else:
        speed = d.quantity("speed", "velocity", required=True)
        accel = d.quantity("acceleration", "acceleration", 0.0) or 0.0
    assert speed is not None
    drive = Drive(link=link, pivot=pair.point, omega=speed, epsilon=accel, ref_angle=0.0,
                  ref_name=guide.name, kind=kind,
                  carrier=pair.b if kind is DriverKind.CYLINDER else GROUND,
                  guide=guide.name, q_range=q_range, law=law)
    if first:
        check_first_law(d, drive)
    return drive


def check_first_law(d: Table, drive: Drive) -> None:
    """The first driver's law must be strictly monotonic: its coordinate names the time."""
    if drive.law is None:
        return
    from ..model.law import turning_time

    turn = turning_time(drive.law)
    if turn is not None:
        raise d.error("law", Text("drives2.law.monotonic", {"t": f"{turn:.6g}"}))


def _check_cylinder(d: Table, rod: str, pair: Pair, guide: Guide, links: dict[str, Link],
                    pairs: list[Pair]) -> None:
    """The barrel's guide must run from its pivot (through) along the cylinder's axis."""
    barrel = pair.b
    if barrel == GROUND:
        raise d.error("link", Text(
            "errmsg2.scene_drivers.rod_on_frame",
            {"rod": rod, "guide": guide.name}))
    pins = [p for p in pairs if p.kind is PairKind.REVOLUTE and p.joins(barrel)]
    if not any(p.point == guide.through for p in pins):
        raise d.error("link", Text(
            "errmsg2.scene_drivers.barrel_pivot",
            {"guide": guide.name, "barrel": barrel, "through": guide.through}))
    if links[rod].points.get(pair.point) != (0.0, 0.0):
        raise d.error("link", Text(
            "errmsg2.scene_drivers.rod_pin",
            {"rod": rod, "pin": pair.point}))


def _range(d: Table) -> tuple[float, float]:
    raw = d.raw("range")
    if not isinstance(raw, list) or len(raw) != 2:
        raise d.error("range", Text("errmsg2.scene_drivers.range_pair", {"value": repr(raw)}))
    lo = d.value_quantity(raw[0], "range[0]", "length")
    hi = d.value_quantity(raw[1], "range[1]", "length")
    if lo == hi:
        raise d.error("range", Text("errmsg2.scene_drivers.range_ends"))
    return (lo, hi)


def linear_positions(t: Table | None, drive: Drive) -> Positions:
    """Positions of a linear driver: its coordinate's values (m), listed or spread on its range."""
    if t is None:
        if drive.q_range is None:
            raise _no_positions(drive)
        return Positions(count=12)
    t.check_keys(("at", "count"))
    if t.has("at"):
        values = t.raw("at")
        if not isinstance(values, list) or not values:
            raise t.error("at", Text("errmsg2.scene_drivers.lengths_list"))
        at = tuple(t.value_quantity(v, f"at[{i}]", "length") for i, v in enumerate(values))
        if drive.law is not None:       # a law by a table reaches only its own lengths
            lo, hi = sorted(drive.law.q_range)
            for i, q in enumerate(at):
                if not lo <= q <= hi:
                    raise t.error(f"at[{i}]", Text("drives2.law.range_outside", {
                        "lo": f"{lo * 1000:.6g}", "hi": f"{hi * 1000:.6g}"}))
        return Positions(angles=at)
    count = t.raw("count", 12)
    if not isinstance(count, int) or isinstance(count, bool) or count < 1:
        raise t.error("count", Text(
            "errmsg2.scene_drivers.count_whole",
            {"value": repr(count)}))
    if drive.q_range is None:
        raise _no_positions(drive)
    return Positions(count=count)


def _no_positions(drive: Drive) -> Exception:
    from ..errors import SceneError

    return SceneError(Text(
        "errmsg2.scene_drivers.needs_positions",
        {"kind": drive.kind.value, "link": drive.link}), key="drive.range")


def linear_assembly_default(top: Table, drive: Drive) -> float:
    """Where a linear driver's (or a crank's by a table) assembly is decided without
    ``assembly.at``: its first position."""
    from .crank_law import crank_law_positions

    read = linear_positions if drive.linear else crank_law_positions
    positions = read(top.table("positions"), drive)
    if positions.angles:
        return positions.angles[0]
    return drive.q_range[0] if drive.q_range else math.nan
