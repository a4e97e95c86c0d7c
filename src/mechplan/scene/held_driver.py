"""Read ``[drive2] hold``: a cylinder held at a length (its valves closed) while the first driver
moves — an excavator's arm cylinder locked while the boom cylinder lifts.

A held cylinder is a second cylinder at rest: ``hold = "2700 mm"`` reads as ``speed = "0 m/s"``
and ``start = "2700 mm"`` (its length at every position), so its group is built with the compass
arcs of a cylinder of that length, its rod's l̇ and l̈ are zero on the plans, and its force
plan gives the force that holds it (F_d of its rod). The structure formula still lists it as
``I(barrel,rod)``: its length is given, not found (docs/held_cylinder.md).
"""

from __future__ import annotations

from ..i18n import Text
from ..model.mechanism import Drive
from .reader import Table

#: keys a held cylinder's law would have: refused beside ``hold``
_LAW_KEYS = ("speed", "acceleration", "start", "law")


def held_table(d: Table, first: Drive) -> Table:
    """``[drive2]`` as read: with ``hold``, the table of a second cylinder at rest at that length
    (errors name ``drive2.hold``); without it, ``d`` itself."""
    if not d.has("hold"):
        return d
    kind = d.raw("kind", "crank")
    if kind != "cylinder":
        raise d.error("hold", Text("excavload.hold.cylinder_only", {"kind": str(kind)}))
    for key in _LAW_KEYS:
        if d.has(key):
            raise d.error(key, Text("excavload.hold.not_both", {"key": key}))
    d.quantity("hold", "length", required=True, positive=True)
    # its length l2 = start + 0·(q1 − q1⁰)/q̇1 is counted from the first driver's reference too
    if first.linear and first.q_range is None:
        raise d.error("hold", Text(
            "drives2.scene.first_range", {"kind": first.kind.value, "link": first.link}))
    if first.law is None and first.omega == 0.0:
        raise d.error("hold", Text("drives2.scene.first_at_rest", {"link": first.link}))
    data = {k: v for k, v in d.data.items() if k != "hold"}
    data |= {"speed": "0 m/s", "start": d.raw("hold")}
    return Table(data, d.path, d.file)
