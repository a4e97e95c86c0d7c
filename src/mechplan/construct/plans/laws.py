"""Driver laws by a table over time (``[drive] law``, ``[drive2] law``): the steps that give a
driver's coordinate and rates at the time of a position (``DRIVER_LAW``, ``ops/inputs.py``).

The first driver's coordinate is the independent variable; the time of a position is its table
inverted (its law by a table) or, at constant rates, t = (q1 − q1⁰)/r1 (as for the laws of
``second_crank.law``). A driver with a table then has its spline's q, q̇, q̈ at that time.
"""

from __future__ import annotations

from typing import Any

from ...model.crank_law import absolute_law
from ...model.law import largest
from ...model.mechanism import Drive
from ..builder import Builder
from ..ops import Op
from ..plans.second_crank import law as affine_law
from ..step import Kind, Role


def clock(first: Drive) -> dict[str, Any]:
    """The parameters that find the time from the first driver's step value."""
    first = absolute_law(first)     # a crank's table in its step's θ
    if first.law is not None:
        return {"clock_times": first.law.times, "clock_values": first.law.values}
    # the time is the constant-rate law of a "second driver" moving at 1 m/s from 0:
    # t = (u1)/r1, the same affine map as l2 = start + l̇2/r1·u1 with start 0 and l̇2 = 1
    from dataclasses import replace

    unit = replace(first, omega=1.0, epsilon=0.0, phase=0.0, law=None)
    from ...model.mechanism import DriverKind

    a, b = affine_law(first, replace(unit, kind=DriverKind.CYLINDER))
    return {"clock_a": a, "clock_b": b}


def motion(drive: Drive, order: int) -> dict[str, Any]:
    """The parameters of a driver's own law (its table, or its start and constant rates)."""
    drive = absolute_law(drive)
    if drive.law is not None:
        size = largest(drive.law, order) if order else 0.0
        return {"times": drive.law.times, "values": drive.law.values, "size": size}
    return {"q0": drive.phase, "rate": drive.omega, "acceleration": drive.epsilon,
            "size": abs(drive.omega if order == 1 else drive.epsilon)}


def first_step(b: Builder) -> str:
    """The step of the first driver's coordinate: θ1 (a crank) or q1."""
    return "pos.q" if b.mech.drive.linear else "pos.phi1"


def law_step(b: Builder, sid: str, drive: Drive, order: int, plan: Any, label: str,
             group: str) -> str:
    """A driver's coordinate (0), rate (1) or acceleration (2) by its law at a position's time."""
    return b.add(sid, Op.DRIVER_LAW, (first_step(b),), plan, Kind.SCALAR, Role.GIVEN, label,
                 group, subject=(b.mech.drive.link, drive.link), order=order,
                 **clock(b.mech.drive), **motion(drive, order))


def by_table(b: Builder) -> bool:
    """Tell whether a driver's law is a table (then every law step goes through DRIVER_LAW)."""
    return any(d.law is not None for d in b.mech.drivers)
