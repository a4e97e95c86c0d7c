"""The kinematic diagrams s(φ), v(φ), a(φ) of the output link are drawn one under another on one
φ axis: their φ axes start and end at the same x on the sheet (main shifted each by the width of
its own y tick labels, up to 7 mm)."""

from __future__ import annotations

import functools

import pytest
from scenes import ROOT

from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.sheet.primitives import Arrow
from mechplan.solve import solve


@functools.cache
def solved(stem: str):
    return solve(load_scene(ROOT / "templates" / f"{stem}.toml"))


@pytest.mark.parametrize("stem", ["slider_crank", "four_bar"])
@pytest.mark.parametrize("size", ["A1", "A3", "A4"])
def test_phi_axes_of_the_kinematic_diagrams_are_aligned(stem, size):
    comp = compose(solved(stem), size, lang="ru")
    stacks = [(p, o) for placed in comp.placements for p, o in placed
              if p.name.startswith("diagram-kinematic")]
    assert stacks
    n = 0
    for panel, (dx, _dy) in stacks:
        axes = [a for a in panel.primitives if isinstance(a, Arrow)
                and abs(a.start[1] - a.end[1]) < 1e-9]            # horizontal: the φ axes
        assert len(axes) >= 2 or len(stacks) > 1
        starts = {round(a.start[0] + dx, 6) for a in axes}
        ends = {round(a.end[0] + dx, 6) for a in axes}
        assert len(starts) == 1 and len(ends) == 1, (starts, ends)
        n += len(axes)
    assert n == 3                          # s, v and a
