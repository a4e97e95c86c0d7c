"""The indicator diagram p(V) of one cylinder over its cycle, and its transfer to the crank angle.

A diagram is a set of branches, one per stroke (four-stroke: intake, compression, expansion,
exhaust; two-stroke: expansion, compression), each a piecewise function p(V) on [V_c, V_a]. It comes
from the thermal calculation (:func:`thermal_diagram`: the Grinevetsky–Mazing construction with the
corners rounded) or from a measured table (:func:`volume_table_diagram`,
:func:`angle_table_diagram`). Any crank mechanism then gives p(φ): the stroke from φ, V from the
piston travel — so the machine-dynamics code can call :meth:`IndicatorDiagram.at_phi` with its own
kinematics. Pressures are absolute (Pa), volumes m³, angles rad from the TDC that opens the intake
(4-stroke) or from the TDC of combustion (2-stroke).
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..i18n import Text
from ..model.engine import ThermalSpec
from .engine.kinematics import SliderCrank

Array = np.ndarray
_GL_X, _GL_W = np.polynomial.legendre.leggauss(40)


def gauss(f: Callable[[Array], Array], a: float, b: float) -> float:
    """∫_a^b f by 40-point Gauss–Legendre (exact for the smooth pieces used here)."""
    if b == a:
        return 0.0
    x = 0.5 * (b - a) * _GL_X + 0.5 * (b + a)
    return float(0.5 * (b - a) * np.dot(_GL_W, f(x)))


class Piece(ABC):
    """p(V) on one interval of a branch (constant, polytropic, straight line …)."""

    @abstractmethod
    def __call__(self, V: Array) -> Array:
        """Pressure (Pa) at volumes V (m³)."""

    def integral(self, V0: float, V1: float) -> float:
        """∫ p dV over [V0, V1]."""
        return gauss(self, V0, V1)


@dataclass(frozen=True)
class Constant(Piece):
    """p = const."""

    p: float

    def __call__(self, V: Array) -> Array:
        return np.full_like(np.asarray(V, float), self.p)


@dataclass(frozen=True)
class Polytrope(Piece):
    """p = p_ref (V_ref/V)^n."""

    p_ref: float
    V_ref: float
    n: float

    def __call__(self, V: Array) -> Array:
        return self.p_ref * (self.V_ref / np.asarray(V, float)) ** self.n

    def slope(self, V: float) -> float:
        """dp/dV."""
        return -self.n * float(self(np.asarray(V))) / V


@dataclass(frozen=True)
class Hermite(Piece):
    """Cubic through (V0, p0) and (V1, p1) with slopes s0, s1 (the rounding of a corner)."""

    V0: float
    p0: float
    s0: float
    V1: float
    p1: float
    s1: float

    def __call__(self, V: Array) -> Array:
        h = self.V1 - self.V0
        t = (np.asarray(V, float) - self.V0) / h
        t2, t3 = t * t, t * t * t
        return ((2 * t3 - 3 * t2 + 1) * self.p0 + (t3 - 2 * t2 + t) * h * self.s0
                + (-2 * t3 + 3 * t2) * self.p1 + (t3 - t2) * h * self.s1)


@dataclass(frozen=True)
class Linear(Piece):
    """p linear in V between two table rows."""

    V0: float
    p0: float
    V1: float
    p1: float

    def __call__(self, V: Array) -> Array:
        return (self.p0 + (self.p1 - self.p0) * (np.asarray(V, float) - self.V0)
                / (self.V1 - self.V0))

    def integral(self, V0: float, V1: float) -> float:
        return float((self(np.asarray(V0)) + self(np.asarray(V1))) / 2.0 * (V1 - V0))


@dataclass(frozen=True)
class AngleLinear(Piece):
    """p linear in crank angle between two table rows, seen as a function of V on one stroke."""

    phi0: float
    p0: float
    phi1: float
    p1: float
    kin: SliderCrank
    V_c: float
    F_p: float
    descending: bool
    turn: float                          # 2π·k added to the stroke's crank angle

    def phi(self, V: Array) -> Array:
        """Crank angle of volume V on this stroke."""
        x = (np.asarray(V, float) - self.V_c) / self.F_p
        return self.kin.phi_of_x(x, self.descending) + self.turn

    def p_phi(self, phi: Array) -> Array:
        """p at crank angle φ."""
        return self.p0 + (self.p1 - self.p0) * (phi - self.phi0) / (self.phi1 - self.phi0)

    def __call__(self, V: Array) -> Array:
        return self.p_phi(self.phi(V))

    def integral(self, V0: float, V1: float) -> float:
        # substitute φ: V(φ) has a square-root turn at the dead centres
        a, b = float(self.phi(np.asarray(V0))), float(self.phi(np.asarray(V1)))
        return gauss(lambda f: self.p_phi(f) * self.F_p * self.kin.dx_dphi(f), a, b)


@dataclass(frozen=True)
class Branch:
    """p(V) on one stroke: pieces on consecutive V intervals (ascending), V rising or falling."""

    knots: tuple[float, ...]            # ascending V, len = pieces + 1
    pieces: tuple[Piece, ...]
    rising: bool

    def __call__(self, V: Array) -> Array:
        V = np.asarray(V, float)
        idx = np.clip(np.searchsorted(self.knots, V, side="right") - 1, 0, len(self.pieces) - 1)
        out = np.empty_like(V)
        for j, piece in enumerate(self.pieces):
            m = idx == j
            if m.any():
                out[m] = piece(V[m])
        return out

    def work(self) -> float:
        """∫ p dV along the stroke's direction."""
        total = sum(p.integral(a, b) for p, a, b in zip(self.pieces, self.knots, self.knots[1:]))
        return total if self.rising else -total


@dataclass(frozen=True)
class IndicatorDiagram:
    """Branches p(V) per stroke of one cylinder; V from V_c to V_a = V_c + V_h."""

    strokes: int
    V_c: float
    V_h: float
    branches: tuple[Branch, ...]
    names: tuple[str, ...]              # message ids of the strokes
    V_c_given: bool = True              # False: a p(φ) table without ε (V_c nominal, p–V unscaled)

    @property
    def V_a(self) -> float:
        """Volume at BDC."""
        return self.V_c + self.V_h

    @property
    def cycle(self) -> float:
        """Cycle angle (rad)."""
        return math.pi * self.strokes

    def pressure(self, V: Array, stroke: Array | int) -> Array:
        """p at volumes V on the given stroke(s) (arrays broadcast)."""
        V = np.asarray(V, float)
        stroke = np.broadcast_to(np.asarray(stroke), V.shape)
        out = np.empty_like(V)
        for k, br in enumerate(self.branches):
            m = stroke == k
            if m.any():
                out[m] = br(V[m])
        return out

    def pressure_xi(self, xi: Array, stroke: Array | int) -> Array:
        """p at the stroke fraction ξ = x/S (0 at TDC, 1 at BDC)."""
        return self.pressure(self.V_c + np.asarray(xi, float) * self.V_h, stroke)

    def stroke_of(self, phi: Array) -> Array:
        """Stroke index at crank angle φ (rad from the cycle's start)."""
        k = np.floor(np.mod(phi, self.cycle) / math.pi).astype(int)
        return np.minimum(k, self.strokes - 1)

    def at_phi(self, phi: Array, xi: Array) -> Array:
        """p(φ) given the stroke fraction ξ(φ) of the crank mechanism in use."""
        return self.pressure_xi(xi, self.stroke_of(phi))

    def work(self) -> float:
        """Indicated work of the cycle ∮ p dV (J), the area of the diagram."""
        return sum(br.work() for br in self.branches)

    def knots_xi(self, stroke: int) -> Array:
        """Stroke fractions where the branch's pieces meet (for exact quadrature)."""
        return (np.asarray(self.branches[stroke].knots) - self.V_c) / self.V_h

    def loop(self, n: int = 90) -> tuple[Array, Array]:
        """The closed p–V curve for drawing: V and p around the cycle."""
        Vs, ps = [], []
        for k, br in enumerate(self.branches):
            xi = (1.0 - np.cos(np.linspace(0.0, math.pi, n))) / 2.0
            V = self.V_c + (xi if br.rising else xi[::-1]) * self.V_h
            Vs.append(V)
            ps.append(self.pressure(V, k))
        return np.concatenate(Vs), np.concatenate(ps)


def _names(strokes: int) -> tuple[str, ...]:
    if strokes == 4:
        return ("engine.stroke.intake", "engine.stroke.compression", "engine.stroke.expansion",
                "engine.stroke.exhaust")
    return ("engine.stroke.expansion", "engine.stroke.compression")


def _branch(parts: Sequence[tuple[float, float, Piece]], rising: bool) -> Branch:
    parts = sorted((p for p in parts if p[1] > p[0]), key=lambda p: p[0])
    return Branch(tuple([parts[0][0]] + [p[1] for p in parts]), tuple(p[2] for p in parts), rising)


def thermal_diagram(spec: ThermalSpec, strokes: int, kin: SliderCrank,
                    F_p: float) -> IndicatorDiagram:
    """The Grinevetsky–Mazing diagram from the thermal calculation, corners rounded.

    Compression p_a(V_a/V)^n1, combustion at V_c (petrol) or at p_z to ρV_c (diesel), expansion
    p_z(ρV_c/V)^n2, exhaust at p_r. Rounding (cubic, tangent to the curves): from the ignition
    advance to p_c'' = tdc_fraction·p_c at TDC, from there to the real peak peak_fraction·p_z at
    peak_angle after TDC (zero slope) and back onto the expansion line at twice that angle; from
    the exhaust opening to (p_b + p_r)/2 at BDC and down to p_r 60° after BDC.
    """
    V_h = F_p * 2.0 * kin.R
    V_c = V_h / (spec.epsilon - 1.0)
    V_a = V_c + V_h

    def V(phi: float) -> float:
        return V_c + F_p * float(kin.x(np.asarray(phi)))

    comp = Polytrope(spec.p_a, V_a, spec.n1)
    p_c = float(comp(np.asarray(V_c)))
    V_z = spec.rho * V_c
    expa = Polytrope(spec.p_z, V_z, spec.n2)
    p_b = float(expa(np.asarray(V_a)))
    p_b2 = (p_b + spec.p_r) / 2.0
    if not spec.rounding:
        comp_parts: list[tuple[float, float, Piece]] = [(V_c, V_a, comp)]
        exp_parts: list[tuple[float, float, Piece]] = [(V_c, V_z, Constant(spec.p_z)),
                                                       (V_z, V_a, expa)]
        exh_parts: list[tuple[float, float, Piece]] = [(V_c, V_a, Constant(spec.p_r))]
    else:
        V_ign = V(spec.ignition_advance)
        p_tdc = spec.tdc_fraction * p_c
        comp_parts = [(V_ign, V_a, comp),
                      (V_c, V_ign, Hermite(V_c, p_tdc, comp.slope(V_c) * spec.tdc_fraction,
                                           V_ign, float(comp(np.asarray(V_ign))),
                                           comp.slope(V_ign)))]
        V_pk = V(spec.peak_angle)
        p_pk = spec.peak_fraction * spec.p_z
        V_j = max(V(2.0 * spec.peak_angle), V_z * (1.0 + 1e-9))
        V_bo = V(math.pi - spec.exhaust_opening)
        V_j = min(V_j, V_bo)
        p_j = float(expa(np.asarray(V_j)))
        exp_parts = [(V_c, V_pk, Hermite(V_c, p_tdc, (p_pk - p_tdc) / (V_pk - V_c) * 2.0,
                                         V_pk, p_pk, 0.0)),
                     (V_pk, V_j, Hermite(V_pk, p_pk, 0.0, V_j, p_j, expa.slope(V_j))),
                     (V_j, V_bo, expa),
                     (V_bo, V_a, Hermite(V_bo, float(expa(np.asarray(V_bo))), expa.slope(V_bo),
                                         V_a, p_b2, 0.0))]
        V_e = V(math.pi / 3.0)
        exh_parts = [(V_c, V_e, Constant(spec.p_r)),
                     (V_e, V_a, Hermite(V_e, spec.p_r, 0.0, V_a, p_b2, 0.0))]
    branches: tuple[Branch, ...]
    if strokes == 4:
        branches = (_branch([(V_c, V_a, Constant(spec.p_a))], True),
                    _branch(comp_parts, False), _branch(exp_parts, True), _branch(exh_parts, False))
    else:
        if spec.rounding:
            # two-stroke: scavenging ends 60° after BDC; round from (p_b + p_r)/2 onto compression
            V_s = V(math.pi / 3.0)
            comp_parts = [(V_c, V_ign, comp_parts[1][2]), (V_ign, V_s, comp),
                          (V_s, V_a, Hermite(V_s, float(comp(np.asarray(V_s))), comp.slope(V_s),
                                             V_a, p_b2, 0.0))]
        branches = (_branch(exp_parts, True), _branch(comp_parts, False))
    return IndicatorDiagram(strokes, V_c, V_h, branches, _names(strokes))


def _runs(values: Array) -> list[tuple[int, int]]:
    """Index ranges [i, j] of the monotone runs of a sequence."""
    d = np.sign(np.diff(values))
    runs, start = [], 0
    for i in range(1, len(d)):
        if d[i] != d[start] and d[i] != 0:
            runs.append((start, i))
            start = i
    runs.append((start, len(d)))
    return runs


def volume_table_diagram(rows: Sequence[tuple[float, float]], strokes: int, V_h: float,
                         file: str, key: str) -> IndicatorDiagram:
    """A measured p(V) table around the closed cycle, starting at the TDC that starts the cycle."""
    V = np.asarray([r[0] for r in rows], float)
    p = np.asarray([r[1] for r in rows], float)
    span = float(V.max() - V.min())
    if abs(V[0] - V[-1]) > 1e-6 * span or abs(p[0] - p[-1]) > 1e-6 * max(abs(p).max(), 1.0):
        raise SceneError(Text("errmsg.dynamics_indicator.p_v_table", {"v": f'{V[0]:g}',
                                                                      "p": f'{p[0]:g}',
                                                                      "v2": f'{V[-1]:g}',
                                                                      "p2": f'{p[-1]:g}'}),
                         file=file, key=key)
    runs = _runs(V)
    if len(runs) != strokes or not V[runs[0][1]] > V[runs[0][0]]:
        raise SceneError(Text("errmsg.dynamics_indicator.p_v_table2", {"strokes": str(strokes),
                                                                       "runs": str(len(runs))}),
                         file=file, key=key)
    if abs(span - V_h) > 0.01 * V_h:
        raise SceneError(Text("errmsg.dynamics_indicator.p_v_table3", {"v_h": f'{V_h:.6g}',
                                                                       "span": f'{span:.6g}'}),
                         file=file, key=key)
    V_c, V_a = float(V.min()), float(V.max())
    branches = []
    for i, j in runs:
        Vr, pr = V[i:j + 1], p[i:j + 1]
        rising = bool(Vr[-1] > Vr[0])
        if not rising:
            Vr, pr = Vr[::-1], pr[::-1]
        Vr = np.concatenate([[V_c], Vr, [V_a]])                  # reach both dead centres
        pr = np.concatenate([[pr[0]], pr, [pr[-1]]])
        keep = np.concatenate([[True], np.diff(Vr) > 0])
        Vr, pr = Vr[keep], pr[keep]
        parts = [(float(a), float(b), Linear(float(a), float(pa), float(b), float(pb)))
                 for a, b, pa, pb in zip(Vr, Vr[1:], pr, pr[1:])]
        branches.append(_branch(parts, rising))
    return IndicatorDiagram(strokes, V_c, V_a - V_c, tuple(branches), _names(strokes))


def angle_table_diagram(rows: Sequence[tuple[float, float]], strokes: int, kin: SliderCrank,
                        F_p: float, epsilon: float | None, file: str,
                        key: str) -> IndicatorDiagram:
    """A measured p(φ) table over the whole cycle (first row at 0, last at the cycle angle).

    p(φ) does not depend on V_c: without the compression ratio ``epsilon`` the diagram takes a
    nominal V_c = V_h (``V_c_given`` False), so only its p–V drawing lacks a volume origin.
    """
    phi = np.asarray([r[0] for r in rows], float)
    p = np.asarray([r[1] for r in rows], float)
    cycle = math.pi * strokes
    if abs(phi[0]) > 1e-9 or abs(phi[-1] - cycle) > 1e-9 or abs(p[0] - p[-1]) > 1e-6 * abs(p).max():
        raise SceneError(
            Text(
                "errmsg.dynamics_indicator.p_table_closed",
                {
                    "cycle": f"{math.degrees(cycle):g}",
                    "phi": f"{math.degrees(phi[0]):g}",
                    "phi2": f"{math.degrees(phi[-1]):g}",
                    "p": f"{p[0]:g}",
                    "p2": f"{p[-1]:g}",
                },
            ),
            file=file,
            key=key,
        )
    if np.any(np.diff(phi) <= 0):
        raise SceneError(Text("errmsg.dynamics_indicator.crank_angles_p"),
                         file=file, key=key)
    V_h = F_p * 2.0 * kin.R
    V_c = V_h / (epsilon - 1.0) if epsilon is not None else V_h
    nodes = np.union1d(phi, np.arange(strokes + 1) * math.pi)
    pn = np.interp(nodes, phi, p)
    branches = []
    for k in range(strokes):
        lo, hi = k * math.pi, (k + 1) * math.pi
        m = (nodes >= lo - 1e-12) & (nodes <= hi + 1e-12)
        f, q = nodes[m], pn[m]
        descending = k % 2 == 1
        turn = 2.0 * math.pi * (k // 2)
        parts = []
        for a, b, pa, pb in zip(f, f[1:], q, q[1:]):
            piece = AngleLinear(float(a), float(pa), float(b), float(pb), kin, V_c, F_p, descending,
                                turn)
            Va = V_c + F_p * float(kin.x(np.asarray(a)))
            Vb = V_c + F_p * float(kin.x(np.asarray(b)))
            parts.append((min(Va, Vb), max(Va, Vb), piece))
        branches.append(_branch(parts, not descending))
    return IndicatorDiagram(strokes, V_c, V_h, tuple(branches), _names(strokes),
                            epsilon is not None)
