"""The optional single-zone Wiebe model: the first law over the integration, the closed-form limits
of instantaneous combustion (Otto constant-volume pressures), the polytropes before combustion, and
the scene that feeds its p(φ) to the dynamic calculation."""

from __future__ import annotations

import math

import numpy as np
import pytest
from helpers import diesel_2600

from mechplan.errors import SceneError
from mechplan.model.engine_wiebe import WiebeSpec, burnt, fuel_heat, volume, wiebe_cycle
from mechplan.scene.engine import parse_engine_scene
from mechplan.sheet.engine import _thermal_panels
from mechplan.studies.engine import EngineStudy

V_h, EPS = 1.357e-3, 17.0


@pytest.mark.parametrize("n1,n2,lam,start,duration,m", [
    (1.37, 1.26, 0.2667, 10.0, 60.0, 1.5), (1.377, 1.251, 0.28, 25.0, 45.0, 3.0),
    (1.35, 1.35, 0.0, -5.0, 80.0, 0.5)])
def test_first_law_over_the_integration(n1, n2, lam, start, duration, m):
    Q = 3000.0
    w = wiebe_cycle(V_h, EPS, lam, 88e3, 322.0, 110e3, n1, n2, Q,
                    WiebeSpec(math.radians(start), math.radians(duration), m))
    assert w.Q == Q
    # heat released = ΔU + ∮p dV, U = pV/(k − 1), the work by Simpson on the sampled pressures
    assert abs(w.residual) < 1e-7 * Q
    # the same work by the trapezoid rule over p–V (second order at 0.5°: to 1e-4)
    trap = float(np.sum((w.p[1:] + w.p[:-1]) / 2.0 * np.diff(w.V)))
    assert trap == pytest.approx(w.work, rel=1e-4)
    # before combustion the pressure is the compression polytrope through a
    before = w.phi < 2.0 * math.pi - math.radians(start)
    V_a = EPS * V_h / (EPS - 1.0)
    assert np.allclose(w.p[before], 88e3 * (V_a / w.V[before]) ** n1, rtol=1e-8)
    # the burnt fraction reaches 1 − e^(−a) at the end of combustion
    end = 2.0 * math.pi - math.radians(start) + math.radians(duration)
    assert float(burnt(end, end - math.radians(duration), w.spec)) == pytest.approx(
        1.0 - math.exp(-6.908), rel=1e-12)


@pytest.mark.parametrize("n1,n2", [(1.35, 1.35), (1.37, 1.26)])
def test_instantaneous_combustion_gives_the_constant_volume_cycle(n1, n2):
    """Burning at TDC within 0.005°: p_z from U_z − U_c = Q at V_c, i.e.
    p_z = (n2 − 1)·(Q + p_c·V_c/(n1 − 1))/V_c (for n1 = n2 = k: p_c + (k − 1)·Q/V_c), then the
    expansion polytrope to p_b = p_z/ε^n2 — the Otto cycle's closed form."""
    Q = 2500.0
    w = wiebe_cycle(V_h, EPS, 0.0, 90e3, 330.0, 110e3, n1, n2, Q,
                    WiebeSpec(0.0, math.radians(0.005), 1.5, 20.0))
    V_c = V_h / (EPS - 1.0)
    p_c = 90e3 * EPS ** n1
    p_z = (n2 - 1.0) * (Q + p_c * V_c / (n1 - 1.0)) / V_c
    assert w.peak[0] == pytest.approx(p_z, rel=2e-4)
    assert w.p[-1] == pytest.approx(p_z / EPS ** n2, rel=1e-6)
    # the cycle's work is the Otto cycle's: W = Q − (U_b − U_a)
    U_b = w.p[-1] * EPS * V_c / (n2 - 1.0)
    U_a = 90e3 * EPS * V_c / (n1 - 1.0)
    assert w.work == pytest.approx(Q - (U_b - U_a), rel=1e-6)


def test_volume_is_the_exact_slider_crank():
    lam, R = 0.27, 0.06
    L = R / lam
    F_p = V_h / (2 * R)
    phi = np.linspace(0, 4 * np.pi, 73)
    beta = np.arcsin(lam * np.sin(phi))
    x = R * (1 - np.cos(phi)) + L * (1 - np.cos(beta))
    assert np.allclose(volume(phi, V_h, EPS, lam), V_h / (EPS - 1) + F_p * x, rtol=1e-13)


SCENE = diesel_2600(engine_extra='table_step = "30 deg"', thermal_extra=(
    'combustion = "wiebe"\ncombustion_start = "{start}"\ncombustion_duration = "50 deg"\n'
    'wiebe_m = 0.8\n{extra}'))


@pytest.fixture(scope="module")
def study() -> EngineStudy:
    return EngineStudy(parse_engine_scene(SCENE.format(start="8 deg", extra=""), "w.toml"))


def test_wiebe_feeds_the_dynamic_calculation(study):
    c, spec = study.scene.cycle, study.scene.engine
    w = c.wiebe
    assert w is not None and spec.indicator.kind.value == "crank_angle"
    # the heat is the fresh charge's fuel: p_a·V_a/(R·T_a)/(1 + γ_r)/M1 kg at ξ_z·H_u
    V_a = 17.0 * spec.V_h / 16.0
    m_f = 88e3 * V_a / (8314.5 * c.T_a) / (1.0 + c.gamma_r) / c.M1
    assert w.Q * spec.V_h == pytest.approx(0.82 * 42.44e6 * m_f, rel=1e-12)
    assert fuel_heat(88e3, c.T_a, V_a, c.gamma_r, c.M1, 0.82, 42440.0, 0.0) == pytest.approx(
        w.Q * spec.V_h, rel=1e-12)
    # the dynamics' diagram work: the closed part plus the gas-exchange loop (p_a − p_r)·V_h,
    # less what the 2° steps after TDC and BDC cut off (2e-5 of the work here)
    W = study.model.diagram.work()
    expected = w.work * spec.V_h - (110e3 - 88e3) * spec.V_h
    assert W == pytest.approx(expected, rel=1e-4)
    # the exact p(φ) of the dynamics at the table angles is the integrated pressure
    t = study.table
    p_dyn = np.asarray(t.cylinders[1].p)
    for k, phi in enumerate(t.phi):
        if math.pi < phi < 3 * math.pi:
            assert p_dyn[k] == pytest.approx(np.interp(phi, w.phi, w.p), rel=1e-4)


def test_wiebe_report_json_and_panel(study):
    doc = study.to_json()["thermal"]["wiebe"]
    assert doc["start_deg"] == pytest.approx(8.0) and doc["m"] == 0.8
    assert abs(doc["residual"]) < 1e-7 * doc["Q"]
    assert doc["Q"] == pytest.approx(doc["dU"] + doc["work"], rel=1e-7)
    assert 360.0 < doc["phi_max_deg"] < 400.0
    assert "Вибе" in study.report("ru")
    names = [p.name for p in _thermal_panels(study, "zh", 1.0)]
    assert names[0] == "thermal_wiebe" and "thermal_indicator" in names


@pytest.mark.parametrize("old,new,key", [
    ('combustion_start = "8 deg"', 'combustion_start = "100 deg"', "thermal.combustion_start"),
    ('combustion_duration = "50 deg"', 'combustion_duration = "170 deg"',
     "thermal.combustion_start"),
    ("wiebe_m = 0.8", "wiebe_m = 9", "thermal.wiebe_m"),
    ('combustion = "wiebe"', 'combustion = "fast"', "thermal.combustion")])
def test_wiebe_errors(old, new, key):
    text = SCENE.format(start="8 deg", extra="")
    assert old in text
    with pytest.raises(SceneError) as e:
        parse_engine_scene(text.replace(old, new), "w.toml")
    assert key in str(e.value)
