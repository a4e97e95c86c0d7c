"""The fused kernel gives the numpy path's values (≤ 1e-15 of each plan's scale), estimates and
flags.

The generated code runs as plain Python for every template (the same source numba compiles), and
JIT-compiled with numba for two templates.
"""

from __future__ import annotations

import numpy as np
import pytest
from construct.test_error_estimates import SLOTTED_THROUGH_PIVOT
from scenes import TEMPLATES

#: templates the fused kernel compiles (all of them; class III groups with slider legs:
#: tests/construct/test_kernel_triadp.py)
KERNEL_TEMPLATES = list(TEMPLATES)

from mechplan.construct.estimate import estimate_errors
from mechplan.construct.kernel import (
    CANNOT_TRUST,
    OVER_TOLERANCE,
    KernelUnavailable,
    compile_kernel,
)
from mechplan.construct.trust import failures
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import build, targets_for

KINEMATIC = ("position", "velocity", "acceleration")
PHI = np.radians(np.arange(0.0, 360.0, 1.0))


def _both(scene, phi, jit):
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    ev = c.evaluate(phi)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    kernel = compile_kernel(c, targets, jit=jit)
    return c, targets, ev, est, kernel(phi)


def _assert_same(targets, ev, est, values, rel):
    for sid in targets:
        scale = est.scale[sid] or 1.0
        diff = np.abs(values[sid] - ev[sid]) / scale
        assert np.nanmax(diff) <= 1e-15, (sid, np.nanmax(diff))
        assert np.array_equal(np.isnan(values[sid]), np.isnan(ev[sid])), sid
        assert np.allclose(rel[sid], est.relative(sid), rtol=1e-5, atol=0), sid


@pytest.mark.parametrize("path", KERNEL_TEMPLATES, ids=lambda p: p.stem)
def test_generated_code_equals_the_numpy_path(path):
    _c, targets, ev, est, (values, rel, bad) = _both(load_scene(path), PHI, jit=False)
    _assert_same(targets, ev, est, values, rel)
    assert not bad.any()


def test_cannot_build_mask_and_estimates_agree_at_a_singular_position():
    scene = parse_scene(SLOTTED_THROUGH_PIVOT, "pivot.toml")
    phi = np.radians([200.0, 269.0, 270.0, 270.001, 271.0])
    c, targets, ev, est, (values, rel, bad) = _both(scene, phi, jit=False)
    expected = {f.k for f in failures(c, ev, est, targets)}
    # the position through the pivot cannot be computed on either path
    kernel_failed = {k for k in range(phi.size)
                     if bad[k] or any(not rel[sid][k] < 1.0 for sid in targets)}
    assert 2 in expected and kernel_failed == expected
    regular = [k for k in range(phi.size) if k not in expected]
    for sid in targets:
        scale = est.scale[sid] or 1.0
        ok = np.isfinite(ev[sid][regular]).all(axis=-1) if ev[sid].ndim == 2 else \
            np.isfinite(ev[sid][regular])
        idx = np.asarray(regular)[ok]
        assert np.allclose(rel[sid][idx], est.relative(sid)[idx], rtol=1e-5), sid
        # the two paths differ by no more than the error both are estimated to carry
        diff = np.abs(values[sid][idx] - ev[sid][idx]) / scale
        bound = 10.0 * est.relative(sid)[idx]
        assert np.all(diff.reshape(len(idx), -1).max(axis=-1) <= np.maximum(bound, 1e-15)), sid
        assert np.allclose(rel[sid][idx], est.relative(sid)[idx], rtol=1e-5), sid


@pytest.mark.parametrize("name", ["four_bar", "v_engine", "six_bar_triad"])
def test_numba_kernel_equals_the_numpy_path(name, tmp_path, monkeypatch):
    pytest.importorskip("numba", reason="the fast extra (numba) is optional")
    monkeypatch.setenv("MECHPLAN_CACHE", str(tmp_path))
    path = next(p for p in TEMPLATES if p.stem == name)
    _c, targets, ev, est, (values, rel, _bad) = _both(load_scene(path), PHI, jit=True)
    _assert_same(targets, ev, est, values, rel)
    assert any(tmp_path.rglob("*.py"))                 # the kernel is cached on disk


def test_force_steps_have_no_kernel():
    scene = load_scene(next(p for p in TEMPLATES if p.stem == "v_engine"))
    _, c = build(scene, (*KINEMATIC, "force"))
    with pytest.raises(KernelUnavailable):
        compile_kernel(c, [c.results["M_b"]], jit=False)


def test_status_bits_say_what_the_stored_estimates_say():
    from mechplan.construct.kernel import CANNOT_TRUST, OVER_TOLERANCE

    scene = parse_scene(SLOTTED_THROUGH_PIVOT, "pivot.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    kernel = compile_kernel(c, targets, jit=False)
    seen = 0
    for deg, tol in (([200.0], 1e-6), ([200.0, 270.1], 1e-6), ([200.0, 270.0], 1e-6),
                     ([200.0], 1e-18)):
        phi = np.radians(deg)
        _, _, _, quiet = kernel.run(phi, tol, store=False)
        block, rel, bad, status = kernel.run(phi, tol, store=True)
        assert quiet == status
        assert bool(status & CANNOT_TRUST) == bool(bad.any() or not (rel < 1.0).all()), deg
        assert bool(status & OVER_TOLERANCE) == bool((rel > tol).any()), (deg, tol)
        assert block.shape == (len(deg), kernel.width)
        seen |= status
    assert seen == CANNOT_TRUST | OVER_TOLERANCE          # both bits were exercised


def _statuses(kernel, phi, tol):
    """(block, bad, status) of the quick body (estimates not stored) and of the full body."""
    quick = kernel.run(phi, tol, store=False)
    full = kernel.run(phi, tol, store=True)
    return quick, full


@pytest.mark.parametrize("path", KERNEL_TEMPLATES, ids=lambda p: p.stem)
def test_quick_body_decides_like_the_full_body(path):
    # the quick body skips the estimates where a bound proves them small; every status bit and
    # value must be the full body's, at a tolerance that nothing meets (every position falls
    # back), one that everything meets, and one in between
    scene = load_scene(path)
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    kernel = compile_kernel(c, targets, jit=False)
    phi = PHI[::4]
    _, full_rel, _, _ = kernel.run(phi, 1e-6, store=True)
    middle = float(np.median(full_rel))
    for tol in (1e-300, 1e-6, middle, np.inf):
        (qb, qbad, qs), (fb, fbad, fs) = ((b, bad, s) for b, _, bad, s in _statuses(kernel, phi,
                                                                                      tol))
        assert qs == fs, (tol, qs, fs)
        assert np.array_equal(qbad, fbad)
        assert np.array_equal(qb, fb, equal_nan=True)


def test_quick_body_at_singular_positions_and_odd_tolerances():
    scene = parse_scene(SLOTTED_THROUGH_PIVOT, "pivot.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    kernel = compile_kernel(c, targets, jit=False)
    phi = np.radians(np.concatenate((np.arange(0.0, 360.0, 7.0), [270.0, 269.9999, 270.1])))
    seen = 0
    for tol in (-1.0, 0.0, 1e-12, 1e-6, 0.7, np.nan, np.inf):
        (qb, qbad, qs), (fb, fbad, fs) = ((b, bad, s) for b, _, bad, s in _statuses(kernel, phi,
                                                                                      tol))
        assert qs == fs, (tol, qs, fs)
        assert np.array_equal(qbad, fbad)
        assert np.array_equal(qb, fb, equal_nan=True)
        seen |= qs
    assert seen == CANNOT_TRUST | OVER_TOLERANCE


def test_threaded_kernel_equals_the_serial_one(tmp_path, monkeypatch):
    pytest.importorskip("numba", reason="the fast extra (numba) is optional")
    from mechplan.construct.kernel import CHUNK, PARALLEL_FROM

    monkeypatch.setenv("MECHPLAN_CACHE", str(tmp_path))
    scene = parse_scene(SLOTTED_THROUGH_PIVOT, "pivot.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    kernel = compile_kernel(c, targets)
    assert kernel.parallel is not None
    n = PARALLEL_FROM + CHUNK // 3                      # a last chunk shorter than the others
    phi = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    # one position exactly through the pivot (cannot be built), in the last chunk
    phi[-5] = np.radians(270.0)
    for tol, store in ((1e-6, False), (1e-6, True), (1e-300, False)):
        block = np.empty((n, kernel.width), order="F")
        xs = np.empty((n, len(kernel.deferred)), order="F")
        rel = np.empty((n if store else 1, len(kernel.targets)))
        bad = np.empty(n, dtype=np.bool_)
        status = kernel.parallel(phi, tol, block, xs, rel, bad, store, CHUNK)   # threads
        sb, sxs, srel = np.empty_like(block), np.empty_like(xs), np.empty_like(rel)
        sbad = np.empty_like(bad)
        serial = kernel.function(phi, tol, sb, sxs, srel, sbad, store)
        assert status == serial and status & CANNOT_TRUST
        assert np.array_equal(block, sb, equal_nan=True) and np.array_equal(bad, sbad)
        assert np.array_equal(xs, sxs, equal_nan=True)
        if store:
            assert np.array_equal(rel, srel, equal_nan=True)
            assert bad[-5] or not (rel[-5] < 1.0).all()


def test_threads_only_on_spare_cores(monkeypatch):
    import os

    from mechplan.construct.kernel_load import spare_cores

    monkeypatch.setattr(os, "cpu_count", lambda: 2)
    monkeypatch.setattr(os, "getloadavg", lambda: (0.9, 0.0, 0.0))     # only this process
    assert spare_cores() == 2.0
    monkeypatch.setattr(os, "getloadavg", lambda: (2.1, 0.0, 0.0))     # and another one
    assert spare_cores() < 1.5


def test_lanes_rename_locals_and_drop_dead_values():
    from mechplan.construct.kernel_load import interleave

    values = ["_t = phi[i] * 2.0", "_t = _t + 1.0", "v1 = _t * _t", "v2 = math.atan2(_t, 1.0)"]
    rest = ["out[i, 0] = v1", "status |= 1 if v1 > 10.0 else 0"]
    lines = interleave(values, rest, lanes=3)
    text = "\n".join(lines)
    assert "atan2" not in text                         # v2: nothing reads it
    assert "_t__1_2" in text and "_t_0 " in text       # one name per assignment and lane
    phi = np.array([0.5, 1.0, 2.0, 3.0])
    out = np.zeros((4, 1))
    scope = {"phi": phi, "out": out, "status": 0, "i0": 0, "i1": 2, "i2": 3, "math": np}
    exec("\n".join(lines), scope)                      # noqa: S102 - the generated lines
    assert out[:, 0].tolist() == [4.0, 0.0, 25.0, 49.0]
    assert scope["status"] == 1
