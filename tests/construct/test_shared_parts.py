"""A part several steps compute alike (a link's unit normal, a similarity ratio) is computed once
per evaluation and gives every step the same bits as computing it again."""

from __future__ import annotations

import numpy as np
import pytest
from scenes import TEMPLATES

from mechplan.construct.ops import Op
from mechplan.scene import load_scene
from mechplan.solve import build, targets_for

KINEMATIC = ("position", "velocity", "acceleration")
PHI = np.radians(np.arange(0.0, 360.0, 7.0))


def _values(path, shares: bool) -> dict[str, np.ndarray]:
    scene = load_scene(path)
    _, c = build(scene, KINEMATIC)
    targets = targets_for(scene, c, KINEMATIC)
    saved = {op: op.shares for op in (Op.LINE_PERP, Op.SIMILAR_IMAGE)}
    try:
        for op in saved:
            object.__setattr__(op, "shares", shares)
        ev = c.evaluate(PHI)
        ev.evaluate_all(targets)
    finally:
        for op, v in saved.items():
            object.__setattr__(op, "shares", v)
    return {sid: ev[sid] for sid in targets}, ev


def test_the_specs_that_share_say_so():
    assert Op.LINE_PERP.shares and Op.SIMILAR_IMAGE.shares
    assert not Op.CIRCLE_CIRCLE.shares
    assert "shared" not in Op.LINE_PERP.inputs


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_shared_parts_give_the_same_bits(path):
    once, ev = _values(path, True)
    again, _ = _values(path, False)
    for sid in once:
        assert np.array_equal(once[sid], again[sid], equal_nan=True), sid
    normals = [k for k in ev.shared if k[0] == "normal"]
    perps = [s for s in ev.construction.steps.values()
             if s.op is Op.LINE_PERP and s.id in ev.values]
    assert len(normals) <= len(perps)
    if perps:
        # the acceleration plan draws its lines ⊥ the same links as the velocity plan
        assert len(normals) < len(perps)
