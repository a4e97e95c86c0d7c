"""A master rod and its articulated rods on one crank pin, solved by mechplan's exact construction
(positions, velocities, accelerations of the pistons and of the lugs).

The linkage scene comes from :func:`mechplan.scene.engine_layout.group_linkage`: the master
cylinder (piston C) along +x, articulated cylinder k (lug Dk on the master rod, piston Ek) at its
bank angle, the crank turning counter-clockwise from +x. Angles given to this module are the
linkage's crank angles (from the master cylinder's axis); the engine model shifts them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ...construct.builder import build_construction
from ...construct.graph import Construction
from ...model.structure import analyse
from ...scene.spec import Scene

Array = np.ndarray
TURN = 2.0 * math.pi
HARMONIC_SAMPLES = 512        # samples per turn of the harmonic analysis (orders 1, 2 to ~1e-16)


@dataclass(frozen=True)
class GroupState:
    """Positions, velocities and accelerations (N, 2) of the group's points at crank angles φ;
    the articulated cylinders' points as tuples in slot order."""

    phi: Array
    B: Array
    C: Array
    v_C: Array
    a_C: Array
    D: tuple[Array, ...]
    E: tuple[Array, ...]
    v_E: tuple[Array, ...]
    a_E: tuple[Array, ...]


@dataclass(frozen=True)
class Slave:
    """One articulated cylinder's exact dead centres (linkage crank angles) and travel."""

    u: Array                        # its axis (outwards)
    phi_tdc: float
    phi_bdc: float
    s_tdc: float                    # distance of the piston pin from the crank axis at TDC
    s_bdc: float
    c1: complex = 0j                # orders 1 and 2 of that distance s(θ) = Σ Re(c_k e^{ikθ})
    c2: complex = 0j

    @property
    def stroke(self) -> float:
        """Stroke of the articulated piston (m)."""
        return self.s_tdc - self.s_bdc

    @property
    def R_eq(self) -> float:
        """|c1|: the crank radius of the piston's 1st-order motion (R of a central slider-crank)."""
        return abs(self.c1)

    @property
    def lam_eq(self) -> float:
        """4|c2|/|c1|: its 2nd order as a λ (λ + λ³/4 + … of a central slider-crank)."""
        return 4.0 * abs(self.c2) / abs(self.c1)

    def a_series(self, theta: Array, omega: float) -> Array:
        """Acceleration (towards the crank axis +) kept to orders 1 and 2 of the exact motion:
        ω²·[Re(c1 e^{iθ}) + 4 Re(c2 e^{2iθ})] at the linkage's crank angles θ."""
        t = np.asarray(theta, float)
        return omega * omega * np.real(self.c1 * np.exp(1j * t) + 4.0 * self.c2 * np.exp(2j * t))

    def xi_brix(self, psi: Array) -> Array:
        """Stroke fraction by Brix's construction drawn for this piston: a circle of radius R_eq,
        the pole shifted R_eq·λ_eq/2 towards BDC, the ray at ψ from the piston's own exact TDC."""
        lam = self.lam_eq
        sn = np.sin(np.asarray(psi, float))
        x = 1.0 - np.cos(psi) * np.sqrt(1.0 - lam * lam * sn * sn / 4.0) + lam / 2.0 * sn * sn
        return np.asarray(x / 2.0)


class ArticulatedGroup:
    """The exact kinematics of a master rod and its articulated rods on one crank pin."""

    def __init__(self, scene: Scene, slots: int) -> None:
        self.scene = scene
        self.slots = slots
        self.construction: Construction = build_construction(
            scene.mechanism, analyse(scene.mechanism), ("position", "velocity", "acceleration"),
            scene.assembly_phi, scene.path, None)
        guides = scene.mechanism.guides
        self.u_C = _unit(guides["Ax"].angle)
        grid = np.linspace(0.0, TURN, 721)[:-1]
        ev = self.construction.evaluate(grid)
        slaves = []
        for k in range(slots):
            u = _unit(guides[f"G{k + 1}"].angle)
            s = ev[self.construction.position(f"E{k + 1}")] @ u
            tdc = self._dead_centre(k, u, int(np.argmax(s)))
            bdc = self._dead_centre(k, u, int(np.argmin(s)))
            ext = self._travel(k, u, np.array([tdc, bdc]))[0]
            c1, c2 = self._orders(k, u)
            slaves.append(Slave(u, tdc, bdc, float(ext[0]), float(ext[1]), c1, c2))
        self.slaves: tuple[Slave, ...] = tuple(slaves)

    def state(self, phi: Array) -> GroupState:
        """Evaluate the group at crank angles φ (rad from the master cylinder's axis)."""
        c = self.construction
        ev = c.evaluate(np.mod(np.asarray(phi, float), TURN))
        names = range(1, self.slots + 1)
        return GroupState(np.asarray(phi, float), ev[c.position("B")], ev[c.position("C")],
                          ev[c.velocity_image("C")], ev[c.acceleration_image("C")],
                          tuple(ev[c.position(f"D{k}")] for k in names),
                          tuple(ev[c.position(f"E{k}")] for k in names),
                          tuple(ev[c.velocity_image(f"E{k}")] for k in names),
                          tuple(ev[c.acceleration_image(f"E{k}")] for k in names))

    def _orders(self, k: int, u: Array, n: int = HARMONIC_SAMPLES) -> tuple[complex, complex]:
        """Orders 1 and 2 of the piston's exact distance from the crank axis (numerical harmonic
        analysis: the discrete Fourier sum of n samples over a turn)."""
        theta = np.arange(n) * TURN / n
        c = np.fft.rfft(self._travel(k, u, theta)[0]) * (2.0 / n)
        return complex(c[1]), complex(c[2])

    def _travel(self, k: int, u: Array, phi: Array) -> tuple[Array, Array]:
        c = self.construction
        ev = c.evaluate(np.mod(phi, TURN))
        return ev[c.position(f"E{k + 1}")] @ u, ev[c.velocity_image(f"E{k + 1}")] @ u

    def _dead_centre(self, k: int, u: Array, i: int) -> float:
        lo, hi = (i - 1) * TURN / 720, (i + 1) * TURN / 720

        def v(f: float) -> float:
            return float(self._travel(k, u, np.array([f]))[1][0])

        return float(brentq(v, lo, hi, xtol=1e-14)) % TURN

    def phi_of_travel(self, k: int, x: float, lo: float, hi: float) -> float:
        """Crank angle in [lo, hi] where slave k has travelled x from its TDC (one stroke)."""
        sl = self.slaves[k]

        def f(p: float) -> float:
            return sl.s_tdc - float(self._travel(k, sl.u, np.array([p]))[0][0]) - x

        return float(brentq(f, lo, hi, xtol=1e-14))

    def pin_force(self, phi: Array, P_C: Array, P_E: tuple[Array, ...]) -> tuple[Array, Array]:
        """T and Z on the crank pin from the statics of the group (rods massless: their masses are
        in P and in the rotating mass); T in the sense of rotation +, Z towards the axis +.

        Each articulated rod DkEk is a two-force member; the master rod takes the piston C's
        force, the guide's normal force at C and the articulated rods' forces at the lugs.
        """
        st = self.state(phi)
        u_C = self.u_C
        n_C = np.array([-u_C[1], u_C[0]])
        F_C = -P_C[:, None] * u_C                        # piston C's force on the master at C
        BC = st.C - st.B
        moment = _cross(BC, F_C)
        F_lugs = np.zeros_like(F_C)
        for k, sl in enumerate(self.slaves):
            e = st.E[k] - st.D[k]
            e /= np.hypot(e[:, 0], e[:, 1])[:, None]
            s = P_E[k] / (e @ sl.u)                      # rod DkEk pushes piston Ek with s·e
            F_D = -s[:, None] * e                        # the articulated rod on the master at Dk
            F_lugs += F_D
            moment = moment + _cross(st.D[k] - st.B, F_D)
        N_C = -moment / _cross(BC, np.broadcast_to(n_C, BC.shape))
        F_pin = F_C + N_C[:, None] * n_C + F_lugs       # master rod on the crank pin
        r = st.B / np.hypot(st.B[:, 0], st.B[:, 1])[:, None]
        t = np.stack([-r[:, 1], r[:, 0]], axis=1)
        return np.sum(F_pin * t, axis=1), -np.sum(F_pin * r, axis=1)


def _unit(angle: float) -> Array:
    return np.array([math.cos(angle), math.sin(angle)])


def _cross(a: Array, b: Array) -> Array:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
