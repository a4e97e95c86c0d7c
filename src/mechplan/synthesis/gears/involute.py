"""The involute pair: working pressure angle from inv α_w (Newton), centre distance, radii, tooth
thicknesses, contact ratio, pointed-tip and interference checks, and the tooth outlines to draw.

Tooth outlines: true involutes from the start of the generated involute (or the base circle) to the
tip circle; below it a radial line and a fillet ARC of radius ρ_f = c*·m/(1 − sin α) (the cutter tip
radius, reduced when the space is too small) tangent to the root circle — not the generated trochoid.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq

from ...errors import SceneError
from ...model.gears import PairSpec, ShiftRule

TIP_MIN = 0.25        # s_a ≥ 0.25·m: the tip is not pointed


def inv(a: float | np.ndarray) -> float | np.ndarray:
    """The involute function tan α − α."""
    return np.tan(a) - a


def inv_inverse(value: float) -> float:
    """α with tan α − α = value (Newton from the cube-root start; to machine precision)."""
    if value < 0:
        raise ValueError(f"inv α must not be negative (got {value})")
    if value == 0:
        return 0.0
    a = min((3.0 * value) ** (1.0 / 3.0), 1.5)
    for _ in range(60):
        t = math.tan(a)
        step = (t - a - value) / (t * t)
        a -= step
        a = min(max(a, 1e-12), 1.5707)
        if abs(step) < 1e-16 * max(1.0, a):
            break
    return a


def x_min(z: int, addendum: float, z_min: int) -> float:
    """The smallest shift without undercut by the course rule x_min = h_a*(z_min − z)/z_min."""
    return addendum * (z_min - z) / z_min


@dataclass(frozen=True)
class Gear:
    """One gear of the pair (SI)."""

    z: int
    x: float
    r: float          # pitch (reference)
    r_b: float        # base
    r_w: float        # working pitch
    r_a: float        # tip
    r_f: float        # root
    s: float          # tooth thickness on the pitch circle
    s_w: float        # on the working pitch circle
    s_a: float        # on the tip circle
    rho_l: float      # curvature radius where the generated involute starts (< 0: undercut)
    rho_p: float      # curvature radius at the lowest point in contact (active profile start)
    sliding: float    # the largest specific sliding (at the active profile start)


@dataclass(frozen=True)
class Pair:
    """An involute pair laid out."""

    spec: PairSpec
    x1: float
    x2: float
    alpha_w: float
    inv_alpha_w: float
    a: float
    a_w: float
    y: float
    dy: float
    g: float            # N1N2 = a_w sin α_w
    g_active: float     # B1B2
    eps: float          # contact ratio ε_α
    gears: tuple[Gear, Gear]

    @property
    def pointed(self) -> tuple[bool, bool]:
        """True where the tip is thinner than TIP_MIN·m."""
        return tuple(g.s_a < TIP_MIN * self.spec.module for g in self.gears)  # type: ignore[return-value]

    @property
    def interference(self) -> tuple[bool, bool]:
        """True where the mating tip reaches below the start of the generated involute."""
        return tuple(g.rho_p < max(g.rho_l, 0.0) - 1e-12 for g in self.gears)  # type: ignore[return-value]


def _layout(p: PairSpec, x1: float, x2: float) -> Pair:
    m, al, ha, c = p.module, p.alpha, p.addendum, p.clearance
    z1, z2 = p.z1, p.z2
    inv_w = 2 * (x1 + x2) * math.tan(al) / (z1 + z2) + float(inv(al))
    if inv_w <= 0:
        raise SceneError(f"x1 + x2 = {x1 + x2:g} gives inv α_w = {inv_w:.3g} ≤ 0; use larger shifts",
                         key="pair.shifts")
    aw = inv_inverse(inv_w)
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(al) / math.cos(aw)
    y = (a_w - a) / m
    dy = x1 + x2 - y
    g = a_w * math.sin(aw)
    raw: list[dict[str, Any]] = []
    for z, x in ((z1, x1), (z2, x2)):
        r = m * z / 2
        r_b = r * math.cos(al)
        r_a = r + m * (ha + x - dy)
        s = m * (math.pi / 2 + 2 * x * math.tan(al))
        a_a = math.acos(min(1.0, r_b / r_a))
        raw.append({"z": z, "x": x, "r": r, "r_b": r_b, "r_w": r_b / math.cos(aw), "r_a": r_a,
                        "r_f": r - m * (ha + c - x), "s": s,
                        "s_w": 2 * (r_b / math.cos(aw)) * (s / (2 * r) + float(inv(al)) - inv_w),
                        "s_a": 2 * r_a * (s / (2 * r) + float(inv(al)) - float(inv(a_a))),
                        "rho_l": r * math.sin(al) - (ha - x) * m / math.sin(al)})
    tip = [math.sqrt(max(q["r_a"] ** 2 - q["r_b"] ** 2, 0.0)) for q in raw]
    rho_p = (g - tip[1], g - tip[0])        # lowest contact on gear 1 (B1), on gear 2 (B2)
    gears = []
    for j, q in enumerate(raw):
        ratio = (z1 / z2) if j == 0 else (z2 / z1)
        rp = rho_p[j]
        sliding = 1 - ratio * (g - rp) / rp if rp > 0 else math.inf
        gears.append(Gear(**q, rho_p=rp, sliding=sliding))
    g_active = tip[0] + tip[1] - g
    eps = g_active / (math.pi * m * math.cos(al))
    return Pair(p, x1, x2, aw, inv_w, a, a_w, y, dy, g, g_active, eps, (gears[0], gears[1]))


def balanced_shift(p: PairSpec) -> float:
    """x1 (with x2 = −x1) making the largest specific slidings of both gears equal."""
    lo = x_min(p.z1, p.addendum, p.z_min)
    hi = -x_min(p.z2, p.addendum, p.z_min)
    if lo > hi:
        raise SceneError(f"z1 + z2 = {p.z1 + p.z2} is too small for x1 + x2 = 0 without undercut "
                         f"(needs ≥ {2 * p.z_min}); give the shifts", key="pair.shift_rule")

    def diff(x1: float) -> float:
        s = _layout(p, x1, -x1).gears
        return s[0].sliding - s[1].sliding
    f_lo, f_hi = diff(lo), diff(hi)
    if f_lo * f_hi > 0 or not (math.isfinite(f_lo) and math.isfinite(f_hi)):
        return lo if abs(f_lo) < abs(f_hi) else hi
    return float(brentq(diff, lo, hi, xtol=1e-12))


def pair_layout(p: PairSpec) -> Pair:
    """Lay out the pair, choosing the shifts by its rule."""
    if p.rule is ShiftRule.NO_UNDERCUT:
        x1 = max(0.0, x_min(p.z1, p.addendum, p.z_min))
        x2 = max(0.0, x_min(p.z2, p.addendum, p.z_min))
    elif p.rule is ShiftRule.BALANCED:
        x1 = balanced_shift(p)
        x2 = -x1
    else:
        x1, x2 = p.shifts
    return _layout(p, x1, x2)


def flank(gear: Gear, alpha: float, n: int = 40) -> tuple[np.ndarray, np.ndarray]:
    """Radii and polar angles of the right flank's involute of a tooth whose axis is at angle 0.

    θ(r) = −(s/(2r_p) + inv α − inv α_r), α_r = arccos(r_b/r): θ + inv α_r is constant.
    """
    r0 = max(gear.r_b, gear.r_f, math.hypot(gear.r_b, max(gear.rho_l, 0.0)))
    r = np.linspace(r0, gear.r_a, n)
    a_r = np.arccos(np.clip(gear.r_b / r, -1.0, 1.0))
    theta = np.asarray(-(gear.s / (2 * gear.r) + float(inv(alpha)) - inv(a_r)), dtype=float)
    return r, theta


def tooth_outline(gear: Gear, alpha: float, module: float, clearance: float,
                  n: int = 40) -> np.ndarray:
    """One tooth from the middle of the space before it to the middle of the next (x, y), m."""
    r, th = flank(gear, alpha, n)
    half_space = math.pi / gear.z
    rho = min(clearance * module / (1 - math.sin(alpha)), max(r[0] - gear.r_f, 0.0))
    right: list[tuple[float, float]] = []
    th0 = float(th[0])
    if rho > 1e-9:
        rc = gear.r_f + rho
        thc = th0 - math.asin(min(rho / rc, 1.0))
        thc = max(thc, -half_space)
        # arc of the fillet circle from the root circle to the radial line through the flank start
        cx, cy = rc * math.cos(thc), rc * math.sin(thc)
        start = thc + math.pi                          # root-side point: towards the origin
        end = th0 + math.pi / 2                        # tangent point on the radial line
        phis = np.linspace(start, end, 12)
        arc = [(cx + rho * math.cos(f), cy + rho * math.sin(f)) for f in phis]
        root = np.linspace(-half_space, thc, 6)
        right = [(gear.r_f * math.cos(t), gear.r_f * math.sin(t)) for t in root] + arc
    else:
        root = np.linspace(-half_space, th0, 6)
        right = [(gear.r_f * math.cos(t), gear.r_f * math.sin(t)) for t in root]
    right += list(zip((r * np.cos(th)).tolist(), (r * np.sin(th)).tolist()))
    tip = np.linspace(float(th[-1]), -float(th[-1]), 8)[1:-1]
    top = [(gear.r_a * math.cos(t), gear.r_a * math.sin(t)) for t in tip]
    left = [(x, -y) for x, y in reversed(right)]
    return np.asarray(right + top + left)
