"""A case's construction in its three uses: exact (float64/float32), ruler mode, finite
differences."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from mechplan.construct.graph import Construction, Evaluation
from mechplan.scene import load_scene
from mechplan.scene.spec import Scene
from mechplan.solve import KINEMATIC, build, choose_scales

from .config import FD_STEP_A, FD_STEP_V, PHI0, ROOT, TWO_PI, Case
from .results import Result
from .ruler import RulerEvaluation


@dataclass
class Model:
    """A case's scene and construction, and the step ids of what is compared."""

    case: Case
    scene: Scene
    c: Construction
    targets: list[str]
    position_targets: list[str]

    @classmethod
    def load(cls, case: Case, templates: Path = ROOT / "templates") -> Model:
        """Load the case's template and build its construction."""
        scene = load_scene(templates / f"{case.name}.toml")
        _, c = build(scene, KINEMATIC)
        targets = [f"pos.{p}" for p in case.points]
        targets += [c.results[f"{s}_{p}"] for s in ("v", "a") for p in case.points]
        targets += [c.results[f"{s}_{lk}"] for s in ("omega", "epsilon") for lk in case.links]
        pos = [f"pos.{p}" for p in case.points] + [c.results[f"angle_{lk}"] for lk in case.links]
        return cls(case, scene, c, targets, pos)

    def phi(self, n: int) -> np.ndarray:
        """φ of N equal steps from PHI0 (rad, scene convention)."""
        return PHI0 + TWO_PI * np.arange(n) / n

    def theta(self, phi: np.ndarray) -> np.ndarray:
        """Absolute crank angles of φ."""
        return self.c.drive.absolute(phi)

    def result(self, ev: Evaluation) -> Result:
        """The compared quantities of an evaluation, as float64."""
        c, out = self.c, Result()
        for p in self.case.points:
            out.r[p] = ev[f"pos.{p}"].astype(float)
            out.v[p] = ev[c.results[f"v_{p}"]].astype(float)
            out.a[p] = ev[c.results[f"a_{p}"]].astype(float)
        for lk in self.case.links:
            out.omega[lk] = ev[c.results[f"omega_{lk}"]].astype(float)
            out.epsilon[lk] = ev[c.results[f"epsilon_{lk}"]].astype(float)
        return out

    def exact(self, phi: np.ndarray, dtype: type = np.float64) -> Callable[[], Evaluation]:
        """A runner evaluating the construction at φ (lazily: only what the case compares)."""
        def run() -> Evaluation:
            ev = self.c.evaluate(phi, dtype=dtype)
            ev.evaluate_all(self.targets)
            return ev
        return run

    def ruler(self, phi: np.ndarray, step_mm: float) -> Callable[[], Evaluation]:
        """A runner of ruler mode: the construction drawn at the scene's scale factors."""
        probe = self.exact(phi)()
        scales = choose_scales(self.scene, self.c, probe, KINEMATIC)

        def run() -> Evaluation:
            ev = RulerEvaluation(self.c, phi, {plan: step_mm * mu for plan, mu in scales.items()})
            ev.evaluate_all(self.targets)
            return ev
        return run

    def finite_differences(self, phi: np.ndarray) -> Callable[[], Result]:
        """A runner: positions from the construction, v and a by central differences in φ."""
        drive = self.scene.mechanism.drive
        rate = abs(drive.omega)      # dφ/dt: φ grows in the sense of rotation
        n = phi.shape[0]
        hv, ha = FD_STEP_V, FD_STEP_A
        stacked = np.concatenate((phi, phi - hv, phi + hv, phi - ha, phi + ha))

        def run() -> Result:
            ev = self.c.evaluate(stacked)
            ev.evaluate_all(self.position_targets)
            out = Result()
            for p in self.case.points:
                r = ev[f"pos.{p}"]
                r0, rmv, rpv, rma, rpa = (r[i * n:(i + 1) * n] for i in range(5))
                out.r[p] = r0
                out.v[p] = (rpv - rmv) * (rate / (2.0 * hv))
                out.a[p] = (rpa - 2.0 * r0 + rma) * (rate * rate / (ha * ha))
            for lk in self.case.links:
                g = ev[self.c.results[f"angle_{lk}"]]
                g0, gmv, gpv, gma, gpa = (g[i * n:(i + 1) * n] for i in range(5))
                out.omega[lk] = _wrap(gpv - gmv) * (rate / (2.0 * hv))
                out.epsilon[lk] = (_wrap(gpa - g0) - _wrap(g0 - gma)) * (rate * rate / (ha * ha))
            return out
        return run


def _wrap(angle: np.ndarray) -> np.ndarray:
    return np.remainder(angle + math.pi, TWO_PI) - math.pi
