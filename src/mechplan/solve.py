"""Solve a scene: structure, construction, positions, evaluation of what the scene asks for."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import __version__
from .construct.builder import build_construction
from .construct.estimate import DEFAULT_TOLERANCE, ErrorEstimate, estimate_errors
from .construct.extremes import extreme_positions
from .construct.graph import Construction, Evaluation
from .construct.scale import SCALE_KEYS
from .construct.segments import SegmentKind
from .construct.trust import Failure, Flag, failures, flags, refuse_unbounded
from .construct.validity import MAX_CONDITION, ensure_valid
from .errors import SceneError
from .i18n import Text
from .limits import check_angles_deg, ensure_within_budget
from .model.mechanism import GROUND
from .model.plans import Plan
from .model.structure import Structure, analyse
from .scene.spec import Scene

KINEMATIC = ("position", "velocity", "acceleration")


@dataclass
class Solution:
    """A solved scene at N crank positions."""

    scene: Scene
    structure: Structure
    construction: Construction
    phi: np.ndarray
    ev: Evaluation
    plans: tuple[str, ...]
    targets: list[str]
    scales: dict[Plan, float] = field(default_factory=dict)
    extras: dict[str, Any] = field(default_factory=dict)
    #: relative error estimate of every evaluated step at every position
    estimate: ErrorEstimate = field(default_factory=ErrorEstimate)
    #: results whose estimate exceeds the tolerance, and sweep positions that could not be built
    flags: list[Flag] = field(default_factory=list)
    failures: list[Failure] = field(default_factory=list)
    tolerance: float = DEFAULT_TOLERANCE

    @property
    def positions(self) -> int:
        """Number of positions."""
        return int(self.phi.shape[0])


def build(
    scene: Scene, plans: tuple[str, ...] | None = None, loading: Any = None
) -> tuple[Structure, Construction]:
    """Structure and construction of a scene."""
    structure = analyse(scene.mechanism)
    plans = plans or scene.plans
    if "force" in plans and loading is None:
        from .dynamics.loading import Loading
        loading = Loading.from_scene(scene)
    build_plans = tuple(
        p for p in (*KINEMATIC, "force") if p in plans or p in ("position", "velocity")
    )
    c = build_construction(scene.mechanism, structure, build_plans, scene.assembly_phi, scene.path,
                           loading)
    return structure, c


def position_count(scene: Scene, count: int | None = None) -> int:
    """How many positions :func:`crank_positions` gives (known before allocating them)."""
    pos = scene.positions
    if pos.angles and count is None:
        return len(pos.angles)
    return count or pos.count or 12


def crank_positions(scene: Scene, c: Construction, count: int | None = None) -> np.ndarray:
    """φ of the positions the scene asks for (rad), numbered in the sense of rotation.

    Refuse (:class:`~mechplan.limits.LimitError`) a count whose angles alone exceed the memory
    budget, before allocating them; callers check the whole evaluation's need first."""
    pos = scene.positions
    if pos.angles and count is None:
        return np.asarray(pos.angles, dtype=float)
    n = position_count(scene, count)
    ensure_within_budget(n, 1, file=scene.path, key=None if count else "positions.count")
    drive = scene.mechanism.drive
    if drive.linear or drive.law is not None:   # equal steps over the driver's range (a
        if drive.q_range is None:               # linear driver's, a crank's table), both ends
            raise SceneError(Text(
                "errmsg2.solve.no_range",
                {"kind": drive.kind.value, "link": drive.link, "count": str(n)}),
                file=scene.path, key="drive.range")
        return np.linspace(drive.q_range[0], drive.q_range[1], n)
    start = pos.start_angle
    if pos.start_extreme is not None:
        ex = [e for e in extreme_positions(c, scene.mechanism, pos.start_extreme.subject)
              if e.which == pos.start_extreme.which]
        if not ex:
            raise SceneError(
                Text("errmsg2.solve.no_extreme",
                     {"subject": pos.start_extreme.subject, "which": pos.start_extreme.which}),
                file=scene.path,
                key="positions.start",
            )
        start = ex[0].phi
    return np.mod(start + np.arange(n) * 2.0 * math.pi / n, 2.0 * math.pi)


def shown_coordinate(scene: Scene, q: float) -> float:
    """A driver's coordinate as positions are asked for (``solve(at_deg=…)``): φ in degrees, or
    a linear driver's length in millimetres."""
    return q * 1000.0 if scene.mechanism.drive.linear else math.degrees(q)


def targets_for(scene: Scene, c: Construction, plans: tuple[str, ...]) -> list[str]:
    """Step ids of the results a scene asks for (their ancestors are all that is evaluated)."""
    points = scene.points_of_interest or tuple(
        p for lk in scene.mechanism.links.values() if lk.id != GROUND for p in lk.points)
    out: list[str] = []
    for p in points:
        if "position" in plans:
            out.append(c.position(p))
        if "velocity" in plans and c.has_result("v", p):
            out.append(c.velocity_image(p))
        if "acceleration" in plans and c.has_result("a", p):
            out.append(c.acceleration_image(p))
    if not scene.points_of_interest:
        out += [sid for sid in c.link_results() if c[sid].plan.value in plans]
    if "force" in plans:
        out += c.force_results()
    return list(dict.fromkeys(out))


def choose_scales(scene: Scene, c: Construction, ev: Evaluation, plans: tuple[str, ...],
                  size: str | None = None, standard: str | None = None) -> dict[Plan, float]:
    """Scale factors of the sheet (the scene's own sheet size by default): the one decision
    shared by the report, the JSON, the sheets and the checker (``sheet.scales``)."""
    from .sheet.scales import decide_scales

    return decide_scales(scene, c, ev, plans, size, standard)


def solve(scene: Scene, at_deg: Sequence[float] | np.ndarray | None = None,
          count: int | None = None,
          plans: tuple[str, ...] | None = None, loading: Any = None,
          max_condition: float = MAX_CONDITION, tolerance: float = DEFAULT_TOLERANCE, *,
          built: tuple[Structure, Construction] | None = None,
          scales: bool = True, targets: Sequence[str] | None = None) -> Solution:
    """Solve a scene at the positions it (or the caller) asks for.

    Positions asked for by their angle (``at_deg``, or the scene's list of angles) must be
    computable: an unreachable or singular one raises. A sweep (``count`` positions, or the scene's
    count) returns every position it can build and lists the others in ``Solution.failures``.
    Results whose estimated relative error exceeds ``tolerance`` are listed in ``Solution.flags``.
    ``built`` reuses a structure and construction from :func:`build` (same scene, plans and
    loading); ``scales=False`` chooses no drawing scale factors (nothing will be drawn);
    ``targets`` (step ids) replaces the results the scene asks for: only their ancestors are
    evaluated, checked and flagged.
    """
    plans = plans or scene.plans
    structure, c = built or build(scene, plans, loading)
    requested = at_deg is not None and len(at_deg) > 0
    individually = requested or (count is None and bool(scene.positions.angles))
    targets = list(targets) if targets is not None else targets_for(scene, c, plans)
    # the budget is checked before the angles are allocated (--positions 100000000000)
    n = len(at_deg) if requested and at_deg is not None else position_count(scene, count)
    ensure_within_budget(n, len(c.ancestors(targets)), file=scene.path,
                         key=None if requested or count else "positions.count")
    if requested:
        phi = (np.asarray(at_deg, dtype=float) / 1000.0 if scene.mechanism.drive.linear
               else np.radians(check_angles_deg(np.asarray(at_deg, dtype=float))))
    else:
        phi = crank_positions(scene, c, count)
    ev = c.evaluate(phi)
    ev.evaluate_all(targets)
    estimate = estimate_errors(c, ev, targets)
    failed: list[Failure] = []
    if individually:
        ensure_valid(c, ev, scene.path, max_condition)
        refuse_unbounded(c, ev, estimate, targets, scene.path)
    else:
        failed = failures(c, ev, estimate, targets, scene.path, max_condition)
    sol = Solution(scene, structure, c, phi, ev, plans, targets,
                   choose_scales(scene, c, ev, plans) if scales else {},
                   estimate=estimate, tolerance=tolerance, failures=failed,
                   flags=flags(c, ev, estimate, targets, tolerance, [f.k for f in failed]))
    if "force" in plans:
        from .dynamics.kinetostatics import analyse_forces
        from .dynamics.loading import Loading
        sol.extras["loading"] = loading or Loading.from_scene(scene)
        sol.extras["forces"] = analyse_forces(c, ev, scene.mechanism, sol.extras["loading"])
    if scene.textbook is not None:
        from .textbook_report import attach
        attach(sol)
    return sol


def _vec(a: np.ndarray) -> list[float]:
    return [float(a[0]), float(a[1])]


def to_json(sol: Solution) -> dict[str, Any]:
    """The JSON document of ``mechplan solve --json`` (SI units, ω/ε counter-clockwise +)."""
    from .trust_report import position_json, trust_json

    scene, c, ev = sol.scene, sol.construction, sol.ev
    points = scene.points_of_interest or tuple(
        p for lk in scene.mechanism.links.values() if lk.id != GROUND for p in lk.points)
    theta = c.drive.absolute(sol.phi)
    positions = []
    for k in range(sol.positions):
        pts: dict[str, Any] = {}
        for p in points:
            entry_p: dict[str, Any] = {}
            if c.has_position(p) and c.position(p) in ev.values:
                entry_p["r"] = _vec(ev[c.position(p)][k])
            for sym, image in (("v", c.velocity_image), ("a", c.acceleration_image)):
                sid = image(p) if c.has_result(sym, p) else None
                if sid is not None and sid in ev.values:
                    entry_p[sym] = _vec(ev[sid][k])
            pts[p] = entry_p
        links: dict[str, Any] = {}
        for lid in scene.mechanism.moving:
            entry: dict[str, Any] = {}
            for key, name, of in (("angle", "angle_deg", c.link_angle), ("omega", "omega", c.omega),
                                  ("epsilon", "epsilon", c.epsilon)):
                sid = of(lid) if c.has_result(key, lid) else None
                if sid is not None and sid in ev.values:
                    val = float(ev[sid][k])
                    entry[name] = (
                        math.degrees(math.remainder(val, 2 * math.pi)) if key == "angle" else val
                    )
            if entry:
                links[lid] = entry
        entry_k: dict[str, Any] = ({"q": float(sol.phi[k])} if c.drive.linear else {
            "phi_deg": round(math.degrees(float(sol.phi[k])), 10),
            "crank_angle_deg": round(
                math.degrees(math.remainder(float(theta[k]), 2 * math.pi)), 10
            )})
        entry_k.update(points=pts, links=links)
        if "forces" in sol.extras:
            entry_k.update(sol.extras["forces"].json(k))
        if "textbook" in sol.extras:
            from .textbook_report import position_json as textbook_json
            entry_k["textbook"] = textbook_json(sol, k)
        entry_k["error_estimate"] = position_json(sol, k)
        positions.append(entry_k)
    doc = {
        "mechplan": __version__,
        "title": scene.title,
        "dof": sol.structure.dof,
        "structure": sol.structure.formula,
        "driver": _driver_json(scene.mechanism.drive),
        **({} if scene.mechanism.drive2 is None else {     # W = 2: the second driver and its law
            "second_driver": _driver_json(scene.mechanism.drive2)
            | {"start" if scene.mechanism.drive2.linear else "phase":
               scene.mechanism.drive2.phase}}),
        "groups": [
            {"class": g.klass, "kind": str(g.kind), "links": list(g.links)}
            for g in sol.structure.groups
        ],
        "positions": positions,
        "accuracy": trust_json(sol),
        "scales": {SCALE_KEYS[plan.value][0]: mu for plan, mu in sol.scales.items()},
        "stats": {"steps_total": len(c.steps), "steps_evaluated": ev.evaluated},
    }
    if "textbook" in sol.extras:
        from .textbook_report import cycle_json
        doc["textbook"] = cycle_json(sol)
    diagram = _diagram_json(sol)
    if diagram is not None:
        doc["kinematic_diagram"] = diagram
    return doc


def _diagram_json(sol: Solution) -> dict[str, Any] | None:
    """The kinematic diagram's ordinates at the solution's positions: the output link's s, v, a
    (a slider: along its guide, m; a rocker: ψ, ω, ε in rad) over the driver's coordinate and the
    law's time of each position (docs/drivers.md)."""
    from .model.law import driver_time
    from .model.output import output_link

    mech, c, ev = sol.scene.mechanism, sol.construction, sol.ev
    out = output_link(mech)
    if out is None:
        return None
    x = np.asarray(sol.phi, dtype=float)        # rad, or m (a linear driver)
    series: dict[str, Any] = {}
    if out.point is not None:
        u = np.asarray(out.direction)
        for key, sym, image in (("s", "r", c.position), ("v", "v", c.velocity_image),
                                ("a", "a", c.acceleration_image)):
            if sym == "r" or c.has_result(sym, out.point):
                sid = image(out.point)
                if sid in ev.values:
                    series[key] = np.asarray(ev[sid]) @ u
    else:
        for key, sym, step in (("s", "angle", c.link_angle), ("v", "omega", c.omega),
                               ("a", "epsilon", c.epsilon)):
            if c.has_result(sym, out.link) and step(out.link) in ev.values:
                series[key] = np.asarray(ev[step(out.link)], dtype=float)
    if "s" not in series:
        return None
    with np.errstate(invalid="ignore", divide="ignore"):
        t = driver_time(mech.drive, x)
    return {"output": {"link": out.link, "point": out.point,
                       "kind": "rocker" if out.point is None else "slider"},
            "coordinate": _driver_json(mech.drive)["coordinate"],
            "x": [_num(v) for v in x], "t": [_num(v) for v in t],
            **{k: [_num(v) for v in arr] for k, arr in series.items()}}


def _num(x: Any) -> float | None:
    x = float(x)
    return x + 0.0 if math.isfinite(x) else None


def _driver_json(drive: Any) -> dict[str, Any]:
    """The driver and its law: its kind, link, coordinate and rates (SI)."""
    linear = drive.linear
    doc = {"kind": drive.kind.value, "link": drive.link,
           "coordinate": ("l" if drive.kind.value == "cylinder" else "s") if linear else "phi",
           "unit": "m" if linear else "rad", "rate": drive.omega, "acceleration": drive.epsilon}
    if drive.law is not None:       # a law by a table over time (docs/drivers.md)
        from .model.law import interpolation_error

        err = interpolation_error(drive.law)
        doc["law"] = {"source": drive.law.source, "rows": len(drive.law.times),
                      "span": list(drive.law.span), "interpolation": "cubic spline",
                      "interpolation_error": {"coordinate": err[0], "rate": err[1],
                                              "acceleration": err[2]}}
    return doc


def segment_table(sol: Solution, plan: Plan, k: int) -> list[tuple[str, float, float, str, float]]:
    """(segment, mm on paper, μ, quantity, physical value) of a plan at position k."""
    rows = []
    mu = sol.scales.get(plan, 1.0)
    for s in sol.construction.segments:
        if s.plan is plan and s.start in sol.ev.values and s.end in sol.ev.values:
            length = float(np.hypot(*(sol.ev[s.end][k] - sol.ev[s.start][k])))
            rows.append((s.name, length / mu, mu, s.quantity, length))
    return rows


__all__ = ["SegmentKind", "Solution", "crank_positions", "position_count", "segment_table",
           "shown_coordinate", "solve", "to_json"]
