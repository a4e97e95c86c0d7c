"""A sweep's plan: one construction per topology, and the steps each varied key changes.

A grid of variants shares the construction's steps, inputs and order; only some steps' parameters
(lengths, branch signs, ω) differ. Each step's dependence on the varied keys is found by probing,
and its versions are built once per combination of the keys it depends on — not once per variant —
so a worker evaluates a variant by swapping a few prepared steps into the shared construction.
Corners of the grid are rebuilt in full and compared, which catches a dependence the probes missed.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..construct.graph import Construction
from ..construct.ops import Op
from ..errors import MechplanError, SceneError
from ..i18n import Text
from ..model.mechanism import GROUND, PairKind
from ..scene import parse_scene
from ..scene.document import parse_toml
from ..solve import build
from .budget import check_axis_steps
from .keys import get_value, quantity_text, split_quantity, with_values

_VARY = re.compile(r"^\s*([^=\s]+)\s*=\s*(.+?)\s*\.\.\s*(.+?)\s*:\s*(\d+)\s*$")
MAX_CORNERS = 64


@dataclass(frozen=True)
class Axis:
    """One varied key: ``steps`` equal values from ``low`` to ``high`` in ``unit``."""

    key: str
    values: tuple[float, ...]
    unit: str = ""

    def scene_value(self, i: int) -> Any:
        """The i-th value as a scene writes it (``"80 mm"``)."""
        return quantity_text(self.values[i], self.unit)


def parse_vary(spec: str) -> Axis:
    """Parse ``KEY=FROM..TO:STEPS`` (e.g. ``links.1.lengths.AB=60mm..100mm:5``)."""
    m = _VARY.match(spec)
    if not m:
        raise SceneError(Text("batchvars.vary", {"value": repr(spec)}))
    key, a, b, steps = m.groups()
    low, unit = split_quantity(a, key)
    high, unit2 = split_quantity(b, key)
    unit = unit or unit2
    if unit2 and unit2 != unit:
        raise SceneError(Text("batchvars.same_unit", {"low": "FROM", "high": "TO",
                                                      "unit": repr(unit), "unit2": repr(unit2)}),
                         key=key)
    if len(steps) > 12:                           # an int of 400 digits is no budget to compute
        check_axis_steps(10**12, key)
    n = int(steps)
    if n < 1:
        raise SceneError(Text("batchvars.steps", {"value": str(n)}), key=key)
    check_axis_steps(n, key)
    if not (math.isfinite(low) and math.isfinite(high)):
        raise SceneError(Text("batchvars.finite", {"value": f"{a!r}..{b!r}"}), key=key)
    return Axis(key, tuple(float(f"{v:.12g}") for v in np.linspace(low, high, n)), unit)


@dataclass
class Summaries:
    """What each variant is summarised by: step ids of the quantities over the cycle."""

    velocity: dict[str, str] = field(default_factory=dict)       # point → step id
    acceleration: dict[str, str] = field(default_factory=dict)
    omega: dict[str, str] = field(default_factory=dict)          # link → step id
    epsilon: dict[str, str] = field(default_factory=dict)
    #: group ("2_3": its links) → (kind "RRR"/"RRP", (p1, p2, p3) position step ids,
    #: guide name or "")
    groups: dict[str, tuple[str, tuple[str, str, str], str]] = field(default_factory=dict)
    moment: str | None = None                                    # M_b step id

    def targets(self) -> list[str]:
        """Step ids to evaluate."""
        out = [*self.velocity.values(), *self.acceleration.values(), *self.omega.values(),
               *self.epsilon.values(), *(p for g in self.groups.values() for p in g[1])]
        if self.moment:
            out.append(self.moment)
        return list(dict.fromkeys(out))


@dataclass
class SweepPlan:
    """Everything a worker needs to evaluate any variant of the grid."""

    file: str
    axes: tuple[Axis, ...]
    phi: np.ndarray
    base: Construction
    summaries: Summaries
    #: record names (step ids, "__drive__", "__guide__.x") → the axes they depend on
    depends: dict[str, tuple[int, ...]]
    #: per dependence: combination of axis indices → {name: value} (None when it cannot be built)
    tables: dict[tuple[int, ...], dict[tuple[int, ...], dict[str, Any] | None]]
    errors: dict[tuple[tuple[int, ...], tuple[int, ...]], str]
    guides: dict[str, float] = field(default_factory=dict)      # frame guide → angle (rad)
    builds: int = 0

    @property
    def shape(self) -> tuple[int, ...]:
        """Grid shape: the number of values of each axis."""
        return tuple(len(a.values) for a in self.axes)

    @property
    def size(self) -> int:
        """Number of variants."""
        return math.prod(self.shape)

    def restricted(self, start: int, stop: int) -> SweepPlan:
        """The plan with only the prepared steps variants ``start``…``stop - 1`` use (small to
        send)."""
        grid = np.unravel_index(np.arange(start, stop), self.shape)
        tables = {}
        for dep, table in self.tables.items():
            used = set(zip(*(grid[i].tolist() for i in dep), strict=True)) if dep else {()}
            tables[dep] = {combo: table[combo] for combo in used}
        errors = {k: v for k, v in self.errors.items() if k[1] in tables[k[0]]}
        return dataclasses.replace(self, tables=tables, errors=errors)


def _plans(scene: Any) -> tuple[str, ...]:
    base = ("position", "velocity", "acceleration")
    return (*base, "force") if "force" in scene.plans else base


def _record(scene: Any, c: Construction) -> dict[str, Any]:
    rec: dict[str, Any] = dict(c.steps)
    rec["__drive__"] = c.drive
    for name, guide in scene.mechanism.guides.items():
        if guide.link == GROUND:
            rec[f"__guide__.{name}"] = guide.angle
    return rec


class _Builder:
    """Build the scene of any grid index (memoised)."""

    def __init__(self, text: str, file: str, axes: Sequence[Axis]) -> None:
        self.doc = parse_toml(text, file)
        self.file = file
        self.axes = axes
        for ax in axes:
            get_value(self.doc, ax.key, file)
        self.count = 0
        self.memo: dict[tuple[int, ...], tuple[Any, dict[str, Any] | str]] = {}

    def __call__(self, index: tuple[int, ...]) -> tuple[Any, dict[str, Any] | str]:
        if index not in self.memo:
            import tomli_w

            values = {ax.key: ax.scene_value(i) for ax, i in zip(self.axes, index, strict=True)}
            text = tomli_w.dumps(with_values(self.doc, values, self.file))
            self.count += 1
            try:
                scene = parse_scene(text, self.file)
                _, c = build(scene, _plans(scene))
                self.memo[index] = (scene, _record(scene, c))
            except MechplanError as exc:
                where = ", ".join(f"{ax.key} = {ax.scene_value(i)}"
                                  for ax, i in zip(self.axes, index, strict=True))
                self.memo[index] = (None, f"{where}: {exc.detail}")
        return self.memo[index]


def _same(a: Any, b: Any) -> bool:
    """Equality of recorded values (steps may hold arrays in their parameters)."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return bool(np.array_equal(a, b))
    if isinstance(a, tuple | list) and isinstance(b, tuple | list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if dataclasses.is_dataclass(a) and type(a) is type(b):
        return all(_same(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a))
    return bool(a == b)


def _same_structure(a: dict[str, Any], b: dict[str, Any], where: str) -> None:
    if a.keys() != b.keys() or any(
            getattr(a[k], "inputs", None) != getattr(b[k], "inputs", None) for k in a):
        raise MechplanError(Text("batchvars.topology", {"where": where}))


def make_plan(text: str, file: str, axes: Sequence[Axis], positions: int = 360) -> SweepPlan:
    """Plan a sweep of a mechanism scene over the grid of ``axes`` at ``positions`` crank angles."""
    if positions < 1:
        raise SceneError(Text("batchvars.positions", {"value": str(positions)}))
    keys = [ax.key for ax in axes]
    if len(set(keys)) != len(keys):
        raise SceneError(Text("batchvars.once", {"keys": ", ".join(keys)}))
    builder = _Builder(text, file, axes)
    origin = (0,) * len(axes)
    scene0, rec0 = builder(origin)
    if scene0 is None:
        raise MechplanError(Text("batchvars.first", {"reason": str(rec0)}), file=file)
    assert isinstance(rec0, dict)
    deps: dict[str, set[int]] = {name: set() for name in rec0}
    for i, ax in enumerate(axes):
        for j in sorted({len(ax.values) - 1, len(ax.values) // 2} - {0}):
            index = tuple(j if k == i else 0 for k in range(len(axes)))
            _, rec = builder(index)
            if isinstance(rec, str):
                for d in deps.values():      # cannot probe here: assume every step depends on it
                    d.add(i)
                continue
            _same_structure(rec0, rec, f"{ax.key} = {ax.scene_value(j)}")
            for name, value in rec.items():
                if not _same(value, rec0[name]):
                    deps[name].add(i)
    corners = list(itertools.product(*[sorted({0, len(a.values) - 1}) for a in axes]))
    if len(corners) > MAX_CORNERS:
        rng = np.random.default_rng(0)
        corners = [corners[int(k)] for k in rng.choice(len(corners), MAX_CORNERS, replace=False)]
    for _ in range(len(axes) + 1):
        tables, errors = _tables(builder, axes, deps)
        missed = False
        for corner in corners:
            _, rec = builder(corner)
            if isinstance(rec, str):
                continue
            _same_structure(rec0, rec, ", ".join(f"{a.key} = {a.scene_value(i)}"
                                                 for a, i in zip(axes, corner, strict=True)))
            derived = _derive(rec0, deps, tables, corner)
            for name, value in rec.items():
                if derived.get(name) is not None and not _same(derived[name], value):
                    deps[name] |= {k for k, i in enumerate(corner) if i}
                    missed = True
        if not missed:
            break
    _, base = build(scene0, _plans(scene0))
    summaries = _summaries(scene0, base)
    phi = np.arange(positions) * (2.0 * math.pi / positions)
    return SweepPlan(file, tuple(axes), phi, base, summaries,
                     {n: tuple(sorted(d)) for n, d in deps.items()}, tables, errors,
                     {n[len("__guide__."):]: v for n, v in rec0.items()
                      if n.startswith("__guide__.")},
                     builder.count)


def _tables(builder: _Builder, axes: Sequence[Axis], deps: dict[str, set[int]]
            ) -> tuple[dict[tuple[int, ...], dict[tuple[int, ...], dict[str, Any] | None]],
                       dict[tuple[tuple[int, ...], tuple[int, ...]], str]]:
    groups: dict[tuple[int, ...], list[str]] = {}
    for name, d in deps.items():
        if d:
            groups.setdefault(tuple(sorted(d)), []).append(name)
    tables: dict[tuple[int, ...], dict[tuple[int, ...], dict[str, Any] | None]] = {}
    errors: dict[tuple[tuple[int, ...], tuple[int, ...]], str] = {}
    for dep, names in groups.items():
        table: dict[tuple[int, ...], dict[str, Any] | None] = {}
        for combo in itertools.product(*[range(len(axes[i].values)) for i in dep]):
            index = [0] * len(axes)
            for i, j in zip(dep, combo, strict=True):
                index[i] = j
            _, rec = builder(tuple(index))
            if isinstance(rec, str):
                table[combo] = None
                errors[(dep, combo)] = rec
            else:
                table[combo] = {n: rec[n] for n in names}
        tables[dep] = table
    return tables, errors


def _derive(rec0: dict[str, Any], deps: dict[str, set[int]],
            tables: dict[tuple[int, ...], dict[tuple[int, ...], dict[str, Any] | None]],
            index: tuple[int, ...]) -> dict[str, Any]:
    out = dict(rec0)
    for dep, table in tables.items():
        row = table[tuple(index[i] for i in dep)]
        for name in (n for n, d in deps.items() if tuple(sorted(d)) == dep):
            out[name] = None if row is None else row[name]
    return out


def _summaries(scene: Any, c: Construction) -> Summaries:
    mech = scene.mechanism
    points = scene.points_of_interest or tuple(
        p for lk in mech.links.values() if lk.id != GROUND for p in lk.points)
    out = Summaries()
    fixed = set(mech.links[GROUND].points) if GROUND in mech.links else set()
    for p in (q for q in dict.fromkeys(points) if q not in fixed):
        for sym, table in (("v", out.velocity), ("a", out.acceleration)):
            if c.has_result(sym, p):
                table[p] = c.velocity_image(p) if sym == "v" else c.acceleration_image(p)
    for lid in mech.moving:
        if lid == mech.drive.link:
            continue
        for sym, table in (("omega", out.omega), ("epsilon", out.epsilon)):
            if c.has_result(sym, lid):
                sid = c.omega(lid) if sym == "omega" else c.epsilon(lid)
                if c[sid].op is not Op.CONSTANT:      # a slider on a frame guide: always zero
                    table[lid] = sid
    for g in _structure_groups(scene):
        p1, p2, p3 = g.outer1.point, g.inner.point, g.outer2.point
        if g.kind == "RRR":
            out.groups["_".join(g.links)] = (
                "RRR", (c.position(p1), c.position(p2), c.position(p3)), "")
        elif (g.kind == "RRP" and g.outer2.kind is PairKind.PRISMATIC and g.outer2.guide
              and mech.guides[g.outer2.guide].link == GROUND):
            out.groups["_".join(g.links)] = (
                "RRP", (c.position(p1), c.position(p2), c.position(p2)), g.outer2.guide)
    if "M_b" in c.results:
        out.moment = c.results["M_b"]
    return out


def _structure_groups(scene: Any) -> tuple[Any, ...]:
    from ..model.structure import analyse

    return analyse(scene.mechanism).groups
