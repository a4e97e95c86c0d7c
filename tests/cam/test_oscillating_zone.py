"""The ψ′–ψ diagram of an oscillating roller follower: a cam centre X is inside the hatched zone
exactly when the pressure angles of the cam built around X (the same arm positions, pivot distance
|AX|, base radius |XB0|) keep within the limits — those computed the other way, from the normal of
the pitch curve by inversion."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from shapely.geometry import Point, Polygon

from mechplan.model.cam import Contact, Motion
from mechplan.studies.cam import solve_cam
from mechplan.synthesis.cam.base_radius import limit_per_angle
from mechplan.synthesis.cam.oscillating_zone import oscillating_zone
from mechplan.synthesis.cam.profile import Geometry, pressure_angle

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "cam_oscillating.toml"


def margin_by_inversion(d, x: np.ndarray, idx: np.ndarray) -> float | None:
    """Least (α_allow − |α|) of the cam centred at x, by the pitch curve's normal."""
    g, lim = d.geometry, d.spec.limits
    a_vec = np.array([g.pivot, 0.0]) - x
    b0 = np.array([g.pivot - g.arm * math.cos(g.gamma0), g.arm * math.sin(g.gamma0)]) - x
    turn = -math.atan2(a_vec[1], a_vec[0])
    c, s = math.cos(turn), math.sin(turn)
    b0r = np.array([c * b0[0] - s * b0[1], s * b0[0] + c * b0[1]])
    if b0r[1] <= 0:                 # the arm must stay above the new line of centres
        return None
    g2 = Geometry(g.phases, g.stroke, 1, Motion.OSCILLATING, Contact.ROLLER,
                  float(np.hypot(*b0r)), 0.0, g.roller, g.arm, float(np.hypot(*a_vec)))
    ds = d.dense
    alpha = pressure_angle(g2, ds.s[idx], ds.s1[idx], ds.s2[idx])
    limit = limit_per_angle(g.phases, ds.phi[idx], lim.alpha_rise, lim.alpha_return)
    return float(np.min(limit - np.abs(alpha)))


def test_zone_membership_is_the_pressure_angle_condition():
    d = solve_cam(TEMPLATE.read_text(encoding="utf-8"), "c.toml").design
    idx = np.arange(0, d.dense.phi.size, 20)
    z = oscillating_zone(d.geometry, d.dense.phi[idx], d.spec.limits.alpha_rise,
                         d.spec.limits.alpha_return,
                         (d.dense.s[idx], d.dense.s1[idx], d.dense.s2[idx]))
    zone = Polygon(z.zone)
    assert abs(z.margin) < 1e-9                          # the least r0: O on the zone's edge
    rng = np.random.default_rng(7)
    checked = inside = 0
    for _ in range(300):
        x = rng.uniform(-0.04, 0.04, 2)
        m = margin_by_inversion(d, x, idx)
        if m is None or abs(m) < 1e-6:
            continue
        checked += 1
        inside += m > 0
        assert zone.contains(Point(*x)) == (m > 0), (x, m)
    assert checked > 200 and 10 < inside < checked - 10


def test_the_sheet_draws_the_zone():
    st = solve_cam(TEMPLATE.read_text(encoding="utf-8"), "c.toml")
    sheets = st.sheets(None, None, "ru", "c")
    texts = " ".join(p.string for s in sheets for p in s.flat() if hasattr(p, "string"))
    assert "ψ′–ψ" in texts
