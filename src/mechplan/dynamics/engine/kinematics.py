"""Piston kinematics of a central slider-crank: exact closed forms, the λ-series and Brix's
transfer.

φ is the crank angle from the top dead centre in the sense of rotation (rad), ω > 0 constant;
x is the piston's travel from TDC towards the crankshaft (m); v = dx/dt, a = d²x/dt².
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

Array = np.ndarray


@dataclass(frozen=True, slots=True)
class SliderCrank:
    """A central slider-crank of crank radius R and rod length L (λ = R/L < 1)."""

    R: float
    L: float

    @property
    def lam(self) -> float:
        """λ = R/L."""
        return self.R / self.L

    def beta(self, phi: Array) -> Array:
        """Rod angle β (sin β = λ sin φ), rad."""
        return np.arcsin(self.lam * np.sin(phi))

    def x(self, phi: Array) -> Array:
        """Exact travel from TDC: R(1 − cos φ) + L(1 − cos β)."""
        s = self.lam * np.sin(phi)
        return self.R * (1.0 - np.cos(phi)) + self.L * (1.0 - np.sqrt(1.0 - s * s))

    def dx_dphi(self, phi: Array) -> Array:
        """dx/dφ = R sin(φ + β)/cos β (the torque arm of the force along the cylinder)."""
        b = self.beta(phi)
        return self.R * np.sin(phi + b) / np.cos(b)

    def v(self, phi: Array, omega: float) -> Array:
        """Exact piston velocity."""
        return omega * self.dx_dphi(phi)

    def a(self, phi: Array, omega: float) -> Array:
        """Exact piston acceleration Rω²[cos(φ+β)/cos β + λ cos²φ/cos³β]."""
        b = self.beta(phi)
        cb = np.cos(b)
        return self.R * omega ** 2 * (np.cos(phi + b) / cb + self.lam * np.cos(phi) ** 2 / cb ** 3)

    def x_series(self, phi: Array) -> Array:
        """λ-series travel R[(1 − cos φ) + (λ/4)(1 − cos 2φ)]."""
        return self.R * ((1.0 - np.cos(phi)) + self.lam / 4.0 * (1.0 - np.cos(2.0 * phi)))

    def a_series(self, phi: Array, omega: float) -> Array:
        """λ-series acceleration Rω²(cos φ + λ cos 2φ)."""
        return self.R * omega ** 2 * (np.cos(phi) + self.lam * np.cos(2.0 * phi))

    def x_brix(self, phi: Array) -> Array:
        """Travel by Brix's construction as drawn (circle of radius R, pole shifted Rλ/2 to BDC).

        The ray from the pole O′ at angle φ meets the circle; its foot on the axis is the piston:
        x = R[1 − cos φ·√(1 − λ² sin²φ/4) + (λ/2) sin²φ].
        """
        lam = self.lam
        s = np.sin(phi)
        return self.R * (1.0 - np.cos(phi) * np.sqrt(1.0 - lam * lam * s * s / 4.0)
                         + lam / 2.0 * s * s)

    def phi_of_x(self, x: Array, descending: bool) -> Array:
        """Crank angle in [0, π] (TDC→BDC) or, if ``descending``, in [π, 2π] for travel x."""
        s = self.R + self.L - np.asarray(x, float)          # distance crank axis → piston pin
        c = np.clip((s * s + self.R ** 2 - self.L ** 2) / (2.0 * s * self.R), -1.0, 1.0)
        phi = np.arccos(c)
        return 2.0 * np.pi - phi if descending else phi


@dataclass(frozen=True, slots=True)
class CrankEnd:
    """The crank-end face of a double-acting cylinder seen as a crank mechanism of its own.

    Its cycle angle φ′ starts at its TDC (the head end's BDC): φ′ = φ − π, and its travel from its
    TDC is x′(φ′) = 2R − x(φ′ + π) (the rod's obliquity mirrored). The indicator diagram of that
    face uses it wherever a crank angle meets a volume.
    """

    head: SliderCrank

    @property
    def R(self) -> float:
        """Crank radius."""
        return self.head.R

    @property
    def lam(self) -> float:
        """λ of the head end's slider-crank."""
        return self.head.lam

    def x(self, phi: Array) -> Array:
        """Travel from the crank end's TDC."""
        return 2.0 * self.head.R - self.head.x(np.asarray(phi, float) + np.pi)

    def dx_dphi(self, phi: Array) -> Array:
        """dx′/dφ′."""
        return -self.head.dx_dphi(np.asarray(phi, float) + np.pi)

    def phi_of_x(self, x: Array, descending: bool) -> Array:
        """Crank angle φ′ in [0, π] (TDC→BDC) or, if ``descending``, in [π, 2π] for travel x′."""
        xh = 2.0 * self.head.R - np.asarray(x, float)
        if descending:
            return self.head.phi_of_x(xh, False) + np.pi
        return self.head.phi_of_x(xh, True) - np.pi
