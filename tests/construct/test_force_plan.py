"""The force plan as a construction: steps, labels, order of groups, evaluators, vectorisation."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechplan.construct.builder import build_construction
from mechplan.construct.ops import EVALUATORS, Op
from mechplan.construct.plans import force
from mechplan.construct.step import Kind
from mechplan.construct.terms import Relation
from mechplan.dynamics import Loading
from mechplan.model.loads import LoadKind, LoadSpec
from mechplan.model.plans import Plan
from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[2]
PLANS = ("position", "velocity", "acceleration", "force")
FORCE_OPS = {Op.FORCE_INERTIA, Op.MOMENT_INERTIA, Op.FORCE_LOAD, Op.MOMENT_ARM_TANGENTIAL,
             Op.FORCE_SUM, Op.FORCE_CLOSE, Op.BALANCING_MOMENT, Op.ZHUKOVSKY, Op.MOMENT_SUM,
             Op.MOMENT_CLOSE, Op.FORCE_LINE, Op.FORCE_REVERSE, Op.GUIDE_OFFSET,
             Op.LINE_OF_ACTION, Op.INERTIA_OFFSET}


def build(name: str, loading: Loading | None = None):
    scene = load_scene(ROOT / "templates" / f"{name}.toml")
    loading = loading or Loading.from_scene(scene)
    c = build_construction(scene.mechanism, analyse(scene.mechanism), PLANS, scene.assembly_phi,
                           scene.path, loading)
    return scene, c


def test_every_force_op_has_an_evaluator():
    assert FORCE_OPS <= set(EVALUATORS)


def test_v_engine_force_steps_and_labels():
    _, c = build("v_engine")
    steps = c.of_plan(Plan.FORCE)
    assert {s.op for s in steps} <= FORCE_OPS | {Op.POLE, Op.DIFFERENCE, Op.CONSTANT}
    labels = {s.label for s in steps}
    assert {"Q2", "M_q2", "G2", "Q3", "G3", "Q5", "G5", "F_C", "F_E", "R^t_12", "R^n_12", "R_12",
            "R_23", "R_03", "R_24", "R_45", "R_05", "R_01", "M_b", "ΣM_C(2)", "ΣM_E(4)"} <= labels
    assert all(s.group for s in steps)
    # polygon vertices a, b, c … per group; the closing meet is a result
    close = [s for s in steps if s.op is Op.FORCE_CLOSE]
    assert [s.group for s in close] == ["II(4,5)", "II(2,3)"]
    assert all(s.kind is Kind.POINT for s in close)


def test_groups_from_the_farthest_back_to_the_crank():
    _, c = build("v_engine")
    order = [s.group for s in c.of_plan(Plan.FORCE) if s.op is Op.POLE]
    assert order == ["II(4,5)", "II(2,3)", "I(0,1)"]
    ids = list(c.steps)
    assert (ids.index(c.results["R_24"]) < ids.index(c.results["R_12"])
            < ids.index(c.results["R_01"]))
    # the reaction of group (4,5) on link 2 is a known force of group (2,3)
    rt = c[c.results["R_12"]]
    assert rt.group == "II(2,3)"
    moment = next(s for s in c if s.op is Op.MOMENT_SUM and s.label == "ΣM_C(2)")
    assert "R_42" in moment.subject


def test_equations_of_the_force_polygons():
    _, c = build("v_engine")
    eq, typed = c.equations[(Plan.FORCE, "II(2,3)")]
    rows = [(term, str(d), m) for term, d, m in typed]      # directions are structured terms
    assert typed[-1][1].relation is Relation.PARALLEL
    assert eq == "R^t_12 + Q2 + G2 + R_42 + Q3 + G3 + F_C + R_03 + R^n_12 = 0"
    assert ("R_03", "⊥ Ax", "?") in rows and ("R^n_12", "∥ BC", "?") in rows
    assert ("F_C", "∥ Ax, towards A", "p·πd²/4") in rows


@pytest.mark.parametrize("name", ["four_bar", "quick_return", "shaper"])
def test_dyad_kinds_of_the_templates_emit_polygons(name):
    scene = load_scene(ROOT / "templates" / f"{name}.toml")
    last = scene.mechanism.moving[-1]
    point = list(scene.mechanism.links[last].points)[-1]     # not a pivot on the frame
    loading = Loading(loads=(LoadSpec(LoadKind.FORCE, last, point, vector=(100.0, 50.0)),))
    _, c = build(name, loading)
    groups = analyse(scene.mechanism).groups
    poles = [s.group for s in c.of_plan(Plan.FORCE) if s.op is Op.POLE]
    assert poles == [g.name for g in reversed(groups)] + ["I(0,1)"]
    ev = c.evaluate(np.radians([33.0]))
    assert abs(ev[c.results["M_b"]][0]) > 0


def test_vectorised_evaluation_equals_single_positions():
    _, c = build("v_engine")
    phi = np.radians([0.0, 47.0, 180.0, 299.0])
    together = c.evaluate(phi)
    for k, p in enumerate(phi):
        alone = c.evaluate(p)
        for key in ("R_12", "R_03", "R_05", "M_b", "M_b_zhukovsky", "d_03"):
            np.testing.assert_array_equal(alone[c.results[key]][0], together[c.results[key]][k])


def test_closing_lines_report_their_conditioning():
    _, c = build("v_engine")
    ev = c.evaluate(np.radians([10.0, 180.0]))
    close = [s.id for s in c.of_plan(Plan.FORCE) if s.op is Op.FORCE_CLOSE]
    for sid in close:
        ev.get(sid)
        assert sid in ev.sines and np.all(ev.sines[sid] > 0.1)


def test_inertia_force_offset_and_line_of_action():
    _, c = build("slider_crank")
    ev = c.evaluate(np.radians([20.0, 130.0]))
    q, mq, h = (ev[c.results[k]] for k in ("Q_2", "M_q2", "h_2"))
    k_point = ev["force.Kq.2"]
    s2 = ev["pos.S2"]
    # the single force Q through K has the moment M_q about S2, |S2K| = |h| = |M_q|/|Q|
    arm = k_point - s2
    np.testing.assert_allclose(arm[:, 0] * q[:, 1] - arm[:, 1] * q[:, 0], mq, rtol=1e-12)
    np.testing.assert_allclose(np.hypot(*arm.T), np.abs(h), rtol=1e-12)
    np.testing.assert_allclose(h, mq / np.hypot(*q.T), rtol=1e-15)
    np.testing.assert_allclose(q, -4.0 * ev[c.results["a_S2"]], rtol=1e-15)
    np.testing.assert_allclose(mq, -0.06 * ev[c.results["epsilon_2"]], rtol=1e-15)


def test_table_against_crank_angle_interpolates_and_wraps():
    text = (ROOT / "templates" / "slider_crank.toml").read_text(encoding="utf-8") + """
[[loads]]
type = "table"
point = "B"
towards = "O"
against = "crank_angle"
table = [["-90 deg", "100 N"], ["90 deg", "300 N"], ["270 deg", "100 N"]]
"""
    scene = parse_scene(text)
    loading = Loading.from_scene(scene)
    c = build_construction(scene.mechanism, analyse(scene.mechanism), PLANS, 0.0, None, loading)
    ev = c.evaluate(np.radians([90.0, 0.0, 180.0, 315.0, 405.0]))
    f = ev[c.results["load_0"]]
    np.testing.assert_allclose(f[:, 1], 0.0, atol=1e-12)
    np.testing.assert_allclose(-f[:, 0], [300.0, 200.0, 200.0, 150.0, 250.0], rtol=1e-12)


def test_table_against_displacement_uses_the_guide_coordinate():
    text = (ROOT / "templates" / "slider_crank.toml").read_text(encoding="utf-8") + """
[[loads]]
type = "table"
point = "B"
towards = "O"
against = "displacement"
table = [["0.3 m", "0 N"], ["0.5 m", "1000 N"]]
"""
    scene = parse_scene(text)
    loading = Loading.from_scene(scene)
    c = build_construction(scene.mechanism, analyse(scene.mechanism), PLANS, 0.0, None, loading)
    phi = np.radians([0.0, 70.0, 180.0])
    ev = c.evaluate(phi)
    x_b = ev["pos.B"][:, 0]
    np.testing.assert_allclose(-ev[c.results["load_0"]][:, 0],
                               np.interp(x_b, [0.3, 0.5], [0, 1000]), rtol=1e-12)


def test_guide_offset_evaluator():
    step = type("S", (), {"param": staticmethod(lambda name, default=None: None)})()
    o = np.array([[1.0, 2.0]])
    at = np.array([[1.0 + 0.3 * math.cos(0.4), 2.0 + 0.3 * math.sin(0.4)]])
    theta = np.array([0.4])
    n = np.array([[-math.sin(0.4), math.cos(0.4)]])
    value, _, _ = EVALUATORS[Op.GUIDE_OFFSET](step, o, at, np.array([5.0]), 10.0 * n, theta)
    np.testing.assert_allclose(value, [0.3 + 0.5])


def test_pair_key():
    assert force.pair_key("0", "3") == "03"
    assert force.pair_key("1", "12") == "1,12"
