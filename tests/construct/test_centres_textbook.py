"""Textbook examples of the instant-centre method, with their printed answers.

Each golden value is computed here independently of mechplan (closed-form positions and the
derivative of the loop-closure equations); the printed answer, read off a drawing by the book,
is checked at the book's drawing accuracy.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.scene import parse_scene
from mechplan.solve import solve
from mechplan.studies.centres import analyse_centres, centres_json
from tests.scenes import slider_crank_text

KHURMI_6_1 = """
title = "Khurmi & Gupta, Theory of Machines, Example 6.1"
[ground]
A = ["0 mm", "0 mm"]
D = ["600 mm", "0 mm"]
[links.1]
lengths = { AB = "300 mm" }
[links.2]
lengths = { BC = "360 mm" }
[links.3]
lengths = { DC = "360 mm" }
[drive]
link = "1"
speed = "100 rpm"
sense = "ccw"
[assembly]
C = "left of B->D"
[positions]
at = ["60 deg"]
[analysis]
plans = ["position", "velocity", "centres"]
"""


def _four_bar_closed_form(a, b, c, d, theta, w1):
    """B, C and ω2, ω3 of a four-bar (frame A = 0, D = (d, 0)), C above BD, from the law of
    cosines and the derivative of B + b·e2 = D + c·e3."""
    B = a * np.array([math.cos(theta), math.sin(theta)])
    BD = np.array([d, 0.0]) - B
    f = math.hypot(*BD)
    # angle at B between BD and BC (triangle B, C, D with sides b, c, f)
    beta = math.acos((b * b + f * f - c * c) / (2 * b * f))
    t2 = math.atan2(BD[1], BD[0]) + beta          # C on the left of B→D
    C = B + b * np.array([math.cos(t2), math.sin(t2)])
    t3 = math.atan2(C[1], C[0] - d)
    # a·ω1·e1⊥ + b·ω2·e2⊥ = c·ω3·e3⊥
    M = np.array([[-b * math.sin(t2), c * math.sin(t3)], [b * math.cos(t2), -c * math.cos(t3)]])
    rhs = -a * w1 * np.array([-math.sin(theta), math.cos(theta)])
    w2, w3 = np.linalg.solve(M, rhs)
    return B, C, w2, w3


def test_khurmi_6_1_four_bar():
    """Khurmi & Gupta, Example 6.1: a four-bar AB = 300, BC = CD = 360, AD = 600 mm, ∠BAD = 60°,
    AB at 100 rpm: locate all the centres and find ω of BC. Printed answer: ω_BC ≈ 6.3 rad/s
    (v_B = 3.14 m/s over I13B ≈ 500 mm measured on the drawing; the book's I13 is our I02)."""
    sol = solve(parse_scene(KHURMI_6_1), scales=False)
    an = analyse_centres(sol)
    w1 = 100 * 2 * math.pi / 60
    B, C, w2, w3 = _four_bar_closed_form(0.3, 0.36, 0.36, 0.6, math.radians(60), w1)
    # the coupler's absolute centre: crank line AB ∩ rocker line DC (closed form)
    t = np.linalg.solve(np.column_stack([B, -(C - np.array([0.6, 0.0]))]), np.array([0.6, 0.0]))
    i02 = t[0] * B
    np.testing.assert_allclose(an.centres.point("0", "2")[0], i02, rtol=1e-13, atol=1e-15)
    # I13 on the frame line where the coupler line meets it
    s = -B[1] / (C - B)[1]
    np.testing.assert_allclose(an.centres.point("1", "3")[0], [B[0] + s * (C - B)[0], 0.0],
                               atol=1e-13)
    np.testing.assert_allclose(an.by_centres.omega["2"][0], w2, rtol=1e-13)
    np.testing.assert_allclose(an.by_centres.omega["3"][0], w3, rtol=1e-13)
    assert abs(abs(w2) - 6.3) <= 0.02 * 6.3                      # the printed answer
    assert math.hypot(*(i02 - B)) == pytest.approx(0.5, rel=0.01)  # "I13B = 500 mm"
    np.testing.assert_allclose(np.hypot(*an.by_centres.v["B"][0]), 0.3 * w1, rtol=1e-14)


@pytest.mark.parametrize("sense", ["cw", "ccw"])
def test_khurmi_6_2_slider_crank(sense):
    """Khurmi & Gupta, Example 6.2: crank OB = 100 mm, rod AB = 400 mm, the crank at 45° from the
    inner dead centre turning clockwise at 10 rad/s: velocity of the slider A and ω of AB.
    Printed answers: v_A = 0.82 m/s, ω_AB = 1.78 rad/s (read off the drawing)."""
    scene = parse_scene(slider_crank_text(100.0, 400.0, speed="10 rad/s", sense=sense))
    sol = solve(scene, at_deg=[45.0], plans=("position", "velocity", "centres"), scales=False)
    an = analyse_centres(sol)
    th, n, w = math.radians(45.0), 4.0, 10.0
    root = math.sqrt(n * n - math.sin(th) ** 2)
    v_slider = 0.1 * w * (math.sin(th) + math.sin(2 * th) / (2 * root))   # closed form
    w_rod = w * math.cos(th) / root
    assert np.hypot(*an.by_centres.v["B"][0]) == pytest.approx(v_slider, rel=1e-13)
    assert abs(an.by_centres.omega["2"][0]) == pytest.approx(w_rod, rel=1e-13)
    assert v_slider == pytest.approx(0.82, rel=0.03)             # the printed answers
    assert w_rod == pytest.approx(1.78, rel=0.03)
    # the slider's centre at infinity ⊥ the guide, the rod's I13 on the line through O ⊥ guide
    doc = centres_json(sol)
    entry = doc["positions"][0]["centres"]
    assert entry["I03"]["at_infinity"] and entry["I03"]["direction"] == pytest.approx([0, 1])
    assert entry["I13"]["r"][0] == pytest.approx(0.0, abs=1e-15)
    # v_slider = ω1 · I01I13 (Khurmi's v_A = ω·I13A… the slider moves with I13 of the crank)
    assert abs(w * entry["I13"]["r"][1]) == pytest.approx(v_slider, rel=1e-13)
