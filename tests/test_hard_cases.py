"""Numerical stability on hard cases, each against an independently derived expectation.

Truth comes from the 40-digit loop-closure reference (``independent.mpref``) or from closed forms
written out here; mechplan's own plans are never the reference.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from independent import mpref
from scenes import SLOTTED_CRANK_PRP

from mechplan.construct.extremes import extreme_positions
from mechplan.construct.validity import MAX_CONDITION, unreachable_intervals, valid_mask
from mechplan.errors import SingularError, UnreachableError
from mechplan.geom import meet
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import build, solve

TEMPLATES = Path(__file__).resolve().parents[1] / "templates"
EPS = np.finfo(float).eps
KINEMATIC = ("position", "velocity", "acceleration")


def construction(scene):
    """The position, velocity and acceleration construction of a scene."""
    return build(scene, KINEMATIC)[1]


def evaluate(c, phi, targets=None):
    """Evaluate every result (or the given targets) at φ (rad)."""
    ev = c.evaluate(np.atleast_1d(np.asarray(phi, dtype=float)))
    ev.evaluate_all(targets if targets is not None else
                    list(c.results.values()) + [s.id for s in c if s.id.startswith("pos.")])
    return ev


def norm(v: np.ndarray) -> np.ndarray:
    return np.hypot(v[..., 0], v[..., 1])


def four_bar_text(a: float, b: float, c: float, d: float, speed: str = "10 rad/s") -> str:
    """Crank AB = a about A = (0, 0), coupler BC = b, rocker DC = c about D = (d, 0); metres."""
    return f"""
title = "four-bar"
[ground]
A = ["0 m", "0 m"]
D = ["{d!r} m", "0 m"]
[links.1]
lengths = {{ AB = "{a!r} m" }}
[links.2]
lengths = {{ BC = "{b!r} m" }}
[links.3]
lengths = {{ DC = "{c!r} m" }}
[drive]
link = "1"
speed = "{speed}"
sense = "ccw"
[assembly]
C = "left of B->D"
"""


def four_bar_reference(a, b, c, d, theta, omega=10.0) -> dict[str, np.ndarray]:
    """mpref's four-bar (C left of B→D) at the exact binary values of the data."""
    res = mpref.four_bar((0, 0), (d, 0), a, b, c, omega, theta, 1)
    return {k: np.array([float(x) for x in v]) for k, v in res.items()}


# -- slider-crank at its dead centres --------------------------------------------------------------
def _dead_centres(r: float, l: float, e: float) -> tuple[float, float]:
    """Crank angles of the outer and inner dead centres (crank and rod in line), closed form."""
    outer = math.asin(e / (l + r))              # B = (l + r)·(cos θ, sin θ) on the guide y = e
    inner = math.pi + math.asin(e / (l - r))    # B = −(l − r)·(cos θ, sin θ)
    return outer, inner


@pytest.mark.parametrize("name, r, l, e", [("slider_crank", 0.1, 0.4, 0.0),
                                           ("offset_slider_crank", 0.08, 0.3, 0.03)])
def test_slider_crank_exactly_at_dead_centres(name: str, r: float, l: float, e: float) -> None:
    scene = load_scene(TEMPLATES / f"{name}.toml")
    c = construction(scene)
    drive = c.drive
    assert drive.ref == 0.0
    thetas = np.array(_dead_centres(r, l, e))
    phi = drive.sense * thetas                  # exact: θ = 0 + sense·φ
    assert np.array_equal(drive.absolute(phi), thetas)
    ev = evaluate(c, phi)
    omega = scene.mechanism.drive.omega
    ref = mpref.reference(name, thetas)
    v_b, a_b = ev[c.results["v_B"]], ev[c.results["a_B"]]
    # the slider stops: |v_B| is zero to 1e-15 of the crank-pin speed
    assert np.all(norm(v_b) <= 1e-15 * r * abs(omega)), norm(v_b) / (r * abs(omega))
    # the acceleration is finite and exact
    assert np.all(np.isfinite(a_b))
    assert np.all(norm(a_b - ref["B"][:, 4:6]) <= 1e-14 * norm(ref["B"][:, 4:6]))
    if e == 0.0:   # central: a_B = −rω²(1 ± λ) along the guide, exactly
        lam = r / l
        assert np.allclose(a_b[:, 0], [-r * omega**2 * (1 + lam), r * omega**2 * (1 - lam)],
                           rtol=1e-14, atol=0)
    # the rod's ω and ε, against the reference, relative to rω/l and rω²/l
    for key, col, size in (("omega_2", 1, r * abs(omega) / l), ("epsilon_2", 2, r * omega**2 / l)):
        assert np.all(np.abs(ev[c.results[key]] - ref["2"][:, col]) <= 1e-14 * size), key
    # the user path accepts the dead centres (no false SingularError) ...
    solve(scene, at_deg=list(np.degrees(phi)))
    # ... and the engine's own dead-centre search lands on the closed-form angles
    found = sorted(drive.absolute(np.array([x.phi for x in extreme_positions(
        c, scene.mechanism, "B")])) % (2 * math.pi))
    assert np.allclose(found, sorted(thetas % (2 * math.pi)), rtol=0, atol=1e-12)


# -- four-bar whose transmission angle passes within 1e-6 rad of π ---------------------------------
# Crank 50, coupler 200, rocker 150 mm; the frame is chosen so that at θ = π (crank along the
# frame, |BD| = a + d at its largest) the transmission angle is π − 0.9e-6 rad: the coupler and
# the rocker are nearly in line, the meet of arcs (and of the plan lines ⊥ BC, ⊥ DC) is nearly
# tangent (parallel). It is a Grashof crank-rocker 3.5e-14 m short of the change point.
A_, B_, C_ = 0.05, 0.2, 0.15
DELTA = 0.9e-6
D_ = math.sqrt(B_**2 + C_**2 + 2 * B_ * C_ * math.cos(DELTA)) - A_
TOGGLE_THETAS = [math.pi, math.pi - 1e-7, math.pi + 1e-5, math.pi - 1e-3, 2.0]
#: directions in which the data (a, b, c, d, θ) are moved by one unit in the last place
ULP_PATTERNS = [(-1, 1, 1, -1, 0), (1, -1, -1, 1, 0), (0, 0, 0, 0, 1), (1, 1, -1, -1, -1),
                (-1, -1, 1, 1, 1)]


@pytest.fixture(scope="module")
def toggle():
    scene = parse_scene(four_bar_text(A_, B_, C_, D_), "near_toggle.toml")
    return scene, construction(scene)


def test_toggle_four_bar_reports_its_condition_number(toggle, record_property) -> None:
    scene, c = toggle
    ev = evaluate(c, [math.pi])
    cond = {sid: 1.0 / float(s[0]) for sid, s in ev.sines.items()}
    record_property("condition_number", cond)
    # the arcs meet, and the plan lines cross, at the transmission angle: 1/sin μ = 1/sin δ
    for sid in ("pos.C", "vel.C", "acc.C"):
        assert cond[sid] == pytest.approx(1.0 / math.sin(DELTA), rel=1e-3), sid
    assert cond["pos.C"] < MAX_CONDITION
    solve(scene, at_deg=[180.0])               # accepted: below the refusal threshold


def test_toggle_four_bar_is_correct_to_double_precision_conditioning(toggle) -> None:
    """Error ≤ the spread of the exact answer when the data move by one unit in the last place."""
    _, c = toggle
    ev = evaluate(c, TOGGLE_THETAS)             # φ = θ (counter-clockwise from +x)
    got = {"r": ev["pos.C"], "v": ev[c.results["v_C"]], "a": ev[c.results["a_C"]],
           "w2": ev[c.results["omega_2"]], "w3": ev[c.results["omega_3"]],
           "e2": ev[c.results["epsilon_2"]], "e3": ev[c.results["epsilon_3"]]}

    def pick(ref):
        return {"r": ref["C"][0:2], "v": ref["C"][2:4], "a": ref["C"][4:6], "w2": ref["2"][1],
                "w3": ref["3"][1], "e2": ref["2"][2], "e3": ref["3"][2]}

    worst_ratio = 0.0
    for k, theta in enumerate(TOGGLE_THETAS):
        exact = pick(four_bar_reference(A_, B_, C_, D_, theta))
        spread = dict.fromkeys(exact, 0.0)
        for pattern in ULP_PATTERNS:
            data = [x * (1 + s * EPS) for x, s in zip((A_, B_, C_, D_, theta), pattern)]
            moved = pick(four_bar_reference(*data))
            for key in exact:
                spread[key] = max(spread[key], float(np.max(np.abs(moved[key] - exact[key]))))
        for key, want in exact.items():
            err = float(np.max(np.abs(got[key][k] - want)))
            floor = 8 * EPS * float(np.max(np.abs(want)))
            assert err <= 2 * spread[key] + floor, (theta, key, err, spread[key])
            if spread[key] > floor:
                worst_ratio = max(worst_ratio, err / spread[key])
    assert worst_ratio < 1.0


def test_toggle_four_bar_keeps_its_branch_through_a_fine_sweep(toggle) -> None:
    _, c = toggle
    phi = np.concatenate((np.linspace(math.pi - 0.02, math.pi + 0.02, 40_001),
                          np.linspace(0.0, 2 * math.pi, 3_601)))
    ev = evaluate(c, phi, ["pos.C", c.results["v_C"], c.results["a_C"]])
    assert valid_mask(ev).all()
    b, cc = ev["pos.B"], ev["pos.C"]
    d = np.array([D_, 0.0])
    side = (d[0] - b[:, 0]) * (cc[:, 1] - b[:, 1]) - (d[1] - b[:, 1]) * (cc[:, 0] - b[:, 0])
    assert np.all(side > 0)                    # C stays left of B→D: no branch jump
    sweep = cc[:40_001]
    steps = norm(np.diff(sweep, axis=0))
    speed = norm(ev[c.results["v_C"]][:40_001]) / 10.0      # |dC/dθ|
    assert np.all(steps <= 1.01 * speed.max() * (0.04 / 40_000) + 1e-15)


# -- Grashof change point: singular, never a silent branch ----------------------------------------
def test_grashof_change_point_is_refused_not_guessed() -> None:
    a, b, c_, d = 0.0625, 0.25, 0.125, 0.3125         # s + l = p + q exactly in binary
    assert a + d == b + c_
    scene = parse_scene(four_bar_text(a, b, c_, d), "change_point.toml")
    with pytest.raises(SingularError) as info:
        solve(scene, at_deg=[180.0])
    err = info.value
    assert err.step == "C" and err.phi_deg == 180.0
    assert err.condition is not None and err.condition > MAX_CONDITION
    assert "condition number" in str(err)
    # the vectorised path marks the position instead of picking a branch
    c = construction(scene)
    ev = evaluate(c, np.radians([90.0, 179.0, 180.0, 181.0, 270.0]))
    assert valid_mask(ev).tolist() == [True, True, False, True, True]
    solve(scene, at_deg=[90.0, 179.0, 181.0, 270.0])


# -- a four-bar that cannot close over part of the cycle -------------------------------------------
UNREACH = (0.1, 0.15, 0.15, 0.25)   # |BD| ∈ [0.15, 0.35] but BC + CD = 0.3


def test_unreachable_interval_is_the_closed_form_one() -> None:
    a, b, c_, d = UNREACH
    start = math.acos((a * a + d * d - (b + c_) ** 2) / (2 * a * d))   # |BD| = b + c
    scene = parse_scene(four_bar_text(a, b, c_, d), "open.toml")
    with pytest.raises(UnreachableError) as info:
        solve(scene, at_deg=[180.0])
    err = info.value
    assert err.group == "II(2,3)"
    assert err.gap == pytest.approx((a + d) - (b + c_), rel=1e-14)
    assert len(err.intervals_deg) == 1
    lo, hi = np.radians(err.intervals_deg[0])
    assert abs(lo - start) <= 1e-9 and abs(hi - (2 * math.pi - start)) <= 1e-9
    (lo2, hi2), = unreachable_intervals(construction(scene), "pos.C")
    assert abs(lo2 - start) <= 1e-12 and abs(hi2 - (2 * math.pi - start)) <= 1e-12
    assert str(round(math.degrees(start), 6))[:8] in str(err)


def test_outside_the_unreachable_interval_everything_is_exact() -> None:
    a, b, c_, d = UNREACH
    start = math.acos((a * a + d * d - (b + c_) ** 2) / (2 * a * d))
    scene = parse_scene(four_bar_text(a, b, c_, d), "open.toml")
    c = construction(scene)
    # the vectorised path: NaN-free and valid outside, marked inside
    phi = np.linspace(-start + 1e-6, start - 1e-6, 2001)
    inside = np.linspace(start + 1e-6, 2 * math.pi - start - 1e-6, 501)
    ev = evaluate(c, np.concatenate((phi, inside)))
    mask = valid_mask(ev)
    assert mask[:2001].all() and not mask[2001:].any()
    assert np.isfinite(ev[c.results["a_C"]][:2001]).all()
    assert np.isnan(ev["pos.C"][2001:]).all()
    # against the 40-digit reference at regular positions outside the interval
    thetas = np.linspace(-start + 0.05, start - 0.05, 13)
    ev = evaluate(c, thetas)
    ref = [four_bar_reference(a, b, c_, d, float(t)) for t in thetas]
    for key, col, point in (("pos.C", 0, "C"), (c.results["v_C"], 2, "C"),
                            (c.results["a_C"], 4, "C")):
        want = np.array([r[point][col:col + 2] for r in ref])
        assert np.max(norm(ev[key] - want)) <= 1e-13 * np.max(norm(want)), key
    for key, link, col in (("omega_3", "3", 1), ("epsilon_3", "3", 2), ("epsilon_2", "2", 2)):
        want = np.array([r[link][col] for r in ref])
        assert np.max(np.abs(ev[c.results[key]] - want)) <= 1e-13 * np.max(np.abs(want)), key
    solve(scene, at_deg=list(np.degrees(thetas)))


# -- micrometres and kilometres --------------------------------------------------------------------
@pytest.mark.parametrize("name", ["four_bar", "shaper"])
def test_same_mechanism_in_micrometres_and_kilometres_scales_exactly(name: str) -> None:
    text = (TEMPLATES / f"{name}.toml").read_text(encoding="utf-8")
    assert ' mm"' in text
    phi = np.linspace(0.0, 2 * math.pi, 37)
    out = {}
    for unit, k in (("mm", 1e-3), ("um", 1e-6), ("km", 1e3)):
        scene = parse_scene(text.replace(' mm"', f' {unit}"'), f"{name}_{unit}.toml")
        c = construction(scene)
        ev = evaluate(c, phi)
        out[unit] = (k, c, ev)
        solve(scene, at_deg=[17.0, 200.0])
    k0, c0, ev0 = out["mm"]
    for unit in ("um", "km"):
        k, c, ev = out[unit]
        assert set(c.steps) == set(c0.steps)
        for sid, step in c.steps.items():
            if sid not in ev0.values or step.kind.value == "line":
                continue
            got, want = ev[sid], ev0[sid]
            is_length = sid.startswith(("pos.", "vel.", "acc.")) and step.kind.value == "point"
            if is_length:
                got, want = got / k, want / k0
            size = np.max(np.abs(want))
            if size == 0.0:
                assert np.all(got == 0.0), sid
                continue
            assert np.max(np.abs(got - want)) <= 1e-14 * size, (unit, sid)
        for sid, sine in ev0.sines.items():   # conditioning does not depend on the unit
            assert np.allclose(ev.sines[sid], sine, rtol=1e-12, atol=1e-15), sid


# -- near-parallel line meets ----------------------------------------------------------------------
@pytest.mark.parametrize("alpha", [1e-2, 1e-5, 1e-8, 1e-11])
def test_line_meet_reports_its_conditioning_and_is_accurate(alpha: float) -> None:
    """Two lines at angle α: the reported sine is sin α, the point is right to ε·cond."""
    from fractions import Fraction as F
    beta = 0.7
    p1 = np.array([[0.3, -0.2]])
    u1 = np.array([[math.cos(beta), math.sin(beta)]])
    u2 = np.array([[math.cos(beta + alpha), math.sin(beta + alpha)]])
    p2 = np.array([[0.3 + 0.05 * u2[0, 0], -0.2 + 0.05 * u2[0, 1]]]) + [[0.0, 1e-3]]
    point, _, sine = meet.line_line(p1, u1, p2, u2)
    assert sine[0] == pytest.approx(math.sin(alpha), rel=10 * EPS / alpha)
    # the exact meet of the lines the floats define, in rational arithmetic
    P1, U1, P2, U2 = ([F(x) for x in v[0]] for v in (p1, u1, p2, u2))
    s = U1[0] * U2[1] - U1[1] * U2[0]
    t = ((P2[0] - P1[0]) * U2[1] - (P2[1] - P1[1]) * U2[0]) / s
    exact = np.array([float(P1[0] + t * U1[0]), float(P1[1] + t * U1[1])])
    cond = 1.0 / sine[0]
    size = max(norm(exact), norm(p1[0]), norm(p2[0]))
    assert norm(point[0] - exact) <= 4 * EPS * cond * size


SLOTTED = SLOTTED_CRANK_PRP


def test_near_parallel_guides_refused_above_threshold_accurate_below() -> None:
    """Slotted crank (PRP): K = slot ∩ guide y = h, x = h·cot θ; the lines cross at angle θ."""
    scene = parse_scene(SLOTTED, "slotted.toml")
    c = construction(scene)
    h, omega = 0.05, 5.0
    # above the threshold (cond 1e9 > 1e8): refused, naming the meet and its conditioning
    with pytest.raises(SingularError) as info:
        solve(scene, at_deg=[math.degrees(1e-9)])
    assert info.value.step == "K"
    assert info.value.condition == pytest.approx(1e9, rel=1e-6)
    # ... and the threshold is the caller's: the same position with a looser one is accepted
    solve(scene, at_deg=[math.degrees(1e-9)], max_condition=1e10)
    # below it: reported conditioning 1/sin θ and results to rounding, against the closed form
    theta = np.array([1e-5, 1e-3, 0.3, 2.0, math.pi - 1e-4])
    ev = evaluate(c, theta)
    for sid in ("pos.K", "vel.K", "acc.K"):
        assert np.allclose(ev.sines[sid], np.abs(np.sin(theta)), rtol=1e-9, atol=0), sid
    assert valid_mask(ev).all()
    s, co = np.sin(theta), np.cos(theta)
    x = h * co / s
    vx = -h * omega / s**2
    ax = 2 * h * omega**2 * co / s**3
    cond = 1.0 / np.abs(s)
    for key, want in (("pos.K", x), (c.results["v_K"], vx), (c.results["a_K"], ax)):
        got = ev[key]
        assert np.all(np.abs(got[:, 0] - want) <= 16 * EPS * cond * np.abs(want)), key
    assert np.allclose(ev["pos.K"][:, 1], h, rtol=4 * EPS, atol=0)
    assert np.all(np.abs(ev[c.results["v_K"]][:, 1]) <= 16 * EPS * cond * np.abs(vx))
    solve(scene, at_deg=list(np.degrees(theta)))


# -- ω1 over twelve decades ------------------------------------------------------------------------
def test_velocities_scale_with_omega_and_accelerations_with_omega_squared() -> None:
    text = (TEMPLATES / "shaper.toml").read_text(encoding="utf-8")
    assert 'speed = "10 rad/s"' in text
    phi = np.linspace(0.0, 2 * math.pi, 25)
    runs = {}
    for w in (1e-6, 1e-3, 1.0, 1e3, 1e6):
        scene = parse_scene(text.replace('speed = "10 rad/s"', f'speed = "{w!r} rad/s"'))
        assert scene.mechanism.drive.omega == w
        c = construction(scene)
        runs[w] = (c, evaluate(c, phi))
        solve(scene, at_deg=[30.0])
    c1, ev1 = runs[1.0]
    for w, (c, ev) in runs.items():
        for key, sid in c.results.items():
            sym = key.split("_")[0]
            power = {"angle": 0, "v": 1, "omega": 1, "a": 2, "epsilon": 2}[sym]
            got, want = ev[sid] / w**power, ev1[c1.results[key]]
            if power == 0:
                assert np.array_equal(got, want), key        # positions do not depend on ω
                continue
            size = np.max(np.abs(want))
            assert np.max(np.abs(got - want)) <= 1e-14 * size, (w, key)
        for sid in c.steps:
            if sid.startswith("pos.") and sid in ev.values:
                assert np.array_equal(ev[sid], ev1[sid], equal_nan=True), sid
