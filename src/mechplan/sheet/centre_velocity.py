"""The velocities by instant centres drawn on the instant-centre panel, and their table.

Each step of the construction (``construct/plans/centre_velocity.py``) is drawn as a student
draws it: a point carried to the line of centres by a thin arc about its fixed centre, a
velocity as an arrow from its point at the panel's arrow scale, the ray of similar triangles from
the fixed centre through the tips of the two arrows on the line of centres. The table beside
gives each velocity as its arrow measured (mm) and read back at that scale, the construction's
value and the velocity plan's, and their relative difference. Nothing here computes mechanics:
the values come from the evaluated construction.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ..construct.centre_drawn import DrawnVelocities, drawn, measured_agreement
from ..construct.centre_kinematics import acceleration_pole
from ..construct.centre_protocol import measure, names
from ..construct.plans.centres import centres_at
from ..construct.scale import round_scale
from ..construct.step import Step
from ..drafting.primitives import Arc, Line, Role, Text
from ..drafting.wrap import wrap
from ..i18n import message, number, scientific, significant
from ..solve import Solution
from .panels import TITLE_H, Panel, table

#: the longest arrow takes this share of the view's larger side
ARROW_SHARE = 0.3
TEXT_H = 2.5
#: what a velocity step is drawn from: the input holding its point
_AT = {"ic_drive_velocity": "point", "ic_pole_velocity": "point", "ic_arc_velocity": "target",
       "ic_similar_velocity": "target"}

MM = Callable[[np.ndarray], tuple[float, float]]


def drawn_velocities(sol: Solution) -> DrawnVelocities | None:
    """The drawn construction of a solution (memoised in ``sol.extras`` as the report's)."""
    if "centres_drawn" not in sol.extras:
        sol.extras["centres_drawn"] = drawn(sol.construction, sol.ev, sol.scene.mechanism,
                                            centres_at(sol.construction, sol.ev,
                                                       sol.scene.mechanism))
    return sol.extras["centres_drawn"]  # type: ignore[no-any-return]


def arrow_scale(dv: DrawnVelocities, k: int, view_mm: float) -> float:
    """A round μv (m/s per mm) for the arrows at position k."""
    top = 0.0
    for st in dv.cv.construction:
        if st.op.value in _AT:
            v = dv.ev[st.id][k]
            if np.all(np.isfinite(v)):
                top = max(top, float(np.hypot(*v)))
    return round_scale(top / (ARROW_SHARE * view_mm)) if top > 0 and view_mm > 0 else 1.0


def _centre(dv: DrawnVelocities, st: Step, k: int) -> np.ndarray | None:
    h = dv.ev[st.input("centre")][k]
    if not np.all(np.isfinite(h)) or h[2] == 0.0:
        return None
    out: np.ndarray = h[:2] * st.param("length") / h[2]
    return out


def draw_velocities(panel: Panel, sol: Solution, k: int, mm: MM, mu: float,
                    lang: str) -> float | None:
    """Draw the construction at position k into the panel (mm = world / μ); the arrows' μv."""
    dv = drawn_velocities(sol)
    if dv is None:
        return None
    x0, y0, x1, y1 = panel.bounds()
    mu_v = arrow_scale(dv, k, max(x1 - x0, y1 - y0))
    grow = 0.1 * max(x1 - x0, y1 - y0)
    box = (np.array([x0 - grow, y0 - grow]), np.array([x1 + grow, y1 + grow]))
    sym = message("centres.symbol", lang)
    ev = dv.ev
    for st in dv.cv.construction:
        op = st.op.value
        if op == "ic_carry":
            _carry(panel, dv, st, k, mm, mu, sym, box)
        elif op in _AT:
            at = ev[st.input(_AT[op])][k]
            v = ev[st.id][k]
            if not (np.all(np.isfinite(at)) and np.all(np.isfinite(v))):
                continue
            base = np.array(mm(at))
            tip = base + v / mu_v
            if op == "ic_similar_velocity":
                _ray(panel, dv, st, k, mm, mu_v, tip, box)
            if float(np.hypot(*(tip - base))) < 0.3 or not _inside(base, box):
                continue
            role = Role.OUTLINE if st.role.value == "result" else Role.THIN
            panel.primitives.extend(_vector(base, tip, role))
            panel.primitives.append(Text((float(tip[0]) + 0.8, float(tip[1]) + 0.8),
                                         names(st.label, sym), TEXT_H))
    panel.primitives.append(Text((x0, y0 - 6.0), message(
        "icdraw.panel.arrows", lang, value=significant(mu_v, 4, lang)), TEXT_H))
    return mu_v


Box = tuple[np.ndarray, np.ndarray]
#: the open arrowhead of a velocity: its length (mm) and half-angle (°)
HEAD_MM, HEAD_DEG = 2.5, 15.0


def _vector(base: np.ndarray, tip: np.ndarray, role: Role) -> list[Line]:
    """A velocity drawn with an open arrowhead (two strokes): the checker's readers take a
    solid arrowhead for the arrow of a far centre, which a velocity is not."""
    d = tip - base
    u = d / float(np.hypot(*d))
    head = min(HEAD_MM, 0.5 * float(np.hypot(*d)))
    out = [Line(tuple(base), tuple(tip), role)]
    for sign in (1.0, -1.0):
        a = math.radians(sign * HEAD_DEG)
        w = np.array([u[0] * math.cos(a) - u[1] * math.sin(a),
                      u[0] * math.sin(a) + u[1] * math.cos(a)])
        out.append(Line(tuple(tip), tuple(tip - head * w), role))
    return out


def _inside(p: np.ndarray, box: Box) -> bool:
    return bool(np.all(p >= box[0]) and np.all(p <= box[1]))


def _clipped(a: np.ndarray, b: np.ndarray, box: Box) -> tuple[np.ndarray, np.ndarray] | None:
    """The part of the segment ab inside the box."""
    t0, t1, d = 0.0, 1.0, b - a
    for i in range(2):
        if abs(d[i]) < 1e-12:
            if not box[0][i] <= a[i] <= box[1][i]:
                return None
            continue
        ta, tb = (box[0][i] - a[i]) / d[i], (box[1][i] - a[i]) / d[i]
        t0, t1 = max(t0, min(ta, tb)), min(t1, max(ta, tb))
    return (a + t0 * d, a + t1 * d) if t0 < t1 else None


def _carry(panel: Panel, dv: DrawnVelocities, st: Step, k: int, mm: MM, mu: float,
           sym: str, box: Box) -> None:
    c = _centre(dv, st, k)
    x, x2 = dv.ev[st.input("point")][k], dv.ev[st.id][k]
    if c is None or not (np.all(np.isfinite(x)) and np.all(np.isfinite(x2))):
        return
    r = float(np.hypot(*(x - c))) / mu
    if r < 0.5 or r > 2.0 * float(np.hypot(*(box[1] - box[0]))) or \
            not _inside(np.array(mm(x2)), box):
        return
    a0 = math.degrees(math.atan2(*(x - c)[::-1]))
    a1 = math.degrees(math.atan2(*(x2 - c)[::-1]))
    sweep = (a1 - a0) % 360.0
    start, end = (a0, a1) if sweep <= 180.0 else (a1, a0)
    if abs(math.remainder(a1 - a0, 360.0)) > 0.2:
        panel.primitives.append(Arc(mm(c), r, start, end, Role.THIN))
    p = mm(x2)
    panel.primitives.append(Text((p[0] + 0.8, p[1] - 3.0), names(st.label, sym), TEXT_H))


def _ray(panel: Panel, dv: DrawnVelocities, st: Step, k: int, mm: MM, mu_v: float,
         tip: np.ndarray, box: Box) -> None:
    """The ray of similar triangles from the fixed centre through the two arrows' tips."""
    c = _centre(dv, st, k)
    src, v_src = dv.ev[st.input("source")][k], dv.ev[st.input("v_source")][k]
    if c is None or not (np.all(np.isfinite(src)) and np.all(np.isfinite(v_src))):
        return
    start = np.array(mm(c))
    other = np.array(mm(src)) + v_src / mu_v
    far = max((tip, other), key=lambda q: float(np.hypot(*(q - start))))
    seg = _clipped(start, far, box) if float(np.hypot(*(far - start))) > 0.3 else None
    if seg is not None:
        panel.primitives.append(Line(tuple(seg[0]), tuple(seg[1]), Role.THIN))


def pole_marks(sol: Solution, k: int, box: tuple[np.ndarray, np.ndarray],
               mm: MM) -> dict[str, tuple[float, float]]:
    """The acceleration poles of the ``[centres] links`` at position k inside the view (world
    box ``box``), named ``Q2`` (the pole of link 2), in panel mm."""
    spec, c, ev, mech = sol.scene.centres, sol.construction, sol.ev, sol.scene.mechanism
    out: dict[str, tuple[float, float]] = {}
    if spec is None or not c.has_result("epsilon", mech.drive.link):
        return out
    for lid in spec.links:
        if not c.has_result("epsilon", lid):
            continue
        p = next(iter(mech.links[lid].points))
        q = acceleration_pole(ev[c.acceleration_image(p)][k:k + 1], ev[c.position(p)][k:k + 1],
                              ev[c.omega(lid)][k:k + 1], ev[c.epsilon(lid)][k:k + 1])[0]
        if np.all(np.isfinite(q)) and np.all(q >= box[0]) and np.all(q <= box[1]):
            out[f"Q{lid}"] = mm(q)
    return out


def velocity_table(sol: Solution, k: int, mu_v: float, lang: str) -> Panel | None:
    """Each velocity and ω by the drawn construction against the velocity plan at position k."""
    dv = drawn_velocities(sol)
    if dv is None:
        return None
    c, ev = sol.construction, sol.ev
    rows = [tuple(message(f"icdraw.table.{key}", lang) for key in
                  ("quantity", "arrow", "measured", "centres", "plan", "difference"))]
    v_scale = max([float(np.hypot(*ev[c.velocity_image(p)][k])) for p in dv.cv.v
                   if c.has_result("v", p)] + [0.0]) or 1.0
    w_scale = max([abs(float(ev[c.omega(lk)][k])) for lk in dv.cv.omega
                   if c.has_result("omega", lk)] + [0.0]) or 1.0
    for p, sid in dv.cv.v.items():
        v = dv.ev[sid][k]
        if not c.has_result("v", p) or not np.all(np.isfinite(v)):
            continue
        plan_v = ev[c.velocity_image(p)][k]
        m = measure(v, mu_v)
        diff = float(np.hypot(*(v - plan_v))) / v_scale
        rows.append((f"v_{p}", number(m.mm, 1, lang), significant(m.value, 4, lang),
                     significant(m.exact, 6, lang), significant(float(np.hypot(*plan_v)), 6, lang),
                     scientific(diff, 2, lang)))
    for lk, sid in dv.cv.omega.items():
        w = float(dv.ev[sid][k])
        if not c.has_result("omega", lk) or not math.isfinite(w):
            continue
        plan_w = float(ev[c.omega(lk)][k])
        rows.append((f"ω{lk}", "", "", significant(w, 6, lang), significant(plan_w, 6, lang),
                     scientific(abs(w - plan_w) / w_scale, 2, lang)))
    panel = Panel("centres-velocity", [table(rows, (0.0, 0.0))], plan=None)
    x0, y0, x1, y1 = panel.bounds()
    title = wrap(message("icdraw.table.title", lang), TITLE_H, max(x1 - x0, 80.0))
    for n, line in enumerate(reversed(title)):
        panel.primitives.append(Text((x0, y1 + 3.0 + 7.0 * n), line, TITLE_H))
    exact = float(dv.agreement[k])
    if math.isfinite(exact):
        lines = [message("icdraw.sheet.agreement", lang),
                 message("icdraw.sheet.exact", lang, value=scientific(max(exact, 0.0), 2, lang)),
                 message("icdraw.sheet.measured", lang, value=scientific(
                     measured_agreement(c, ev, dv, k, mu_v), 2, lang))]
        for n, line in enumerate(lines):
            panel.primitives.append(Text((x0, y0 - 5.0 - 4.0 * n), line, TEXT_H))
    return panel


__all__ = ["arrow_scale", "draw_velocities", "velocity_table"]
