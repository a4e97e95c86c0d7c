"""A crank's law by a table in the construction's own angle: θ = ref + sense·φ.

The scene gives a crank's table as φ in its own sense from its reference (as its positions); the
construction's step value is the absolute direction θ (rad, counter-clockwise from +x), so its
spline's derivatives are the signed ω and ε the plans lay off.
"""

from __future__ import annotations

from dataclasses import replace

from .law import TableLaw
from .mechanism import Drive


def absolute_law(drive: Drive) -> Drive:
    """``drive`` with a crank's table in θ (a linear driver's, or a crank without one, as is)."""
    if drive.linear or drive.law is None:
        return drive
    law = drive.law
    values = tuple(drive.ref_angle + drive.sense * v for v in law.values)
    return replace(drive, law=TableLaw(law.times, values, law.source))
