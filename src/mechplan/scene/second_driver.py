"""Read ``[drive2]``: a second driving crank (W = 2, e.g. a five-bar with two cranks).

Its keys are the crank keys of ``[drive]`` (``link``, ``speed``/``omega``, ``sense``, ``from``,
``epsilon``) and ``phase``: its angle φ2 when the first crank is at φ1 = 0. The first driver's φ1
stays the independent variable of every plan; the second follows its law at constant speeds,
φ2 = phase + |ω2|/|ω1|·φ1 (both measured in their own sense from their own ``from``), and its ω2,
ε2 are given at every position like ω1, ε1 (docs/two_inputs.md).
"""

from __future__ import annotations

from dataclasses import replace

from ..i18n import Text
from ..model.mechanism import Drive, Guide, Link, Pair
from .reader import Table

#: keys of [drive2]
SECOND_KEYS = ("kind", "link", "speed", "omega", "sense", "from", "epsilon", "phase")


def second_drive(top: Table, links: dict[str, Link], guides: dict[str, Guide],
                 pairs: list[Pair], first: Drive) -> Drive | None:
    """The second crank of ``[drive2]`` (None without the table)."""
    d = top.table("drive2")
    if d is None:
        return None
    d.check_keys(SECOND_KEYS)
    d.string("kind", "crank", choices=("crank",))
    if first.linear:
        raise d.error("link", Text(
            "errmsg2.scene_second_driver.crank_first",
            {"kind": first.kind.value}))
    from .loader import crank_drive

    drive = crank_drive(d, links, guides, pairs)
    if drive.link == first.link:
        raise d.error("link", Text(
            "errmsg2.scene_second_driver.already_first",
            {"link": drive.link}))
    phase = d.quantity("phase", "angle", 0.0) or 0.0
    # [centres] is read: Kennedy's theorem finds the centres it can, the velocities by centres
    # start from both cranks and name the links they do not reach
    return replace(drive, phase=phase)
