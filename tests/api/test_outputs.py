"""solve(points=, links=): only what is asked is computed, with the values of a full solve."""

from __future__ import annotations

import numpy as np
import pytest
from construct.test_error_estimates import SLOTTED_THROUGH_PIVOT
from scenes import TEMPLATES

import mechplan
from mechplan.fast import numba_available

KINEMATIC = ("position", "velocity", "acceleration")
PATHS = [False] + ([True] if numba_available() else [])


@pytest.fixture(autouse=True)
def _kernel_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("MECHPLAN_CACHE", str(tmp_path))


def _template(name):
    return mechplan.load(next(p for p in TEMPLATES if p.stem == name))


@pytest.mark.parametrize("fast", PATHS)
def test_asked_outputs_only_with_the_full_solves_values(fast):
    m = _template("four_bar")
    full = m.solve(positions=72, plans=KINEMATIC, fast=False)
    few = m.solve(positions=72, plans=KINEMATIC, points=("C", "B"), links=("3",), fast=fast)
    for group in ("r", "v", "a"):
        assert set(getattr(few, group)) == {"B", "C"}, group
    for group in ("angle", "omega", "epsilon"):
        assert set(getattr(few, group)) == {"3"}, group
    for group in ("r", "v", "a", "angle", "omega", "epsilon"):
        for key, value in getattr(few, group).items():
            want = getattr(full, group)[key]
            scale = float(np.max(np.abs(want)))
            assert value.shape == want.shape
            assert np.max(np.abs(value - want)) <= 4e-15 * scale, (group, key)
            assert not value.flags.writeable
    with pytest.raises(KeyError, match="known: 3"):
        few.omega["2"]


@pytest.mark.parametrize("fast", PATHS)
def test_one_of_points_or_links_leaves_the_other_empty(fast):
    m = _template("slider_crank")
    only_links = m.solve(phi_deg=[10.0, 20.0], plans=KINEMATIC, links=("2",), fast=fast)
    assert len(only_links.r) == 0 and set(only_links.epsilon) == {"2"}
    only_points = m.solve(phi_deg=[10.0, 20.0], plans=("position",), points=("B",), fast=fast)
    assert set(only_points.r) == {"B"} and len(only_points.v) == 0 == len(only_points.angle)


def test_unknown_or_malformed_outputs_are_refused():
    m = _template("four_bar")
    with pytest.raises(mechplan.MechplanError, match="points must be among"):
        m.solve(phi_deg=[10.0], points=("Z",))
    with pytest.raises(mechplan.MechplanError, match="links must be among"):
        m.solve(phi_deg=[10.0], links=("9",))
    with pytest.raises(mechplan.MechplanError, match="sequence of names"):
        m.solve(phi_deg=[10.0], points="B")
    with pytest.raises(mechplan.MechplanError, match="must not both be empty"):
        m.solve(phi_deg=[10.0], points=(), links=())


@pytest.mark.parametrize("fast", PATHS)
def test_flags_are_those_of_the_asked_outputs(fast):
    m = mechplan.loads(SLOTTED_THROUGH_PIVOT)
    near = [200.0, 270.1]
    full = m.solve(phi_deg=near, plans=KINEMATIC, fast=False)
    few = m.solve(phi_deg=near, plans=KINEMATIC, links=("3",), fast=fast)
    want = {(k, q, s) for k, q, s, _ in full.flags if s == "3"}
    assert want and {(k, q, s) for k, q, s, _ in few.flags} == want


@pytest.mark.skipif(not numba_available(), reason="the fast extra (numba) is not installed")
def test_fused_memory_budget_counts_the_asked_results_only(monkeypatch):
    m = _template("v_engine")
    n = 20_000
    few = {"points": ("B",), "links": ()}
    # B's r, v, a: 3 results × 48 bytes × n; all steps of the construction need far more
    monkeypatch.setenv("MECHPLAN_MEMORY_BUDGET", str(3 * 48 * n + 1))
    sol = m.solve(positions=n, plans=KINEMATIC, fast=True, **few)
    assert sol.r["B"].shape == (n, 2)
    with pytest.raises(mechplan.MechplanError, match="MECHPLAN_MEMORY_BUDGET"):
        m.solve(positions=n, plans=KINEMATIC, fast=False, **few)
    with pytest.raises(mechplan.MechplanError, match="MECHPLAN_MEMORY_BUDGET"):
        m.solve(positions=n, plans=KINEMATIC, fast=True)
