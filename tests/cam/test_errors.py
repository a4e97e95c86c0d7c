"""User errors of a cam scene name the key and say what is expected."""

from __future__ import annotations

import pytest

from mechplan.errors import SceneError
from mechplan.scene.cam import parse_cam
from mechplan.synthesis.cam import design

from .scenes import cam_text, oscillating_text


def _error(text: str) -> SceneError:
    with pytest.raises(SceneError) as info:
        design(parse_cam(text, "c.toml"))
    return info.value


def test_phases_must_sum_to_360():
    e = _error(cam_text(near="80 deg"))
    assert e.key == "motion.phases" and "360" in str(e) and "350" in str(e)


def test_stroke_must_be_positive():
    e = _error(cam_text(stroke="-5 mm"))
    assert e.key == "motion.stroke" and "positive" in str(e)
    assert _error(cam_text(stroke="0 mm")).key == "motion.stroke"


def test_allowable_angle_below_90():
    e = _error(cam_text(alpha_rise="90 deg"))
    assert e.key == "limits.pressure_angle_rise" and "90" in str(e)


def test_roller_too_large_for_the_curvature():
    e = _error(cam_text(roller="30 mm"))
    assert e.key == "follower.roller_radius"
    assert "undercut" in str(e) and "ρmin" in str(e) and "°" in str(e)


def test_base_radius_that_cannot_meet_the_limit():
    e = _error(cam_text(base="20 mm"))
    assert e.key == "limits.base_radius" and "at least" in str(e)
    e = _error(oscillating_text(base="22 mm"))
    assert e.key == "limits.base_radius" and "at least" in str(e)


def test_flat_base_radius_below_convexity():
    e = _error(cam_text(contact="flat", base="2 mm"))
    assert e.key == "limits.base_radius" and "convex" in str(e)


def test_phase_order_and_laws():
    text = cam_text().replace('kind = "far_dwell"', 'kind = "near_dwell"', 1)
    assert _error(text).key == "motion.phases[1].kind"
    assert _error(cam_text(law="spline")).key == "motion.phases[0].law"


def test_unknown_key_suggests():
    e = _error(cam_text().replace("roller_radius", "roler_radius"))
    assert e.key == "follower.roler_radius" and "roller_radius" in str(e)


def test_acceleration_table_must_end_at_rest():
    text = cam_text().replace('law = "cycloidal" }', 'law = "table", a = [1, 1, 1] }', 1)
    e = _error(text)
    assert e.key == "motion.phases[0].a" and "rest" in str(e)
