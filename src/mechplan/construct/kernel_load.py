"""The fixed parts of a generated kernel's source, and loading it: plain Python, or JIT-compiled
with numba and cached on disk.

The source is written to the cache folder (``MECHPLAN_CACHE``, default
``~/.cache/mechplan/kernels``) under the hash of its text and compiled with
``numba.njit(cache=True)``, so other processes load the compiled code instead of compiling.
"""

from __future__ import annotations

import ast
import copy
import functools
import hashlib
import importlib.util
import math
import os
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .step import Kind


class KernelUnavailable(RuntimeError):
    """The construction (or this installation) has no compiled kernel; use the numpy path."""


class KernelUnsupported(KernelUnavailable):
    """An operation the outputs need has no scalar form in ``construct/kernel.py``; use the numpy
    path (an internal signal: callers catch :class:`KernelUnavailable`)."""


def _helpers_digest() -> str:
    """The digest of the helpers every kernel calls: ``kernel_helpers.py``, ``kernel_triad.py``,
    ``kernel_triadp.py`` and the triad solver's constants in ``ops/triad_closure.py`` (read, not
    imported: importing them imports numba)."""
    here = Path(__file__)
    text = b"".join((here.parent / name).read_bytes()
                    for name in ("kernel_helpers.py", "kernel_triad.py", "ops/triad_closure.py",
                                 "kernel_law.py", "kernel_triadp.py"))
    return hashlib.sha256(text).hexdigest()[:16]


#: what every generated source starts with: the shared helpers (``kernel_helpers``, compiled once
#: per machine) and the digest of their version
HELPERS = f"""
import math

import numpy as np

from mechplan.construct.kernel_helpers import _below1, _cdiv, _div, _div_nz, _height, _hyp
from mechplan.construct.kernel_triad import _triad_angle
from mechplan.construct.kernel_triadp import _triadp_angle
from mechplan.construct.kernel_law import _law_at, _law_time, _where_finite

# helpers {_helpers_digest()}
prange = range
NAN = math.nan
INF = math.inf

"""

#: the entry points: serial, and chunks of positions on numba's threads (``#@parallel``); without
#: stored estimates each runs the interleaved ``_quick`` loop, which hands a position to the full
#: ``_body`` only when its cheap bound does not decide
DRIVERS = """

#@jit
def kernel(phi, tol, out, xs, rel, bad, store):
    if store:
        return _body(phi, tol, out, xs, rel, bad, store, 0, phi.shape[0])
    return _quick(phi, tol, out, xs, rel, bad, store, 0, phi.shape[0])


#@parallel
def kernel_parallel(phi, tol, out, xs, rel, bad, store, chunk):
    n = phi.shape[0]
    count = (n + chunk - 1) // chunk
    each = np.zeros(count, dtype=np.int64)
    for c in prange(count):
        lo = c * chunk
        hi = min(n, lo + chunk)
        if store:
            each[c] = _body(phi, tol, out, xs, rel, bad, store, lo, hi)
        else:
            each[c] = _quick(phi, tol, out, xs, rel, bad, store, lo, hi)
    status = 0
    for c in range(count):
        status |= each[c]
    return status
"""

#: positions computed side by side in one pass of the quick loop: independent chains of
#: dependent divisions and square roots overlap (bit for bit the same values)
LANES = 2
#: names the lanes share (the loop's status, the positions left for the full body)
SHARED = frozenset({"status", "redo", "redo_n"})


def single_assignment(stmts: list[ast.stmt]) -> list[ast.stmt]:
    """``stmts`` with every reassigned temporary given a new name at each assignment (``_dx``,
    ``_dx__1`` …), so that numba has no variable of several definitions to reconcile (its SSA
    pass grows quickly with them). Names assigned inside ``if`` blocks, and the names the lanes
    share, keep theirs."""
    nested = {n.id for stmt in stmts if not isinstance(stmt, (ast.Assign, ast.AugAssign))
              for n in ast.walk(stmt) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
    nested |= SHARED
    current: dict[str, str] = {}
    count: dict[str, int] = {}

    def load(node: ast.AST) -> None:
        for n in ast.walk(node):
            if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load) and n.id in current:
                n.id = current[n.id]

    out = []
    for stmt in stmts:
        stmt = copy.deepcopy(stmt)
        if isinstance(stmt, ast.AugAssign) and isinstance(stmt.target, ast.Name) \
                and stmt.target.id not in nested:
            name = stmt.target.id
            stmt = ast.Assign([ast.Name(name, ast.Store())],
                              ast.BinOp(ast.Name(name, ast.Load()), stmt.op, stmt.value),
                              lineno=stmt.lineno)
        if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 \
                and isinstance(stmt.targets[0], ast.Name) and stmt.targets[0].id not in nested:
            load(stmt.value)
            target = stmt.targets[0]
            base = target.id
            if base in count:
                count[base] += 1
                current[base] = target.id = f"{base}__{count[base]}"
            else:
                count[base] = 0
                current[base] = base
        else:
            load(stmt)
        out.append(stmt)
    return out


def without_dead(stmts: list[ast.stmt]) -> list[ast.stmt]:
    """``stmts`` (in single assignment) without the assignments of names nothing reads after
    them — e.g. an angle whose atan2 is left to numpy. Every generated expression is free of
    side effects; stores into arrays and ``if`` blocks stay."""
    live: set[str] = set()
    kept: list[ast.stmt] = []
    for stmt in reversed(stmts):
        if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 \
                and isinstance(stmt.targets[0], ast.Name) \
                and stmt.targets[0].id not in live | SHARED:
            continue
        live |= {n.id for n in ast.walk(stmt) if isinstance(n, ast.Name)
                 and isinstance(n.ctx, ast.Load)}
        kept.append(stmt)
    return kept[::-1]


def interleave(values: Sequence[str], rest: Sequence[str], lanes: int = LANES) -> list[str]:
    """The loop body of ``lanes`` positions ``i0 … i{lanes-1}``: the statements of ``values``
    interleaved lane by lane (each lane's locals renamed ``name_k``), then each lane's ``rest``;
    every temporary assigned once (:func:`single_assignment`), none that nothing reads."""
    parsed = ast.parse("\n".join([*values, *rest])).body
    head = len(ast.parse("\n".join(values)).body)
    for k, stmt in enumerate(parsed):
        stmt.lineno = k              # the position survives the passes: values come first
    stmts = without_dead(single_assignment(parsed))
    trees = [[t for t in stmts if t.lineno < head], [t for t in stmts if t.lineno >= head]]
    local = {n.id for stmt in stmts for n in ast.walk(stmt)
             if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)} - SHARED

    def lane(stmt: ast.stmt, k: int) -> list[str]:
        stmt = copy.deepcopy(stmt)
        for node in ast.walk(stmt):
            if isinstance(node, ast.Name):
                if node.id == "i":
                    node.id = f"i{k}"
                elif node.id in local:
                    node.id = f"{node.id}_{k}"
        return ast.unparse(ast.fix_missing_locations(stmt)).split("\n")

    out = [line for stmt in trees[0] for k in range(lanes) for line in lane(stmt, k)]
    return out + [line for k in range(lanes) for stmt in trees[1] for line in lane(stmt, k)]


#: positions from which a call runs on numba's threads (chunks of CHUNK positions each), when
#: the machine has a spare core
PARALLEL_FROM = 20_000
CHUNK = 4096


def spare_cores() -> float:
    """Cores not busy with other work: the core count less the load average, this process's own
    share (one core while it computes) given back. Threads on cores busy with other processes
    make a run slower than one thread, not faster."""
    count = os.cpu_count() or 1
    try:
        busy = os.getloadavg()[0]
    except OSError:                   # no load average on this system: trust the core count
        return float(count)
    return count - max(busy - 1.0, 0.0)


def tree_sum(terms: Sequence[str]) -> str:
    """A sum as a balanced tree: a short chain of dependent additions."""
    if len(terms) == 1:
        return terms[0]
    half = len(terms) // 2
    return f"({tree_sum(terms[:half])} + {tree_sum(terms[half:])})"


def indent(lines: Sequence[str], depth: int = 2) -> list[str]:
    return ["    " * depth + line for line in lines]


@dataclass(frozen=True)
class Kernel:
    """A compiled construction: ``kernel(phi)`` → values and relative error estimates of the
    outputs.

    The outputs are the columns of one (N, width) block: a point takes two (x, y), a scalar one
    (``columns[j]`` is target j's slice). While it loops, the kernel also finds whether any position
    cannot be built or has an estimate ≥ 1 (status bit 1, :data:`CANNOT_TRUST`) and whether any
    estimate exceeds the tolerance (status bit 2, :data:`OVER_TOLERANCE`), so the estimate matrix
    need only be stored when a caller asks for it. From :data:`PARALLEL_FROM` positions on, a
    compiled kernel runs chunks of positions on numba's threads (each chunk writes its own rows and
    its own status, combined after the loop).
    """

    targets: tuple[str, ...]
    kinds: tuple[Kind, ...]
    columns: tuple[slice | int, ...]
    width: int
    source: str
    function: Callable[..., int]
    compiled: bool
    parallel: Callable[..., int] | None = None
    #: angle outputs computed after the loop: (column, column of the x arguments, angle
    #: subtracted); the loop leaves y in the column and x in the column of ``xs``
    deferred: tuple[tuple[int, int, float], ...] = ()

    def run(self, phi: np.ndarray, tolerance: float = math.inf, store: bool = True
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
        """Evaluate at φ (rad, float64, 1-D): the (N, width) block of outputs, the (N, targets)
        relative estimates (stored only when ``store``; else an unused (1, targets) array), the
        cannot-build mask and the status bits."""
        n = phi.shape[0]
        # column by column (Fortran order): each result is one contiguous array
        block = np.empty((n, self.width), order="F")
        xs = np.empty((n, len(self.deferred)), order="F")
        rel = np.empty((n if store else 1, len(self.targets)))
        bad = np.empty(n, dtype=np.bool_)
        if self.parallel is not None and n >= PARALLEL_FROM and spare_cores() >= 1.5:
            import numba

            # dynamic scheduling, one chunk at a time: a thread that shares its core with another
            # process takes fewer chunks (set from here: inside, it would keep numba from caching)
            previous = numba.set_parallel_chunksize(1)
            try:
                status = self.parallel(phi, tolerance, block, xs, rel, bad, store, CHUNK)
            finally:
                numba.set_parallel_chunksize(previous)
        else:
            status = self.function(phi, tolerance, block, xs, rel, bad, store)
        if n == 1 and self.deferred:    # one position (the API's common call): one ufunc call
            cols, js, subtracted = self._deferred_arrays
            row = block[0]
            row[cols] = np.arctan2(row[cols], xs[0, js]) - subtracted
        else:
            for col, j, minus in self.deferred:
                angle = block[:, col]
                np.arctan2(angle, xs[:, j], out=angle)
                if minus != 0.0:
                    angle -= minus
        return block, rel, bad, int(status)

    @functools.cached_property
    def _deferred_arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The deferred angles as index arrays (columns, x columns, angles subtracted)."""
        cols, js, minus = zip(*self.deferred, strict=True)
        return np.array(cols), np.array(js), np.array(minus, dtype=float)

    def __call__(self, phi: np.ndarray) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray],
                                                   np.ndarray]:
        """Evaluate at crank angles φ (rad); return (values, relative estimates, cannot-build
        mask)."""
        phi = np.ascontiguousarray(np.atleast_1d(np.asarray(phi, dtype=np.float64)))
        block, rel, bad, _ = self.run(phi)
        block.flags.writeable = False
        values = {sid: block[:, col] for sid, col in zip(self.targets, self.columns)}
        estimates = {sid: rel[:, j] for j, sid in enumerate(self.targets)}
        return values, estimates, bad


#: status bits of a kernel run
CANNOT_TRUST = 1
OVER_TOLERANCE = 2


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
#: ``#@typed``: the loops, compiled once for the one signature every caller uses (without it a
#: call with a constant argument, ``store`` or ``lo = 0``, would compile a loop once more)
_TYPED = ("@numba.njit('int64(float64[::1], float64, float64[:, :], float64[:, :], "
          "float64[:, ::1], boolean[::1], boolean, int64, int64)', cache=True, "
          "error_model='numpy')")


def numba_source(source: str) -> str:
    """The generated source as numba compiles it: ``#@jit`` / ``#@typed`` / ``#@parallel``
    markers become decorators and ``prange`` numba's parallel range."""
    return (source.replace("#@jit\n", _JIT + "\n").replace("#@typed\n", _TYPED + "\n")
            .replace("#@parallel\n", _PARALLEL + "\n")
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
    module = sys.modules.get(name)
    if module is None:
        # registered before it runs: its typed loops compile (or load from the cache) as the
        # module executes, and numba finds their globals through sys.modules
        module = sys.modules[name] = importlib.util.module_from_spec(spec)
        try:
            spec.loader.exec_module(module)
        except BaseException:
            del sys.modules[name]
            raise
    return {k: getattr(module, k) for k in ("kernel", "kernel_parallel")}, True
