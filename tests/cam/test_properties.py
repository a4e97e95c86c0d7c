"""Properties over random cams (hypothesis): the pressure-angle formula, the envelope offset and the
limit at the minimum base radius hold for every law, stroke, phase split, offset and sense."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from mechplan.errors import SceneError
from mechplan.scene.cam import parse_cam
from mechplan.synthesis.cam import design, sample
from mechplan.synthesis.cam.motion import motion

from .scenes import cam_text

LAWS = ["uniform", "parabolic", "cosine", "cycloidal", "poly345", "modified_trapezoid"]


@settings(max_examples=10, deadline=None)
@given(law=st.sampled_from(LAWS), ret_law=st.sampled_from(LAWS),
       rise=st.integers(60, 150), far=st.integers(0, 40), ret=st.integers(60, 150),
       stroke=st.floats(5.0, 40.0), offset=st.floats(-8.0, 8.0),
       sense=st.sampled_from(["ccw", "cw"]),
       limit=st.integers(20, 40))
def test_random_cams(law, ret_law, rise, far, ret, stroke, offset, sense, limit):
    near = 360 - rise - far - ret
    text = cam_text(law=law, return_law=ret_law, rise=f"{rise} deg", far=f"{far + 0.5} deg",
                    ret=f"{ret} deg", near=f"{near - 0.5} deg", stroke=f"{stroke} mm",
                    offset=f"{offset} mm", sense=sense, alpha_rise=f"{limit} deg",
                    alpha_return=f"{limit + 10} deg", roller="1 mm")
    try:
        d = design(parse_cam(text))
    except SceneError as exc:                      # an undercut is refused, never drawn
        assert exc.key == "follower.roller_radius"
        return
    g = d.geometry
    phi = np.linspace(0, 2 * math.pi, 500, endpoint=False)
    smp = sample(g, phi)
    m = motion(g.phases, g.stroke, phi)
    s0 = math.sqrt(g.r0 ** 2 - g.e ** 2)
    assert np.allclose(np.tan(np.abs(smp.alpha)), np.abs((m.s1 - g.e) / (m.s + s0)), atol=1e-9)
    # the working profile is the pitch curve offset by rr along the normal, at every angle
    assert np.allclose(np.hypot(*(smp.pitch - smp.profile).T), g.roller, atol=1e-12)
    # at the minimum base radius the largest pressure angle reaches the limit on one side
    worst = max(d.alpha_rise.value / math.radians(limit),
                d.alpha_return.value / math.radians(limit + 10))
    assert 1 - 1e-4 < worst <= 1 + 1e-9
