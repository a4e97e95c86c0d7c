"""Two- and three-position rigid-body guidance: the coupler BC given in its positions, the fixed
pivots found on the perpendicular bisectors (for given moving pivots B and C). Three positions:
the bisectors meet at the pivots. Two positions: the pivots are where the bisectors cross a given
line (``pivot_line``); the bisectors themselves meet at the pole P12 of the displacement.

A is the centre of the circle through B1, B2, B3 (where the perpendicular bisectors of B1B2 and
B2B3 meet), D that through C1, C2, C3. Defects are reported: the positions on different assembly
branches (branch defect), the input link passing them out of order for either sense of rotation
(order defect), a position between them where the linkage cannot be assembled (circuit defect).
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from . import geometry as g
from .crank_rocker import grashof
from .design import LinkageDesign, Step, Stroke
from .function import rocker_angle
from .scene_out import base, link_name, mm

SWEEP_SAMPLES = 721
#: relative tolerance on the coupler length BC being the same in the three positions (positions
#: given to a drawing's precision; the round trip reports the miss this leaves)
RIGID_TOL = 1e-4


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def circumcentre(p1: g.Vec, p2: g.Vec, p3: g.Vec) -> g.Vec | None:
    """The centre of the circle through three points (None when they are collinear)."""
    ax, ay = p2[0] - p1[0], p2[1] - p1[1]
    bx, by = p3[0] - p1[0], p3[1] - p1[1]
    den = 2.0 * (ax * by - ay * bx)
    scale = max(g.norm((ax, ay)), g.norm((bx, by))) ** 2
    if abs(den) <= 1e-12 * scale:
        return None
    a2, b2 = ax * ax + ay * ay, bx * bx + by * by
    return p1[0] + (by * a2 - ay * b2) / den, p1[1] + (ax * b2 - bx * a2) / den


Line = tuple[g.Vec, float]


def _bisector_line(p: g.Vec, q: g.Vec) -> Line:
    """The perpendicular bisector of pq as (a point, a direction angle)."""
    return g.mul(g.add(p, q), 0.5), g.angle_of(g.sub(q, p)) + math.pi / 2


def _on_line(first: Line, second: Line) -> g.Vec | None:
    """Where two lines meet (None when they are parallel)."""
    (p, a1), (q, a2) = first, second
    u, v = (math.cos(a1), math.sin(a1)), (math.cos(a2), math.sin(a2))
    den = g.cross(u, v)
    if abs(den) < 1e-12:
        return None
    t = g.cross(g.sub(q, p), v) / den
    return g.add(p, g.mul(u, t))


def _bisector(p: g.Vec, q: g.Vec, centre: g.Vec) -> Stroke:
    """The perpendicular bisector of pq drawn from the chord's middle to the centre (and a bit
    beyond)."""
    m = g.mul(g.add(p, q), 0.5)
    return Stroke("line", g.sub(m, g.mul(g.sub(centre, m), 0.15)),
                  g.add(centre, g.mul(g.sub(centre, m), 0.1)))


def guidance(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the four-bar that carries the coupler BC through three given positions."""
    bs, cs = spec.guide_b, spec.guide_c
    if bs is None or cs is None:
        raise _error(spec, "B" if bs is None else "C", "needs", problem=spec.problem)
    lengths_bc = [g.norm(g.sub(c, b)) for b, c in zip(bs, cs)]
    if max(lengths_bc) - min(lengths_bc) > RIGID_TOL * max(lengths_bc):
        raise _error(spec, "C", "not_rigid",
                     lengths=", ".join(repr(round(v * 1e3, 6)) for v in lengths_bc))
    two = len(bs) == 2
    pole: g.Vec | None = None
    if two:
        if spec.pivot_line is None:
            raise _error(spec, "pivot_line", "needs", problem="guidance (2)")
        A = _on_line(_bisector_line(bs[0], bs[1]), spec.pivot_line)
        D = _on_line(_bisector_line(cs[0], cs[1]), spec.pivot_line)
        pole = _on_line(_bisector_line(bs[0], bs[1]), _bisector_line(cs[0], cs[1]))
        if A is None or D is None:
            raise _error(spec, "pivot_line", "parallel")
    else:
        A = circumcentre(*bs)
        D = circumcentre(*cs)
        if A is None or D is None:
            raise _error(spec, "B" if A is None else "C", "collinear")
    a, c = g.norm(g.sub(bs[0], A)), g.norm(g.sub(cs[0], D))
    b, d = sum(lengths_bc) / len(bs), g.norm(g.sub(D, A))
    if d <= 0 or a <= 0 or c <= 0:
        raise _error(spec, "B", "collinear")
    sides = [math.copysign(1.0, g.cross(g.sub(D, bj), g.sub(cj, bj))) for bj, cj in zip(bs, cs)]
    branch_defect = any(sd != sides[0] for sd in sides)
    phis = [g.angle_of(g.sub(bj, A)) for bj in bs]
    ccw2 = (phis[1] - phis[0]) % (2 * math.pi)
    ccw3 = (phis[-1] - phis[0]) % (2 * math.pi)
    if two:                                  # the shorter way from 1 to 2
        sense = 1 if ccw2 <= math.pi else -1
    else:                                    # the sense that meets 1, 2, 3 in order
        sense = 1 if ccw2 < ccw3 else -1
    sweep = ccw3 if sense > 0 else (2 * math.pi - ccw3)
    ok, margin = grashof({"1": a, "2": b, "3": c, "0": d})
    crank = ok and min(a, b, c, d) in (a, d)
    # the circuit between the positions: frame along +x from A
    frame_angle = g.angle_of(g.sub(D, A))
    phi_sweep = phis[0] - frame_angle + sense * np.linspace(0.0, sweep, SWEEP_SAMPLES)
    circuit_defect = bool(np.any(np.isnan(rocker_angle(phi_sweep, a, b, c, d, sides[0]))))
    order_defect = not crank and sweep > math.pi   # a rocking input cannot turn that far
    drive_sense = sense
    engine_phis = [(drive_sense * p) % (2 * math.pi) for p in phis]
    scene = base(spec, {"A": [mm(A[0]), mm(A[1])], "D": [mm(D[0]), mm(D[1])]}, {
        "1": {"name": link_name("crank", spec), "lengths": {"AB": mm(a)}},
        "2": {"name": link_name("coupler", spec), "lengths": {"BC": mm(b)}},
        "3": {"name": link_name("rocker", spec), "lengths": {"DC": mm(c)}},
    }, {}, {"at": repr(math.degrees(engine_phis[0])) + " deg",
            "C": [mm(cs[0][0]), mm(cs[0][1])]})
    scene["drive"]["sense"] = "ccw" if drive_sense > 0 else "cw"
    scene["positions"] = {"at": [repr(math.degrees(p)) + " deg" for p in engine_phis]}
    strokes: list[Stroke] = []
    for j, (bj, cj) in enumerate(zip(bs, cs), start=1):
        strokes += [Stroke("line", bj, cj, role="given"),
                    Stroke("point", bj, role="given", label=f"B{j}"),
                    Stroke("point", cj, role="given", label=f"C{j}")]
    for ps, centre in ((bs, A), (cs, D)):
        for p, q in itertools.pairwise(ps):
            strokes += [Stroke("line", p, q), _bisector(p, q, centre)]
    if pole is not None and spec.pivot_line is not None:
        (px, py), ang = spec.pivot_line
        u = (math.cos(ang), math.sin(ang))
        ts = [(q[0] - px) * u[0] + (q[1] - py) * u[1] for q in (A, D)]
        lo, hi = min(ts) - 0.2 * d, max(ts) + 0.2 * d
        strokes += [Stroke("line", (px + lo * u[0], py + lo * u[1]),
                           (px + hi * u[0], py + hi * u[1]), role="given"),
                    Stroke("point", pole, role="aux", label="P12"),
                    Stroke("line", A, pole), Stroke("line", D, pole)]
    strokes += [Stroke("point", A, role="result", label="A"),
                Stroke("point", D, role="result", label="D"),
                Stroke("line", A, D, role="mechanism")]
    for bj, cj in zip(bs, cs):
        strokes += [Stroke("line", A, bj, role="mechanism"), Stroke("line", D, cj,
                                                                     role="mechanism")]
    if two:
        protocol = [Step("synth.gd.given2", {"b": b})]
        if pole is not None:
            turn = math.remainder(g.angle_of(g.sub(cs[1], bs[1]))
                                  - g.angle_of(g.sub(cs[0], bs[0])), 2 * math.pi)
            protocol.append(Step("synth.gd.pole", {"x": pole[0], "y": pole[1], "angle": turn}))
        protocol += [Step("synth.gd.line_a", {"x": A[0], "y": A[1], "a": a}),
                     Step("synth.gd.line_d", {"x": D[0], "y": D[1], "c": c})]
    else:
        protocol = [Step("synth.gd.given", {"b": b}),
                    Step("synth.gd.pivot_a", {"x": A[0], "y": A[1], "a": a}),
                    Step("synth.gd.pivot_d", {"x": D[0], "y": D[1], "c": c})]
    protocol.append(Step("synth.gd.lengths", {"a": a, "b": b, "c": c, "d": d}))
    conditions = {
        "grashof": ok, "grashof_margin": margin, "crank": crank,
        "branch_defect": branch_defect, "order_defect": order_defect,
        "circuit_defect": circuit_defect, "sense": drive_sense,
        "precision_phi": engine_phis, "sweep": sweep,
        "positions_b": [list(p) for p in bs], "positions_c": [list(p) for p in cs],
        "A": list(A), "D": list(D),
    }
    return LinkageDesign("guidance", 1.0, 0.0, {"a": a, "b": b, "c": c, "d": d}, strokes,
                         protocol, conditions, [], protocol[1], scene, "3", "guidance", 0.0)
