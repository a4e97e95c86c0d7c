"""Read a crank's or rocker's law given by a table over time: ``[drive] law = { table = [[t, φ],
…] }`` or ``{ file = "crank.csv", units = ["s", "deg"] }`` (docs/drivers.md, "A crank's law by a
table").

φ is the crank's angle in its own ``sense`` from its ``from`` reference, as its positions are
given; q̇ = ω and q̈ = ε come from the table's cubic spline (scene/law.py reads the rows). The
first driver's φ names the time of a position, so its table must increase (the crank turns in its
``sense``) and move one way; a second crank's table may turn back (a rocker).
"""

from __future__ import annotations

import math

from ..i18n import Text, number
from ..model.law import largest
from ..model.mechanism import Drive
from .reader import Table
from .spec import Positions

#: keys of a crank's table that a law by a table replaces
RATE_KEYS = ("speed", "omega", "epsilon")


def crank_law_drive(d: Table, link: str, pivot: str, ref: float, ref_name: str, sign: float,
                    first: bool) -> Drive:
    """The crank ``link`` about ``pivot`` moving by ``d.law`` (φ in the sense ``sign``)."""
    from .drivers import check_first_law
    from .law import read_law

    for key in RATE_KEYS:
        if d.has(key):
            raise d.error(key, Text("drives2.law.not_both", {"key": key}))
    law = read_law(d, "angle")
    (q0, q1) = law.q_range
    if first and not q1 > q0:
        raise d.error("law", Text("drives3.crank_law.increasing", {"link": link}))
    rate = law.mean_rate() if first else largest(law, 1)
    if rate == 0.0:
        raise d.error("law", Text("drives3.crank_law.at_rest", {"link": link}))
    drive = Drive(link=link, pivot=pivot, omega=sign * abs(rate), epsilon=0.0, ref_angle=ref,
                  ref_name=ref_name, q_range=law.q_range, law=law)
    if first:
        check_first_law(d, drive)
    return drive


def crank_law_positions(t: Table | None, drive: Drive) -> Positions:
    """Positions of a crank moving by a table: angles within the table's, or ``count`` spread
    over them (both ends included)."""
    assert drive.law is not None
    if t is None:
        return Positions(count=12)
    t.check_keys(("at", "count"))
    lo, hi = sorted(drive.law.q_range)
    if t.has("at"):
        values = t.raw("at")
        if not isinstance(values, list) or not values:
            raise t.error("at", Text("errmsg2.scene_loader.angles_list"))
        at = tuple(t.value_quantity(v, f"at[{i}]", "angle") for i, v in enumerate(values))
        for i, phi in enumerate(at):
            if not lo - 1e-12 <= phi <= hi + 1e-12:
                raise t.error(f"at[{i}]", Text("drives3.crank_law.outside", {
                    "link": drive.link, "lo": _deg(lo), "hi": _deg(hi)}))
        return Positions(angles=at)
    count = t.raw("count", 12)
    if not isinstance(count, int) or isinstance(count, bool) or count < 1:
        raise t.error("count", Text("errmsg2.scene_loader.count_whole", {"value": repr(count)}))
    return Positions(count=count)


def _deg(rad: float) -> str:
    return number(math.degrees(rad), 2, "en")


def check_first_clock(d: Table, first: Drive, key: str) -> None:
    """A second crank after a linear first driver: the first's law must name the time of a
    position — its table, or a constant rate counted from its range's start."""
    if not first.linear or first.law is not None:
        return
    if first.q_range is None:
        raise d.error(key, Text("drives2.scene.first_range",
                                {"kind": first.kind.value, "link": first.link}))
    if first.omega == 0.0:
        raise d.error(key, Text("drives2.scene.first_at_rest", {"link": first.link}))
