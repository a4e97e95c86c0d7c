"""Dynamics of a machine unit over its steady cycle: moments, works, ΔT, flywheel, law of motion."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..geom.vec import Array
from ..i18n import Text
from ..model.dynamics import DynamicsSpec, Unknown
from ..scene.spec import Scene
from .cycle import CycleState, MachineCycle
from .flywheel import (
    Extremes,
    FlywheelSize,
    Merkalov,
    Wittenbauer,
    cumulative_work,
    delta_of,
    exact_flywheel,
    extremes,
    flywheel_size,
    merkalov,
    speed,
    wittenbauer,
)


@dataclass(frozen=True)
class MachineDynamics:
    """Everything the dynamics sheet and report show; arrays over the dense grid θ (N + 1,).

    ``drawn`` indexes the drawn positions in the dense grid (the last one closes the cycle).
    M_d, M_c: reduced moments of the driving and of the resisting forces (resisting positive).
    """

    spec: DynamicsSpec
    omega_m: float
    phi0: float
    theta: Array
    drawn: Array
    M_d: Array
    M_c: Array
    A_d: Array
    A_c: Array
    dT: Array
    J_red: Array
    dJ_red: Array
    J_present: float          # constant inertia already there: J_const + the crank's own
    M_const: float            # the constant moment (found or given)
    net_work: float           # A_d(Φ) − A_c(Φ)
    A_d_drawn: Array          # trapezoids over the drawn positions
    M_lever: Array            # the given loads' reduced moment at the drawn positions by the lever
    M_given: Array            # … and by the equality of powers
    A_c_drawn: Array
    witt: Wittenbauer
    merk: Merkalov
    J_exact: float
    delta_witt: float         # δ that each flywheel gives, by the exact integration
    delta_merk: float
    merk_omega_error: float   # max |Merkalov's ω − the exact ω with Merkalov's flywheel| (rad/s)
    delta_exact: float
    omega: Array
    epsilon: Array
    ext: Extremes
    size: FlywheelSize | None

    @property
    def J_var(self) -> Array:
        """Variable part of J_red (kg·m²)."""
        return self.J_red - self.J_present

    @property
    def dT_drawn(self) -> Array:
        """ΔT by trapezoids over the drawn positions (J)."""
        return self.A_d_drawn - self.A_c_drawn


def _split(spec: DynamicsSpec, theta: Array, st: CycleState,
           file: str) -> tuple[Array, Array, float, float]:
    """(M_d, M_c, M_const, net work) from the given loads and the constant side."""
    cycle = spec.cycle
    A_given = float(cumulative_work(theta, st.M_given)[-1])
    if spec.unknown is Unknown.RESISTING:
        if spec.constant_moment is None:
            if not A_given > 0:
                raise SceneError(
                    Text("errmsg.dynamics_machine.work_given_loads", {"a_given": f"{A_given:.4g}"}),
                    file=file,
                    key="dynamics.unknown",
                )
            M = A_given / cycle
        else:
            M = spec.constant_moment
        return st.M_given, np.full_like(theta, M), M, A_given - M * cycle
    if spec.constant_moment is None:
        if not A_given < 0:
            raise SceneError(
                Text("errmsg.dynamics_machine.given_loads_absorb", {"a_given": f"{A_given:.4g}"}),
                file=file,
                key="dynamics.unknown",
            )
        M = -A_given / cycle
    else:
        M = spec.constant_moment
    return np.full_like(theta, M), -st.M_given, M, M * cycle + A_given


def machine_dynamics(scene: Scene, spec: DynamicsSpec, phi0: float,
                     per_turn: int) -> MachineDynamics:
    """Solve the machine's dynamics with ``per_turn`` drawn positions per crank turn from φ0."""
    turns = round(spec.cycle / (2 * math.pi))
    m = max(1, math.ceil(spec.dense / per_turn))
    n = per_turn * m * turns
    theta = np.linspace(0.0, spec.cycle, n + 1)
    mc = MachineCycle(scene, spec, phi0)
    st = mc.evaluate(theta)
    M_d, M_c, M_const, net = _split(spec, theta, st, scene.path)
    if spec.constant_moment is not None:
        scale = max(float(cumulative_work(theta, np.abs(M_d))[-1]), 1e-300)
        if abs(net) > spec.balance_tolerance * scale:
            raise SceneError(
                Text(
                    "errmsg.dynamics_machine.driving_resisting_works",
                    {
                        "balance_tolerance": f"{spec.balance_tolerance:.0%}",
                        "net": f"{net:.4g}",
                        "scale": f"{scale:.4g}",
                    },
                ),
                file=scene.path,
                key="dynamics.constant_moment",
            )
    A_d, A_c = cumulative_work(theta, M_d), cumulative_work(theta, M_c)
    dT = A_d - A_c
    drawn = np.arange(0, n + 1, m)
    A_d_drawn = cumulative_work(theta[drawn], M_d[drawn])
    A_c_drawn = cumulative_work(theta[drawn], M_c[drawn])
    if spec.constant_moment is None:
        # as on the sheet: the constant moment from the trapezoid works of the drawn positions
        if spec.unknown is Unknown.RESISTING:
            A_c_drawn = theta[drawn] * (A_d_drawn[-1] / spec.cycle)
        else:
            A_d_drawn = theta[drawn] * (A_c_drawn[-1] / spec.cycle)
    omega_m = mc.omega1
    J_present = spec.inertia_const + st.J_crank
    J_red = st.J_red + spec.inertia_const
    witt = wittenbauer(J_red, dT, omega_m, spec.delta)
    merk = merkalov(J_red - J_present, dT, omega_m, spec.delta, J_present)
    J_exact, E0 = exact_flywheel(theta, J_red, dT, omega_m, spec.delta, merk.J_flywheel)
    J = J_red + J_exact
    omega = speed(J, dT, E0)
    delta_merk, E0_merk = delta_of(theta, J_red + merk.J_flywheel, dT, omega_m)
    omega_merk = speed(J_red + merk.J_flywheel, dT, E0_merk)
    epsilon = (M_d - M_c) / J - omega ** 2 * st.dJ_red / (2.0 * J)
    return MachineDynamics(
        spec=spec, omega_m=omega_m, phi0=phi0, theta=theta, drawn=drawn, M_d=M_d, M_c=M_c,
        A_d=A_d, A_c=A_c, dT=dT, J_red=J_red, dJ_red=st.dJ_red, J_present=J_present,
        M_const=M_const, net_work=net, A_d_drawn=A_d_drawn, M_lever=st.M_lever[drawn],
        M_given=st.M_given[drawn], A_c_drawn=A_c_drawn, witt=witt,
        merk=merk, J_exact=J_exact,
        delta_witt=delta_of(theta, J_red + witt.J_flywheel, dT, omega_m)[0],
        delta_merk=delta_merk,
        merk_omega_error=float(np.abs(merk.omega - omega_merk).max()),
        delta_exact=delta_of(theta, J, dT, omega_m)[0], omega=omega, epsilon=epsilon,
        ext=extremes(theta, omega),
        size=flywheel_size(J_exact, spec.flywheel) if spec.flywheel is not None else None)
