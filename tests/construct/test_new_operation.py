"""Adding an operation is one entry: a spec declared beside its function (here, in this test) is
evaluated, written in the protocol and estimated like any other, and a construction that needs it,
having no scalar form in the fused kernel, is solved by the numpy path with the same results."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import mechplan
from mechplan import solve as solve_module
from mechplan.construct.estimate import estimate_errors
from mechplan.construct.kernel import KernelUnavailable, KernelUnsupported, compile_kernel
from mechplan.construct.ops import Grade, Op, OpSpec, Written
from mechplan.construct.protocol import sentence
from mechplan.fast import FastPath
from mechplan.scene import load_scene
from mechplan.solve import build, targets_for

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = ROOT / "templates" / "four_bar.toml"
KINEMATIC = ("position", "velocity", "acceleration")
PHI_DEG = np.arange(0.0, 360.0, 7.5)


def toy_omega(step, p, q, vp, vq):
    """ω of the link pq as (v_q − v_p)·(pq turned by 90°) / |pq|², written out by hand."""
    rx, ry = q[:, 0] - p[:, 0], q[:, 1] - p[:, 1]
    dx, dy = vq[:, 0] - vp[:, 0], vq[:, 1] - vp[:, 1]
    return (dx * -ry + dy * rx) / (rx * rx + ry * ry), None, None


#: the new operation, in one entry (its sentence borrowed from ω: a real one adds
#: ``protocol.op.toy_omega`` to the four catalogues)
TOY_OMEGA = OpSpec("toy_omega", toy_omega, "protocol.op.omega", grade=Grade.VALUE,
                   written=Written.RATE, lever=("p", "q"))


def _with_toy(c):
    """The construction with every ω step done by the toy operation instead."""
    steps = {sid: dataclasses.replace(s, op=TOY_OMEGA) if s.op is Op.OMEGA else s
             for sid, s in c.steps.items()}
    return dataclasses.replace(c, steps=steps, derived={})


def test_a_new_operation_evaluates_writes_and_is_estimated():
    scene = load_scene(FOUR_BAR)
    _, c = build(scene, KINEMATIC)
    toy = _with_toy(c)
    omegas = [s.id for s in c if s.op is Op.OMEGA]
    assert omegas and all(toy[sid].op is TOY_OMEGA for sid in omegas)
    assert TOY_OMEGA.inputs == ("p", "q", "vp", "vq") and toy[omegas[0]].input("vq")
    targets = targets_for(scene, c, KINEMATIC)
    phi = np.radians(PHI_DEG)
    ev, ev_toy = c.evaluate(phi), toy.evaluate(phi)
    ev.evaluate_all(targets)
    ev_toy.evaluate_all(targets)
    for sid in targets:
        np.testing.assert_allclose(ev_toy[sid], ev[sid], rtol=1e-13, atol=1e-12)
    est, est_toy = estimate_errors(c, ev, targets), estimate_errors(toy, ev_toy, targets)
    for sid in targets:
        np.testing.assert_allclose(est_toy.relative(sid), est.relative(sid), rtol=1e-6)
    mu = {plan: 1.0 for plan in {s.plan for s in c}}
    for lang in ("en", "ru"):
        for sid in omegas:
            said = sentence(toy, toy[sid], ev_toy, 3, lang, mu)
            assert said == sentence(c, c[sid], ev, 3, lang, mu) and "ω" in said
    with pytest.raises(KernelUnsupported, match="toy_omega"):
        compile_kernel(toy, targets, jit=False)
    assert issubclass(KernelUnsupported, KernelUnavailable)


def test_without_a_scalar_form_the_api_solves_on_the_numpy_path(monkeypatch):
    scene = load_scene(FOUR_BAR)
    assert FastPath(scene).prepare(build(scene, KINEMATIC)[1], KINEMATIC) is not None
    reference = mechplan.load(FOUR_BAR).solve(PHI_DEG, plans=KINEMATIC)   # the fused kernel

    def build_with_toy(scene, plans=None, loading=None):
        structure, c = build(scene, plans, loading)
        return structure, _with_toy(c)

    monkeypatch.setattr(solve_module, "build", build_with_toy)
    mech = mechplan.load(FOUR_BAR)
    toy = mech.construction(KINEMATIC)
    assert any(s.op is TOY_OMEGA for s in toy)
    assert FastPath(scene).prepare(toy, KINEMATIC) is None          # no kernel: numpy decides
    solved = mech.solve(PHI_DEG, plans=KINEMATIC)
    for field in ("r", "v", "a", "angle", "omega", "epsilon"):
        ref, got = getattr(reference, field), getattr(solved, field)
        assert set(got) == set(ref) and ref, field
        for key in ref:
            scale = float(np.max(np.abs(ref[key]))) or 1.0
            np.testing.assert_allclose(got[key], ref[key], rtol=0, atol=1e-13 * scale,
                                       err_msg=f"{field} {key}")
