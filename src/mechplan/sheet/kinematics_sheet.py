"""Panels of the course sheets: sheet 1 kinematics, sheet 2 kinetostatics.

Sheet 1: the position plan (every position with the trajectories), the velocity plans of all
positions in order (small; the chosen positions with their tables), the acceleration plans of the
chosen positions, and the kinematic diagrams of the output link — s(φ), v(φ), a(φ) exact, with the
course's graphical differentiation (chords of the curve over the positions) beside them.
Sheet 2: force polygons, Zhukovsky's lever and the diagram of the balancing moment M_b(φ).
Nothing here computes mechanics beyond reading the evaluated construction.
"""

from __future__ import annotations

import math

import numpy as np

from ..drafting.primitives import Primitive, Role, Table, Text
from ..i18n import message, number
from ..model.output import Output, output_link
from ..solve import Solution
from .diagram import Axis, Curve, diagram_panel
from .panels import TABLE_H, TITLE_H, Panel
from .scales import Room

SWEEP = 361            # samples of an exact curve over one turn


def _series(sol: Solution, out: Output, phi: np.ndarray) -> dict[str, np.ndarray]:
    """s, v, a (or ψ, ω, ε) of the output link at the angles phi (evaluated construction)."""
    c = sol.construction
    ev = c.evaluate(phi)
    res: dict[str, np.ndarray] = {}
    if out.point is not None:
        u = np.asarray(out.direction)
        res["s"] = np.asarray(ev.get(c.position(out.point))) @ u
        for sym, image in (("v", c.velocity_image), ("a", c.acceleration_image)):
            if not c.has_result(sym, out.point) or (sym == "a" and "acceleration" not in sol.plans):
                continue
            res[sym] = np.asarray(ev.get(image(out.point))) @ u
    else:
        if not c.has_result("angle", out.link):
            return res
        res["s"] = np.unwrap(np.asarray(ev.get(c.link_angle(out.link)), dtype=float))
        for sym, key, rate in (("v", "omega", c.omega), ("a", "epsilon", c.epsilon)):
            if c.has_result(key, out.link) and (sym == "v" or "acceleration" in sol.plans):
                res[sym] = np.asarray(ev.get(rate(out.link)), dtype=float)
    return res


def chords(x: np.ndarray, y: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Graphical differentiation by chords: slope of each chord at the middle of its interval."""
    return (0.5 * (x[1:] + x[:-1]), np.diff(y) / dt)


def kinematic_diagrams(sol: Solution, lang: str, r: Room, tall: float = 1.0) -> list[Panel]:
    """s(φ), v(φ), a(φ) of the output link: exact curves and the graphical differentiation;
    ``tall``: their ordinate axes that many times their usual length (grown into free room)."""
    out = output_link(sol.scene.mechanism)
    if out is None:
        return []
    drive = sol.scene.mechanism.drive
    if drive.linear or drive.law is not None:   # over the driver's range (a linear driver's, a
        return _linear_diagrams(sol, out, lang, r, tall)  # crank's table), against the law's time
    omega = abs(sol.scene.mechanism.drive.omega)
    sweep_positions = not sol.scene.positions.angles and sol.positions >= 4
    phi0 = float(sol.phi[0]) if sweep_positions else 0.0
    n = sol.positions if sweep_positions and sol.positions <= 72 else 12
    phi = phi0 + np.linspace(0.0, 2.0 * math.pi, SWEEP)
    exact = _series(sol, out, phi)
    if "s" not in exact or omega == 0:
        return []
    phi_k = phi0 + np.arange(n + 1) * 2.0 * math.pi / n
    s_k = _series(sol, out, phi_k)["s"]
    x = np.degrees(phi - phi0)
    x_k = np.degrees(phi_k - phi0)
    shift = float(np.nanmin(exact["s"]))
    rocker = out.point is None
    conv = math.degrees(1.0) if rocker else 1.0
    s_exact, s_pos = (exact["s"] - shift) * conv, (s_k - shift) * conv
    dt = 2.0 * math.pi / n / omega
    xv, v_graph = chords(x_k, s_k, dt)
    symbols = ("ψ", "ω", "ε") if rocker else ("s", "v", "a")
    units = ("°", "rad/s", "rad/s²") if rocker else ("m", "m/s", "m/s²")
    length_x = min(160.0, 0.36 * r.width)
    length_y = min(28.0, 0.1 * r.height) * tall
    x_axis = Axis("φ", "°", length_x)
    # which line is which, over the diagrams: "—— exact   – – – graphical differentiation"
    legend = (f"—— {message('layout.diagram.exact', lang)}   – – – "
              f"{message('layout.diagram.graphical', lang)}")
    specs = [("displacement", symbols[0], units[0],
              [Curve(x, s_exact), Curve(x_k, s_pos, label=None)])]
    if "v" in exact:
        specs.append(("velocity", symbols[1], units[1],
                      [Curve(x, exact["v"]), Curve(xv, v_graph, role=Role.DASHED)]))
        if "a" in exact:
            xa, a_graph = chords(xv, v_graph, dt)
            specs.append(("acceleration", symbols[2], units[2],
                          [Curve(x, exact["a"]), Curve(xa, a_graph, role=Role.DASHED)]))
    return _stacked(specs, out, x_axis, length_y, "φ", legend, lang, r)


def _stacked(specs: list[tuple[str, str, str, list[Curve]]], out: Output, x_axis: Axis,
             length_y: float, x_symbol: str, legend: str, lang: str, r: Room) -> list[Panel]:
    """The diagrams one under the other on the same x axis, as the course draws them."""
    panels: list[Panel] = []
    for kind, sym, unit, curves in specs:
        title = (message(f"layout.diagram.{kind}", lang, symbol=sym, link=out.link)
                 if x_symbol == "φ" else     # over a linear driver's length
                 message(f"drives2.diagram.{kind}", lang, symbol=sym, x=x_symbol, link=out.link))
        d = diagram_panel(f"diagram-{kind}", title, curves, x_axis,
                          Axis(sym, unit, length_y, mu_symbol=f"μ{sym}({x_symbol})"), lang)
        panels.append(d.panel)
    width = max(p.bounds()[2] - p.bounds()[0] for p in panels)
    stacks = grid("diagram-kinematic", panels, width, r.height - 8.0, same_origin=True)
    if len(specs) > 1:
        for stack in stacks:
            x0, _y0, _x1, y1 = stack.bounds()
            stack.primitives.append(Text((x0, y1 + 3.0), legend, TABLE_H))
    return stacks


def _linear_diagrams(sol: Solution, out: Output, lang: str, r: Room,
                     tall: float = 1.0) -> list[Panel]:
    """s(t), v(t), a(t) of the output link over a linear driver's range, against the law's time
    (constant rate: t = (q − q⁰)/q̇; a table: its spline inverted): the exact curves, and the
    graphical differentiation by chords over the positions."""
    from ..model.law import driver_time

    drive = sol.scene.mechanism.drive
    if drive.q_range is None or drive.omega == 0:
        return []
    lo, hi = drive.q_range
    sweep_positions = not sol.scene.positions.angles and sol.positions >= 4
    n = sol.positions - 1 if sweep_positions and sol.positions <= 73 else 12
    q = np.linspace(lo, hi, SWEEP)
    exact = _series(sol, out, q)
    if "s" not in exact:
        return []
    q_k = np.linspace(lo, hi, n + 1)
    s_k = _series(sol, out, q_k)["s"]
    x, x_k = driver_time(drive, q), driver_time(drive, q_k)
    shift = float(np.nanmin(exact["s"]))
    rocker = out.point is None
    conv = math.degrees(1.0) if rocker else 1.0
    symbols = ("ψ", "ω", "ε") if rocker else ("s", "v", "a")
    units = ("°", "rad/s", "rad/s²") if rocker else ("m", "m/s", "m/s²")
    x_axis = Axis("t", "s", min(160.0, 0.36 * r.width))
    specs = [("displacement", symbols[0], units[0],
              [Curve(x, (exact["s"] - shift) * conv), Curve(x_k, (s_k - shift) * conv)])]
    if "v" in exact:
        # a chord's slope Δs/Δt at the middle of its interval
        xv = 0.5 * (x_k[1:] + x_k[:-1])
        v_graph = np.diff(s_k) / np.diff(x_k)
        specs.append(("velocity", symbols[1], units[1],
                      [Curve(x, exact["v"]), Curve(xv, v_graph, role=Role.DASHED)]))
        if "a" in exact:
            specs.append(("acceleration", symbols[2], units[2],
                          [Curve(x, exact["a"]),
                           Curve(0.5 * (xv[1:] + xv[:-1]), np.diff(v_graph) / np.diff(xv),
                                 role=Role.DASHED)]))
    legend = (f"—— {message('layout.diagram.exact', lang)}   – – – "
              f"{message('layout.diagram.graphical', lang)}")
    return _stacked(specs, out, x_axis, min(28.0, 0.1 * r.height) * tall, "t", legend, lang, r)


def balancing_diagram(sol: Solution, lang: str, r: Room) -> Panel | None:
    """M_b at the positions of a sweep, over the crank angle (a closed diagram of one turn)."""
    c = sol.construction
    sid = c.results.get("M_b")
    if (sid is None or sid not in sol.ev.values or sol.scene.positions.angles
            or sol.positions < 4 or sol.scene.mechanism.drive.law is not None):
        return None         # (a crank by a table: its positions are not one closed turn)
    m = np.asarray(sol.ev[sid], dtype=float)
    n = sol.positions
    x = np.arange(n + 1) * 360.0 / n
    y = np.append(m, m[0])
    d = diagram_panel("force-diagram-Mb", message("layout.diagram.balancing", lang, symbol="M_b"),
                      [Curve(x, y)], Axis("φ", "°", min(180.0, 0.42 * r.width)),
                      Axis("M_b", "N·m", min(60.0, 0.2 * r.height)), lang)
    return d.panel


def small_plan(panel: Panel, k: int, phi_deg: float | str, lang: str) -> Panel:
    """A velocity plan without its tables, titled by its position only."""
    keep: list[Primitive | Table] = [
        p for p in panel.primitives if not isinstance(p, Table)
        and not (isinstance(p, Text) and p.height_mm in (TABLE_H, TITLE_H))]
    out = Panel(panel.name, keep)
    x0, _y0, _x1, y1 = out.bounds()
    title = (message("drivers.small_title", lang, position=k, at=phi_deg)   # a linear driver
             if isinstance(phi_deg, str) else
             message("layout.plan.small_title", lang, position=k, phi=number(phi_deg, 1, lang)))
    out.primitives.append(Text((x0, y1 + 2.0), title, TABLE_H + 1.0))
    return out


def drawing_of(panel: Panel) -> Panel:
    """A plan panel without its tables (its title and μ line kept): the plan when its tables
    go on a panel of their own (:func:`tables_of`)."""
    keep: list[Primitive | Table] = [
        p for p in panel.primitives if not isinstance(p, Table)
        and not (isinstance(p, Text) and p.height_mm == TABLE_H)]
    return Panel(panel.name, keep, plan=panel.plan)


def split_tables(panel: Panel, title: str, apart: bool, r: Room) -> list[Panel]:
    """A plan panel as it goes on the sheet: whole, or its drawing and its tables apart (when
    the scale decision says so, or the plan with its tables is taller than the drawing area)."""
    _x0, y0, _x1, y1 = panel.bounds()
    if not apart and y1 - y0 <= r.height:
        return [panel]
    tables = tables_of(panel, title)
    return [drawing_of(panel)] + ([tables] if tables.primitives else [])


def tables_of(panel: Panel, title: str) -> Panel:
    """The tables of a plan panel (segments, vector equations) under a title, without the plan;
    the layout splits them by rows into a sheet's free room (:mod:`.table_rows`)."""
    keep: list[Primitive | Table] = [
        p for p in panel.primitives if isinstance(p, Table)
        or (isinstance(p, Text) and p.height_mm == TABLE_H)]
    if not keep:
        return Panel(f"{panel.name}-tables", [])
    from .table_rows import splittable

    return splittable(keep, f"{panel.name}-tables", title)


#: room above a titled grid for its title (5 mm text 4 mm above the cells)
GRID_TITLE_MM = 12.0


def grid(name: str, cells: list[Panel], width_mm: float, height_mm: float,
         gap: float = 6.0, same_origin: bool = False, title: str | None = None) -> list[Panel]:
    """Panels in reading order on a grid of equal cells, as few grid panels as fit the room.

    ``same_origin``: the cells' own x = 0 (a diagram's φ = 0) falls at the same place in every
    column, so diagrams drawn one under another share their φ axis; otherwise each cell's left
    edge is at its column's left. With a title, each grid panel has it above its cells (within
    ``height_mm``) and can be redrawn (``Panel.refit(w, h)``) as a first part of at most w × h
    with its other cells and those of the later grid panels laid out again for the room — so the
    layout fills a sheet's free room with the first rows and carries the others over.
    """
    if not cells:
        return []
    boxes = [c.bounds() for c in cells]
    if same_origin:
        left = min(b[0] for b in boxes)
        boxes = [(left, b[1], b[2], b[3]) for b in boxes]
    cw = max(b[2] - b[0] for b in boxes) + gap
    ch = max(b[3] - b[1] for b in boxes) + gap

    def shape(w: float, h: float) -> tuple[int, int]:
        h -= GRID_TITLE_MM if title else 0.0
        cols = max(1, min(len(cells), int((w + gap) // cw)))
        rows_per = max(1, int((h + gap) // ch))
        if len(cells) <= cols * rows_per:            # full rows: as few columns as rows allow
            cols = math.ceil(len(cells) / math.ceil(len(cells) / cols))
        return cols, rows_per

    cols, rows_per = shape(width_mm, height_mm)
    per = cols * rows_per
    out: list[Panel] = []
    for start in range(0, len(cells), per):
        chunk = cells[start:start + per]
        panel = _grid_panel(f"{name}-{start // per + 1}" if len(cells) > per else name,
                            chunk, boxes[start:start + per], cols, cw, ch, title)
        if title:
            drawn: dict[tuple[int, int], list[Panel]] = {}

            def refit(w: float, h: float, start: int = start, cname: str = panel.name,
                      drawn: dict[tuple[int, int], list[Panel]] = drawn) -> list[Panel]:
                c, r = shape(w, h)
                if (c, r) not in drawn:
                    cut = start + c * r
                    head = _grid_panel(f"{cname}-1", cells[start:cut], boxes[start:cut], c, cw,
                                       ch, title)
                    drawn[c, r] = [head] + grid(f"{cname}-2", cells[cut:], width_mm, height_mm,
                                                gap, same_origin, title)
                return list(drawn[c, r])
            panel.refit = refit
        out.append(panel)
    return out


def _grid_panel(name: str, cells: list[Panel], boxes: list[tuple[float, float, float, float]],
                cols: int, cw: float, ch: float, title: str | None) -> Panel:
    from .layout import moved

    panel = Panel(name, [])
    for i, (cell, b) in enumerate(zip(cells, boxes)):
        col, row = i % cols, i // cols
        dx, dy = col * cw - b[0], -row * ch - b[3]
        panel.primitives.extend(moved(p, dx, dy) for p in cell.primitives)
    if title:
        x0, _y0, _x1, y1 = panel.bounds()
        panel.primitives.append(Text((x0, y1 + 4.0), title, TITLE_H))
    return panel
