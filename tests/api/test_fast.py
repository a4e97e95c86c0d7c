"""The public solve path through the fused kernel equals the numpy path: values, flags, errors."""

from __future__ import annotations

import numpy as np
import pytest
from construct.test_error_estimates import SLOTTED_THROUGH_PIVOT
from scenes import TEMPLATES

import mechplan
from mechplan.fast import numba_available

KINEMATIC = ("position", "velocity", "acceleration")
pytestmark = pytest.mark.skipif(not numba_available(),
                                reason="the fast extra (numba) is not installed")


@pytest.fixture(autouse=True)
def _kernel_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("MECHPLAN_CACHE", str(tmp_path))


@pytest.mark.parametrize("name", ["four_bar", "shaper"])
def test_fast_path_equals_the_numpy_path(name):
    m = mechplan.load(next(p for p in TEMPLATES if p.stem == name))
    slow = m.solve(positions=360, plans=KINEMATIC, fast=False)
    fast = m.solve(positions=360, plans=KINEMATIC, fast=True)
    assert m._fast.kernel(m.construction(KINEMATIC), m._plans(KINEMATIC)) is not None
    for group in ("r", "v", "a", "angle", "omega", "epsilon"):
        a, b = getattr(slow, group), getattr(fast, group)
        assert set(a) == set(b), group
        for key in a:
            scale = max(float(np.max(np.abs(a[key]))), 1e-300)
            assert np.max(np.abs(a[key] - b[key])) <= 1e-15 * scale * 4, (group, key)
            assert not b[key].flags.writeable
    assert fast.flags == slow.flags == ()


def test_flags_and_refusals_are_the_numpy_paths():
    m = mechplan.loads(SLOTTED_THROUGH_PIVOT)
    near = [200.0, 270.1]
    slow = m.solve(phi_deg=near, plans=KINEMATIC, fast=False)
    fast = m.solve(phi_deg=near, plans=KINEMATIC, fast=True)
    assert {(k, q, s) for k, q, s, _ in fast.flags} == {(k, q, s) for k, q, s, _ in slow.flags}
    assert {k for k, *_ in fast.flags} == {1}
    with pytest.raises(mechplan.MechplanError) as slow_err:
        m.solve(phi_deg=[270.0], plans=KINEMATIC, fast=False)
    with pytest.raises(mechplan.MechplanError) as fast_err:
        m.solve(phi_deg=[270.0], plans=KINEMATIC, fast=True)
    assert str(fast_err.value) == str(slow_err.value)
