"""The involute pair against closed forms and mpmath, and the drawn teeth against the involute."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from shapely.geometry import Polygon

from mechplan.model.gears import PairSpec, ShiftRule
from mechplan.synthesis.gears.involute import (
    flank,
    inv_inverse,
    pair_layout,
    tooth_outline,
    trochoid_fillet,
)

ALPHA = math.radians(20)


def _inv(a):
    return math.tan(a) - a


@pytest.mark.parametrize("value", [1e-9, 1e-4, 0.0149044, 0.02, 0.05, 0.3])
def test_inv_inverse_against_mpmath(value):
    with mpmath.workdps(30):             # local precision: never touch mpmath's global state
        ref = mpmath.findroot(lambda a: mpmath.tan(a) - a - value, (3 * value) ** (1 / 3))
    assert inv_inverse(value) == pytest.approx(float(ref), rel=1e-13)


@pytest.mark.parametrize(("z1", "z2", "x1", "x2"), [(17, 34, 0.0, 0.0), (12, 30, 0.3, 0.1),
                                                    (20, 41, 0.5, 0.45), (25, 60, 0.2, -0.2)])
def test_pair_closed_forms(z1, z2, x1, x2):
    m, ha, c = 0.004, 1.0, 0.25
    p = pair_layout(PairSpec(m, z1, z2, shifts=(x1, x2)))
    inv_w = 2 * (x1 + x2) * math.tan(ALPHA) / (z1 + z2) + _inv(ALPHA)
    with mpmath.workdps(30):
        aw = float(mpmath.findroot(lambda a: mpmath.tan(a) - a - inv_w, 0.4))
    assert p.alpha_w == pytest.approx(aw, rel=1e-12)
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(ALPHA) / math.cos(aw)
    assert p.a_w == pytest.approx(a_w, rel=1e-12)
    dy = x1 + x2 - (a_w - a) / m
    ra = [m * z / 2 + m * (ha + x - dy) for z, x in ((z1, x1), (z2, x2))]
    rb = [m * z / 2 * math.cos(ALPHA) for z in (z1, z2)]
    eps = (math.sqrt(ra[0] ** 2 - rb[0] ** 2) + math.sqrt(ra[1] ** 2 - rb[1] ** 2)
           - a_w * math.sin(aw)) / (math.pi * m * math.cos(ALPHA))
    assert p.eps == pytest.approx(eps, rel=1e-12)
    for g, z, x, r_a in zip(p.gears, (z1, z2), (x1, x2), ra):
        assert g.r_a == pytest.approx(r_a) and g.r_f == pytest.approx(m * z / 2 - m * (ha + c - x))
        assert g.s == pytest.approx(m * (math.pi / 2 + 2 * x * math.tan(ALPHA)))
    # no backlash: the working tooth thicknesses fill the working pitch
    p_w = math.pi * m * math.cos(ALPHA) / math.cos(aw)
    assert p.gears[0].s_w + p.gears[1].s_w == pytest.approx(p_w, rel=1e-10)


def test_standard_pair_of_the_worked_example():
    p = pair_layout(PairSpec(0.004, 17, 34))
    assert p.a_w == pytest.approx(0.102) and p.alpha_w == pytest.approx(ALPHA)
    assert not any(p.pointed) and not any(p.interference)


def test_shift_rules():
    p = pair_layout(PairSpec(0.003, 12, 30, rule=ShiftRule.NO_UNDERCUT))
    assert (p.x1, p.x2) == (pytest.approx(5 / 17), 0.0)
    b = pair_layout(PairSpec(0.004, 17, 34, rule=ShiftRule.BALANCED))
    assert b.x2 == -b.x1 and 0 < b.x1 < 1
    assert b.gears[0].sliding == pytest.approx(b.gears[1].sliding, rel=1e-9)


def test_small_gear_without_shift_undercuts_and_interferes():
    p = pair_layout(PairSpec(0.003, 10, 60))
    assert p.gears[0].rho_l < 0             # undercut: the involute cannot start above the base
    assert p.interference[0]


def test_pointed_tip_with_large_shift():
    p = pair_layout(PairSpec(0.003, 12, 20, shifts=(1.2, 0.0)))
    assert p.pointed[0]


@pytest.mark.parametrize(("z", "x"), [(17, 0.0), (12, 0.3), (40, -0.2)])
def test_drawn_flank_lies_on_the_involute(z, x):
    p = pair_layout(PairSpec(0.004, z, 50, shifts=(x, 0.0)))
    g = p.gears[0]
    r, th = flank(g, ALPHA)
    const = th - np.array([_inv(math.acos(g.r_b / v)) for v in r])
    assert np.ptp(const) < 1e-12
    # and the same points in the tooth outline: polar angle + inv(arccos(r_b/r)) constant
    pts = tooth_outline(g, ALPHA, 0.004, 0.25)
    rr = np.hypot(pts[:, 0], pts[:, 1])
    ang = np.arctan2(pts[:, 1], pts[:, 0])
    right = (ang < 0) & (rr > r[0] + 1e-9) & (rr < g.r_a - 1e-9)
    c2 = ang[right] - np.array([_inv(math.acos(g.r_b / v)) for v in rr[right]])
    assert right.sum() > 10 and np.ptp(c2) < 1e-12
    # the involute meets the pitch circle at half the tooth thickness
    assert -np.interp(g.r, r, th) * g.r == pytest.approx(g.s / 2, rel=1e-3)


def test_meshed_teeth_touch_without_overlap():
    p = pair_layout(PairSpec(0.004, 17, 34, shifts=(0.3, 0.1)))
    g1, g2 = p.gears

    def teeth(g, centre, axis, offsets):
        out = []
        for k in offsets:
            pts = tooth_outline(g, ALPHA, 0.004, 0.25)
            a = axis + k * 2 * math.pi / g.z
            ca, sa = math.cos(a), math.sin(a)
            xy = [(centre[0] + ca * x - sa * y, centre[1] + sa * x + ca * y) for x, y in pts]
            out.append(Polygon(xy + [centre]).buffer(0))
        return out

    one = teeth(g1, (0.0, -g1.r_w), math.pi / 2, (-1, 0, 1))
    two = teeth(g2, (0.0, g2.r_w), -math.pi / 2, (-1.5, -0.5, 0.5, 1.5))
    overlap = sum(a.intersection(b).area for a in one for b in two)
    tooth_area = one[1].area
    assert overlap < 1e-6 * tooth_area
    gap = min(a.distance(b) for a in one for b in two)
    assert gap < 1e-6                    # they touch (no backlash) up to the chords, < 1 µm


@pytest.mark.parametrize(("z", "x"), [(34, 0.0), (30, 0.3), (60, 0.0), (20, 0.5)])
def test_generated_fillet_runs_from_the_root_circle_into_the_involute(z, x):
    """The rack's tip rounding, rolled on the pitch circle, ends where the rack's straight flank
    starts generating: exactly at the start of the involute computed from inv α (a second
    method)."""
    p = pair_layout(PairSpec(0.004, z, 50, shifts=(x, 0.0)))
    g = p.gears[0]
    f = trochoid_fillet(g, ALPHA, 0.004, 1.0, 0.25, n=60)
    r, th = flank(g, ALPHA)
    assert math.hypot(*f[0]) == pytest.approx(g.r_f, abs=1e-12)
    assert math.hypot(*f[-1]) == pytest.approx(r[0], abs=1e-12)
    assert math.atan2(f[-1][1], f[-1][0]) == pytest.approx(th[0], abs=1e-12)
    # the start radius is the lower limit of the generated involute:
    # ρ_l = r sin α − (h_a* − x)m/sin α
    rho_l = g.r * math.sin(ALPHA) - (1.0 - x) * 0.004 / math.sin(ALPHA)
    assert r[0] == pytest.approx(math.hypot(g.r_b, rho_l), rel=1e-12)
    radii = np.hypot(f[:, 0], f[:, 1])
    assert np.all(np.diff(radii) >= -1e-15)            # climbs from the root to the involute


@pytest.mark.parametrize(("z", "x"), [(8, 0.0), (10, 0.0), (13, 0.0), (17, 0.0), (20, -0.5)])
def test_undercut_outline_is_a_simple_polygon_thinner_at_the_base(z, x):
    p = pair_layout(PairSpec(0.004, z, 50, shifts=(x, 0.0)))
    g = p.gears[0]
    assert g.rho_l < 0
    o = tooth_outline(g, ALPHA, 0.004, 0.25)
    assert Polygon([*map(tuple, o), (0.0, 0.0)]).is_valid
    # the undercut removes material: where the outline crosses the base circle the tooth is no
    # wider than the involute there (half-angle ψ_b = s/(2r) + inv α)
    ang = np.arctan2(o[:, 1], o[:, 0])
    d = np.hypot(o[:, 0], o[:, 1]) - g.r_b
    psi_b = g.s / (2 * g.r) + _inv(ALPHA)
    crossings = [ang[i] + (ang[i + 1] - ang[i]) * d[i] / (d[i] - d[i + 1])
                 for i in range(len(o) - 1) if d[i] * d[i + 1] <= 0 and d[i] != d[i + 1]
                 and ang[i] < 0]
    assert crossings
    assert all(-c <= psi_b + 1e-9 for c in crossings)
