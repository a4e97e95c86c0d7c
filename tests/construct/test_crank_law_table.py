"""A crank or rocker moving by a law by a table over time (``[drive] law`` of a crank).

Golden values: the laws are cubic polynomials φ(t) (the not-a-knot spline through their rows is
the polynomial itself), so the time of a position is the polynomial's root (brentq) and the
crank's ω, ε its derivatives there; the other links' angles come from the loop closure solved by
scipy at t, t ± h, t ± 2h and their rates from five-point finite differences in time. Nothing of
mechplan's construction is used.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq, fsolve

from mechplan.errors import SceneError
from mechplan.scene.loader import load_scene, parse_scene
from mechplan.solve import solve, to_json

KIN = ("position", "velocity", "acceleration")
ROOT = Path(__file__).parents[2] / "src/mechplan/templates"
A, D = np.array([0.0, 0.0]), np.array([0.25, 0.0])
L1, L2, L3 = 0.08, 0.26, 0.18
T = np.arange(0.0, 0.80001, 0.1)
P = np.polynomial.Polynomial([0.0, 8.0, 6.0, -1.0])        # φ1(t), rad: increasing on [0, 0.8]


def rows(p, times=T) -> str:
    return ", ".join(f"[{float(t)!r}, {math.degrees(float(p(t)))!r}]" for t in times)


FOUR_BAR = (ROOT / "four_bar.toml").read_text(encoding="utf-8")
CRANK = 'speed = "10 rad/s"\nsense = "ccw"'


def four_bar(law: str, sense: str = "ccw", start: str = "+x", positions: str = "") -> str:
    text = FOUR_BAR.replace(CRANK, f'sense = "{sense}"\nfrom = "{start}"\n{law}')
    head, _, _ = text.partition("[positions]")
    return head + (positions or "[positions]\ncount = 5\n")


def _e(a: float) -> np.ndarray:
    return np.array([math.cos(a), math.sin(a)])


def _four_bar_closure(th1: float, guess: np.ndarray) -> np.ndarray:
    b = A + L1 * _e(th1)

    def f(x):
        return b + L2 * _e(x[0]) - D - L3 * _e(x[1])

    x = fsolve(f, guess, xtol=1e-13)
    assert np.abs(f(x)).max() < 1e-14
    return x


def _guess(th1: float) -> np.ndarray:
    """C left of B→D (the template's assembly), crudely."""
    b = A + L1 * _e(th1)
    m, u = (b + D) / 2, (D - b) / np.linalg.norm(D - b)
    c = m + 0.1 * np.array([-u[1], u[0]])
    return np.array([math.atan2(*(c - b)[::-1]), math.atan2(*(c - D)[::-1])])


def fd(theta_of_t, t0: float, guess_of, closure, h: float = 1e-4):
    """Angles, first and second time derivatives at t0 by five-point stencils."""
    x0 = closure(theta_of_t(t0), guess_of(theta_of_t(t0)))
    xs = {0: x0}
    for k in (-2, -1, 1, 2):
        xs[k] = closure(theta_of_t(t0 + k * h), x0)
    d1 = (xs[-2] - 8 * xs[-1] + 8 * xs[1] - xs[2]) / (12 * h)
    d2 = (-xs[-2] + 16 * xs[-1] - 30 * xs[0] + 16 * xs[1] - xs[2]) / (12 * h * h)
    return x0, d1, d2


@pytest.mark.parametrize(("sense", "start", "ref", "s"), [
    ("ccw", "+x", 0.0, 1.0), ("cw", "-x", math.pi, -1.0)])
@pytest.mark.parametrize("deg", [20.0, 140.0, 275.0, 420.0])
def test_a_crank_by_a_table_equals_the_loop_closure(sense, start, ref, s, deg):
    scene = parse_scene(four_bar(f"law = {{ table = [{rows(P)}] }}", sense, start), "fb.toml")
    sol = solve(scene, at_deg=[deg], plans=KIN)
    c, ev = sol.construction, sol.ev
    t0 = brentq(lambda t: P(t) - math.radians(deg), 0.0, 0.8, xtol=1e-15)

    def theta(t):
        return ref + s * P(t)

    x0, d1, d2 = fd(theta, t0, _guess, _four_bar_closure)
    assert ev[c.omega("1")][0] == pytest.approx(s * P.deriv()(t0), rel=1e-12)
    assert ev[c.epsilon("1")][0] == pytest.approx(s * P.deriv(2)(t0), rel=1e-11)
    for link, i in (("2", 0), ("3", 1)):
        got = ev[c.link_angle(link)][0]
        assert math.remainder(got - x0[i], 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
        assert ev[c.omega(link)][0] == pytest.approx(d1[i], rel=1e-8, abs=1e-8)
        assert ev[c.epsilon(link)][0] == pytest.approx(d2[i], rel=1e-5, abs=1e-4)


def _sine(t):
    return 6 * t + 0.3 * np.sin(5 * t)


def test_positions_spread_over_the_table_and_json_reports_the_error_estimate():
    tt = np.linspace(0.0, 1.0, 11)
    table = ", ".join(f"[{float(t)!r}, {math.degrees(_sine(t))!r}]" for t in tt)
    doc = to_json(solve(parse_scene(four_bar(f"law = {{ table = [{table}] }}"), "fb.toml")))
    assert [p["phi_deg"] for p in doc["positions"]] == pytest.approx(
        list(np.linspace(0.0, math.degrees(_sine(1.0)), 5)), abs=1e-9)
    assert doc["driver"]["unit"] == "rad"
    est = doc["driver"]["law"]["interpolation_error"]
    # the true errors of the spline against φ = 6t + 0.3 sin 5t (rad, rad/s, rad/s²)
    spl = CubicSpline(tt, _sine(tt))
    fine = np.linspace(0.0, 1.0, 2001)
    exact = (_sine(fine), 6 + 1.5 * np.cos(5 * fine), -7.5 * np.sin(5 * fine))
    true = [np.max(np.abs(spl(fine, k) - exact[k])) for k in range(3)]
    for key, want in zip(("coordinate", "rate", "acceleration"), true, strict=True):
        assert want / 2.5 < est[key] < want * 2.5, (key, est[key], want)


def test_the_law_from_a_csv_file_equals_the_inline_table(tmp_path):
    (tmp_path / "crank.csv").write_text(
        "# t, phi\ntime_s,phi_deg\n" + "\n".join(
            f"{float(t)!r},{math.degrees(P(t))!r}" for t in T), encoding="utf-8")
    path = tmp_path / "fb.toml"
    path.write_text(four_bar('law = { file = "crank.csv", units = ["s", "deg"] }'),
                    encoding="utf-8")
    inline = solve(parse_scene(four_bar(f"law = {{ table = [{rows(P)}] }}"), "fb.toml"),
                   at_deg=[100.0], plans=KIN)
    filed = solve(load_scene(path), at_deg=[100.0], plans=KIN)
    for link in "123":
        assert filed.ev[filed.construction.epsilon(link)][0] == pytest.approx(
            inline.ev[inline.construction.epsilon(link)][0], rel=1e-13)


@pytest.mark.parametrize(("law", "extra", "key"), [
    ("law = { table = [[0, 50], [1, 40], [2, 30], [3, 20], [4, 10]] }", "", "drive.law"),
    ("law = { table = [[0, 0], [1, 40], [2, 30], [3, 60], [4, 90]] }", "", "drive.law"),
    ("law = { table = [[0, 0], [1, 10], [2, 20], [3, 30], [4, 40]] }", 'speed = "1 rad/s"',
     "drive.speed"),
    ("law = { table = [[0, 0], [1, 10], [2, 20], [3, 30], [4, 40]] }",
     '\n[positions]\nat = ["20 deg", "50 deg"]\n', "positions.at[1]"),
])
def test_refusals_name_the_key(law, extra, key):
    if extra.startswith("\n["):
        text = four_bar(law, positions=extra)
    else:
        text = four_bar(f"{law}\n{extra}")
    with pytest.raises(SceneError) as e:
        solve(parse_scene(text, "fb.toml"), plans=KIN)
    assert e.value.key == key, str(e.value)


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_the_protocol_writes_the_law_steps_in_every_language(lang):
    from mechplan.construct.protocol import protocol
    from mechplan.i18n import has_message
    from mechplan.model.plans import Plan

    assert has_message("protocol.op.crank_law", lang) and has_message("check.op.crank_law", lang)
    sol = solve(parse_scene(four_bar(f"law = {{ table = [{rows(P)}] }}"), "fb.toml"),
                at_deg=[100.0], plans=KIN)
    lines = protocol(sol.construction, sol.ev, 0, lang, sol.scales,
                     (Plan.VELOCITY, Plan.ACCELERATION))
    labels = [label for _, label, _ in lines]
    assert "ω1" in labels and "ε1" in labels


# -- W = 2: a five-bar whose cranks move by tables or at constant speed -------------------------
FIVE = (ROOT / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
E5 = np.array([0.150, 0.0])
K1, K2, K3, K4 = 0.060, 0.200, 0.180, 0.080
P4 = np.polynomial.Polynomial([0.5, 9.0, -4.0, 2.0])       # φ4(t) clockwise from −x, rad


def _five_closure(th: tuple[float, float], guess: np.ndarray) -> np.ndarray:
    b, d = A + K1 * _e(th[0]), E5 + K4 * _e(th[1])

    def f(x):
        return b + K2 * _e(x[0]) - d - K3 * _e(x[1])

    x = fsolve(f, guess, xtol=1e-13)
    assert np.abs(f(x)).max() < 1e-14
    return x


def _five_guess(th: tuple[float, float]) -> np.ndarray:
    b, d = A + K1 * _e(th[0]), E5 + K4 * _e(th[1])
    m, u = (b + d) / 2, (d - b) / np.linalg.norm(d - b)
    c = m + 0.15 * np.array([-u[1], u[0]])
    return np.array([math.atan2(*(c - b)[::-1]), math.atan2(*(c - d)[::-1])])


@pytest.mark.parametrize("which", ["first", "second", "both"])
@pytest.mark.parametrize("deg", [30.0, 95.0, 200.0])
def test_five_bar_cranks_by_tables_equal_the_loop_closure(which, deg):
    head, _, tail = FIVE.partition("[drive2]")
    if which in ("first", "both"):
        head = head.replace('speed = "10 rad/s"\nsense = "ccw"',
                            f'sense = "ccw"\nlaw = {{ table = [{rows(P)}] }}')
    if which in ("second", "both"):
        tail = tail.replace('speed = "10 rad/s"', f'law = {{ table = [{rows(P4)}] }}').replace(
            'phase = "90 deg"\n', "")
    sol = solve(parse_scene(head + "[drive2]" + tail, "five.toml"), at_deg=[deg], plans=KIN)
    c, ev = sol.construction, sol.ev
    phi = math.radians(deg)
    t0 = (brentq(lambda t: P(t) - phi, 0.0, 0.8, xtol=1e-15) if which != "second"
          else phi / 10.0)

    def phi1(t):
        return P(t) if which != "second" else 10.0 * t

    def phi4(t):
        return P4(t) if which != "first" else math.pi / 2 + 10.0 * t

    def theta(t):
        return (phi1(t), math.pi - phi4(t))

    x0, d1, d2 = fd(theta, t0, _five_guess, _five_closure)
    w4 = -10.0 if which == "first" else -P4.deriv()(t0)
    e4 = 0.0 if which == "first" else -P4.deriv(2)(t0)
    assert math.remainder(ev[c.link_angle("4")][0] - theta(t0)[1], 2 * math.pi) == pytest.approx(
        0.0, abs=1e-12)
    assert ev[c.omega("4")][0] == pytest.approx(w4, rel=1e-12)
    assert ev[c.epsilon("4")][0] == pytest.approx(e4, rel=1e-11, abs=1e-12)
    for link, i in (("2", 0), ("3", 1)):
        got = ev[c.link_angle(link)][0]
        assert math.remainder(got - x0[i], 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
        assert ev[c.omega(link)][0] == pytest.approx(d1[i], rel=1e-8, abs=1e-8)
        assert ev[c.epsilon(link)][0] == pytest.approx(d2[i], rel=1e-5, abs=1e-4)


def test_a_second_crank_with_a_table_refuses_a_phase():
    head, _, tail = FIVE.partition("[drive2]")
    tail = tail.replace('speed = "10 rad/s"', f'law = {{ table = [{rows(P4)}] }}')
    with pytest.raises(SceneError) as e:
        parse_scene(head + "[drive2]" + tail, "five.toml")
    assert e.value.key == "drive2.phase"


def test_diagrams_are_over_the_tables_time():
    """The JSON kinematic diagram's abscissa is the table's time (its spline inverted), and the
    sheet draws the output link's diagrams over it."""
    from mechplan.sheet.compose import compose

    sol = solve(parse_scene(four_bar(f"law = {{ table = [{rows(P)}] }}"), "fb.toml"))
    doc = to_json(sol)["kinematic_diagram"]
    want = [brentq(lambda t, x=x: P(t) - x, 0.0, 0.8, xtol=1e-15) for x in doc["x"]]
    assert doc["t"] == pytest.approx(want, abs=1e-12)
    comp = compose(sol, "A1", "iso", "en", name="fb")
    names = [panel.name for sheet in comp.placements for panel, _ in sheet]
    assert "diagram-kinematic" in names


ROCKER = """
title = "A four-bar driven by its rocker"
language = "en"

[ground]
A = ["0 mm", "0 mm"]
D = ["250 mm", "0 mm"]

[links.1]
lengths = { AB = "80 mm" }

[links.2]
lengths = { BC = "260 mm" }

[links.3]
lengths = { DC = "180 mm" }

[drive]
link = "3"
sense = "ccw"
law = { table = [ROWS] }

[assembly]
B = "left of A->C"
"""
R3 = np.polynomial.Polynomial([math.radians(85.0), 0.9, -0.2])     # φ3(t): 85° → 125.1° in 1 s


@pytest.mark.parametrize("deg", [88.0, 105.0, 122.0])
def test_a_rocker_by_a_table_drives_the_four_bar(deg):
    tt = np.linspace(0.0, 1.0, 11)
    table = ", ".join(f"[{float(t)!r}, {math.degrees(float(R3(t)))!r}]" for t in tt)
    sol = solve(parse_scene(ROCKER.replace("ROWS", table), "rocker.toml"), at_deg=[deg], plans=KIN)
    c, ev = sol.construction, sol.ev
    t0 = brentq(lambda t: R3(t) - math.radians(deg), 0.0, 1.0, xtol=1e-15)

    def closure(th3, guess):
        cc = D + L3 * _e(th3)

        def f(x):
            return A + L1 * _e(x[0]) + L2 * _e(x[1]) - cc

        x = fsolve(f, guess, xtol=1e-13)
        assert np.abs(f(x)).max() < 1e-14
        return x

    def guess(th3):
        cc = D + L3 * _e(th3)
        u = cc / np.linalg.norm(cc)
        b = 0.5 * L1 * u + 0.07 * np.array([-u[1], u[0]])       # left of A→C
        return np.array([math.atan2(b[1], b[0]), math.atan2(*(cc - b)[::-1])])

    x0, d1, d2 = fd(R3, t0, guess, closure)
    assert ev[c.omega("3")][0] == pytest.approx(R3.deriv()(t0), rel=1e-12)
    for link, i in (("1", 0), ("2", 1)):
        got = ev[c.link_angle(link)][0]
        assert math.remainder(got - x0[i], 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
        assert ev[c.omega(link)][0] == pytest.approx(d1[i], rel=1e-8, abs=1e-8)
        assert ev[c.epsilon(link)][0] == pytest.approx(d2[i], rel=1e-5, abs=1e-4)


def _kernel_equals_numpy(scene, q, jit, tol=1e-14, extra=()):
    from mechplan.construct.estimate import estimate_errors
    from mechplan.construct.kernel import compile_kernel
    from mechplan.solve import build, targets_for

    _, c = build(scene, KIN)
    targets = [*targets_for(scene, c, KIN), *extra]
    ev = c.evaluate(q)
    ev.evaluate_all(targets)
    est = estimate_errors(c, ev, targets)
    values, rel, bad = compile_kernel(c, targets, jit=jit)(q)
    assert not bad.any()
    for sid in targets:
        size = max(float(np.max(np.abs(ev[sid]))), est.scale[sid])
        assert np.max(np.abs(values[sid] - ev[sid])) <= tol * size, sid
        assert np.allclose(rel[sid], est.relative(sid), rtol=1e-5, atol=0), sid
    return c, ev, values


@pytest.mark.parametrize("jit", [False, True])
@pytest.mark.parametrize("which", ["four_bar", "five_bar_both", "five_bar_second"])
def test_the_fused_kernel_evaluates_the_laws_as_the_numpy_path(which, jit):
    if which == "four_bar":
        scene = parse_scene(four_bar(f"law = {{ table = [{rows(P)}] }}"), "fb.toml")
        q = np.radians(np.linspace(5.0, 500.0, 37))
    else:
        head, _, tail = FIVE.partition("[drive2]")
        if which == "five_bar_both":
            head = head.replace('speed = "10 rad/s"\nsense = "ccw"',
                                f'sense = "ccw"\nlaw = {{ table = [{rows(P)}] }}')
        tail = tail.replace('speed = "10 rad/s"', f'law = {{ table = [{rows(P4)}] }}').replace(
            'phase = "90 deg"\n', "")
        scene = parse_scene(head + "[drive2]" + tail, "five.toml")
        q = np.radians(np.linspace(5.0, 250.0, 29))
    _kernel_equals_numpy(scene, q, jit)


def test_the_fused_kernel_evaluates_linear_drivers_tables_as_the_numpy_path():
    """Two cylinders by tables (tests/construct/test_driver_law_table.py): driver_law's form."""
    import sys

    sys.path.insert(0, str(Path(__file__).parent))
    from test_driver_law_table import scene_text

    scene = parse_scene(scene_text(), "arm.toml")
    # the law's steps are bit for bit the numpy path's; the arm's ω5 (~0.01 rad/s, through two
    # groups) differs by a few ulps, as at constant rates (test_cylinder_second_driver.py)
    laws = ("pos.q2", "vel.rate", "vel.rate2", "acc.rate", "acc.rate2")
    _, ev, values = _kernel_equals_numpy(scene, np.linspace(2.21, 2.99, 27), jit=False,
                                         tol=1e-13, extra=laws)
    for sid in laws:
        assert np.array_equal(values[sid], ev[sid]), sid
