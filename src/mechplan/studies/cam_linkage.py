"""A linkage whose crank is a cam's follower lever: its plans at each cam angle from the cam's
law ψ, ψ′, ψ″, and its load carried back to the cam (the lever's moment → the contact force → the
cam torque).

Signs: the cam scene's follower swings its arm clockwise as ψ grows when the cam turns
counter-clockwise (the pivot at (a, 0), the arm above the line of centres), so in a plane shared
with the linkage the lever's absolute angle is θ = θ_near − σ·ψ (σ = +1 for a counter-clockwise
cam). The linkage's balancing moment M_b (what the lever must be given) is the generalised force
Q = −σ·M_b along ψ; the follower's own inertia, damper, spring and load (the cam's
``[dynamics]``) add theirs. The cam presses along the profile's normal: N·l·cos α = Q (a roller or
knife at the arm's length l, pressure angle α) or N·L = Q (a flat face, contact at L from the
pivot); by power T·ω = Q·ψ̇ the cam torque is T = Q·ψ′.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from ..dynamics.cam_linkage import STEP_DEG, CamLinkage
from ..errors import SceneError
from ..i18n import Text
from ..model.cam import CamSpec, Contact, Motion
from ..model.mechanism import GROUND, DriverKind


def cam_linkage(cam: CamSpec, scene: Any, near: float, omega_cam: float, name: str,
                cam_name: str, subject: str | None, key: str) -> CamLinkage:
    """Solve the linkage ``scene`` (a parsed mechanism scene) driven by the follower of ``cam``.

    ``near``: the linkage's crank angle φ (its scene's convention) at the cam's near position, or
    a driving slider's coordinate (m) there (a translating follower);
    ``omega_cam``: the cam's speed (rad/s, > 0). Errors name ``key`` (the member).
    """
    from ..construct.law_drive import law_evaluation
    from ..construct.textbook.stroke import default_outputs
    from ..solve import build
    from ..synthesis.cam import design
    from ..synthesis.cam.motion import motion
    from ..synthesis.cam.profile import sample

    mech = scene.mechanism
    sliding = mech.drive.kind is DriverKind.SLIDER
    if mech.drive.kind is DriverKind.CYLINDER or mech.drive2 is not None:
        raise SceneError(Text("machine.error.law_linear", {"kind": mech.drive.kind.value}),
                         key=key + ".scene")
    if (cam.follower.motion is Motion.OSCILLATING) == sliding:
        raise SceneError(Text("machine.error.follower_driver", {
            "name": name, "cam": cam_name, "motion": cam.follower.motion.value,
            "kind": mech.drive.kind.value}), key=key + ".driven_by")
    loaded = bool(scene.loads) or any(m.mass or m.inertia for m in scene.masses.values())
    plans = ("position", "velocity", "acceleration") + (("force",) if loaded else ())
    # the lever has an angular acceleration: built with a non-zero ε the plan's equation lists
    # the tangential component too (its values come from the law at each position)
    lawful = replace(scene, mechanism=replace(mech, drive=replace(mech.drive, epsilon=1.0)))
    _, c = build(lawful, plans)
    phi = np.radians(np.arange(0.0, 360.0, STEP_DEG))
    m = motion(cam.phases, cam.stroke, phi)
    # a lever turns clockwise as ψ grows under a counter-clockwise cam; a slider moves along
    # its guide's direction as s grows
    sigma = 1 if sliding else cam.sense
    theta = (near + m.s) if sliding else c.drive.absolute(np.full_like(m.s, near)) - sigma * m.s
    omega = (1 if sliding else -sigma) * m.s1 * omega_cam
    epsilon = (1 if sliding else -sigma) * m.s2 * omega_cam ** 2
    try:
        ev = law_evaluation(c, mech, theta, omega, epsilon, key + ".scene")
    except SceneError as exc:
        raise SceneError(exc.detail, key=exc.key or key + ".scene") from None
    outs = [subject] if subject else default_outputs(mech)
    if not outs:
        raise SceneError(Text("machine_cycle.error.no_output", {"name": name}), key=key + ".output")
    out_name = outs[0]
    rocker = out_name in mech.links
    if rocker:
        try:
            value = np.unwrap(ev[c.link_angle(out_name)])
            rate, acc = ev[c.omega(out_name)], ev[c.epsilon(out_name)]
        except KeyError:
            raise SceneError(Text("machine.error.output", {"name": name, "output": out_name}),
                             key=key + ".output") from None
    else:
        owner = next((k for k, lk in mech.links.items() if out_name in lk.points
                      and lk.slides_on and mech.guides[lk.slides_on].link == GROUND), None)
        if owner is None:
            raise SceneError(Text("machine.error.output", {"name": name, "output": out_name}),
                             key=key + ".output")
        g = mech.guides[mech.links[owner].slides_on]
        d = np.array([math.cos(g.angle), math.sin(g.angle)])
        value = (ev[c.position(out_name)] - np.array(g.origin)) @ d
        rate = ev[c.velocity_image(out_name)] @ d
        acc = ev[c.acceleration_image(out_name)] @ d
    bad = ~np.isfinite(value)
    if bad.any():
        raise SceneError(Text("machine.error.unreachable", {
            "name": name, "phi": f"{math.degrees(float(phi[np.argmax(bad)])):.0f}"}),
            key=key + ".near")
    moment = generalised = contact = torque = None
    dyn = cam.dynamics
    if loaded or dyn is not None:
        if loaded:
            moment = np.asarray(ev[c.driving_force() if sliding else c.balancing_moment()],
                                dtype=float)
        generalised = ((moment if sliding else -sigma * moment) if moment is not None
                       else np.zeros_like(phi))
        des = design(cam)
        if dyn is not None and des.dynamics is not None:
            k, f0 = des.dynamics.stiffness, des.dynamics.preload
            generalised = generalised + (dyn.mass * omega_cam ** 2 * m.s2
                                         + dyn.damping * omega_cam * m.s1 + k * m.s + f0 + dyn.load)
        smp = sample(des.geometry, phi)
        if sliding:                 # along the follower: N·cos α = Q (a flat face: α = 0)
            arm = (np.ones_like(phi) if cam.follower.contact is Contact.FLAT
                   else np.cos(smp.alpha))
        elif cam.follower.contact is Contact.FLAT:
            pivot = np.array([cam.sense * cam.follower.pivot_distance, 0.0])
            arm = np.hypot(*(smp.follower - pivot).T)
        else:
            arm = cam.follower.arm * np.cos(smp.alpha)
        contact = generalised / arm
        torque = generalised * m.s1
    return CamLinkage(name, cam_name, out_name, rocker, omega_cam, phi, m.s, m.s1, m.s2, theta,
                      omega, epsilon, np.asarray(value), np.asarray(rate), np.asarray(acc),
                      moment, generalised, contact, torque, c, ev,
                      int(np.argmax(np.abs(omega))))
