"""The single-mass elastic follower (DYNACAM's one-degree-of-freedom model): the follower's mass m
on a stiffness k (the follower train's elasticity) and a viscous damper c driven by the cam's
displacement s(t) at constant cam speed ω:

    m·ẍ + c·(ẋ − ṡ) + k·(x − s) = 0,  t = φ/ω,  ω_n = √(k/m), ζ = c/(2√(k·m)).

The error e = x − s obeys ë + 2ζω_n·ė + ω_n²·e = −s̈. Integrated from rest (e = ė = 0) over a number
of cam turns by an explicit Runge–Kutta method of order 8 (scipy's DOP853, steps no longer than a
tenth of the natural period); reported: the natural frequency, the largest |e| during the last turn
and the residual vibration at the start of each dwell, amplitude √(e² + (ė/ω_d)²) with
ω_d = ω_n·√(1 − ζ²) — for an undamped cycloidal rise of duration T started from rest, it is
h·|sin πλ|/(πλ·|1 − λ²|) with λ = T·ω_n/(2π) (a test checks it).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ...model.cam import CamSpec, PhaseKind
from .motion import motion, phase_starts


@dataclass(frozen=True)
class ElasticResult:
    """The elastic follower's response (SI; e in the stroke's unit)."""

    natural_frequency: float              # ω_n, rad/s
    damping_ratio: float
    phi: np.ndarray                       # cam angles of the last turn, rad
    error: np.ndarray                     # e = x − s over the last turn
    error_max: float
    residual: tuple[tuple[str, float, float], ...]   # (dwell kind, its start φ, amplitude)
    first_residual: tuple[tuple[str, float, float], ...]   # the same in the first turn


def elastic_follower(spec: CamSpec, stiffness: float, damping_ratio: float, turns: int = 3,
                     points: int = 3600) -> ElasticResult:
    """Integrate the error equation over ``turns`` cam turns from rest."""
    d = spec.dynamics
    assert d is not None
    m, w = d.mass, spec.omega
    wn = math.sqrt(stiffness / m)
    zeta = damping_ratio
    wd = wn * math.sqrt(max(1.0 - zeta * zeta, 1e-12))

    period = 2 * math.pi / w
    starts = phase_starts(spec.phases)
    # s̈ tabulated finely inside each phase (its pieces are smooth there), read by interpolation
    grids = []
    for i in range(len(spec.phases)):
        g = np.linspace(starts[i], starts[i + 1], 20001)
        inner = np.clip(g, starts[i] + 1e-12, starts[i + 1] - 1e-12)   # inside this phase
        grids.append((g, motion(spec.phases, spec.stroke, inner).s2 * w * w))
    current: list[tuple[np.ndarray, np.ndarray]] = [grids[0]]

    def rhs(t: float, y: np.ndarray) -> list[float]:
        g, a = current[0]
        s2 = float(np.interp(math.fmod(w * t, 2 * math.pi), g, a))
        return [y[1], -2 * zeta * wn * y[1] - wn * wn * y[0] - s2]

    # integrate phase by phase (the law's pieces are smooth inside each phase)
    bounds = sorted({float(t) for k in range(turns) for t in (starts + 2 * math.pi * k) / w})
    y = np.zeros(2)
    t_all: list[np.ndarray] = []
    e_all: list[np.ndarray] = []
    states: dict[float, np.ndarray] = {}
    for t0, t1 in itertools.pairwise(bounds):
        states[t0] = y.copy()
        mid = math.fmod(w * 0.5 * (t0 + t1), 2 * math.pi)
        current[0] = grids[int(np.searchsorted(starts, mid, side="right")) - 1]
        n = max(3, int(points * (t1 - t0) / period))
        sol = solve_ivp(rhs, (t0, t1), y, method="DOP853", rtol=1e-11, atol=1e-14 * spec.stroke,
                        t_eval=np.linspace(t0, t1, n))
        y = sol.y[:, -1]
        t_all.append(sol.t)
        e_all.append(sol.y[0])
    states[bounds[-1]] = y.copy()
    t = np.concatenate(t_all)
    e = np.concatenate(e_all)
    last = t >= (turns - 1) * period - 1e-12

    def dwells(turn: int) -> tuple[tuple[str, float, float], ...]:
        out = []
        for i, p in enumerate(spec.phases):
            if p.kind in (PhaseKind.FAR_DWELL, PhaseKind.NEAR_DWELL):
                key = min(states, key=lambda tt: abs(tt - (starts[i] + 2 * math.pi * turn) / w))
                ee, ev = states[key]
                out.append((p.kind.value, float(starts[i]), float(math.hypot(ee, ev / wd))))
        return tuple(out)

    return ElasticResult(wn, zeta, np.mod(w * t[last], 2 * math.pi), e[last],
                         float(np.max(np.abs(e[last]))), dwells(turns - 1), dwells(0))
