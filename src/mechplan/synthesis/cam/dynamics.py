"""The follower's dynamics on a rigid cam turning at constant speed ω: the closing spring, the
contact force over the cycle, the jump speed and the cam torque.

Along the follower's motion (s a length or the swing ψ), the cam must push with
N(φ, ω) = m·ω²·s″ + c·ω·s′ + k·s + F0 + F_load; contact holds while N > 0. The torque on the
cam shaft follows from the power balance T·ω = N·ds/dt = N·s′·ω, so T = N·s′.

Spring selection: when neither the stiffness nor the preload is given, the spring that keeps
N ≥ margin at every cam angle and every speed up to ω_max with the least mean spring force over the
stroke, F0 + k·h/2, is found by linear programming (the constraints are linear in F0 and k); with
one of them given, the other is the least that holds. The jump speed is the least
ω at which N reaches zero somewhere: for each cam angle N is a quadratic in ω, whose smallest
positive root is exact; the least over the dense angles is refined by Brent's method in φ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import linprog, minimize_scalar

from ...errors import SceneError
from ...i18n import Text
from ...model.cam import CamSpec, FollowerDynamics
from .elastic import ElasticResult, elastic_follower
from .motion import motion


@dataclass(frozen=True)
class DynamicsResult:
    """Spring, contact force, jump speed and cam torque (SI; N or N·m along the follower)."""

    stiffness: float
    preload: float
    spring_max: float                 # F0 + k·h
    chosen: bool                      # the spring was chosen here (not given)
    speed: float                      # the cam's speed, rad/s
    speed_max: float
    phi: np.ndarray                   # dense cam angles, rad
    contact: np.ndarray               # N(φ) at the cam's speed
    contact_max_speed: np.ndarray     # N(φ) at speed_max
    normal: np.ndarray | None         # force normal to the profile, N (translating follower)
    torque: np.ndarray                # cam torque T(φ) at the cam's speed, N·m
    contact_min: tuple[float, float]  # (least N, its φ) at the cam's speed
    jump_speed: float                 # rad/s (inf: never leaves)
    jump_phi: float                   # cam angle where the jump starts, rad
    torque_extremes: tuple[float, float, float, float]   # T max, its φ, T min, its φ
    torque_mean: float
    elastic: ElasticResult | None = None


def _terms(d: FollowerDynamics, s: np.ndarray, s1: np.ndarray, s2: np.ndarray, w_max: float
           ) -> np.ndarray:
    """The least of m·ω²·s″ + c·ω·s′ over 0 ≤ ω ≤ ω_max at each cam angle."""
    a, b = d.mass * s2, d.damping * s1
    low = np.minimum(0.0, a * w_max ** 2 + b * w_max)
    with np.errstate(divide="ignore", invalid="ignore"):
        vertex = np.where(a > 0, -b / (2 * a), -1.0)
    inside = (vertex > 0) & (vertex < w_max)
    return np.where(inside, np.minimum(low, a * vertex ** 2 + b * vertex), low)


def choose_spring(d: FollowerDynamics, s: np.ndarray, s1: np.ndarray, s2: np.ndarray,
                  stroke: float, w_max: float, key: str = "dynamics") -> tuple[float, float]:
    """(k, F0) keeping N ≥ margin up to ω_max with the least mean spring force over the stroke,
    F0 + k·h/2; given values are kept (the other is then the least that holds)."""
    need = d.margin - d.load - _terms(d, s, s1, s2, w_max)      # F0 + k·s ≥ need
    k, f0 = d.stiffness, d.preload
    if k is not None and f0 is not None:
        return k, f0
    if k is not None:
        return k, max(0.0, float(np.max(need - k * s)))
    if f0 is not None:
        at_rest = s <= 1e-12 * stroke
        if np.any(need[at_rest] > f0 * (1 + 1e-12) + 1e-12):
            raise SceneError(
                Text(
                    "errmsg.synthesis_cam_dynamics.too_small_near",
                    {"need": f"{float(np.max(need[at_rest])):.6g}"},
                ),
                key=f"{key}.preload",
            )
        moving = ~at_rest
        return max(0.0, float(np.max((need[moving] - f0) / s[moving]))) if moving.any() \
            else 0.0, f0
    res = linprog(c=[1.0, stroke / 2], A_ub=np.column_stack([-np.ones_like(s), -s]), b_ub=-need,
                  bounds=[(0, None), (0, None)], method="highs")
    if not res.success:  # pragma: no cover - the problem is always feasible
        raise SceneError(
            Text("errmsg.synthesis_cam_dynamics.no_spring_found", {"message": str(res.message)}),
            key=f"{key}.stiffness",
        )
    f0, k = (float(v) for v in res.x)
    tiny = 1e-9 * max(1.0, float(np.max(np.abs(need))))      # the solver's round-off
    return (0.0 if k * stroke < tiny else k), (0.0 if f0 < tiny else f0)


def _root(a: float, b: float, c0: float, tol: float = 0.0) -> float:
    """The least ω > 0 with a·ω² + b·ω + c0 = 0 where the value turns negative (inf: none);
    |c0| ≤ ``tol`` counts as touching at rest (N = 0 is still contact)."""
    if c0 < -tol:
        return 0.0
    if c0 <= tol:
        if b < 0 or (b == 0 and a < 0):
            return 0.0
        return -b / a if a < 0 else math.inf
    if a == 0:
        return -c0 / b if b < 0 else math.inf
    disc = b * b - 4 * a * c0
    if a < 0:
        return (-b - math.sqrt(disc)) / (2 * a)
    if b >= 0 or disc < 0:
        return math.inf
    q = -0.5 * (b - math.sqrt(disc))          # stable: roots q/a and c0/q, both positive
    return min(q / a, c0 / q)


def jump_speed(spec: CamSpec, d: FollowerDynamics, k: float, f0: float,
               phi: np.ndarray) -> tuple[float, float]:
    """The least cam speed at which the contact force reaches zero, and the cam angle."""
    tol = 1e-9 * (abs(k * spec.stroke) + abs(f0) + abs(d.load))
    eps = 1e-12 * spec.stroke

    def coefficients(p: np.ndarray | float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        m = motion(spec.phases, spec.stroke, p)
        s = np.where(np.abs(m.s) < eps, 0.0, m.s)              # round-off at the phase ends
        s1 = np.where(np.abs(m.s1) < eps, 0.0, m.s1)
        return d.mass * m.s2, d.damping * s1, k * s + f0 + d.load

    def at(p: float) -> float:
        a, b, c0 = (float(v[0]) for v in coefficients(p))
        return min(1e30, _root(a, b, c0, tol))                 # finite for Brent

    roots = np.array([_root(a, b, c0, tol) for a, b, c0 in zip(*coefficients(phi), strict=True)])
    j = int(np.argmin(roots))
    if not math.isfinite(roots[j]):
        return math.inf, math.nan
    step = float(phi[1] - phi[0])
    lo, hi = float(phi[j]) - step, float(phi[j]) + step
    best = minimize_scalar(at, bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-12})
    if best.success and best.fun < roots[j]:
        return float(best.fun), float(np.mod(best.x, 2 * math.pi))
    return float(roots[j]), float(phi[j])


def follower_dynamics(spec: CamSpec, phi: np.ndarray, alpha: np.ndarray | None
                      ) -> DynamicsResult | None:
    """Everything the report and sheet say about the follower's dynamics (None: no table)."""
    d = spec.dynamics
    if d is None:
        return None
    w = spec.omega
    w_max = d.speed_max if d.speed_max is not None else w
    m = motion(spec.phases, spec.stroke, phi)
    k, f0 = choose_spring(d, m.s, m.s1, m.s2, spec.stroke, w_max)

    def contact(speed: float) -> np.ndarray:
        return d.mass * speed ** 2 * m.s2 + d.damping * speed * m.s1 + k * m.s + f0 + d.load

    n = contact(w)
    torque = n * m.s1
    j_min, j_tmax, j_tmin = int(np.argmin(n)), int(np.argmax(torque)), int(np.argmin(torque))
    ws, wphi = jump_speed(spec, d, k, f0, phi)
    normal = n / np.cos(alpha) if alpha is not None else None
    return DynamicsResult(
        stiffness=k, preload=f0, spring_max=f0 + k * spec.stroke,
        chosen=d.stiffness is None or d.preload is None, speed=w, speed_max=w_max, phi=phi,
        contact=n, contact_max_speed=contact(w_max), normal=normal, torque=torque,
        contact_min=(float(n[j_min]), float(phi[j_min])), jump_speed=ws, jump_phi=wphi,
        torque_extremes=(float(torque[j_tmax]), float(phi[j_tmax]), float(torque[j_tmin]),
                         float(phi[j_tmin])),
        torque_mean=float(np.mean(torque)),
        elastic=(elastic_follower(spec, d.follower_stiffness, d.damping_ratio)
                 if d.follower_stiffness is not None else None))
