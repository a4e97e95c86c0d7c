"""Three-position rigid-body guidance: the coupler BC given in three positions, the fixed pivots
found on the perpendicular bisectors (Burmester's construction for given moving pivots).

A is the centre of the circle through B1, B2, B3 (where the perpendicular bisectors of B1B2 and
B2B3 meet), D that through C1, C2, C3. Defects are reported: the positions on different assembly
branches (branch defect), the input link passing them out of order for either sense of rotation
(order defect), a position between them where the linkage cannot be assembled (circuit defect).
"""

from __future__ import annotations

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
        raise _error(spec, "C", "not_rigid", b1=repr(round(lengths_bc[0] * 1e3, 6)),
                     b2=repr(round(lengths_bc[1] * 1e3, 6)),
                     b3=repr(round(lengths_bc[2] * 1e3, 6)))
    A = circumcentre(*bs)
    D = circumcentre(*cs)
    if A is None or D is None:
        raise _error(spec, "B" if A is None else "C", "collinear")
    a, c = g.norm(g.sub(bs[0], A)), g.norm(g.sub(cs[0], D))
    b, d = sum(lengths_bc) / 3, g.norm(g.sub(D, A))
    if d <= 0 or a <= 0 or c <= 0:
        raise _error(spec, "B", "collinear")
    sides = [math.copysign(1.0, g.cross(g.sub(D, bj), g.sub(cj, bj))) for bj, cj in zip(bs, cs)]
    branch_defect = any(sd != sides[0] for sd in sides)
    phis = [g.angle_of(g.sub(bj, A)) for bj in bs]
    ccw2 = (phis[1] - phis[0]) % (2 * math.pi)
    ccw3 = (phis[2] - phis[0]) % (2 * math.pi)
    sense = 1 if ccw2 < ccw3 else -1         # the sense that meets 1, 2, 3 in order
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
    strokes += [Stroke("line", bs[0], bs[1]), Stroke("line", bs[1], bs[2]),
                Stroke("line", cs[0], cs[1]), Stroke("line", cs[1], cs[2]),
                _bisector(bs[0], bs[1], A), _bisector(bs[1], bs[2], A),
                _bisector(cs[0], cs[1], D), _bisector(cs[1], cs[2], D),
                Stroke("point", A, role="result", label="A"),
                Stroke("point", D, role="result", label="D"),
                Stroke("line", A, D, role="mechanism")]
    for bj, cj in zip(bs, cs):
        strokes += [Stroke("line", A, bj, role="mechanism"), Stroke("line", D, cj,
                                                                     role="mechanism")]
    protocol = [Step("synth.gd.given", {"b": b}),
                Step("synth.gd.pivot_a", {"x": A[0], "y": A[1], "a": a}),
                Step("synth.gd.pivot_d", {"x": D[0], "y": D[1], "c": c}),
                Step("synth.gd.lengths", {"a": a, "b": b, "c": c, "d": d})]
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
