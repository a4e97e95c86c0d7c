"""Moving, rotating, mirroring or scaling a scene moves, rotates, mirrors or scales every plan."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scenes import build_text, four_bar_text, slider_crank_text

PHI = np.radians(np.array([5.0, 50.0, 100.0, 170.0, 200.0, 290.0]))


def rot(v, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.stack((c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]), axis=-1)


def plans(c, ev, points):
    return {p: (ev[f"pos.{p}"], ev[c.results[f"v_{p}"]], ev[c.results[f"a_{p}"]]) for p in points}


@given(st.floats(-500, 500), st.floats(-500, 500), st.floats(-180, 180))
@settings(max_examples=25, deadline=None)
def test_rigid_motion_of_slider_crank(dx, dy, deg):
    _, c0 = build_text(slider_crank_text(e_mm=20.0))
    _, c1 = build_text(slider_crank_text(e_mm=20.0, origin=(dx, dy), rot_deg=deg))
    ev0, ev1 = c0.evaluate(PHI), c1.evaluate(PHI)
    shift = np.array([dx, dy]) / 1000
    for p in ("A", "B", "S2"):
        assert np.allclose(ev1[f"pos.{p}"], rot(ev0[f"pos.{p}"], deg) + shift, rtol=0, atol=1e-13)
        for key, tol in (("v", 1e-12), ("a", 1e-9)):
            assert np.allclose(ev1[c1.results[f"{key}_{p}"]],
                               rot(ev0[c0.results[f"{key}_{p}"]], deg), rtol=0, atol=tol)
    assert np.allclose(ev1[c1.results["omega_2"]], ev0[c0.results["omega_2"]],
                       rtol=1e-12, atol=1e-12)


@given(st.floats(-300, 300), st.floats(-300, 300), st.floats(-180, 180))
@settings(max_examples=25, deadline=None)
def test_rigid_motion_of_four_bar(dx, dy, deg):
    d = rot(np.array([250.0, 0.0]), deg) + np.array([dx, dy])
    _, c0 = build_text(four_bar_text())
    _, c1 = build_text(four_bar_text(a=(dx, dy), d=(float(d[0]), float(d[1])), ref_deg=deg))
    ev0, ev1 = c0.evaluate(PHI), c1.evaluate(PHI)
    for p in ("B", "C", "E"):
        assert np.allclose(ev1[f"pos.{p}"], rot(ev0[f"pos.{p}"], deg) + np.array([dx, dy]) / 1000,
                           rtol=0, atol=1e-13)
        assert np.allclose(ev1[c1.results[f"v_{p}"]], rot(ev0[c0.results[f"v_{p}"]], deg),
                           atol=1e-12)
        assert np.allclose(ev1[c1.results[f"a_{p}"]], rot(ev0[c0.results[f"a_{p}"]], deg),
                           atol=1e-11)


def test_mirror_image_of_four_bar():
    """Mirror in the x axis: y → −y, the crank turns the other way, sides swap, ω and ε change
    sign."""
    _, c0 = build_text(four_bar_text())
    _, c1 = build_text(four_bar_text(sense="cw", side_c="right", side_e="right"))
    ev0, ev1 = c0.evaluate(PHI), c1.evaluate(PHI)
    flip = np.array([1.0, -1.0])
    for p in ("B", "C", "E"):
        for sid0, sid1 in ((f"pos.{p}", f"pos.{p}"), (c0.results[f"v_{p}"], c1.results[f"v_{p}"]),
                           (c0.results[f"a_{p}"], c1.results[f"a_{p}"])):
            assert np.allclose(ev1[sid1], ev0[sid0] * flip, rtol=0, atol=1e-12)
    for link in ("2", "3"):
        assert np.allclose(ev1[c1.results[f"omega_{link}"]], -ev0[c0.results[f"omega_{link}"]],
                           atol=1e-12)
        assert np.allclose(ev1[c1.results[f"epsilon_{link}"]],
                           -ev0[c0.results[f"epsilon_{link}"]], atol=1e-10)


@given(st.floats(1e-3, 1e3))
@settings(max_examples=20, deadline=None)
def test_scaling_all_lengths_scales_velocities_and_accelerations(k):
    _, c0 = build_text(four_bar_text())
    _, c1 = build_text(four_bar_text(d=(250.0 * k, 0.0), ab=80.0 * k, bc=260.0 * k, cd=180.0 * k,
                                     be=150.0 * k, ce=180.0 * k))
    ev0, ev1 = c0.evaluate(PHI), c1.evaluate(PHI)
    for p in ("B", "C", "E"):
        for sid0, sid1 in ((f"pos.{p}", f"pos.{p}"), (c0.results[f"v_{p}"], c1.results[f"v_{p}"]),
                           (c0.results[f"a_{p}"], c1.results[f"a_{p}"])):
            ref = ev0[sid0] * k
            assert np.max(np.abs(ev1[sid1] - ref)) <= 1e-13 * np.max(np.abs(ref))
    for link in ("2", "3"):
        w0, w1 = ev0[c0.results[f"omega_{link}"]], ev1[c1.results[f"omega_{link}"]]
        assert np.max(np.abs(w1 - w0)) <= 1e-13 * np.max(np.abs(w0))
