"""A five-bar with two cranks and friction: the force sheet carries the machine's η(φ1) under its
own title; the protocol writes the second crank's friction-free M_b4⁰ in every language."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from mechplan.construct.protocol import protocol
from mechplan.i18n import catalogue, message
from mechplan.model.plans import Plan
from mechplan.scene import parse_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "dynamics"))
from test_friction_two_drivers import _five_text


@pytest.fixture(scope="module")
def five():
    text = _five_text().replace("[friction]\n", "[friction]\ndiagram = true\n")
    return solve(parse_scene(text, "five.toml"))


def test_the_machines_efficiency_is_drawn(five):
    comp = compose(five, "A1", "iso", "en", name="five")
    panels = [panel for placed in comp.placements for panel, _ in placed]
    eta = [p for p in panels if p.name == "force-diagram-eta"]
    assert len(eta) == 1
    title = message("frictionw2.diagram.efficiency", "en")
    texts = [str(getattr(item, "string", "")) for item in eta[0].primitives]
    assert any(title[:40] in t for t in texts), texts[:5]
    fr = five.extras["forces"].friction
    assert fr.second is not None and np.isfinite(fr.efficiency).sum() >= 4


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_protocol_writes_the_second_cranks_friction_free_moment(five, lang):
    steps = protocol(five.construction, five.ev, 0, lang, {Plan.FORCE: 2.0}, (Plan.FORCE,))
    found = [s for _, label, s in steps if label == "M_b4⁰"]
    assert len(found) == 1 and "{" not in found[0]
    assert found[0].startswith(catalogue(lang)["protocol.op.friction_free"].split("{")[0])
