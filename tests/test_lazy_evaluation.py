"""Model only what a scene needs: count the construction steps an evaluation actually runs."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from mechplan import cli
from mechplan.dynamics.loading import Loading
from mechplan.model.plans import Plan
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import build, solve

TEMPLATES = Path(__file__).resolve().parents[1] / "templates"
STATS = re.compile(r"steps: (\d+) in the construction, (\d+) evaluated for (\d+) position\(s\)")


def _v_engine_text(**analysis: str) -> str:
    text = (TEMPLATES / "v_engine.toml").read_text(encoding="utf-8")
    assert "[analysis]" not in text
    lines = "".join(f"{k} = {v}\n" for k, v in analysis.items())
    return text + "\n[analysis]\n" + lines


@pytest.fixture(scope="module")
def v_engine_full():
    """The V-engine with position, velocity, acceleration and force plans in one construction."""
    scene = load_scene(TEMPLATES / "v_engine.toml")
    structure, c = build(scene, ("position", "velocity", "acceleration", "force"),
                         Loading.from_scene(scene))
    return scene, structure, c


def test_the_full_construction_has_every_plan(v_engine_full) -> None:
    _, structure, c = v_engine_full
    plans = {s.plan for s in c}
    assert plans == {Plan.POSITION, Plan.VELOCITY, Plan.ACCELERATION, Plan.FORCE}
    assert [g.name for g in structure.groups] == ["II(2,3)", "II(4,5)"]


def test_velocity_of_one_point_runs_no_acceleration_force_or_later_group(v_engine_full) -> None:
    _, structure, c = v_engine_full
    ev = c.evaluate(np.radians([30.0, 200.0]))
    ev.get(c.results["v_C"])                      # C belongs to the first group, II(2,3)
    done = [c[s] for s in ev.values]
    assert {s.plan for s in done} <= {Plan.POSITION, Plan.VELOCITY}
    later = structure.groups[1].name
    assert not [s.id for s in done if s.group == later]
    assert not [s.id for s in done if s.plan in (Plan.ACCELERATION, Plan.FORCE)]
    # exactly the ancestor closure, and a small part of the graph
    assert ev.evaluated == len(c.ancestors([c.results["v_C"]]))
    assert ev.evaluated < len(c.steps) / 5


def test_asking_more_later_evaluates_only_the_difference(v_engine_full) -> None:
    _, _, c = v_engine_full
    ev = c.evaluate(np.radians([30.0]))
    ev.get(c.results["v_C"])
    first = set(ev.values)
    ev.get(c.results["v_E"])                      # the second group's velocity
    added = [c[s] for s in set(ev.values) - first]
    assert added and {s.group for s in added} <= {"II(4,5)", "II(2,3)"}
    assert "II(4,5)" in {s.group for s in added}
    assert not [s for s in added if s.plan in (Plan.ACCELERATION, Plan.FORCE)]
    assert ev.evaluated == len(c.ancestors([c.results["v_C"], c.results["v_E"]]))


def test_position_only_request_evaluates_no_velocity_step(v_engine_full) -> None:
    _, _, c = v_engine_full
    ev = c.evaluate(np.radians([0.0, 90.0, 180.0]))
    ev.get("pos.E")
    assert {c[s].plan for s in ev.values} == {Plan.POSITION}


def test_solve_with_only_position_plans_evaluates_no_velocity_step() -> None:
    scene = parse_scene(_v_engine_text(plans='["position"]'), "v_position_only.toml")
    sol = solve(scene, at_deg=[30.0, 120.0])
    assert any(s.plan is Plan.VELOCITY for s in sol.construction)   # built, yet not run
    assert {sol.construction[s].plan for s in sol.ev.values} == {Plan.POSITION}


def test_solve_with_one_velocity_evaluates_only_its_closure() -> None:
    scene = parse_scene(_v_engine_text(plans='["velocity"]', points='["C"]'), "v_c.toml")
    sol = solve(scene, at_deg=[30.0])
    c = sol.construction
    assert not any(s.plan in (Plan.ACCELERATION, Plan.FORCE) for s in c)   # not even built
    assert set(sol.ev.values) == set(c.ancestors([c.results["v_C"]]))
    assert not [s for s in sol.ev.values if c[s].group == "II(4,5)"]


def _stats(capsys, argv: list[str]) -> tuple[int, int, int]:
    assert cli.main(argv) == 0
    err = capsys.readouterr().err
    m = STATS.search(err)
    assert m, err
    return int(m[1]), int(m[2]), int(m[3])


def test_cli_stats_counts_steps(capsys, tmp_path: Path) -> None:
    full = _stats(capsys, ["solve", str(TEMPLATES / "v_engine.toml"), "--stats", "--json",
                           "--positions", "12"])
    total, evaluated, positions = full
    assert positions == 12 and 0 < evaluated <= total

    scene = tmp_path / "v_only.toml"
    scene.write_text(_v_engine_text(plans='["velocity"]', points='["C"]'), encoding="utf-8")
    small = _stats(capsys, ["solve", str(scene), "--stats", "--at", "30"])
    # the numbers printed are the engine's own: the whole graph (position and velocity plans
    # only, since nothing asks for more) and the ancestor closure of v_C
    sol = solve(load_scene(scene), at_deg=[30.0])
    c = sol.construction
    assert {s.plan for s in c} == {Plan.POSITION, Plan.VELOCITY}
    assert small == (len(c.steps), len(c.ancestors([c.results["v_C"]])), 1)
    assert small[1] < small[0] and small[1] < evaluated


def test_cli_stats_text_report_same_counts(capsys, tmp_path: Path) -> None:
    scene = tmp_path / "v_only.toml"
    scene.write_text(_v_engine_text(plans='["velocity"]', points='["C"]'), encoding="utf-8")
    text = _stats(capsys, ["solve", str(scene), "--stats", "--at", "30", "60"])
    c = solve(load_scene(scene), at_deg=[30.0]).construction
    assert text == (len(c.steps), len(c.ancestors([c.results["v_C"]])), 2)
