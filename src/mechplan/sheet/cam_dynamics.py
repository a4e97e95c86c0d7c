"""The follower's dynamics on the cam sheet and in the report: the spring, the contact force over
the cycle (at the cam's speed and at the top speed), the jump speed and the cam torque."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..drafting.primitives import Role
from ..i18n import message, number, significant, unit
from ..model.cam import Motion
from .diagram import Axis, Curve, diagram_panel

if TYPE_CHECKING:
    from ..synthesis.cam import CamDesign
    from .panels import Panel

STEP = 10


def dynamics_lines(d: CamDesign, lang: str) -> list[str]:
    """The report's sentences on the follower's dynamics (none without ``[dynamics]``)."""
    r = d.dynamics
    if r is None:
        return []
    swinging = d.spec.follower.motion is Motion.OSCILLATING
    uf = unit("N·m" if swinging else "N", lang)
    uk = unit("N·m/rad" if swinging else "N/mm", lang)
    k = r.stiffness if swinging else r.stiffness * 1e-3
    rpm = (lambda w: number(w * 30 / math.pi, 0, lang))
    deg = (lambda p: number(math.degrees(p), 1, lang))
    spec = d.spec.dynamics
    assert spec is not None
    out = [message("gearcam.cam.spring", lang, k=significant(k, 5, lang), uk=uk,
                   f0=significant(r.preload, 5, lang), fmax=significant(r.spring_max, 5, lang),
                   uf=uf)]
    if r.chosen:
        out.append(message("gearcam.cam.spring_chosen", lang,
                           margin=significant(spec.margin, 4, lang), uf=uf,
                           n=rpm(r.speed_max)))
    out.append(message("gearcam.cam.contact", lang, n=rpm(r.speed),
                       least=significant(r.contact_min[0], 4, lang), uf=uf,
                       phi=deg(r.contact_min[1])))
    if r.normal is not None:
        out.append(message("gearcam.cam.normal", lang,
                           most=significant(float(np.max(r.normal)), 4, lang), uf=uf))
    if math.isfinite(r.jump_speed):
        out.append(message("gearcam.cam.jump", lang, w=significant(r.jump_speed, 5, lang),
                           n=rpm(r.jump_speed), phi=deg(r.jump_phi)))
    else:
        out.append(message("gearcam.cam.no_jump", lang))
    if r.elastic is not None:
        el = r.elastic
        u = unit("°" if swinging else "mm", lang)
        f = math.degrees(1.0) if swinging else 1e3
        out.append(message("gearcam.cam.elastic", lang,
                           wn=significant(el.natural_frequency, 5, lang),
                           hz=significant(el.natural_frequency / (2 * math.pi), 4, lang),
                           zeta=significant(el.damping_ratio, 3, lang),
                           emax=significant(el.error_max * f, 4, lang), u=u))
        for kind, start, amp in el.residual:
            out.append("  " + message("gearcam.cam.residual", lang,
                                      kind=message(f"cam.phase.{kind}", lang), phi=deg(start),
                                      a=significant(amp * f, 4, lang), u=u))
    tmax, pmax, tmin, pmin = r.torque_extremes
    out.append(message("gearcam.cam.torque", lang, n=rpm(r.speed),
                       tmax=significant(tmax, 4, lang), p1=deg(pmax),
                       tmin=significant(tmin, 4, lang), p2=deg(pmin),
                       mean=significant(r.torque_mean, 4, lang), ut=unit("N·m", lang)))
    return out


def dynamics_panels(d: CamDesign, lang: str, scale: float, width: float, height: float
                    ) -> list[Panel]:
    """Diagrams of the contact force N(φ) (cam speed: solid; top speed: dashed) and of the cam
    torque T(φ) over a turn."""
    r = d.dynamics
    if r is None:
        return []
    swinging = d.spec.follower.motion is Motion.OSCILLATING
    phi = np.append(np.degrees(r.phi[::STEP]), 360.0)

    def closed(v: np.ndarray) -> np.ndarray:
        return np.append(v[::STEP], v[0])

    x_axis = Axis("φ", "°", width * scale)
    curves = [Curve(phi, closed(r.contact), Role.OUTLINE)]
    if r.speed_max != r.speed:
        curves.append(Curve(phi, closed(r.contact_max_speed), Role.DASHED,
                            f"{number(r.speed_max * 30 / math.pi, 0, lang)} "
                            f"{unit('rpm', lang)}"))
    force = diagram_panel("cam-contact", message("gearcam.cam.sheet.contact", lang), curves,
                          x_axis, Axis("N", "N·m" if swinging else "N", height * scale), lang)
    torque = diagram_panel("cam-torque", message("gearcam.cam.sheet.torque", lang),
                           [Curve(phi, closed(r.torque), Role.OUTLINE)], x_axis,
                           Axis("T", "N·m", height * scale), lang)
    return [force.panel, torque.panel]
