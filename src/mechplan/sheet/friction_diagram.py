"""The diagram of the instantaneous efficiency η(φ) over the positions (a scene with friction
that asks for it: ``[friction] diagram = true``). η is read from the solution, never computed."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..i18n import message
from ..solve import Solution
from .diagram import Axis, Curve, Marker, diagram_panel
from .panels import Panel
from .scales import Room


def efficiency_diagram(sol: Solution, lang: str, r: Room) -> Panel | None:
    """η(φ) at the positions of a sweep; gaps where the balancing moment does not drive."""
    spec = sol.scene.friction
    forces = sol.extras.get("forces")
    friction = getattr(forces, "friction", None)
    if (spec is None or not spec.diagram or friction is None or sol.scene.positions.angles
            or sol.positions < 4):
        return None
    eta = np.asarray(friction.efficiency, dtype=float)
    if not np.isfinite(eta).any():
        return None
    n = sol.positions
    drive = sol.scene.mechanism.drive
    if drive.linear:            # over the driver's time t = (q − q⁰)/q̇, an open curve
        return _over_time(sol, eta, friction, lang, r)
    x = np.arange(n + 1) * 360.0 / n
    y = np.append(eta, eta[0])
    # every position where η is defined is marked with its number (a lone one has no line)
    markers = [Marker(float(x[k]), float(y[k]), str(k)) for k in range(n) if np.isfinite(y[k])]
    # two drivers (W = 2): the machine's η = P⁰/P of the drivers' input powers
    title = ("frictionw2.diagram.efficiency" if friction.second is not None
             else "forces.diagram.efficiency")
    d = diagram_panel("force-diagram-eta", message(title, lang),
                      [Curve(x, y)], Axis("φ", "°", min(180.0, 0.42 * r.width)),
                      Axis("η", "", min(50.0, 0.18 * r.height)), lang, markers=markers)
    return d.panel


def _over_time(sol: Solution, eta: np.ndarray, friction: Any, lang: str,
               r: Room) -> Panel | None:
    """η over a linear driver's sweep (its positions from one end of its range to the other)
    against the law's time, as its kinematic diagrams."""
    from ..model.law import driver_time

    drive = sol.scene.mechanism.drive
    if drive.omega == 0:
        return None
    x = np.asarray(driver_time(drive, np.asarray(sol.phi, dtype=float)), dtype=float)
    markers = [Marker(float(x[k]), float(eta[k]), str(k)) for k in range(len(eta))
               if np.isfinite(eta[k])]
    title = ("frictionw2.diagram.efficiency_time" if friction.second is not None
             else "frictionlin.diagram.efficiency")
    d = diagram_panel("force-diagram-eta", message(title, lang),
                      [Curve(x, eta)], Axis("t", "s", min(160.0, 0.36 * r.width)),
                      Axis("η", "", min(50.0, 0.18 * r.height)), lang, markers=markers)
    return d.panel
