"""Speed against error: every way of getting a mechanism's kinematics, timed and checked.

``mechplan bench [--quick]`` times, in one process, the construction engine (float64 and float32),
"ruler mode" (the construction with every placed point rounded to the drawing's precision, as a
student carries measured segments on), velocities and accelerations by finite differences of
positions, the engine λ-series (slider-crank), the hand-written numpy closed forms and the peer
packages that are installed (pylinkage with and without numba, mechanism), and measures each one's
error against a 40-digit mpmath reference (Newton on the loop-closure equations and mpmath
differentiation, ``tests/independent/mpref.py`` — not the project's plans).

Errors are relative to the size of the quantity over the cycle: for each kind (r, v, a of points,
ω, ε of links) the largest vector difference from the reference, divided by the largest magnitude
of that kind in the reference over 24 positions of the cycle. The full benchmark is
``benchmarks/speed_error.py``; ``benchmarks/kinematics.py`` is the issue-2 subset.
"""

from __future__ import annotations

import argparse
import ctypes
import ctypes.util
import importlib.util
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, field
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np

from .construct.graph import Construction, Evaluation
from .construct.step import Kind, Op, Plan
from .errors import MechplanError
from .scene import load_scene
from .scene.spec import Scene
from .solve import KINEMATIC, build, choose_scales

ROOT = Path(__file__).resolve().parents[2]
KINDS = ("r", "v", "a", "omega", "epsilon")
TWO_PI = 2.0 * math.pi
#: φ of the first position (rad, scene convention); the others follow at 2π/N
PHI0 = 0.1
#: positions of the cycle on which the reference sizes of r, v, a, ω, ε are taken
SCALE_POSITIONS = 24
#: finite-difference steps in φ (rad): ~ (3ε)^(1/3) for v, ~ (48ε)^(1/4) for a
FD_STEP_V = 1e-5
FD_STEP_A = 1e-4
#: ruler precisions (mm of paper)
RULER_MM = (0.5, 0.1)


@dataclass(frozen=True, slots=True)
class Case:
    """A benchmarked mechanism: template / reference preset name, points and links compared."""

    name: str
    points: tuple[str, ...]
    links: tuple[str, ...]


CASES: dict[str, Case] = {c.name: c for c in (
    Case("slider_crank", ("A", "B", "S2"), ("2",)),
    Case("four_bar", ("B", "C", "E"), ("2", "3")),
    Case("v_engine", ("B", "C", "D", "E", "S2"), ("2", "4")),
    Case("shaper", ("A", "B", "C"), ("3", "4")),
)}

METHODS = ("exact float64", "exact float32", "ruler 0.5 mm", "ruler 0.1 mm",
           "finite differences", "λ-series", "numpy closed form", "pylinkage + numba",
           "pylinkage (no numba)", "mechanism (fsolve)")


@dataclass
class Config:
    """What one benchmark run measures."""

    cases: tuple[str, ...] = tuple(CASES)
    ns: tuple[int, ...] = (1, 12, 360, 100_000)
    methods: tuple[str, ...] = METHODS
    #: positions compared with the reference when N is larger (a deterministic subsample)
    max_compared: int = 360
    subsample: int = 50
    #: timing: repeat until both counts are reached (best of k), at most max_repeats
    min_repeats: int = 7
    min_seconds: float = 0.5
    max_repeats: int = 200
    #: largest N for the slow peers (pure-Python pylinkage, mechanism's fsolve loop)
    slow_peer_max_n: int = 100_000
    fsolve_max_n: int = 360
    steady_allocator: bool = False


def quick_config() -> Config:
    """A reduced run for ``mechplan bench --quick`` (about ten seconds)."""
    return Config(ns=(1, 12, 10_000), max_compared=12, subsample=12, min_repeats=3,
                  min_seconds=0.05, max_repeats=50, fsolve_max_n=12,
                  methods=tuple(m for m in METHODS if m != "pylinkage (no numba)"))


@dataclass
class Row:
    """One measurement: a method on a mechanism at N positions."""

    mechanism: str
    method: str
    n: int
    seconds: float              # best of ``repeats`` for all N positions
    repeats: int
    compared: int               # positions compared with the reference
    errors: dict[str, float] = field(default_factory=dict)   # kind → relative error
    note: str = ""

    @property
    def ns_per_position(self) -> float:
        """Time per position in nanoseconds."""
        return self.seconds / self.n * 1e9

    @property
    def max_error(self) -> float:
        """Largest relative error over the kinds this method gives (inf if it failed)."""
        return max(self.errors.values()) if self.errors else math.nan


@dataclass
class Result:
    """Kinematics a method produced at N positions: points (N, 2) and link scalars (N,)."""

    r: dict[str, np.ndarray] = field(default_factory=dict)
    v: dict[str, np.ndarray] = field(default_factory=dict)
    a: dict[str, np.ndarray] = field(default_factory=dict)
    omega: dict[str, np.ndarray] = field(default_factory=dict)
    epsilon: dict[str, np.ndarray] = field(default_factory=dict)


# -- independent references -----------------------------------------------------------------------
def independent(name: str) -> ModuleType:
    """Load ``tests/independent/<name>.py`` (mpref, closed_form) from the repository checkout."""
    path = ROOT / "tests" / "independent" / f"{name}.py"
    if not path.exists():
        raise MechplanError(f"mechplan bench needs the independent reference {path} (got no such "
                            "file); run it from a clone installed with pip install -e '.[bench]'")
    key = f"_mechplan_bench_{name}"
    if key in sys.modules:
        return sys.modules[key]
    spec = importlib.util.spec_from_file_location(key, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[key] = module           # dataclasses look their module up while it loads
    try:
        spec.loader.exec_module(module)
    except ImportError as exc:
        del sys.modules[key]
        raise MechplanError(f"the reference {name} needs {exc.name} (got ImportError); install "
                            "the extras: pip install -e '.[bench]'") from exc
    return module


class Reference:
    """40-digit reference values (mpref), memoised by (mechanism, θ)."""

    def __init__(self) -> None:
        self.mpref = independent("mpref")
        self._memo: dict[tuple[str, float], dict[str, np.ndarray]] = {}

    def at(self, name: str, theta: np.ndarray) -> dict[str, np.ndarray]:
        """Reference arrays (mpref layout) at absolute crank angles θ."""
        theta = np.asarray(theta, dtype=float)
        todo = sorted({float(t) for t in theta if (name, float(t)) not in self._memo})
        if todo:
            ref = self.mpref.reference(name, np.array(todo))
            for i, t in enumerate(todo):
                self._memo[(name, t)] = {k: v[i] for k, v in ref.items()}
        rows = [self._memo[(name, float(t))] for t in theta]
        return {k: np.array([row[k] for row in rows]) for k in rows[0]}


def reference_result(case: Case, ref: dict[str, np.ndarray]) -> Result:
    """The reference arrays of a case as a :class:`Result`."""
    out = Result()
    for p in case.points:
        out.r[p], out.v[p], out.a[p] = ref[p][:, 0:2], ref[p][:, 2:4], ref[p][:, 4:6]
    for lk in case.links:
        out.omega[lk], out.epsilon[lk] = ref[lk][:, 1], ref[lk][:, 2]
    return out


def sizes(case: Case, ref: Result) -> dict[str, float]:
    """Largest magnitude of each kind over the reference positions."""
    out = {}
    for kind in KINDS:
        values = getattr(ref, kind)
        out[kind] = max(float(np.max(np.abs(v) if v.ndim == 1 else np.hypot(v[:, 0], v[:, 1])))
                        for v in values.values())
    return out


def relative_errors(got: Result, want: Result, idx: np.ndarray, size: dict[str, float]) -> dict[str, float]:
    """Relative error per kind of ``got`` at positions ``idx`` against ``want`` (all of its rows).

    A NaN where the reference has a value counts as an infinite error (a failed position).
    """
    errs: dict[str, float] = {}
    for kind in KINDS:
        values = getattr(got, kind)
        if not values:
            continue
        worst = 0.0
        for key, arr in values.items():
            ref = getattr(want, kind)[key]
            diff = np.asarray(arr, dtype=float)[idx] - ref
            d = np.abs(diff) if diff.ndim == 1 else np.hypot(diff[:, 0], diff[:, 1])
            worst = math.inf if np.isnan(d).any() else max(worst, float(d.max()))
        errs[kind] = worst / size[kind]
    return errs


# -- timing ----------------------------------------------------------------------------------------
def best_time(run: Callable[[], Any], cfg: Config) -> tuple[float, int, Any]:
    """Best wall time of ``run()`` over k calls (time.perf_counter), k, and the last result."""
    best, total, k, out = math.inf, 0.0, 0, None
    while k < cfg.max_repeats:
        t0 = time.perf_counter()
        out = run()
        dt = time.perf_counter() - t0
        best, total, k = min(best, dt), total + dt, k + 1
        if k >= cfg.min_repeats and total >= cfg.min_seconds:
            break
        if dt > 2.0 and k >= 2:     # slow methods: best of two is all the time allows
            break
    return best, k, out


def steady_allocator() -> bool:
    """Keep freed heap memory in the process (glibc), so timings do not count fresh-page faults.

    Without it glibc returns the tens of megabytes an N = 100 000 evaluation frees to the kernel,
    and the next evaluation pays a page fault per 4 KiB again; which runs pay depends on the
    process's allocation history. Returns whether the setting was applied.
    """
    name = ctypes.util.find_library("c")
    if not name or platform.system() != "Linux":
        return False
    try:
        libc = ctypes.CDLL(name)
        m_trim_threshold, m_mmap_threshold = -1, -3
        ok = libc.mallopt(m_trim_threshold, 1 << 30) == 1
        return bool(libc.mallopt(m_mmap_threshold, 32 << 20) == 1 and ok)
    except (OSError, AttributeError):
        return False


# -- the construction, in its three uses ------------------------------------------------------------
@dataclass
class Model:
    """A case's scene and construction, and the step ids of what is compared."""

    case: Case
    scene: Scene
    c: Construction
    targets: list[str]
    position_targets: list[str]

    @classmethod
    def load(cls, case: Case, templates: Path = ROOT / "templates") -> Model:
        """Load the case's template and build its construction."""
        scene = load_scene(templates / f"{case.name}.toml")
        _, c = build(scene, KINEMATIC)
        targets = [f"pos.{p}" for p in case.points]
        targets += [c.results[f"{s}_{p}"] for s in ("v", "a") for p in case.points]
        targets += [c.results[f"{s}_{lk}"] for s in ("omega", "epsilon") for lk in case.links]
        pos = [f"pos.{p}" for p in case.points] + [c.results[f"angle_{lk}"] for lk in case.links]
        return cls(case, scene, c, targets, pos)

    def phi(self, n: int) -> np.ndarray:
        """φ of N equal steps from PHI0 (rad, scene convention)."""
        return PHI0 + TWO_PI * np.arange(n) / n

    def theta(self, phi: np.ndarray) -> np.ndarray:
        """Absolute crank angles of φ."""
        return self.c.drive.absolute(phi)

    def result(self, ev: Evaluation) -> Result:
        """The compared quantities of an evaluation, as float64."""
        c, out = self.c, Result()
        for p in self.case.points:
            out.r[p] = ev[f"pos.{p}"].astype(float)
            out.v[p] = ev[c.results[f"v_{p}"]].astype(float)
            out.a[p] = ev[c.results[f"a_{p}"]].astype(float)
        for lk in self.case.links:
            out.omega[lk] = ev[c.results[f"omega_{lk}"]].astype(float)
            out.epsilon[lk] = ev[c.results[f"epsilon_{lk}"]].astype(float)
        return out

    def exact(self, phi: np.ndarray, dtype: type = np.float64) -> Callable[[], Evaluation]:
        """A runner evaluating the construction at φ (lazily: only what the case compares)."""
        def run() -> Evaluation:
            ev = self.c.evaluate(phi, dtype=dtype)
            ev.evaluate_all(self.targets)
            return ev
        return run

    def ruler(self, phi: np.ndarray, step_mm: float) -> Callable[[], Evaluation]:
        """A runner of ruler mode: the construction drawn at the scene's scale factors."""
        probe = self.exact(phi)()
        scales = choose_scales(self.scene, self.c, probe, KINEMATIC)

        def run() -> Evaluation:
            ev = RulerEvaluation(self.c, phi, {plan: step_mm * mu for plan, mu in scales.items()})
            ev.evaluate_all(self.targets)
            return ev
        return run

    def finite_differences(self, phi: np.ndarray) -> Callable[[], Result]:
        """A runner: positions from the construction, v and a by central differences in φ."""
        drive = self.scene.mechanism.drive
        rate = abs(drive.omega)      # dφ/dt: φ grows in the sense of rotation
        n = phi.shape[0]
        hv, ha = FD_STEP_V, FD_STEP_A
        stacked = np.concatenate((phi, phi - hv, phi + hv, phi - ha, phi + ha))

        def run() -> Result:
            ev = self.c.evaluate(stacked)
            ev.evaluate_all(self.position_targets)
            out = Result()
            for p in self.case.points:
                r = ev[f"pos.{p}"]
                r0, rmv, rpv, rma, rpa = (r[i * n:(i + 1) * n] for i in range(5))
                out.r[p] = r0
                out.v[p] = (rpv - rmv) * (rate / (2.0 * hv))
                out.a[p] = (rpa - 2.0 * r0 + rma) * (rate * rate / (ha * ha))
            for lk in self.case.links:
                g = ev[self.c.results[f"angle_{lk}"]]
                g0, gmv, gpv, gma, gpa = (g[i * n:(i + 1) * n] for i in range(5))
                out.omega[lk] = _wrap(gpv - gmv) * (rate / (2.0 * hv))
                out.epsilon[lk] = (_wrap(gpa - g0) - _wrap(g0 - gma)) * (rate * rate / (ha * ha))
            return out
        return run


def _wrap(angle: np.ndarray) -> np.ndarray:
    return np.remainder(angle + math.pi, TWO_PI) - math.pi


class RulerEvaluation(Evaluation):
    """The construction as a student draws it: each point placed to the ruler's precision.

    Every point-valued step of a plan (a crank pin, a compass meet, an image on the velocity or
    acceleration plan, the end of a normal or Coriolis component) is measured from the point its
    segment starts at (the previous image, the pole, the link's other end) and put back at that
    length rounded to ``delta`` (the ruler's precision in mm times the plan's scale factor μ), with
    its direction rounded so that the end moves by at most half of ``delta`` sideways too.
    Everything after it — lines through it, meets, ω and ε from measured segments — is built from
    the rounded point, so errors are carried on as on paper. Frame points and poles are exact.
    """

    def __init__(self, construction: Construction, phi: np.ndarray,
                 delta: dict[Plan, float]) -> None:
        super().__init__(construction, np.atleast_1d(np.asarray(phi, dtype=float)))
        self.delta = delta
        starts: dict[str, str] = {}
        for s in construction.segments:
            starts.setdefault(s.end, s.start)
        self.starts = starts

    def _compute(self, step: Any) -> None:
        Evaluation._compute(self, step)
        if step.kind is not Kind.POINT or step.op in (Op.FIXED_POINT, Op.POLE):
            return
        delta = self.delta.get(step.plan)
        start = self.starts.get(step.id)
        if start is None or start not in self.values:
            start = next((i for i in step.inputs if self.construction[i].kind is Kind.POINT
                          and i in self.values), None)
        if delta is None or start is None:
            return
        origin = self.values[start]
        rel = self.values[step.id] - origin
        length = np.hypot(rel[..., 0], rel[..., 1])
        drawn = np.round(length / delta) * delta
        with np.errstate(invalid="ignore", divide="ignore"):
            arc = np.where(drawn > 0, delta / drawn, 1.0)
            angle = np.round(np.arctan2(rel[..., 1], rel[..., 0]) / arc) * arc
        value = origin + drawn[..., None] * np.stack((np.cos(angle), np.sin(angle)), axis=-1)
        value.flags.writeable = False
        self.values[step.id] = value


# -- other ways of computing the same -------------------------------------------------------------
def lambda_series(model: Model, phi: np.ndarray) -> Callable[[], Result]:
    """The engine formulas to first order in λ = r/l (central slider-crank): slider B only."""
    mech = model.scene.mechanism
    r = mech.links["1"].distance("O", "A")
    length = mech.links["2"].distance("A", "B")
    lam, omega = r / length, mech.drive.omega
    theta = model.theta(phi)

    def run() -> Result:
        c1, s1, c2, s2 = np.cos(theta), np.sin(theta), np.cos(2 * theta), np.sin(2 * theta)
        zero = np.zeros_like(theta)
        out = Result()
        out.r["B"] = np.stack((r * c1 + length - 0.25 * lam * r * (1.0 - c2), zero), axis=-1)
        out.v["B"] = np.stack((-r * omega * (s1 + 0.5 * lam * s2), zero), axis=-1)
        out.a["B"] = np.stack((-r * omega * omega * (c1 + lam * c2), zero), axis=-1)
        return out
    return run


def closed_form(model: Model, phi: np.ndarray) -> Callable[[], Result] | None:
    """The hand-written vectorised numpy closed form (slider-crank, four-bar)."""
    cf = independent("closed_form")
    if model.case.name not in cf.PRESETS:
        return None
    theta = model.theta(phi)
    case = model.case

    def run() -> Result:
        res = cf.preset(case.name, theta)
        return reference_result(case, res)
    return run


# -- peers ------------------------------------------------------------------------------------------
def _pylinkage_linkage(case: Case, theta0: float, step: float, omega: float) -> tuple[Any, dict[str, int]]:
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


def _have(module: str) -> bool:
    return importlib.util.find_spec(module) is not None


def _pylinkage_without_numba(cfg: Config, cases: Sequence[str], ns: Sequence[int],
                             log: Callable[[str], None]) -> dict[tuple[str, int], tuple[float, int, Result]]:
    """Run pylinkage in a child process with numba's JIT disabled; (case, N) → (time, k, result)."""
    with tempfile.TemporaryDirectory() as tmp:
        spec = {"cases": list(cases), "ns": list(ns), "out": tmp,
                "cfg": {k: v for k, v in asdict(cfg).items() if not isinstance(v, tuple)}}
        env = dict(os.environ, NUMBA_DISABLE_JIT="1")
        env["PYTHONPATH"] = os.pathsep.join([str(ROOT / "src"), env.get("PYTHONPATH", "")])
        log("pylinkage without numba: child process (NUMBA_DISABLE_JIT=1)")
        code = "import sys, json; from mechplan.bench import _child; _child(json.loads(sys.argv[1]))"
        proc = subprocess.run([sys.executable, "-c", code, json.dumps(spec)], env=env, check=False,
                              capture_output=True, text=True, timeout=3600)
        if proc.returncode != 0:
            raise MechplanError(f"pylinkage child process failed: {proc.stderr.strip()[-500:]}")
        meta = json.loads((Path(tmp) / "meta.json").read_text())
        out = {}
        for entry in meta:
            arrays = np.load(Path(tmp) / f"{entry['case']}_{entry['n']}.npz")
            res = Result()
            for key in arrays.files:
                kind, name = key.split(":")
                getattr(res, kind)[name] = arrays[key]
            out[(entry["case"], entry["n"])] = (entry["seconds"], entry["repeats"], res)
        return out


def _child(spec: dict[str, Any]) -> None:
    """Child-process side of :func:`_pylinkage_without_numba`."""
    cfg = Config(**spec["cfg"])
    meta = []
    for name in spec["cases"]:
        model = Model.load(CASES[name])
        for n in spec["ns"]:
            phi = model.phi(n)
            best, k, res = best_time(pylinkage_runner(model, phi), cfg)
            arrays = {f"{kind}:{key}": v for kind in KINDS for key, v in getattr(res, kind).items()}
            np.savez(Path(spec["out"]) / f"{name}_{n}.npz", **arrays)
            meta.append({"case": name, "n": n, "seconds": best, "repeats": k})
    (Path(spec["out"]) / "meta.json").write_text(json.dumps(meta))


# -- the run ----------------------------------------------------------------------------------------
def compared_indices(n: int, cfg: Config) -> np.ndarray:
    """All positions up to ``max_compared``, else an evenly spread deterministic subsample."""
    if n <= cfg.max_compared:
        return np.arange(n)
    return np.unique(np.round(np.linspace(0, n - 1, cfg.subsample)).astype(int))


def run_benchmark(cfg: Config | None = None, log: Callable[[str], None] | None = None,
                  reference: Reference | None = None) -> list[Row]:
    """Measure every configured method on every configured case and N; return the rows."""
    cfg = cfg or Config()
    log = log or (lambda msg: None)
    ref = reference or Reference()
    if cfg.steady_allocator:
        steady_allocator()
    rows: list[Row] = []
    slow_peer: dict[tuple[str, int], tuple[float, int, Result]] = {}
    if "pylinkage (no numba)" in cfg.methods and _have("pylinkage"):
        ns = [n for n in cfg.ns if n <= cfg.slow_peer_max_n]
        slow_peer = _pylinkage_without_numba(cfg, cfg.cases, ns, log)
    for name in cfg.cases:
        case = CASES[name]
        model = Model.load(case)
        cycle = model.phi(SCALE_POSITIONS)
        size = sizes(case, reference_result(case, ref.at(name, model.theta(cycle))))
        for n in cfg.ns:
            phi = model.phi(n)
            idx = compared_indices(n, cfg)
            log(f"{name}: N = {n}, reference at {idx.size} position(s)")
            want = reference_result(case, ref.at(name, model.theta(phi[idx])))
            for method in cfg.methods:
                runner, note = _runner(method, model, phi, cfg, slow_peer)
                if runner is None:
                    if note:
                        rows.append(Row(name, method, n, math.nan, 0, 0, {}, note))
                    continue
                best, k, out = best_time(runner, cfg) if callable(runner) else runner
                got = model.result(out) if isinstance(out, Evaluation) else out
                errs = relative_errors(got, want, idx, size)
                rows.append(Row(name, method, n, best, k, idx.size, errs, note))
    return rows


def _runner(method: str, model: Model, phi: np.ndarray, cfg: Config,
            slow_peer: dict) -> tuple[Any, str]:
    """The runner of a method (or a finished measurement) and a note; (None, note) if not run."""
    n, name = phi.shape[0], model.case.name
    if method == "exact float64":
        return model.exact(phi), ""
    if method == "exact float32":
        return model.exact(phi, np.float32), ""
    if method.startswith("ruler"):
        return model.ruler(phi, float(method.split()[1])), ""
    if method == "finite differences":
        return model.finite_differences(phi), f"h_v = {FD_STEP_V:g}, h_a = {FD_STEP_A:g} rad"
    if method == "λ-series":
        if name != "slider_crank":
            return None, ""
        return lambda_series(model, phi), "slider B only"
    if method == "numpy closed form":
        return closed_form(model, phi), ""
    if method == "pylinkage + numba":
        if not (_have("pylinkage") and _have("numba")):
            return None, "pylinkage or numba not installed"
        return pylinkage_runner(model, phi), "points only (no ω, ε)"
    if method == "pylinkage (no numba)":
        if (name, n) in slow_peer:
            return slow_peer[(name, n)], "points only; NUMBA_DISABLE_JIT=1 child process"
        if not _have("pylinkage"):
            return None, "pylinkage not installed"
        return None, ""
    if method == "mechanism (fsolve)":
        if name not in ("slider_crank", "four_bar"):
            return None, ""
        if not _have("mechanism"):
            return None, "mechanism not installed"
        if n > cfg.fsolve_max_n:
            return None, (f"not run: a Python loop of three fsolve calls per position (see the "
                          f"largest N ≤ {cfg.fsolve_max_n} for its cost per position)")
        run = mechanism_runner(model, phi)
        return run, ("" if run is None else "four-bar: B, C only" if name == "four_bar" else
                     "slider: A, B only")
    raise KeyError(method)


def profile(model: Model, n: int, repeats: int = 5) -> list[tuple[str, int, float]]:
    """Where the exact evaluation spends its time at N positions: (operation, steps, seconds).

    Each step's evaluation is timed on its own (best of ``repeats``), then summed per operation.
    """
    phi = model.phi(n)
    best: dict[str, float] = {}

    class Timed(Evaluation):
        def _compute(self, step: Any) -> None:
            t0 = time.perf_counter()
            Evaluation._compute(self, step)
            dt = time.perf_counter() - t0
            best[step.id] = min(best.get(step.id, math.inf), dt)

    for _ in range(repeats):
        Timed(model.c, phi).evaluate_all(model.targets)
    per_op: dict[str, list[float]] = {}
    for sid, dt in best.items():
        per_op.setdefault(model.c[sid].op.value, []).append(dt)
    return sorted(((op, len(v), sum(v)) for op, v in per_op.items()), key=lambda x: -x[2])


# -- output -----------------------------------------------------------------------------------------
def _fmt_err(x: float | None) -> str:
    if x is None:
        return "—"
    if math.isinf(x):
        return "fail"
    return f"{x:.1e}"


def format_table(rows: Iterable[Row], markdown: bool = False) -> str:
    """The rows as a text or Markdown table."""
    head = ["mechanism", "method", "N", "ns/position", "max rel. error", *KINDS, "compared", "note"]
    body = []
    for r in rows:
        if r.repeats == 0:
            body.append([r.mechanism, r.method, str(r.n), "—", "—", *(["—"] * len(KINDS)), "0", r.note])
            continue
        body.append([r.mechanism, r.method, str(r.n), f"{r.ns_per_position:,.0f}",
                     _fmt_err(r.max_error), *(_fmt_err(r.errors.get(k)) for k in KINDS),
                     str(r.compared), r.note])
    if markdown:
        lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        lines += ["| " + " | ".join(row) + " |" for row in body]
        return "\n".join(lines)
    widths = [max(len(x) for x in col) for col in zip(head, *body)]
    fmt = "  ".join(f"{{:{'<' if i < 2 or i == len(head) - 1 else '>'}{w}}}"
                    for i, w in enumerate(widths))
    return "\n".join(fmt.format(*row).rstrip() for row in [head, *body])


def goals(rows: Sequence[Row]) -> list[tuple[str, bool | None, str]]:
    """The issue's goals checked on measured rows: (goal, met or None if not measured, detail)."""
    by = {(r.mechanism, r.method, r.n): r for r in rows if r.repeats}
    big = max((r.n for r in rows), default=0)
    out: list[tuple[str, bool | None, str]] = []
    ratios, faster = [], []
    for name in CASES:
        ex = by.get((name, "exact float64", big))
        cf = by.get((name, "numpy closed form", big))
        pl = by.get((name, "pylinkage + numba", big))
        if ex and cf:
            ratios.append((name, ex.seconds / cf.seconds))
        if ex and pl:
            faster.append((name, ex.seconds / pl.seconds))
    out.append((f"exact float64 at N = {big:,} faster per position than pylinkage + numba",
                all(x < 1 for _, x in faster) if faster else None,
                ", ".join(f"{n}: {x:.2f}× pylinkage's time" for n, x in faster) or "not measured"))
    out.append((f"exact float64 at N = {big:,} within 3× of the numpy closed form",
                all(x <= 3 for _, x in ratios) if ratios else None,
                ", ".join(f"{n}: {x:.2f}×" for n, x in ratios) or "not measured"))
    errs = [r.max_error for r in rows if r.method == "exact float64" and r.repeats]
    out.append(("exact float64 max relative error ≤ 1e-13 (all mechanisms, all N)",
                max(errs) <= 1e-13 if errs else None,
                f"worst {max(errs):.1e}" if errs else "not measured"))
    return out


def machine() -> dict[str, str]:
    """The machine and versions a run measured on."""
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    info = {"cpu": cpu, "cores": str(os.cpu_count()), "os": platform.platform(),
            "python": platform.python_version(), "numpy": np.__version__}
    for mod in ("mpmath", "numba", "pylinkage", "mechanism", "scipy"):
        try:
            info[mod] = version(mod)
        except PackageNotFoundError:
            info[mod] = "not installed"
    return info


# -- CLI --------------------------------------------------------------------------------------------
def add_parser(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``mechplan bench`` on the CLI's subparsers."""
    b = subparsers.add_parser("bench", help="speed against error of every method, against a "
                              "40-digit reference")
    b.add_argument("--quick", action="store_true", help="N = 1, 12, 10 000; fewer repeats")
    b.add_argument("--mechanism", nargs="+", choices=sorted(CASES), metavar="NAME",
                   help=f"only these ({', '.join(CASES)})")
    b.add_argument("--json", action="store_true", help="rows as one JSON document")
    b.set_defaults(func=run)
    return b


def run(args: argparse.Namespace) -> int:
    """Run the benchmark for the CLI; print the table (progress goes to stderr)."""
    cfg = quick_config() if args.quick else Config()
    if getattr(args, "mechanism", None):
        cfg.cases = tuple(args.mechanism)
    cfg.steady_allocator = True
    rows = run_benchmark(cfg, log=lambda msg: print(msg, file=sys.stderr, flush=True))
    if getattr(args, "json", False):
        def num(x: float) -> float | str:
            return x if math.isfinite(x) else str(x)
        doc = {"machine": machine(), "rows": [
            {"mechanism": r.mechanism, "method": r.method, "n": r.n, "seconds": num(r.seconds),
             "repeats": r.repeats, "compared": r.compared, "note": r.note,
             "ns_per_position": num(r.ns_per_position), "max_error": num(r.max_error),
             "errors": {k: num(v) for k, v in r.errors.items()}} for r in rows],
            "goals": [{"goal": g, "met": m, "detail": d} for g, m, d in goals(rows)]}
        print(json.dumps(doc, ensure_ascii=False, indent=1, default=float))
        return 0
    print(format_table(rows))
    print()
    for goal, met, detail in goals(rows):
        print(f"{'met' if met else 'NOT met' if met is False else 'not measured'}: {goal} ({detail})")
    return 0
