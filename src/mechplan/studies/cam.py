"""A cam scene solved: report, JSON with the tables, the cam sheet, the profile DXF, its answers."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..i18n import message, number
from ..model.cam import Contact, Law, Motion, PhaseKind
from ..sheet.cam import table_rows, units_of
from ..sheet.cam_dynamics import dynamics_lines
from ..synthesis.cam import CamDesign, design, profile_table
from .answers import Keys, Own, Written

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet


def law_text(phase_law: Law | None, blend: float, lang: str) -> str:
    """The law's name in ``lang``."""
    if phase_law is None:
        return ""
    return message(f"cam.law.{phase_law.value}", lang, blend=number(blend, 2, lang))


def follower_text(d: CamDesign, lang: str) -> str:
    """"Follower: translating follower, roller …; offset e = … mm"."""
    f, g = d.spec.follower, d.geometry
    contact = message(f"cam.contact.{f.contact.value}", lang,
                      rr=number(f.roller_radius * 1e3, 1, lang))
    where = (message("cam.offset", lang, e=number(g.e * 1e3, 2, lang))
             if f.motion is Motion.TRANSLATING
             else message("cam.arm", lang, l=number(f.arm * 1e3, 1, lang),
                          a=number(f.pivot_distance * 1e3, 1, lang)))
    if f.motion is Motion.OSCILLATING and f.contact is Contact.FLAT:
        where = message("gearcam.cam.pivot_face", lang, a=number(f.pivot_distance * 1e3, 1, lang))
    return message("cam.report.follower", lang,
                   motion=message(f"cam.motion.{f.motion.value}", lang),
                   contact=contact, where=where)


@dataclass(frozen=True)
class CamStudy:
    """A cam synthesised from its scene."""

    design: CamDesign

    @property
    def language(self) -> str:
        """The scene's language."""
        return self.design.spec.language

    def report(self, language: str | None = None) -> str:
        """Return the text report."""
        lang = language or self.language
        d, spec = self.design, self.design.spec
        u = units_of(d, lang)
        deg = math.degrees
        lines = [message("cam.title", lang, title=spec.title), "", follower_text(d, lang)]
        translating = spec.follower.motion is Motion.TRANSLATING
        stroke = (f"h = {number(spec.stroke * 1e3, 2, lang)} {u.u0}" if translating
                  else f"ψmax = {number(deg(spec.stroke), 2, lang)}°")
        lines.append(message("cam.report.program", lang, stroke=stroke,
                             omega=number(spec.omega, 2, lang),
                             rpm=number(spec.omega * 30 / math.pi, 1, lang),
                             sense=message("cam.sense." + ("ccw" if spec.sense > 0 else "cw"),
                                           lang)))
        starts = d.phase_starts
        w = spec.omega
        for i, p in enumerate(spec.phases):
            common = {"n": i + 1, "kind": message(f"cam.phase.{p.kind.value}", lang),
                          "start": number(deg(starts[i]), 1, lang),
                          "end": number(deg(starts[i + 1]), 1, lang),
                          "angle": number(deg(p.angle), 1, lang)}
            if p.law is None:
                lines.append("  " + message("cam.report.dwell", lang, **common))
            else:
                lines.append("  " + message("cam.report.phase", lang,
                                            law=law_text(p.law, p.blend, lang), **common))
        lines.append("")
        idx = np.searchsorted(starts, np.mod(d.dense.phi, 2 * math.pi), side="right") - 1
        for i, p in enumerate(spec.phases):
            if p.law is None:
                continue
            m = idx == i
            s1 = float(np.max(np.abs(d.dense.s1[m])))
            s2 = float(np.max(np.abs(d.dense.s2[m])))
            lines.append(message("cam.report.peaks", lang,
                                 kind=message(f"cam.phase.{p.kind.value}", lang),
                                 s1=number(s1 * u.f1, 3, lang), u1=u.u1,
                                 s2=number(s2 * u.f1, 3, lang), u2=u.u2, v=number(s1 * w, 4, lang),
                                 uv=u.uv, a=number(s2 * w * w, 2, lang), ua=u.ua))
        lines.append("")
        lines.append(message("cam.report.graphical_head", lang, parts=12))
        for c in d.comparisons:
            lines.append("  " + message(
                "cam.report.graphical", lang, kind=message(f"cam.phase.{c.kind.value}", lang),
                d1=number(c.d_s1_chords * u.f1, 4, lang), d2=number(c.d_s2_chords * u.f1, 4, lang),
                d3=number(c.d_s1_integral * u.f1, 4, lang),
                d4=number(c.d_s_integral * u.f0, 4, lang),
                u0=u.u0, u1=u.u1, u2=u.u2))
        lines.append("")
        lim = spec.limits
        swinging_flat = translating is False and spec.follower.contact is Contact.FLAT
        if swinging_flat:
            lines.append(message("gearcam.cam.r0_convex_osc", lang,
                                 rho=number(lim.min_curvature * 1e3, 2, lang),
                                 r0=number(d.r0_min * 1e3, 3, lang)))
        elif spec.follower.contact is Contact.FLAT:
            lines.append(message("cam.report.r0_convex", lang,
                                 rho=number(lim.min_curvature * 1e3, 2, lang),
                                 r0=number(d.r0_min * 1e3, 3, lang)))
        else:
            text = message("cam.report.r0_pressure", lang, ar=number(deg(lim.alpha_rise), 1, lang),
                           ad=number(deg(lim.alpha_return), 1, lang),
                           r0=number(d.r0_min * 1e3, 3, lang),
                           e=number(d.geometry.e * 1e3, 3, lang))
            if spec.follower.offset is None and spec.follower.motion is Motion.TRANSLATING:
                text += " — " + message("cam.report.r0_best", lang)
            lines.append(text)
        g = d.geometry
        if spec.follower.contact is Contact.FLAT:
            lines.append(message("cam.report.r0_flat", lang, r0=number(g.r0 * 1e3, 3, lang)))
        else:
            lines.append(message("cam.report.r0_used", lang, r0=number(g.r0 * 1e3, 3, lang),
                                 rw=number((g.r0 - g.roller) * 1e3, 3, lang)))
        if spec.follower.contact is not Contact.FLAT:
            lines.append(message("cam.report.alpha", lang,
                                 ar=number(deg(d.alpha_rise.value), 2, lang),
                                 pr=number(deg(d.alpha_rise.phi), 2, lang),
                                 ad=number(deg(d.alpha_return.value), 2, lang),
                                 pd=number(deg(d.alpha_return.phi), 2, lang)))
        lines.append(message("cam.report.rho", lang,
                             rp=number(d.rho_pitch_min.value * 1e3, 3, lang),
                             pp=number(deg(d.rho_pitch_min.phi), 2, lang),
                             rw=number(d.rho_profile_min.value * 1e3, 3, lang),
                             pw=number(deg(d.rho_profile_min.phi), 2, lang)))
        if d.face is not None:
            lo, hi = d.face
            lines.append(message("gearcam.cam.face_osc" if swinging_flat else "cam.report.face",
                                 lang, lo=number(lo * 1e3, 2, lang), hi=number(hi * 1e3, 2, lang),
                                 w=number((hi - lo) * 1e3, 2, lang)))
        lines.append(message("cam.report.profile", lang, n=len(d.profile_points),
                             err=number(d.chord_error * 1e6, 3, lang),
                             tol=number(spec.drawing.chord_error * 1e6, 3, lang)))
        for msgid, values in d.notes:
            lines.append(message(msgid, lang, **{k: number(v, 2, lang) for k, v in values.items()}))
        lines.extend(dynamics_lines(d, lang))
        lines.append("")
        lines.append(message("cam.report.table", lang,
                             step=number(deg(spec.drawing.table_step), 1, lang)))
        lines.extend(self.table_lines(lang))
        return "\n".join(lines) + "\n"

    def table_rows(self, lang: str) -> tuple[list[str], list[list[str]]]:
        """Heading and rows of the profile table, formatted for ``lang``."""
        return table_rows(self.design, lang)

    def table_lines(self, lang: str) -> list[str]:
        """The profile table as aligned text."""
        head, rows = self.table_rows(lang)
        widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(head)]
        out = ["  ".join(h.rjust(w) for h, w in zip(head, widths))]
        out += ["  ".join(c.rjust(w) for c, w in zip(r, widths)) for r in rows]
        return out

    def to_json(self) -> dict[str, Any]:
        """The results and tables in SI units (m, rad, s)."""
        d, spec = self.design, self.design.spec
        g = d.geometry
        phases = []
        starts = d.phase_starts
        for i, p in enumerate(spec.phases):
            phases.append({"kind": p.kind.value, "start": float(starts[i]), "angle": p.angle,
                           "law": p.law.value if p.law else None})
        zone = None
        if d.zone is not None:
            zone = {"centre": list(d.zone.centre), "r0": d.zone.r0, "e": d.zone.e,
                    "half_planes": [{"normal": list(h.n), "c": h.c, "through": list(h.at),
                                     "limit": h.limit} for h in d.zone.planes]}
        return {
            "kind": "cam", "title": spec.title,
            "follower": {"motion": spec.follower.motion.value,
                         "contact": spec.follower.contact.value,
                         "offset": g.e, "roller_radius": g.roller, "arm": g.arm,
                         "pivot_distance": g.pivot},
            "stroke": spec.stroke, "omega": spec.omega, "sense": "ccw" if spec.sense > 0 else "cw",
            "phases": phases,
            "base_radius": {"minimum": d.r0_min, "used": g.r0, "offset": g.e,
                            "working_profile": g.r0 - g.roller},
            "s_prime_s_zone": zone,
            "pressure_angle_max": {"rise": [d.alpha_rise.value, d.alpha_rise.phi],
                                   "return": [d.alpha_return.value, d.alpha_return.phi]},
            "radius_of_curvature_min": {
                "pitch": [d.rho_pitch_min.value, d.rho_pitch_min.phi],
                "profile": [d.rho_profile_min.value, d.rho_profile_min.phi]},
            "face": list(d.face) if d.face else None,
            "graphical": [{"phase": c.index, "kind": c.kind.value, "d_s1_chords": c.d_s1_chords,
                           "d_s2_chords": c.d_s2_chords, "d_s1_integral": c.d_s1_integral,
                           "d_s_integral": c.d_s_integral} for c in d.comparisons],
            "table": profile_table(d.table),
            "profile": {"chord_error": d.chord_error, "bound": spec.drawing.chord_error,
                        "points": d.profile_points.tolist()},
            "notes": [k for k, _ in d.notes],
            "dynamics": _dynamics_json(d),
        }

    def answers(self) -> Keys:
        """The exact answers: radii, extreme angles, and s, s′, s″, α at any cam angle."""
        from ..synthesis.cam.profile import sample

        g = self.design.geometry
        doc = self.to_json()
        k = Keys("cam", study=doc, geometry=g, formulas=_own_cam)
        base, pa = doc["base_radius"], doc["pressure_angle_max"]
        rho = doc["radius_of_curvature_min"]
        k.scalars = {"r0": base["used"], "e": base["offset"], "r_profile": base["working_profile"],
                     "alpha_max_rise": pa["rise"][0], "alpha_max_return": pa["return"][0],
                     "alpha_max": max(pa["rise"][0], pa["return"][0]),
                     "rho_min": abs(rho["profile"][0]), "rho_min_pitch": abs(rho["pitch"][0])}
        for name in ("s1", "s2"):
            k.spans[name] = max(abs(r[name]) for r in doc["table"])
        k.spans["s"], k.spans["alpha"] = g.stroke, math.radians(50.0)

        def at(phi_deg: float) -> dict[str, float]:
            m = sample(g, math.radians(phi_deg))
            out = {"s": float(m.s[0]), "s1": float(m.s1[0]), "s2": float(m.s2[0])}
            return out | ({"alpha": abs(float(m.alpha[0]))} if _has_alpha(doc) else {})

        k.any_angle = at
        if doc["follower"]["motion"] != "translating":       # the follower's s is an angle ψ
            k.dimensions = {"s": "angle", "s1": "dimensionless", "s2": "dimensionless"}
        return k

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        """The cam sheet(s)."""
        from ..sheet.cam import cam_sheets

        lang = language or self.language
        return cam_sheets(self.design, self.summary(lang), self.table_rows(lang), size, standard,
                          lang, name)

    def summary(self, lang: str) -> list[str]:
        """The result sentences of the report (base radius, angles, curvature, profile)."""
        lines = self.report(lang).splitlines()
        first = next(i for i, ln in enumerate(lines) if "r0" in ln)
        last = next(i for i, ln in enumerate(lines) if i > first and not ln.strip())
        return lines[first:last]

    def write_files(self, out_dir: str | Path, name: str) -> list[Path]:
        """Write the working profile as its own DXF, ``<name>-profile.dxf``."""
        from ..render.profile_dxf import write_profile_dxf

        pts = [(float(x) * 1e3, float(y) * 1e3) for x, y in self.design.profile_points]
        return [write_profile_dxf(pts, Path(out_dir) / f"{name}-profile.dxf")]


def _dynamics_json(d: CamDesign) -> dict[str, Any] | None:
    """The follower's dynamics in SI (N or N·m along the follower, rad/s, N·m on the cam)."""
    r = d.dynamics
    if r is None:
        return None
    step = max(1, r.phi.size // 360)
    return {"stiffness": r.stiffness, "preload": r.preload, "spring_max": r.spring_max,
            "spring_chosen": r.chosen, "speed": r.speed, "speed_max": r.speed_max,
            "jump_speed": r.jump_speed if math.isfinite(r.jump_speed) else None,
            "jump_phi": r.jump_phi if math.isfinite(r.jump_phi) else None,
            "contact_min": list(r.contact_min),
            "torque_max": [r.torque_extremes[0], r.torque_extremes[1]],
            "torque_min": [r.torque_extremes[2], r.torque_extremes[3]],
            "torque_mean": r.torque_mean,
            "elastic": None if r.elastic is None else {
                "natural_frequency": r.elastic.natural_frequency,
                "damping_ratio": r.elastic.damping_ratio, "error_max": r.elastic.error_max,
                "residual": [{"dwell": k, "phi": p, "amplitude": a}
                             for k, p, a in r.elastic.residual],
                "residual_first_turn": [{"dwell": k, "phi": p, "amplitude": a}
                                        for k, p, a in r.elastic.first_residual]},
            "cycle": {"phi": r.phi[::step].tolist(), "contact": r.contact[::step].tolist(),
                      "contact_speed_max": r.contact_max_speed[::step].tolist(),
                      "normal": r.normal[::step].tolist() if r.normal is not None else None,
                      "torque": r.torque[::step].tolist()}}


def solve_cam(text: str, file: str) -> CamStudy:
    """Parse and synthesise a cam scene."""
    from ..scene.cam import parse_cam

    return CamStudy(design(parse_cam(text, file)))


# -- answers ------------------------------------------------------------------------------------
def _has_alpha(doc: dict[str, Any]) -> bool:
    """Pressure angles per angle are graded for a translating knife or roller follower."""
    return doc["follower"]["motion"] == "translating" and doc["follower"]["contact"] != "flat"


def _own_cam(k: Keys, name: str, phi: float | None, w: Written) -> Own | None:
    """The working radius and the pressure angle from the student's own r₀, e, s, s′."""
    from ..synthesis.cam.profile import pressure_angle

    doc = k.study
    r0 = w.get(("r0", None)) or doc["base_radius"]["used"]
    if name == "r_profile" and ("r0", None) in w and doc["follower"]["contact"] == "roller":
        return w[("r0", None)] - doc["follower"]["roller_radius"], "r = r₀ − r_р", ("r0",)
    s, s1 = w.get(("s", phi)), w.get(("s1", phi))
    if name == "alpha" and phi is not None and _has_alpha(doc) and s is not None and \
            s1 is not None:       # the engine's pressure angle at the student's own r₀, e, s, s′
        g = replace(k.geometry, r0=r0, e=w.get(("e", None), doc["base_radius"]["offset"]))
        alpha = pressure_angle(g, np.array([s]), np.array([s1]), np.zeros(1))
        return abs(float(alpha[0])), "tg α = (s′ ∓ e)/(√(r₀² − e²) + s)", ("s", "s1")
    return None


__all__ = ["CamStudy", "PhaseKind", "solve_cam"]
