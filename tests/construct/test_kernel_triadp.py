"""The fused kernel of class III groups with sliding legs gives the numpy path's values, estimates
and cannot-build mask (issue 29).

Configurations: the template ``six_bar_triad_slider`` (``RRP-RRR``, a frame guide), its slider on a
guide of the crank (Coriolis terms), its guide turned to 120° (the slider leg's normal gives the
special point), two slider legs (``RPP-RRR``), three (``PPP-RRR``, one on a guide of the crank), a
block on the base link (``RRR-RRP``), and the template with the leg AB shortened to 100 mm. Every
position of a full turn (0.5° apart); where a group stops closing inside the turn (the crank's
guide, three sliders, the shortened leg), its ends — found by bisection on the numpy path, the
group's Jacobian singular there — sampled 1°, 1e-3°, 1e-6°, 1e-9° and 0° away on either side.

- values: ≤ 1e-14 of the larger of the plan's scale and the value's own size, at every position
  both paths build; NaN at the same positions;
- the cannot-build mask (a gap, a sine below the least, an unbounded estimate) is the numpy path's,
  position for position;
- the estimates are the numpy path's (rtol 1e-5, as ``test_kernel.py``);
- the kernel compiles them (no ``KernelUnsupported``), and the public fast path uses it.

The generated code runs JIT-compiled with numba (skipped without the fast extra) and as plain
Python (the same source).
"""

from __future__ import annotations

import math
from functools import partial

import numpy as np
import pytest
from construct.test_triadp import TEMPLATE, _block, _coriolis_scene, _turned, _two_sliders

from mechplan.construct.estimate import UNBOUNDED, estimate_errors
from mechplan.construct.kernel import compile_kernel
from mechplan.construct.ops import Op
from mechplan.construct.trust import unbounded_positions
from mechplan.construct.validity import MAX_CONDITION
from mechplan.scene import parse_scene
from mechplan.solve import build, targets_for

KINEMATIC = ("position", "velocity", "acceleration")
TURN = np.radians(np.arange(0.0, 360.0, 0.5))
#: offsets (deg) from an end of the closing range, on either side
NEAR = np.array([1.0, 1e-3, 1e-6, 1e-9, 0.0])
#: the least sine of a position's meets below which it is near a singular one (condition > 20)
NEAR_SINGULAR = 0.05
EPS = float(np.finfo(float).eps)


def _shortened() -> str:
    text = TEMPLATE.read_text(encoding="utf-8").replace('AB = "120 mm"', 'AB = "100 mm"')
    return text.replace('B = ["120 mm", "89 mm"]\n', "")


def _three_sliders() -> str:
    """Two slider legs (``_two_sliders``) and the leg AB replaced by a slider B on a guide of the
    crank through O, 36.56° from OA: a group PPP-RRR (three guide lines; B_1 the meet of two
    lines), closing over part of the turn."""
    t = _two_sliders().replace(
        'lengths = { OA = "40 mm" }',
        'lengths = { OA = "40 mm" }\nguides.h = { through = "O", angle = "36.56 deg" }')
    return (t[:t.index("[links.2]")] + '[links.2]\nname = "slider B"\nslides = { point = "B", '
            'on = "h" }\n\n' + t[t.index("[links.3]"):])


CONFIGS = {
    "six_bar_triad_slider": lambda: TEMPLATE.read_text(encoding="utf-8"),
    "crank_guide_coriolis": _coriolis_scene,
    "guide_turned_120": lambda: _turned(120),
    "two_sliders_RPP": _two_sliders,
    "block_RRQ": _block,
    "three_sliders_PPP": _three_sliders,
    "shortened_singular": _shortened,
}


def _ends(c, angle: str) -> list[float]:
    """Crank angles (rad) where the group stops closing on the numpy path, to ~1e-16 rad."""
    def closes(phi: np.ndarray) -> np.ndarray:
        return np.isfinite(np.asarray(c.evaluate(phi)[angle]))

    phi = np.linspace(0.0, 2 * np.pi, 1441)
    ok = closes(phi)
    out = []
    for k in np.nonzero(ok[:-1] != ok[1:])[0]:
        lo, hi, side = phi[k], phi[k + 1], ok[k]
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if closes(np.array([mid]))[0] == side:
                lo = mid
            else:
                hi = mid
        out.append(lo if side else hi)            # the last angle that closes
    return out


def _case(name: str):
    scene = parse_scene(CONFIGS[name](), f"{name}.toml")
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    (angle,) = [s.id for s in c.steps.values() if s.op is Op.TRIADP_ANGLE]
    near = [end + np.radians(sign * NEAR) for end in _ends(c, angle) for sign in (-1.0, 1.0)]
    phi = np.concatenate([TURN, *near])
    ev = c.evaluate(phi)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    return scene, c, targets, phi, ev, est, len(near)


#: compiled by numba too (≈10 s of CPU each): the template, the Coriolis terms and two ends, an
#: arc and a line, two lines; the others run as plain Python (the same generated source)
COMPILED = ("six_bar_triad_slider", "crank_guide_coriolis", "two_sliders_RPP",
            "three_sliders_PPP")


@pytest.fixture(scope="module", params=list(CONFIGS))
def case(request):
    return request.param, _case(request.param)


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    return tmp_path_factory.mktemp("kernels")


def _numpy_mask(c, ev, est, targets) -> np.ndarray:
    """The positions the numpy path cannot build (``trust.failures`` without the reasons)."""
    bad = unbounded_positions(est, targets, ev.n)
    for gap in ev.gaps.values():
        bad |= gap > 0
    for sine in ev.sines.values():
        with np.errstate(divide="ignore"):
            bad |= 1.0 / sine > MAX_CONDITION
    return bad


def _run(c, targets, phi, jit):
    kernel = compile_kernel(c, targets, jit=jit)
    assert kernel.compiled == jit
    return kernel(phi)


def _check(c, targets, phi, ev, est, kernel) -> None:
    angle = next(s.id for s in c.steps.values() if s.op is Op.TRIADP_ANGLE)
    values, rel, bad = kernel([*targets, angle, "pos.B"], phi)
    expected = _numpy_mask(c, ev, est, targets)
    failed = bad.copy()
    for sid in targets:
        failed |= ~(rel[sid] < UNBOUNDED)
    np.testing.assert_array_equal(failed, expected)
    # the group's own steps: the numpy path's values to a few roundings at every position (a
    # domain edge is libm's arccos here, numpy's there), bit for bit at almost all
    for sid in (angle, "pos.B"):
        mine, theirs = np.asarray(values[sid]), np.asarray(ev[sid])
        np.testing.assert_array_equal(np.isnan(mine), np.isnan(theirs), err_msg=sid)
        np.testing.assert_allclose(mine, theirs, rtol=4 * EPS, atol=0, err_msg=sid)
        same = ((mine == theirs) | np.isnan(theirs)).reshape(phi.size, -1).all(axis=1)
        assert same.mean() > 0.99, sid
    ok = ~expected
    least = np.min(np.stack([np.broadcast_to(v, phi.shape) for v in ev.sines.values()]), axis=0)
    regular = ok & (least >= NEAR_SINGULAR)
    assert regular.mean() > 0.1
    for sid in targets:
        mine, theirs = np.asarray(values[sid]), np.asarray(ev[sid])
        np.testing.assert_array_equal(np.isnan(mine), np.isnan(theirs), err_msg=sid)
        size = np.abs(theirs) if theirs.ndim == 1 else np.hypot(theirs[:, 0], theirs[:, 1])
        scale = np.maximum(est.scale[sid] or 1.0, size)
        diff = np.abs(mine - theirs).reshape(phi.size, -1).max(axis=1) / scale
        assert np.nanmax(diff[regular], initial=0.0) <= 1e-14, (sid, np.nanmax(diff[regular]))
        # near a singular position (the group's, or a meet's of two nearly parallel lines) the
        # plans amplify a rounding of any earlier step (the similarity steps' complex products
        # round differently in numpy): the two paths differ by no more than the error both are
        # estimated to carry
        near = ok & ~regular
        bound = np.maximum(10.0 * est.relative(sid), 1e-14)
        assert np.all(diff[near] <= bound[near]), sid
        np.testing.assert_allclose(rel[sid][ok], est.relative(sid)[ok], rtol=1e-5, atol=0,
                                   err_msg=sid)


@pytest.mark.parametrize("case", COMPILED, indirect=True)
def test_numba_kernel_equals_the_numpy_path(case, cache, monkeypatch):
    pytest.importorskip("numba", reason="the fast extra (numba) is optional")
    monkeypatch.setenv("MECHPLAN_CACHE", str(cache))
    name, (_scene, c, targets, phi, ev, est, near) = case
    _check(c, targets, phi, ev, est, partial(_run, c, jit=True))
    if name == "crank_guide_coriolis":
        assert near >= 4                                   # ends, both sides of each
        mask = _numpy_mask(c, ev, est, targets)
        assert mask[TURN.size:].any() and not mask[TURN.size:].all()


def test_generated_code_as_plain_python_equals_the_numpy_path(case):
    _name, (_scene, c, targets, phi, ev, est, _near) = case
    _check(c, targets, phi, ev, est, partial(_run, c, jit=False))


def test_the_kernel_compiles_the_sliding_triads_operations(case):
    """No ``KernelUnsupported``: every triadp operation a kinematic plan needs has a scalar form
    (the force step ``leg_normal_force`` is a force step: no kernel, as for every force)."""
    _name, (_scene, c, targets, *_rest) = case
    kernel = compile_kernel(c, targets, jit=False)
    ops = {c[s].op for s in c.ancestors(targets)}
    assert {Op.TRIADP_ANGLE, Op.TRIADP_POINT} <= ops
    assert kernel.targets == tuple(targets)


def test_the_public_fast_path_uses_the_kernel(cache, monkeypatch):
    pytest.importorskip("numba", reason="the fast extra (numba) is optional")
    monkeypatch.setenv("MECHPLAN_CACHE", str(cache))
    import mechplan
    from mechplan.fast import FastPath

    scene = parse_scene(_two_sliders(), "two.toml")
    _, c = build(scene, KINEMATIC)
    assert FastPath(scene).prepare(c, KINEMATIC) is not None
    m = mechplan.loads(_two_sliders())
    at = np.arange(0.0, 360.0, 20.0)
    slow, quick = m.solve(at, plans=KINEMATIC, fast=False), m.solve(at, plans=KINEMATIC)
    for n in "BCE":
        for mine, theirs in ((quick.r[n], slow.r[n]), (quick.v[n], slow.v[n]),
                             (quick.a[n], slow.a[n])):
            assert np.max(np.abs(mine - theirs)) <= 1e-14 * max(1.0, float(np.max(np.abs(theirs))))
    assert math.isclose(float(np.max(np.abs(quick.omega["3"] - slow.omega["3"]))), 0.0,
                        abs_tol=1e-12)


def test_every_sliding_operation_has_a_scalar_form():
    from mechplan.construct.kernel_scalar import SCALAR_FORMS

    assert {Op.TRIADP_ANGLE, Op.TRIADP_POINT, Op.NORMAL_THROUGH} <= set(SCALAR_FORMS)
    assert Op.LEG_NORMAL_FORCE not in SCALAR_FORMS          # a force step


def test_the_scalar_solver_is_the_numpy_solver_at_a_double_root():
    """The group of ``test_triadp.test_singular_group_is_flagged_then_refused`` (the three legs'
    lines through one point: a double root), its guide moved across it in steps of 1e-5 m: θ,
    the gap and the sine of the one-position solver (compiled, and as plain Python) are
    ``triadp_solve.solve``'s — regular, flagged and refused positions alike."""
    from mechplan.construct import kernel_triadp as kt
    from mechplan.construct.ops import triadp_solve as ts

    b = [np.array([0.0, 0.0]), np.array([0.08, 0.0]), np.array([0.04, 0.06])]
    q = np.array([0.04, -0.10])
    a = [bb + 0.09 * (bb - q) / np.linalg.norm(bb - q) for bb in b[:2]]
    n3 = (b[2] - q) / np.linalg.norm(b[2] - q)
    u3 = np.array([-n3[1], n3[0]])
    shifts = np.linspace(-4e-4, 4e-4, 81)
    one, two = np.repeat(a[0][None], shifts.size, 0), np.repeat(a[1][None], shifts.size, 0)
    guide = np.stack((b[2] + shifts[:, None] * n3, np.repeat(u3[None], shifts.size, 0)), axis=1)
    solvers = [getattr(kt._triadp_angle, "py_func", kt._triadp_angle), kt._triadp_angle]
    seen = set()
    for sigma in (1, -1):
        for slope in (1, -1):
            g = ts.Group("RRP", (0.09, 0.09, 0.0), tuple(b[1] - b[0]), tuple(b[2] - b[0]), sigma,
                         slope, 0.0)
            theta, gap, sine = ts.solve((one, two, guide), g)
            seen |= {("closed" if s > 1e-3 else "flagged") if np.isfinite(t) else "refused"
                     for t, s in zip(theta, sine, strict=True)}
            trig = kt.grid_trig(g.ref)
            for solver in solvers:
                for k in range(shifts.size):
                    lc = (*one[k], 0.0, 0.0, *two[k], 0.0, 0.0, *guide[k, 0], *guide[k, 1])
                    got = solver(lc, (0, 0, 1), kt.group_args(g), kt.CONSTANTS, *trig)
                    for mine, theirs in zip(got, (theta[k], gap[k], sine[k]), strict=True):
                        assert mine == theirs or (np.isnan(mine) and np.isnan(theirs)) or \
                            abs(mine - theirs) <= 4 * EPS * abs(theirs), (k, sigma, slope)
    assert seen == {"closed", "flagged", "refused"}
