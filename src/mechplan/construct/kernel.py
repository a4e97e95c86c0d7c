"""The compiled construction: one straight-line function per requested output set.

From the ordered steps that the requested outputs need (and nothing else), generate the source of
one function that evaluates them for one position in scalar arithmetic — the same formulas, in the
same order of operations, as the vectorised evaluators — looped over the positions, together with
each output's error estimate and a mask of positions that cannot be built. With numba installed
(``pip install mechplan[fast]``) the function is JIT-compiled and cached on disk across processes;
without it the numpy path is used (:func:`compile_kernel` raises :class:`KernelUnavailable`, and
:func:`evaluate_fast` falls back).

Two loops are generated: ``_body`` (one position at a time, values and estimates) and ``_quick``
(``LANES`` positions side by side, values and a cheap bound only; a position the bound does not
clear is handed to ``_body``). A value several steps use is computed once (``ScalarGen.once``); an
angle output is left as its atan2 arguments and taken by ``np.arctan2`` after the loop
(``Kernel.deferred``). See ``kernel_load.interleave`` for the lanes.

Only the kinematic operations have scalar forms (``kernel_scalar.SCALAR_FORMS``); a
construction whose outputs need a step without one — a force step, or a new operation — raises
:class:`KernelUnsupported` and is evaluated by the numpy path. A step's error lever is its
spec's (``OpSpec.lever_of``), as in ``construct/estimate.py``.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .estimate import ROUNDINGS_PER_STEP, UNBOUNDED, length_scale, plan_sizes, scale_of
from .graph import Construction
from .kernel_load import (
    CANNOT_TRUST,
    CHUNK,
    DRIVERS,
    HELPERS,
    LANES,
    OVER_TOLERANCE,
    PARALLEL_FROM,
    Kernel,
    KernelUnavailable,
    KernelUnsupported,
    indent,
    interleave,
    load,
    tree_sum,
)
from .kernel_scalar import ScalarGen, literal
from .step import Kind
from .validity import MAX_CONDITION


def _columns(kinds: Sequence[Kind]) -> tuple[tuple[slice | int, ...], int]:
    cols: list[slice | int] = []
    at = 0
    for k in kinds:
        if k is Kind.POINT:
            cols.append(slice(at, at + 2))
            at += 2
        else:
            cols.append(at)
            at += 1
    return tuple(cols), at


def kernel_source(c: Construction, targets: Sequence[str]) -> str:
    """The source of the kernel that evaluates ``targets``: see :func:`_generate`."""
    return _generate(c, targets)[0]


def _generate(c: Construction, targets: Sequence[str]
              ) -> tuple[str, tuple[tuple[int, int, float], ...]]:
    """Generate the source of the kernel that evaluates ``targets`` (and only their ancestors).

    Each position's values are computed; the estimates only when stored or when a cheap bound
    cannot show them small. A step's estimate is (the largest of its inputs' + U) divided by its
    divisors (distances over the length, sines), so it is at most depth·U over the product of the
    divisors below 1 along its ancestors, and every estimate is at most B = steps·U / Π min(1,
    divisor) over all of them. A position where 2·B is at most both the tolerance and ½ (and
    every value is finite) has no flag; at any other the estimates are evaluated and decide —
    the same status bits as evaluating them everywhere, for fewer operations.
    """
    for sid in targets:
        if c[sid].kind is Kind.LINE:
            raise KernelUnavailable(f"step {sid} is a line; kernels return points and scalars")
    g = ScalarGen(c, length_scale(c))
    for sid in c.ancestors(targets):
        g.step(c[sid])
    estimates = list(g.estimates)
    sizes = plan_sizes(c)
    columns, _ = _columns([c[sid].kind for sid in targets])
    values: list[str] = []
    writes: list[str] = []
    deferred = _deferred(g, targets, columns)
    for j, (sid, col) in enumerate(zip(targets, columns)):
        scale = scale_of(c[sid], sizes)
        if sid in deferred:
            # an angle output: its atan2 arguments, taken by np.arctan2 after the loop
            y, x, _ = g.arctan[sid]
            writes += [f"out[i, {col}] = {y}", f"xs[i, {deferred[sid][1]}] = {x}"]
            size = f"abs({g.name(sid)})"
            values += [y, x]
        elif isinstance(col, slice):
            x, y = g.pt(sid)
            writes += [f"out[i, {col.start}] = {x}", f"out[i, {col.start + 1}] = {y}"]
            size = f"math.sqrt({x} * {x} + {y} * {y})"
            values += [x, y]
        else:
            writes += [f"out[i, {col}] = {g.name(sid)}"]
            size = f"abs({g.name(sid)})"
            values.append(g.name(sid))
        if scale > 0.0:
            # measured against the larger of the plan's scale and the result's own size
            estimates.append(f"_r = _div({g.err(sid)}, max({size} / {literal(scale)}, 1.0))")
        else:
            estimates.append(f"_r = {g.err(sid)}")
        estimates += ["if store:", f"    rel[i, {j}] = _r", f"if not (_r < {literal(UNBOUNDED)}):",
                      f"    status |= {CANNOT_TRUST}", "if _r > tol:",
                      f"    status |= {OVER_TOLERANCE}"]
    # a NaN (or ±inf) value: not shown clean, the estimates decide
    checks = ["_qa = 1.0", "_qs = 1.0", *g.checks, f"_chk = {tree_sum(values)} * 0.0"]
    clean = "NU2 <= _thr2 * (_qa * (_qs * _qs)) + _chk"
    start = ["status = 0", "_thr = tol if tol < 0.5 else 0.5",
             "_thr2 = _thr * _thr if _thr > 0.0 else -1.0"]
    body = ["#@typed", "def _body(phi, tol, out, xs, rel, bad, store, lo, hi):",
            *indent(start, 1),
            "    for i in range(lo, hi):",
            *indent(["bad_i = False", *g.values, *writes, *checks, f"if store or not ({clean}):"]),
            *indent(estimates, 3),
            *indent(["bad[i] = bad_i", "if bad_i:", f"    status |= {CANNOT_TRUST}"]),
            "    return status"]
    # the quick loop: LANES positions side by side; the positions the bound does not show clean
    # are evaluated again after the loop, one by one, by _body (which computes their estimates)
    decide = [f"if {clean}:", "    bad[i] = bad_i", "    if bad_i:",
              f"        status |= {CANNOT_TRUST}",
              "elif redo_n == 0 or redo[redo_n - 1] != i:", "    redo[redo_n] = i",
              "    redo_n += 1"]
    lanes = [f"i{k} = i + {k} if i + {k} < hi else hi - 1" for k in range(LANES)]
    quick = ["", "", "#@typed", "def _quick(phi, tol, out, xs, rel, bad, store, lo, hi):",
             *indent(start, 1),
             "    redo = np.empty(hi - lo, dtype=np.int64)", "    redo_n = 0",
             f"    for i in range(lo, hi, {LANES}):",
             *indent([*lanes, *interleave(["bad_i = False", *g.values],
                                           [*writes, *checks, *decide])]),
             "    for k in range(redo_n):",
             "        status |= _body(phi, tol, out, xs, rel, bad, store, redo[k], redo[k] + 1)",
             "    return status"]
    u = float(np.finfo(np.float64).eps * ROUNDINGS_PER_STEP)
    drive = c.drive
    head = (HELPERS + f"REF = {literal(drive.ref)}\nSENSE = {literal(drive.sense)}\n"
            f"U = {literal(u)}\n"
            f"NU2 = {literal((2.0 * len(g.idx) * u) ** 2)}\n"
            f"MIN_SINE = {literal(1.0 / MAX_CONDITION)}\n\n\n")
    return head + "\n".join(body + quick) + "\n" + DRIVERS, tuple(deferred.values())


def compile_kernel(c: Construction, targets: Sequence[str], jit: bool = True) -> Kernel:
    """Compile the kernel of ``targets``; ``jit=False`` runs the generated code as plain Python."""
    targets = tuple(targets)
    source, deferred = _generate(c, targets)
    functions, compiled = load(source, jit)
    kinds = tuple(c[sid].kind for sid in targets)
    columns, width = _columns(kinds)
    return Kernel(targets, kinds, columns, width, source, functions["kernel"], compiled,
                  functions["kernel_parallel"] if compiled else None, deferred)


def _deferred(g: ScalarGen, targets: Sequence[str], columns: Sequence[slice | int]
              ) -> dict[str, tuple[int, int, float]]:
    """The angle outputs whose atan2 is left to numpy after the loop (vectorised: a fraction of
    the scalar call's time): target → (its column, its column of the x arguments, the angle
    subtracted)."""
    out: dict[str, tuple[int, int, float]] = {}
    for sid, col in zip(targets, columns):
        if sid in g.arctan and isinstance(col, int):
            out[sid] = (col, len(out), g.arctan[sid][2])
    return out


__all__ = ["CANNOT_TRUST", "CHUNK", "OVER_TOLERANCE", "PARALLEL_FROM", "Kernel",
           "KernelUnavailable", "KernelUnsupported", "compile_kernel", "kernel_source"]
