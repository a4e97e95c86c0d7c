"""The Wiebe model of a two-stroke engine: the cycle 0 … 2π from the combustion TDC (expansion,
then compression), closed by the scavenging drop p_b → p_a after the BDC; the constant-volume
closed form of instantaneous combustion; the diagram fed to the dynamic calculation."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_wiebe import SCENE

from mechplan.errors import SceneError
from mechplan.model.engine_wiebe import BLEND, WiebeSpec, wiebe_cycle
from mechplan.scene.engine import parse_engine_scene
from mechplan.sheet.engine_thermal import wiebe_panel
from mechplan.studies.engine import EngineStudy

V_h, EPS = 1.357e-3, 17.0


def test_instantaneous_combustion_two_stroke_rows():
    """Burning at TDC within 0.005°: the two-stroke rows start at the combustion TDC with the
    constant-volume peak p_z = (n2 − 1)·(Q + p_c·V_c/(n1 − 1))/V_c (closed form), expand on
    p_z·(V_c/V)^n2 to p_b = p_z/ε^n2 at the BDC, drop to the compression polytrope within
    BLEND and end at the TDC where they began."""
    n1, n2, Q, p_a = 1.36, 1.28, 2500.0, 95e3
    w = wiebe_cycle(V_h, EPS, 0.0, p_a, 330.0, 110e3, n1, n2, Q,
                    WiebeSpec(0.0, math.radians(0.005), 1.5, 20.0), strokes=2)
    V_c = V_h / (EPS - 1.0)
    p_c = p_a * EPS ** n1
    p_z = (n2 - 1.0) * (Q + p_c * V_c / (n1 - 1.0)) / V_c
    phi = np.array([r[0] for r in w.rows])
    p = np.array([r[1] for r in w.rows])
    assert phi[0] == 0.0 and phi[-1] == pytest.approx(2.0 * math.pi, abs=1e-15)
    assert np.all(np.diff(phi) > 0.0) and p[0] == p[-1]
    assert p[0] == pytest.approx(p_c, rel=1e-8)           # combustion starts at TDC
    assert w.peak[0] == pytest.approx(p_z, rel=2e-4)
    assert 0.0 <= w.peak[1] < math.radians(1.0)           # in the two-stroke's own angle
    k_b = int(np.searchsorted(phi, math.pi))
    assert phi[k_b] == pytest.approx(math.pi) and p[k_b] == pytest.approx(p_z / EPS ** n2,
                                                                          rel=1e-6)
    # on the expansion (after combustion) every row is the polytrope through z
    V = V_c + V_h / 2.0 * (1.0 - np.cos(phi))
    exp = (phi > math.radians(0.01)) & (phi < math.pi)
    assert np.allclose(p[exp], p_z * (V_c / V[exp]) ** n2, rtol=3e-4)
    assert np.allclose(p[exp] * V[exp] ** n2, p[k_b] * V[k_b] ** n2, rtol=1e-6)
    # after the scavenging drop: the compression polytrope through a
    comp = phi >= math.pi + BLEND
    assert np.allclose(p[comp], p_a * (EPS * V_c / V[comp]) ** n1, rtol=1e-8)


@pytest.fixture(scope="module")
def study() -> EngineStudy:
    text = SCENE.format(start="8 deg", extra="").replace("[engine]\n", "[engine]\nstrokes = 2\n")
    return EngineStudy(parse_engine_scene(text, "w2.toml"))


def test_two_stroke_wiebe_feeds_the_dynamic_calculation(study):
    c, spec = study.scene.cycle, study.scene.engine
    w = c.wiebe
    assert w is not None and w.strokes == 2 and spec.strokes == 2
    # no pumping loop in a two-stroke: the diagram's work is the closed part's, less what the
    # 2° scavenging drop cuts off (≈ 1e-5 of the work)
    W = study.model.diagram.work()
    assert W == pytest.approx(w.work * spec.V_h, rel=1e-4)
    assert W != pytest.approx(w.work * spec.V_h, rel=1e-9)
    t = study.table
    p_dyn = np.asarray(t.cylinders[1].p)
    for k, phi in enumerate(t.phi):
        closed = phi + 2.0 * math.pi if phi < math.pi else phi
        if not (math.pi <= phi <= math.pi + BLEND):
            assert p_dyn[k] == pytest.approx(np.interp(closed, w.phi, w.p), rel=1e-4)
    doc = study.to_json()["thermal"]["wiebe"]
    assert 0.0 < doc["phi_max_deg"] < 40.0
    assert abs(doc["residual"]) < 1e-7 * doc["Q"]
    # the panel is drawn about the combustion TDC (−180° … 180°), φs at −8°
    panel = wiebe_panel(w, "en")
    assert panel.name == "thermal_wiebe"
    assert np.degrees(w.phi_cycle[0]) == pytest.approx(-180.0)


def test_two_stroke_wiebe_errors_name_the_key():
    text = SCENE.format(start="100 deg", extra="").replace("[engine]\n",
                                                           "[engine]\nstrokes = 2\n")
    with pytest.raises(SceneError) as e:
        parse_engine_scene(text, "w2.toml")
    assert "thermal.combustion_start" in str(e.value)
