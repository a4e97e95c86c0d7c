"""Driver laws by a table over time (``law = { table = … }`` / ``{ file = … }``), cubic spline.

Golden values: the laws are cubic polynomials q(t) (a not-a-knot cubic spline through their rows
is the polynomial itself), so the time of a position is the polynomial's root (brentq), the
second cylinder's length and both rates are the polynomials and their derivatives there; the
machine's angles, ω, ε come from the loop closure solved by a bracketing root-finder with
five-point finite differences in time (tests/construct/test_cylinder_second_driver.py). The
interpolation error estimate is checked against a law that is not a polynomial.
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.errors import SceneError
from mechplan.model.law import TableLaw, at_time, interpolation_error
from mechplan.scene.loader import load_scene, parse_scene
from mechplan.solve import solve, to_json

sys.path.insert(0, str(Path(__file__).parent))
from test_cylinder_second_driver import TEMPLATE, boom_angle, fd, state

KIN = ("position", "velocity", "acceleration")
T = np.arange(0.0, 8.0001, 0.5)
P4 = np.polynomial.Polynomial([2.2, 0.08, 0.004, -0.0001])     # l4(t), m
P7 = np.polynomial.Polynomial([2.7, 0.05, 0.003, -0.0002])     # l7(t), m


def rows(p, unit_mm=True) -> str:
    return ", ".join(f"[{float(t)!r}, {float(p(t) * (1000 if unit_mm else 1))!r}]" for t in T)


FIRST = 'speed = "0.1 m/s"\nacceleration = "0 m/s^2"\nrange = ["2200 mm", "3000 mm"]'
SECOND = 'speed = "0.075 m/s"\nstart = "2700 mm"'


def scene_text(first: bool = True, second: bool = True) -> str:
    text = TEMPLATE.read_text(encoding="utf-8")
    if first:
        text = text.replace(FIRST, f"law = {{ table = [{rows(P4)}] }}")
    if second:
        text = text.replace(SECOND, f"law = {{ table = [{rows(P7)}] }}")
    return text


def time_of(l4: float) -> float:
    return brentq(lambda t: P4(t) - l4, 0.0, 8.0, xtol=1e-15)


@pytest.mark.parametrize("l4_mm", [2250.0, 2500.0, 2800.0, 3000.0])
def test_two_cylinders_by_tables_equal_the_loop_closure(l4_mm):
    sol = solve(parse_scene(scene_text(), "arm.toml"), at_deg=[l4_mm], plans=KIN)
    ev, c = sol.ev, sol.construction
    t0 = time_of(l4_mm / 1000)
    d4, d7 = P4.deriv(), P7.deriv()
    assert ev["pos.q2"][0] == pytest.approx(P7(t0), abs=1e-12)
    assert ev["vel.rate"][0] == pytest.approx(d4(t0), rel=1e-11)
    assert ev["vel.rate2"][0] == pytest.approx(d7(t0), rel=1e-11)
    assert ev["acc.rate"][0] == pytest.approx(d4.deriv()(t0), rel=1e-9)
    assert ev["acc.rate2"][0] == pytest.approx(d7.deriv()(t0), rel=1e-9)

    def motion(tau):
        return state(boom_angle(P4(t0 + tau)), P7(t0 + tau))
    x, v, a = fd(motion)
    for link, i in (("2", 0), ("5", 1), ("3", 2), ("6", 3)):
        assert math.remainder(ev[c.link_angle(link)][0] - x[i], 2 * math.pi) == pytest.approx(
            0.0, abs=1e-11), link
        assert ev[c.omega(link)][0] == pytest.approx(v[i], rel=1e-8, abs=1e-10), link
        assert ev[c.epsilon(link)][0] == pytest.approx(a[i], rel=1e-5, abs=1e-8), link
    np.testing.assert_allclose(ev[c.acceleration_image("H")][0], a[4:6], rtol=0, atol=1e-7)


def test_a_table_first_driver_with_a_constant_rate_second():
    """The time from the first's table; the second at start + l̇·t (its law at constant rate)."""
    sol = solve(parse_scene(scene_text(second=False), "arm.toml"), at_deg=[2600.0], plans=KIN)
    t0 = time_of(2.6)
    assert sol.ev["pos.q2"][0] == pytest.approx(2.7 + 0.075 * t0, abs=1e-12)
    assert sol.ev["vel.rate2"][0] == 0.075

    def motion(tau):
        return state(boom_angle(P4(t0 + tau)), 2.7 + 0.075 * (t0 + tau))
    _x, v, _a = fd(motion)
    assert sol.ev[sol.construction.omega("5")][0] == pytest.approx(v[1], rel=1e-8)


def test_positions_default_to_the_tables_range_and_a_sweep_runs():
    sol = solve(parse_scene(scene_text(), "arm.toml"), plans=KIN)
    np.testing.assert_allclose(sol.phi, np.linspace(P4(0.0), P4(8.0), 5), rtol=0, atol=1e-15)
    assert np.all(np.isfinite(sol.ev[sol.construction.epsilon("5")]))


def test_a_csv_file_gives_the_same_law(tmp_path):
    text = scene_text(second=False).replace(
        f"law = {{ table = [{rows(P4)}] }}", 'law = { file = "boom.csv", units = ["s", "m"] }')
    csv = "# boom cylinder, measured\ntime, length\n" + "\n".join(
        f"{float(t)!r}, {float(P4(t))!r}" for t in T)
    (tmp_path / "boom.csv").write_text(csv, encoding="utf-8")
    (tmp_path / "arm.toml").write_text(text, encoding="utf-8")
    a = solve(load_scene(tmp_path / "arm.toml"), at_deg=[2500.0], plans=KIN)
    b = solve(parse_scene(scene_text(second=False), "arm.toml"), at_deg=[2500.0], plans=KIN)
    for sid in ("vel.rate", "acc.rate", "pos.q2"):
        assert a.ev[sid][0] == pytest.approx(b.ev[sid][0], rel=1e-12)


def test_a_law_file_outside_the_scene_folder_is_refused(tmp_path):
    inner = tmp_path / "scenes"
    inner.mkdir()
    (tmp_path / "boom.csv").write_text("0, 2200\n", encoding="utf-8")
    text = scene_text(second=False).replace(
        f"law = {{ table = [{rows(P4)}] }}", 'law = { file = "../boom.csv" }')
    (inner / "arm.toml").write_text(text, encoding="utf-8")
    with pytest.raises(SceneError) as err:
        load_scene(inner / "arm.toml")
    assert err.value.key == "drive.law.file"


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_law_file_that_is_a_fifo_is_refused_without_blocking(tmp_path):
    os.mkfifo(tmp_path / "boom.csv")
    text = scene_text(second=False).replace(
        f"law = {{ table = [{rows(P4)}] }}", 'law = { file = "boom.csv" }')
    (tmp_path / "arm.toml").write_text(text, encoding="utf-8")
    with pytest.raises(SceneError) as err:
        load_scene(tmp_path / "arm.toml")
    assert err.value.key == "drive.law.file"


@pytest.mark.parametrize(("table", "key"), [
    ("[[0, 2200], [1, 2300], [2, 2350], [3, 2300], [4, 2400]]", "drive.law"),   # turns back
    ("[[0, 2200], [1, 2300], [2, 2350], [3, 2400]]", "drive.law.table"),        # 4 rows
    ("[[0, 2200], [1, 2300], [1, 2350], [3, 2400], [4, 2500]]", "drive.law.table[2]"),
    ("[[0, 2200], [1, 2300], [2, \"x\"], [3, 2400], [4, 2500]]", "drive.law.table[2]"),
])
def test_bad_tables_are_refused_naming_the_key(table, key):
    text = TEMPLATE.read_text(encoding="utf-8").replace(FIRST, f"law = {{ table = {table} }}")
    with pytest.raises(SceneError) as err:
        parse_scene(text, "arm.toml")
    assert err.value.key == key


def test_speed_and_a_law_exclude_each_other():
    text = TEMPLATE.read_text(encoding="utf-8").replace(
        FIRST, f'speed = "0.1 m/s"\nlaw = {{ table = [{rows(P4)}] }}')
    with pytest.raises(SceneError) as err:
        parse_scene(text, "arm.toml")
    assert err.value.key == "drive.speed"


def test_json_reports_the_law_and_its_interpolation_error():
    doc = to_json(solve(parse_scene(scene_text(), "arm.toml"), at_deg=[2500.0]))
    law = doc["driver"]["law"]
    assert law["rows"] == len(T) and law["span"] == [0.0, 8.0]
    # a cubic's rows: the spline is the cubic, so the estimate is rounding only
    assert max(law["interpolation_error"].values()) < 1e-12
    assert doc["second_driver"]["law"]["rows"] == len(T)


def test_the_interpolation_error_estimate_brackets_the_true_error():
    """q(t) = 2.6 + 0.4·sin(0.3t) through 11 rows: the estimate is of the true error's size."""
    t = np.linspace(0.0, 5.0, 11)
    law = TableLaw(tuple(t), tuple(2.6 + 0.4 * np.sin(0.3 * t)))
    dense = np.linspace(0.0, 5.0, 2001)
    true = [np.max(np.abs(at_time(law, dense, 0) - (2.6 + 0.4 * np.sin(0.3 * dense)))),
            np.max(np.abs(at_time(law, dense, 1) - 0.12 * np.cos(0.3 * dense))),
            np.max(np.abs(at_time(law, dense, 2) + 0.036 * np.sin(0.3 * dense)))]
    est = interpolation_error(law)
    for e, tr in zip(est, true, strict=True):
        assert tr / 4 <= e <= tr * 4, (est, true)


def test_the_law_steps_are_written_in_every_language():
    from mechplan.construct.protocol import protocol
    from mechplan.model.plans import Plan

    sol = solve(parse_scene(scene_text(), "arm.toml"), at_deg=[2500.0])
    for lang in ("en", "ru", "vi", "zh"):
        lines = protocol(sol.construction, sol.ev, 0, lang, sol.scales,
                         (Plan.POSITION, Plan.VELOCITY))
        assert any(label == "l7" for _, label, _ in lines)
        assert any(label.startswith("l̇") for _, label, _ in lines)


def test_a_position_outside_the_table_is_refused_naming_it():
    text = scene_text().replace("[positions]\ncount = 5", '[positions]\nat = ["3100 mm"]')
    with pytest.raises(SceneError, match="3044") as err:
        parse_scene(text, "arm.toml")
    assert err.value.key == "positions.at[0]"


def test_a_law_over_the_cycle_scales_its_times_by_the_period():
    """The same law written over the cycle's fraction with period = 8 s gives the same plans."""
    cyc = ", ".join(f"[{float(t) / 8!r}, {float(P4(t) * 1000)!r}]" for t in T)
    text = scene_text(second=False).replace(
        f"law = {{ table = [{rows(P4)}] }}",
        f'law = {{ table = [{cyc}], units = ["cycle", "mm"], period = "8 s" }}')
    a = solve(parse_scene(text, "arm.toml"), at_deg=[2500.0], plans=KIN)
    b = solve(parse_scene(scene_text(second=False), "arm.toml"), at_deg=[2500.0], plans=KIN)
    for sid in ("vel.rate", "acc.rate", "pos.q2"):
        assert a.ev[sid][0] == pytest.approx(b.ev[sid][0], rel=1e-12)
    with pytest.raises(SceneError) as err:
        parse_scene(text.replace(', period = "8 s"', ""), "arm.toml")
    assert err.value.key == "drive.law.period"
