"""An optional smooth indicator diagram: single-zone Wiebe heat release integrated over the closed
part of the cycle (from the BDC that ends the intake to the BDC that ends the expansion).

Model (stated choices): the charge of the thermal calculation (p_a, T_a, γ_r: n = p_a·V_a/(R·T_a)
kmol, of which n/(1 + γ_r) fresh, i.e. n/((1 + γ_r)·M1) kg of fuel) releases
Q = ξ_z·(H_u − ΔH_u)·m_fuel after the Wiebe law x(φ) = 1 − exp(−a·((φ − φ_s)/Δφ)^(m+1)); the gas is
ideal with U = pV/(k − 1), its ratio k going from the compression polytrope n1 to the expansion
polytrope n2 with the burnt fraction, k = n1 + (n2 − n1)·x (the walls' heat folded into the
polytropes as the courses do). The first law dQ = dU + p dV then reads

    V·dp/dφ = (k − 1)·dQ/dφ − k·p·dV/dφ + p·V·(dk/dφ)/(k − 1),

so before combustion the pressure follows p·V^n1 = const and after it p·V^n2 = const; the exact
slider-crank volume V(φ) = V_c + V_h/2·[1 − cos φ + (1 − √(1 − λ² sin² φ))/λ]. A four-stroke
cycle is closed by intake at p_a and exhaust at p_r, the pressure moving linearly within ``BLEND``
after the BDC and TDC where the sharp-cornered diagram has its vertical lines; a two-stroke cycle
(0 … 2π from the combustion TDC: expansion, then compression) by the scavenging drop from p_b to
p_a within ``BLEND`` after the BDC, where the courses' two-stroke diagram has its vertical b–a.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

R_J = 8314.5                 # J/(kmol·K)
BLEND = math.radians(2.0)    # rad, the gas exchange's pressure steps


@dataclass(frozen=True, slots=True)
class WiebeSpec:
    """Start of combustion before TDC (rad, may be negative: after TDC), duration (rad), the
    shape exponent m and the completeness a (6.908: 99.9 % burnt at the end)."""

    start: float
    duration: float
    m: float = 1.5
    a: float = 6.908


@dataclass(frozen=True, slots=True)
class Wiebe:
    """The integrated closed cycle and its checks (SI; φ of the closed part from the intake TDC
    of a four-stroke cycle, combustion TDC at 2π, for either cycle; ``rows`` and ``peak`` in the
    engine's own cycle angle: 0 … 4π, or 0 … 2π from the combustion TDC of a two-stroke)."""

    spec: WiebeSpec
    phi: np.ndarray              # rad, closed part π … 3π
    V: np.ndarray                # m³
    p: np.ndarray                # Pa
    x: np.ndarray                # burnt fraction
    Q: float                     # J, heat released per cycle (per m³ of V_h when V_h = 1)
    work: float                  # J, ∮p dV of the closed part (likewise)
    dU: float                    # J, U(3π) − U(π) (likewise)
    p_i: float                   # Pa, work / V_h
    rows: tuple[tuple[float, float], ...]   # (φ, p) over the whole cycle for the dynamics
    strokes: int = 4

    @property
    def residual(self) -> float:
        """Q − ΔU − W: the first law over the integration (J)."""
        return self.Q - self.dU - self.work

    @property
    def peak(self) -> tuple[float, float]:
        """(p_max Pa, φ at the maximum rad, in the engine's cycle angle)."""
        k = int(np.argmax(self.p))
        phi = float(self.phi[k])
        return float(self.p[k]), phi if self.strokes == 4 else phi % (2.0 * math.pi)

    @property
    def phi_cycle(self) -> np.ndarray:
        """φ of the closed part in the engine's cycle angle (a two-stroke's −π … π about its
        combustion TDC)."""
        return self.phi if self.strokes == 4 else self.phi - 2.0 * math.pi


def burnt(phi: np.ndarray | float, phi_s: float, spec: WiebeSpec) -> np.ndarray:
    """x(φ) of the Wiebe law (0 before φ_s, 1 − e^(−a) at φ_s + Δφ, growing on after it)."""
    s = np.clip((np.asarray(phi, float) - phi_s) / spec.duration, 0.0, None)
    return np.asarray(1.0 - np.exp(-spec.a * s ** (spec.m + 1.0)))


def _rate(phi: float, phi_s: float, spec: WiebeSpec) -> float:
    """dx/dφ."""
    s = (phi - phi_s) / spec.duration
    if s <= 0.0:
        return 0.0
    return float(spec.a * (spec.m + 1.0) / spec.duration * s ** spec.m
                 * math.exp(-spec.a * s ** (spec.m + 1.0)))


def volume(phi: np.ndarray | float, V_h: float, epsilon: float, lam: float) -> np.ndarray:
    """Exact slider-crank cylinder volume (λ = 0: the harmonic limit)."""
    f = np.asarray(phi, float)
    V_c = V_h / (epsilon - 1.0)
    rod = (1.0 - np.sqrt(1.0 - (lam * np.sin(f)) ** 2)) / lam if lam > 0 else 0.0 * f
    return np.asarray(V_c + V_h / 2.0 * (1.0 - np.cos(f) + rod))


def _dV(phi: float, V_h: float, lam: float) -> float:
    s, c = math.sin(phi), math.cos(phi)
    return V_h / 2.0 * (s + lam * s * c / math.sqrt(1.0 - (lam * s) ** 2))


def wiebe_cycle(V_h: float, epsilon: float, lam: float, p_a: float, T_a: float, p_r: float,
                n1: float, n2: float, Q: float, spec: WiebeSpec, step: float = math.radians(0.5),
                strokes: int = 4) -> Wiebe:
    """Integrate the closed part for heat Q (J per cycle) and build the whole cycle's p(φ) of a
    four- or two-stroke engine (``strokes``)."""
    phi_s = 2.0 * math.pi - spec.start
    phi_e = phi_s + spec.duration

    def k_of(x: float) -> float:
        return n1 + (n2 - n1) * x

    def rhs(phi: float, y: np.ndarray) -> list[float]:
        p = y[0]
        x = float(burnt(phi, phi_s, spec))
        dx = _rate(phi, phi_s, spec)
        k = k_of(x)
        V = float(volume(phi, V_h, epsilon, lam))
        dp = ((k - 1.0) * Q * dx - k * p * _dV(phi, V_h, lam)
              + p * V * (n2 - n1) * dx / (k - 1.0)) / V
        return [dp]

    knots = [math.pi, phi_s, phi_e, 3.0 * math.pi]
    phis: list[np.ndarray] = []
    ps: list[np.ndarray] = []
    p0 = p_a
    for a, b in itertools.pairwise(knots):
        n = max(2, math.ceil((b - a) / step) + 1)
        grid = np.linspace(a, b, n)
        sol = solve_ivp(rhs, (a, b), [p0], method="DOP853", t_eval=grid, rtol=1e-11,
                        atol=1e-6, max_step=step)
        phis.append(sol.t if not phis else sol.t[1:])
        ps.append(sol.y[0] if not ps else sol.y[0][1:])
        p0 = float(sol.y[0][-1])
    phi = np.concatenate(phis)
    p = np.concatenate(ps)
    V = volume(phi, V_h, epsilon, lam)
    x = burnt(phi, phi_s, spec)
    k = n1 + (n2 - n1) * x
    U = p * V / (k - 1.0)
    work = _work(phi, p, V_h, epsilon, lam, knots)
    rows = _rows(phi, p, p_a, p_r) if strokes == 4 else _rows_two_stroke(phi, p)
    return Wiebe(spec, phi, V, p, x, Q, work, float(U[-1] - U[0]), work / V_h, rows, strokes)


def _work(phi: np.ndarray, p: np.ndarray, V_h: float, epsilon: float, lam: float,
          knots: list[float]) -> float:
    """∫p dV by Simpson's rule on each smooth piece (the grid is uniform within a piece)."""
    from scipy.integrate import simpson

    total = 0.0
    for a, b in itertools.pairwise(knots):
        m = (phi >= a - 1e-12) & (phi <= b + 1e-12)
        f = phi[m]
        dV = np.array([_dV(float(t), V_h, lam) for t in f])
        total += float(simpson(p[m] * dV, x=f))
    return total


def _rows(phi: np.ndarray, p: np.ndarray, p_a: float, p_r: float) -> tuple[tuple[float, float],
                                                                           ...]:
    """(φ, p) over 0 … 4π: intake at p_a, the closed part, exhaust at p_r."""
    pi = math.pi
    rows = [(0.0, p_r), (BLEND, p_a), (pi, p_a)]
    rows += [(float(f), float(q)) for f, q in zip(phi[1:-1], p[1:-1])]
    rows += [(3.0 * pi, float(p[-1])), (3.0 * pi + BLEND, p_r), (4.0 * pi, p_r)]
    return tuple(rows)


def _rows_two_stroke(phi: np.ndarray, p: np.ndarray) -> tuple[tuple[float, float], ...]:
    """(φ, p) over 0 … 2π from the combustion TDC: the expansion (closed part 2π … 3π), the
    scavenging drop from p_b to p_a within ``BLEND`` after the BDC, the compression (π … 2π)."""
    pi = math.pi
    p_tdc = float(np.interp(2.0 * pi, phi, p))
    later = (phi > 2.0 * pi) & (phi < 3.0 * pi)
    earlier = (phi > pi + BLEND) & (phi < 2.0 * pi)
    rows = [(0.0, p_tdc)]
    rows += [(float(f) - 2.0 * pi, float(q)) for f, q in zip(phi[later], p[later])]
    rows += [(pi, float(p[-1])), (pi + BLEND, float(np.interp(pi + BLEND, phi, p)))]
    rows += [(float(f), float(q)) for f, q in zip(phi[earlier], p[earlier])]
    rows.append((2.0 * pi, p_tdc))
    return tuple(rows)


def fuel_heat(p_a: float, T_a: float, V_a: float, gamma_r: float, M1: float, xi: float,
              H_u: float, dH_u: float) -> float:
    """Heat released per cycle (J): ξ·(H_u − ΔH_u) (kJ/kg) times the fuel of the fresh charge."""
    n = p_a * V_a / (R_J * T_a)
    return xi * (H_u - dH_u) * 1e3 * n / ((1.0 + gamma_r) * M1)
