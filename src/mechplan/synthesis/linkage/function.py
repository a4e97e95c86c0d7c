"""A four-bar function generator by Freudenstein's equation at three precision points.

y = f(x) on [x0, x1] is mapped linearly to the crank angle φ (from the frame line A→D) and the
rocker angle ψ (of DC, from the same line). With A at the origin and D at (d, 0), the loop
a·e^{iφ} + b·e^{iθ} = d + c·e^{iψ} gives Freudenstein's equation

    K1·cos ψ − K2·cos φ + K3 = cos(φ − ψ),  K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac),

linear in K1, K2, K3: three precision points (Chebyshev spacing by default) fix them. Between the
points the linkage deviates from f: the structural error, computed along the range on the branch
of the first precision point. Defects are reported: a precision point on the other assembly branch
(branch defect) or a position between the points where the linkage cannot be assembled (the
motion would have to pass a dead position: circuit defect).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from . import geometry as g
from .crank_rocker import grashof
from .design import LinkageDesign, Step, Stroke
from .scene_out import base, link_name, mm

FUNCTIONS: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "log10": np.log10, "ln": np.log, "exp": np.exp, "sqrt": np.sqrt,
    "square": np.square, "cube": lambda x: x ** 3, "reciprocal": lambda x: 1.0 / x,
    "sin": np.sin, "cos": np.cos, "tan": np.tan,
}
ERROR_SAMPLES = 721
DEFAULT_FRAME = 0.1


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def chebyshev(x0: float, x1: float, n: int = 3) -> list[float]:
    """Chebyshev spacing of n precision points on [x0, x1]."""
    return [(x0 + x1) / 2 - (x1 - x0) / 2 * math.cos((2 * j - 1) * math.pi / (2 * n))
            for j in range(1, n + 1)]


def freudenstein(phi: list[float], psi: list[float]) -> tuple[float, float, float]:
    """K1, K2, K3 from three (φ, ψ) pairs (rad) exactly, from more by least squares."""
    m = np.array([[math.cos(s), -math.cos(p), 1.0] for p, s in zip(phi, psi)])
    rhs = np.array([math.cos(p - s) for p, s in zip(phi, psi)])
    sv = np.linalg.svd(m, compute_uv=False)
    if sv[-1] < 1e-12 * sv[0]:
        raise np.linalg.LinAlgError("singular")
    k1, k2, k3 = np.linalg.lstsq(m, rhs, rcond=None)[0]
    return float(k1), float(k2), float(k3)


def rocker_angle(phi: np.ndarray, a: float, b: float, c: float, d: float,
                 branch: float) -> np.ndarray:
    """ψ of the four-bar at crank angles φ on the branch sign(cross(D − B, C − B)) = branch;
    NaN where it cannot be assembled."""
    bx, by = a * np.cos(phi), a * np.sin(phi)
    ex, ey = d - bx, -by                      # B → D
    e = np.hypot(ex, ey)
    # C on circle(B, b) ∩ circle(D, c): foot along B→D, then ± along the normal
    along = (b * b - c * c + e * e) / (2 * e)
    h2 = b * b - along * along
    h = np.sqrt(np.where(h2 >= 0, h2, np.nan))
    ux, uy = ex / e, ey / e
    # the normal (−uy, ux) is to the left of B→D: cross(D − B, C − B) > 0 there
    cx = bx + along * ux - branch * h * uy
    cy = by + along * uy + branch * h * ux
    return np.arctan2(cy, cx - d)


def function_generator(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the function generator a ``problem = "function"`` scene asks for."""
    if spec.function is None or spec.x_range is None:
        raise _error(spec, "function" if spec.function is None else "x_range", "needs",
                     problem=spec.problem)
    if not spec.input_range or not spec.output_range:
        raise _error(spec, "input_range" if not spec.input_range else "output_range",
                     "nonzero", problem=spec.problem)
    f = FUNCTIONS[spec.function]
    x0, x1 = spec.x_range
    y0, y1 = (float(v) for v in f(np.array([x0, x1], dtype=float)))
    if not (math.isfinite(y0) and math.isfinite(y1)) or y0 == y1:
        raise _error(spec, "x_range", "function_range", f=spec.function, x0=repr(x0),
                     x1=repr(x1))
    d = spec.frame if spec.frame is not None else DEFAULT_FRAME
    xs = list(spec.points) if spec.points is not None else chebyshev(x0, x1, spec.point_count)

    def phi_of(x: np.ndarray | float) -> np.ndarray | float:
        return spec.input_start + spec.input_range * (x - x0) / (x1 - x0)  # type: ignore[operator]

    def psi_of(x: np.ndarray) -> np.ndarray:
        return spec.output_start + spec.output_range * (f(x) - y0) / (y1 - y0)  # type: ignore[operator]

    phis = [float(phi_of(x)) for x in xs]
    psis = [float(v) for v in psi_of(np.array(xs, dtype=float))]
    if not all(math.isfinite(v) for v in psis):
        raise _error(spec, "points", "function_range", f=spec.function, x0=repr(x0),
                     x1=repr(x1))
    try:
        k1, k2, k3 = freudenstein(phis, psis)
    except np.linalg.LinAlgError:
        raise _error(spec, "points", "singular_points") from None
    if k1 == 0 or k2 == 0:
        raise _error(spec, "input_start", "no_linkage", k1=repr(round(k1, 6)),
                     k2=repr(round(k2, 6)))
    a_s, c_s = d / k1, d / k2            # signed: a negative link points the other way
    b2 = a_s * a_s + c_s * c_s + d * d - 2 * a_s * c_s * k3
    if not b2 > 0:
        raise _error(spec, "input_start", "no_coupler", b2=repr(round(b2 * 1e6, 6)))
    a, b, c = abs(a_s), math.sqrt(b2), abs(c_s)
    turn_a = math.pi if a_s < 0 else 0.0   # the drawn crank at φ + 180°
    turn_c = math.pi if c_s < 0 else 0.0   # the drawn rocker at ψ + 180°
    phi_of_asked, psi_of_asked = phi_of, psi_of

    def phi_of(x):  # type: ignore[no-redef]
        return phi_of_asked(x) + turn_a

    def psi_of(x):  # type: ignore[no-redef]
        return psi_of_asked(x) + turn_c

    asked = list(zip(phis, psis))
    phis = [p + turn_a for p in phis]
    psis = [v + turn_c for v in psis]
    # the branch of each precision point (B from φ, C from ψ)
    sides = []
    for p, s in zip(phis, psis):
        bp = (a * math.cos(p), a * math.sin(p))
        cp = (d + c * math.cos(s), c * math.sin(s))
        sides.append(math.copysign(1.0, g.cross(g.sub((d, 0.0), bp), g.sub(cp, bp))))
    branch = sides[0]
    branch_defect = any(sd != branch for sd in sides)
    x_dense = np.linspace(x0, x1, ERROR_SAMPLES)
    psi_act = rocker_angle(np.asarray(phi_of(x_dense)), a, b, c, d, branch)
    circuit_defect = bool(np.any(np.isnan(psi_act)))
    dpsi = np.angle(np.exp(1j * (psi_act - psi_of(x_dense))))
    dy = dpsi * (y1 - y0) / spec.output_range
    i = int(np.nanargmax(np.abs(dy))) if not np.all(np.isnan(dy)) else 0
    ok, margin = grashof({"1": a, "2": b, "3": c, "0": d})
    scene = base(spec, {"A": ["0 mm", "0 mm"], "D": [mm(d), "0 mm"]}, {
        "1": {"name": link_name("crank", spec), "lengths": {"AB": mm(a)}},
        "2": {"name": link_name("coupler", spec), "lengths": {"BC": mm(b)}},
        "3": {"name": link_name("rocker", spec), "lengths": {"DC": mm(c)}},
    }, {"angle": repr(math.degrees(phis[0])) + " deg"},
        {"at": repr(math.degrees(phis[0])) + " deg",
         "C": ("left" if branch > 0 else "right") + " of B->D"})
    scene["positions"] = {"at": [repr(math.degrees(p)) + " deg" for p in phis]}
    strokes = [Stroke("point", (0.0, 0.0), role="given", label="A"),
               Stroke("point", (d, 0.0), role="given", label="D"),
               Stroke("line", (0.0, 0.0), (d, 0.0), role="given")]
    for j, (p, s) in enumerate(zip(phis, psis), start=1):
        bp = (a * math.cos(p), a * math.sin(p))
        cp = (d + c * math.cos(s), c * math.sin(s))
        strokes += [Stroke("line", (0.0, 0.0), bp, role="mechanism", label=f"B{j}"),
                    Stroke("line", bp, cp, role="result"),
                    Stroke("line", (d, 0.0), cp, role="mechanism", label=f"C{j}")]
    strokes.append(Stroke("circle", (0.0, 0.0), r=a, role="aux"))
    strokes.append(Stroke("circle", (d, 0.0), r=c, role="aux"))
    protocol = [Step("synth.fg.mapping", {"x0": x0, "x1": x1, "phi0": spec.input_start,
                                          "dphi": spec.input_range,
                                          "psi0": spec.output_start,
                                          "dpsi": spec.output_range})]
    choice = Step("synth.fg.chebyshev" if spec.points is None else "synth.fg.points",
                  {"n": len(xs)})
    protocol.append(choice)
    for j, (x, (p, s)) in enumerate(zip(xs, asked), start=1):
        protocol.append(Step("synth.fg.point", {"n": j, "x": x, "y": float(f(np.array(x))),
                                                "phi": p, "psi": s}))
    protocol += [Step("synth.fg.solve" if len(xs) == 3 else "synth.fg.lstsq",
                      {"k1": k1, "k2": k2, "k3": k3, "n": len(xs)}),
                 Step("synth.fg.lengths", {"d": d, "a": a_s, "b": b, "c": c_s})]
    if turn_a or turn_c:
        protocol.append(Step("synth.fg.turned", {"a": a, "c": c}))
    conditions = {
        "grashof": ok, "grashof_margin": margin,
        "branch_defect": branch_defect, "circuit_defect": circuit_defect,
        "precision_x": xs, "precision_phi": phis, "precision_psi": psis,
        "structural_error_max": float(abs(dy[i])), "structural_error_at_x": float(x_dense[i]),
        # every 6th sample: x, φ, the wanted ψ and the error in y
        "structural_error": [[float(x), float(p), float(w), float(e)] for x, p, w, e in
                             zip(x_dense[::6], np.asarray(phi_of(x_dense))[::6],
                                 psi_of(x_dense)[::6], dy[::6])],
        "y_per_rad": (y1 - y0) / spec.output_range,
        "K1": k1, "K2": k2, "K3": k3, "crank_turned": bool(turn_a), "rocker_turned": bool(turn_c),
    }
    return LinkageDesign("function", 1.0, 0.0, {"a": a, "b": b, "c": c, "d": d}, strokes,
                         protocol, conditions, [], choice, scene, "3", "function", 0.0)
