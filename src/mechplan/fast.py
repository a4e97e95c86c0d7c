"""The fused path of the public API: the compiled kernel of a mechanism's kinematics.

``Mechanism.solve`` uses it when numba is installed (``pip install mechplan[fast]``) and only
kinematic plans are asked for. A position the kernel marks as not buildable, or whose estimate
says the result carries no information, sends the whole call to the numpy path, which raises or
lists it exactly as it always does — so both paths give the same values, errors and flags.

Everything that does not depend on the positions (the kernel, the column of each result, the
grouping by quantity) is prepared once per (plans, points, links) and reused by every call.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .construct.estimate import DEFAULT_TOLERANCE
from .construct.graph import Construction
from .construct.kernel import (
    CANNOT_TRUST,
    OVER_TOLERANCE,
    Kernel,
    KernelUnavailable,
    compile_kernel,
)
from .model.mechanism import GROUND
from .scene.spec import Scene

QUANTITIES = ("r", "v", "a", "angle", "omega", "epsilon")
_PLAN_OF = {"r": "position", "v": "velocity", "a": "acceleration", "angle": "position",
            "omega": "velocity", "epsilon": "acceleration"}


def numba_available() -> bool:
    """Tell whether the fused kernel can be JIT-compiled here."""
    return importlib.util.find_spec("numba") is not None


def all_points(scene: Scene) -> tuple[str, ...]:
    """Names of the points of the moving links, in the scene's order."""
    return tuple(dict.fromkeys(p for lk in scene.mechanism.links.values() if lk.id != GROUND
                               for p in lk.points))


def targets(scene: Scene, c: Construction, plans: Sequence[str],
            points: Sequence[str] | None = None,
            links: Sequence[str] | None = None) -> dict[tuple[str, str], str]:
    """Step id of every (quantity, subject) asked for: r, v, a of ``points`` and angle, ω, ε of
    ``links`` (default: every point and moving link) on the kinematic ``plans``."""
    accessors = {"r": c.position, "v": c.velocity_image, "a": c.acceleration_image,
                 "angle": c.link_angle, "omega": c.omega, "epsilon": c.epsilon}
    pts = all_points(scene) if points is None else tuple(points)
    lks = tuple(scene.mechanism.moving) if links is None else tuple(links)
    out: dict[tuple[str, str], str] = {}
    for q in QUANTITIES:
        if _PLAN_OF[q] not in plans:
            continue
        for s in (pts if q in ("r", "v", "a") else lks):
            try:
                out[(q, s)] = accessors[q](s)
            except KeyError:          # a point or link with no step on this plan
                continue
    return out


@dataclass(frozen=True)
class Prepared:
    """A kernel and where each (quantity, subject) lies in its output block."""

    kernel: Kernel
    keys: tuple[tuple[str, str], ...]
    #: quantity → subject → column (a slice for points, an index for scalars) of the block
    columns: dict[str, dict[str, slice | int]]


@dataclass(frozen=True)
class FastResult:
    """The (N, width) read-only output block, its columns and the flagged entries."""

    block: np.ndarray
    columns: dict[str, dict[str, slice | int]]
    flagged: tuple[tuple[int, str, str, float], ...]     # (position, quantity, subject, estimate)


class FastPath:
    """Kernels of one mechanism, compiled once per (plans, points, links)."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self._prepared: dict[tuple[object, ...], Prepared | None] = {}

    def prepare(self, c: Construction, plans: tuple[str, ...],
                points: tuple[str, ...] | None = None,
                links: tuple[str, ...] | None = None) -> Prepared | None:
        """The kernel of what is asked for (None when it has none: force plans, no numba)."""
        key = (plans, points, links)
        if key not in self._prepared:
            entry = None
            if "force" not in plans and numba_available():
                wanted = targets(self.scene, c, plans, points, links)
                try:
                    kernel = compile_kernel(c, list(wanted.values()))
                except KernelUnavailable:
                    kernel = None
                if kernel is not None:
                    columns: dict[str, dict[str, slice | int]] = {q: {} for q in QUANTITIES}
                    for (q, s), col in zip(wanted, kernel.columns):
                        columns[q][s] = col
                    entry = Prepared(kernel, tuple(wanted), columns)
            self._prepared[key] = entry
        return self._prepared[key]

    def kernel(self, c: Construction, plans: tuple[str, ...]) -> Prepared | None:
        """The prepared kernel of every point and link on ``plans``."""
        return self.prepare(c, plans)

    @staticmethod
    def evaluate(prepared: Prepared, phi: np.ndarray,
                 tolerance: float = DEFAULT_TOLERANCE) -> FastResult | None:
        """Evaluate at φ (rad); None when the numpy path must decide."""
        if phi.dtype != np.float64 or not phi.flags.c_contiguous:
            phi = np.ascontiguousarray(phi, dtype=np.float64)
        kernel = prepared.kernel
        block, rel, _, status = kernel.run(phi, tolerance, store=False)
        if status & CANNOT_TRUST:
            return None
        flagged: tuple[tuple[int, str, str, float], ...] = ()
        if status & OVER_TOLERANCE:
            # rare: run again keeping the estimates, to say which results at which positions
            block, rel, _, status = kernel.run(phi, tolerance, store=True)
            keys = prepared.keys
            flagged = tuple((int(k), keys[j][0], keys[j][1], float(rel[k, j]))
                            for k, j in np.argwhere(rel > tolerance))
        block.flags.writeable = False
        return FastResult(block, prepared.columns, flagged)
