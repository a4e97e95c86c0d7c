"""The course sheet set: one scale decision, every sheet size, diagrams, many positions."""

from __future__ import annotations

import functools
import json
import math
import re

import numpy as np
import pytest
from scenes import ROOT, TEMPLATES
from shapely import box

from mechplan.cli import main
from mechplan.construct.protocol import mm
from mechplan.i18n import unit
from mechplan.model.plans import Plan
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose, packing_area
from mechplan.sheet.frame import make_frame
from mechplan.sheet.kinematics_sheet import _series, chords, output_link
from mechplan.sheet.panels import _points_of
from mechplan.sheet.primitives import Polyline, Text
from mechplan.solve import solve

SIZES = ("A4", "A3", "A2", "A1")


@functools.cache
def solved(stem: str):
    return solve(load_scene(ROOT / "templates" / f"{stem}.toml"))


def _texts(comp) -> set[str]:
    return {p.string for s in comp.sheets for p in s.flat() if isinstance(p, Text)}


def _number(text: str) -> float:
    return float(text.replace(",", "."))


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_solve_prints_the_scale_factors_and_segments_of_the_sheet(path, capsys):
    assert main(["solve", str(path)]) == 0
    report = capsys.readouterr().out
    comp = compose(solved(path.stem))
    # every "### <plan> (μ = …)" of the report is the μ the sheet is drawn at
    printed = [_number(m) for m in re.findall(r"^### .*\(μ = ([0-9.,]+) ", report, re.MULTILINE)]
    drawn = {Plan.POSITION, Plan.VELOCITY, Plan.ACCELERATION, Plan.FORCE}
    assert printed and all(any(math.isclose(v, comp.scales[p], rel_tol=1e-9) for p in drawn)
                           for v in printed)
    assert math.isclose(printed[0], comp.scales[Plan.POSITION], rel_tol=1e-9)
    # the segment lengths the report lists for a chosen position are in the sheet's tables
    sol = solved(path.stem)
    k = sol.scene.drawing.plan_positions[0] if sol.scene.drawing.plan_positions else (
        0 if sol.scene.positions.angles else 1)
    section = re.split(r"^## ", report, flags=re.MULTILINE)[1 + k]
    position_scale = f" {unit('m/mm', sol.scene.language)})"
    plans = [part for part in section.split("### ")[1:]
             if position_scale not in part.split("\n")[0]]
    mm_word = re.escape(mm(sol.scene.language))
    rows = [r for part in plans
            for r in re.findall(rf"^    (\S+)\s+(-?[0-9.,]+) {mm_word}", part, re.MULTILINE)]
    assert rows
    texts = _texts(comp)
    assert all(mm in texts for _, mm in rows), [r for r in rows if r[1] not in texts]


@pytest.mark.parametrize("size", SIZES)
@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_every_template_fits_every_sheet_size_without_overlap(path, size):
    sol = solved(path.stem)
    comp = compose(sol, size=size)
    std = sol.scene.drawing.standard
    area = packing_area(make_frame(size, std, {"title": "x"}, language=sol.scene.language))
    total = len(comp.sheets)
    for i, (sheet, placed) in enumerate(zip(comp.sheets, comp.placements)):
        assert placed, f"sheet {i + 1} is empty"
        assert sheet.attributes["sheet_number"] == str(i + 1)
        assert sheet.attributes["sheets_total"] == str(total)
        boxes = []
        for panel, (dx, dy) in placed:
            x0, y0, x1, y1 = panel.bounds()
            b = box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)
            assert area.contains(b), (size, panel.name)
            for p in panel.primitives:
                pts = [(x + dx, y + dy) for x, y in _points_of(p)]
                if pts:
                    xs, ys = [q[0] for q in pts], [q[1] for q in pts]
                    assert b.buffer(1e-6).contains(box(min(xs), min(ys), max(xs), max(ys)))
            boxes.append(b)
        for j, a in enumerate(boxes):
            for b in boxes[j + 1:]:
                assert a.intersection(b).area < 1e-6, size
    coverage = comp.coverage()
    assert len(coverage) == total and all(0.0 < c <= 1.0 for c in coverage)
    assert sum(coverage) / total > 0.3, coverage      # panels fill the set, no sheet of scraps


def test_twelve_position_kinematics_sheet_covers_most_of_an_a1():
    comp = compose(solved("four_bar"), size="A1")
    names = [p.name for p, _ in comp.placements[0]]
    assert len(comp.sheets) == 1
    assert names[:2] == ["position", "velocity-all"] and "diagram-kinematic" in names
    assert comp.coverage()[0] >= 0.6


def test_velocity_plans_of_every_position_in_order_at_one_scale():
    comp = compose(solved("four_bar"), size="A1")
    grid = next(p for p, _ in comp.placements[0] if p.name == "velocity-all")
    titles = [t for t in grid.primitives if isinstance(t, Text) and t.string.startswith("Position")]
    assert [int(re.match(r"Position (\d+)", t.string).group(1)) for t in titles] == list(range(12))
    # reading order: each row left to right, rows top to bottom
    keys = [(-round(t.position[1]), t.position[0]) for t in titles]
    assert keys == sorted(keys)
    mu = {t.string for t in grid.primitives if isinstance(t, Text) and t.string.startswith("μv")}
    assert mu == {"μv = 0.02 (m/s)/mm"}


@pytest.mark.parametrize("stem", ["slider_crank", "four_bar"])
def test_graphical_differentiation_approaches_the_exact_curves(stem):
    """Chords of the position curve (finite differences) against the velocity the plans give."""
    sol = solved(stem)
    out = output_link(sol.scene.mechanism)
    omega = abs(sol.scene.mechanism.drive.omega)
    n = 720
    phi = np.arange(n + 1) * 2 * math.pi / n
    s = _series(sol, out, phi)
    x, v_chord = chords(np.degrees(phi), s["s"], 2 * math.pi / n / omega)
    exact = _series(sol, out, np.radians(x))
    scale = np.abs(exact["v"]).max()
    assert np.abs(v_chord - exact["v"]).max() < 1e-3 * scale
    xa, a_chord = chords(x, v_chord, 2 * math.pi / n / omega)
    exact_a = _series(sol, out, np.radians(xa))["a"]
    assert np.abs(a_chord - exact_a).max() < 1e-2 * np.abs(exact_a).max()


def test_kinematic_and_balancing_moment_diagrams_are_on_the_sheets():
    comp = compose(solved("slider_crank"), size="A1", lang="ru")
    texts = _texts(comp)
    assert any(t.startswith("Диаграмма перемещений s(φ)") for t in texts)
    assert any(t.startswith("Диаграмма ускорений a(φ)") for t in texts)
    assert any("графическое дифференцирование" in t for t in texts)
    force_sheet = comp.placements[-1]
    assert any(p.name == "force-diagram-Mb" for p, _ in force_sheet)


def test_many_positions_are_drawn_as_trajectories_with_a_note():
    sol = solve(load_scene(ROOT / "templates" / "four_bar.toml"), count=400)
    comp = compose(sol, size="A1")
    position = next(p for p, _ in comp.placements[0] if p.name == "position")
    notes = [t.string for t in position.primitives if isinstance(t, Text)
             and t.string.startswith("400 positions")]
    assert notes
    # only the chosen positions' links, not 400 of them
    links = [p for p in position.primitives if isinstance(p, Polyline) and p.closed]
    assert len(links) < 10


def test_the_coupler_point_closes_its_rigid_triangle():
    sol = solved("four_bar")
    comp = compose(sol, size="A1")
    panel, _ = comp.placements[0][0]
    mu = comp.scales[Plan.POSITION]
    k = 1
    b, c, e = (tuple(np.asarray(sol.ev[f"pos.{p}"][k]) / mu) for p in "BCE")
    triangles = [p for p in panel.primitives if isinstance(p, Polyline) and p.closed
                 and len(p.points) == 3]
    assert any(all(min(math.dist(q, v) for q in t.points) < 1e-6 for v in (b, c, e))
               for t in triangles)


@pytest.mark.parametrize("size", ["A4", "A2"])
def test_solve_with_a_sheet_prints_the_scale_factors_of_that_sheet(size, capsys):
    path = ROOT / "templates" / "slider_crank.toml"
    assert main(["solve", str(path), "--sheet", size, "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)["scales"]
    drawn = compose(solved("slider_crank"), size=size).scales
    keys = {Plan.POSITION: "mu_l", Plan.VELOCITY: "mu_v", Plan.ACCELERATION: "mu_a",
            Plan.FORCE: "mu_F"}
    assert printed == {keys[p]: mu for p, mu in drawn.items()}
    assert printed != json.loads(_solve_json(path, capsys))["scales"] or size == "A1"


def _solve_json(path, capsys) -> str:
    assert main(["solve", str(path), "--json"]) == 0
    return capsys.readouterr().out


@pytest.mark.parametrize("standard, lang", [("gost", "ru"), ("tcvn", "vi")])
@pytest.mark.parametrize("stem", ["v_engine", "machine_unit", "slider_crank"])
def test_the_largest_plans_fit_an_a4_of_every_standard(stem, standard, lang):
    """The templates with the most tables (forces, two groups) in ГОСТ's and TCVN's frames."""
    comp = compose(solved(stem), size="A4", standard=standard, lang=lang)
    area = packing_area(make_frame("A4", standard, {"title": "x"}, language=lang))
    for placed in comp.placements:
        for panel, (dx, dy) in placed:
            x0, y0, x1, y1 = panel.bounds()
            assert area.contains(box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)), panel.name
