"""The press template's sheets carry η(φ); its report and protocol speak of friction in every
language."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechplan.construct.protocol import protocol
from mechplan.model.plans import Plan
from mechplan.report import text_report
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def press():
    return solve(load_scene(ROOT / "templates" / "press_friction.toml"))


def test_efficiency_diagram_is_on_the_sheet_where_the_scene_asks(press):
    comp = compose(press, "A1", "iso", "en", name="press")
    names = [panel.name for placed in comp.placements for panel, _ in placed]
    assert "force-diagram-eta" in names
    fa = press.extras["forces"].friction
    # η is defined where M_b drives and lies in (0, 1) there
    eta = fa.efficiency[np.isfinite(fa.efficiency)]
    assert eta.size and np.all((eta > 0) & (eta < 1))


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_report_and_protocol_speak_of_friction(press, lang):
    text = text_report(press, lang)
    assert "M_b⁰" in text and "η" in text
    steps = protocol(press.construction, press.ev, 1, lang, {Plan.FORCE: 2.0}, (Plan.FORCE,))
    labels = {label for _, label, _ in steps}
    assert {"M_b⁰", "M^f_01", "M^f_12", "M^f_23", "F^f_03"} <= labels
    sentences = [s for _, label, s in steps if label in ("M^f_12", "F^f_03")]
    assert all("{" not in s for s in sentences)
    assert not math.isnan(float(press.extras["forces"].friction.moment[1]))
