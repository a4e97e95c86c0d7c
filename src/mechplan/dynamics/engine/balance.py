"""Balancing of an engine: free forces and moments of the rotating masses and of every harmonic
order of the reciprocating masses, exact (harmonic analysis of the exact piston accelerations) and
by the λ-series; counterweights on the cheeks; Lanchester balance shafts for the 2nd order.

Frame: x along cylinder 1's axis (outwards, towards its TDC), y a quarter turn further in the sense
of rotation, z along the crankshaft. A force of order k is written F(φ) = Re(e^{ikφ}·C) with
C ∈ ℂ² (one complex amplitude per component); it is the sum of a vector turning with the crank at
kω (magnitude |f|, f = (C_x + iC_y)/2) and one turning against it (|b|, b = (C_x − iC_y)/2).
A free moment is M = Σ (z_i − z_0)·F_i about the middle z_0 of the crankshaft: the couple acting in
the plane through the crankshaft axis and the direction of M.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...model.engine_balance import BalanceSpec
from .analysis import PinLoad
from .model import EngineModel

Array = np.ndarray
N_FFT = 512


def extremes(C: Array) -> tuple[float, float]:
    """Largest and smallest |Re(e^{iθ}·C)| over θ (the ellipse's semi-axes): the singular values
    of [Re C, Im C]."""
    m = np.array([[C[0].real, C[0].imag], [C[1].real, C[1].imag]])
    s = np.linalg.svd(m, compute_uv=False)
    return float(s[0]), float(s[1])


def course(C: Array, k: int, phi: Array) -> Array:
    """The vector Re(e^{ikφ}·C) at crank angles φ, shape (N, 2)."""
    e = np.exp(1j * k * np.asarray(phi, float))
    return np.stack([(e * C[0]).real, (e * C[1]).real], axis=1)


def turning(C: Array) -> tuple[complex, complex]:
    """(f, b): the parts turning with the crank and against it (|f|, |b| are their magnitudes)."""
    return complex((C[0] + 1j * C[1]) / 2.0), complex((C[0] - 1j * C[1]) / 2.0)


def axis_of(model: EngineModel, number: int) -> Array:
    """Unit vector of cylinder ``number``'s axis (outwards) in the engine frame."""
    bank = {c.number: c.bank for c in model.spec.cylinders}
    g = bank[number] - bank[1]
    return np.array([math.cos(g), math.sin(g)])


def crank_lag(model: EngineModel, number: int) -> float:
    """Angle by which the crank of cylinder ``number`` follows crank 1 (rad)."""
    throw = {c.number: c.throw for c in model.spec.cylinders}
    return throw[number] - throw[1]


def exact_accelerations(model: EngineModel, phi: Array) -> dict[int, Array]:
    """Exact piston accelerations d²x/dt² (x towards the crankshaft) at engine crank angles φ."""
    out = {}
    for c in model.spec.cylinders:
        art = model.articulated.get(c.number)
        if art is not None:
            assert model.group is not None
            st = model.group.state(phi - art.offset)
            out[c.number] = -(st.a_E[art.slot] @ model.group.slaves[art.slot].u)
        else:
            out[c.number] = model.kin.a(np.mod(phi - model.phases[c.number], 2.0 * math.pi),
                                        model.omega)
    return out


def harmonics(a: Array) -> Array:
    """Complex amplitudes c_k (k = 0 … N/2) of a periodic sample a(2πn/N) = Σ Re(c_k e^{ikφ})."""
    n = a.shape[0]
    c = np.fft.rfft(a) * (2.0 / n)
    c[0] /= 2.0
    return c


def series_harmonics(model: EngineModel, number: int) -> dict[int, complex]:
    """The λ-series amplitudes of a cylinder: Rω²·e^{−iδ} (1st order), λRω²·e^{−2iδ} (2nd)."""
    rw2 = model.spec.R * model.omega ** 2
    d = model.phases[number]
    return {1: rw2 * complex(np.exp(-1j * d)), 2: model.kin.lam * rw2 * complex(np.exp(-2j * d))}


@dataclass(frozen=True)
class OrderBalance:
    """One harmonic order of the reciprocating masses: free force and moment amplitudes."""

    k: int
    F: Array                         # C of the free force (N)
    M: Array                         # C of the free moment (N·m)
    F_series: Array | None           # by the λ-series (orders 1, 2)
    M_series: Array | None
    A: float                         # |c_k|/(Rω²) of cylinder 1 (exact)
    A_series: float | None           # 1 or λ

    @property
    def F_max(self) -> float:
        return extremes(self.F)[0]

    @property
    def M_max(self) -> float:
        return extremes(self.M)[0]


@dataclass(frozen=True)
class Counterweights:
    """Counterweights opposite every throw's crank (two cheeks per throw)."""

    share: float
    reduced: dict[int, float]        # pin → mass reduced to R of the throw's counterweights, kg
    per_cheek: dict[int, float]      # pin → m·r of one cheek, kg·m
    mass: dict[int, float] | None    # pin → mass of one cheek at the given radius, kg
    journals_before: Array           # (J, N, 2) journal loads with the scene's counterweights
    journals_after: Array


@dataclass(frozen=True)
class BalanceShafts:
    """Two shafts at 2ω cancelling the 2nd-order free force (exact amplitude)."""

    mr_with: float                   # m·r of the shaft turning with the crank, kg·m
    angle_with: float                # its mass's angle from x at φ = 0, rad
    mr_against: float                # of the shaft turning against it
    angle_against: float


@dataclass(frozen=True)
class Balance:
    """Free forces and moments of an engine, its counterweights and balance shafts."""

    positions: dict[int, float]      # pin → z (m)
    spacing_given: bool
    z0: float
    rotating_F: Array                # first-order C of the rotating masses (scene's counterweights)
    rotating_M: Array
    orders: dict[int, OrderBalance]
    counterweights: Counterweights
    after_F: Array                   # first order, rotating + reciprocating, with the sized weights
    after_M: Array
    before_F: Array                  # the same with the scene's counterweights
    before_M: Array
    shafts: BalanceShafts | None
    total_exact: Array               # (N, 2) reciprocating free force over one turn, exact
    total_series: Array              # the same with the 1st and 2nd orders of the λ-series
    residual: float                  # max |exact − Σ reported orders| (the orders left out), N
    terms: dict[int, Array]          # cylinder → m_j·c_k (k = 0 … orders): its share of each order
    arms: dict[int, float]           # cylinder → z − z0


def positions_of(model: EngineModel, spec: BalanceSpec) -> tuple[dict[int, float], bool]:
    """Axial position of every pin (unit spacing when the scene gives none)."""
    pins = sorted(model.pins)
    if spec.positions is not None:
        return dict(zip(pins, spec.positions, strict=True)), True
    return {p: float(i) for i, p in enumerate(pins)}, False


def rod_plane(model: EngineModel, spec: BalanceSpec, number: int) -> float:
    """Axial offset of a cylinder's rod from its pin's middle: side-by-side rods of a shared pin
    at −``rod_offset``/2 (the first) and +``rod_offset``/2 (the second), else 0."""
    for members in model.pins.values():
        if number in members and len(members) == 2 and not model.articulated:
            return spec.rod_offset * (members.index(number) - 0.5)
    return 0.0


def _rot(mass_r: float, lag: float) -> Array:
    """C of a rotating force m·r·ω²… (ω² left out) of a mass at angle φ − lag."""
    return mass_r * complex(np.exp(-1j * lag)) * np.array([1.0, -1j])


def journal_loads_with(model: EngineModel, phi: Array, pins: dict[int, PinLoad],
                       reduced: dict[int, float]) -> Array:
    """Main-journal loads as :func:`analysis.journal_loads` with counterweights ``reduced``
    (pin → mass reduced to R)."""
    spec = model.spec
    w2 = spec.R * model.omega ** 2
    W = []
    for pin in sorted(pins):
        theta = phi - crank_lag(model, model.pins[pin][0])
        r = np.stack([np.cos(theta), np.sin(theta)], axis=1)
        t = np.stack([-np.sin(theta), np.cos(theta)], axis=1)
        q = pins[pin]
        outward = -q.Q_Z + (spec.masses.crank - reduced[pin]) * w2
        W.append(q.Q_T[:, None] * t + outward[:, None] * r)
    zero = np.zeros_like(W[0])
    return np.stack([0.5 * ((W[j - 1] if j > 0 else zero) + (W[j] if j < len(W) else zero))
                     for j in range(len(W) + 1)])


def balance(model: EngineModel, spec: BalanceSpec, phi: Array, pins: dict[int, PinLoad]) -> Balance:
    """Balance an engine; ``phi``/``pins``: the dense grid and its pin loads (journal loads)."""
    eng = model.spec
    R, w2 = eng.R, model.omega ** 2
    pos, given = positions_of(model, spec)
    z0 = 0.5 * (min(pos.values()) + max(pos.values()))
    pin_of = {c: p for p, members in model.pins.items() for c in members}
    arm = {c.number: pos[pin_of[c.number]] - z0 + rod_plane(model, spec, c.number)
           for c in eng.cylinders}
    grid = np.arange(N_FFT) * 2.0 * math.pi / N_FFT
    acc = exact_accelerations(model, grid)
    coeff = {n: harmonics(a) for n, a in acc.items()}
    top = max(2, spec.orders)
    orders = {}
    for k in range(1, top + 1):
        F = np.zeros(2, complex)
        M = np.zeros(2, complex)
        Fs = np.zeros(2, complex)
        Ms = np.zeros(2, complex)
        for c in eng.cylinders:
            u = axis_of(model, c.number) * model.m_j[c.number]
            F += coeff[c.number][k] * u
            M += coeff[c.number][k] * u * arm[c.number]
            if k <= 2:
                s = series_harmonics(model, c.number)[k]
                Fs += s * u
                Ms += s * u * arm[c.number]
        orders[k] = OrderBalance(k, F, M, Fs if k <= 2 else None, Ms if k <= 2 else None,
                                 float(abs(coeff[1][k]) / (R * w2)),
                                 (1.0, model.kin.lam)[k - 1] if k <= 2 else None)
    # rotating masses: the rods' big ends on their cranks, each throw's crank and counterweight
    rotF = np.zeros(2, complex)
    rotM = np.zeros(2, complex)
    for c in eng.cylinders:
        C = _rot(model.m_rot[c.number] * R * w2, crank_lag(model, c.number))
        rotF += C
        rotM += C * arm[c.number]
    lead = {p: members[0] for p, members in model.pins.items()}
    cw_F = np.zeros(2, complex)
    cw_M = np.zeros(2, complex)
    scene_cw_F = np.zeros(2, complex)
    scene_cw_M = np.zeros(2, complex)
    reduced, per_cheek = {}, {}
    for p, members in model.pins.items():
        lag = crank_lag(model, lead[p])
        unbal = _rot((eng.masses.crank - eng.masses.counterweight) * R * w2, lag)
        scene_cw_F += unbal
        scene_cw_M += unbal * (pos[p] - z0)
        need = (sum(model.m_rot[c] + spec.share * model.m_j[c] for c in members)
                + eng.masses.crank)
        reduced[p] = need
        per_cheek[p] = need * R / 2.0
        C = _rot((eng.masses.crank - need) * R * w2, lag)
        cw_F += C
        cw_M += C * (pos[p] - z0)
    mass = ({p: v / spec.cw_radius for p, v in per_cheek.items()}
            if spec.cw_radius is not None else None)
    before = journal_loads_with(model, phi, pins, {p: eng.masses.counterweight for p in pins})
    after = journal_loads_with(model, phi, pins, reduced)
    cws = Counterweights(spec.share, reduced, per_cheek, mass, before, after)
    first = orders[1]
    shafts = None
    if spec.shafts:
        f, b = turning(orders[2].F)
        shafts = BalanceShafts(abs(f) / (4.0 * w2), math.atan2(f.imag, f.real) + math.pi,
                               abs(b) / (4.0 * w2), -math.atan2(b.imag, b.real) + math.pi)
    exact = sum(np.outer(a, axis_of(model, n) * model.m_j[n]) for n, a in acc.items())
    series = np.zeros((N_FFT, 2))
    for c in eng.cylinders:
        sh = series_harmonics(model, c.number)
        u = axis_of(model, c.number) * model.m_j[c.number]
        for k in (1, 2):
            series += course(sh[k] * u, k, grid)
    rebuilt = sum(course(o.F, o.k, grid) for o in orders.values())
    total0 = sum(coeff[n][0] * axis_of(model, n) * model.m_j[n] for n in acc).real
    residual = float(np.max(np.abs(exact - rebuilt - total0)))
    return Balance(pos, given, z0, rotF + scene_cw_F, rotM + scene_cw_M, orders, cws,
                   rotF + cw_F + first.F, rotM + cw_M + first.M,
                   rotF + scene_cw_F + first.F, rotM + scene_cw_M + first.M, shafts,
                   np.asarray(exact), series, residual,
                   {n: model.m_j[n] * coeff[n][:top + 1] for n in coeff}, arm)
