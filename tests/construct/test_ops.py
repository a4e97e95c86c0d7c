"""The operation registry: one complete spec per operation, named inputs that fit every step."""

from __future__ import annotations

import inspect
from pathlib import Path

import numpy as np
import pytest

from mechplan.construct.builder import build_construction
from mechplan.construct.ops import SPECS, Source, spec
from mechplan.construct.step import Op
from mechplan.dynamics import Loading
from mechplan.i18n import LANGUAGES, has_message
from mechplan.model.loads import LoadKind, LoadSpec
from mechplan.model.structure import analyse
from mechplan.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def test_every_operation_has_one_spec():
    assert set(SPECS) == set(Op)
    for op, s in SPECS.items():
        assert s.op is op
        assert (s.evaluate is None) == (s.source is Source.DRIVE), op


def test_every_sentence_is_in_every_catalogue():
    for s in SPECS.values():
        if s.message is not None:
            assert s.message == f"protocol.op.{s.op.value}"
            for lang in LANGUAGES:
                assert has_message(s.message, lang), (s.message, lang)


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
