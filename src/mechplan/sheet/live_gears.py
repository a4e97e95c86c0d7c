"""The live page of a planetary train (``draw --format html`` of ``kind = "gears"``): the velocity
plans of the gear sheet replayed line by line (ray by ray), and the train turning in an end view
— each wheel and the carrier rotated by ω·t, the planets carried round on the carrier radius —
over one cycle. The angular velocities are the gear study's; nothing here solves the train.
"""

from __future__ import annotations

import math

import numpy as np

from ..construct.scale import round_scale
from ..drafting.primitives import (
    Circle,
    HAlign,
    Line,
    Polyline,
    Primitive,
    Role,
    Table,
    Text,
    VAlign,
)
from ..i18n import LANGUAGES, message, unit
from ..i18n import number as format_number
from ..model.plans import Plan
from ..synthesis.gears.solve import OrdinaryPlan, PlanetaryResult
from .gears_drawing import plan_panels
from .live import Doc, each
from .panels import Panel, mu_text

#: paper radius of the train's end view, mm
VIEW_MM = 70.0
#: the fastest link turns at most this much a frame, degrees
MAX_STEP_DEG = 3.0
#: frames of a cycle: at least, at most
MIN_FRAMES, MAX_FRAMES = 360, 2880


def _order(res: PlanetaryResult) -> list[str]:
    """The lines of the plan in the order a student draws them: the links whose ω is given (the
    input, the fixed link, a differential's two), the planet block, then the others."""
    s, p = res.spec, res.plan
    assert p is not None
    drawn = [n for n in p.names if n not in p.names[2:-2]]     # the planet block: one line
    known = [s.input, s.fixed, *(n for n, _ in s.speeds or ())]
    first = [n for n in dict.fromkeys(known) if n in drawn]
    planet = [p.names[1]] if p.names[1] not in first else []
    return first + planet + [n for n in drawn if n not in first and n not in planet]


def _mm(lang: str, v: float, digits: int = 1) -> str:
    return format_number(v, digits, lang)


def _line_sentence(res: PlanetaryResult, n: str, lang: str) -> str:
    s, p = res.spec, res.plan
    assert p is not None
    (r0, v0), (r1, v1) = p.lines[n]
    w = format_number(p.omega[n], 4, lang)
    if n == s.fixed:
        return message("htmlmore.gears.fixed", lang, n=n)
    if n == p.names[1]:
        block = ",".join(p.names[1:-2]) if s.scheme.two_row else n
        return message("htmlmore.gears.planet", lang, n=block, r0=_mm(lang, r0 * 1e3),
                       v0=format_number(v0, 3, lang), r1=_mm(lang, r1 * 1e3),
                       v1=format_number(v1, 3, lang), w=w)
    key = "given" if n == s.input or n in dict(s.speeds or ()) else "line"
    return message(f"htmlmore.gears.{key}", lang, n=n, r=_mm(lang, r1 * 1e3),
                   v=format_number(v1, 3, lang), w=w)


def gear_replays(res: PlanetaryResult, ordinary: OrdinaryPlan | None = None) -> list[Doc]:
    """The linear velocity plan line by line and the angular velocity plan ray by ray (with the
    pair 5–6 of ``ordinary``), from the gear sheet's own drawing (its primitives tagged with
    their line, ray)."""
    p = res.plan
    assert p is not None
    drawn = {lang: plan_panels(res, lang, ordinary=ordinary) for lang in LANGUAGES}
    order = _order(res)
    linear, angular = drawn[LANGUAGES[0]]
    ends = {sid: prim for j, prim in enumerate(linear.primitives)
            if isinstance(prim, Polyline) and (sid := linear.steps.get(j, "")).startswith("line-")}
    mu_v = max((abs(p.lines[n][1][1]) / abs(ends[f"line-{n}"].points[-1][0]), n)
               for n in order if abs(ends[f"line-{n}"].points[-1][0]) > 1e-9)[0] \
        if any(abs(e.points[-1][0]) > 1e-9 for e in ends.values()) else 1.0
    index = {"base": 0} | {f"line-{n}": i + 1 for i, n in enumerate(order)}
    steps = [{"id": "base", "group": "", "label": each(lambda _l: "r, v"),
              "sentence": each(lambda lang: message("htmlmore.gears.base", lang))}]
    steps += [{"id": f"line-{n}", "group": "", "label": each(lambda _l, n=n: n),
               "sentence": each(lambda lang, n=n: _line_sentence(res, n, lang))} for n in order]
    if res.partials:
        index |= {sid: len(steps) for sid in set(linear.steps.values())
                  if sid.startswith("partial")}
        steps.append({"id": "partials", "group": "", "label": each(lambda _l: "′, ″"),
                      "sentence": each(lambda lang: message("htmlmore.gears.partials", lang))})
    far = {n: (0 if abs(p.lines[n][0][1]) >= abs(p.lines[n][1][1]) else 1) for n in order}
    rows = [{"step": index[f"line-{n}"], "name": each(lambda _l, n=n: n),
             "mm": each(lambda lang, n=n: _mm(lang, abs(ends[f"line-{n}"].points[far[n]][0]))),
             "quantity": f"v{n}",
             "value": each(lambda lang, n=n: f"{format_number(p.lines[n][far[n]][1], 3, lang)} "
                                             f"{unit('m/s', lang)}")}
            for n in order]
    out = [_replay("gears-velocity", "velocity", drawn, 0, index, steps, rows,
                   each(lambda lang: message("gears.sheet.velocity", lang)),
                   each(lambda lang: mu_text(Plan.VELOCITY, mu_v, lang)))]
    rays = {sid: prim for j, prim in enumerate(angular.primitives)
            if isinstance(prim, Line) and (sid := angular.steps.get(j, "")).startswith("ray-")}
    groups = {sid: prim.string for j, prim in enumerate(angular.primitives)
              if isinstance(prim, Text) and (sid := angular.steps.get(j, "")).startswith("ray-")}
    omega = dict(p.omega) | ({"5": ordinary.omega5, "6": ordinary.omega6} if ordinary else {})
    ray_order = sorted(rays, key=lambda sid: rays[sid].end[0])
    a_index = {"base": 0} | {sid: i + 1 for i, sid in enumerate(ray_order)}
    a_steps = [{"id": "base", "group": "", "label": each(lambda _l: "P"),
                "sentence": each(lambda lang: message("htmlmore.gears.pole", lang))}]
    a_steps += [{"id": sid, "group": "", "label": each(lambda _l, s=sid: s[4:]),
                 "sentence": each(lambda lang, s=sid: message(
                     "htmlmore.gears.ray", lang, n=s[4:], names=groups[s],
                     mm=_mm(lang, rays[s].end[0]),
                     w=format_number(omega[s[4:]], 4, lang)))}
                for sid in ray_order]
    a_rows = [{"step": a_index[sid], "name": each(lambda _l, s=sid: groups[s]),
               "mm": each(lambda lang, s=sid: _mm(lang, rays[s].end[0])),
               "quantity": "ω",
               "value": each(lambda lang, s=sid: f"{format_number(omega[s[4:]], 4, lang)} "
                                                 f"{unit('1/s', lang)}")}
              for sid in ray_order]
    out.append(_replay("gears-angular", "angular", drawn, 1, a_index, a_steps, a_rows,
                       each(lambda lang: message("htmlmore.gears.angular", lang)),
                       each(lambda _l: "")))
    return out


def _replay(rid: str, plan: str, drawn: dict[str, list[Panel]], which: int,
            index: dict[str, int], steps: list[Doc], rows: list[Doc], title: dict[str, str],
            mu: dict[str, str]) -> Doc:
    prims = {lang: [(q, index[panels[which].steps.get(j, "base")])     # the labels too
                    for j, q in enumerate(panels[which].primitives) if not isinstance(q, Table)]
             for lang, panels in drawn.items()}
    return {"id": rid, "plan": plan, "k": 0, "phi": 0.0, "unit": "m", "title": title,
            "mu": mu, "steps": steps, "prims": prims, "rows": rows, "equations": []}


def _wheel(r: float, internal: bool, fixed: bool, spokes: int) -> list[Primitive]:
    """A wheel about its own centre (paper mm): pitch circle, spokes (or a ring's body and
    marks) that show it turning."""
    out: list[Primitive] = [Circle((0.0, 0.0), r, Role.OUTLINE)]
    if internal:
        out.append(Circle((0.0, 0.0), 1.12 * r, Role.OUTLINE))
        for j in range(12):
            a = 2 * math.pi * j / 12
            c, s = math.cos(a), math.sin(a)
            out.append(Line((r * c, r * s), (1.12 * r * c, 1.12 * r * s),
                            Role.THIN if fixed else Role.OUTLINE))
        return out
    out.append(Circle((0.0, 0.0), min(1.5, 0.2 * r), Role.OUTLINE))
    for j in range(spokes):
        a = 2 * math.pi * j / spokes
        out.append(Line((0.2 * r * math.cos(a), 0.2 * r * math.sin(a)),
                        (0.9 * r * math.cos(a), 0.9 * r * math.sin(a)), Role.OUTLINE))
    return out


def cycle(res: PlanetaryResult, frames: int | None = None) -> tuple[np.ndarray, str]:
    """Times of the animation's frames (s) over one turn of the carrier (of the input when the
    carrier is held), and the link whose turn that is."""
    p, s = res.plan, res.spec
    assert p is not None
    ref = "h" if abs(p.omega["h"]) > 1e-12 else s.input
    w_ref = abs(p.omega[ref]) or 1.0
    if frames is None:
        fastest = max(abs(w) for w in p.omega.values()) / w_ref
        frames = int(min(MAX_FRAMES, max(MIN_FRAMES, 360 * math.ceil(fastest / MAX_STEP_DEG))))
    return np.arange(frames) * (2 * math.pi / w_ref) / frames, ref


def gear_animation(res: PlanetaryResult, frames: int | None = None) -> Doc:
    """The train turning in an end view: central wheels about O, the carrier's arms, the
    planets at the carrier radius, each rotated by its own ω·t."""
    p, s = res.plan, res.spec
    assert p is not None
    t, _ref = cycle(res, frames)
    names = s.scheme.gear_names
    int1, int2 = s.scheme.internal
    central = {names[0]: int1, names[-1]: int2}
    planets = names[1:-1]
    r_max = max([p.radius[n] * (1.12 if internal else 1.0) for n, internal in central.items()]
                + [p.a_w + p.radius[n] for n in planets])
    mu = round_scale(r_max / VIEW_MM)
    reach = r_max / mu + 4.0
    items: list[Doc] = []
    fixed: list[Primitive] = []

    def angle(n: str) -> np.ndarray:       # turned counter-clockwise by ω·t; y down on the page
        return -np.degrees(p.omega[n] * t)

    for n, internal in central.items():
        r = p.radius[n] / mu
        items.append({"kind": "rotor", "name": n,
                      "shape": _wheel(r, internal, n == s.fixed, 3), "angle": angle(n),
                      "omega": p.omega[n]})
        a = math.radians(60.0 if internal else 35.0)
        fixed.append(Text((1.12 * r * math.cos(a) + 1.0, 1.12 * r * math.sin(a) + 1.0), n, 3.5,
                          halign=HAlign.LEFT, valign=VAlign.BOTTOM))
    k = s.planets
    a_w = p.a_w / mu
    arms: list[Primitive] = [Circle((0.0, 0.0), 2.0, Role.OUTLINE)]
    for j in range(k):
        a = 2 * math.pi * j / k
        arms.append(Line((2.0 * math.cos(a), 2.0 * math.sin(a)),
                         (a_w * math.cos(a), a_w * math.sin(a)), Role.OUTLINE))
    items.append({"kind": "rotor", "name": "h", "shape": arms, "angle": angle("h"),
                  "omega": p.omega["h"]})
    carrier = p.omega["h"] * t
    block = ",".join(planets)
    points: Doc = {"O": {"label": each(lambda _l: "O"), "xy": np.zeros((t.size, 2)),
                         "trace": False}}
    for j in range(k):
        turned = carrier + 2 * math.pi * j / k
        centre = np.column_stack([a_w * np.cos(turned), a_w * np.sin(turned)])
        shape = [q for n in planets for q in _wheel(p.radius[n] / mu, False, False, 2)]
        items.append({"kind": "rotor", "name": f"{planets[0]}-{j}", "shape": shape,
                      "angle": angle(planets[0]), "centre": centre, "omega": p.omega[planets[0]]})
        points[f"O{j + 1}"] = {"label": each(lambda _l: block), "xy": centre, "trace": j == 0}
    links = [*names, "h"]
    values = [{"quantity": f"φ{n}", "name": each(lambda _l, n=n: f"φ{n}"),
               "unit": each(lambda _l: "°"), "value": np.degrees(p.omega[n] * t)}
              for n in links]
    values += [{"quantity": f"ω{n}", "name": each(lambda _l, n=n: f"ω{n}"),
                "unit": each(lambda lang: unit("1/s", lang)),
                "value": np.full(t.size, p.omega[n])} for n in links]
    panel = {"id": "gears-train", "plan": "train", "box": [-reach, -reach, reach, reach],
             "scale": mu, "title": each(lambda lang: message("htmlmore.gears.turning", lang)),
             "mu": each(lambda lang: mu_text(Plan.POSITION, mu, lang)),
             "points": points, "fixed": fixed, "items": items}
    return {"frames": int(t.size), "phi_deg": np.degrees(p.omega[s.input] * t),
            "time": t, "panels": [panel], "values": values, "marks": [],
            "angle": each(lambda lang: message("htmlmore.gears.angle", lang, n=s.input))}


__all__ = ["cycle", "gear_animation", "gear_replays"]
