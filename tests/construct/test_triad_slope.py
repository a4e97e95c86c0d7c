"""The Newton step of the triad's closure (``triad_newton._slope_at``, issue 29): f and the arcs'
sine are :func:`triad_solve.closure`'s to the bit, and f′ — by implicit differentiation of the two
arcs — is the derivative of f taken by mpmath at 40 digits (numerical differentiation of the
closure written out anew in mpmath: B₁ on the arcs about A₁ and A₂ − R(θ)·d2, then
|B₁ − A₃ + R(θ)·d3| − l₃), never from mechplan's formulas.
"""

from __future__ import annotations

from pathlib import Path

import mpmath as mp
import numpy as np

from mechplan.construct.ops import triad_newton as tn
from mechplan.construct.ops import triad_solve as ts
from mechplan.construct.ops.triad import params
from mechplan.scene import load_scene
from mechplan.solve import build

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "six_bar_triad.toml"


def _inputs(phi):
    _, c = build(load_scene(TEMPLATE), ("position",))
    ev = c.evaluate(phi)
    step = c["pos.angle.3"]
    a1, a2, a3 = (np.array(ev[i]) for i in step.inputs)
    return a1, a2, a3, params(step)


def _f(a1, a2, a3, t, theta):
    """f(θ) in mpmath (the current precision)."""
    c, s = mp.cos(theta), mp.sin(theta)
    cx = mp.mpf(a2[0]) - (c * t.d2[0] - s * t.d2[1])
    cy = mp.mpf(a2[1]) - (s * t.d2[0] + c * t.d2[1])
    dx, dy = cx - mp.mpf(a1[0]), cy - mp.mpf(a1[1])
    dd = dx * dx + dy * dy
    along = (mp.mpf(t.l1) ** 2 - mp.mpf(t.l2) ** 2 + dd) / (2 * dd)
    h = t.sigma * mp.sqrt(mp.mpf(t.l1) ** 2 / dd - along * along)
    bx = mp.mpf(a1[0]) + along * dx - h * dy
    by = mp.mpf(a1[1]) + along * dy + h * dx
    rx = bx - mp.mpf(a3[0]) + (c * t.d3[0] - s * t.d3[1])
    ry = by - mp.mpf(a3[1]) + (s * t.d3[0] + c * t.d3[1])
    return mp.sqrt(rx * rx + ry * ry) - t.l3


def test_the_newton_step_is_the_closure_with_its_derivative():
    rng = np.random.default_rng(29)
    phi = rng.uniform(0.0, 2 * np.pi, 60)
    a1, a2, a3, t = _inputs(phi)
    # at the roots, and up to a cell away from them
    theta = ts.solve(a1, a2, a3, t)[0] + rng.uniform(-0.26, 0.26, phi.size)
    a = tuple(np.ascontiguousarray(p[:, j]) for p in (a1, a2, a3) for j in (0, 1))
    f, sine, fp = tn._slope_at(a, theta, t)
    f0, sine0, _ = ts.closure(a1, a2, a3, theta, t)
    inside = np.isfinite(f0) & (sine0 > 1e-3)          # off a domain edge (f′ finite)
    assert inside.sum() > 30
    np.testing.assert_array_equal(f[inside], f0[inside])
    np.testing.assert_array_equal(sine[inside], sine0[inside])
    with mp.workdps(40):
        for k in np.nonzero(inside)[0]:
            ref = mp.diff(lambda x, k=k: _f(a1[k], a2[k], a3[k], t, x), mp.mpf(theta[k]))
            assert abs(fp[k] - float(ref)) <= 1e-13 * (1 + abs(float(ref))), (k, fp[k], ref)
