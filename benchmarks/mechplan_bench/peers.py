"""The peer packages on the same cases: pylinkage (compiled simulation) and mechanism (fsolve)."""

from __future__ import annotations

import importlib.util
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .config import TWO_PI, Case
from .model import Model
from .results import Result


def installed(module: str) -> bool:
    """Whether ``module`` can be imported (without importing it)."""
    return importlib.util.find_spec(module) is not None


def _pylinkage_linkage(case: Case, theta0: float, step: float,
                       omega: float) -> tuple[Any, dict[str, int]]:
    """A pylinkage model of a case whose k-th output is at θ0 + k·step; (linkage, names).

    Dimensions are those of ``templates/<case>.toml`` (metres); the assembly branch is given by
    initial positions near the scene's branch (pylinkage then keeps the nearest solution).
    """
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import FixedDyad, RRPDyad, RRRDyad
    from pylinkage.simulation import Linkage

    parts: list[Any]
    a: Any
    b: Any
    c: Any
    d: Any
    e: Any

    def crank(anchor: Any, radius: float) -> Any:
        return Crank(anchor=anchor, radius=radius, angular_velocity=step,
                     initial_angle=theta0 - step, name="crank")

    if case.name == "slider_crank":
        o, g = Ground(0.0, 0.0, name="O"), Ground(1.0, 0.0, name="G")
        a = crank(o, 0.1)
        b = RRPDyad(a.output, o, g, distance=0.4, x=0.5, y=0.0, name="B")
        s2 = FixedDyad(a.output, b, distance=0.12, angle=0.0, name="S2")
        parts, names, drive = [o, g, a, b, s2], {"A": 2, "B": 3, "S2": 4}, a
    elif case.name == "four_bar":
        ga, gd = Ground(0.0, 0.0, name="A"), Ground(0.25, 0.0, name="D")
        b = crank(ga, 0.08)
        bx, by = 0.08 * math.cos(theta0 - step), 0.08 * math.sin(theta0 - step)
        cx, cy = _circle_meet((bx, by), 0.26, (0.25, 0.0), 0.18)
        c = RRRDyad(b.output, gd, distance1=0.26, distance2=0.18, x=cx, y=cy, name="C")
        beta = math.acos((0.15 ** 2 + 0.26 ** 2 - 0.18 ** 2) / (2 * 0.15 * 0.26))
        e = FixedDyad(b.output, c, distance=0.15, angle=beta, name="E")
        parts, names, drive = [ga, gd, b, c, e], {"B": 2, "C": 3, "E": 4}, b
    elif case.name == "v_engine":
        ga = Ground(0.0, 0.0, name="A")
        gx = Ground(math.cos(math.radians(60)), math.sin(math.radians(60)), name="X")
        gy = Ground(math.cos(math.radians(120)), math.sin(math.radians(120)), name="Y")
        b = crank(ga, 0.08)
        ux, uy = math.cos(math.radians(60)), math.sin(math.radians(60))
        c = RRPDyad(b.output, ga, gx, distance=0.248, x=0.3 * ux, y=0.3 * uy, name="C")
        beta = math.acos((0.248 ** 2 + 0.062 ** 2 - 0.218 ** 2) / (2 * 0.248 * 0.062))
        d = FixedDyad(b.output, c, distance=0.062, angle=beta, name="D")
        e = RRPDyad(d, ga, gy, distance=0.218, x=-0.3 * ux, y=0.3 * uy, name="E")
        s2 = FixedDyad(b.output, c, distance=0.124, angle=0.0, name="S2")
        parts, names = [ga, gx, gy, b, c, d, e, s2], {"B": 3, "C": 4, "D": 5, "E": 6, "S2": 7}
        drive = b
    elif case.name == "shaper":
        o1, o3 = Ground(0.0, 0.0, name="O1"), Ground(0.0, -0.3, name="O3")
        r1, r2 = Ground(0.0, 0.32, name="R"), Ground(1.0, 0.32, name="R2")
        a = crank(o1, 0.1)
        b = FixedDyad(o3, a.output, distance=0.6, angle=0.0, name="B")
        c = RRPDyad(b, r1, r2, distance=0.15, x=0.5, y=0.32, name="C")
        parts, names, drive = [o1, o3, r1, r2, a, b, c], {"A": 4, "B": 5, "C": 6}, a
    else:
        raise KeyError(case.name)
    linkage = Linkage(parts, name=case.name)
    linkage.set_input_velocity(drive, omega=omega)
    return linkage, names


def _circle_meet(p: tuple[float, float], r1: float, q: tuple[float, float],
                 r2: float) -> tuple[float, float]:
    """Meet of circles (p, r1), (q, r2) left of p→q (a branch hint for pylinkage)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    return p[0] + (a * dx - h * dy) / d, p[1] + (a * dy + h * dx) / d


def pylinkage_runner(model: Model, phi: np.ndarray) -> Callable[[], Result]:
    """A runner of pylinkage's compiled simulation with kinematics (numba when installed)."""
    case, n = model.case, phi.shape[0]
    theta = model.theta(phi)
    sense = model.c.drive.sense
    omega = model.scene.mechanism.drive.omega
    linkage, names = _pylinkage_linkage(case, float(theta[0]), sense * TWO_PI / n, omega)
    linkage.compile()
    start = [(comp.x, comp.y) for comp in linkage.components]

    def run() -> Result:
        for comp, (x, y) in zip(linkage.components, start):
            comp.x, comp.y = x, y
        pos, vel, acc = linkage.step_fast_with_kinematics(iterations=n)
        out = Result()
        for p in case.points:
            j = names[p]
            out.r[p], out.v[p], out.a[p] = pos[:, j], vel[:, j], acc[:, j]
        return out
    return run


def mechanism_runner(model: Model, phi: np.ndarray) -> Callable[[], Result] | None:
    """A runner of the ``mechanism`` package (loop equations, scipy fsolve per position)."""
    if model.case.name not in ("slider_crank", "four_bar"):
        return None
    from mechanism import Mechanism, Vector, get_joints

    theta = model.theta(phi)
    n = theta.shape[0]
    omega = model.scene.mechanism.drive.omega

    def run() -> Result:
        out = Result()
        if model.case.name == "slider_crank":
            o, a, b = get_joints("O A B")
            va, vb = Vector((o, a), r=0.1), Vector((a, b), r=0.4)
            vc = Vector((o, b), theta=0.0, style="ground")

            def loops(x, inp):
                return (va(inp) + vb(x[0]) - vc(x[1])).flatten()
            guess = (np.array([0.0, 0.45]), np.zeros(2), np.zeros(2))
            m = Mechanism(vectors=(va, vb, vc), origin=o, loops=loops, pos=theta,
                          vel=np.full(n, omega), acc=np.zeros(n), guess=guess)
            m.iterate()
            joints, links = {"A": a, "B": b}, {"2": vb}
        else:
            a0, b, c, d = get_joints("A B C D")
            va, vb = Vector((a0, b), r=0.08), Vector((b, c), r=0.26)
            vc, vd = Vector((d, c), r=0.18), Vector((a0, d), r=0.25, theta=0.0, style="ground")

            def loops(x, inp):
                return (va(inp) + vb(x[0]) - vc(x[1]) - vd()).flatten()
            t0 = float(theta[0])
            bx, by = 0.08 * math.cos(t0), 0.08 * math.sin(t0)
            cx, cy = _circle_meet((bx, by), 0.26, (0.25, 0.0), 0.18)
            guess = (np.array([math.atan2(cy - by, cx - bx), math.atan2(cy, cx - 0.25)]),
                     np.zeros(2), np.zeros(2))
            m = Mechanism(vectors=(va, vb, vc, vd), origin=a0, loops=loops, pos=theta,
                          vel=np.full(n, omega), acc=np.zeros(n), guess=guess)
            m.iterate()
            joints, links = {"B": b, "C": c}, {"2": vb, "3": vc}
        for p, j in joints.items():
            out.r[p] = np.stack((j.x_positions, j.y_positions), axis=-1)
            out.v[p] = np.stack((j.x_velocities, j.y_velocities), axis=-1)
            out.a[p] = np.stack((j.x_accelerations, j.y_accelerations), axis=-1)
        for lk, vec in links.items():
            out.omega[lk], out.epsilon[lk] = np.array(vec.vel.omegas), np.array(vec.acc.alphas)
        return out
    return run
