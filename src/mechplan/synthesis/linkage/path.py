"""Path generation with prescribed timing: a four-bar whose coupler point P passes through given
points P1…Pn at given rotations of the crank from its first position.

Three points (Erdman & Sandor's standard form): each dyad — crank AB with the coupler vector BP,
rocker DC with CP — satisfies W·(e^{iβj} − 1) + Z·(e^{iαj} − 1) = Pj − P1 (j = 2, 3) with the
crank rotations βj and the coupler rotations αj (for the rocker dyad the rocker rotations γj in
place of βj). Given βj, αj, γj this is linear in W, Z: solved exactly. More points: the loop
closures A + W·e^{iβj} + Z·e^{iαj} = Pj and D + W*·e^{iγj} + Z*·e^{iαj} = Pj at every point are
solved by least squares (αj, γj unknown), started from the exact three-point linkage through the
first, middle and last points. The miss of the linkage itself (its coupler point at the crank
angles, on the first position's assembly) is reported with branch, order and circuit defects.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from .crank_rocker import grashof
from .design import LinkageDesign, Step, Stroke
from .function import rocker_angle
from .scene_out import base, link_name, mm

SWEEP_SAMPLES = 721


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def dyad(delta: list[complex], beta: list[float], alpha: list[float]) -> tuple[complex, complex]:
    """The standard-form dyad W, Z through three positions: W(e^{iβ}−1) + Z(e^{iα}−1) = δ."""
    m = np.array([[np.exp(1j * b) - 1, np.exp(1j * a) - 1] for b, a in zip(beta, alpha)])
    if abs(np.linalg.det(m)) < 1e-12:
        raise np.linalg.LinAlgError("singular dyad")
    w, z = np.linalg.solve(m, np.array(delta))
    return complex(w), complex(z)


def three_point(p: list[complex], beta: tuple[float, float], alpha: tuple[float, float],
                gamma: tuple[float, float]) -> tuple[complex, ...]:
    """A, W, Z, D, W*, Z* of the four-bar through three points (prescribed timing)."""
    delta = [p[1] - p[0], p[2] - p[0]]
    w, z = dyad(delta, list(beta), list(alpha))
    ws, zs = dyad(delta, list(gamma), list(alpha))
    return p[0] - z - w, w, z, p[0] - zs - ws, ws, zs


def _residuals(x: np.ndarray, p: np.ndarray, beta: np.ndarray) -> np.ndarray:
    n = p.size
    a_, w, z, d_, ws = (complex(x[2 * i], x[2 * i + 1]) for i in range(5))
    zs = a_ + w + z - d_ - ws                 # one rigid coupler: E1 = B1 + Z = C1 + Z*
    alpha = np.concatenate([[0.0], x[10:9 + n]])
    gamma = np.concatenate([[0.0], x[9 + n:8 + 2 * n]])
    r1 = a_ + w * np.exp(1j * beta) + z * np.exp(1j * alpha) - p
    r2 = d_ + ws * np.exp(1j * gamma) + zs * np.exp(1j * alpha) - p
    return np.concatenate([r1.real, r1.imag, r2.real, r2.imag])


def least_squares_fit(p: list[complex], beta: list[float], start: tuple[complex, ...],
                      alpha0: list[float], gamma0: list[float]) -> tuple[complex, ...]:
    """Refine A, W, Z, D, W*, Z* over all the points by least squares on the loop closures."""
    from scipy.optimize import least_squares

    x0 = [v for c in start[:5] for v in (c.real, c.imag)] + list(alpha0) + list(gamma0)
    sol = least_squares(_residuals, np.array(x0), args=(np.array(p), np.array(beta)),
                        method="trf", xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=20000)
    a_, w, z, d_, ws = (complex(sol.x[2 * i], sol.x[2 * i + 1]) for i in range(5))
    return a_, w, z, d_, ws, a_ + w + z - d_ - ws


def coupler_points(a_: complex, w: complex, z: complex, d_: complex, ws: complex, zs: complex,
                   phis: np.ndarray) -> np.ndarray:
    """The coupler point of the four-bar at absolute crank angles (complex; NaN where it does
    not assemble), on the assembly of position 1."""
    a, b, c = abs(w), abs(zs - z), abs(ws)
    frame = d_ - a_
    d, f = abs(frame), np.angle(frame)
    b1, c1 = a_ + w, d_ + ws
    branch = math.copysign(1.0, ((d_ - b1).conjugate() * (c1 - b1)).imag)
    psi = rocker_angle(phis - f, a, b, c, d, branch) + f
    bj = a_ + a * np.exp(1j * phis)
    cj = d_ + c * np.exp(1j * psi)
    turn = (cj - bj) / (c1 - b1)          # the coupler's rotation from position 1
    return bj + z * turn


def path_generation(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the four-bar whose coupler point passes the given points at given crank
    rotations."""
    pts, beta_in = spec.path_points, spec.crank_rotations
    if pts is None or beta_in is None:
        raise _error(spec, "points" if pts is None else "crank_rotations", "needs",
                     problem=spec.problem)
    n = len(pts)
    if len(beta_in) != n - 1:
        raise _error(spec, "crank_rotations", "numbers", n=str(n - 1), value=str(len(beta_in)))
    alpha_in, gamma_in = spec.coupler_rotations, spec.rocker_rotations
    if alpha_in is None or gamma_in is None:
        raise _error(spec, "coupler_rotations" if alpha_in is None else "rocker_rotations",
                     "needs", problem=spec.problem)
    p = [complex(x, y) for x, y in pts]
    beta = [0.0, *beta_in]
    mid = n // 2 if n > 3 else 1
    picks = [0, mid, n - 1]
    try:
        start = three_point([p[i] for i in picks], (beta[mid], beta[-1]), alpha_in, gamma_in)
    except np.linalg.LinAlgError:
        raise _error(spec, "coupler_rotations", "path_singular") from None
    exact = n == 3
    if exact:
        sol = start
    else:
        ai = np.interp(range(n), picks, [0.0, *alpha_in])[1:]
        gi = np.interp(range(n), picks, [0.0, *gamma_in])[1:]
        sol = least_squares_fit(p, beta, start, list(ai), list(gi))
    a_, w, z, d_, ws, zs = sol
    a, b, c, d = abs(w), abs(zs - z), abs(ws), abs(d_ - a_)
    if min(a, b, c, d) <= 1e-9 * max(a, b, c, d):
        raise _error(spec, "points", "path_degenerate")
    b1, c1 = a_ + w, d_ + ws
    p1 = b1 + z                               # the coupler point of the linkage at position 1
    phi1 = float(np.angle(w))
    sense = 1 if beta[-1] >= 0 else -1
    phis = np.array([phi1 + bj for bj in beta])
    def side(bj: complex, cj: complex) -> float:
        return math.copysign(1.0, ((d_ - bj).conjugate() * (cj - bj)).imag)

    alpha_all = [0.0] + [float(np.angle((p[j] - (a_ + w * np.exp(1j * beta[j]))) / z))
                         for j in range(1, n)]
    cjs = [p[j] - zs * np.exp(1j * alpha_all[j]) for j in range(n)]
    bjs = [a_ + w * np.exp(1j * beta[j]) for j in range(n)]
    sides = [side(bj, cj) for bj, cj in zip(bjs, cjs)]
    branch_defect = any(s != sides[0] for s in sides)
    turns = [(sense * bj) % (2 * math.pi) for bj in beta]
    order_defect_turn = any(t2 <= t1 for t1, t2 in itertools.pairwise(turns))
    sweep = turns[-1]
    ok, margin = grashof({"1": a, "2": b, "3": c, "0": d})
    crank = ok and min(a, b, c, d) in (a, d)
    order_defect = order_defect_turn or (not crank and sweep > math.pi)
    frame_angle = float(np.angle(d_ - a_))
    phi_sweep = phi1 - frame_angle + sense * np.linspace(0.0, sweep, SWEEP_SAMPLES)
    circuit_defect = bool(np.any(np.isnan(rocker_angle(phi_sweep, a, b, c, d, sides[0]))))
    got = coupler_points(a_, w, z, d_, ws, zs, phis)
    miss = np.abs(got - np.array(p))
    miss_max = float(np.nanmax(miss)) if not np.all(np.isnan(miss)) else math.inf
    if np.any(np.isnan(miss)):
        miss_max = math.inf
    left = ((c1 - b1).conjugate() * (p1 - b1)).imag > 0
    engine_phis = [float((sense * ph) % (2 * math.pi)) for ph in phis]
    scene = base(spec, {"A": [mm(a_.real), mm(a_.imag)], "D": [mm(d_.real), mm(d_.imag)]}, {
        "1": {"name": link_name("crank", spec), "lengths": {"AB": mm(a)}},
        "2": {"name": link_name("coupler", spec),
              "lengths": {"BC": mm(b), "BE": mm(abs(z)), "CE": mm(abs(zs))},
              "side": {"E": ("left" if left else "right") + " of B->C"}},
        "3": {"name": link_name("rocker", spec), "lengths": {"DC": mm(c)}},
    }, {}, {"at": repr(math.degrees(engine_phis[0])) + " deg",
            "C": [mm(c1.real), mm(c1.imag)]})
    scene["drive"]["sense"] = "ccw" if sense > 0 else "cw"
    scene["positions"] = {"at": [repr(math.degrees(ph)) + " deg" for ph in engine_phis]}
    strokes: list[Stroke] = []
    for j, pj in enumerate(p, start=1):
        strokes.append(Stroke("point", (pj.real, pj.imag), role="given", label=f"P{j}"))
    # the coupler curve over a turn (or the reachable part of it)
    curve = coupler_points(a_, w, z, d_, ws, zs, phi1 + np.linspace(0, 2 * math.pi, 361))
    for q0, q1 in itertools.pairwise(curve):
        if not (np.isnan(q0) or np.isnan(q1)):
            strokes.append(Stroke("line", (q0.real, q0.imag), (q1.real, q1.imag),
                                  role="family"))

    def pt(v: complex) -> tuple[float, float]:
        return (v.real, v.imag)

    strokes += [Stroke("point", pt(a_), role="result", label="A"),
                Stroke("point", pt(d_), role="result", label="D"),
                Stroke("line", pt(a_), pt(d_), role="mechanism"),
                Stroke("line", pt(a_), pt(b1), role="mechanism"),
                Stroke("line", pt(b1), pt(c1), role="mechanism"),
                Stroke("line", pt(b1), pt(p1), role="mechanism"),
                Stroke("line", pt(c1), pt(p1), role="mechanism"),
                Stroke("line", pt(d_), pt(c1), role="mechanism"),
                Stroke("point", pt(b1), role="result", label="B1"),
                Stroke("point", pt(c1), role="result", label="C1")]
    protocol = [Step("synth.pg.given" if exact else "synth.pg.given_lsq", {"n": float(n)}),
                Step("synth.pg.dyad_a", {"x": a_.real, "y": a_.imag, "a": a, "e": abs(z)}),
                Step("synth.pg.dyad_d", {"x": d_.real, "y": d_.imag, "c": c, "e": abs(zs)}),
                Step("synth.gd.lengths", {"a": a, "b": b, "c": c, "d": d})]
    conditions = {
        "grashof": ok, "grashof_margin": margin, "crank": crank,
        "branch_defect": branch_defect, "order_defect": order_defect,
        "circuit_defect": circuit_defect, "sense": sense, "precision_phi": engine_phis,
        "sweep": sweep, "path_points": [list(q) for q in pts], "exact": exact,
        "path_miss": miss_max, "coupler_rotations": alpha_all,
        "A": [a_.real, a_.imag], "D": [d_.real, d_.imag],
        "coupler_point": {"BE": abs(z), "CE": abs(zs), "left": bool(left)},
    }
    return LinkageDesign("path", 1.0, 0.0, {"a": a, "b": b, "c": c, "d": d}, strokes,
                         protocol, conditions, [], protocol[1], scene, "3", "path", 0.0)
