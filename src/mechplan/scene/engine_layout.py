"""Engine layouts with several cylinders on one crank pin: a master rod with articulated rods on
every throw of a V engine, radial engines; and the crank-end face of a double-acting cylinder.

The master rod and its articulated rods are written as a mechanism scene (:func:`group_linkage`),
so mechplan's exact construction computes every articulated piston.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..errors import SceneError
from ..i18n import Text
from ..model.engine import ArticulatedRod, ArticulatedSpec, EngineSpec, Layout, RodSideSpec
from .reader import Table
from .spec import Scene

TURN = 2.0 * math.pi


def articulated_layout(e: Table, a: Table, layout: Layout, L: float
                       ) -> tuple[int, list[float], list[float], tuple[ArticulatedRod, ...]]:
    """Cylinders, throws, banks and articulated rods of a ``v_articulated`` or ``radial`` engine.

    ``v_articulated``: cylinders 2k−1 (master, bank 0) and 2k (articulated, bank ``bank_angle``)
    on throw k. ``radial``: one throw, cylinder 1 with the master rod, the others at equal angles
    (or ``[engine] banks``) with articulated rods whose lugs sit at ``lug_angles`` (default: each
    cylinder's angle from cylinder 1).
    """
    from .engine import _angles, _articulated, _rod

    if layout is Layout.ARTICULATED:
        art, bank = _articulated(a)
        n = e.raw("cylinders", 2)
        if not isinstance(n, int) or isinstance(n, bool) or not 2 <= n <= 24 or n % 2:
            raise e.error("cylinders", Text("layouts.error.articulated_cylinders",
                                            {"value": repr(n)}))
        if e.has("banks"):
            raise e.error("banks", Text("layouts.error.banks_from_bank_angle"))
        if n > 2 and not e.has("throws"):
            raise e.error("throws", Text("errmsg3.engine.v_throws"))
        throws = _angles(e, "throws", n)
        for k in range(0, n, 2):
            if abs(math.remainder(throws[k] - throws[k + 1], TURN)) > 1e-12:
                raise e.error("throws", Text("layouts.error.pair_throw",
                                             {"master": str(k + 1), "rod": str(k + 2)}))
        banks = [0.0 if i % 2 == 0 else bank for i in range(n)]
        lug = art.lug_angle if math.sin(bank) > 0 else -art.lug_angle
        rods = tuple(ArticulatedRod(k + 2, k + 1, lug, art) for k in range(0, n, 2))
        return n, throws, banks, rods
    a.check_keys(("lug_radius", "lug_angles", "rod_length", "piston", "rod", "rod_small_end",
                  "rod_centre", "rod_J"))
    n = e.raw("cylinders", None)
    if not isinstance(n, int) or isinstance(n, bool) or not 2 <= n <= 12:
        raise e.error("cylinders", Text("layouts.error.radial_cylinders", {"value": repr(n)}))
    if e.has("throws"):
        raise e.error("throws", Text("layouts.error.radial_throws"))
    banks = (_angles(e, "banks", n) if e.has("banks")
             else [(i * TURN / n) % TURN for i in range(n)])
    r = a.quantity("lug_radius", "length", required=True, positive=True)
    length = a.quantity("rod_length", "length", required=True, positive=True)
    piston = a.quantity("piston", "mass", required=True, nonnegative=True)
    assert r is not None and length is not None and piston is not None
    if r >= L:
        raise a.error("lug_radius", Text("layouts.error.lug_radius",
                                         {"r": f"{r * 1e3:g}", "L": f"{L * 1e3:g}"}))
    if a.has("lug_angles"):
        lugs = [math.remainder(v, TURN) for v in _angles(a, "lug_angles", n - 1)]
    else:
        lugs = [math.remainder(b - banks[0], TURN) for b in banks[1:]]
    spec = ArticulatedSpec(r, 0.0, length, piston, _rod(a, length))
    rods = tuple(ArticulatedRod(i + 2, 1, lugs[i], spec) for i in range(n - 1))
    return n, [0.0] * n, banks, rods


def radial_firing_order(n: int, strokes: int) -> list[int]:
    """The usual firing order of a radial: every other cylinder (four-stroke, odd n), else in
    turn."""
    if strokes == 4 and n % 2:
        return list(range(1, n + 1, 2)) + list(range(2, n + 1, 2))
    return list(range(1, n + 1))


def group_linkage(spec: EngineSpec, file: str) -> Scene:
    """The crank, master rod and articulated rods of one throw as a mechanism scene.

    The master cylinder (piston C) lies along +x, articulated cylinder k (lug Dk, piston Ek) on
    guide Gk at its bank angle from the master's counter-clockwise; the crank turns
    counter-clockwise from +x, so the scene's crank angle is the engine's crank angle from the
    master cylinder's axis. Every throw of a ``v_articulated`` engine has this same geometry.
    """
    from .loader import parse_scene

    first = spec.rods[0].master
    rods = [r for r in spec.rods if r.master == first]
    bank = {c.number: c.bank for c in spec.cylinders}
    for r in rods:
        _check_reach(spec, r, math.remainder(bank[r.number] - bank[first], TURN), file)
    mm = 1e3

    def q(x: float, unit: str = "mm") -> str:
        return f'"{x!r} {unit}"'

    guides = "".join(
        f'guides.G{k} = {{ through = "A", angle = '
        f'{q(math.degrees(math.remainder(bank[r.number] - bank[first], TURN)), "deg")} }}\n'
        for k, r in enumerate(rods, 1))
    lugs = ", ".join(
        f"D{k} = [{q(r.spec.lug_radius * math.cos(r.lug) * mm)}, "
        f"{q(r.spec.lug_radius * math.sin(r.lug) * mm)}]" for k, r in enumerate(rods, 1))
    links = "".join(
        f"[links.{2 * k + 2}]\nlengths = {{ D{k}E{k} = {q(r.spec.rod_length * mm)} }}\n"
        f'[links.{2 * k + 3}]\nslides = {{ point = "E{k}", on = "G{k}" }}\n'
        for k, r in enumerate(rods, 1))
    assembly = "".join(f'E{k} = "+"\n' for k in range(1, len(rods) + 1))
    text = f"""
title = "master and articulated rods"
[ground]
A = ["0 mm", "0 mm"]
guides.Ax = {{ through = "A", angle = "0 deg" }}
{guides}
[links.1]
lengths = {{ AB = {q(spec.R * mm)} }}
[links.2]
lengths = {{ BC = {q(spec.L * mm)} }}
points = {{ {lugs} }}
[links.3]
slides = {{ point = "C", on = "Ax" }}
{links}
[drive]
link = "1"
speed = "{spec.speed!r} rad/s"
sense = "ccw"
from = "Ax"
[assembly]
C = "+"
{assembly}
"""
    try:
        return parse_scene(text, file)
    except SceneError as exc:
        raise SceneError(Text("errmsg3.engine.articulated_build", {"reason": exc.detail}),
                         file=file, key="articulated") from None


def _check_reach(spec: EngineSpec, rod: ArticulatedRod, bank: float, file: str) -> None:
    """Refuse an articulated rod that cannot reach its cylinder's axis (on the cylinder's side of
    the crank axis) at some crank angle: the closed-form master rod over a turn."""
    theta = np.linspace(0.0, TURN, 3601)
    Bx, By = spec.R * np.cos(theta), spec.R * np.sin(theta)
    Cx = Bx + np.sqrt(spec.L ** 2 - By ** 2)
    alpha = np.arctan2(-By, Cx - Bx)
    r, length = rod.spec.lug_radius, rod.spec.rod_length
    Dx, Dy = Bx + r * np.cos(alpha + rod.lug), By + r * np.sin(alpha + rod.lug)
    ux, uy = math.cos(bank), math.sin(bank)
    across = np.abs(Dx * uy - Dy * ux)
    along = Dx * ux + Dy * uy + np.sqrt(np.clip(length ** 2 - across ** 2, 0.0, None))
    bad = np.flatnonzero((across >= length * (1.0 - 1e-9)) | (along <= 0.0))
    if bad.size:
        k = int(bad[0])
        need = float(np.max(across)) * 1e3
        raise SceneError(Text("layouts.error.unreachable", {
            "number": str(rod.number), "angle": f"{math.degrees(theta[k]):.1f}",
            "need": f"{need:.1f}"}), file=file, key="articulated.rod_length")


def rod_side(t: Table, bore: float, strokes: int, file: str,
             data_dir: str | Path | None) -> RodSideSpec:
    """The ``[rod_side]`` table of a double-acting cylinder."""
    from .engine import _indicator

    t.check_keys(("rod_diameter", "indicator"))
    d = t.quantity("rod_diameter", "length", required=True, positive=True)
    assert d is not None
    if not d < bore:
        raise t.error("rod_diameter", Text("layouts.error.rod_diameter",
                                           {"d": f"{d * 1e3:g}", "bore": f"{bore * 1e3:g}"}))
    ind = t.table("indicator")
    return RodSideSpec(d, None if ind is None else _indicator(ind, strokes, file, data_dir))
