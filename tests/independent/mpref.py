"""Independent high-precision reference solvers for planar mechanisms (golden truth).

This module deliberately does NOT import ``mechplan``.  It is a second, independent method:

* positions: the loop-closure equations of each mechanism are solved by Newton's method
  (``mpmath.findroot``, multidimensional Newton with the analytic Jacobian of the *constraint*
  equations) at 40 significant digits, started from a float64 guess computed in closed form
  (the ``guess_*`` functions below); the residual is checked (< 1e-35, and at the level of the
  working precision) and the assembly branch is verified after convergence;
* velocities and accelerations: ``mpmath.diff`` (central differences at raised working precision)
  of the position solution with respect to the crank angle, times ``omega`` resp. ``omega**2``
  (constant crank speed, ``d/dt = omega d/dtheta``).  No closed-form velocity formula is used.

Conventions: SI units (metres, radians, seconds).  ``theta`` is the ABSOLUTE crank angle,
counter-clockwise from +x.  ``omega`` is signed, + = counter-clockwise.

Every solver returns ``dict[str, tuple[mpf, ...]]``:

* point name -> ``(x, y, vx, vy, ax, ay)``
* link name  -> ``(angle, omega, epsilon)``; ``angle`` = ``atan2`` direction of a named pair of
  the link's points, in (-pi, pi]; omega / epsilon counter-clockwise positive
* ``"s3"`` (quick_return, shaper only) -> ``(s, ds/dt, d2s/dt2)`` with ``s = |O3A|`` (relative
  sliding of the slider along the coulisse slot).

Importing this module sets ``mpmath.mp.dps = 40`` (as required by the test-suite); every public
function additionally computes inside ``mp.workdps(DPS)`` so it stays correct if someone changes
the global precision later.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
from mpmath import mp, mpf

__all__ = [
    "DPS",
    "PRESETS",
    "PRESET_PARAMS",
    "RESIDUAL_LIMIT",
    "ConvergenceError",
    "four_bar",
    "guess_four_bar",
    "guess_quick_return",
    "guess_shaper",
    "guess_slider_crank",
    "guess_v_engine",
    "preset_omega",
    "quick_return",
    "reference",
    "rpm",
    "shaper",
    "slider_crank",
    "solve",
    "v_engine",
]

DPS: int = 40
RESIDUAL_LIMIT: float = 1e-35
mp.dps = DPS

Number = float | int | str | mpf
Vec = tuple[mpf, mpf]
Result = dict[str, tuple[mpf, ...]]


class ConvergenceError(RuntimeError):
    """Newton did not converge to the requested precision / assembly branch."""


def rpm(n: Number) -> mpf:
    """Convert revolutions per minute to rad/s (sign preserved) in mpmath."""
    return mpf(n) * 2 * mp.pi / 60


# --------------------------------------------------------------------------------------------
# small mpmath vector helpers
# --------------------------------------------------------------------------------------------
def _e(phi: mpf) -> Vec:
    return (mp.cos(phi), mp.sin(phi))


def _add(a: Vec, b: Vec) -> Vec:
    return (a[0] + b[0], a[1] + b[1])


def _sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1])


def _mul(k: mpf, a: Vec) -> Vec:
    return (k * a[0], k * a[1])


def _dot(a: Vec, b: Vec) -> mpf:
    return a[0] * b[0] + a[1] * b[1]


def _cross(a: Vec, b: Vec) -> mpf:
    return a[0] * b[1] - a[1] * b[0]


def _mpvec(p: Sequence[Number]) -> Vec:
    return (mpf(p[0]), mpf(p[1]))


# --------------------------------------------------------------------------------------------
# generic machinery
# --------------------------------------------------------------------------------------------
@dataclass
class _Mechanism:
    """A mechanism as a set of loop-closure equations in unknowns ``q`` for a crank angle."""

    name: str
    guess: Callable[[float], list[float]]
    residual: Callable[[mpf, Sequence[mpf]], list[mpf]]
    jacobian: Callable[[mpf, Sequence[mpf]], list[list[mpf]]]
    points: Callable[[mpf, Sequence[mpf]], dict[str, Vec]]
    links: dict[str, tuple[str, str]]
    branch_ok: Callable[[mpf, Sequence[mpf]], bool]
    scalars: dict[str, Callable[[mpf, Sequence[mpf]], mpf]] = field(default_factory=dict)


def _solve_q(mech: _Mechanism, theta: mpf) -> list[mpf]:
    """Newton solve of the loop closure at the *current* working precision."""
    q0 = mech.guess(float(theta))
    tol = mp.eps * 2**4  # findroot compares the residual max-norm with tol * max(1, |q|)
    try:
        sol = mp.findroot(
            lambda *q: mech.residual(theta, q),
            q0,
            J=lambda *q: mp.matrix(mech.jacobian(theta, q)),
            tol=tol,
            maxsteps=60,
            verify=False,
        )
    except (ZeroDivisionError, ValueError) as exc:  # singular Jacobian etc.
        raise ConvergenceError(f"{mech.name}: Newton failed at theta={theta}: {exc}") from exc
    q = [sol[i] for i in range(len(q0))]
    res = max(abs(r) for r in mech.residual(theta, q))
    limit = min(mpf(RESIDUAL_LIMIT), mp.eps * 2**12)
    if not res < limit:
        raise ConvergenceError(
            f"{mech.name}: loop-closure residual {mpmath.nstr(res, 5)} >= "
            f"{mpmath.nstr(limit, 5)} at theta={mpmath.nstr(theta, 20)}"
        )
    if not mech.branch_ok(theta, q):
        raise ConvergenceError(
            f"{mech.name}: Newton converged to the wrong assembly branch at theta={theta}"
        )
    return q


def _analyse(mech: _Mechanism, theta: Number, omega: Number) -> Result:
    """Positions by Newton, velocities/accelerations by mpmath.diff w.r.t. theta."""
    with mp.workdps(DPS):
        theta = mpf(theta)
        omega = mpf(omega)
        q0 = _solve_q(mech, theta)
        pts0 = mech.points(theta, q0)
        names = list(pts0)
        link_dirs0 = {k: _sub(pts0[b], pts0[a]) for k, (a, b) in mech.links.items()}
        link_names = list(mech.links)
        scalar_names = list(mech.scalars)

        cache: dict[tuple[mpf, int], list[mpf]] = {}

        def sample(th: mpf) -> list[mpf]:
            """All position-level quantities at angle th (cached per value and precision).

            Link angles are returned RELATIVE to their direction at the base angle (so that
            the function is smooth across the atan2 branch cut)."""
            key = (th, mp.prec)
            hit = cache.get(key)
            if hit is not None:
                return hit
            q = _solve_q(mech, th)
            pts = mech.points(th, q)
            out: list[mpf] = []
            for n in names:
                out.extend(pts[n])
            for k in link_names:
                a, b = mech.links[k]
                d = _sub(pts[b], pts[a])
                d0 = link_dirs0[k]
                out.append(mp.atan2(_cross(d0, d), _dot(d0, d)))
            for k in scalar_names:
                out.append(mech.scalars[k](th, q))
            cache[key] = out
            return out

        base = sample(theta)
        ncomp = len(base)
        d1 = [mp.diff(lambda t, i=i: sample(t)[i], theta, 1) * omega for i in range(ncomp)]
        d2 = [mp.diff(lambda t, i=i: sample(t)[i], theta, 2) * omega**2 for i in range(ncomp)]

        result: Result = {}
        j = 0
        for n in names:
            x, y = pts0[n]
            result[n] = (+x, +y, d1[j], d1[j + 1], d2[j], d2[j + 1])
            j += 2
        for k in link_names:
            dx, dy = link_dirs0[k]
            result[k] = (mp.atan2(dy, dx), d1[j], d2[j])
            j += 1
        for k in scalar_names:
            result[k] = (+base[j], d1[j], d2[j])
            j += 1
        return result


# --------------------------------------------------------------------------------------------
# a. slider-crank
# --------------------------------------------------------------------------------------------
def guess_slider_crank(
    r: float, l: float, e: float, theta: float, guide_angle: float = 0.0
) -> list[float]:
    """Closed-form float guess ``[phi2, t]`` (rod angle, slider coordinate along the guide)."""
    r, l, e, g = float(r), float(l), float(e), float(guide_angle)
    alpha = theta - g
    a_u, a_n = r * math.cos(alpha), r * math.sin(alpha)
    h = e - a_n
    w = math.sqrt(max(l * l - h * h, 0.0))
    return [g + math.atan2(h, w), a_u + w]


def _slider_crank_mech(r: Number, l: Number, e: Number, guide_angle: Number,
                       frac_S2: Number) -> _Mechanism:
    r, l, e, g, f = mpf(r), mpf(l), mpf(e), mpf(guide_angle), mpf(frac_S2)
    rf, lf, ef, gf = float(r), float(l), float(e), float(g)

    def frame() -> tuple[Vec, Vec]:
        u = _e(g)
        return u, (-u[1], u[0])

    def residual(th: mpf, q: Sequence[mpf]) -> list[mpf]:
        u, n = frame()
        a = _mul(r, _e(th))
        b = _add(_mul(e, n), _mul(q[1], u))
        res = _sub(_add(a, _mul(l, _e(q[0]))), b)
        return [res[0], res[1]]

    def jacobian(th: mpf, q: Sequence[mpf]) -> list[list[mpf]]:
        u, _ = frame()
        c, s = _e(q[0])
        return [[-l * s, -u[0]], [l * c, -u[1]]]

    def points(th: mpf, q: Sequence[mpf]) -> dict[str, Vec]:
        u, n = frame()
        a = _mul(r, _e(th))
        b = _add(_mul(e, n), _mul(q[1], u))
        return {"O": (mpf(0), mpf(0)), "A": a, "B": b, "S2": _add(a, _mul(f, _sub(b, a)))}

    def branch_ok(th: mpf, q: Sequence[mpf]) -> bool:
        u, _ = frame()
        p = points(th, q)
        return _dot(_sub(p["B"], p["A"]), u) > 0

    return _Mechanism(
        name="slider_crank",
        guess=lambda th: guess_slider_crank(rf, lf, ef, th, gf),
        residual=residual,
        jacobian=jacobian,
        points=points,
        links={"1": ("O", "A"), "2": ("A", "B")},
        branch_ok=branch_ok,
    )


def slider_crank(
    r: Number,
    l: Number,
    e: Number,
    omega: Number,
    theta: Number,
    guide_angle: Number = 0,
    frac_S2: Number = 0.5,
) -> Result:
    """Slider-crank: crank O=(0,0)->A (length r), rod A->B (length l), B on the guide line
    ``{e*n + t*u}`` (u = (cos g, sin g), n = (-sin g, cos g)), B = intersection with larger t.

    Points O, A, B, S2 (S2 = A + frac_S2*(B-A)); links "1" (O->A), "2" (A->B).
    """
    with mp.workdps(DPS):
        mech = _slider_crank_mech(r, l, e, guide_angle, frac_S2)
    return _analyse(mech, theta, omega)


# --------------------------------------------------------------------------------------------
# b. four-bar
# --------------------------------------------------------------------------------------------
def guess_four_bar(
    A: Sequence[float], D: Sequence[float], lAB: float, lBC: float, lCD: float,
    theta: float, branch: int = 1,
) -> list[float]:
    """Closed-form float guess ``[phi2, phi3]`` (angles of B->C and D->C)."""
    ax, ay, dx, dy = float(A[0]), float(A[1]), float(D[0]), float(D[1])
    lAB, lBC, lCD = float(lAB), float(lBC), float(lCD)
    bx, by = ax + lAB * math.cos(theta), ay + lAB * math.sin(theta)
    vx, vy = dx - bx, dy - by
    L = math.hypot(vx, vy)
    a = (lBC**2 - lCD**2 + L**2) / (2 * L)
    h = math.sqrt(max(lBC**2 - a**2, 0.0))
    ux, uy = vx / L, vy / L
    cx = bx + a * ux - branch * h * uy
    cy = by + a * uy + branch * h * ux
    return [math.atan2(cy - by, cx - bx), math.atan2(cy - dy, cx - dx)]


def _four_bar_mech(A: Sequence[Number], D: Sequence[Number], lAB: Number, lBC: Number,
                   lCD: Number, branch: int, lBE: Number | None,
                   lCE: Number | None) -> _Mechanism:
    if branch not in (1, -1):
        raise ValueError("branch must be +1 or -1")
    Am, Dm = _mpvec(A), _mpvec(D)
    lAB, lBC, lCD = mpf(lAB), mpf(lBC), mpf(lCD)
    Af, Df = (float(Am[0]), float(Am[1])), (float(Dm[0]), float(Dm[1]))
    fl = (float(lAB), float(lBC), float(lCD))
    has_E = lBE is not None and lCE is not None
    if has_E:
        lBE_m, lCE_m = mpf(lBE), mpf(lCE)

    def B_of(th: mpf) -> Vec:
        return _add(Am, _mul(lAB, _e(th)))

    def residual(th: mpf, q: Sequence[mpf]) -> list[mpf]:
        res = _sub(_add(B_of(th), _mul(lBC, _e(q[0]))), _add(Dm, _mul(lCD, _e(q[1]))))
        return [res[0], res[1]]

    def jacobian(th: mpf, q: Sequence[mpf]) -> list[list[mpf]]:
        c2, s2 = _e(q[0])
        c3, s3 = _e(q[1])
        return [[-lBC * s2, lCD * s3], [lBC * c2, -lCD * c3]]

    def points(th: mpf, q: Sequence[mpf]) -> dict[str, Vec]:
        B = B_of(th)
        C = _add(B, _mul(lBC, _e(q[0])))
        pts = {"A": Am, "B": B, "C": C, "D": Dm}
        if has_E:
            # E left of B->C: rotate the direction B->C counter-clockwise by the angle CBE.
            cosb = (lBE_m**2 + lBC**2 - lCE_m**2) / (2 * lBE_m * lBC)
            pts["E"] = _add(B, _mul(lBE_m, _e(q[0] + mp.acos(cosb))))
        return pts

    def branch_ok(th: mpf, q: Sequence[mpf]) -> bool:
        p = points(th, q)
        return branch * _cross(_sub(Dm, p["B"]), _sub(p["C"], p["B"])) > 0

    return _Mechanism(
        name="four_bar",
        guess=lambda th: guess_four_bar(Af, Df, *fl, th, branch),
        residual=residual,
        jacobian=jacobian,
        points=points,
        links={"1": ("A", "B"), "2": ("B", "C"), "3": ("D", "C")},
        branch_ok=branch_ok,
    )


def four_bar(
    A: Sequence[Number],
    D: Sequence[Number],
    lAB: Number,
    lBC: Number,
    lCD: Number,
    omega: Number,
    theta: Number,
    branch: int = 1,
    lBE: Number | None = None,
    lCE: Number | None = None,
) -> Result:
    """Four-bar: ground pivots A, D; crank AB, coupler BC, rocker DC.

    C is left of the directed line B->D for ``branch=+1`` (``cross(D-B, C-B) > 0``), right for
    -1.  If ``lBE`` and ``lCE`` are given, coupler point E (left of B->C) is added.
    Points A, B, C, D[, E]; links "1" (A->B), "2" (B->C), "3" (D->C).
    """
    with mp.workdps(DPS):
        mech = _four_bar_mech(A, D, lAB, lBC, lCD, branch, lBE, lCE)
    return _analyse(mech, theta, omega)


# --------------------------------------------------------------------------------------------
# c. V-engine (WORKED_EXAMPLES section 1)
# --------------------------------------------------------------------------------------------
V_ENGINE_GEOMETRY: dict[str, float] = {
    "lAB": 0.08, "lBC": 0.248, "lBD": 0.062, "lCD": 0.218, "lDE": 0.218,
    "axis_x_deg": 60.0, "axis_y_deg": 120.0,
}


def guess_v_engine(
    theta: float, lAB: float = 0.08, lBC: float = 0.248, lBD: float = 0.062,
    lCD: float = 0.218, lDE: float = 0.218, axis_x_deg: float = 60.0,
    axis_y_deg: float = 120.0,
) -> list[float]:
    """Closed-form float guess ``[phi2, sC, phi4, sE]`` for the V-engine (A at the origin)."""
    gx, gy = math.radians(axis_x_deg), math.radians(axis_y_deg)
    beta = math.acos((lBC**2 + lBD**2 - lCD**2) / (2 * lBC * lBD))
    bx, by = lAB * math.cos(theta), lAB * math.sin(theta)

    def on_axis(px: float, py: float, length: float, g: float) -> float:
        ux, uy = math.cos(g), math.sin(g)
        pu, pn = px * ux + py * uy, -px * uy + py * ux
        return pu + math.sqrt(max(length**2 - pn**2, 0.0))

    sC = on_axis(bx, by, lBC, gx)
    phi2 = math.atan2(sC * math.sin(gx) - by, sC * math.cos(gx) - bx)
    dx, dy = bx + lBD * math.cos(phi2 + beta), by + lBD * math.sin(phi2 + beta)
    sE = on_axis(dx, dy, lDE, gy)
    phi4 = math.atan2(sE * math.sin(gy) - dy, sE * math.cos(gy) - dx)
    return [phi2, sC, phi4, sE]


def _v_engine_mech(lAB: Number, lBC: Number, lBD: Number, lCD: Number, lDE: Number,
                   axis_x_deg: Number, axis_y_deg: Number) -> _Mechanism:
    lAB, lBC, lBD, lCD, lDE = map(mpf, (lAB, lBC, lBD, lCD, lDE))
    gx, gy = mp.radians(mpf(axis_x_deg)), mp.radians(mpf(axis_y_deg))
    fl = tuple(float(v) for v in (lAB, lBC, lBD, lCD, lDE, axis_x_deg, axis_y_deg))
    origin = (mpf(0), mpf(0))

    def beta() -> mpf:  # angle CBD, D on the left of B->C
        return mp.acos((lBC**2 + lBD**2 - lCD**2) / (2 * lBC * lBD))

    def parts(th: mpf, q: Sequence[mpf]) -> dict[str, Vec]:
        B = _mul(lAB, _e(th))
        C = _mul(q[1], _e(gx))
        D = _add(B, _mul(lBD, _e(q[0] + beta())))
        E = _mul(q[3], _e(gy))
        return {"A": origin, "B": B, "C": C, "D": D, "E": E}

    def residual(th: mpf, q: Sequence[mpf]) -> list[mpf]:
        p = parts(th, q)
        r1 = _sub(_add(p["B"], _mul(lBC, _e(q[0]))), p["C"])
        r2 = _sub(_add(p["D"], _mul(lDE, _e(q[2]))), p["E"])
        return [r1[0], r1[1], r2[0], r2[1]]

    def jacobian(th: mpf, q: Sequence[mpf]) -> list[list[mpf]]:
        c2, s2 = _e(q[0])
        cb, sb = _e(q[0] + beta())
        c4, s4 = _e(q[2])
        ux, uy = _e(gx), _e(gy)
        z = mpf(0)
        return [
            [-lBC * s2, -ux[0], z, z],
            [lBC * c2, -ux[1], z, z],
            [-lBD * sb, z, -lDE * s4, -uy[0]],
            [lBD * cb, z, lDE * c4, -uy[1]],
        ]

    def points(th: mpf, q: Sequence[mpf]) -> dict[str, Vec]:
        p = parts(th, q)
        p["S2"] = _mul(mpf(1) / 2, _add(p["B"], p["C"]))
        return p

    def branch_ok(th: mpf, q: Sequence[mpf]) -> bool:
        p = parts(th, q)
        return (
            _dot(_sub(p["C"], p["B"]), _e(gx)) > 0
            and _dot(_sub(p["E"], p["D"]), _e(gy)) > 0
            and _cross(_sub(p["C"], p["B"]), _sub(p["D"], p["B"])) > 0
        )

    return _Mechanism(
        name="v_engine",
        guess=lambda th: guess_v_engine(th, *fl),
        residual=residual,
        jacobian=jacobian,
        points=points,
        links={"1": ("A", "B"), "2": ("B", "C"), "4": ("D", "E")},
        branch_ok=branch_ok,
    )


def v_engine(
    theta: Number,
    omega: Number | None = None,
    lAB: Number = "0.08",
    lBC: Number = "0.248",
    lBD: Number = "0.062",
    lCD: Number = "0.218",
    lDE: Number = "0.218",
    axis_x_deg: Number = 60,
    axis_y_deg: Number = 120,
) -> Result:
    """V-engine with master rod B-C-D and articulated rod D-E (WORKED_EXAMPLES section 1).

    A=(0,0); C slides on axis Ax (angle axis_x_deg through A, C on the + side), E on axis Ay
    (E on the + side); D on the left of directed line B->C.  ``omega`` defaults to -800 rpm.
    Points A, B, C, D, E, S2 (midpoint of BC); links "1" (A->B), "2" (B->C), "4" (D->E).
    """
    with mp.workdps(DPS):
        if omega is None:
            omega = rpm(-800)
        mech = _v_engine_mech(lAB, lBC, lBD, lCD, lDE, axis_x_deg, axis_y_deg)
        return _analyse(mech, theta, omega)


# --------------------------------------------------------------------------------------------
# d./e. crank-coulisse quick return and six-link shaper
# --------------------------------------------------------------------------------------------
def guess_quick_return(
    theta: float, lO1A: float = 0.1, O3: Sequence[float] = (0.0, -0.3)
) -> list[float]:
    """Closed-form float guess ``[phi3, s]`` (coulisse angle, s = |O3A|); O1 at the origin."""
    ax, ay = lO1A * math.cos(theta), lO1A * math.sin(theta)
    vx, vy = ax - O3[0], ay - O3[1]
    return [math.atan2(vy, vx), math.hypot(vx, vy)]


def guess_shaper(
    theta: float, lO1A: float = 0.1, O3: Sequence[float] = (0.0, -0.3), lO3B: float = 0.6,
    lBC: float = 0.15, yC: float = 0.32,
) -> list[float]:
    """Closed-form float guess ``[phi3, s, phi4, xC]`` for the shaper."""
    phi3, s = guess_quick_return(theta, lO1A, O3)
    bx, by = O3[0] + lO3B * math.cos(phi3), O3[1] + lO3B * math.sin(phi3)
    xC = bx + math.sqrt(max(lBC**2 - (yC - by) ** 2, 0.0))
    return [phi3, s, math.atan2(yC - by, xC - bx), xC]


def _coulisse_mech(lO1A: Number, O3: Sequence[Number], lO3B: Number, lBC: Number | None,
                   yC: Number | None) -> _Mechanism:
    lO1A, lO3B = mpf(lO1A), mpf(lO3B)
    O3m = _mpvec(O3)
    O1 = (mpf(0), mpf(0))
    six = lBC is not None
    f_O3 = (float(O3m[0]), float(O3m[1]))
    if six:
        lBCm, yCm = mpf(lBC), mpf(yC)
        f_six = (float(lO1A), f_O3, float(lO3B), float(lBCm), float(yCm))

    def parts(th: mpf, q: Sequence[mpf]) -> dict[str, Vec]:
        p = {
            "O1": O1,
            "A": _mul(lO1A, _e(th)),
            "O3": O3m,
            "B": _add(O3m, _mul(lO3B, _e(q[0]))),
        }
        if six:
            p["C"] = (q[3], yCm)
        return p

    def residual(th: mpf, q: Sequence[mpf]) -> list[mpf]:
        p = parts(th, q)
        r1 = _sub(_add(O3m, _mul(q[1], _e(q[0]))), p["A"])
        out = [r1[0], r1[1]]
        if six:
            r2 = _sub(_add(p["B"], _mul(lBCm, _e(q[2]))), p["C"])
            out += [r2[0], r2[1]]
        return out

    def jacobian(th: mpf, q: Sequence[mpf]) -> list[list[mpf]]:
        c3, s3 = _e(q[0])
        if not six:
            return [[-q[1] * s3, c3], [q[1] * c3, s3]]
        c4, s4 = _e(q[2])
        z = mpf(0)
        return [
            [-q[1] * s3, c3, z, z],
            [q[1] * c3, s3, z, z],
            [-lO3B * s3, z, -lBCm * s4, mpf(-1)],
            [lO3B * c3, z, lBCm * c4, z],
        ]

    def branch_ok(th: mpf, q: Sequence[mpf]) -> bool:
        ok = q[1] > 0
        if six:
            p = parts(th, q)
            ok = ok and p["C"][0] > p["B"][0]
        return bool(ok)

    if six:
        guess = lambda th: guess_shaper(th, *f_six)
        links = {"1": ("O1", "A"), "3": ("O3", "B"), "4": ("B", "C")}
    else:
        guess = lambda th: guess_quick_return(th, float(lO1A), f_O3)
        links = {"1": ("O1", "A"), "3": ("O3", "B")}
    return _Mechanism(
        name="shaper" if six else "quick_return",
        guess=guess,
        residual=residual,
        jacobian=jacobian,
        points=parts,
        links=links,
        branch_ok=branch_ok,
        scalars={"s3": lambda th, q: q[1]},
    )


def quick_return(
    theta: Number,
    omega: Number = 10,
    lO1A: Number = "0.1",
    O3: Sequence[Number] = ("0", "-0.3"),
    lO3B: Number = "0.6",
) -> Result:
    """Crank-coulisse quick-return: crank O1A (O1 at the origin), coulisse O3B, slider at A on
    the slot O3->B (same side as B).  Points O1, A, O3, B; links "1" (O1->A), "3" (O3->B);
    ``"s3"`` -> (|O3A|, d/dt, d2/dt2).
    """
    with mp.workdps(DPS):
        mech = _coulisse_mech(lO1A, O3, lO3B, None, None)
    return _analyse(mech, theta, omega)


def shaper(
    theta: Number,
    omega: Number = 10,
    lO1A: Number = "0.1",
    O3: Sequence[Number] = ("0", "-0.3"),
    lO3B: Number = "0.6",
    lBC: Number = "0.15",
    yC: Number = "0.32",
) -> Result:
    """Six-link shaper: quick_return plus rod B->C and ram C on the line y = yC (larger x).

    Points O1, A, O3, B, C; links "1", "3", "4" (B->C); ``"s3"`` as in :func:`quick_return`.
    """
    with mp.workdps(DPS):
        mech = _coulisse_mech(lO1A, O3, lO3B, lBC, yC)
    return _analyse(mech, theta, omega)


# --------------------------------------------------------------------------------------------
# presets
# --------------------------------------------------------------------------------------------
#: Parameters of the presets (strings -> exact decimal in mpmath; omega in rpm or rad/s as named).
PRESET_PARAMS: dict[str, dict[str, Any]] = {
    "slider_crank": {"r": "0.1", "l": "0.4", "e": "0", "omega_rpm": 1500, "frac_S2": "0.3"},
    "offset_slider_crank": {"r": "0.08", "l": "0.3", "e": "0.03", "omega_rpm": -600,
                            "frac_S2": "0.35"},
    "machine_unit": {"r": "0.075", "l": "0.383", "e": "0", "omega_rpm": 300, "frac_S2": "0.35"},
    "four_bar": {"A": ("0", "0"), "D": ("0.25", "0"), "lAB": "0.08", "lBC": "0.26",
                 "lCD": "0.18", "omega_rad_s": 10, "branch": 1, "lBE": "0.15", "lCE": "0.18"},
    "v_engine": {**{k: str(v) for k, v in V_ENGINE_GEOMETRY.items()}, "omega_rpm": -800},
    "quick_return": {"lO1A": "0.1", "O3": ("0", "-0.3"), "lO3B": "0.6", "omega_rad_s": 10},
    "shaper": {"lO1A": "0.1", "O3": ("0", "-0.3"), "lO3B": "0.6", "lBC": "0.15", "yC": "0.32",
               "omega_rad_s": 10},
}


def _preset_omega(name: str) -> mpf:
    p = PRESET_PARAMS[name]
    if "omega_rpm" in p:
        return rpm(p["omega_rpm"])
    return mpf(p["omega_rad_s"])


def _sc_preset(name: str) -> Callable[[Number], Result]:
    p = PRESET_PARAMS[name]

    def run(theta: Number) -> Result:
        with mp.workdps(DPS):
            return slider_crank(p["r"], p["l"], p["e"], _preset_omega(name), theta, 0,
                                p["frac_S2"])

    return run


def _four_bar_preset(theta: Number) -> Result:
    p = PRESET_PARAMS["four_bar"]
    with mp.workdps(DPS):
        return four_bar(p["A"], p["D"], p["lAB"], p["lBC"], p["lCD"],
                        _preset_omega("four_bar"), theta, 1, p["lBE"], p["lCE"])


PRESETS: dict[str, Callable[[Number], Result]] = {
    "slider_crank": _sc_preset("slider_crank"),
    "offset_slider_crank": _sc_preset("offset_slider_crank"),
    "machine_unit": _sc_preset("machine_unit"),
    "four_bar": _four_bar_preset,
    "v_engine": lambda theta: v_engine(theta),
    "quick_return": lambda theta: quick_return(theta),
    "shaper": lambda theta: shaper(theta),
}


def preset_omega(name: str) -> mpf:
    """Signed crank speed of a preset in rad/s (mpf, 40 digits)."""
    with mp.workdps(DPS):
        return _preset_omega(name)


def solve(mech_name: str, theta: Number) -> Result:
    """High-precision solution (mpf values) of preset ``mech_name`` at crank angle ``theta``."""
    try:
        fn = PRESETS[mech_name]
    except KeyError:
        raise KeyError(f"unknown mechanism {mech_name!r}; known: {sorted(PRESETS)}") from None
    return fn(theta)


def reference(mech_name: str, thetas: Iterable[Number] | np.ndarray) -> dict[str, np.ndarray]:
    """Evaluate preset ``mech_name`` at every angle in ``thetas``; convert to float64.

    Returns name -> array of shape ``(N, 6)`` for points (x, y, vx, vy, ax, ay), ``(N, 3)`` for
    links (angle, omega, epsilon) and for ``"s3"`` (s, ds/dt, d2s/dt2).  Angles are as given
    (float64 thetas are used exactly).
    """
    ths = np.atleast_1d(np.asarray(thetas, dtype=object))
    rows = [solve(mech_name, th.item() if isinstance(th, np.generic) else th) for th in ths]
    if not rows:
        return {}
    return {k: np.array([[float(v) for v in row[k]] for row in rows], dtype=np.float64)
            for k in rows[0]}
