"""Machine dynamics of scenes: dJ/dφ, reduced moments, trapezoid works, study output, errors."""

from __future__ import annotations

import itertools
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from mechplan.dynamics.cycle import MachineCycle
from mechplan.dynamics.loading import Loading
from mechplan.dynamics.machine import machine_dynamics
from mechplan.dynamics.reduced import reduced_of
from mechplan.errors import SceneError
from mechplan.scene import parse_scene
from mechplan.scene.document import parse_toml
from mechplan.scene.dynamics import parse_dynamics
from mechplan.solve import build, crank_positions
from mechplan.studies import solve_text

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
ENGINE = (TEMPLATES / "machine_unit.toml").read_text(encoding="utf-8")
SHAPER = (TEMPLATES / "shaper_flywheel.toml").read_text(encoding="utf-8")


def _setup(text: str):
    scene = parse_scene(text, "t.toml")
    spec = parse_dynamics(parse_toml(text, "t.toml"), "t.toml", scene.mechanism)
    _, c = build(scene, ("position", "velocity"))
    phi = crank_positions(scene, c)
    return scene, spec, phi


def test_dJ_matches_finite_differences():
    scene, spec, phi = _setup(SHAPER)
    mc = MachineCycle(scene, spec, float(phi[0]))
    theta = np.linspace(0.05, 2 * math.pi - 0.05, 37)
    h = 1e-5
    fd = (mc.evaluate(theta + h).J_red - mc.evaluate(theta - h).J_red) / (2 * h)
    np.testing.assert_allclose(mc.evaluate(theta).dJ_red, fd, rtol=1e-6, atol=1e-8)


def test_reduced_moment_agrees_with_the_velocity_plans_at_drawn_positions():
    """Over the first turn M_given equals the power route of the kinetostatics (reduced_of)."""
    scene, spec, phi = _setup(SHAPER)
    mc = MachineCycle(scene, spec, float(phi[0]))
    st = mc.evaluate(np.mod(phi - phi[0], 2 * math.pi))
    loading = Loading.from_scene(scene)
    _, c = build(scene, ("position", "velocity", "acceleration", "force"), loading)
    ev = c.evaluate(phi)
    m_red, j_red = reduced_of(c, ev, scene.mechanism, loading)
    np.testing.assert_allclose(st.M_given, m_red * np.sign(scene.mechanism.drive.omega),
                               rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(st.J_red, j_red, rtol=1e-12)


def test_engine_cycle_balances_and_trapezoids_converge():
    scene, spec, phi = _setup(ENGINE)
    errors = []
    for n in (12, 24, 48, 96):
        d = machine_dynamics(scene, replace(spec, dense=2880), float(phi[0]), n)
        errors.append(abs(d.A_d_drawn[-1] - d.A_d[-1]) / d.A_d[-1])
        assert d.A_d[-1] == pytest.approx(d.A_c[-1], rel=1e-12)     # balanced cycle
        assert d.M_const == pytest.approx(d.A_d[-1] / (4 * math.pi), rel=1e-12)
    assert all(a > b for a, b in itertools.pairwise(errors)) and errors[-1] < 0.01
    assert d.delta_exact == pytest.approx(spec.delta, rel=1e-9)
    assert d.ext.omega_max > d.omega_m > d.ext.omega_min


def test_study_json_and_report():
    study = solve_text(ENGINE, "machine_unit.toml")
    doc = study.to_json()["dynamics"]
    fw = doc["flywheel"]
    assert doc["cycle_deg"] == pytest.approx(720.0) and len(doc["positions"]) == 25
    assert fw["exact"]["delta_actual"] == pytest.approx(1 / 80, rel=1e-9)
    assert fw["wittenbauer"]["J"] == pytest.approx(fw["exact"]["J"], rel=0.01)
    assert fw["merkalov"]["J"] == pytest.approx(fw["exact"]["J"], rel=0.01)
    assert doc["scales"]["mu_A"] == pytest.approx(
        doc["scales"]["mu_M"] * doc["scales"]["mu_phi"] * doc["scales"]["H_mm"])
    assert "Мерцалов" in study.report("ru") and "梅尔察洛夫" in study.report("zh")
    # Merkalov's law of motion: its spread is δ·ω_m about ω_m by construction, and it is close to
    # (but not the same as) the exact motion with Merkalov's flywheel
    merk, w_m, delta = fw["merkalov"], doc["omega_m"], doc["delta"]
    assert merk["omega_max"] - merk["omega_min"] == pytest.approx(delta * w_m, rel=1e-9)
    assert 0.5 * (merk["omega_max"] + merk["omega_min"]) == pytest.approx(w_m, rel=1e-12)
    assert 0.0 < merk["omega_error_max"] < 0.5 * delta * w_m
    om = [p["omega_merkalov"] for p in doc["positions"]]
    assert min(om) >= merk["omega_min"] - 1e-12 and max(om) <= merk["omega_max"] + 1e-12
    assert "Мерцалову" in study.report("ru")
    sheets = study.sheets("A1", "gost", "vi", "machine_unit")
    assert any(s.name.endswith("-dynamics") for s in sheets)


@pytest.mark.parametrize(("old", "new", "key"), [
    ('delta = "1/80"', 'delta = "0"', "dynamics.delta"),
    ('delta = "1/80"', 'delta = "1.5"', "dynamics.delta"),
    ('unknown = "resisting"', 'unknown = "driving"', "dynamics.unknown"),
    ('unknown = "resisting"', 'unknown = "resisting"\nconstant_moment = "50 N*m"',
     "dynamics.constant_moment"),
    ('exhaust = [["0 mm", "0.11 MPa"], ["150 mm", "0.11 MPa"]]',
     'exhaust = [["0 mm", "0.11 MPa"], ["100 mm", "0.11 MPa"]]',
     "dynamics.indicator.strokes.exhaust"),
])
def test_bad_input_names_the_key(old, new, key):
    assert old in ENGINE
    with pytest.raises(SceneError) as err:
        solve_text(ENGINE.replace(old, new), "bad.toml")
    assert f"'{key}'" in str(err.value)


def test_crank_angle_indicator_must_cover_the_cycle_and_be_periodic():
    head = ENGINE[:ENGINE.index("[dynamics.indicator.strokes]")]
    good = head + ('table = [["0 deg", "0.1 MPa"], ["180 deg", "0.1 MPa"], ["360 deg", "1.2 MPa"], '
                   '["370 deg", "3 MPa"], ["540 deg", "0.3 MPa"], ["720 deg", "0.1 MPa"]]\n')
    d = solve_text(good, "ok.toml").to_json()["dynamics"]
    assert d["cycle_deg"] == pytest.approx(720.0)
    short = good.replace('"720 deg", "0.1 MPa"', '"600 deg", "0.1 MPa"')
    with pytest.raises(SceneError, match="cover the cycle") as err:
        solve_text(short.replace('unknown = "resisting"',
                                 'unknown = "resisting"\ncycle = "720 deg"'), "bad.toml")
    assert "'dynamics.indicator.table'" in str(err.value)
    jump = good.replace('["720 deg", "0.1 MPa"]', '["720 deg", "0.5 MPa"]')
    with pytest.raises(SceneError, match="periodic"):
        solve_text(jump.replace('unknown = "resisting"',
                                'unknown = "resisting"\ncycle = "720 deg"'), "bad.toml")


def test_both_sides_given_reports_the_net_work():
    text = ENGINE.replace('unknown = "resisting"',
                          'unknown = "resisting"\nconstant_moment = "80 N*m"')
    d = solve_text(text, "both.toml").to_json()["dynamics"]
    assert not d["constant_moment_found"] and d["constant_moment"] == pytest.approx(80.0)
    # independent: the net work is the driving work minus 80 N·m over 4π
    assert d["net_work"] == pytest.approx(d["work_driving"] - 80.0 * 4 * math.pi, rel=1e-12)


def test_resisting_table_must_cover_a_turn_and_be_periodic():
    short = SHAPER.replace('["350 deg", "2000 N"], ["360 deg", "2000 N"]]',
                           '["350 deg", "2000 N"]]')
    with pytest.raises(SceneError, match="cover the cycle") as err:
        solve_text(short, "bad.toml")
    assert "'loads[0].table'" in str(err.value)
    jump = SHAPER.replace('["360 deg", "2000 N"]]', '["360 deg", "0 N"]]')
    with pytest.raises(SceneError, match="periodic") as err:
        solve_text(jump, "bad.toml")
    assert "'loads[0].table'" in str(err.value)


def test_epsilon_is_omega_times_its_derivative():
    scene, spec, phi = _setup(SHAPER)
    d = machine_dynamics(scene, spec, float(phi[0]), len(phi))
    fd = d.omega * np.gradient(d.omega, d.theta)            # ε = dω/dt = ω·dω/dφ
    scale = float(np.abs(d.epsilon).max())
    # away from the cutting table's corners, where M (and ε) jump
    corners = np.radians([185.0, 190.0, 345.0, 350.0]) - d.phi0
    near = np.min(np.abs(np.angle(np.exp(1j * (d.theta[:, None] - corners[None, :])))), axis=1)
    keep = (near > np.radians(0.6)) & (np.arange(d.theta.size) > 2) & \
        (np.arange(d.theta.size) < d.theta.size - 3)
    assert keep.mean() > 0.98
    np.testing.assert_allclose(d.epsilon[keep], fd[keep], atol=2e-3 * scale)


def test_a_720_degree_load_table_equals_the_same_indicator():
    """The gas force given as a [[loads]] table over 720° gives the indicator's dynamics."""
    rows = [(0, 0.1), (180, 0.1), (360, 1.2), (370, 3.0), (540, 0.3), (720, 0.1)]
    head = ENGINE[:ENGINE.index("[dynamics.indicator]")]
    area = math.pi * 0.12 ** 2 / 4
    indicator = head + ('[dynamics.indicator]\npoint = "B"\ntowards = "O"\nbore = "120 mm"\n'
                        'ambient = "0.1 MPa"\ntable = [' + ", ".join(
                            f'["{a} deg", "{p} MPa"]' for a, p in rows) + "]\n")
    table = ENGINE[:ENGINE.index("[dynamics]")] + (
        '[[loads]]\ntype = "table"\npoint = "B"\ntowards = "O"\nagainst = "crank_angle"\ntable = ['
        + ", ".join(f'["{a} deg", "{(p - 0.1) * 1e6 * area} N"]' for a, p in rows) + "]\n\n"
        + head[head.index("[dynamics]"):].replace('unknown = "resisting"',
                                                  'unknown = "resisting"\ncycle = "720 deg"'))
    a = solve_text(indicator, "a.toml").to_json()["dynamics"]
    b = solve_text(table, "b.toml").to_json()["dynamics"]
    assert a["work_driving"] == pytest.approx(b["work_driving"], rel=1e-9)
    assert a["flywheel"]["exact"]["J"] == pytest.approx(b["flywheel"]["exact"]["J"], rel=1e-7)
    for pa, pb in zip(a["positions"], b["positions"], strict=True):
        assert pa["M_d"] == pytest.approx(pb["M_d"], rel=1e-9, abs=1e-9)


def test_default_pole_distance_keeps_the_work_diagram_within_60_mm():
    from mechplan.sheet.dynamics import dynamics_scales

    text = ENGINE.replace('pole_distance = "10 mm"', "")
    study = solve_text(text, "h.toml")
    sc = dynamics_scales(study.dynamics)
    tallest = float(np.abs(study.dynamics.A_d_drawn).max()) / sc.mu_A
    assert 30.0 < tallest <= 60.0 and sc.mu_A == pytest.approx(sc.mu_M * sc.mu_phi * sc.H_mm)
