"""A linkage whose crank is turned by a law (a cam's follower lever): at each position its own
angle, angular velocity and angular acceleration.

The construction is the scene's own: the crank's given steps (ω1, the driving vector p b, ε1 and
π b′) take each position's values instead of the scene's constant speed, and every later step of
the velocity, acceleration and force plans is built on them as usual.
"""

from __future__ import annotations

import numpy as np

from ..errors import SceneError
from ..geom.vec import Array
from ..i18n import Text
from ..model.mechanism import DriverKind, Mechanism
from .graph import Construction, Evaluation
from .ops import Op


def _perp(v: Array) -> Array:
    return np.stack([-v[:, 1], v[:, 0]], axis=1)


def _slider(c: Construction, q: Array, rate: Array, accel: Array) -> Evaluation:
    """A driving slider at coordinates ``q`` (m) with the rates ṡ, s̈ of each position."""
    q = np.asarray(q, dtype=float)
    over = {sid: np.broadcast_to(np.asarray(v, dtype=float), q.shape).copy()
            for sid, v in (("vel.rate", rate), ("acc.rate", accel)) if sid in c.steps}
    return c.evaluate(q, overrides=over)


def law_evaluation(c: Construction, mech: Mechanism, theta: Array, omega: Array, epsilon: Array,
                   key: str = "drive") -> Evaluation:
    """Evaluate ``c`` with the crank at absolute angles ``theta`` (rad, counter-clockwise from
    +x), turning at ``omega`` (rad/s) with ``epsilon`` (rad/s²), all of shape (N,), signed
    counter-clockwise positive; a driving slider at coordinates ``theta`` (m) with the rates
    ``omega`` (m/s) and ``epsilon`` (m/s²). A cylinder or a second driver is refused (``key``)."""
    drive = mech.drive
    if mech.drive2 is not None or drive.kind is DriverKind.CYLINDER:
        raise SceneError(Text("machine.error.law_linear", {"kind": drive.kind.value}), key=key)
    if drive.kind is DriverKind.SLIDER:
        return _slider(c, theta, omega, epsilon)
    theta = np.asarray(theta, dtype=float)
    omega = np.broadcast_to(np.asarray(omega, dtype=float), theta.shape)
    epsilon = np.broadcast_to(np.asarray(epsilon, dtype=float), theta.shape)
    phi = c.drive.scene(theta)
    ev0 = c.evaluate(phi)
    over: dict[str, Array] = {}
    w_id, e_id = f"vel.omega.{drive.link}", f"acc.epsilon.{drive.link}"
    for step in c.steps.values():
        if step.op is not Op.DRIVE_VELOCITY and step.op is not Op.DRIVE_ACCELERATION:
            continue
        pivot, tip = ev0[step.input("pivot")], ev0[step.input("tip")]
        r = tip - pivot
        if step.op is Op.DRIVE_VELOCITY:
            over[step.id] = omega[:, None] * _perp(r)
        else:
            over[step.id] = epsilon[:, None] * _perp(r) - (omega * omega)[:, None] * r
    if w_id in c.steps:
        over[w_id] = omega.copy()
    if e_id in c.steps:
        over[e_id] = epsilon.copy()
    return c.evaluate(phi, overrides=over)
