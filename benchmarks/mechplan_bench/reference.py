"""The independent 40-digit reference (``tests/independent``) and relative errors against it."""

from __future__ import annotations

import importlib.util
import math
import sys
from types import ModuleType

import numpy as np

from mechplan.errors import MechplanError

from .config import KINDS, ROOT, Case
from .results import Result


def independent(name: str) -> ModuleType:
    """Load ``tests/independent/<name>.py`` (mpref, closed_form) from the repository checkout."""
    path = ROOT / "tests" / "independent" / f"{name}.py"
    if not path.exists():
        raise MechplanError(f"the benchmark needs the independent reference {path} (got no such "
                            "file); run it from a clone installed with pip install -e '.[bench]'")
    key = f"_mechplan_bench_{name}"
    if key in sys.modules:
        return sys.modules[key]
    spec = importlib.util.spec_from_file_location(key, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[key] = module           # dataclasses look their module up while it loads
    try:
        spec.loader.exec_module(module)
    except ImportError as exc:
        del sys.modules[key]
        raise MechplanError(f"the reference {name} needs {exc.name} (got ImportError); install "
                            "the extras: pip install -e '.[bench]'") from exc
    return module


class Reference:
    """40-digit reference values (mpref), memoised by (mechanism, θ)."""

    def __init__(self) -> None:
        self.mpref = independent("mpref")
        self._memo: dict[tuple[str, float], dict[str, np.ndarray]] = {}

    def at(self, name: str, theta: np.ndarray) -> dict[str, np.ndarray]:
        """Reference arrays (mpref layout) at absolute crank angles θ."""
        theta = np.asarray(theta, dtype=float)
        todo = sorted({float(t) for t in theta if (name, float(t)) not in self._memo})
        if todo:
            ref = self.mpref.reference(name, np.array(todo))
            for i, t in enumerate(todo):
                self._memo[(name, t)] = {k: v[i] for k, v in ref.items()}
        rows = [self._memo[(name, float(t))] for t in theta]
        return {k: np.array([row[k] for row in rows]) for k in rows[0]}


def reference_result(case: Case, ref: dict[str, np.ndarray]) -> Result:
    """The reference arrays of a case as a :class:`Result`."""
    out = Result()
    for p in case.points:
        out.r[p], out.v[p], out.a[p] = ref[p][:, 0:2], ref[p][:, 2:4], ref[p][:, 4:6]
    for lk in case.links:
        out.omega[lk], out.epsilon[lk] = ref[lk][:, 1], ref[lk][:, 2]
    return out


def sizes(case: Case, ref: Result) -> dict[str, float]:
    """Largest magnitude of each kind over the reference positions."""
    out = {}
    for kind in KINDS:
        values = getattr(ref, kind)
        out[kind] = max(float(np.max(np.abs(v) if v.ndim == 1 else np.hypot(v[:, 0], v[:, 1])))
                        for v in values.values())
    return out


def relative_errors(got: Result, want: Result, idx: np.ndarray,
                    size: dict[str, float]) -> dict[str, float]:
    """Relative error per kind of ``got`` at positions ``idx`` against ``want`` (all of its rows).

    A NaN where the reference has a value counts as an infinite error (a failed position).
    """
    errs: dict[str, float] = {}
    for kind in KINDS:
        values = getattr(got, kind)
        if not values:
            continue
        worst = 0.0
        for key, arr in values.items():
            ref = getattr(want, kind)[key]
            diff = np.asarray(arr, dtype=float)[idx] - ref
            d = np.abs(diff) if diff.ndim == 1 else np.hypot(diff[:, 0], diff[:, 1])
            worst = math.inf if np.isnan(d).any() else max(worst, float(d.max()))
        errs[kind] = worst / size[kind]
    return errs
