"""The live page of a cam (``draw --format html`` of ``kind = "cam"``): the profile built by
inversion ray by ray (the cam sheet's own drawing, each primitive tagged with its ray), and the
cam turning with its follower moving on it, with s(φ) and a cursor. The positions are the
synthesis' samples; nothing here computes the cam.
"""

from __future__ import annotations

import math
from dataclasses import fields

import numpy as np

from ..drafting.primitives import Circle, Line, Polyline, Primitive, Role
from ..i18n import LANGUAGES, message
from ..i18n import number as format_number
from ..model.cam import Contact, Motion
from ..synthesis.cam import CamDesign
from ..synthesis.cam.profile import Sample, follower_positions
from .cam import _inversion
from .diagram import Axis, Curve, diagram_panel
from .live import Doc, cursor_panel, each, tagged

#: angles of the cam's animation over one turn
CAM_FRAMES = 360


def _rot(v: np.ndarray, ang: np.ndarray) -> np.ndarray:
    c, s = np.cos(ang), np.sin(ang)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=1)


def cam_replay(d: CamDesign) -> tuple[Doc, float]:
    """The inversion drawing of the cam sheet, ray by ray: base circle, each ray with the
    follower's inverted position and its point, then the pitch curve and the working profile."""
    drawn = {lang: _inversion(d, lang, 1.0) for lang in LANGUAGES}
    mu = drawn[LANGUAGES[0]][1]
    g, rays = d.geometry, d.rays
    n = int(rays.phi.size)
    index = {f"ray-{i}": i + 1 for i in range(n)} | {"profile": n + 1}
    r0 = g.r0 * 1e3

    def base(lang: str) -> str:
        return message("html.cam.base", lang, r0=format_number(r0, 2, lang),
                       mm=format_number(r0 / (mu * 1e3), 1, lang))

    swing = g.motion is Motion.OSCILLATING          # s is the arm's angle ψ (rad)

    def ray(lang: str, i: int) -> str:
        s = float(rays.s[i])
        phi = format_number(math.degrees(float(rays.phi[i])), 1, lang)
        if swing:
            return message("html.cam.ray_angle", lang, k=i, phi=phi,
                           psi=format_number(math.degrees(s), 2, lang))
        return message("html.cam.ray", lang, k=i, phi=phi, s=format_number(s * 1e3, 2, lang),
                       mm=format_number(s / mu, 1, lang))

    def row(lang: str, i: int, paper: bool) -> str:
        s = float(rays.s[i])
        if swing:
            return "" if paper else format_number(math.degrees(s), 2, lang) + "°"
        return format_number(s / mu, 1, lang) if paper else format_number(s * 1e3, 2, lang)

    def profile(lang: str) -> str:
        return message("html.cam.profile", lang, last=n - 1)

    steps = ([{"id": "base", "group": "", "label": each(lambda _l: "r0"), "sentence": each(base)}]
             + [{"id": f"ray-{i}", "group": "", "label": each(lambda _l, i=i: str(i)),
                 "sentence": each(lambda lang, i=i: ray(lang, i))} for i in range(n)]
             + [{"id": "profile", "group": "", "label": each(lambda _l: "—"),
                 "sentence": each(profile)}])
    prims = {lang: tagged(((p, panel.steps.get(j, "base")) for j, p in
                            enumerate(panel.primitives)), index | {"base": 0})
             for lang, (panel, _mu) in drawn.items()}
    rows = [{"step": i + 1, "name": each(lambda _l, i=i: str(i)),
             "mm": each(lambda lang, i=i: row(lang, i, True)),
             "quantity": f"ψ{i}" if swing else f"s{i}, mm",
             "value": each(lambda lang, i=i: row(lang, i, False))}
            for i in range(n)]
    title = each(lambda lang: message("cam.sheet.inversion", lang))
    return {"id": "cam-inversion", "plan": "position", "k": 0, "phi": 0.0, "unit": "m",
            "title": title, "mu": each(lambda lang: f"μl = {format_number(mu * 1e3, 3, lang)} "
                                                     f"{message('html.cam.mm_per_mm', lang)}"),
            "steps": steps, "prims": prims, "rows": rows, "equations": []}, mu


def _sampled(smp: Sample, idx: np.ndarray) -> Sample:
    return Sample(*(getattr(smp, f.name)[idx] for f in fields(Sample)))


def cam_animation(d: CamDesign, mu: float, frames: int = CAM_FRAMES) -> Doc:
    """The cam turning (its profile rotated by the cam angle) with the follower at its samples."""
    g = d.geometry
    dense = d.dense
    idx = np.unique(np.linspace(0, dense.phi.size - 1, frames + 1).round().astype(int))[:-1]
    smp = _sampled(dense, idx)
    sigma = 1.0 if g.sense > 0 else -1.0
    turn = sigma * smp.phi                           # the cam's angle at each frame
    a, b = (_rot(v, turn) for v in follower_positions(g, smp, 0.35 * g.r0))   # fixed frame
    flat = d.spec.follower.contact is Contact.FLAT
    lo, hi = d.face or (-0.01, 0.01)
    follower_frames: list[list[Primitive]] = []
    for k in range(idx.size):
        p, q = a[k] / mu, b[k] / mu
        pr: list[Primitive] = [Line((float(p[0]), float(p[1])), (float(q[0]), float(q[1])),
                                    Role.OUTLINE)]
        if flat:
            u = smp.direction[k]
            t = np.array([u[1], -u[0]])
            c = smp.follower[k]
            pr.append(Line(tuple(((c + lo * t) / mu).tolist()), tuple(((c + hi * t) / mu)
                                                                      .tolist()), Role.OUTLINE))
        if g.roller > 0:
            c = smp.follower[k] / mu
            pr.append(Circle((float(c[0]), float(c[1])), g.roller / mu, Role.OUTLINE))
        follower_frames.append(pr)
    shape: list[Primitive] = [Circle((0.0, 0.0), g.r0 / mu, Role.CHAIN)]
    shape.append(Polyline(tuple((float(x) / mu, float(y) / mu) for x, y in d.profile_points),
                          Role.OUTLINE, closed=True))
    reach = max(float(np.max(np.hypot(*d.profile_points.T))),
                float(np.max(np.hypot(*a.T))), float(np.max(np.hypot(*b.T)))) / mu + g.roller / mu
    cam = {"id": "cam", "plan": "cam", "box": [-reach, -reach, reach, reach],
           "title": each(lambda lang: message("html.cam.turning", lang)),
           "mu": each(lambda _l: ""),
           "points": {"O": {"label": each(lambda _l: "O"), "xy": np.zeros((idx.size, 2)),
                            "trace": False},
                      "B": {"label": each(lambda _l: "B"), "xy": smp.follower / mu,
                            "trace": True}},
           "items": [{"kind": "rotor", "shape": shape, "angle": -np.degrees(turn)},
                     {"kind": "segment", "name": "follower", "thick": True,
                      "frames": follower_frames}]}
    x = np.degrees(smp.phi)
    conv, sym, si = ((math.degrees(1.0), "ψ", "°") if g.motion is Motion.OSCILLATING
                     else (1e3, "s", "mm"))
    y = smp.s * conv

    def title(lang: str) -> str:
        return message("html.cam.s_diagram", lang)

    q = slice(None, None, max(1, dense.phi.size // 720))      # the pen's resolution
    dias = {lang: diagram_panel("cam-s", title(lang), [Curve(np.degrees(dense.phi[q]),
                                                              dense.s[q] * conv)],
                                Axis("φ", "°", 120.0), Axis(sym, si, 40.0), lang)
            for lang in LANGUAGES}
    s_row = ("ψ", "°", np.degrees(smp.s)) if g.motion is Motion.OSCILLATING \
        else ("s", "mm", smp.s * 1e3)
    values = [{"quantity": q, "name": each(lambda _l, q=q: q), "unit": each(lambda _l, u=u: u),
               "value": v} for q, u, v in (s_row, ("α", "°", np.degrees(smp.alpha)))]
    return {"frames": int(idx.size), "phi_deg": x,
            "panels": [cam, cursor_panel("cam-s", title, dias, x, y, sym)],
            "values": values, "marks": [],
            "angle": each(lambda lang: message("html.cam.angle", lang))}


__all__ = ["CAM_FRAMES", "cam_animation", "cam_replay"]
