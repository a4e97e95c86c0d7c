"""Loading a generated kernel: plain Python, or JIT-compiled with numba and cached on disk.

The source is written to the cache folder (``MECHPLAN_CACHE``, default
``~/.cache/mechplan/kernels``) under the hash of its text and compiled with
``numba.njit(cache=True)``, so other processes load the compiled code instead of compiling.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any


class KernelUnavailable(RuntimeError):
    """The construction (or this installation) has no compiled kernel; use the numpy path."""


def _cache_dir() -> Path:
    base = os.environ.get("MECHPLAN_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"),
        "mechplan")
    path = Path(base) / "kernels"
    path.mkdir(parents=True, exist_ok=True)
    return path


#: what the markers of the generated source become when numba compiles it
_JIT = "@numba.njit(cache=True, error_model='numpy')"
_PARALLEL = "@numba.njit(cache=True, error_model='numpy', parallel=True)"


def numba_source(source: str) -> str:
    """The generated source as numba compiles it: ``#@jit`` / ``#@parallel`` markers become
    decorators and ``prange`` numba's parallel range."""
    return (source.replace("#@jit\n", _JIT + "\n").replace("#@parallel\n", _PARALLEL + "\n")
            .replace("prange = range\n", "from numba import prange\n", 1)
            .replace("import math\n", "import math\n\nimport numba\n", 1))


def load(source: str, jit: bool) -> tuple[dict[str, Callable[..., int]], bool]:
    """The functions ``kernel`` and ``kernel_parallel`` of a generated source, and whether numba
    compiled them."""
    digest = hashlib.sha256(source.encode()).hexdigest()[:24]
    name = f"mechplan_kernel_{digest}"
    if not jit:
        namespace: dict[str, Any] = {}
        exec(compile(source, name, "exec"), namespace)   # noqa: S102 - our own generated code
        return {k: namespace[k] for k in ("kernel", "kernel_parallel")}, False
    if importlib.util.find_spec("numba") is None:
        raise KernelUnavailable("numba is not installed (pip install mechplan[fast])") from None
    path = _cache_dir() / f"{name}.py"
    if not path.exists():
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(numba_source(source), encoding="utf-8")
        os.replace(tmp, path)
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise KernelUnavailable(f"cannot load the kernel module {path}")
    module = sys.modules.get(name) or importlib.util.module_from_spec(spec)
    if name not in sys.modules:
        spec.loader.exec_module(module)
        sys.modules[name] = module
    return {k: getattr(module, k) for k in ("kernel", "kernel_parallel")}, True
