"""Meets lie on both loci; gaps and conditioning are reported."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from mechplan.geom.meet import circle_circle, circle_line, line_line
from mechplan.geom.vec import cross, norm

coord = st.floats(-1e3, 1e3, allow_nan=False)
radius = st.floats(1e-2, 1e3, allow_nan=False)


@given(coord, coord, radius, coord, coord, radius, st.sampled_from([1, -1]))
@settings(max_examples=200, deadline=None)
def test_circle_circle_point_lies_on_both_circles(x1, y1, r1, x2, y2, r2, sigma):
    c1, c2 = np.array([[x1, y1]]), np.array([[x2, y2]])
    p, gap, sine = circle_circle(c1, r1, c2, r2, sigma)
    d = float(norm(c2 - c1)[0])
    if gap[0] <= 0 and d > 1e-6 and sine[0] > 1e-6:
        scale = max(r1, r2, d)
        assert abs(norm(p - c1)[0] - r1) <= 1e-9 * scale
        assert abs(norm(p - c2)[0] - r2) <= 1e-9 * scale
        side = cross(c2 - c1, p - c1)[0]
        assert side * sigma >= -1e-9 * scale * scale
    elif gap[0] > 0:
        assert np.isnan(p).all()


def test_circle_circle_reports_gap_when_too_far():
    p, gap, _ = circle_circle(np.array([[0.0, 0.0]]), 1.0, np.array([[5.0, 0.0]]), 1.5, 1)
    assert gap[0] == 2.5 and np.isnan(p).all()


@given(coord, coord, radius, coord, coord, st.floats(0, 2 * np.pi), st.sampled_from([1, -1]))
@settings(max_examples=200, deadline=None)
def test_circle_line_point_lies_on_circle_and_line(cx, cy, r, px, py, ang, sigma):
    c, p0 = np.array([[cx, cy]]), np.array([[px, py]])
    u = np.array([[np.cos(ang), np.sin(ang)]])
    p, gap, sine = circle_line(c, r, p0, u, sigma)
    scale = max(r, abs(cx), abs(cy), abs(px), abs(py), 1.0)
    if gap[0] <= 0 and sine[0] > 1e-6:
        assert abs(norm(p - c)[0] - r) <= 1e-9 * scale
        assert abs(cross(u, p - p0)[0]) <= 1e-9 * scale
        far = p - c
        assert sigma * float(far[0] @ u[0]) >= -1e-9 * scale


@given(coord, coord, st.floats(0, np.pi), coord, coord, st.floats(0, np.pi))
@settings(max_examples=200, deadline=None)
def test_line_line_point_lies_on_both_lines(x1, y1, a1, x2, y2, a2):
    p1, p2 = np.array([[x1, y1]]), np.array([[x2, y2]])
    u1, u2 = np.array([[np.cos(a1), np.sin(a1)]]), np.array([[np.cos(a2), np.sin(a2)]])
    p, _, sine = line_line(p1, u1, p2, u2)
    assert np.isclose(sine[0], abs(np.sin(a2 - a1)), atol=1e-15)
    if sine[0] > 1e-3:
        scale = max(abs(x1), abs(y1), abs(x2), abs(y2), 1.0) / sine[0]
        assert abs(cross(u1, p - p1)[0]) <= 1e-9 * scale
        assert abs(cross(u2, p - p2)[0]) <= 1e-9 * scale


def test_parallel_lines_give_nan_and_zero_sine():
    p, _, sine = line_line(np.array([[0.0, 0.0]]), np.array([[1.0, 0.0]]),
                           np.array([[0.0, 1.0]]), np.array([[1.0, 0.0]]))
    assert np.isnan(p).all() and sine[0] == 0.0
