"""What a linkage turned by a cam's follower gives over one cam turn (the result of
:func:`mechplan.studies.cam_linkage.cam_linkage`): the lever's law, the output, the lever's
moment, the contact force and the cam torque."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

STEP_DEG = 1.0          # the cam angles of the tables and diagrams


@dataclass(frozen=True)
class CamLinkage:
    """The cam-driven linkage over one cam turn (arrays of shape (N,), SI, cam angles from the
    start of the cam's first phase)."""

    name: str
    cam: str
    output: str                 # the linkage's output: a rocker's link or a slider's point
    rocker: bool                # True: the output is a link angle (rad), else a length (m)
    omega_cam: float            # the cam's speed, rad/s (> 0)
    phi: np.ndarray
    psi: np.ndarray             # the follower's swing (rad), ψ′, ψ″
    psi1: np.ndarray
    psi2: np.ndarray
    theta: np.ndarray           # the lever's absolute angle, ω, ε (counter-clockwise +)
    omega: np.ndarray
    epsilon: np.ndarray
    out: np.ndarray             # the output's coordinate, rate and acceleration
    out_rate: np.ndarray
    out_acc: np.ndarray
    moment: np.ndarray | None   # M_b on the lever (None: the linkage is not loaded)
    generalised: np.ndarray | None   # Q along ψ, N·m
    contact: np.ndarray | None  # the cam's force on the follower along the normal, N
    torque: np.ndarray | None   # the cam torque, N·m
    #: the linkage's construction and its evaluation at every cam angle (the plans drawn), and
    #: the cam angle (index) whose plans the sheet draws: the lever's fastest
    construction: Any = None
    evaluation: Any = None
    plan_index: int = 0

    def extremes(self) -> dict[str, Any]:
        """Extremes of the output and of the forces: (value, cam angle in degrees)."""
        out: dict[str, Any] = {}

        def ext(key: str, a: np.ndarray | None) -> None:
            if a is None:
                return
            i, j = int(np.argmax(a)), int(np.argmin(a))
            out[key] = {"max": float(a[i]), "max_phi_deg": math.degrees(self.phi[i]),
                        "min": float(a[j]), "min_phi_deg": math.degrees(self.phi[j])}
        for k, a in (("output", self.out), ("output_rate", self.out_rate),
                     ("output_acceleration", self.out_acc), ("lever_omega", self.omega),
                     ("lever_epsilon", self.epsilon), ("moment", self.moment),
                     ("contact", self.contact), ("torque", self.torque)):
            ext(k, a)
        if self.torque is not None:
            out["torque_mean"] = float(np.mean(self.torque))
        return out

    @property
    def separates(self) -> bool:
        """True when the cam would have to pull the follower somewhere (N < 0)."""
        return self.contact is not None and bool(np.any(self.contact < 0.0))

    def plans(self) -> tuple[Any, Any, int]:
        """(construction, evaluation, position index) of the plans the sheet draws."""
        return self.construction, self.evaluation, self.plan_index

    def to_json(self) -> dict[str, Any]:
        """Every array every degree, SI units."""
        def arr(a: np.ndarray | None) -> list[float] | None:
            return None if a is None else [float(x) for x in a]
        return {"name": self.name, "cam": self.cam, "output": self.output,
                "rocker": self.rocker, "omega_cam_rad_s": self.omega_cam,
                "extremes": self.extremes(), "separates": self.separates,
                "phi_deg": [math.degrees(x) for x in self.phi], "psi": arr(self.psi),
                "psi1": arr(self.psi1), "psi2": arr(self.psi2), "lever_angle": arr(self.theta),
                "lever_omega": arr(self.omega), "lever_epsilon": arr(self.epsilon),
                "output_value": arr(self.out), "output_rate": arr(self.out_rate),
                "output_acceleration": arr(self.out_acc), "moment": arr(self.moment),
                "generalised_force": arr(self.generalised), "contact": arr(self.contact),
                "torque": arr(self.torque)}
