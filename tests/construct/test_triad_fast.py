"""The triad's fast closure (issue 29) against reference paths, over sweeps that reach its singular
positions.

- Brackets: the window laid out node by node (``triad_solve._window``) takes, wherever it decides,
  the very cell the general cells take (``triad_solve._general``: the window's nodes and the
  domain's edges sorted, the nearest crossing, cells off the domain left out) — an independent
  formulation of the same rule.
- Roots: θ of the fast path (Newton's iteration settled by its error estimate, blocks of
  positions) against the Illinois secant run to the last bit on the general cells
  (``triad_solve.refine``): within 1e-12 rad, or — where the group is near its singular position
  and f′ → 0 — within the width of f's rounding band over f′ (the root of an f known to
  ``RESIDUAL_ULPS`` roundings of the group's size is known no better).
- The gap's sign and the flags are the reference's (a flagged or refused position stays so).
- The scalar solver of the fused kernel follows the constants it is given (numba's cache of it
  never keeps old ones).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechplan.construct.kernel_triad import CONSTANTS, _triad_angle, window_trig
from mechplan.construct.kernel_triad import _window as scalar_window
from mechplan.construct.ops import triad_solve as ts
from mechplan.construct.ops.triad import params
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import build

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "six_bar_triad.toml"
EPS = float(np.finfo(float).eps)


def _shortened():
    text = TEMPLATE.read_text(encoding="utf-8").replace('FE = "100 mm"', 'FE = "75 mm"')
    return parse_scene(text.replace('E = ["139 mm", "22 mm"]\n', ""), "singular.toml")


def _inputs(scene, phi):
    _, c = build(scene, ("position",))
    ev = c.evaluate(phi)
    step = c["pos.angle.3"]
    a1, a2, a3 = (ev[i] for i in step.inputs)
    return np.array(a1), np.array(a2), np.array(a3), params(step)


def _ends(scene) -> list[float]:
    """Crank angles where the group stops closing (θ turns NaN), to 1e-15 rad by bisection."""
    phi = np.linspace(0.0, 2 * np.pi, 3601)
    theta = ts.solve(*_inputs(scene, phi))[0]
    out = []
    for k in np.nonzero(np.isnan(theta[:-1]) != np.isnan(theta[1:]))[0]:
        lo, hi = phi[k], phi[k + 1]                    # lo on the side of theta[k]
        side = math.isnan(theta[k])
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if math.isnan(ts.solve(*_inputs(scene, np.array([mid])))[0][0]) == side:
                lo = mid
            else:
                hi = mid
        out.append(hi if side else lo)                 # the last angle that closes
    return out


def _sweep(scene, ends: bool) -> np.ndarray:
    rng = np.random.default_rng(29)
    phi = [np.linspace(0.0, 2 * np.pi, 7200, endpoint=False), rng.uniform(0, 2 * np.pi, 2000)]
    if ends:
        for end in _ends(scene):
            for sign in (-1.0, 1.0):
                phi.append(end + sign * np.radians(np.array([1.0, 1e-3, 1e-6, 1e-9, 0.0])))
    return np.concatenate(phi)


@pytest.fixture(scope="module", params=["six_bar", "shortened"])
def sweep(request):
    scene = load_scene(TEMPLATE) if request.param == "six_bar" else _shortened()
    phi = _sweep(scene, ends=request.param == "shortened")
    return _inputs(scene, phi)


def test_the_window_takes_the_general_cells_bracket(sweep):
    a1, a2, a3, t = sweep
    cells, found = ts._window(a1, a2, a3, t)
    ref = ts._general(a1, a2, a3, t)
    assert found.mean() > 0.5
    assert np.all(ref.found[found])
    for name in ("lo", "hi", "flo", "fhi"):
        np.testing.assert_array_equal(getattr(cells, name)[found], getattr(ref, name)[found],
                                      err_msg=name)


def test_the_scalar_window_takes_the_numpy_windows_bracket(sweep):
    """The fused kernel's window (no arrays, each edge's halves offered at its cell) decides
    where the numpy path's does, with the same cell and the same values at its ends (a domain
    edge, from libm's arccos and arctan2 there and numpy's here, within a few roundings, and f
    there within the square root of that)."""
    a1, a2, a3, t = sweep
    cells, found = ts._window(a1, a2, a3, t)
    counts, _ = CONSTANTS
    cth, sth = window_trig(t.ref)
    p = (t.l1, t.l2, t.l3, *t.d2, *t.d3, float(t.sigma), float(t.slope), t.ref)
    for k in range(a1.shape[0]):
        lo, hi, flo, fhi, ok = scalar_window((*a1[k], *a2[k], *a3[k]), p, counts, cth, sth)
        assert ok == found[k]
        if ok:
            for x, f, x_np, f_np in ((lo, flo, cells.lo[k], cells.flo[k]),
                                     (hi, fhi, cells.hi[k], cells.fhi[k])):
                assert abs(x - x_np) <= 4e-15
                # at a node the same value; at an edge f′ is infinite (the half-chord ∝ √)
                assert abs(f - f_np) <= (1e-15 if x == x_np else 1e-7 * t.size)


def test_roots_agree_with_a_secant_to_the_last_bit(sweep):
    a1, a2, a3, t = sweep
    theta, gap, sine = ts.solve(a1, a2, a3, t)
    ref = ts._general(a1, a2, a3, t)
    closes = ref.found & np.isfinite(theta)
    # a position the general cells do not close is refused by the fast path too
    assert not np.any(np.isfinite(theta) & ~ref.found)
    np.testing.assert_array_equal(gap > 0, ~np.isfinite(theta))
    j = np.nonzero(ref.found)[0]
    x = ts.refine(a1[j], a2[j], a3[j], ref.lo[j], ref.hi[j], ref.flo[j], ref.fhi[j], t, t.sigma)
    exact = np.full(theta.shape, np.nan)
    exact[j] = x
    assert np.all(np.isfinite(theta[ref.found]) | (sine[ref.found] == 0.0))
    _, _, fp = ts.closure(a1, a2, a3, exact, t, slope=True)
    assert fp is not None
    band = ts.RESIDUAL_ULPS * EPS * t.size / np.abs(fp)
    err = np.abs(theta - exact)[closes]
    allowed = np.maximum(1e-12 * (1 + np.abs(exact)), 2 * band)[closes]
    assert np.all(err <= allowed), float(np.max(err / allowed))
    trusted = closes & (sine > 1e-6)
    assert trusted.mean() > 0.5
    assert float(np.max(np.abs(theta - exact)[trusted])) <= 1e-12


def test_blocks_give_the_values_of_one_block(sweep, monkeypatch):
    a1, a2, a3, t = sweep
    whole = ts._solve(a1, a2, a3, t)
    monkeypatch.setattr(ts, "BLOCK", 1000)
    for mine, theirs in zip(ts.solve(a1, a2, a3, t), whole, strict=True):
        np.testing.assert_array_equal(mine, theirs)


def test_the_scalar_solver_agrees_and_follows_its_constants(sweep):
    a1, a2, a3, t = sweep
    theta = ts.solve(a1, a2, a3, t)[0]
    counts, tols = CONSTANTS
    cth, sth = window_trig(t.ref)
    consts = (t.l1, t.l2, t.l3, *t.d2, *t.d3, float(t.sigma), float(t.slope), t.ref, t.size)
    rng = np.random.default_rng(3)
    for k in rng.choice(a1.shape[0], 200, replace=False):
        pts = (*a1[k], *a2[k], *a3[k])
        th = _triad_angle(*pts, *consts, counts, tols, cth, sth)[0]
        if math.isnan(theta[k]):
            assert math.isnan(th)
        else:
            assert abs(th - theta[k]) <= 1e-12 * (1 + abs(theta[k]))
    # no Newton step, no safeguarded iteration: the secant point of the bracket, not the root
    cell = np.abs(np.remainder((theta - t.ref) / (2 * np.pi / ts.GRID), 1.0) - 0.5)
    k = int(np.nanargmin(cell))                        # a root mid-cell, far from the nodes
    pts = (*a1[k], *a2[k], *a3[k])
    short = (counts[0], counts[1], 0, 0, 0)
    th = _triad_angle(*pts, *consts, short, tols, cth, sth)[0]
    assert abs(th - theta[k]) > 1e-12
