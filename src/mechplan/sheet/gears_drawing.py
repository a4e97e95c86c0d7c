"""Drawings of the gear sheet: the kinematic diagram beside its linear velocity plan (one radius
scale), the angular velocity plan (pole at distance H), the meshing of the involute pair."""

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
from ..i18n import message, number, scale_factor, significant, unit
from ..synthesis.gears.involute import Pair, flank, tooth_outline
from ..synthesis.gears.solve import OrdinaryPlan, PlanetaryResult
from .diagram import Axis, Curve, diagram_panel
from .fit import drawing_right, text_block
from .layout import moved
from .panels import Panel

TEXT_H = 2.5
TITLE_H = 3.5
PLAN_MM = 130.0        # paper height of the largest radius, width of the largest velocity


def _scheme(res: PlanetaryResult, mu_l: float, sx: float = 1.0) -> list[Primitive]:
    """Upper half of the train in section: gears as lines across their pitch diameters; the
    gears' places along the axis ``sx`` times the usual 95 mm."""
    p = res.plan
    assert p is not None, "a train that cannot be drawn has no drawing"
    sch = res.spec.scheme
    names = sch.gear_names
    int1, int2 = sch.internal
    y = {n: p.radius[n] / mu_l for n in names}
    aw = p.a_w / mu_l
    prims: list[Primitive] = [Line((-95.0 * sx, 0.0), (-5.0 * sx, 0.0), Role.CHAIN)]
    two = sch.two_row
    xs = {names[0]: -80.0 * sx, names[1]: -62.0 * sx,
          names[-1]: (-22.0 if two else -42.0) * sx}
    if two:
        xs[names[2]] = -42.0 * sx
    for n in names:
        x = xs[n]
        central = n in (names[0], names[-1])
        y0, y1 = (0.0, y[n]) if central else (aw - y[n], aw + y[n])
        if not central and not two:          # a shifted single row's planet: A to B
            y0, y1 = p.pitch_points["A"] / mu_l, p.pitch_points["B"] / mu_l
        prims.append(Line((x, y0), (x, y1), Role.OUTLINE))
        ring = central and ((n == names[0] and int1) or (n == names[-1] and int2))
        cap = 3.0 if ring else 1.5
        prims.append(Line((x - cap if ring and n == names[-1] else x - 1.5, y1),
                          (x + cap if ring and n == names[0] else x + 1.5, y1), Role.OUTLINE))
        if not central:
            prims.append(Line((x - 1.5, y0), (x + 1.5, y0), Role.OUTLINE))
        prims.append(Text((x + 1.0, y1 + 1.5), n, TEXT_H))
        if n == res.spec.fixed:
            for j in range(4):
                prims.append(Line((x - 4.0 + 2.0 * j, y1 + 3.0), (x - 2.0 + 2.0 * j, y1 + 5.0),
                                  Role.THIN))
    # shafts of the central links, the planet axle and the carrier
    prims.append(Line((-92.0 * sx, 0.6), (xs[names[0]], 0.6), Role.OUTLINE))
    prims.append(Line((xs[names[-1]], -0.6), (-8.0 * sx, -0.6), Role.OUTLINE))
    x_pl = [xs[n] for n in names[1:-1]]
    prims.append(Line((min(x_pl) - 4.0, aw), (max(x_pl) + 4.0, aw), Role.OUTLINE))
    prims.append(Polyline(((max(x_pl) + 4.0, aw), (max(x_pl) + 8.0, aw),
                           (max(x_pl) + 8.0, -2.0), (-8.0 * sx, -2.0)), Role.OUTLINE))
    prims.append(Text((max(x_pl) + 9.0, aw / 2), "h", TEXT_H))
    for label, yy in (("A", p.pitch_points["A"] / mu_l), ("B", p.pitch_points["B"] / mu_l),
                      ("O", aw)):
        prims.append(Line((-95.0 * sx, yy), (0.0, yy), Role.DASHED))
        prims.append(Text((-95.0 * sx - 3.0, yy), label, TEXT_H, halign=HAlign.RIGHT,
                          valign=VAlign.MIDDLE))
    return prims


def pair_56_panel(o: OrdinaryPlan, output: str, lang: str, scale: float = 1.0) -> Panel:
    """The pair 5–6: its kinematic diagram (gear 5 on the planetary output shaft ``output``) beside
    its linear velocity plan, on a radius scale of its own."""
    size = 0.45 * PLAN_MM * scale
    mu_l = round_scale((o.a56 + o.r6) / size)
    curves = [Curve(np.array([v0, v1]), np.array([y0, y1]), Role.OUTLINE, n)
              for n, ((y0, v0), (y1, v1)) in o.lines.items()]
    v_max = max(abs(v) for line in o.lines.values() for (_, v) in line) or 1.0
    dia = diagram_panel("velocity56", message("gearcam.sheet.pair56", lang, shaft=output),
                        curves, Axis("v", "m/s", size, round_scale(v_max / size)),
                        Axis("r", "m", size, mu_l, mu_symbol="μl"), lang)
    x0 = min(0.0, min(c.x.min() for c in curves) / dia.mu_x - 10.0)
    dia.panel.primitives.extend(moved(q, x0, 0.0) for q in _pair_56(o, mu_l))
    return dia.panel


def _pair_56(o: OrdinaryPlan, mu_l: float) -> list[Primitive]:
    """Gear 5 on the output shaft, gear 6 on its parallel shaft, pitch point C."""
    x = -10.0
    sx = 0.3
    r5, a56, r6 = o.r5 / mu_l, o.a56 / mu_l, o.r6 / mu_l
    prims: list[Primitive] = [
        Line((x, 0.0), (x, r5), Role.OUTLINE), Line((x - 1.5, r5), (x + 1.5, r5), Role.OUTLINE),
        Line((x + 1.0, a56 - r6), (x + 1.0, a56 + r6), Role.OUTLINE),
        Line((x - 0.5, a56 - r6), (x + 2.5, a56 - r6), Role.OUTLINE),
        Line((x - 0.5, a56 + r6), (x + 2.5, a56 + r6), Role.OUTLINE),
        Line((x - 6.0, a56), (x + 8.0, a56), Role.CHAIN),
        Line((x - 5.0, a56 + 0.6), (x + 1.0, a56 + 0.6), Role.OUTLINE),
        Text((x - 4.0, r5 / 2), "5", TEXT_H, halign=HAlign.RIGHT),
        Text((x + 3.5, a56 + r6 / 2), "6", TEXT_H),
        Line((-95.0 * sx, r5), (0.0, r5), Role.DASHED),
        Text((-95.0 * sx - 3.0, r5), "C", TEXT_H, halign=HAlign.RIGHT, valign=VAlign.MIDDLE),
    ]
    return prims


def plan_panels(res: PlanetaryResult, lang: str, scale: float = 1.0,
                ordinary: OrdinaryPlan | None = None) -> list[Panel]:
    """The diagram with the linear velocity plan, and the angular velocity plan (their size
    ``scale`` times the usual); with ``ordinary``, the pair 5–6 in a panel of its own and on the
    angular velocity plan."""
    size = PLAN_MM * scale
    p = res.plan
    assert p is not None
    r_max = max(p.radius[n] + (p.a_w if n not in (p.names[0], p.names[-2]) else 0.0)
                for n in p.names[:-1])

    mu_l = round_scale(r_max / size)
    curves = []
    for n in p.names:
        (y0, v0), (y1, v1) = p.lines[n]
        if n in p.names[2:-2]:
            continue                         # the planet block has one line, labelled by its first
        label = f"{n},{p.names[2]}" if n == p.names[1] and res.spec.scheme.two_row else n
        curves.append(Curve(np.array([v0, v1]), np.array([y0, y1]), Role.OUTLINE, label,
                            tag=f"line-{n}"))
    v_all = [v for n in p.names for (_, v) in p.lines[n]]
    for j, part in enumerate(res.partials or ()):     # a differential: each input alone, thin
        for n in part.names:
            if n in part.names[2:-2]:
                continue
            (y0, v0), (y1, v1) = part.lines[n]
            curves.append(Curve(np.array([v0, v1]), np.array([y0, y1]), Role.THIN,
                                f"{n}{chr(0x2032) * (j + 1)}", tag=f"partial{j}-{n}"))
            v_all += [v0, v1]
    mu_v = round_scale(max(abs(v) for v in v_all) / size) if any(v_all) else 1.0
    if res.partials is not None and any(v_all):       # a differential runs both ways: the span
        mu_v = round_scale((max(0.0, *v_all) - min(0.0, *v_all)) / size)
    dia = diagram_panel("velocity", message("gears.sheet.velocity", lang), curves,
                        Axis("v", "m/s", size, mu_v), Axis("r", "m", size, mu_l, mu_symbol="μl"),
                        lang)
    sx = min(1.0, max(scale, 0.5))           # the diagram narrows on a small sheet
    # the diagram stands left of the plan's leftmost velocity (a differential's run both ways)
    x0 = min(0.0, min(v_all) / mu_v - 10.0) if min(v_all) < 0 else 0.0
    scheme = [*_scheme(res, mu_l, sx),
              *text_block((-95.0 * sx, -8.0), message("gears.sheet.scheme", lang),
                          TITLE_H, 95.0 * sx - 4.0, valign=VAlign.TOP,
                          measure_min=0.0)]     # clear of the scale factors
    dia.panel.primitives.extend(moved(q, x0, 0.0) for q in scheme)
    # angular velocity plan: rays from the pole P parallel to the plan's lines cut the reference
    # line
    w = {n: p.omega[n] for n in p.names}
    if ordinary is not None:
        w |= {"5": ordinary.omega5, "6": ordinary.omega6}
    w_max = max(abs(v) for v in w.values()) or 1.0
    H = max(5.0, math.floor(size * mu_v / (mu_l * w_max) / 5.0) * 5.0)
    mu_w = mu_v / (mu_l * H)
    prims: list[Primitive | Table] = []
    rays: dict[int, str] = {}                # the primitives of each ray (``Panel.steps``)
    xs = {n: v / mu_w for n, v in w.items()}
    lo, hi = min(0.0, *xs.values()), max(0.0, *xs.values())
    prims.append(Line((lo - 10.0, 0.0), (hi + 10.0, 0.0), Role.THIN))
    prims.append(Circle((0.0, -H), 0.6, Role.OUTLINE))
    prims.append(Text((1.5, -H - 1.5), "P", TEXT_H, valign=VAlign.TOP))
    prims.append(Text((-1.0, -1.0), "0", TEXT_H, halign=HAlign.RIGHT, valign=VAlign.TOP))
    shown: dict[float, list[str]] = {}
    for n, x in xs.items():
        shown.setdefault(round(x, 3), []).append(n)
    for k, (x, group) in enumerate(sorted(shown.items())):
        rays |= dict.fromkeys((len(prims), len(prims) + 1), f"ray-{group[0]}")
        prims.append(Line((0.0, -H), (x, 0.0), Role.OUTLINE))
        prims.append(Text((x, 1.5 + 4.0 * (k % 2)), ",".join(group), TEXT_H,
                          halign=HAlign.CENTER))
    x_in, x_out = xs[res.spec.input], xs[res.spec.output]
    read = x_in / x_out if x_out else math.inf
    width = drawing_right(prims) - (lo - 10.0)
    read_text = (f"u_{res.spec.input}{res.spec.output} = {significant(x_in, 4, lang)} / "
                 f"{significant(x_out, 4, lang)} = {number(read, 4, lang)}")
    if res.spec.speeds is not None:
        read_text = (f"ω_{res.spec.output} = {significant(x_out, 4, lang)} · μω = "
                     f"{significant(w[res.spec.output], 6, lang)} {unit('1/s', lang)}")
    prims.extend(text_block((lo - 10.0, -H - 8.0), read_text, TEXT_H, width))
    prims.extend(text_block((lo - 10.0, 14.0), message("gears.sheet.angular", lang,
                                                       H=number(H, 0, lang),
                                                       mu=scale_factor(mu_w, lang)), TITLE_H, width,
                            upward=True))
    return [dia.panel, Panel("angular", prims, steps=rays)]


def _arc(c: tuple[float, float], r: float, a0: float, a1: float,
         n: int = 40) -> list[tuple[float, float]]:
    t = np.linspace(a0, a1, n)
    return list(zip((c[0] + r * np.cos(t)).tolist(), (c[1] + r * np.sin(t)).tolist()))


def _place(pts: np.ndarray, c: tuple[float, float], angle: float,
           s: float) -> list[tuple[float, float]]:
    ca, sa = math.cos(angle), math.sin(angle)
    x, y = pts[:, 0], pts[:, 1]
    return list(zip((c[0] + s * (ca * x - sa * y)).tolist(),
                    (c[1] + s * (sa * x + ca * y)).tolist()))


def mesh_scale(pair: Pair, width_mm: float = 280.0) -> float:
    """Drawing scale (paper mm per mm): the largest of 10, 5, 4, 2.5, 2, 1 … fitting 5 pitches
    in ``width_mm``."""
    m_mm = pair.spec.module * 1000
    for s in (10.0, 5.0, 4.0, 2.5, 2.0, 1.0, 0.5, 0.25):
        if 5.0 * math.pi * m_mm * s <= width_mm:
            return s
    return 0.1


def mesh_panel(pair: Pair, lang: str, scale: float = 1.0) -> Panel:
    """Three teeth of each gear with their circles, the line of action and its active part
    (5 pitches in up to ``scale`` × 280 mm)."""
    sp = pair.spec
    S = mesh_scale(pair, 280.0 * scale) * 1000.0      # paper mm per metre
    g1, g2 = pair.gears
    O1, O2 = (0.0, -g1.r_w * S), (0.0, g2.r_w * S)
    prims: list[Primitive | Table] = []
    for g, c, axis, off in ((g1, O1, math.pi / 2, 0.0), (g2, O2, -math.pi / 2, 0.5)):
        tau = 2 * math.pi / g.z
        half = 2.6 * tau
        for r, role in ((g.r_b, Role.THIN), (g.r, Role.CHAIN), (g.r_w, Role.DASHED),
                        (g.r_a, Role.THIN), (g.r_f, Role.THIN)):
            prims.append(Polyline(tuple(_arc(c, r * S, axis - half, axis + half)), role))
        outline = tooth_outline(g, sp.alpha, sp.module, sp.clearance, addendum=sp.addendum)
        pts: list[tuple[float, float]] = []
        for j in ((-1, 0, 1) if off == 0.0 else (-2, -1, 0)):
            pts += _place(outline, c, axis + (j + off) * tau, S)
        prims.append(Polyline(tuple(pts), Role.OUTLINE))
        # working profiles: the flanks of the tooth next to P from the lowest contact to the tip
        rr, th = flank(g, sp.alpha)
        r_low = math.hypot(g.r_b, max(g.rho_p, 0.0))
        keep = rr >= r_low
        if keep.sum() > 1:
            fl = np.column_stack([rr[keep] * np.cos(th[keep]), rr[keep] * np.sin(th[keep])])
            mirror = fl * np.array([1.0, -1.0])
            for j in ((0,) if off == 0.0 else (-1, 0)):
                for part in (fl, mirror):
                    prims.append(Polyline(tuple(_place(part, c, axis + (j + off) * tau, S)),
                                          Role.DIMENSION))
    aw = pair.alpha_w
    d = np.array([math.cos(aw), -math.sin(aw)])
    N1 = d * g1.r_w * math.sin(aw) * S
    N2 = -d * g2.r_w * math.sin(aw) * S
    B2 = N1 - d * math.sqrt(g1.r_a ** 2 - g1.r_b ** 2) * S
    B1 = N2 + d * math.sqrt(g2.r_a ** 2 - g2.r_b ** 2) * S
    prims.append(Line(tuple(N1 + d * 8.0), tuple(N2 - d * 8.0), Role.THIN))
    prims.append(Line(tuple(B1), tuple(B2), Role.OUTLINE))
    reach = 1.6 * math.pi * sp.module * S + 20.0         # the centre line within the drawing
    prims.append(Line((0.0, max(O1[1], -reach)), (0.0, min(O2[1], reach)), Role.CHAIN))
    for label, q in (("N1", N1), ("N2", N2), ("B1", B1), ("B2", B2), ("P", (0.0, 0.0))):
        prims.append(Circle((float(q[0]), float(q[1])), 0.5, Role.OUTLINE))
        prims.append(Text((float(q[0]) + 1.2, float(q[1]) + 1.2), label, TEXT_H))
    for label, c, g in (("O1", O1, g1), ("O2", O2, g2)):
        if abs(c[1]) <= reach:
            prims.append(Circle(c, 0.8, Role.OUTLINE))
            prims.append(Text((c[0] + 1.5, c[1]), label, TEXT_H))
    top = max(p for q in prims if isinstance(q, Polyline) for _, p in q.points)
    left = min(p for q in prims if isinstance(q, Polyline) for p, _ in q.points)
    rho = sp.clearance * sp.module / (1 - math.sin(sp.alpha))
    width = drawing_right(prims) - left
    fillet = text_block((left, top + 6.0), message("gears.sheet.fillet", lang,
                                                   rho=number(rho * 1000, 2, lang)), TEXT_H,
                        width, upward=True)
    title = text_block((left, fillet[0].position[1] + 6.0),
                       message("gears.sheet.mesh", lang, scale=number(S / 1000.0, 1, lang)),
                       TITLE_H, width, upward=True)
    return Panel("mesh", [*prims, *fillet, *title])
