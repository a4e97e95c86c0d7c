"""Read ``[drive2]``: a second driver (W = 2), a crank, a cylinder or a slider on a frame guide.

A second crank (five-bar with two cranks) has the crank keys of ``[drive]`` (``link``,
``speed``/``omega``, ``sense``, ``from``, ``epsilon``) and ``phase``: its angle φ2 when the first
crank is at φ1 = 0 (or at a linear first driver's range start). A second cylinder (crank +
cylinder, two cylinders: an excavator's boom and arm) has the cylinder keys of ``[drive]``
(``link``, ``speed``, ``acceleration``) and ``start``: its length when the first driver is at its
reference (a crank's φ1 = 0, a linear driver's ``range`` start); a second slider on a frame
guide likewise, ``start`` its displacement s along its guide (docs/drivers.md).

The first driver's coordinate stays the independent variable of every plan; the second follows
its law at constant rates, q2 = q2⁰ + (rate2/rate1)·(q1 − q1⁰) (docs/two_inputs.md,
docs/drivers.md), and its rate and acceleration are given at every position like the first's.
"""

from __future__ import annotations

from dataclasses import replace

from ..i18n import Text
from ..model.mechanism import Drive, DriverKind, Guide, Link, Pair
from .reader import Table

#: keys of [drive2] with a second crank
SECOND_KEYS = ("kind", "link", "speed", "omega", "sense", "from", "epsilon", "phase", "law")


def second_drive(top: Table, links: dict[str, Link], guides: dict[str, Guide],
                 pairs: list[Pair], first: Drive) -> Drive | None:
    """The second driver of ``[drive2]`` (None without the table)."""
    d = top.table("drive2")
    if d is None:
        return None
    from .held_driver import held_table

    d = held_table(d, first)        # hold = L: a cylinder at rest at the length L
    kind = d.string("kind", "crank", choices=("crank", "cylinder", "slider"))
    if kind != "crank":
        drive = _second_cylinder(d, links, guides, pairs, first, DriverKind(kind))
    else:
        d.check_keys(SECOND_KEYS)
        from .crank_law import check_first_clock
        from .loader import crank_drive

        drive = crank_drive(d, links, guides, pairs)
        check_first_clock(d, first, "link")     # after a linear driver: its law names the time
        if drive.law is not None and d.has("phase"):     # its table gives φ2 at every time
            raise d.error("phase", Text("drives2.law.not_both", {"key": "phase"}))
        drive = replace(drive, phase=d.quantity("phase", "angle", 0.0) or 0.0)
    if drive.link == first.link:
        raise d.error("link", Text(
            "errmsg2.scene_second_driver.already_first",
            {"link": drive.link}))
    # [centres] is read: Kennedy's theorem finds the centres it can, the velocities by centres
    # start from the cranks and name the links they do not reach
    return drive


def _second_cylinder(d: Table, links: dict[str, Link], guides: dict[str, Guide],
                     pairs: list[Pair], first: Drive, kind: DriverKind = DriverKind.CYLINDER
                     ) -> Drive:
    """A second cylinder or slider on a frame guide: its link, law and ``start`` (its length,
    or a slider's displacement, at the first's reference)."""
    from .drivers import linear_drive

    drive = linear_drive(d, kind, links, guides, pairs, extra_keys=("start",), first=False)
    if drive.link == first.link or (first.kind is DriverKind.CYLINDER
                                    and drive.carrier == first.carrier):
        raise d.error("link", Text(
            "errmsg2.scene_second_driver.already_first",
            {"link": drive.link}))
    if drive.law is not None:       # its law by a table: its length is the table's at each time
        if d.has("start"):
            raise d.error("start", Text("drives2.law.not_both", {"key": "start"}))
        if first.law is None and first.omega == 0.0:
            raise d.error("law", Text("drives2.scene.first_at_rest", {"link": first.link}))
        if first.linear and first.q_range is None:
            raise d.error("law", Text(
                "drives2.scene.first_range", {"kind": first.kind.value, "link": first.link}))
        return drive
    start = d.quantity("start", "length", required=True,
                       positive=kind is DriverKind.CYLINDER)    # a slider's s may be ≤ 0
    assert start is not None
    if first.linear and first.q_range is None:
        raise d.error("start", Text(
            "drives2.scene.first_range",
            {"kind": first.kind.value, "link": first.link}))
    if first.omega == 0.0:
        raise d.error("start", Text("drives2.scene.first_at_rest", {"link": first.link}))
    return replace(drive, phase=start)
