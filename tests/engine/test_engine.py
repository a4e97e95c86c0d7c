"""Engine dynamics: the indicated-work identity, inertia torque, T·R against mechplan's
kinetostatics, multi-cylinder phases, the articulated pair, errors and the CSV."""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest
from helpers import moto

from mechplan.dynamics.engine.checks import two_mass_torque_error
from mechplan.errors import SceneError
from mechplan.scene import parse_scene

TEMPLATES = Path(__file__).resolve().parents[2] / "templates"
from mechplan.solve import solve
from mechplan.studies import solve_text
from mechplan.studies.engine import EngineStudy

R, L = 0.0235, 0.106
OMEGA = 8500 * math.pi / 30


def test_indicated_work_identity_and_inertia_mean():
    st = solve_text(moto(), "m.toml")
    ch = st.checks
    assert ch.work_error < 1e-9
    assert abs(ch.inertia_mean) < 1e-9 * ch.inertia_peak
    # the mean torque on the dense grid (trapezoids) agrees to the grid's accuracy
    assert math.isclose(st.dense.M_mean, ch.work_torque / (4 * math.pi), rel_tol=1e-4)


def test_torque_is_force_times_dx_dphi_by_finite_differences():
    st = solve_text(moto(), "m.toml")
    f = st.table.cylinders[1]
    h = 1e-6

    def x(phi):
        return R * (1 - np.cos(phi)) + L * (1 - np.sqrt(1 - (R / L * np.sin(phi)) ** 2))

    dx = (x(f.phi + h) - x(f.phi - h)) / (2 * h)
    assert np.allclose(f.M, f.P * dx, rtol=1e-7, atol=1e-6)
    # N, T, Z decompose P: T² + Z² = S² and N = S sin β
    assert np.allclose(f.T ** 2 + f.Z ** 2, f.S ** 2, rtol=1e-12)
    assert np.allclose(f.N, f.S * np.sin(f.beta), rtol=1e-12, atol=1e-9)


def _slider_crank_scene(Pk_rows, J):
    rows = ", ".join(f'["{float(d)!r} deg", "{float(v)!r} N"]' for d, v in Pk_rows)
    frac = 0.040 / 0.215                # centre of mass from the big end A: l2/L = m1/m
    return f"""
[ground]
O = ["0 mm", "0 mm"]
guides.x = {{ through = "O", angle = "0 deg" }}
[links.1]
lengths = {{ OA = "23.5 mm" }}
[links.2]
lengths = {{ AB = "106 mm" }}
points = {{ S2 = "{frac!r} of A B" }}
mass = "0.215 kg"
centre = "S2"
J = "{J!r} kg*m^2"
[links.3]
slides = {{ point = "B", on = "x" }}
mass = "0.170 kg"
[drive]
link = "1"
speed = "8500 rpm"
sense = "ccw"
from = "+x"
[[loads]]
type = "table"
point = "B"
towards = "O"
table = [{rows}]
"""


@pytest.mark.parametrize("exact", [True, False])
def test_T_R_equals_kinetostatic_balancing_moment(exact):
    """With a dynamically exact two-mass rod, T·R = −M_b of mechplan's kinetostatics."""
    m, l2 = 0.215, 0.106 * 0.040 / 0.215
    l1 = 0.106 - l2
    J = m * l1 * l2 if exact else 0.9e-3
    split = (f'rod_small_end = "40 g"\nrod_J = "{J!r} kg*m^2"' if not exact
             else 'rod_small_end = "40 g"')
    st = solve_text(moto(rod_split=split).replace('rod_small_end = "40 g"\nrod_J',
                                                  'rod_centre = "19.7209302325581 mm"\nrod_J'),
                    "m.toml")
    degs = np.arange(0.0, 720.0, 15.0)
    res = st.model.cylinder(1, np.radians(degs))
    for turn in (0, 1):
        sel = slice(24 * turn, 24 * turn + 24)
        rows = list(zip(degs[sel] - 360 * turn, res.Pk[sel]))
        sol = solve(parse_scene(_slider_crank_scene(rows, J), "sc.toml"),
                    at_deg=list(degs[sel] - 360 * turn), plans=("position", "velocity",
                                                                "acceleration", "force"))
        M_b = sol.extras["forces"].balancing_moment
        expected = res.M[sel]
        if not exact:
            expected = expected + two_mass_torque_error(st.model, np.radians(degs[sel]))
        assert np.allclose(-M_b, expected, rtol=1e-9, atol=1e-9 * np.abs(res.M).max())


def test_two_mass_error_is_reported_only_with_J():
    assert solve_text(moto(), "m.toml").checks.two_mass_dM_max is None


def test_four_cylinder_inline_phases_and_identity():
    st = solve_text(moto(engine_extra='cylinders = 4\nfiring_order = [1, 3, 4, 2]'), "m.toml")
    assert [round(math.degrees(st.model.phases[i])) for i in (1, 2, 3, 4)] == [0, 540, 180, 360]
    assert [round(math.degrees(c.throw)) for c in st.scene.engine.cylinders] == [0, 180, 180, 0]
    assert st.checks.work_error < 1e-9
    assert math.isclose(st.checks.work_torque, 4 * st.checks.work_diagram, rel_tol=1e-9)
    # ΣM is the sum of cylinder 1's curve shifted by the phases (independent shift by index)
    one = solve_text(moto(engine_extra="grid = 720"), "m.toml").dense.M_total[:-1]
    total = sum(np.roll(one, round(math.degrees(st.model.phases[i]))) for i in (1, 2, 3, 4))
    assert np.allclose(st.dense.M_total[:-1], total, rtol=1e-9, atol=1e-9)
    # the inertia torques of the first order cancel: the mean is the gas torque's
    assert abs(st.dense.M_inertia.mean()) < 1e-6 * np.abs(st.dense.M_inertia).max()


def test_v_engine_side_by_side_shares_a_pin():
    st = solve_text(moto(engine_extra='layout = "v"\ncylinders = 2\nthrows = ["0 deg", "0 deg"]\n'
                                      'banks = ["0 deg", "90 deg"]\nfiring_order = [1, 2]'),
                    "m.toml")
    assert math.degrees(st.model.phases[2]) == pytest.approx(90.0)
    q = st.table.pins[1]
    c1, c2 = st.table.cylinders[1], st.table.cylinders[2]
    assert np.allclose(q.T, c1.T + c2.T) and np.allclose(q.Z, c1.Z + c2.Z)
    assert q.K_r == pytest.approx(-2 * 0.195 * R * OMEGA ** 2)
    assert st.checks.work_error < 1e-9


def test_articulated_pair_is_exact_and_closes_its_work():
    from mechplan.studies import solve_file
    st = solve_file(TEMPLATES / "v_engine_dynamics.toml")
    assert isinstance(st, EngineStudy)
    ch = st.checks
    assert ch.work_error < 1e-9
    assert ch.pair_torque_error < 1e-9
    # master piston C from the linkage equals the closed-form slider-crank
    phi = np.radians(np.arange(0, 360, 7.0))
    state = st.model.pair.state(phi)
    R_, L_, w = 0.08, 0.248, 800 * math.pi / 30
    s = R_ * np.cos(phi) + np.sqrt(L_ ** 2 - (R_ * np.sin(phi)) ** 2)
    assert np.allclose(state.C[:, 0], s, atol=1e-12)
    f = st.model.cylinder(1, phi)
    assert np.allclose(-state.a_C[:, 0], f.a, rtol=1e-9, atol=1e-9 * w * w * R_)
    # articulated stroke differs from 2R; the work scales with it
    assert st.model.stroke_of(2) != pytest.approx(2 * R_, rel=1e-3)


def test_csv_round_trip():
    st = solve_text(moto(), "m.toml")
    rows = list(csv.DictReader(io.StringIO(st.to_csv())))
    doc = st.to_json()
    assert len(rows) == len(doc["angles"]) == 49
    for r, a in zip(rows, doc["angles"]):
        assert float(r["phi_deg"]) == pytest.approx(a["phi_deg"])
        assert float(r["T_kN_1"]) * 1e3 == pytest.approx(a["cylinders"]["1"]["T"], rel=1e-8,
                                                         abs=1e-9)
        assert float(r["M_total_Nm"]) == pytest.approx(a["M_total"], rel=1e-8, abs=1e-9)


@pytest.mark.parametrize(("edit", "pattern"), [
    (('rod_length = "106 mm"', 'rod_length = "20 mm"'),
     r"engine\.rod_length.*λ = R/L must be less than 1"),
    (('rod_length = "106 mm"', 'lambda = 1.2'), r"engine\.lambda.*between 0 and 1"),
    (('rod = "215 g"', 'rod = "30 g"'), r"masses\.rod_small_end.*cannot be split"),
    (('rod_small_end = "40 g"', 'rod_centre = "200 mm"'), r"masses\.rod_centre.*cannot be split"),
    (('p0 = "100 kPa"', 'p0 = "-1 kPa"'), r"engine\.p0.*must not be negative"),
])
def test_errors_name_the_key(edit, pattern):
    with pytest.raises(SceneError, match=pattern):
        solve_text(moto().replace(*edit), "e.toml")


def test_firing_order_must_list_every_cylinder_once():
    with pytest.raises(SceneError, match=r"engine\.firing_order.*every cylinder 1…4 exactly once"):
        solve_text(moto(engine_extra='cylinders = 4\nfiring_order = [1, 3, 3, 2]'), "e.toml")
    with pytest.raises(SceneError, match=r"engine\.firing_order.*does not fit"):
        solve_text(moto(engine_extra='cylinders = 2\nthrows = ["0 deg", "0 deg"]\n'
                        'firing_order = [1, 2]\nstrokes = 2').replace("strokes = 4\n", ""),
                   "e.toml")


def test_articulated_pair_torque_equals_kinetostatic_balancing_moment():
    """The whole master/articulated linkage through mechplan's force plans: −M_b = M1 + M2."""
    from mechplan.studies import solve_file
    st = solve_file(TEMPLATES / "v_engine_dynamics.toml")
    m = st.model
    degs = np.arange(0.0, 720.0, 20.0)
    phi = np.radians(degs)
    c1, c2 = m.cylinder(1, phi), m.cylinder(2, phi)
    text = _linkage_text(st)
    for turn in (0, 1):
        sel = (degs >= 360 * turn) & (degs < 360 * (turn + 1))
        d = degs[sel] - 360 * turn

        def table(values, d=d):
            return ", ".join(f'["{float(a)!r} deg", "{float(v)!r} N"]' for a, v in zip(d, values))

        scene = text + f"""
[[loads]]
type = "table"
point = "C"
towards = "A"
table = [{table(c1.Pk[sel])}]
[[loads]]
type = "table"
point = "E"
towards = "A"
table = [{table(c2.Pk[sel])}]
"""
        sol = solve(parse_scene(scene, "pair.toml"), at_deg=list(d),
                    plans=("position", "velocity", "acceleration", "force"))
        M_b = sol.extras["forces"].balancing_moment
        total = c1.M[sel] + c2.M[sel]
        assert np.allclose(-M_b, total, rtol=1e-8, atol=1e-8 * np.abs(total).max())


def _linkage_text(st):
    """The generated linkage scene with the reciprocating masses on the pistons (rods massless)."""
    spec, m = st.scene.engine, st.model
    art = spec.articulated
    CD = math.sqrt(spec.L ** 2 + art.lug_radius ** 2
                   - 2 * spec.L * art.lug_radius * math.cos(art.lug_angle))
    bank = math.degrees(spec.cylinders[1].bank)
    side = "left" if math.sin(math.radians(bank)) > 0 else "right"
    return f"""
[ground]
A = ["0 mm", "0 mm"]
guides.Ax = {{ through = "A", angle = "0 deg" }}
guides.Ay = {{ through = "A", angle = "{bank!r} deg" }}
[links.1]
lengths = {{ AB = "80 mm" }}
[links.2]
lengths = {{ BC = "248 mm", BD = "62 mm", CD = "{CD * 1e3!r} mm" }}
side = {{ D = "{side} of B->C" }}
[links.3]
slides = {{ point = "C", on = "Ax" }}
mass = "{m.m_j[1]!r} kg"
[links.4]
lengths = {{ DE = "218 mm" }}
[links.5]
slides = {{ point = "E", on = "Ay" }}
mass = "{m.m_j[2]!r} kg"
[drive]
link = "1"
speed = "800 rpm"
sense = "ccw"
from = "Ax"
[assembly]
C = "+"
E = "+"
"""


def test_two_stroke_closes_its_work():
    st = solve_text(moto(engine_extra="strokes = 2").replace("strokes = 4\n", ""), "t.toml")
    assert st.scene.engine.cycle == pytest.approx(2 * math.pi)
    assert st.checks.work_error < 1e-9
    assert len(st.table.phi) == 25


def test_output_csv_key_writes_the_table(tmp_path):
    text = moto() + '\n[output]\ncsv = "out.csv"\n'
    st = solve_text(text, str(tmp_path / "s.toml"))
    written = (tmp_path / "out.csv").read_text(encoding="utf-8")
    assert written == st.to_csv()
    assert written.splitlines()[0].startswith("phi_deg,p_MPa_1,Pk_kN_1")


def test_wear_spreads_each_load_over_plus_minus_60_degrees():
    from mechplan.dynamics.engine.analysis import PinLoad, wear
    n = 10
    # Q towards the axis: presses the outer side
    load = PinLoad(np.zeros(n), np.full(n, 2.0), 0.0)
    rays, sums = wear(load)
    deg = np.round(np.degrees(rays)).astype(int)
    inside = (deg <= 60) | (deg >= 300)
    assert np.all(sums[inside] == 2.0 * n) and np.all(sums[~inside] == 0.0)
    # a load across the crank in the sense of rotation presses the pin at 270° (opposite side)
    rays, sums = wear(PinLoad(np.full(n, 1.0), np.zeros(n), 0.0))
    assert math.degrees(rays[np.argmax(sums)]) in (210.0, 270.0)
    assert (sums[np.round(np.degrees(rays)) == 270.0][0] == n
            and sums[np.round(np.degrees(rays)) == 90.0][0] == 0)


def test_journals_share_the_throw_load():
    st = solve_text(moto().replace('rotating_extra = "20 g"',
                                   'rotating_extra = "20 g"\ncrank = "300 g"'), "m.toml")
    t = st.table
    q = t.pins[1]
    theta = t.phi
    r = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    tt = np.stack([-np.sin(theta), np.cos(theta)], axis=1)
    W = q.T[:, None] * tt + (-(q.Z + q.K_r) + 0.3 * R * OMEGA ** 2)[:, None] * r
    assert t.journals.shape == (2, len(theta), 2)
    assert np.allclose(t.journals[0] + t.journals[1], W)
    assert np.allclose(t.journals[0], t.journals[1])


def test_cli_writes_the_per_angle_csv(tmp_path):
    from mechplan.cli import main

    out = tmp_path / "table.csv"
    assert main(["solve", str(TEMPLATES / "motorcycle_engine.toml"), "--csv", str(out)]) == 0
    rows = list(csv.reader(io.StringIO(out.read_text(encoding="utf-8"))))
    assert rows[0][0] == "phi_deg" and len(rows) > 2
    angles = [float(r[0]) for r in rows[1:]]
    assert angles[0] == 0.0 and angles == sorted(angles) and angles[-1] <= 720.0
    assert main(["solve", str(TEMPLATES / "four_bar.toml"), "--csv", str(tmp_path / "x.csv")]) == 2
    assert not (tmp_path / "x.csv").exists()
