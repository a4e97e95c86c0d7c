"""The operation registry: one complete spec per operation, named inputs that fit every step."""

from __future__ import annotations

import copy
import inspect
import pickle
from pathlib import Path

import numpy as np
import pytest

from mechplan.construct.builder import build_construction
from mechplan.construct.ops import FAMILIES, SPECS, Drawn, Op, OpSpec, Source, registered, spec
from mechplan.construct.step import Kind, Role, Step
from mechplan.dynamics import Loading
from mechplan.i18n import LANGUAGES, has_message
from mechplan.model.loads import LoadKind, LoadSpec
from mechplan.model.plans import Plan
from mechplan.model.structure import analyse
from mechplan.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def test_every_operation_has_one_spec():
    names = [s.value for family in FAMILIES for s in (getattr(family, n) for n in family.__all__)]
    # 57: 42 before, the drivers' 8, the friction's 3 and the triads' triad_angle,
    # triad_point, line_through, moment_along, and the second crank's second_crank_angle (W = 2);
    # the velocities by instant centres' 9 (ops/centre_velocity.py); a second cylinder's
    # second_driver_length and a driver's law by a table, driver_law (W = 2 with cylinders);
    # a crank's ω, ε (and a second crank's θ) by its law, crank_law, and a second slider's
    # second_slider_position, and a cylinder's arc cutting a guide line, circle_line_driven
    # (ops/driver_inputs.py); triads with slider legs' triadp_angle, triadp_point,
    # normal_through, leg_normal_force (ops/triadp.py); friction_free, a second driver's
    # friction-free M_b⁰ or F_d⁰ (W = 2)
    assert len(names) == len(set(names)) == len(SPECS) == 77
    for family in FAMILIES:
        declared = {n for n, v in vars(family).items() if isinstance(v, OpSpec)}
        assert declared == set(family.__all__), family.__name__      # none left out of Op
        for name in family.__all__:
            s = getattr(family, name)
            assert s.name == name == s.value.upper() and SPECS[s.value] is s
            assert getattr(Op, name) is s                             # the Op namespace
            assert (s.evaluate is None) == (s.source is Source.DRIVE), name
    assert {v for v in vars(Op).values() if isinstance(v, OpSpec)} == set(SPECS.values())
    assert spec(Op.LINE_PERP) is Op.LINE_PERP and registered("line_perp") is Op.LINE_PERP
    assert repr(Op.CIRCLE_CIRCLE) == "Op.CIRCLE_CIRCLE"
    assert Op.CIRCLE_CIRCLE.value == "circle_circle"
    with pytest.raises(KeyError, match="no operation"):
        registered("circle_square")


def test_specs_are_identities_across_processes():
    # a step sent to a worker process comes back holding the registry's spec, not a copy
    step = Step("v.c", Op.LINE_LINE, ("a", "b"), Plan.VELOCITY, Kind.POINT, Role.RESULT, "c")
    again = pickle.loads(pickle.dumps(step))
    assert again.op is Op.LINE_LINE and again == step and hash(again) == hash(step)
    assert copy.deepcopy(Op.OMEGA) is Op.OMEGA and Op.OMEGA != Op.EPSILON


def test_every_sentence_is_in_every_catalogue():
    for s in SPECS.values():
        for lang in LANGUAGES:
            # the checker names every operation ("check step c: two lines meet")
            assert has_message(f"check.op.{s.value}", lang), (s.value, lang)
        if s.message is not None:
            assert s.message == f"protocol.op.{s.value}"
            for lang in LANGUAGES:
                assert has_message(s.message, lang), (s.message, lang)


def test_levers_name_two_point_inputs():
    assert Op.SIMILAR_IMAGE.lever == ("pa", "pb") and Op.LINE_PERP.lever == ("p", "q")
    for s in SPECS.values():
        if isinstance(s.lever, tuple):
            assert len(s.lever) == 2 and set(s.lever) <= set(s.inputs), s.value
        if s.rate_of is not None:      # a link's rate: its relative vector over the link's length
            assert isinstance(s.lever, tuple) and set(s.rate_of) <= set(s.inputs), s.value
    assert {s for s in SPECS.values() if s.rate_of} == {Op.OMEGA, Op.EPSILON}
    with pytest.raises(KeyError, match="has no input"):
        OpSpec("toy", SPECS["omega"].evaluate, None, lever=("p", "nowhere"))


def test_construction_lines_name_the_point_they_are_drawn_through():
    lines = {s for s in SPECS.values() if s.draw is Drawn.CONSTRUCTION_LINE}
    assert {s for s in SPECS.values() if s.through} == lines
    assert all(s.through in s.inputs for s in lines)
    assert Op.LOCUS_LINE.through == "base" and Op.LINE_PERP.through == "through"


def test_inputs_are_the_parameters_of_the_evaluation():
    s = spec(Op.SIMILAR_IMAGE)
    assert s.inputs == ("a", "b", "pa", "pb", "px") and s.rest is None
    assert spec(Op.LOCUS_LINE).inputs == ("base",) and spec(Op.LOCUS_LINE).rest == "angle"
    assert spec(Op.POLE).inputs == ()
    for s in SPECS.values():
        if s.source is Source.INPUTS:
            params = list(inspect.signature(s.evaluate).parameters)[1:]
            assert params[:len(s.inputs)] == list(s.inputs)


@pytest.mark.parametrize("name", ["v_engine", "shaper"])
def test_every_step_fits_its_named_inputs(name):
    scene = load_scene(ROOT / "templates" / f"{name}.toml")
    loading = Loading.from_scene(scene)
    if not loading.loads:
        last = scene.mechanism.moving[-1]
        point = list(scene.mechanism.links[last].points)[-1]
        loading = Loading(loads=(LoadSpec(LoadKind.FORCE, last, point, vector=(100.0, 50.0)),))
    c = build_construction(scene.mechanism, analyse(scene.mechanism),
                           ("position", "velocity", "acceleration", "force"), scene.assembly_phi,
                           scene.path, loading)
    seen = set()
    for step in c:
        s = spec(step.op)
        seen.add(step.op)
        if s.rest is None:
            assert len(step.inputs) == len(s.inputs), step.id
        else:
            assert len(step.inputs) >= len(s.inputs), step.id
        for i, name_ in enumerate(s.inputs):
            assert step.input(name_) == step.inputs[i]
        assert step.rest() == step.inputs[len(s.inputs):]
    assert {Op.SIMILAR_IMAGE, Op.LINE_LINE, Op.FORCE_CLOSE, Op.ZHUKOVSKY} <= seen
    with pytest.raises(KeyError, match="has no input"):
        next(iter(c)).input("nonsense")
    # the registry's evaluation is the construction's: one value checked by hand
    ev = c.evaluate(np.radians([30.0]))
    pole = next(s for s in c if s.op is Op.POLE)
    assert np.array_equal(ev[pole.id], [[0.0, 0.0]])
