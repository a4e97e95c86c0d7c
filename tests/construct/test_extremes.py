"""Dead centres (extreme positions) found exactly, against closed forms."""

import math

import numpy as np
import pytest
from scenes import template

from mechplan.construct.extremes import extreme_positions


def phi_of(c, theta):
    return float(c.drive.scene(np.array([theta]))[0])


def angdiff(a, b):
    return abs(math.remainder(a - b, 2 * math.pi))


def test_central_slider_crank_dead_centres():
    scene, c = template("slider_crank")
    ex = {e.which: e for e in extreme_positions(c, scene.mechanism, "B")}
    assert angdiff(ex["max"].phi, 0.0) < 1e-12
    assert angdiff(ex["min"].phi, math.pi) < 1e-12
    assert ex["max"].value == pytest.approx(0.5, rel=1e-14)      # r + l
    assert ex["min"].value == pytest.approx(0.3, rel=1e-14)      # l − r


def test_offset_slider_crank_dead_centres():
    scene, c = template("offset_slider_crank")
    r, l, e = 0.08, 0.3, 0.03
    ex = {x.which: x for x in extreme_positions(c, scene.mechanism, "B")}
    outer = phi_of(c, math.asin(e / (l + r)))
    inner = phi_of(c, math.pi + math.asin(e / (l - r)))
    assert angdiff(ex["max"].phi, outer) < 1e-12
    assert angdiff(ex["min"].phi, inner) < 1e-12
    assert ex["max"].value == pytest.approx(math.sqrt((l + r) ** 2 - e * e), rel=1e-14)
    assert ex["min"].value == pytest.approx(math.sqrt((l - r) ** 2 - e * e), rel=1e-14)


def test_quick_return_coulisse_extremes_where_crank_is_perpendicular():
    scene, c = template("quick_return")
    ex = sorted(extreme_positions(c, scene.mechanism, "3"), key=lambda e: e.phi)
    half = math.acos(0.1 / 0.3)
    expected = sorted(phi_of(c, -math.pi / 2 + s * half) for s in (1, -1))
    assert len(ex) == 2
    for got, want in zip(ex, expected):
        assert angdiff(got.phi, want) < 1e-12
    # the working stroke takes the longer arc: time ratio (π + 2·asin(r/d))/(π − 2·asin(r/d))
    arc = (ex[1].phi - ex[0].phi) % (2 * math.pi)
    assert max(arc, 2 * math.pi - arc) == pytest.approx(math.pi + 2 * math.asin(1 / 3), rel=1e-12)


def test_four_bar_rocker_extremes_when_crank_and_coupler_are_collinear():
    scene, c = template("four_bar")
    ab, bc, cd, ad = 0.08, 0.26, 0.18, 0.25
    found = sorted(e.phi for e in extreme_positions(c, scene.mechanism, "3"))
    want = []
    for reach in (bc + ab, bc - ab):
        # C on circle (A, reach) and circle (D, cd), left of B→D (C above the frame line here)
        a = (reach ** 2 - cd ** 2 + ad ** 2) / (2 * ad)
        cy = math.sqrt(reach ** 2 - a ** 2)
        ang = math.atan2(cy, a)
        want.append(phi_of(c, ang if reach == bc + ab else ang + math.pi))
    assert len(found) == 2
    for got, w in zip(found, sorted(want)):
        assert angdiff(got, w) < 1e-11
