"""Plans against independent truth: 40-digit loop-closure references, closed forms, finite
differences of positions, rigid-body relations."""

import math

import numpy as np
import pytest
from independent import closed_form, mpref
from scenes import PHI, SCOTCH_YOKE, SLOTTED_CRANK_PRP, TEMPLATES, construction_of, template

from mechplan.scene import parse_scene

POINTS = {
    "slider_crank": ["A", "B", "S2"], "offset_slider_crank": ["A", "B", "S2"],
    "machine_unit": ["A", "B", "S2"], "four_bar": ["B", "C", "E"],
    "v_engine": ["B", "C", "D", "E", "S2"], "quick_return": ["A", "B"], "shaper": ["A", "B", "C"],
}
LINKS = {"four_bar": ["2", "3"], "v_engine": ["2", "4"], "quick_return": ["3"],
         "shaper": ["3", "4"], "slider_crank": ["2"], "offset_slider_crank": ["2"],
         "machine_unit": ["2"]}


def rel(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(np.max(np.abs(b)), 1e-300))


@pytest.mark.parametrize("name", sorted(POINTS))
def test_template_matches_40_digit_reference(name):
    _scene, c = template(name)
    phi = PHI[::2]
    ev = c.evaluate(phi)
    ref = mpref.reference(name, c.drive.absolute(phi))
    for p in POINTS[name]:
        assert rel(ev[f"pos.{p}"], ref[p][:, 0:2]) < 1e-13, p
        assert rel(ev[c.results[f"v_{p}"]], ref[p][:, 2:4]) < 1e-13, p
        assert rel(ev[c.results[f"a_{p}"]], ref[p][:, 4:6]) < 1e-13, p
    for link in LINKS[name]:
        assert rel(ev[c.results[f"omega_{link}"]], ref[link][:, 1]) < 1e-13, link
        assert rel(ev[c.results[f"epsilon_{link}"]], ref[link][:, 2]) < 1e-13, link


@pytest.mark.parametrize("name", ["slider_crank", "offset_slider_crank", "four_bar"])
def test_closed_form_over_the_cycle(name):
    _scene, c = template(name)
    phi = np.linspace(0, 2 * np.pi, 3601)
    ev = c.evaluate(phi)
    ref = closed_form.preset(name, c.drive.absolute(phi))
    for p in POINTS[name]:
        for col, sid in ((slice(0, 2), f"pos.{p}"), (slice(2, 4), c.results[f"v_{p}"]),
                         (slice(4, 6), c.results[f"a_{p}"])):
            assert rel(ev[sid], ref[p][:, col]) < 1e-12, (p, sid)


def _fd(f, x, h):
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h)


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_velocities_and_accelerations_are_derivatives_of_positions(path):
    from mechplan.scene import load_scene
    scene = load_scene(path)
    c = construction_of(scene)
    omega = scene.mechanism.drive.omega
    sense = c.drive.sense
    h = 1e-3
    ev = c.evaluate(PHI)
    for p in [p for lk in scene.mechanism.links.values() if lk.id != "0" for p in lk.points]:
        # d/dt = ω d/dθ and θ = ref + sense·φ
        pos = lambda phi, p=p: c.evaluate(phi)[c.position(p)]
        vel = lambda phi, p=p: c.evaluate(phi)[c.velocity_image(p)]
        v_fd = _fd(pos, PHI, h) * omega * sense
        a_fd = _fd(vel, PHI, h) * omega * sense
        scale_v = max(np.max(np.abs(ev[c.results[f"v_{p}"]])), abs(omega) * 1e-3)
        scale_a = max(np.max(np.abs(ev[c.results[f"a_{p}"]])), omega ** 2 * 1e-3)
        assert np.max(np.abs(v_fd - ev[c.results[f"v_{p}"]])) < 1e-8 * scale_v, p
        assert np.max(np.abs(a_fd - ev[c.results[f"a_{p}"]])) < 1e-7 * scale_a, p


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_every_link_moves_rigidly(path):
    """Images of any two points of a link satisfy v_Y − v_X = ω × XY, a_Y − a_X = ε × XY − ω² XY."""
    from mechplan.scene import load_scene
    scene = load_scene(path)
    c = construction_of(scene)
    ev = c.evaluate(np.linspace(0, 2 * np.pi, 73))
    for lid in scene.mechanism.moving:
        pts = list(scene.mechanism.links[lid].points)
        w, e = ev[c.results[f"omega_{lid}"]], ev[c.results[f"epsilon_{lid}"]]
        for x in pts:
            for y in pts:
                if x == y:
                    continue
                r = ev[f"pos.{y}"] - ev[f"pos.{x}"]
                perp = np.stack((-r[:, 1], r[:, 0]), axis=1)
                dv = ev[c.results[f"v_{y}"]] - ev[c.results[f"v_{x}"]]
                da = ev[c.results[f"a_{y}"]] - ev[c.results[f"a_{x}"]]
                scale_v = max(np.max(np.abs(ev[c.results[f"v_{q}"]])) for q in (x, y))
                scale_a = max(np.max(np.abs(ev[c.results[f"a_{q}"]])) for q in (x, y))
                assert np.max(np.abs(dv - w[:, None] * perp)) < 1e-12 * scale_v
                assert (np.max(np.abs(da - e[:, None] * perp + (w * w)[:, None] * r))
                        < 1e-11 * scale_a)


def test_scotch_yoke_rpp_closed_form():
    scene = parse_scene(SCOTCH_YOKE)
    c = construction_of(scene)
    phi = np.linspace(0, 2 * np.pi, 37)
    ev = c.evaluate(phi)
    r, w = 0.05, 20.0
    x = r * np.cos(phi)
    assert rel(ev["pos.Y"][:, 0], x) < 1e-14 and np.max(np.abs(ev["pos.Y"][:, 1])) < 1e-16
    assert rel(ev[c.results["v_Y"]][:, 0], -r * w * np.sin(phi)) < 1e-13
    assert rel(ev[c.results["a_Y"]][:, 0], -r * w * w * np.cos(phi)) < 1e-13
    assert rel(ev[c.results["a_K"]], ev[c.results["a_Y"]]) < 1e-13  # the yoke translates


def test_slotted_crank_prp_closed_form():
    scene = parse_scene(SLOTTED_CRANK_PRP)
    c = construction_of(scene)
    phi = np.radians(np.linspace(20, 160, 29))
    ev = c.evaluate(phi)
    h, w = 0.05, 5.0
    x = h / np.tan(phi)
    assert rel(ev["pos.K"][:, 0], x) < 1e-13
    assert rel(ev[c.results["v_K"]][:, 0], -h * w / np.sin(phi) ** 2) < 1e-13
    assert rel(ev[c.results["a_K"]][:, 0], 2 * h * w * w * np.cos(phi) / np.sin(phi) ** 3) < 1e-12


def test_v_engine_worked_example_position():
    """§1: at φ1 = 180° (BDC of C) v_C = 0, c coincides with p, s2 is the midpoint of bc."""
    _scene, c = template("v_engine")
    ev = c.evaluate(np.radians([180.0]))
    w1 = 800 * 2 * math.pi / 60
    vb = ev[c.results["v_B"]][0]
    assert np.hypot(*vb) == pytest.approx(w1 * 0.08, rel=1e-15)          # 6.702 m/s
    assert np.hypot(*ev[c.results["v_C"]][0]) < 1e-14
    s2 = ev[c.results["v_S2"]][0]
    assert np.allclose(s2, 0.5 * (vb + ev[c.results["v_C"]][0]), atol=1e-15)
    assert ev[c.results["omega_2"]][0] == pytest.approx(-w1 * 0.08 / 0.248, rel=1e-14)
    assert math.degrees(math.atan2(*ev["pos.B"][0][::-1])) == pytest.approx(-120.0, abs=1e-12)
