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

from ..model.mechanism import GROUND, Drive, DriverKind, Guide, Link, Pair, PairKind
from .reader import Table
from .spec import Positions

#: keys of [drive] for a linear driver
LINEAR_KEYS = ("kind", "link", "speed", "acceleration", "range")


def linear_drive(d: Table, kind: DriverKind, links: dict[str, Link], guides: dict[str, Guide],
                 pairs: list[Pair]) -> Drive:
    """The cylinder or slider named by ``[drive] link``, with its law and range."""
    d.check_keys(LINEAR_KEYS)
    link = d.string("link", required=True)
    assert link is not None
    if link not in links or link == GROUND:
        known = ", ".join(k for k in links if k != GROUND)
        raise d.error("link", f"unknown link {link!r}; links are {known}")
    slides = [p for p in pairs if p.kind is PairKind.PRISMATIC and p.a == link]
    what = "the cylinder's rod" if kind is DriverKind.CYLINDER else "the driving slider"
    if len(slides) != 1:
        raise d.error("link", f"{what} {link} must slide on one guide (it slides on "
                      f"{len(slides)}); give the link slides = {{ point = …, on = … }}")
    pair = slides[0]
    assert pair.guide is not None
    guide = guides[pair.guide]
    if kind is DriverKind.SLIDER and pair.b != GROUND:
        raise d.error("link", f"the driving slider {link} must slide on a frame guide (guide "
                      f"{guide.name} belongs to link {pair.b}); for a rod in a barrel use "
                      "kind = \"cylinder\"")
    if kind is DriverKind.CYLINDER:
        _check_cylinder(d, link, pair, guide, links, pairs)
    speed = d.quantity("speed", "velocity", required=True)
    assert speed is not None
    accel = d.quantity("acceleration", "acceleration", 0.0) or 0.0
    q_range = _range(d) if d.has("range") else None
    return Drive(link=link, pivot=pair.point, omega=speed, epsilon=accel, ref_angle=0.0,
                 ref_name=guide.name, kind=kind,
                 carrier=pair.b if kind is DriverKind.CYLINDER else GROUND,
                 guide=guide.name, q_range=q_range)


def _check_cylinder(d: Table, rod: str, pair: Pair, guide: Guide, links: dict[str, Link],
                    pairs: list[Pair]) -> None:
    """The barrel's guide must run from its pivot (through) along the cylinder's axis."""
    barrel = pair.b
    if barrel == GROUND:
        raise d.error("link", f"the cylinder's rod {rod} slides on the frame guide {guide.name}; "
                      "a cylinder's barrel is a link pinned to the frame or to another link "
                      "(use kind = \"slider\" for a slider on a frame guide)")
    pins = [p for p in pairs if p.kind is PairKind.REVOLUTE and p.joins(barrel)]
    if not any(p.point == guide.through for p in pins):
        raise d.error("link", f"the guide {guide.name} of the barrel {barrel} must pass through "
                      f"the barrel's pivot (it passes through {guide.through}); the cylinder's "
                      "axis runs from the barrel's pivot to the rod's pin")
    if links[rod].points.get(pair.point) != (0.0, 0.0):
        raise d.error("link", f"the rod {rod} must slide at its pin {pair.point}")


def _range(d: Table) -> tuple[float, float]:
    raw = d.raw("range")
    if not isinstance(raw, list) or len(raw) != 2:
        raise d.error("range", "expected [from, to] lengths, e.g. [\"1.2 m\", \"1.8 m\"] "
                      f"(got {raw!r})")
    lo = d.value_quantity(raw[0], "range[0]", "length")
    hi = d.value_quantity(raw[1], "range[1]", "length")
    if lo == hi:
        raise d.error("range", "the range's two ends must differ")
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
            raise t.error("at", "expected a list of the driver's lengths, e.g. [\"1.2 m\", "
                          "\"1.4 m\"]")
        return Positions(angles=tuple(t.value_quantity(v, f"at[{i}]", "length")
                                      for i, v in enumerate(values)))
    count = t.raw("count", 12)
    if not isinstance(count, int) or isinstance(count, bool) or count < 1:
        raise t.error("count", f"must be a whole number ≥ 1 (got {count!r})")
    if drive.q_range is None:
        raise _no_positions(drive)
    return Positions(count=count)


def _no_positions(drive: Drive) -> Exception:
    from ..errors import SceneError

    return SceneError(f"the {drive.kind.value} driver {drive.link} needs its positions: "
                      "[positions] at = [lengths], or [drive] range = [from, to] with "
                      "[positions] count", key="drive.range")


def linear_assembly_default(top: Table, drive: Drive) -> float:
    """Where a linear driver's assembly is decided without ``assembly.at``: its first position."""
    positions = linear_positions(top.table("positions"), drive)
    if positions.angles:
        return positions.angles[0]
    return drive.q_range[0] if drive.q_range else math.nan
