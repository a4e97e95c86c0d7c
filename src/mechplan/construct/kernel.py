"""The compiled construction: one straight-line function per requested output set.

From the ordered steps that the requested outputs need (and nothing else), generate the source of
one function that evaluates them for one position in scalar arithmetic — the same formulas, in the
same order of operations, as the vectorised evaluators — looped over the positions, together with
each output's error estimate and a mask of positions that cannot be built. With numba installed
(``pip install mechplan[fast]``) the function is JIT-compiled and cached on disk across processes;
without it the numpy path is used (:func:`compile_kernel` raises :class:`KernelUnavailable`, and
:func:`evaluate_fast` falls back).

Only the kinematic operations have scalar forms (``_OPS``); a construction whose outputs need a
step without one — a force step, or a new operation — raises :class:`KernelUnsupported` and is
evaluated by the numpy path. A step's error lever is its spec's (``OpSpec.lever_of``), as in
``construct/estimate.py``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

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
from .ops import Op, OpSpec
from .step import Kind, Step
from .validity import MAX_CONDITION


def _f(x: Any) -> str:
    """A float literal that reads back to the same binary value."""
    x = float(x)
    if math.isnan(x):
        return "NAN"
    if math.isinf(x):
        return "INF" if x > 0 else "(-INF)"
    return repr(x)


class _Gen:
    """Source lines of the loop body, step by step, in three parts: ``values`` (what the
    evaluators compute), ``checks`` (the product of the divisors below 1 that the estimates are
    divided by, from which a bound of every estimate follows: see :func:`kernel_source`) and
    ``estimates`` (every step's error estimate, evaluated only where the bound does not decide).
    """

    def __init__(self, c: Construction, length: float) -> None:
        self.c = c
        self.idx: dict[str, int] = {}
        self.values: list[str] = []
        self.checks: list[str] = []
        self.estimates: list[str] = []
        self.length = length
        self.distances: dict[tuple[str, str], str] = {}
        self.squares: dict[tuple[str, str], str] = {}
        self.shared: dict[tuple[str, ...], str] = {}

    def name(self, sid: str) -> str:
        return f"v{self.idx[sid]}"

    def pt(self, sid: str) -> tuple[str, str]:
        n = self.name(sid)
        return f"{n}x", f"{n}y"

    def line(self, sid: str) -> tuple[str, str, str, str]:
        n = self.name(sid)
        return f"{n}px", f"{n}py", f"{n}ux", f"{n}uy"

    def err(self, sid: str) -> str:
        return f"e{self.idx[sid]}"

    def _key(self, a: str, b: str) -> tuple[str, str]:
        return (a, b) if a < b else (b, a)

    def distance(self, a: str, b: str) -> str:
        """|b − a| over the mechanism's length, computed once per pair of points.

        An error estimate, not a value: like the numpy path's estimates it is √(dx² + dy²),
        which needs no call of hypot.
        """
        key = self._key(a, b)
        name = self.distances.get(key)
        if name is None:
            name = self.distances[key] = f"_l{len(self.distances)}"
            (ax, ay), (bx, by) = self.pt(a), self.pt(b)
            self.estimates.extend((
                f"_ex = {bx} - {ax}", f"_ey = {by} - {ay}",
                f"{name} = math.sqrt(_ex * _ex + _ey * _ey) / {_f(self.length)}"))
        return name

    def square(self, a: str, b: str) -> str:
        """(|b − a| over the mechanism's length)², once per pair (for the checks)."""
        key = self._key(a, b)
        name = self.squares.get(key)
        if name is None:
            name = self.squares[key] = f"_m{len(self.squares)}"
            (ax, ay), (bx, by) = self.pt(a), self.pt(b)
            inverse = _f(1.0 / (self.length * self.length))
            self.checks.extend((f"_ex = {bx} - {ax}", f"_ey = {by} - {ay}",
                                f"{name} = (_ex * _ex + _ey * _ey) * {inverse}"))
        return name

    def emit(self, *lines: str) -> None:
        """Lines that compute values."""
        self.values.extend(lines)

    def once(self, key: tuple[str, ...], lines: Callable[[str], Sequence[str]]) -> str:
        """The name of a value several steps use (the unit normal of a link, a similarity
        ratio, |r|²): its ``lines(name)`` are emitted the first time only, by the same
        expression the steps computed each, so every value stays bit for bit the same."""
        name = self.shared.get(key)
        if name is None:
            name = self.shared[key] = f"_k{len(self.shared)}"
            self.emit(*lines(name))
        return name

    def step(self, s: Step) -> None:
        self.idx[s.id] = len(self.idx)
        gen = _OPS.get(s.op)
        if gen is None:
            raise KernelUnsupported(f"no scalar form for the operation {s.op.value}")
        n = self.name(s.id)
        sine = gen(self, s, n)
        e = self.err(s.id)
        if not s.inputs:
            self.estimates.append(f"{e} = U")
            return
        # max(a + U, b + U) = max(a, b) + U exactly (rounding is monotonic)
        terms = [self.err(i) for i in dict.fromkeys(s.inputs)]
        best = terms[0]
        for t in terms[1:]:
            best = f"max({best}, {t})"
        self.estimates.append(f"{e} = {best} + U")
        pair = s.op.lever_of(s)      # the spec's lever, as the numpy estimate reads it
        if pair is not None:
            self.estimates.append(f"{e} = _div({e}, {self.distance(*pair)})")
            m = self.square(*pair)
            self.checks.append(f"_qa = _qa * _below1({m})")
        if sine is not None:
            self.estimates.append(f"{e} = _div({e}, {sine})")
            self.checks.append(f"_qs = _qs * _below1({sine})")


# -- scalar forms: each mirrors the vectorised evaluator in construct/ops.py ------------------
Gen = Callable[[_Gen, Step, str], str | None]


def _crank(g: _Gen, s: Step, n: str) -> None:
    g.emit(f"{n} = REF + SENSE * phi[i]")


def _fixed(g: _Gen, s: Step, n: str) -> None:
    x, y = s.param("xy")
    g.emit(f"{n}x = {_f(x)}", f"{n}y = {_f(y)}")


def _constant(g: _Gen, s: Step, n: str) -> None:
    g.emit(f"{n} = {_f(s.param('value'))}")


def _pole(g: _Gen, s: Step, n: str) -> None:
    g.emit(f"{n}x = 0.0", f"{n}y = 0.0")


def _polar(g: _Gen, s: Step, n: str) -> None:
    (cx, cy), a = g.pt(s.inputs[0]), g.name(s.inputs[1])
    length, offset = _f(s.param("length")), _f(s.param("offset", 0.0))
    g.emit(f"_a = {a} + {offset}", f"{n}x = {cx} + {length} * math.cos(_a)",
           f"{n}y = {cy} + {length} * math.sin(_a)")


def _angle_of(g: _Gen, s: Step, n: str) -> None:
    (px, py), (qx, qy) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    g.emit(f"{n} = math.atan2({qy} - {py}, {qx} - {px}) - {_f(s.param('minus', 0.0))}")


def _angle_plus(g: _Gen, s: Step, n: str) -> None:
    g.emit(f"{n} = {g.name(s.inputs[0])} + {_f(s.param('delta'))}")


def _circle_circle(g: _Gen, s: Step, n: str) -> str:
    (ax, ay), (bx, by) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    r1, r2, sigma = _f(s.param("r1")), _f(s.param("r2")), _f(s.param("sigma"))
    g.emit(f"_dx = {bx} - {ax}", f"_dy = {by} - {ay}", "_d = _hyp(_dx, _dy)",
           f"_gap = max(_d - ({r1} + {r2}), abs({r1} - {r2}) - _d)",
           f"_a = _div({r1} * {r1} - {r2} * {r2} + _d * _d, 2.0 * _d)",
           f"_h2 = _div((({r1} + {r2}) ** 2 - _d * _d) * (_d * _d - ({r1} - {r2}) ** 2), "
           "4.0 * _d * _d)",
           "_h = _height(_h2, _gap)",
           "_ux = _div(_dx, _d)", "_uy = _div(_dy, _d)", f"_sh = {sigma} * _h",
           f"{n}x = {ax} + _a * _ux - _sh * _uy", f"{n}y = {ay} + _a * _uy + _sh * _ux",
           f"sn{n} = abs(_div(_h * _d, {r1} * {r2}))",
           f"bad_i = bad_i | (not (_gap <= 0.0)) | (sn{n} < MIN_SINE)")
    return f"sn{n}"


def _circle_line_core(g: _Gen, n: str, cx: str, cy: str, r: str, px: str, py: str, ux: str,
                      uy: str, sigma: str) -> None:
    g.emit(f"_w = {ux} * ({cy} - {py}) - {uy} * ({cx} - {px})",
           f"_along = ({cx} - {px}) * {ux} + ({cy} - {py}) * {uy}",
           f"_gap = abs(_w) - {r}", f"_h2 = ({r} - _w) * ({r} + _w)",
           "_h = _height(_h2, _gap)", f"_sh = {sigma} * _h",
           f"_fx = {px} + _along * {ux}", f"_fy = {py} + _along * {uy}",
           f"{n}x = _fx + _sh * {ux}", f"{n}y = _fy + _sh * {uy}",
           f"sn{n} = abs(_div(_h, {r}))",
           f"bad_i = bad_i | (not (_gap <= 0.0)) | (sn{n} < MIN_SINE)")


def _circle_line(g: _Gen, s: Step, n: str) -> str:
    (cx, cy), (px, py, ux, uy) = g.pt(s.inputs[0]), g.line(s.inputs[1])
    _circle_line_core(g, n, cx, cy, _f(s.param("r")), px, py, ux, uy, _f(s.param("sigma")))
    return f"sn{n}"


def _line_line(g: _Gen, s: Step, n: str) -> str:
    (ax, ay, au, av), (bx, by, bu, bv) = g.line(s.inputs[0]), g.line(s.inputs[1])
    g.emit(f"_s = {au} * {bv} - {av} * {bu}",
           f"_t = _div_nz(({bx} - {ax}) * {bv} - ({by} - {ay}) * {bu}, _s)",
           f"{n}x = {ax} + _t * {au}", f"{n}y = {ay} + _t * {av}", f"sn{n} = abs(_s)",
           f"bad_i = bad_i | (not (sn{n} >= MIN_SINE))")
    return f"sn{n}"


def _locus_line(g: _Gen, s: Step, n: str) -> None:
    (bx, by) = g.pt(s.inputs[0])
    ox, oy = (_f(v) for v in s.param("offset"))
    dir_angle = float(s.param("dir_angle"))
    if len(s.inputs) == 1:
        # rotate(offset, 0) and direction(0 + dir_angle), as the vectorised path computes them
        g.emit(f"{n}px = {bx} + (1.0 * {ox} - 0.0 * {oy})",
               f"{n}py = {by} + (0.0 * {ox} + 1.0 * {oy})",
               f"{n}ux = math.cos(0.0 + {_f(dir_angle)})",
               f"{n}uy = math.sin(0.0 + {_f(dir_angle)})")
        return
    th = g.name(s.inputs[1])
    g.emit(f"_c = math.cos({th})", f"_s = math.sin({th})",
           f"{n}px = {bx} + (_c * {ox} - _s * {oy})", f"{n}py = {by} + (_s * {ox} + _c * {oy})")
    if dir_angle == 0.0:
        g.emit(f"{n}ux = _c", f"{n}uy = _s")
    else:
        g.emit(f"{n}ux = math.cos({th} + {_f(dir_angle)})",
               f"{n}uy = math.sin({th} + {_f(dir_angle)})")


def _carrier_angle(g: _Gen, s: Step, n: str) -> str:
    (cx, cy), (px, py) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    qx, qy = (_f(v) for v in s.param("q0"))
    g.emit(f"_rx = {px} - {cx}", f"_ry = {py} - {cy}", "_rad = _hyp(_rx, _ry)",
           f"_dux = math.cos({_f(s.param('dir_angle'))})",
           f"_duy = math.sin({_f(s.param('dir_angle'))})")
    _circle_line_core(g, f"_hit{n}", "0.0", "0.0", "_rad", qx, qy, "_dux", "_duy",
                      _f(s.param("sigma")))
    g.emit(f"{n} = math.atan2(_ry, _rx) - math.atan2(_hit{n}y, _hit{n}x)", f"sn{n} = sn_hit{n}")
    return f"sn{n}"


def _place(g: _Gen, s: Step, n: str) -> None:
    (ox, oy), a = g.pt(s.inputs[0]), g.name(s.inputs[1])
    vx, vy = (_f(v) for v in s.param("offset"))
    g.emit(f"_c = math.cos({a})", f"_s = math.sin({a})",
           f"{n}x = {ox} + (_c * {vx} - _s * {vy})", f"{n}y = {oy} + (_s * {vx} + _c * {vy})")


def _similar_position(g: _Gen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    z = complex(s.param("z"))
    g.emit(f"_z = complex({ax}, {ay}) + (complex({bx}, {by}) - complex({ax}, {ay})) * "
           f"complex({_f(z.real)}, {_f(z.imag)})", f"{n}x = _z.real", f"{n}y = _z.imag")


def _similar_image(g: _Gen, s: Step, n: str) -> None:
    (ax, ay), (bx, by), (pax, pay), (pbx, pby), (pxx, pxy) = (g.pt(i) for i in s.inputs)
    ratio = g.once(("ratio", *s.inputs[2:]), lambda r: (
        f"_q = complex({pbx}, {pby}) - complex({pax}, {pay})",
        f"{r} = _cdiv(complex({pxx}, {pxy}) - complex({pax}, {pay}), _q)"))
    g.emit(f"_z = complex({ax}, {ay}) + (complex({bx}, {by}) - complex({ax}, {ay})) * {ratio}",
           f"{n}x = _z.real", f"{n}y = _z.imag")


def _rigid_velocity(g: _Gen, s: Step, n: str) -> None:
    (ox, oy), w, (pox, poy), (pxx, pxy) = (g.pt(s.inputs[0]), g.name(s.inputs[1]),
                                           g.pt(s.inputs[2]), g.pt(s.inputs[3]))
    g.emit(f"{n}x = {ox} + {w} * (-({pxy} - {poy}))", f"{n}y = {oy} + {w} * ({pxx} - {pox})")


def _rigid_acceleration(g: _Gen, s: Step, n: str) -> None:
    (ox, oy), w, e, (pox, poy), (pxx, pxy) = (g.pt(s.inputs[0]), g.name(s.inputs[1]),
                                              g.name(s.inputs[2]), g.pt(s.inputs[3]),
                                              g.pt(s.inputs[4]))
    g.emit(f"_rx = {pxx} - {pox}", f"_ry = {pxy} - {poy}", f"_w2 = {w} * {w}",
           f"{n}x = {ox} + {e} * (-_ry) - _w2 * _rx", f"{n}y = {oy} + {e} * _rx - _w2 * _ry")


def _drive_velocity(g: _Gen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    w = _f(s.param("omega"))
    g.emit(f"{n}x = {w} * (-({by} - {ay}))", f"{n}y = {w} * ({bx} - {ax})")


def _drive_acceleration(g: _Gen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    w, e = _f(s.param("omega")), _f(s.param("epsilon", 0.0))
    g.emit(f"_rx = {bx} - {ax}", f"_ry = {by} - {ay}",
           f"{n}x = {e} * (-_ry) - {w} * {w} * _rx", f"{n}y = {e} * _rx - {w} * {w} * _ry")


def _line_perp(g: _Gen, s: Step, n: str) -> None:
    (tx, ty), (px, py), (qx, qy) = (g.pt(i) for i in s.inputs)
    unit = g.once(("perp", *s.inputs[1:]), lambda u: (
        f"_vx = -({qy} - {py})", f"_vy = {qx} - {px}", "_nn = _hyp(_vx, _vy)",
        f"{u}x = _div(_vx, _nn)", f"{u}y = _div(_vy, _nn)"))
    g.emit(f"{n}px = {tx}", f"{n}py = {ty}", f"{n}ux = {unit}x", f"{n}uy = {unit}y")


def _line_parallel(g: _Gen, s: Step, n: str) -> None:
    (tx, ty), (_, _, ux, uy) = g.pt(s.inputs[0]), g.line(s.inputs[1])
    g.emit(f"{n}px = {tx}", f"{n}py = {ty}", f"{n}ux = {ux}", f"{n}uy = {uy}")


def _omega(g: _Gen, s: Step, n: str) -> None:
    (px, py), (qx, qy), (ax, ay), (bx, by) = (g.pt(i) for i in s.inputs)
    g.emit(f"_rx = {qx} - {px}", f"_ry = {qy} - {py}")
    rr = g.once(("rr", *s.inputs[:2]), lambda r: (f"{r} = _rx * _rx + _ry * _ry",))
    g.emit(f"_dx = {bx} - {ax}", f"_dy = {by} - {ay}", f"{n} = _div(_rx * _dy - _ry * _dx, {rr})")


_epsilon = _omega      # ε = (r × (a_q − n)) / r·r has the form of ω = (r × (v_q − v_p)) / r·r


def _normal(g: _Gen, s: Step, n: str) -> None:
    (ax, ay), w, (px, py), (qx, qy) = (g.pt(s.inputs[0]), g.name(s.inputs[1]), g.pt(s.inputs[2]),
                                       g.pt(s.inputs[3]))
    g.emit(f"_w2 = {w} * {w}", f"{n}x = {ax} - _w2 * ({qx} - {px})",
           f"{n}y = {ay} - _w2 * ({qy} - {py})")


def _coriolis(g: _Gen, s: Step, n: str) -> None:
    (sx, sy), w, (fx, fy), (tx, ty) = (g.pt(s.inputs[0]), g.name(s.inputs[1]), g.pt(s.inputs[2]),
                                       g.pt(s.inputs[3]))
    g.emit(f"_k = 2.0 * {w}", f"{n}x = {sx} + _k * (-({ty} - {fy}))",
           f"{n}y = {sy} + _k * ({tx} - {fx})")


def _copy(g: _Gen, s: Step, n: str) -> None:
    src = s.inputs[0]
    kind = s.kind
    if kind is Kind.POINT:
        x, y = g.pt(src)
        g.emit(f"{n}x = {x}", f"{n}y = {y}")
    else:
        g.emit(f"{n} = {g.name(src)}")


def _difference(g: _Gen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.inputs[0]), g.pt(s.inputs[1])
    g.emit(f"{n}x = {bx} - {ax}", f"{n}y = {by} - {ay}")


#: the scalar form of each operation that has one (an operation without one makes
#: :func:`compile_kernel` raise :class:`KernelUnsupported`: the caller uses the numpy path)
_OPS: dict[OpSpec, Gen] = {
    Op.CRANK_ANGLE: _crank, Op.FIXED_POINT: _fixed, Op.CONSTANT: _constant, Op.POLE: _pole,
    Op.POLAR_POINT: _polar, Op.ANGLE_OF: _angle_of, Op.ANGLE_PLUS: _angle_plus,
    Op.CIRCLE_CIRCLE: _circle_circle, Op.CIRCLE_LINE: _circle_line, Op.LINE_LINE: _line_line,
    Op.LOCUS_LINE: _locus_line, Op.CARRIER_ANGLE: _carrier_angle, Op.PLACE: _place,
    Op.SIMILAR_POSITION: _similar_position, Op.SIMILAR_IMAGE: _similar_image,
    Op.RIGID_VELOCITY: _rigid_velocity, Op.RIGID_ACCELERATION: _rigid_acceleration,
    Op.DRIVE_VELOCITY: _drive_velocity, Op.DRIVE_ACCELERATION: _drive_acceleration,
    Op.LINE_PERP: _line_perp, Op.LINE_PARALLEL: _line_parallel, Op.OMEGA: _omega,
    Op.EPSILON: _epsilon, Op.NORMAL: _normal, Op.CORIOLIS: _coriolis, Op.COPY: _copy,
    Op.DIFFERENCE: _difference,
}



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
    g = _Gen(c, length_scale(c))
    for sid in c.ancestors(targets):
        g.step(c[sid])
    estimates = list(g.estimates)
    sizes = plan_sizes(c)
    columns, _ = _columns([c[sid].kind for sid in targets])
    values: list[str] = []
    writes: list[str] = []
    for j, (sid, col) in enumerate(zip(targets, columns)):
        scale = scale_of(c[sid], sizes)
        if isinstance(col, slice):
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
            estimates.append(f"_r = _div({g.err(sid)}, max({size} / {_f(scale)}, 1.0))")
        else:
            estimates.append(f"_r = {g.err(sid)}")
        estimates += ["if store:", f"    rel[i, {j}] = _r", f"if not (_r < {_f(UNBOUNDED)}):",
                      f"    status |= {CANNOT_TRUST}", "if _r > tol:",
                      f"    status |= {OVER_TOLERANCE}"]
    # a NaN (or ±inf) value: not shown clean, the estimates decide
    checks = ["_qa = 1.0", "_qs = 1.0", *g.checks, f"_chk = {tree_sum(values)} * 0.0"]
    clean = "NU2 <= _thr2 * (_qa * (_qs * _qs)) + _chk"
    start = ["status = 0", "_thr = tol if tol < 0.5 else 0.5",
             "_thr2 = _thr * _thr if _thr > 0.0 else -1.0"]
    body = ["#@typed", "def _body(phi, tol, out, rel, bad, store, lo, hi):", *indent(start, 1),
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
    quick = ["", "", "#@typed", "def _quick(phi, tol, out, rel, bad, store, lo, hi):", *indent(start, 1),
             "    redo = np.empty(hi - lo, dtype=np.int64)", "    redo_n = 0",
             f"    for i in range(lo, hi, {LANES}):",
             *indent([*lanes, *interleave(["bad_i = False", *g.values],
                                           [*writes, *checks, *decide])]),
             "    for k in range(redo_n):",
             "        status |= _body(phi, tol, out, rel, bad, store, redo[k], redo[k] + 1)",
             "    return status"]
    u = float(np.finfo(np.float64).eps * ROUNDINGS_PER_STEP)
    drive = c.drive
    head = (HELPERS + f"REF = {_f(drive.ref)}\nSENSE = {_f(drive.sense)}\nU = {_f(u)}\n"
            f"NU2 = {_f((2.0 * len(g.idx) * u) ** 2)}\n"
            f"MIN_SINE = {_f(1.0 / MAX_CONDITION)}\n\n\n")
    return head + "\n".join(body + quick) + "\n" + DRIVERS


def compile_kernel(c: Construction, targets: Sequence[str], jit: bool = True) -> Kernel:
    """Compile the kernel of ``targets``; ``jit=False`` runs the generated code as plain Python."""
    targets = tuple(targets)
    source = kernel_source(c, targets)
    functions, compiled = load(source, jit)
    kinds = tuple(c[sid].kind for sid in targets)
    columns, width = _columns(kinds)
    return Kernel(targets, kinds, columns, width, source, functions["kernel"], compiled,
                  functions["kernel_parallel"] if compiled else None)


__all__ = ["CANNOT_TRUST", "CHUNK", "OVER_TOLERANCE", "PARALLEL_FROM", "Kernel",
           "KernelUnavailable", "KernelUnsupported", "compile_kernel", "kernel_source"]
