"""Motion laws against closed forms (METHODS.md §3, worked example §5), finite differences and
continuity at the phase boundaries."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.model.cam import Law, Phase, PhaseKind
from mechplan.synthesis.cam.laws import normalised
from mechplan.synthesis.cam.motion import motion

X = np.linspace(0.0, 1.0, 2001)

#: closed forms of s/h at x = φ/β (METHODS.md §3), written independently of the code
CLOSED = {
    Law.PARABOLIC: lambda x: np.where(x <= 0.5, 2 * x ** 2, 1 - 2 * (1 - x) ** 2),
    Law.COSINE: lambda x: 0.5 * (1 - np.cos(np.pi * x)),
    Law.CYCLOIDAL: lambda x: x - np.sin(2 * np.pi * x) / (2 * np.pi),
    Law.POLY345: lambda x: 10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5,
}

#: (law, s′max·β/h, s″max·β²/h) from the textbooks
PEAKS = [
    (Law.CYCLOIDAL, 2.0, 2 * math.pi),
    (Law.POLY345, 1.875, 10 / math.sqrt(3)),          # 5.7735
    (Law.COSINE, math.pi / 2, math.pi ** 2 / 2),
    (Law.PARABOLIC, 2.0, 4.0),
    (Law.MODIFIED_TRAPEZOID, 2.0, 4.8881),
]


@pytest.mark.parametrize("law", list(CLOSED), ids=lambda law: law.value)
def test_displacement_matches_the_closed_form(law):
    y, _, _ = normalised(law, X)
    assert np.max(np.abs(y - CLOSED[law](X))) < 1e-12


@pytest.mark.parametrize(("law", "v_peak", "a_peak"), PEAKS, ids=lambda v: getattr(v, "value", ""))
def test_peaks_of_s1_and_s2(law, v_peak, a_peak):
    h, beta = 0.02, math.radians(100)
    phases = (Phase(PhaseKind.RISE, beta, law), Phase(PhaseKind.FAR_DWELL, 2 * math.pi - beta))
    phi = np.linspace(0, beta, 200001)
    m = motion(phases, h, phi)
    assert m.s1.max() == pytest.approx(v_peak * h / beta, rel=1e-6)
    tol = 2e-4 if law is Law.MODIFIED_TRAPEZOID else 1e-6   # 4.8881 is the rounded textbook value
    assert np.abs(m.s2).max() == pytest.approx(a_peak * h / beta ** 2, rel=tol)


def test_uniform_law_with_blends():
    k = 0.2
    y, y1, y2 = normalised(Law.UNIFORM, X, blend=k)
    v = 1 / (1 - k)                               # velocity of the middle part
    mid = (X > k + 1e-9) & (X < 1 - k - 1e-9)
    assert np.allclose(y1[mid], v) and np.allclose(y2[mid], 0.0)
    assert np.max(np.abs(y2)) == pytest.approx(v / k)
    assert y[-1] == pytest.approx(1.0) and y1[0] == 0 and abs(y1[-1]) < 1e-12


def test_worked_example_acceleration_law():
    """§5: a(φ) = (h·2π/φу²)·sin(2πφ/φу) on the rise, then the mirror on the return."""
    h, fr = 0.01, math.radians(60)
    phases = (Phase(PhaseKind.RISE, fr, Law.CYCLOIDAL), Phase(PhaseKind.FAR_DWELL, 1.0),
              Phase(PhaseKind.RETURN, fr, Law.CYCLOIDAL), Phase(PhaseKind.NEAR_DWELL,
                                                                2 * math.pi - 1.0 - 2 * fr))
    phi = np.linspace(0, fr, 301)
    a = h * 2 * math.pi / fr ** 2 * np.sin(2 * math.pi * phi / fr)
    assert np.allclose(motion(phases, h, phi).s2, a, atol=1e-12)
    back = motion(phases, h, fr + 1.0 + phi)
    assert np.allclose(back.s2, -a, atol=1e-12)
    assert np.allclose(back.s, h - motion(phases, h, phi).s, atol=1e-15)


ALL = [Law.UNIFORM, Law.PARABOLIC, Law.COSINE, Law.CYCLOIDAL, Law.POLY345, Law.MODIFIED_TRAPEZOID]


@pytest.mark.parametrize("law", ALL, ids=lambda law: law.value)
def test_derivatives_are_the_finite_differences(law):
    y, y1, y2 = normalised(law, X, blend=0.15)
    dx = X[1] - X[0]
    fd1 = (y[2:] - y[:-2]) / (2 * dx)
    fd2 = (y[2:] - 2 * y[1:-1] + y[:-2]) / dx ** 2
    smooth = np.abs(y2[2:] - y2[:-2]) < 0.05         # away from jumps of y″ (parabolic, uniform)
    assert np.max(np.abs(fd1 - y1[1:-1])[smooth]) < 1e-5
    assert np.max(np.abs(fd1 - y1[1:-1])) < 1e-2     # and only O(dx) at a jump
    assert np.max(np.abs(fd2 - y2[1:-1])[smooth]) < 1e-3


@pytest.mark.parametrize("law", ALL, ids=lambda law: law.value)
def test_continuity_at_phase_boundaries(law):
    h = 0.015
    phases = (Phase(PhaseKind.RISE, 2.0, law, 0.15), Phase(PhaseKind.FAR_DWELL, 0.5),
              Phase(PhaseKind.RETURN, 1.5, law, 0.15),
              Phase(PhaseKind.NEAR_DWELL, 2 * math.pi - 4.0))
    for b in np.cumsum([0.0, 2.0, 0.5, 1.5]):
        left, right = motion(phases, h, b - 1e-9), motion(phases, h, b + 1e-9)
        assert abs(left.s[0] - right.s[0]) < 1e-9
        assert abs(left.s1[0] - right.s1[0]) < 1e-7
        if law in (Law.CYCLOIDAL, Law.POLY345, Law.MODIFIED_TRAPEZOID):   # zero s″ at the ends
            assert abs(left.s2[0] - right.s2[0]) < 1e-6


def test_table_of_s_reproduces_a_smooth_law():
    n = 41
    xs = np.linspace(0, 1, n)
    table = tuple(CLOSED[Law.POLY345](xs))
    y, y1, _y2 = normalised(Law.TABLE_S, X, table=table)
    assert np.max(np.abs(y - CLOSED[Law.POLY345](X))) < 2e-5
    assert abs(y1[0]) < 1e-12 and abs(y1[-1]) < 1e-12          # clamped ends: no velocity jump
    dx = X[1] - X[0]
    assert np.max(np.abs((y[2:] - y[:-2]) / (2 * dx) - y1[1:-1])) < 1e-4


def test_table_of_a_integrates_to_the_cycloidal_law():
    xs = np.linspace(0, 1, 201)
    y, y1, _y2 = normalised(Law.TABLE_A, X, table=tuple(np.sin(2 * np.pi * xs)))
    assert np.max(np.abs(y - CLOSED[Law.CYCLOIDAL](X))) < 1e-4
    assert y[-1] == pytest.approx(1.0) and abs(y1[-1]) < 1e-9
