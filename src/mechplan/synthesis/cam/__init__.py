"""Cam synthesis: motion laws, diagrams, minimum base radius, the profile by inversion.

:func:`design` takes a :class:`~mechplan.model.cam.CamSpec` and returns a :class:`CamDesign` with
every number the report, the JSON and the sheet present; nothing downstream computes mechanics.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.cam import CamSpec, Contact, Motion, PhaseKind
from .base_radius import (
    Zone,
    flat_r0,
    limit_per_angle,
    max_ratio,
    oscillating_r0,
    translating_zone,
)
from .chords import profile_angles
from .dynamics import DynamicsResult, follower_dynamics
from .graphical import PhaseComparison, compare
from .motion import motion, phase_starts
from .profile import Geometry, Sample, polar, sample

DENSE = 36000          # cam angles per turn for the extremes and the base radius (0.01°)


@dataclass(frozen=True)
class Extreme:
    """A value and the cam angle (rad) where it occurs."""

    value: float
    phi: float


@dataclass(frozen=True)
class CamDesign:
    """A synthesised cam: dimensions, samples, extremes, tables and the profile points."""

    spec: CamSpec
    geometry: Geometry
    r0_min: float                     # from the limits (pressure angle or convexity)
    zone: Zone | None                 # s′–s diagram of a translating knife/roller follower
    dense: Sample                     # at DENSE cam angles
    table: Sample                     # at the table step
    rays: Sample                      # at the ray step (inversion construction)
    alpha_rise: Extreme
    alpha_return: Extreme
    rho_pitch_min: Extreme            # least convex radius of the pitch curve
    rho_profile_min: Extreme          # least |radius| of the working profile
    comparisons: list[PhaseComparison]
    profile_phi: np.ndarray           # cam angles of the profile polyline
    profile_points: np.ndarray        # (N, 2) m, cam frame, closed (first point not repeated)
    chord_error: float                # largest measured chord deviation, m
    face: tuple[float, float] | None = None     # flat face: extent from the axis (−, +), m
    notes: list[tuple[str, dict[str, float]]] = field(default_factory=list)
    dynamics: DynamicsResult | None = None

    @property
    def phase_starts(self) -> np.ndarray:
        """Cam angle at each phase start and at the end (rad)."""
        return phase_starts(self.spec.phases)


def _extreme(values: np.ndarray, phi: np.ndarray, mask: np.ndarray | None = None,
             largest: bool = True) -> Extreme:
    v = np.where(mask, values, np.nan) if mask is not None else values
    if not np.any(np.isfinite(v)):
        return Extreme(float("nan"), float("nan"))
    j = int(np.nanargmax(v) if largest else np.nanargmin(v))
    return Extreme(float(values[j]), float(phi[j]))


def _intervals(mask: np.ndarray, phi: np.ndarray) -> str:
    """Cam-angle intervals (degrees) where ``mask`` holds, as text."""
    out: list[str] = []
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return ""
    splits = np.flatnonzero(np.diff(idx) > 1)
    for run in np.split(idx, splits + 1):
        out.append(f"{math.degrees(phi[run[0]]):.1f}°…{math.degrees(phi[run[-1]]):.1f}°")
    return ", ".join(out)


def _geometry(spec: CamSpec, r0: float, e: float) -> Geometry:
    f = spec.follower
    return Geometry(spec.phases, spec.stroke, spec.sense, f.motion, f.contact, r0, e,
                    f.roller_radius if f.contact is Contact.ROLLER else 0.0, f.arm,
                    f.pivot_distance)


def _base_radius(spec: CamSpec, phi: np.ndarray) -> tuple[float, float, float, Zone | None]:
    """(r0 used, e used, r0 from the limits, zone)."""
    f, lim = spec.follower, spec.limits
    m = motion(spec.phases, spec.stroke, phi)
    given = lim.base_radius
    if f.contact is Contact.FLAT and f.motion is Motion.OSCILLATING:
        return _oscillating_flat_r0(spec, m.s, m.s1, m.s2)
    if f.contact is Contact.FLAT:
        r_min = flat_r0(m.s, m.s2, lim.min_curvature)
        if given is None:
            if not r_min > 0:
                raise SceneError(
                    Text(
                        "errmsg.synthesis_cam.missing_convexity_alone",
                        {"value": f"{r_min * 1000.0:.3f}"},
                    ),
                    file=spec.path,
                    key="limits.base_radius",
                )
            return r_min, 0.0, r_min, None
        if given < r_min:
            raise SceneError(
                Text(
                    "errmsg.synthesis_cam.least_value_mm2",
                    {
                        "value": f"{r_min * 1000.0:.3f}",
                        "value2": f"{lim.min_curvature * 1000.0:g}",
                        "value3": f"{given * 1000.0:g}",
                    },
                ),
                file=spec.path,
                key="limits.base_radius",
            )
        return given, 0.0, r_min, None
    limit = limit_per_angle(spec.phases, phi, lim.alpha_rise, lim.alpha_return)
    if f.motion is Motion.TRANSLATING:
        zone = translating_zone(m.s, m.s1, limit, f.offset)
        e = zone.e
        if given is None:
            return zone.r0, e, zone.r0, zone
        if given <= abs(e):
            raise SceneError(
                Text(
                    "errmsg.synthesis_cam.exceed_offset_e",
                    {"value": f"{abs(e) * 1000.0:g}", "value2": f"{given * 1000.0:g}"},
                ),
                file=spec.path,
                key="limits.base_radius",
            )
        if given < zone.r0 * (1 - 1e-9):
            raise SceneError(
                Text(
                    "errmsg.synthesis_cam.cannot_meet_allowable2",
                    {
                        "value": f"{zone.r0 * 1000.0:.3f}",
                        "value2": f"{e * 1000.0:g}",
                        "value3": f"{given * 1000.0:g}",
                    },
                ),
                file=spec.path,
                key="limits.base_radius",
            )
        return given, e, zone.r0, zone
    g0 = _geometry(spec, f.arm, 0.0)
    coarse = phi[::10]
    r_osc = oscillating_r0(g0, coarse, limit[::10])
    if r_osc is None:
        raise SceneError(Text("errmsg.synthesis_cam.cannot_met_any"), file=spec.path,
                         key="limits.pressure_angle_rise")

    def fails(r: float) -> bool:
        return max_ratio(_geometry(spec, r, 0.0), phi, limit, m) > 1.0 + 1e-12

    # refine on the dense grid: bracket, then bisect
    if fails(r_osc):
        lo, step = r_osc, 1e-7 * r_osc
        while fails(lo + step):
            lo, step = lo + step, 2 * step
        hi = lo + step
        while hi - lo > 1e-10 * hi:
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if fails(mid) else (lo, mid)
        r_osc = hi
    r_min = r_osc
    if given is None:
        return r_min, 0.0, r_min, None
    if not abs(f.pivot_distance - f.arm) < given < f.pivot_distance + f.arm:
        raise SceneError(
            Text("errmsg.synthesis_cam.lie_between_l", {"value": f"{given * 1000.0:g}"}),
            file=spec.path,
            key="limits.base_radius",
        )
    if max_ratio(_geometry(spec, given, 0.0), phi, limit, m) > 1.0 + 1e-9:
        raise SceneError(
            Text(
                "errmsg.synthesis_cam.cannot_meet_allowable",
                {"value": f"{r_min * 1000.0:.3f}", "value2": f"{given * 1000.0:g}"},
            ),
            file=spec.path,
            key="limits.base_radius",
        )
    return given, 0.0, r_min, None


def _oscillating_flat_r0(spec: CamSpec, s: np.ndarray, s1: np.ndarray, s2: np.ndarray
                         ) -> tuple[float, float, float, Zone | None]:
    """(r0 used, 0, least r0, None) of an oscillating flat-faced follower's cam."""
    from .oscillating_flat import least_r0

    f, lim = spec.follower, spec.limits
    if np.min(s1) <= -1.0:
        raise SceneError(
            Text("errmsg.synthesis_cam.follower_swings_back", {"s1": f"{float(np.min(s1)):.4g}"}),
            file=spec.path,
            key="motion.phases",
        )
    r_min = least_r0(f.pivot_distance, s, s1, s2, lim.min_curvature)
    if r_min is None:
        raise SceneError(
            Text(
                "errmsg.synthesis_cam.no_base_radius", {"value": f"{f.pivot_distance * 1000.0:g}"}
            ),
            file=spec.path,
            key="follower.pivot_distance",
        )
    given = lim.base_radius
    if given is None:
        return r_min, 0.0, r_min, None
    if not r_min * (1 - 1e-9) <= given < f.pivot_distance:
        raise SceneError(
            Text(
                "errmsg.synthesis_cam.least_value_mm",
                {
                    "value": f"{r_min * 1000.0:.3f}",
                    "value2": f"{f.pivot_distance * 1000.0:g}",
                    "value3": f"{given * 1000.0:g}",
                },
            ),
            file=spec.path,
            key="limits.base_radius",
        )
    return given, 0.0, r_min, None


def design(spec: CamSpec) -> CamDesign:
    """Synthesise the cam of a scene; raise :class:`SceneError` naming the key when impossible."""
    phi = np.linspace(0.0, 2 * math.pi, DENSE, endpoint=False)
    r0, e, r_min, zone = _base_radius(spec, phi)
    g = _geometry(spec, r0, e)
    dense = sample(g, phi)
    kinds = np.array([p.kind for p in spec.phases])
    from .motion import phase_of

    kind_at = kinds[phase_of(spec.phases, phi)]
    rise = kind_at == PhaseKind.RISE
    ret = kind_at == PhaseKind.RETURN
    convex = dense.radius_pitch > 0
    roller = g.roller
    if spec.follower.contact is Contact.ROLLER:
        bad = convex & (dense.radius_pitch <= roller)
        if bad.any():
            worst = _extreme(dense.radius_pitch, phi, convex, largest=False)
            raise SceneError(
                Text(
                    "errmsg.synthesis_cam.less_than_least",
                    {
                        "value": f"{worst.value * 1000.0:.3f}",
                        "phi": f"{math.degrees(worst.phi):.2f}",
                        "value2": f"{roller * 1000.0:g}",
                        "bad": str(_intervals(bad, phi)),
                    },
                ),
                file=spec.path,
                key="follower.roller_radius",
            )
    if spec.follower.contact is Contact.FLAT and np.any(dense.radius <= 0):
        raise SceneError(
            Text(
                "errmsg.synthesis_cam.gives_profile_that",
                {"value": str(_intervals(dense.radius <= 0, phi))},
            ),
            file=spec.path,
            key="limits.base_radius",
        )
    alpha_rise = _extreme(np.abs(dense.alpha), phi, rise)
    alpha_return = _extreme(np.abs(dense.alpha), phi, ret)
    rho_p = _extreme(dense.radius_pitch, phi, convex, largest=False)
    rho_w = _extreme(np.abs(dense.radius), phi, None, largest=False)
    d = spec.drawing
    tphi = np.arange(0.0, 2 * math.pi - 1e-9, d.table_step)
    rphi = np.arange(0.0, 2 * math.pi - 1e-9, d.ray_step)
    angles, err = profile_angles(g, d.chord_error)
    points = sample(g, angles).profile
    face = None
    notes: list[tuple[str, dict[str, float]]] = []
    if spec.follower.contact is Contact.FLAT:
        margin = spec.follower.face_margin
        if spec.follower.motion is Motion.OSCILLATING:          # distances from the pivot
            pivot = np.array([spec.sense * spec.follower.pivot_distance, 0.0])
            along = np.hypot(*(dense.follower - pivot).T)
            face = (float(along.min()) - margin, float(along.max()) + margin)
        else:
            face = (float(dense.s1.min()) - margin, float(dense.s1.max()) + margin)
    if spec.follower.contact is Contact.ROLLER:
        if roller > 0.4 * r0:
            notes.append(("cam.note.roller_r0",
                          {"rr_mm": roller * 1e3, "limit_mm": 0.4 * r0 * 1e3}))
        if roller > 0.8 * rho_p.value:
            notes.append(("cam.note.roller_rho", {"rr_mm": roller * 1e3,
                                                  "limit_mm": 0.8 * rho_p.value * 1e3}))
    alpha = None
    if spec.follower.motion is Motion.TRANSLATING:
        alpha = (np.zeros_like(phi) if spec.follower.contact is Contact.FLAT
                 else np.asarray(dense.alpha))
    try:
        dyn = follower_dynamics(spec, phi, alpha)
    except SceneError as exc:
        raise SceneError(exc.detail, file=spec.path, key=exc.key) from None
    return CamDesign(spec, g, r_min, zone, dense, sample(g, tphi), sample(g, rphi), alpha_rise,
                     alpha_return, rho_p, rho_w, compare(spec.phases, spec.stroke), angles, points,
                     err, face, notes, dyn)


def profile_table(table: Sample) -> list[dict[str, float]]:
    """Rows of the profile table: φ, s, s′, s″, α, polar (ρ, θ) and Cartesian (x, y) of the
    profile."""
    rho, theta = polar(table.profile)
    rows = []
    for i in range(table.phi.size):
        rows.append({"phi": float(table.phi[i]), "s": float(table.s[i]), "s1": float(table.s1[i]),
                     "s2": float(table.s2[i]), "alpha": float(table.alpha[i]),
                     "rho": float(rho[i]), "theta": float(theta[i]),
                     "x": float(table.profile[i, 0]), "y": float(table.profile[i, 1]),
                     "x_pitch": float(table.pitch[i, 0]), "y_pitch": float(table.pitch[i, 1]),
                     "radius": float(table.radius[i])})
    return rows


__all__ = ["CamDesign", "Extreme", "design", "motion", "profile_table", "sample"]
