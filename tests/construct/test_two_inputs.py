"""W = 2: a five-bar with two cranks (``[drive2]``), against an independent loop closure.

Golden values: the loop closure B(θ1) + l2·e(θ2) = D(θ4) + l3·e(θ3) solved by scipy at times
t = 0, ±h, ±2h, with each crank moving by its own law θ(t) = θ0 + ω·t + ε·t²/2; velocities and
accelerations by finite differences in time. Nothing of mechplan's construction is used.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechplan.errors import TopologyError
from mechplan.model.structure import analyse
from mechplan.scene.loader import parse_scene
from mechplan.solve import solve

TEMPLATE = Path(__file__).parents[2] / "src/mechplan/templates/five_bar_two_cranks.toml"
A, E = np.array([0.0, 0.0]), np.array([0.150, 0.0])
L1, L2, L3, L4 = 0.060, 0.200, 0.180, 0.080
W1, W4 = 10.0, -10.0          # ccw, cw (rad/s, + counter-clockwise)
EPS1, EPS4 = 4.0, -7.0        # the test scene's ε1 (ccw) and ε4 (cw), rad/s²


def _scene(eps: bool = True):
    text = TEMPLATE.read_text(encoding="utf-8")
    if eps:
        text = text.replace('sense = "ccw"\n', 'sense = "ccw"\nepsilon = "4 rad/s^2"\n', 1)
        text = text.replace('phase = "90 deg"\n', 'phase = "90 deg"\nepsilon = "7 rad/s^2"\n')
    return parse_scene(text, str(TEMPLATE))


def _e(a: float) -> np.ndarray:
    return np.array([math.cos(a), math.sin(a)])


def _closure(phi1: float, t: float, guess: np.ndarray) -> np.ndarray:
    """(θ2, θ3, θ1, θ4) at time t from the position φ1 (rad)."""
    th1 = phi1 + W1 * t + EPS1 * t * t / 2
    # crank 4: φ4 = 90° + φ1 measured clockwise from −x, then its own law in time
    th4 = math.pi - (math.pi / 2 + phi1) + W4 * t + EPS4 * t * t / 2
    b, d = A + L1 * _e(th1), E + L4 * _e(th4)

    def f(x):
        return b + L2 * _e(x[0]) - d - L3 * _e(x[1])

    x = fsolve(f, guess, xtol=1e-13)
    assert np.abs(f(x)).max() < 1e-14
    return np.array([x[0], x[1], th1, th4])


def _guess(phi1: float) -> np.ndarray:
    """A start on the scene's assembly: C left of B→D, at the two lengths (crudely)."""
    th1, th4 = phi1, math.pi - (math.pi / 2 + phi1)
    b, d = A + L1 * _e(th1), E + L4 * _e(th4)
    m, u = (b + d) / 2, (d - b) / np.linalg.norm(d - b)
    c = m + 0.15 * np.array([-u[1], u[0]])
    return np.array([math.atan2(*(c - b)[::-1]), math.atan2(*(c - d)[::-1])])


def _golden(phi1: float, h: float = 2e-4):
    x0 = _closure(phi1, 0.0, _guess(phi1))
    xs = {k: _closure(phi1, k * h, x0[:2]) for k in (-2, -1, 1, 2)}
    xs[0] = x0
    # five-point stencils (error O(h⁴))
    d1 = (xs[-2] - 8 * xs[-1] + 8 * xs[1] - xs[2]) / (12 * h)
    d2 = (-xs[-2] + 16 * xs[-1] - 30 * xs[0] + 16 * xs[1] - xs[2]) / (12 * h * h)
    c = A + L1 * _e(x0[2]) + L2 * _e(x0[0])

    def point(x):
        return A + L1 * _e(x[2]) + L2 * _e(x[0])
    vc = (point(xs[-2]) - 8 * point(xs[-1]) + 8 * point(xs[1]) - point(xs[2])) / (12 * h)
    ac = (-point(xs[-2]) + 16 * point(xs[-1]) - 30 * point(xs[0]) + 16 * point(xs[1])
          - point(xs[2])) / (12 * h * h)
    return x0, d1, d2, c, vc, ac


def test_structure_formula_lists_both_cranks():
    st = analyse(_scene().mechanism)
    assert st.dof == 2
    assert st.formula == "I(0,1), I(0,4) → II(2,3)"


ANGLES = [0.0, 40.0, 95.0, 180.0, 250.0, 315.0]


@pytest.mark.parametrize("deg", ANGLES)
def test_kinematics_equal_the_loop_closure(deg):
    sol = solve(_scene(), at_deg=[deg], plans=("position", "velocity", "acceleration"))
    c, ev = sol.construction, sol.ev
    x0, d1, d2, pc, vc, ac = _golden(math.radians(deg))
    for link, i in (("2", 0), ("3", 1), ("4", 3)):
        assert math.remainder(ev[c.link_angle(link)][0] - x0[i], 2 * math.pi) == pytest.approx(
            0.0, abs=1e-12)
        assert ev[c.omega(link)][0] == pytest.approx(d1[i], rel=1e-8, abs=1e-8)
        assert ev[c.epsilon(link)][0] == pytest.approx(d2[i], rel=1e-6, abs=1e-5)
    np.testing.assert_allclose(ev[c.position("C")][0], pc, atol=1e-13)
    np.testing.assert_allclose(ev[c.velocity_image("C")][0], vc, rtol=0, atol=1e-9)
    np.testing.assert_allclose(ev[c.acceleration_image("C")][0], ac, rtol=0, atol=1e-5)


def test_the_second_crank_is_a_step_of_its_own_with_its_sentence():
    from mechplan.construct.ops import Op

    sol = solve(_scene(), at_deg=[30.0])
    c = sol.construction
    steps = [s for s in c if s.op is Op.SECOND_CRANK_ANGLE]
    assert len(steps) == 1 and steps[0].group == "I(0,4)"
    # φ4 = 90° + 30° clockwise from −x → θ4 = 180° − 120° = 60°
    assert math.degrees(sol.ev[c.link_angle("4")][0]) == pytest.approx(60.0, abs=1e-12)


def test_one_driver_for_a_five_bar_is_refused_naming_w():
    text = TEMPLATE.read_text(encoding="utf-8")
    head, _, tail = text.partition("[drive2]")
    tail = tail[tail.index("[assembly]"):]
    with pytest.raises(TopologyError, match=r"W = 3·4 − 2·5 = 2 .* 1 driver"):
        parse_scene(head + tail, "five.toml")


def test_a_second_driver_that_is_the_first_is_refused():
    text = TEMPLATE.read_text(encoding="utf-8").replace('link = "4"', 'link = "1"')
    with pytest.raises(Exception, match="drive2"):
        parse_scene(text, "five.toml")


def test_json_names_the_second_driver_and_its_law():
    from mechplan.solve import to_json

    doc = to_json(solve(_scene(), at_deg=[30.0]))
    assert doc["dof"] == 2 and doc["structure"] == "I(0,1), I(0,4) → II(2,3)"
    second = doc["second_driver"]
    assert second["link"] == "4" and second["rate"] == -10.0 and second["acceleration"] == -7.0
    assert second["phase"] == pytest.approx(math.pi / 2, abs=1e-15)


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_the_protocol_writes_the_second_crank_in_every_language(lang):
    from mechplan.construct.protocol import protocol
    from mechplan.i18n import has_message

    assert has_message("protocol.op.second_crank_angle", lang)
    assert has_message("check.op.second_crank_angle", lang)
    from mechplan.model.plans import Plan

    sol = solve(_scene(), at_deg=[30.0])
    lines = protocol(sol.construction, sol.ev, 0, lang, sol.scales, (Plan.POSITION,))
    second = [s for _, label, s in lines if label == "θ4"]
    assert len(second) == 1 and "60" in second[0] and "φ4" in second[0], second


# [centres] with two drivers is read (issue 30): tests/construct/test_centre_velocity.py
# (test_two_drivers_draw_what_the_centres_determine_and_name_the_rest)


@pytest.mark.parametrize(("sense1", "from1", "speed2", "sense2", "from2", "phase", "deg"), [
    ("cw", "-x", "20 rad/s", "ccw", "+y", 30.0, 40.0),
    ("ccw", "+x", "5 rad/s", "cw", "-y", -45.0, 100.0),
    ("cw", "+y", "15 rad/s", "cw", "+x", 200.0, 250.0),
])
def test_the_second_crank_follows_its_law(sense1, from1, speed2, sense2, from2, phase, deg):
    """θ2 = ref2 + s2·(phase + |ω2|/|ω1|·φ1), φ1 the scene's angle of the first crank."""
    text = TEMPLATE.read_text(encoding="utf-8")
    text = text.replace('sense = "ccw"\n', f'sense = "{sense1}"\nfrom = "{from1}"\n', 1)
    head, _, tail = text.partition("[drive2]")
    tail = (tail.replace('speed = "10 rad/s"', f'speed = "{speed2}"')
            .replace('sense = "cw"', f'sense = "{sense2}"')
            .replace('from = "-x"', f'from = "{from2}"')
            .replace('phase = "90 deg"', f'phase = "{phase} deg"'))
    sol = solve(parse_scene(head + "[drive2]" + tail, "five.toml"), at_deg=[deg],
                plans=("position", "velocity", "acceleration"))
    c, ev = sol.construction, sol.ev
    refs = {"+x": 0.0, "-x": 180.0, "+y": 90.0, "-y": -90.0}
    s1, s2 = (1 if sense1 == "ccw" else -1), (1 if sense2 == "ccw" else -1)
    ratio = float(speed2.split()[0]) / 10.0
    theta1 = refs[from1] + s1 * deg
    theta4 = refs[from2] + s2 * (phase + ratio * deg)
    for link, want in (("1", theta1), ("4", theta4)):
        got = math.degrees(ev[c.link_angle(link)][0])
        assert math.remainder(got - want, 360.0) == pytest.approx(0.0, abs=1e-11), link
    assert ev[c.omega("4")][0] == s2 * float(speed2.split()[0])
    # the dyad closes between the two pins: |BC| and |DC| hold
    b, cc, d = (ev[c.position(p)][0] for p in "BCD")
    assert np.hypot(*(cc - b)) == pytest.approx(L2, abs=1e-15)
    assert np.hypot(*(cc - d)) == pytest.approx(L3, abs=1e-15)
