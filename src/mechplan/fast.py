"""The fused path of the public API: the compiled kernel of a mechanism's kinematics.

``Mechanism.solve`` uses it when numba is installed (``pip install mechplan[fast]``) and only
kinematic plans are asked for. A position the kernel marks as not buildable, or whose estimate
says the result carries no information, sends the whole call to the numpy path, which raises or
lists it exactly as it always does — so both paths give the same values, errors and flags.
"""

from __future__ import annotations

import importlib.util
from dataclasses import dataclass

import numpy as np

from .construct.estimate import DEFAULT_TOLERANCE, UNBOUNDED
from .construct.graph import Construction
from .construct.kernel import Kernel, KernelUnavailable, compile_kernel
from .model.mechanism import GROUND
from .scene.spec import Scene

QUANTITIES = ("r", "v", "a", "angle", "omega", "epsilon")
_PLAN_OF = {"r": "position", "v": "velocity", "a": "acceleration", "angle": "position",
            "omega": "velocity", "epsilon": "acceleration"}


def numba_available() -> bool:
    """Tell whether the fused kernel can be JIT-compiled here."""
    return importlib.util.find_spec("numba") is not None


@dataclass(frozen=True)
class FastResult:
    """Values and relative error estimates by (quantity, subject), and the flagged entries."""

    values: dict[tuple[str, str], np.ndarray]
    keys: list[tuple[str, str]]
    relative: np.ndarray                                 # (N, len(keys)) relative estimates
    flagged: tuple[tuple[int, str, str, float], ...]     # (position, quantity, subject, estimate)

    def estimate(self, quantity: str, subject: str) -> np.ndarray:
        """Relative error estimate of one result at every position."""
        return self.relative[:, self.keys.index((quantity, subject))]


def _targets(scene: Scene, c: Construction, plans: tuple[str, ...]) -> dict[tuple[str, str], str]:
    points = dict.fromkeys(p for lk in scene.mechanism.links.values() if lk.id != GROUND
                           for p in lk.points)
    accessors = {"r": c.position, "v": c.velocity_image, "a": c.acceleration_image,
                 "angle": c.link_angle, "omega": c.omega, "epsilon": c.epsilon}
    out: dict[tuple[str, str], str] = {}
    for q in QUANTITIES:
        if _PLAN_OF[q] not in plans:
            continue
        subjects = points if q in ("r", "v", "a") else scene.mechanism.moving
        for s in subjects:
            try:
                out[(q, s)] = accessors[q](s)
            except KeyError:          # a point or link with no step on this plan
                continue
    return out


class FastPath:
    """Kernels of one mechanism, compiled once per set of plans."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self._kernels: dict[tuple[str, ...], tuple[Kernel, dict[tuple[str, str], str]] | None] = {}

    def kernel(self, c: Construction, plans: tuple[str, ...]) -> tuple[Kernel, dict] | None:
        """The kernel for ``plans`` (None when it has none: force plans, no numba)."""
        if plans not in self._kernels:
            entry = None
            if "force" not in plans and numba_available():
                targets = _targets(self.scene, c, plans)
                try:
                    entry = (compile_kernel(c, list(targets.values())), targets)
                except KernelUnavailable:
                    entry = None
            self._kernels[plans] = entry
        return self._kernels[plans]

    def evaluate(self, c: Construction, plans: tuple[str, ...], phi: np.ndarray,
                 tolerance: float = DEFAULT_TOLERANCE) -> FastResult | None:
        """Evaluate at φ (rad); None when the numpy path must decide (or there is no kernel)."""
        entry = self.kernel(c, plans)
        if entry is None:
            return None
        kernel, targets = entry
        outs, rel, bad = kernel.run(phi)
        if bad.any() or not (rel < UNBOUNDED).all():
            return None
        keys = list(targets)
        over = rel > tolerance
        flagged = tuple((int(k), keys[j][0], keys[j][1], float(rel[k, j]))
                        for k, j in np.argwhere(over)) if over.any() else ()
        for out in outs:
            out.flags.writeable = False
        rel.flags.writeable = False
        return FastResult(dict(zip(keys, outs)), keys, rel, flagged)
