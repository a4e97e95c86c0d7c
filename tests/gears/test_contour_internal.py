"""The internal pair's blocking contour against an independent evaluation of each limit at points
on its boundary: α_w from the zero-backlash condition solved numerically on the involutes' polar
angles (parametric involutes, not inv α), the line of action laid out in coordinates and cut by the
tip circles (ε_α and the contact points), the start of each generated involute from the rack's tip
line met in coordinates, top lands from the parametric involutes; and the tip (trochoid)
interference by rotating the pair and looking for a pinion tip corner inside a ring tooth."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.errors import SceneError
from mechplan.model.gears import PairSpec
from mechplan.studies import solve_text
from mechplan.synthesis.gears.contour import ContourSpec
from mechplan.synthesis.gears.contour_internal import internal_contour, internal_limits

ALPHA = math.radians(20.0)
M = 0.002
C = ContourSpec(0.25, 1.2)


def _theta(r_b: float, r: float) -> float:
    """The polar angle of the involute point at radius r (from the parametric involute)."""
    t = math.sqrt(max(r * r / (r_b * r_b) - 1.0, 0.0))
    x, y = r_b * (math.cos(t) + t * math.sin(t)), r_b * (math.sin(t) - t * math.cos(t))
    return math.atan2(y, x)


class Independent:
    """The internal pair z1/z2 at shifts x1, x2, built without the code under test."""

    def __init__(self, z1: int, z2: int, x1: float, x2: float) -> None:
        self.z1, self.z2 = z1, z2
        r1, r2 = M * z1 / 2, M * z2 / 2
        self.r1, self.r2 = r1, r2
        self.rb1, self.rb2 = r1 * math.cos(ALPHA), r2 * math.cos(ALPHA)
        self.s1 = M * (math.pi / 2 + 2 * x1 * math.tan(ALPHA))           # pinion tooth
        self.e2 = math.pi * M - M * (math.pi / 2 - 2 * x2 * math.tan(ALPHA))   # ring space
        self.ra1, self.ra2 = r1 + M * (1 + x1), r2 - M * (1 - x2)
        self.x1, self.x2 = x1, x2

        def backlash(a: float) -> float:        # pinion tooth − ring space on the working circles
            rw1, rw2 = self.rb1 / math.cos(a), self.rb2 / math.cos(a)
            return self.beta1(rw1) - self.gamma2(rw2) * rw2 / rw1
        # no working angle where the shifts leave no pair (the tip lines run on regardless)
        self.alpha_w = (brentq(backlash, 1e-4, 1.2, xtol=1e-15)
                        if backlash(1e-4) * backlash(1.2) < 0 else math.nan)
        self.a_w = (self.rb2 - self.rb1) / math.cos(self.alpha_w)
        # the line of action in coordinates: ring centre O2 at the origin, pinion centre O1 on +x,
        # the pitch point P beyond O1, the line through P at α_w to the tangent
        self.O1 = np.array([self.a_w, 0.0])
        self.P = np.array([self.rb2 / math.cos(self.alpha_w), 0.0])
        self.d = np.array([math.sin(self.alpha_w), math.cos(self.alpha_w)])

    def beta1(self, r: float) -> float:
        """Half the pinion tooth's angle at radius r."""
        return self.s1 / (2 * self.r1) + _theta(self.rb1, self.r1) - _theta(self.rb1, r)

    def gamma2(self, r: float) -> float:
        """Half the ring's space angle at radius r."""
        return self.e2 / (2 * self.r2) + _theta(self.rb2, self.r2) - _theta(self.rb2, r)

    def _t(self, centre: np.ndarray, radius: float) -> float:
        """The larger parameter t where P + t·d meets the circle."""
        w = self.P - centre
        b, c = float(w @ self.d), float(w @ w) - radius * radius
        return -b + math.sqrt(b * b - c)

    def feet(self) -> tuple[float, float]:
        """t of N1 and N2 (the feet from O1 and O2)."""
        return -float((self.P - self.O1) @ self.d), -float(self.P @ self.d)

    def eps(self) -> float:
        t_a, t_e = self._t(self.O1, self.ra1), self._t(np.zeros(2), self.ra2)
        return (t_a - t_e) / (math.pi * M * math.cos(ALPHA))

    def rho_p(self) -> tuple[float, float]:
        """The pinion's lowest contact (from N1) and the ring's deepest (from N2)."""
        n1, n2 = self.feet()
        return self._t(np.zeros(2), self.ra2) - n1, self._t(self.O1, self.ra1) - n2

    def rho_l(self) -> tuple[float, float]:
        """Where each generating rack's tip line meets its line of action, from N (coordinates:
        the gear's centre at the origin, the pitch point at (0, r), u along the line)."""
        out = []
        for r, h, side in ((self.r1, (1 - self.x1) * M, -1.0), (self.r2, (1 - self.x2) * M, 1.0)):
            P0, u = np.array([0.0, r]), np.array([math.cos(ALPHA), -math.sin(ALPHA)])
            N = P0 - float(P0 @ u) * u
            t = -side * h / math.sin(ALPHA)            # y = r + side·h on the line
            X = P0 + t * u
            out.append(float(np.hypot(*(X - N))) * (1.0 if side > 0 or t < -float(P0 @ u)
                                                    else -1.0))
        return out[0], out[1]

    def tip_lands(self) -> tuple[float, float]:
        return (2 * self.ra1 * self.beta1(self.ra1),
                2 * self.ra2 * (math.pi / self.z2 - self.gamma2(self.ra2)))

    def corner_depth(self, steps: int = 6000) -> float:
        """The deepest a pinion tip corner goes into a ring tooth (m) over a pitch of rotation
        around the mesh (the ring tooth's sides are its involutes, outside its tip circle)."""
        b1 = self.beta1(self.ra1)
        worst = -math.inf
        for phi1 in np.linspace(-4 * math.pi / self.z1, 4 * math.pi / self.z1, steps):
            phi2 = phi1 * self.z1 / self.z2
            for j in range(-3, 4):
                for sgn in (-1.0, 1.0):
                    a = phi1 + 2 * math.pi * j / self.z1 + sgn * b1
                    q = self.O1 + self.ra1 * np.array([math.cos(a), math.sin(a)])
                    rho = float(np.hypot(*q))
                    if rho <= self.ra2:
                        continue
                    th = math.atan2(q[1], q[0]) - phi2
                    k = round((th - math.pi / self.z2) / (2 * math.pi / self.z2))
                    axis = math.pi / self.z2 + 2 * math.pi * k / self.z2
                    tau = math.pi / self.z2 - self.gamma2(rho)
                    worst = max(worst, (tau - abs(th - axis)) * rho)
        return worst


def _boundary(z1: int, z2: int, name: str) -> np.ndarray:
    p = PairSpec(module=M, z1=z1, z2=z2, internal=True)
    c = internal_contour(p, C, n=61)
    pts = c.lines[name]
    return pts[np.isfinite(pts[:, 0])]


@pytest.mark.parametrize("z1, z2", [(18, 60), (24, 70)])
def test_each_limit_is_zero_on_its_line_by_independent_evaluation(z1: int, z2: int) -> None:
    checked = 0
    for name in ("contact", "tip1", "tip2", "interference1", "interference2"):
        pts = _boundary(z1, z2, name)
        for x1, x2 in pts[:: max(1, len(pts) // 6)]:
            ind = Independent(z1, z2, float(x1), float(x2))
            if name == "contact":
                assert ind.eps() == pytest.approx(1.2, abs=1e-9)
            elif name.startswith("tip"):
                sa = ind.tip_lands()[int(name[-1]) - 1]
                assert sa / M == pytest.approx(0.25, abs=1e-9)
            elif name == "interference1":
                rp, rl = ind.rho_p()[0], max(ind.rho_l()[0], 0.0)
                assert (rp - rl) / M == pytest.approx(0.0, abs=1e-9)
            else:
                assert (ind.rho_l()[1] - ind.rho_p()[1]) / M == pytest.approx(0.0, abs=1e-9)
            checked += 1
    assert checked >= 15


def test_the_working_angle_and_centre_distance_agree() -> None:
    p = PairSpec(module=M, z1=20, z2=50, internal=True)
    from mechplan.synthesis.gears.contour_internal import internal_arrays

    for x1, x2 in ((0.0, 0.0), (0.3, 0.5), (-0.2, 0.1), (0.5, 0.2)):
        q = internal_arrays(p, x1, x2)
        ind = Independent(20, 50, x1, x2)
        assert float(q.alpha_w) == pytest.approx(ind.alpha_w, abs=1e-12)
        assert float(q.a_w) == pytest.approx(ind.a_w, rel=1e-12)
        assert float(q.eps) == pytest.approx(ind.eps(), abs=1e-10)


def test_tip_interference_line_separates_pairs_whose_tips_collide() -> None:
    """Either side of the tip-interference line, a pinion tip corner enters a ring tooth exactly
    on the side the limit forbids (by 0.07 mm; on the other side it at most touches)."""
    z1, z2 = 30, 40
    p = PairSpec(module=M, z1=z1, z2=z2, internal=True)
    pts = _boundary(z1, z2, "trochoid")
    assert len(pts) > 0
    seen = 0
    for x1, x2 in pts[:: max(1, len(pts) // 5)]:
        for dx2 in (-0.03, 0.03):
            v = internal_limits(p, C, x1, x2 + dx2)
            ind = Independent(z1, z2, float(x1), float(x2 + dx2))
            if not (math.isfinite(ind.alpha_w) and float(v["involute2"]) >= 0):
                continue
            depth = ind.corner_depth(3000)
            if float(v["trochoid"]) >= 0:
                assert depth < 1e-9, (x1, x2 + dx2, depth)
            else:
                assert depth > 1e-7, (x1, x2 + dx2, depth)
            seen += 1
    assert seen >= 8


def test_the_scene_key_and_its_errors() -> None:
    text = ('kind = "gears"\ntitle = "i"\n[pair]\nmodule = "2 mm"\nteeth = [18, 60]\n'
            'internal = true\nshift_rule = "contour"\n')
    st = solve_text(text, "i.toml")
    doc = st.to_json()["internal_pair"]
    assert doc["admissible"] and all(v >= 0 for v in doc["limits"].values())
    ind = Independent(18, 60, *doc["x"])
    assert doc["contact_ratio"] == pytest.approx(ind.eps(), abs=1e-10)
    assert st.sheets(None, None, None, "i")
    with pytest.raises(SceneError) as e:
        solve_text(text.replace("[18, 60]", "[60, 18]"), "i.toml")
    assert e.value.key == "pair.teeth"
    with pytest.raises(SceneError) as e:
        solve_text(text.replace('"contour"', '"no_undercut"'), "i.toml")
    assert e.value.key == "pair.shift_rule"
    given = text.replace('shift_rule = "contour"', "shifts = [0.0, 0.0]")
    assert solve_text(given, "i.toml").warnings("en")         # 18/60 unshifted interferes
