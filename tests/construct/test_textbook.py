"""Textbook answers against closed forms, finite differences and a printed textbook example."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechplan.construct.textbook import textbook_answers
from mechplan.errors import SceneError
from mechplan.model.textbook import Answer, TextbookSpec
from mechplan.scene import parse_scene
from mechplan.solve import solve

ALL = TextbookSpec(frozenset(Answer), pin_radius=0.01)


def slider_crank(r_mm: float, l_mm: float, e_mm: float = 0.0, rpm: str = "60 rad/s",
                 sense: str = "ccw", extra: str = "") -> str:
    return f"""
[ground]
O = ["0 mm", "0 mm"]
G = ["0 mm", "{e_mm} mm"]
Y = ["0 mm", "1000 mm"]
guides.x = {{ through = "G", angle = "0 deg" }}
[links.1]
lengths = {{ OA = "{r_mm} mm" }}
[links.2]
lengths = {{ AB = "{l_mm} mm" }}
[links.3]
slides = {{ point = "B", on = "x" }}
[drive]
link = "1"
speed = "{rpm}"
sense = "{sense}"
[assembly]
B = "right of O->Y"
{extra}
"""


def four_bar(a: float, b: float, c: float, d: float) -> str:
    return f"""
[ground]
A = ["0 mm", "0 mm"]
D = ["{d} mm", "0 mm"]
[links.1]
lengths = {{ AB = "{a} mm" }}
[links.2]
lengths = {{ BC = "{b} mm" }}
[links.3]
lengths = {{ DC = "{c} mm" }}
[drive]
link = "1"
speed = "10 rad/s"
[assembly]
C = "left of B->D"
"""


QUICK_RETURN = """
[ground]
O1 = ["0 mm", "0 mm"]
O3 = ["0 mm", "-300 mm"]
[links.1]
lengths = { O1A = "100 mm" }
[links.2]
slides = { point = "A", on = "slot" }
[links.3]
lengths = { O3B = "600 mm" }
guides.slot = { through = "O3", toward = "B" }
[drive]
link = "1"
speed = "10 rad/s"
"""


def answers(text: str, at: list[float], spec: TextbookSpec = ALL):
    scene = parse_scene(text)
    sol = solve(scene, at_deg=at)
    return sol, textbook_answers(sol.construction, sol.ev, scene.mechanism, sol.structure, spec)


def _abs_angle(sol, phi: float) -> float:
    return float(sol.construction.drive.absolute(np.array([phi]))[0])


# -- stroke and K --------------------------------------------------------------------------
@pytest.mark.parametrize("r, l, e", [(100, 400, 0), (100, 350, 50), (60, 250, -40)])
def test_slider_crank_stroke_and_K_closed_form(r, l, e):
    sol, t = answers(slider_crank(r, l, e), [30.0])
    (s,) = t.strokes
    r_, l_, e_ = r / 1e3, l / 1e3, e / 1e3
    H = math.sqrt((l_ + r_) ** 2 - e_ ** 2) - math.sqrt((l_ - r_) ** 2 - e_ ** 2)
    theta = abs(math.asin(e_ / (l_ - r_)) - math.asin(e_ / (l_ + r_)))
    assert s.size == pytest.approx(H, rel=1e-12)
    assert s.K == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-10)
    # the crank angles of the extremes: crank along the rod (far) and against it (near)
    far = math.atan2(e_ / (l_ + r_), math.sqrt(1 - (e_ / (l_ + r_)) ** 2))
    near = math.atan2(-e_ / (l_ - r_), -math.sqrt(1 - (e_ / (l_ - r_)) ** 2))
    assert math.remainder(_abs_angle(sol, s.phi_max) - far, 2 * math.pi) == pytest.approx(
        0, abs=1e-10)
    assert math.remainder(_abs_angle(sol, s.phi_min) - near, 2 * math.pi) == pytest.approx(
        0, abs=1e-10)
    assert s.theta_work + s.theta_return == pytest.approx(2 * math.pi)


def test_crank_rocker_swing_K_and_least_transmission_by_cosine_rule():
    a, b, c, d = 80.0, 260.0, 180.0, 250.0
    sol, t = answers(four_bar(a, b, c, d), [30.0, 200.0])
    (s,) = t.strokes
    assert s.rocker and s.subject == "3"

    def at_D(ac):        # angle ADC of triangle A-D-C (rocker from the frame line)
        return math.acos((d * d + c * c - ac * ac) / (2 * d * c))

    def at_A(ac):        # angle DAC
        return math.acos((d * d + ac * ac - c * c) / (2 * d * ac))
    psi = abs(at_D(b + a) - at_D(b - a))
    theta = abs(at_A(b + a) - at_A(b - a))
    assert s.size == pytest.approx(psi, rel=1e-10)
    assert s.K == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-9)
    # the least transmission angle: crank along the frame line, BD = d ∓ a
    mus = [math.acos((b * b + c * c - bd * bd) / (2 * b * c)) for bd in (d - a, d + a)]
    gamma_min = min(min(m, math.pi - m) for m in mus)
    phi, g = t.least_gamma["II(2,3)"]
    assert g == pytest.approx(gamma_min, abs=1e-9)
    assert math.remainder(_abs_angle(sol, phi), math.pi) == pytest.approx(0, abs=1e-6)
    # at the positions asked: μ is the angle between CB and CD
    ev = sol.ev
    B, C, D = (ev[sol.construction.position(p)] for p in "BCD")
    u, w = B - C, D - C
    mu = np.arccos(np.einsum("ij,ij->i", u, w) / np.hypot(*u.T) / np.hypot(*w.T))
    (tr,) = t.transmission
    assert np.allclose(tr.mu, mu, atol=1e-12)
    assert np.allclose(tr.gamma, np.minimum(mu, math.pi - mu), atol=1e-12)


# -- relative motion by finite differences -------------------------------------------------
def _fd(text: str, phi_deg: float, f, h: float = 1e-4):
    """First and second time derivatives of f(evaluation) at φ by central differences."""
    scene = parse_scene(text)
    sol = solve(scene, at_deg=[phi_deg])
    c = sol.construction
    w = scene.mechanism.drive.omega
    phi = math.radians(phi_deg)
    vals = [f(c, c.evaluate(np.array([phi + s * h]))) for s in (-1, 0, 1)]
    d1 = (vals[2] - vals[0]) / (2 * h) * w
    d2 = (vals[2] - 2 * vals[1] + vals[0]) / (h * h) * w * w
    return d1, d2


def test_point_pair_relative_velocity_and_components_by_finite_differences():
    text = slider_crank(100, 400, 30)
    _, t = answers(text, [37.0])
    (ba,) = [p for p in t.point_pairs if (p.p, p.q) == ("B", "A")]
    d1, d2 = _fd(text, 37.0, lambda c, ev: ev[c.position("B")][0] - ev[c.position("A")][0])
    assert np.allclose(ba.v[0], d1, rtol=1e-7, atol=1e-7 * np.hypot(*d1))
    assert np.allclose(ba.a[0], d2, atol=1e-4 * np.hypot(*d2))
    assert np.allclose(ba.a_n[0] + ba.a_t[0], ba.a[0], atol=1e-9 * np.hypot(*d2))
    assert np.dot(ba.a_n[0], ba.a_t[0]) == pytest.approx(0, abs=1e-6 * np.hypot(*d2) ** 2)


def test_coriolis_and_sliding_against_the_slider_in_the_rotating_guide():
    """s(t) = O3A·d(t); v_rel = ṡ, a_rel = s̈ along the slot, a_k = 2 ω3 ṡ (k × d)."""
    for phi in (20.0, 75.0, 140.0, 250.0):
        _, t = answers(QUICK_RETURN, [phi])
        (sl,) = t.sliding

        def s_of(c, ev):
            a, o3, b = (ev[c.position(p)][0] for p in ("A", "O3", "B"))
            return np.dot(a - o3, (b - o3) / np.hypot(*(b - o3)))

        def th3(c, ev):
            o3, b = ev[c.position("O3")][0], ev[c.position("B")][0]
            return math.atan2(b[1] - o3[1], b[0] - o3[0])
        s1, s2 = _fd(QUICK_RETURN, phi, s_of)
        w3, _ = _fd(QUICK_RETURN, phi, th3)
        assert sl.v_slide[0] == pytest.approx(s1, rel=1e-7)
        assert sl.a_slide[0] == pytest.approx(s2, rel=1e-4, abs=1e-4)
        d = sl.direction[0]
        expected = 2 * w3 * s1 * np.array([-d[1], d[0]])
        assert np.allclose(sl.a_cor[0], expected, rtol=1e-6, atol=1e-7)
        assert np.hypot(*sl.a_cor[0]) == pytest.approx(2 * abs(w3 * s1), rel=1e-6)


# -- dead centres ---------------------------------------------------------------------------
def test_dead_centres_zero_sliding_velocity_and_transmission_angle_limit():
    _, t = answers(slider_crank(100, 400), [0.0, 180.0])
    (sl,) = t.sliding
    assert np.allclose(sl.v_slide, 0.0, atol=1e-12)
    (tr,) = t.transmission
    assert np.allclose(tr.gamma, math.pi / 2, atol=1e-12)     # rod along the guide: α = 0
    # offset: at the exact extremes the slider stops and the rod lies along the crank, so the
    # pressure angle is the rod's slope asin(e/(l ± r))
    _, t = answers(slider_crank(100, 350, 50), [30.0])
    (s,) = t.strokes
    _, t2 = answers(slider_crank(100, 350, 50), [math.degrees(s.phi_min), math.degrees(s.phi_max)])
    assert np.allclose(t2.sliding[0].v_slide, 0.0, atol=1e-9)
    expected = [math.pi / 2 - math.asin(0.05 / 0.25), math.pi / 2 - math.asin(0.05 / 0.45)]
    assert np.allclose(t2.transmission[0].gamma, expected, atol=1e-9)
    # at the extreme of the swing the rocker stops: its frame pin D does not rub
    _, t = answers(four_bar(80, 260, 180, 250), [30.0])
    (sw,) = t.strokes
    _, t3 = answers(four_bar(80, 260, 180, 250), [math.degrees(sw.phi_min)])
    (d_pin,) = [r for r in t3.rubbing if r.pair.point == "D"]
    assert d_pin.v_rub[0] == pytest.approx(0.0, abs=1e-12)


# -- Khurmi & Gupta, Theory of Machines, Example 7.2 -----------------------------------------
def test_khurmi_example_7_2_rubbing_velocities_and_slowest_point():
    """Crank 0.5 m, rod 2 m, 180 rpm, 45° from the dead centre; pins Ø50 (crankshaft), Ø60
    (crank pin), Ø30 (cross-head). Printed (graphical) answers: 0.471, 0.6675, 0.051 m/s."""
    text = slider_crank(500, 2000, 0, rpm="180 rpm", extra="""
[answers]
ask = ["rubbing", "least_velocity"]
pins = { O = "25 mm", A = "30 mm", B = "15 mm" }
""")
    scene = parse_scene(text)
    sol = solve(scene, at_deg=[45.0])
    t = sol.extras["textbook"]
    w1 = 180 * 2 * math.pi / 60
    th = math.radians(45.0)
    beta = math.asin(0.5 * math.sin(th) / 2.0)
    w2 = w1 * 0.5 * math.cos(th) / (2.0 * math.cos(beta))     # |ω2|, opposite sense to ω1
    exact = {"O": w1 * 0.025, "A": (w1 + w2) * 0.030, "B": w2 * 0.015}
    printed = {"O": 0.471, "A": 0.6675, "B": 0.051}
    got = {r.pair.point: float(r.v_rub[0]) for r in t.rubbing}
    for p in "OAB":
        assert got[p] == pytest.approx(exact[p], rel=1e-12)
        assert got[p] == pytest.approx(printed[p], rel=0.01)
    # slowest point of the rod: foot of the perpendicular from I (crank line ∩ normal at B)
    A = 0.5 * np.array([math.cos(th), math.sin(th)])
    B = np.array([0.5 * math.cos(th) + 2.0 * math.cos(beta), 0.0])
    I = np.array([B[0], B[0] * math.tan(th)])
    u = (B - A) / np.hypot(*(B - A))
    G = A + np.dot(I - A, u) * u
    (lv,) = [x for x in t.least_velocity if x.link == "2"]
    assert np.allclose(lv.centre[0], I, atol=1e-12)
    assert np.allclose(lv.G[0], G, atol=1e-12)
    assert lv.v_min[0] == pytest.approx(w2 * np.hypot(*(G - I)), rel=1e-10)
    assert lv.v_min[0] <= np.hypot(*sol.ev[sol.construction.velocity_image("B")][0])


# -- what is asked, scene errors ------------------------------------------------------------
def test_only_what_is_asked_is_computed_and_said():
    plain = solve(parse_scene(slider_crank(100, 400)), at_deg=[30.0])
    assert "textbook" not in plain.extras
    from mechplan.solve import to_json
    assert "textbook" not in to_json(plain)
    text = slider_crank(100, 400, extra='[answers]\nask = ["stroke"]\n')
    sol = solve(parse_scene(text), at_deg=[30.0])
    doc = to_json(sol)
    assert set(doc["textbook"]) == {"asked", "strokes"}
    assert doc["textbook"]["strokes"]["B"]["H"] == pytest.approx(0.2, rel=1e-12)
    assert doc["positions"][0]["textbook"] == {}


@pytest.mark.parametrize("section, key", [
    ('[answers]\nask = ["speed"]\n', "answers.ask"),
    ('[answers]\nask = ["rubbing"]\npins = { Z = "5 mm" }\n', "answers.pins.Z"),
    ('[answers]\nask = ["rubbing"]\n', "answers.pin_radius"),
    ('[answers]\noutputs = ["Q"]\n', "answers.outputs"),
])
def test_scene_errors_name_the_key(section, key):
    with pytest.raises(SceneError) as exc:
        parse_scene(slider_crank(100, 400, extra=section))
    assert exc.value.key == key


def test_report_says_the_answers_in_every_language():
    from mechplan.report import text_report
    text = slider_crank(100, 350, 50, extra='[answers]\npin_radius = "10 mm"\n')
    sol = solve(parse_scene(text), at_deg=[30.0])
    for lang in ("en", "ru", "vi", "zh"):
        out = text_report(sol, lang)
        assert "K = " in out and "γ_min" in out and "v_rel" in out


def test_slowest_point_of_a_plate_by_brute_force():
    """The coupler BCE of the four-bar template is a plate: the slowest point of the triangle,
    found by sampling it densely with v = v_B + ω×BP, is the one computed."""
    from pathlib import Path

    from mechplan.scene import load_scene
    scene = load_scene(Path(__file__).resolve().parents[2] / "templates" / "four_bar.toml")
    sol = solve(scene, at_deg=[0.0, 33.0, 100.0, 250.0])
    t = textbook_answers(sol.construction, sol.ev, scene.mechanism, sol.structure,
                         TextbookSpec(frozenset({Answer.LEAST_VELOCITY})))
    (lv,) = t.least_velocity
    c, ev = sol.construction, sol.ev
    u, w = np.meshgrid(np.linspace(0, 1, 401), np.linspace(0, 1, 401))
    keep = (u + w) <= 1
    u, w = u[keep], w[keep]
    for k in range(sol.positions):
        B, C, E = (ev[c.position(p)][k] for p in "BCE")
        vB, om = ev[c.velocity_image("B")][k], ev[c.omega("2")][k]
        P = B + u[:, None] * (C - B) + w[:, None] * (E - B)
        rho = P - B
        v = vB + om * np.stack([-rho[:, 1], rho[:, 0]], axis=1)
        speed = np.hypot(*v.T)
        i = int(np.argmin(speed))
        assert lv.v_min[k] <= speed[i] + 1e-12
        assert lv.v_min[k] == pytest.approx(speed[i], abs=abs(om) * 0.3 * 2 / 400 + 1e-12)
        assert np.hypot(*(lv.G[k] - P[i])) < 0.3 * 2 / 400 * 2


def test_relative_rotation_in_the_pins_by_finite_differences():
    text = slider_crank(100, 400, 30)
    _, t = answers(text, [58.0])
    (pin_a,) = [x for x in t.turning if x.pair.point == "A"]

    def rod(c, ev):
        a, b = ev[c.position("A")][0], ev[c.position("B")][0]
        return math.atan2(b[1] - a[1], b[0] - a[0])
    w2, e2 = _fd(text, 58.0, rod)
    sign = 1.0 if pin_a.pair.a == "1" else -1.0        # ω_a − ω_b, a and b as the pair has them
    assert pin_a.omega_rel[0] == pytest.approx(sign * (60.0 - w2), rel=1e-8)
    assert pin_a.epsilon_rel[0] == pytest.approx(sign * (0.0 - e2), rel=1e-4)


OFFSET_COULISSE = QUICK_RETURN.replace(
    'guides.slot = { through = "O3", toward = "B" }',
    'points = { P = ["0 mm", "40 mm"], Q = ["600 mm", "40 mm"] }\n'
    'guides.slot = { through = "P", toward = "Q" }')


def test_offset_coulisse_transmission_angle_swing_and_K():
    """The slot 40 mm off the pivot: γ = 90° − asin(e/O3A); the extremes are where the slot
    line touches the crank circle: n·(O1 − O3) = e ± r for the slot's normal n."""
    r, d, e = 0.1, 0.3, 0.04
    sol, t = answers(OFFSET_COULISSE, [0.0, 30.0, 200.0, 270.0])
    A, O3 = (sol.ev[sol.construction.position(p)] for p in ("A", "O3"))
    expected = math.pi / 2 - np.arcsin(e / np.hypot(*(A - O3).T))
    assert np.allclose(t.transmission[0].gamma, expected, atol=1e-12)
    assert t.least_gamma["II(2,3)"][1] == pytest.approx(math.pi / 2 - math.asin(e / (d - r)),
                                                       abs=1e-9)
    (s,) = t.strokes
    alphas, cranks = [], []
    for sign in (1, -1):
        alpha = math.acos((e + sign * r) / d)          # slot direction; n = (−sin α, cos α)
        n = np.array([-math.sin(alpha), math.cos(alpha)])
        tangent = -sign * r * n                         # the crank pin where the line touches
        alphas.append(alpha)
        cranks.append(math.atan2(tangent[1], tangent[0]))
    assert s.size == pytest.approx(abs(alphas[0] - alphas[1]), rel=1e-10)
    up = (cranks[0] - cranks[1]) % (2 * math.pi)
    assert s.K == pytest.approx(max(up, 2 * math.pi - up) / min(up, 2 * math.pi - up), rel=1e-9)
    got = sorted(_abs_angle(sol, x.phi) % (2 * math.pi) for x in s.extremes)
    assert got == pytest.approx(sorted(c % (2 * math.pi) for c in cranks), abs=1e-9)


@settings(max_examples=12, deadline=None)
@given(st.floats(0.5, 3.0), st.floats(3.2, 6.0), st.floats(-0.8, 0.8), st.floats(1.5, 4.0),
       st.floats(5.0, 355.0))
def test_scaling_the_lengths_scales_what_has_a_length(r, ratio, off, s, phi):
    """Every length × s: H, v_slide, v_rub × s (same pin radius × s); γ, ψ, K unchanged."""
    r_mm, l_mm, e_mm = 20.0 * r, 20.0 * r * ratio, 20.0 * r * off
    spec = TextbookSpec(frozenset(Answer), pin_radius=0.005)
    spec_s = TextbookSpec(frozenset(Answer), pin_radius=0.005 * s)
    _, t1 = answers(slider_crank(r_mm, l_mm, e_mm), [phi], spec)
    _, t2 = answers(slider_crank(r_mm * s, l_mm * s, e_mm * s), [phi], spec_s)
    assert t2.strokes[0].size == pytest.approx(s * t1.strokes[0].size, rel=1e-9)
    assert t2.strokes[0].K == pytest.approx(t1.strokes[0].K, rel=1e-9)
    assert t2.sliding[0].v_slide[0] == pytest.approx(s * t1.sliding[0].v_slide[0], rel=1e-9,
                                                     abs=1e-12)
    assert t2.transmission[0].gamma[0] == pytest.approx(t1.transmission[0].gamma[0], abs=1e-12)
    for a, b in zip(t1.rubbing, t2.rubbing):
        assert b.v_rub[0] == pytest.approx(s * a.v_rub[0], rel=1e-9, abs=1e-15)


def test_a_pin_radius_by_its_point_and_links():
    text = slider_crank(100, 400, extra='[answers]\nask = ["rubbing"]\npin_radius = "5 mm"\n'
                        'pins = { "A(2,1)" = "30 mm", B = "15 mm" }\n')
    sol = solve(parse_scene(text), at_deg=[45.0])
    radii = {r.pair.point: r.radius for r in sol.extras["textbook"].rubbing}
    assert radii == {"O": 0.005, "A": 0.030, "B": 0.015}
    with pytest.raises(SceneError) as exc:
        parse_scene(slider_crank(100, 400, extra='[answers]\npins = { "A(1,3)" = "3 mm" }\n'))
    assert exc.value.key == 'answers.pins."A(1,3)"' or exc.value.key.endswith("A(1,3)")
