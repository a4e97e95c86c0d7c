"""pylinkage without numba: timed in a child process with numba's JIT disabled."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np

from mechplan.errors import MechplanError

from .config import CASES, KINDS, ROOT, Config
from .model import Model
from .peers import pylinkage_runner
from .results import Result
from .timing import best_time


def pylinkage_without_numba(cfg: Config, cases: Sequence[str], ns: Sequence[int],
                            log: Callable[[str], None]
                            ) -> dict[tuple[str, int], tuple[float, int, Result]]:
    """Run pylinkage in a child process with numba's JIT disabled; (case, N) → (time, k, result)."""
    with tempfile.TemporaryDirectory() as tmp:
        spec = {"cases": list(cases), "ns": list(ns), "out": tmp,
                "cfg": {k: v for k, v in asdict(cfg).items() if not isinstance(v, tuple)}}
        env = dict(os.environ, NUMBA_DISABLE_JIT="1")
        env["PYTHONPATH"] = os.pathsep.join([str(ROOT / "src"), str(ROOT / "benchmarks"),
                                             env.get("PYTHONPATH", "")])
        log("pylinkage without numba: child process (NUMBA_DISABLE_JIT=1)")
        code = ("import sys, json; from mechplan_bench.no_numba import _child; "
                "_child(json.loads(sys.argv[1]))")
        proc = subprocess.run([sys.executable, "-c", code, json.dumps(spec)], env=env, check=False,
                              capture_output=True, text=True, timeout=3600)
        if proc.returncode != 0:
            raise MechplanError(f"pylinkage child process failed: {proc.stderr.strip()[-500:]}")
        meta = json.loads((Path(tmp) / "meta.json").read_text())
        out = {}
        for entry in meta:
            arrays = np.load(Path(tmp) / f"{entry['case']}_{entry['n']}.npz")
            res = Result()
            for key in arrays.files:
                kind, name = key.split(":")
                getattr(res, kind)[name] = arrays[key]
            out[(entry["case"], entry["n"])] = (entry["seconds"], entry["repeats"], res)
        return out


def _child(spec: dict[str, Any]) -> None:
    """Child-process side of :func:`pylinkage_without_numba`."""
    cfg = Config(**spec["cfg"])
    meta = []
    for name in spec["cases"]:
        model = Model.load(CASES[name])
        for n in spec["ns"]:
            phi = model.phi(n)
            best, k, res = best_time(pylinkage_runner(model, phi), cfg)
            arrays = {f"{kind}:{key}": v for kind in KINDS for key, v in getattr(res, kind).items()}
            np.savez(Path(spec["out"]) / f"{name}_{n}.npz", **arrays)
            meta.append({"case": name, "n": n, "seconds": best, "repeats": k})
    (Path(spec["out"]) / "meta.json").write_text(json.dumps(meta))
