"""The scalar form of each construction operation, as source lines of the fused kernel's loop.

:class:`ScalarGen` collects, step by step, the lines that compute each value (``values``), the
divisors the error estimates are divided by (``checks``) and the estimates themselves
(``estimates``); ``SCALAR_FORMS`` maps an operation's spec to its emitter. Each emitter mirrors
the vectorised evaluator of its operation in ``construct/ops/`` — the same formulas in the same
order of operations — so the kernel's values are the numpy path's.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

from .estimate import plan_sizes
from .graph import Construction
from .kernel_load import KernelUnsupported
from .ops import Op, OpSpec
from .step import Kind, Step


def literal(x: Any) -> str:
    """A float literal that reads back to the same binary value."""
    x = float(x)
    if math.isnan(x):
        return "NAN"
    if math.isinf(x):
        return "INF" if x > 0 else "(-INF)"
    return repr(x)


class ScalarGen:
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
        #: angle steps → the names of their atan2 arguments and the angle subtracted
        self.arctan: dict[str, tuple[str, str, float]] = {}
        #: line steps → the name of their direction's error (rad), as estimate.py's ``turn``
        self.turns: dict[str, str] = {}
        self.sizes = plan_sizes(c)

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
                f"{name} = math.sqrt(_ex * _ex + _ey * _ey) / {literal(self.length)}"))
        return name

    def square(self, a: str, b: str) -> str:
        """(|b − a| over the mechanism's length)², once per pair (for the checks)."""
        key = self._key(a, b)
        name = self.squares.get(key)
        if name is None:
            name = self.squares[key] = f"_m{len(self.squares)}"
            (ax, ay), (bx, by) = self.pt(a), self.pt(b)
            inverse = literal(1.0 / (self.length * self.length))
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
        gen = SCALAR_FORMS.get(s.op)
        if gen is None:
            raise KernelUnsupported(f"no scalar form for the operation {s.op.value}")
        n = self.name(s.id)
        sine = gen(self, s, n)
        e = self.err(s.id)
        if not s.inputs:
            self.estimates.append(f"{e} = U")
            if s.kind is Kind.LINE:
                self._turn(s)
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
        if s.op is Op.LINE_LINE and self.sizes.get(s.plan, 0.0) > 0.0:
            self._far_meet(s, n, e, sine)
        if s.kind is Kind.LINE:
            self._turn(s)

    def _far_meet(self, s: Step, n: str, e: str, sine: str | None) -> None:
        """A meet of two lines far from their points: at least the lines' direction error ×
        its distance over the plan's size ÷ the sine (estimate.py's ``reach``)."""
        size = literal(self.sizes[s.plan])
        reach = []
        for key in ("line1", "line2"):
            px, py, _, _ = self.line(s.input(key))
            reach.append(f"(({n}x - {px}) * ({n}x - {px}) + ({n}y - {py}) * ({n}y - {py}))")
        far = f"_far{self.idx[s.id]}"
        turn = f"max({self.turns[s.input('line1')]}, {self.turns[s.input('line2')]}) + U"
        self.estimates += [
            f"{far} = max(1.0, math.sqrt(max({reach[0]}, {reach[1]})) / {size})",
            f"_t = ({turn}) * {far}",
            *([f"_t = _div(_t, {sine})"] if sine is not None else []),
            f"{e} = max({e}, _t)"]
        square = literal(self.sizes[s.plan] ** 2)
        self.checks.append(f"_qa = _qa * _below1(_div({square}, max({reach[0]}, {reach[1]})))")

    def _turn(self, s: Step) -> None:
        """A line's direction error (rad), as estimate.py's ``_turn_of``."""
        t = self.turns[s.id] = f"t{self.idx[s.id]}"
        if not s.inputs:
            self.estimates.append(f"{t} = {self.err(s.id)}")
            return
        pair = s.op.lever_of(s)
        if pair is not None:
            a, b = (self.err(i) for i in pair)
            self.estimates.append(f"{t} = _div(max({a}, {b}) + U, {self.distance(*pair)})")
            return
        terms = ["U"]
        for i in dict.fromkeys(s.inputs):
            kind = self.c[i].kind
            if kind is Kind.LINE:
                terms.append(f"{self.turns[i]} + U")
            elif kind is not Kind.POINT:
                terms.append(f"{self.err(i)} + U")
        expr = terms[0]
        for term in terms[1:]:
            expr = f"max({expr}, {term})"
        self.estimates.append(f"{t} = {expr}")


# -- scalar forms: each mirrors the vectorised evaluator in construct/ops.py ------------------
Gen = Callable[[ScalarGen, Step, str], str | None]


def _crank(g: ScalarGen, s: Step, n: str) -> None:
    g.emit(f"{n} = REF + SENSE * phi[i]")


def _fixed(g: ScalarGen, s: Step, n: str) -> None:
    x, y = s.param("xy")
    g.emit(f"{n}x = {literal(x)}", f"{n}y = {literal(y)}")


def _constant(g: ScalarGen, s: Step, n: str) -> None:
    g.emit(f"{n} = {literal(s.param('value'))}")


def _pole(g: ScalarGen, s: Step, n: str) -> None:
    g.emit(f"{n}x = 0.0", f"{n}y = 0.0")


def _polar(g: ScalarGen, s: Step, n: str) -> None:
    (cx, cy), a = g.pt(s.input("centre")), g.name(s.input("angle"))
    length, offset = literal(s.param("length")), literal(s.param("offset", 0.0))
    g.emit(f"_a = {a} + {offset}", f"{n}x = {cx} + {length} * math.cos(_a)",
           f"{n}y = {cy} + {length} * math.sin(_a)")


def _angle_of(g: ScalarGen, s: Step, n: str) -> None:
    (px, py), (qx, qy) = g.pt(s.input("start")), g.pt(s.input("end"))
    minus = literal(s.param("minus", 0.0))
    g.emit(f"_ay{n} = {qy} - {py}", f"_ax{n} = {qx} - {px}",
           f"{n} = math.atan2(_ay{n}, _ax{n}) - {minus}")
    g.arctan[s.id] = (f"_ay{n}", f"_ax{n}", float(s.param("minus", 0.0)))


def _angle_plus(g: ScalarGen, s: Step, n: str) -> None:
    g.emit(f"{n} = {g.name(s.input('angle'))} + {literal(s.param('delta'))}")


def _circle_circle(g: ScalarGen, s: Step, n: str) -> str:
    return circle_meet(g, s, n, literal(s.param("r1")), literal(s.param("r2")))


def circle_meet(g: ScalarGen, s: Step, n: str, r1: str, r2: str,
                sine_squared: bool = False,
                centres: tuple[tuple[str, str], tuple[str, str]] | None = None,
                squares: tuple[str, str] | None = None) -> str:
    """Two compass arcs about ``centre1``, ``centre2`` (or the ``centres`` given as source
    expressions) of radii ``r1``, ``r2`` (source expressions) meeting at point ``n`` on the
    step's side; its sine (squared when one radius is driven: the conditioning of a driven
    length, docs/drivers.md). ``squares``: (r1 + r2)² and (r1 − r2)² as given expressions."""
    (ax, ay), (bx, by) = centres or (g.pt(s.input("centre1")), g.pt(s.input("centre2")))
    sigma = literal(s.param("sigma"))
    big, small = squares or (f"({r1} + {r2}) ** 2", f"({r1} - {r2}) ** 2")
    g.emit(f"_dx = {bx} - {ax}", f"_dy = {by} - {ay}", "_d = _hyp(_dx, _dy)",
           f"_gap = max(_d - ({r1} + {r2}), abs({r1} - {r2}) - _d)",
           f"_a = _div({r1} * {r1} - {r2} * {r2} + _d * _d, 2.0 * _d)",
           f"_h2 = _div(({big} - _d * _d) * (_d * _d - {small}), 4.0 * _d * _d)",
           "_h = _height(_h2, _gap)",
           "_ux = _div(_dx, _d)", "_uy = _div(_dy, _d)", f"_sh = {sigma} * _h",
           f"{n}x = {ax} + _a * _ux - _sh * _uy", f"{n}y = {ay} + _a * _uy + _sh * _ux",
           f"sn{n} = abs(_div(_h * _d, {r1} * {r2}))",
           *([f"sn{n} = sn{n} * sn{n}"] if sine_squared else []),
           f"bad_i = bad_i | (not (_gap <= 0.0)) | (sn{n} < MIN_SINE)")
    return f"sn{n}"


def _circle_line_core(g: ScalarGen, n: str, cx: str, cy: str, r: str, px: str, py: str, ux: str,
                      uy: str, sigma: str) -> None:
    g.emit(f"_w = {ux} * ({cy} - {py}) - {uy} * ({cx} - {px})",
           f"_along = ({cx} - {px}) * {ux} + ({cy} - {py}) * {uy}",
           f"_gap = abs(_w) - {r}", f"_h2 = ({r} - _w) * ({r} + _w)",
           "_h = _height(_h2, _gap)", f"_sh = {sigma} * _h",
           f"_fx = {px} + _along * {ux}", f"_fy = {py} + _along * {uy}",
           f"{n}x = _fx + _sh * {ux}", f"{n}y = _fy + _sh * {uy}",
           f"sn{n} = abs(_div(_h, {r}))",
           f"bad_i = bad_i | (not (_gap <= 0.0)) | (sn{n} < MIN_SINE)")


def _circle_line(g: ScalarGen, s: Step, n: str) -> str:
    (cx, cy), (px, py, ux, uy) = g.pt(s.input("centre")), g.line(s.input("guide"))
    _circle_line_core(g, n, cx, cy, literal(s.param("r")), px, py, ux, uy,
                      literal(s.param("sigma")))
    return f"sn{n}"


def _line_line(g: ScalarGen, s: Step, n: str) -> str:
    return line_meet(g, n, g.line(s.input("line1")), g.line(s.input("line2")))


def line_meet(g: ScalarGen, n: str, one: tuple[str, str, str, str],
              two: tuple[str, str, str, str]) -> str:
    """Two lines (point, unit direction: source expressions) meeting at point ``n``; its sine."""
    (ax, ay, au, av), (bx, by, bu, bv) = one, two
    g.emit(f"_s = {au} * {bv} - {av} * {bu}",
           f"_t = _div_nz(({bx} - {ax}) * {bv} - ({by} - {ay}) * {bu}, _s)",
           f"{n}x = {ax} + _t * {au}", f"{n}y = {ay} + _t * {av}", f"sn{n} = abs(_s)",
           f"bad_i = bad_i | (not (sn{n} >= MIN_SINE))")
    return f"sn{n}"


def _locus_line(g: ScalarGen, s: Step, n: str) -> None:
    (bx, by) = g.pt(s.input("base"))
    angle = s.rest()   # none: a guide of the frame
    ox, oy = (literal(v) for v in s.param("offset"))
    dir_angle = float(s.param("dir_angle"))
    if not angle:
        # rotate(offset, 0) and direction(0 + dir_angle), as the vectorised path computes them
        g.emit(f"{n}px = {bx} + (1.0 * {ox} - 0.0 * {oy})",
               f"{n}py = {by} + (0.0 * {ox} + 1.0 * {oy})",
               f"{n}ux = math.cos(0.0 + {literal(dir_angle)})",
               f"{n}uy = math.sin(0.0 + {literal(dir_angle)})")
        return
    th = g.name(angle[0])
    g.emit(f"_c = math.cos({th})", f"_s = math.sin({th})",
           f"{n}px = {bx} + (_c * {ox} - _s * {oy})", f"{n}py = {by} + (_s * {ox} + _c * {oy})")
    if dir_angle == 0.0:
        g.emit(f"{n}ux = _c", f"{n}uy = _s")
    else:
        g.emit(f"{n}ux = math.cos({th} + {literal(dir_angle)})",
               f"{n}uy = math.sin({th} + {literal(dir_angle)})")


def _carrier_angle(g: ScalarGen, s: Step, n: str) -> str:
    (cx, cy), (px, py) = g.pt(s.input("pivot")), g.pt(s.input("slider"))
    qx, qy = (literal(v) for v in s.param("q0"))
    g.emit(f"_rx = {px} - {cx}", f"_ry = {py} - {cy}", "_rad = _hyp(_rx, _ry)",
           f"_dux = math.cos({literal(s.param('dir_angle'))})",
           f"_duy = math.sin({literal(s.param('dir_angle'))})")
    _circle_line_core(g, f"_hit{n}", "0.0", "0.0", "_rad", qx, qy, "_dux", "_duy",
                      literal(s.param("sigma")))
    g.emit(f"{n} = math.atan2(_ry, _rx) - math.atan2(_hit{n}y, _hit{n}x)", f"sn{n} = sn_hit{n}")
    return f"sn{n}"


def _place(g: ScalarGen, s: Step, n: str) -> None:
    (ox, oy), a = g.pt(s.input("origin")), g.name(s.input("angle"))
    vx, vy = (literal(v) for v in s.param("offset"))
    g.emit(f"_c = math.cos({a})", f"_s = math.sin({a})",
           f"{n}x = {ox} + (_c * {vx} - _s * {vy})", f"{n}y = {oy} + (_s * {vx} + _c * {vy})")


def _similar_position(g: ScalarGen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.input("a")), g.pt(s.input("b"))
    z = complex(s.param("z"))
    g.emit(f"_z = complex({ax}, {ay}) + (complex({bx}, {by}) - complex({ax}, {ay})) * "
           f"complex({literal(z.real)}, {literal(z.imag)})", f"{n}x = _z.real", f"{n}y = _z.imag")


def _similar_image(g: ScalarGen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.input("a")), g.pt(s.input("b"))
    pa, pb, px = s.input("pa"), s.input("pb"), s.input("px")
    (pax, pay), (pbx, pby), (pxx, pxy) = g.pt(pa), g.pt(pb), g.pt(px)
    ratio = g.once(("ratio", pa, pb, px), lambda r: (
        f"_q = complex({pbx}, {pby}) - complex({pax}, {pay})",
        f"{r} = _cdiv(complex({pxx}, {pxy}) - complex({pax}, {pay}), _q)"))
    g.emit(f"_z = complex({ax}, {ay}) + (complex({bx}, {by}) - complex({ax}, {ay})) * {ratio}",
           f"{n}x = _z.real", f"{n}y = _z.imag")


def _rigid_velocity(g: ScalarGen, s: Step, n: str) -> None:
    (ox, oy), w = g.pt(s.input("origin")), g.name(s.input("omega"))
    (pox, poy), (pxx, pxy) = g.pt(s.input("p_origin")), g.pt(s.input("p_point"))
    g.emit(f"{n}x = {ox} + {w} * (-({pxy} - {poy}))", f"{n}y = {oy} + {w} * ({pxx} - {pox})")


def _rigid_acceleration(g: ScalarGen, s: Step, n: str) -> None:
    (ox, oy), w, e = g.pt(s.input("origin")), g.name(s.input("omega")), g.name(s.input("eps"))
    (pox, poy), (pxx, pxy) = g.pt(s.input("p_origin")), g.pt(s.input("p_point"))
    g.emit(f"_rx = {pxx} - {pox}", f"_ry = {pxy} - {poy}", f"_w2 = {w} * {w}",
           f"{n}x = {ox} + {e} * (-_ry) - _w2 * _rx", f"{n}y = {oy} + {e} * _rx - _w2 * _ry")


def _drive_velocity(g: ScalarGen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.input("pivot")), g.pt(s.input("tip"))
    rest = s.rest()         # a law by a table: ω of the position is a step
    w = g.name(rest[0]) if rest else literal(s.param("omega"))
    g.emit(f"{n}x = {w} * (-({by} - {ay}))", f"{n}y = {w} * ({bx} - {ax})")


def _drive_acceleration(g: ScalarGen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.input("pivot")), g.pt(s.input("tip"))
    rest = s.rest()         # a law by a table: ω and ε of the position are steps
    w, e = ((g.name(rest[0]), g.name(rest[1])) if rest
            else (literal(s.param("omega")), literal(s.param("epsilon", 0.0))))
    g.emit(f"_rx = {bx} - {ax}", f"_ry = {by} - {ay}",
           f"{n}x = {e} * (-_ry) - {w} * {w} * _rx", f"{n}y = {e} * _rx - {w} * {w} * _ry")


def _line_perp(g: ScalarGen, s: Step, n: str) -> None:
    p, q = s.input("p"), s.input("q")
    (tx, ty), (px, py), (qx, qy) = g.pt(s.input("through")), g.pt(p), g.pt(q)
    unit = g.once(("perp", p, q), lambda u: (
        f"_vx = -({qy} - {py})", f"_vy = {qx} - {px}", "_nn = _hyp(_vx, _vy)",
        f"{u}x = _div(_vx, _nn)", f"{u}y = _div(_vy, _nn)"))
    g.emit(f"{n}px = {tx}", f"{n}py = {ty}", f"{n}ux = {unit}x", f"{n}uy = {unit}y")


def _line_parallel(g: ScalarGen, s: Step, n: str) -> None:
    (tx, ty), (_, _, ux, uy) = g.pt(s.input("through")), g.line(s.input("guide"))
    g.emit(f"{n}px = {tx}", f"{n}py = {ty}", f"{n}ux = {ux}", f"{n}uy = {uy}")


def _rate(g: ScalarGen, s: Step, n: str) -> None:
    """A link's ω or ε: (r × (b − a)) / r·r, r = q − p, a and b the images its spec reads it from
    (``OpSpec.rate_of``: v_p, v_q for ω; the normal's end n, a_q for ε)."""
    assert s.op.rate_of is not None
    p, q = s.input("p"), s.input("q")
    (px, py), (qx, qy) = g.pt(p), g.pt(q)
    (ax, ay), (bx, by) = (g.pt(s.input(name)) for name in s.op.rate_of)
    g.emit(f"_rx = {qx} - {px}", f"_ry = {qy} - {py}")
    rr = g.once(("rr", p, q), lambda r: (f"{r} = _rx * _rx + _ry * _ry",))
    g.emit(f"_dx = {bx} - {ax}", f"_dy = {by} - {ay}", f"{n} = _div(_rx * _dy - _ry * _dx, {rr})")


def _normal(g: ScalarGen, s: Step, n: str) -> None:
    (ax, ay), w = g.pt(s.input("start")), g.name(s.input("omega"))
    (px, py), (qx, qy) = g.pt(s.input("p")), g.pt(s.input("q"))
    g.emit(f"_w2 = {w} * {w}", f"{n}x = {ax} - _w2 * ({qx} - {px})",
           f"{n}y = {ay} - _w2 * ({qy} - {py})")


def _coriolis(g: ScalarGen, s: Step, n: str) -> None:
    (sx, sy), w = g.pt(s.input("start")), g.name(s.input("omega"))
    (fx, fy), (tx, ty) = g.pt(s.input("v_from")), g.pt(s.input("v_to"))
    g.emit(f"_k = 2.0 * {w}", f"{n}x = {sx} + _k * (-({ty} - {fy}))",
           f"{n}y = {sy} + _k * ({tx} - {fx})")


def _copy(g: ScalarGen, s: Step, n: str) -> None:
    src = s.input("value")
    kind = s.kind
    if kind is Kind.POINT:
        x, y = g.pt(src)
        g.emit(f"{n}x = {x}", f"{n}y = {y}")
    else:
        g.emit(f"{n} = {g.name(src)}")


def _difference(g: ScalarGen, s: Step, n: str) -> None:
    (ax, ay), (bx, by) = g.pt(s.input("start")), g.pt(s.input("end"))
    g.emit(f"{n}x = {bx} - {ax}", f"{n}y = {by} - {ay}")


#: the scalar form of each operation that has one (an operation without one makes
#: :func:`compile_kernel` raise :class:`KernelUnsupported`: the caller uses the numpy path)
SCALAR_FORMS: dict[OpSpec, Gen] = {
    Op.CRANK_ANGLE: _crank, Op.FIXED_POINT: _fixed, Op.CONSTANT: _constant, Op.POLE: _pole,
    Op.POLAR_POINT: _polar, Op.ANGLE_OF: _angle_of, Op.ANGLE_PLUS: _angle_plus,
    Op.CIRCLE_CIRCLE: _circle_circle, Op.CIRCLE_LINE: _circle_line, Op.LINE_LINE: _line_line,
    Op.LOCUS_LINE: _locus_line, Op.CARRIER_ANGLE: _carrier_angle, Op.PLACE: _place,
    Op.SIMILAR_POSITION: _similar_position, Op.SIMILAR_IMAGE: _similar_image,
    Op.RIGID_VELOCITY: _rigid_velocity, Op.RIGID_ACCELERATION: _rigid_acceleration,
    Op.DRIVE_VELOCITY: _drive_velocity, Op.DRIVE_ACCELERATION: _drive_acceleration,
    Op.LINE_PERP: _line_perp, Op.LINE_PARALLEL: _line_parallel, Op.OMEGA: _rate,
    Op.EPSILON: _rate, Op.NORMAL: _normal, Op.CORIOLIS: _coriolis, Op.COPY: _copy,
    Op.DIFFERENCE: _difference,
}

# the linear drivers' operations (a cylinder, a slider): their module reads this one's helpers
from .kernel_drivers import DRIVER_FORMS

SCALAR_FORMS.update(DRIVER_FORMS)

# a second crank (W = 2): its angle from the first's
from .kernel_inputs import INPUT_FORMS

SCALAR_FORMS.update(INPUT_FORMS)

# class III groups (triads): the closure's root, the first inner point, a leg's line
from .kernel_triad_forms import TRIAD_FORMS

SCALAR_FORMS.update(TRIAD_FORMS)

# class III groups with sliding legs: the closure's root, the first inner point, a slider leg's line
from .kernel_triadp_forms import TRIADP_FORMS

SCALAR_FORMS.update(TRIADP_FORMS)
