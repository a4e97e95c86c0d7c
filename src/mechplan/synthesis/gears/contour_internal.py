"""The blocking contour of an internal pair: an external pinion 1 in a ring gear 2 (ГОСТ 19274
internal gearing, the KHK/ISO 21771 interference checks).

Shifts in the course's (ГОСТ) sense: x2 > 0 moves the ring's teeth away from the axis (thinner
teeth, wider spaces), so inv α_w = 2(x2 − x1)·tan α/(z2 − z1) + inv α and
a_w = m(z2 − z1)·cos α/(2 cos α_w). Tip circles r_a1 = r1 + m(h_a* + x1), r_a2 = r2 − m(h_a* − x2);
tooth thicknesses s1 = m(π/2 + 2x1·tan α), s2 = m(π/2 − 2x2·tan α) on the reference circles.
Along the line of action N1, N2 are on the same side of the pitch point, g = N1N2 = a_w·sin α_w,
and at a contact point the involutes' radii of curvature differ by g: ρ2 = ρ1 + g.

Each limit is g(x1, x2) ≥ 0 (in modules or radians):

- ``undercut1``: x1 ≥ h_a*(z_min − z1)/z_min (the pinion cut by a rack);
- ``tip1``, ``tip2``: top lands s_a ≥ k·m, s_a1 = 2r_a1(s1/(2r1) + inv α − inv α_a1),
  s_a2 = 2r_a2(s2/(2r2) − inv α + inv α_a2) (the ring's tooth is thinnest at its inner tip);
- ``contact``: ε_α = (ρ_a1 − ρ_a2 + g)/(π m cos α) ≥ ε_min, ρ_a = √(r_a² − r_b²);
- ``interference1``: the ring's tip meets the pinion at ρ_p1 = ρ_a2 − g, which must not lie below
  the start of the pinion's generated involute ρ_l1 = r1·sin α − (h_a* − x1)m/sin α, nor below N1;
- ``interference2``: the pinion's tip meets the ring at ρ_p2 = ρ_a1 + g, which must not lie beyond
  the ring's involute ρ_l2 = r2·sin α + (h_a* − x2)m/sin α (where its root fillet begins);
- ``involute2``: the ring's tip circle outside its base circle, r_a2 ≥ r_b2;
- ``trochoid``: no tip (secondary, trochoid) interference as the pinion's tip leaves the mesh:
  θ1·z1/z2 + inv α_w − inv α_a2 ≥ θ2, θ1 = arccos((r_a2² − r_a1² − a_w²)/(2a_w·r_a1)) + inv α_a1
  − inv α_w, θ2 = arccos((a_w² + r_a2² − r_a1²)/(2a_w·r_a2));
- ``trimming``: the pinion can be put in radially without trimming the ring's tips:
  θ1 + inv α_a1 − inv α_w ≥ (z2/z1)(θ2 + inv α_a2 − inv α_w), θ1 = arcsin √((1 − (cos α_a1/
  cos α_a2)²)/(1 − (z1/z2)²)), θ2 = arcsin √(((cos α_a2/cos α_a1)² − 1)/((z2/z1)² − 1)).

The recommended shifts: on the line of balanced specific sliding (η1 = 1 − (z1/z2)·ρ2/ρ1 at the
pinion's lowest contact point equal to η2 = 1 − (z2/z1)·ρ1/ρ2 at the ring's deepest one) inside the
contour, the point of the largest ε_α; without one, the admissible grid point of the largest ε_α.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import PairSpec
from .contour import Contour, ContourSpec, _roots, contour_on_grid, inv_inverse_array

LIMITS_INTERNAL = ("undercut1", "tip1", "tip2", "contact", "interference1", "interference2",
                   "involute2", "trochoid", "trimming")


def _inv(a: np.ndarray) -> np.ndarray:
    return np.tan(a) - a


@dataclass(frozen=True)
class InternalArrays:
    """The internal pair at arrays of shifts (SI; shapes of x1, x2 broadcast)."""

    alpha_w: np.ndarray
    a_w: np.ndarray
    g: np.ndarray
    r_a: tuple[np.ndarray, np.ndarray]
    rho_a: tuple[np.ndarray, np.ndarray]     # NaN where the tip is inside the base circle
    s_a: tuple[np.ndarray, np.ndarray]
    eps: np.ndarray
    rho_p: tuple[np.ndarray, np.ndarray]     # the pinion's lowest, the ring's deepest contact
    rho_l: tuple[float | np.ndarray, np.ndarray]
    sliding: tuple[np.ndarray, np.ndarray]   # η1 at ρ_p1, η2 at ρ_p2


def internal_arrays(p: PairSpec, x1: np.ndarray | float, x2: np.ndarray | float
                    ) -> InternalArrays:
    """Lay the internal pair out at every (x1, x2) at once (``p.z1`` the pinion, ``p.z2`` the
    ring)."""
    x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
    m, al, ha = p.module, p.alpha, p.addendum
    z1, z2 = p.z1, p.z2
    inv_al = math.tan(al) - al
    aw = inv_inverse_array(2 * (x2 - x1) * math.tan(al) / (z2 - z1) + inv_al)
    a_w = m * (z2 - z1) * math.cos(al) / (2 * np.cos(aw))
    g = a_w * np.sin(aw)
    r1, r2 = m * z1 / 2, m * z2 / 2
    rb1, rb2 = r1 * math.cos(al), r2 * math.cos(al)
    ra1, ra2 = r1 + m * (ha + x1), r2 - m * (ha - x2)
    with np.errstate(invalid="ignore"):
        rho_a1 = np.sqrt(ra1 ** 2 - rb1 ** 2)
        rho_a2 = np.where(ra2 >= rb2, np.sqrt(np.maximum(ra2 ** 2 - rb2 ** 2, 0.0)), np.nan)
        aa1 = np.arccos(np.clip(rb1 / ra1, -1.0, 1.0))
        aa2 = np.where(ra2 >= rb2, np.arccos(np.clip(rb2 / ra2, -1.0, 1.0)), np.nan)
    s1 = m * (math.pi / 2 + 2 * x1 * math.tan(al))
    s2 = m * (math.pi / 2 - 2 * x2 * math.tan(al))
    sa1 = 2 * ra1 * (s1 / (2 * r1) + inv_al - _inv(aa1))
    sa2 = 2 * ra2 * (s2 / (2 * r2) - inv_al + _inv(aa2))
    eps = (rho_a1 - rho_a2 + g) / (math.pi * m * math.cos(al))
    rho_p1, rho_p2 = rho_a2 - g, rho_a1 + g
    rho_l1 = r1 * math.sin(al) - (ha - x1) * m / math.sin(al)
    rho_l2 = r2 * math.sin(al) + (ha - x2) * m / math.sin(al)
    with np.errstate(divide="ignore", invalid="ignore"):
        eta1 = np.where(rho_p1 > 0, 1 - (z1 / z2) * (rho_p1 + g) / rho_p1, -np.inf)
        eta2 = 1 - (z2 / z1) * rho_a1 / rho_p2
    return InternalArrays(aw, a_w, g, (ra1, ra2), (rho_a1, rho_a2), (sa1, sa2), eps,
                          (rho_p1, rho_p2), (rho_l1, rho_l2), (eta1, eta2))


def internal_limits(p: PairSpec, c: ContourSpec, x1: np.ndarray | float,
                    x2: np.ndarray | float) -> dict[str, np.ndarray]:
    """g(x1, x2) of every limit of :data:`LIMITS_INTERNAL` (≥ 0: satisfied)."""
    q = internal_arrays(p, x1, x2)
    m, al = p.module, p.alpha
    x1a, _ = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
    z1, z2 = p.z1, p.z2
    rb1, rb2 = m * z1 / 2 * math.cos(al), m * z2 / 2 * math.cos(al)
    ra1, ra2 = q.r_a
    a_w, aw = q.a_w, q.alpha_w
    with np.errstate(invalid="ignore", divide="ignore"):
        aa1 = np.arccos(np.clip(rb1 / ra1, -1.0, 1.0))
        aa2 = np.where(ra2 >= rb2, np.arccos(np.clip(rb2 / ra2, -1.0, 1.0)), np.nan)
        t1 = (np.arccos(np.clip((ra2 ** 2 - ra1 ** 2 - a_w ** 2) / (2 * a_w * ra1), -1, 1))
              + _inv(aa1) - _inv(aw))
        t2 = np.arccos(np.clip((a_w ** 2 + ra2 ** 2 - ra1 ** 2) / (2 * a_w * ra2), -1, 1))
        trochoid = t1 * z1 / z2 + _inv(aw) - _inv(aa2) - t2
        c12 = np.cos(aa1) / np.cos(aa2)
        u1 = np.arcsin(np.sqrt(np.clip((1 - c12 ** 2) / (1 - (z1 / z2) ** 2), 0, 1)))
        u2 = np.arcsin(np.sqrt(np.clip((1 / c12 ** 2 - 1) / ((z2 / z1) ** 2 - 1), 0, 1)))
        trimming = (u1 + _inv(aa1) - _inv(aw)) - (z2 / z1) * (u2 + _inv(aa2) - _inv(aw))
    out = {
        "undercut1": x1a - p.addendum * (p.z_min - z1) / p.z_min,
        "tip1": q.s_a[0] / m - c.tip_land,
        "tip2": q.s_a[1] / m - c.tip_land,
        "contact": q.eps - c.eps_min,
        "interference1": (q.rho_p[0] - np.maximum(q.rho_l[0], 0.0)) / m,
        "interference2": (q.rho_l[1] - q.rho_p[1]) / m,
        "involute2": (ra2 - rb2) / m,
        "trochoid": trochoid,
        "trimming": trimming,
    }
    return {k: np.asarray(out[k], dtype=float) for k in LIMITS_INTERNAL}


def internal_admissible(p: PairSpec, c: ContourSpec, x1: np.ndarray | float,
                        x2: np.ndarray | float) -> np.ndarray:
    """True where every limit of the internal pair holds."""
    vals = internal_limits(p, c, x1, x2)
    ok = np.ones(np.broadcast(np.asarray(x1), np.asarray(x2)).shape, dtype=bool)
    for v in vals.values():
        ok &= np.nan_to_num(v, nan=-1.0) >= 0
    return ok


def internal_contour(p: PairSpec, c: ContourSpec | None = None,
                     x1_range: tuple[float, float] | None = None,
                     x2_range: tuple[float, float] | None = None, n: int = 121) -> Contour:
    """The contour of the internal pair on an n × n grid (x from −1, or the pinion's undercut
    limit − 0.5, up to 1.5); raise :class:`SceneError` when no shift pair is admissible."""
    c = c or ContourSpec()
    if not p.z2 > p.z1:
        raise SceneError(Text("machine.error.internal_teeth", {"z1": p.z1, "z2": p.z2}),
                         key="pair.teeth")
    lo1 = min(-1.0, p.addendum * (p.z_min - p.z1) / p.z_min - 0.5)
    x1 = np.linspace(*(x1_range or (lo1, 1.5)), n)
    x2 = np.linspace(*(x2_range or (-1.0, 1.5)), n)
    lines = {name: _roots(lambda a, b, name=name: internal_limits(p, c, a, b)[name], x1, x2)
             for name in LIMITS_INTERNAL}
    return contour_on_grid(p, c, x1, x2, lines,
                           lambda a, b: internal_admissible(p, c, a, b),
                           lambda a, b: internal_arrays(p, a, b))


@dataclass(frozen=True)
class InternalPair:
    """An internal pair solved: its contour, the shifts (given or the contour's), the pair's
    quantities and every limit's value there."""

    spec: PairSpec
    contour: Contour
    x1: float
    x2: float
    arrays: InternalArrays
    limits: dict[str, float]

    @property
    def admissible(self) -> bool:
        """True when every limit holds at the shifts."""
        return all(math.isfinite(v) and v >= 0 for v in self.limits.values())


def internal_pair(p: PairSpec) -> InternalPair:
    """The contour of the internal pair and the shifts: the contour's recommendation
    (``shift_rule = "contour"``) or the given ones, checked."""
    from ...model.gears import ShiftRule

    c = ContourSpec(p.tip_land, p.eps_min)
    contour = internal_contour(p, c)
    x1, x2 = contour.recommended if p.rule is ShiftRule.CONTOUR else p.shifts
    vals = internal_limits(p, c, x1, x2)
    return InternalPair(p, contour, float(x1), float(x2), internal_arrays(p, x1, x2),
                        {k: float(v) for k, v in vals.items()})
