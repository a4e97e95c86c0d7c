"""A linkage synthesis solved: the construction protocol, the conditions, the round trip through
the analysis (the produced scene solved by mechplan gives back K and ψ or H), report, JSON,
the synthesis sheet and the mechanism scene file."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..i18n import message, number, significant
from ..model.synthesis import SynthesisSpec
from ..scene.writer import to_toml
from ..synthesis.linkage import LinkageDesign, k_of_theta, synthesise
from ..synthesis.linkage.design import Step
from .answers import Keys

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet

ANGLES = ("theta", "psi", "angle", "gamma", "psi0", "alpha", "phi", "phi0", "dphi", "dpsi")
RATIOS = ("k", "lam", "x0", "x1", "k1", "k2", "k3")
#: values that are numbers (4 decimals) in some sentences and lengths in others
NUMBERS_OF = {"synth.fg.point": ("x", "y")}
#: crank positions over a turn where the analysis samples the transmission angle
CYCLE_SAMPLES = 3600


def say(step: Step, lang: str) -> str:
    """A protocol sentence with its values in mm and degrees."""
    values: dict[str, str] = {}
    for key, v in step.values.items():
        if key in ANGLES:
            values[key] = number(math.degrees(v), 4, lang)
        elif key in RATIOS or key in NUMBERS_OF.get(step.msgid, ()):
            values[key] = number(v, 4, lang)
        elif key == "n":
            values[key] = str(int(v))
        else:
            values[key] = number(v * 1e3, 3, lang)
    return message(step.msgid, lang, **values)


@dataclass(frozen=True)
class RoundTrip:
    """What mechplan's own analysis of the produced scene gives: K, ψ (rad) or H (m), the
    transmission angle's minimum over a sampled cycle (rad) and the crank angle there."""

    k: float
    output: float
    gamma_min: float = math.nan
    gamma_phi: float = math.nan
    extremes_phi: tuple[float, ...] = ()
    structural_max: float = math.nan    # a function generator: the largest |Δy| the engine gives


def round_trip(d: LinkageDesign) -> RoundTrip:
    """Solve the produced scene with the engine; find the output's extremes and γ over a turn."""
    from ..construct.extremes import extreme_positions
    from ..scene import parse_scene
    from ..solve import solve

    scene = parse_scene(to_toml(d.scene), "<synthesised>")
    if d.output_kind == "function":
        return _function_round_trip(d, scene)
    if d.output_kind == "guidance":
        return _guidance_round_trip(d, scene)
    if d.output_kind == "path":
        return _path_round_trip(d, scene)
    sol = solve(scene, count=1)
    mech = scene.mechanism
    ex = extreme_positions(sol.construction, mech, d.output)
    if len(ex) != 2:
        raise ValueError(f"the synthesised output {d.output} has {len(ex)} extreme positions")
    a = (ex[1].phi - ex[0].phi) % (2 * math.pi)
    slow = max(a, 2 * math.pi - a)
    k = slow / (2 * math.pi - slow)
    out = abs(ex[1].value - ex[0].value)
    phi = np.arange(CYCLE_SAMPLES) * (2 * math.pi / CYCLE_SAMPLES)
    ev = sol.construction.evaluate(phi)
    b = ev["pos.B"]
    c = ev["pos.C"] if "pos.C" in sol.construction.steps else None
    if d.problem == "crank_rocker":
        ref = np.array([d.lengths["d"], 0.0]) - c       # C → D (D on the +x axis)
    elif d.problem in ("slider_crank", "shaper"):
        ref = np.tile([1.0, 0.0], (phi.size, 1))
    else:
        ref = None
    if ref is not None and c is not None:
        u = b - c
        cos = np.abs(np.sum(u * ref, axis=1)) / (np.hypot(*u.T) * np.hypot(*ref.T))
        gam = np.arccos(np.clip(cos, 0.0, 1.0))
        if d.problem != "crank_rocker":       # γ = 90° − the pressure angle on a guide
            gam = math.pi / 2 - gam
        i = int(np.argmin(gam))
        g_min, g_phi = float(gam[i]), float(phi[i])
    else:
        g_min = g_phi = math.nan
    return RoundTrip(k, out, g_min, g_phi, (ex[0].phi, ex[1].phi))


def _function_round_trip(d: LinkageDesign, scene: Any) -> RoundTrip:
    """The function generator solved by the engine at its precision points (``output``: the
    largest miss of ψ, rad) and along its range (``structural_max``: the largest |Δy|)."""
    from ..solve import solve

    c = d.conditions
    sol = solve(scene)
    dd = np.array([d.lengths["d"], 0.0])

    def psi_at(phi: np.ndarray) -> np.ndarray:
        cp = sol.construction.evaluate(phi)["pos.C"] - dd
        return np.arctan2(cp[:, 1], cp[:, 0])

    def wrapped(x: np.ndarray) -> np.ndarray:
        return np.angle(np.exp(1j * x))

    miss = wrapped(psi_at(np.array(c["precision_phi"])) - np.array(c["precision_psi"]))
    samples = np.array(c["structural_error"])
    dy = wrapped(psi_at(samples[:, 1]) - samples[:, 2]) * c["y_per_rad"]
    return RoundTrip(math.nan, float(np.max(np.abs(miss))),
                     structural_max=float(np.max(np.abs(dy))))


def _guidance_round_trip(d: LinkageDesign, scene: Any) -> RoundTrip:
    """The guided linkage solved by the engine at its three crank angles: the largest distance of
    B and C from the given positions (m) is ``output``."""
    from ..solve import solve

    c = d.conditions
    sol = solve(scene)
    ev = sol.construction.evaluate(np.array(c["precision_phi"]))
    miss = max(float(np.max(np.hypot(*(ev["pos.B"] - np.array(c["positions_b"])).T))),
               float(np.max(np.hypot(*(ev["pos.C"] - np.array(c["positions_c"])).T))))
    return RoundTrip(math.nan, miss)


def _path_round_trip(d: LinkageDesign, scene: Any) -> RoundTrip:
    """The path generator solved by the engine at its crank angles: the largest distance of the
    coupler point E from the given points (m) is ``output``."""
    from ..solve import solve

    c = d.conditions
    ev = solve(scene).construction.evaluate(np.array(c["precision_phi"]))
    miss = np.hypot(*(ev["pos.E"] - np.array(c["path_points"])).T)
    return RoundTrip(math.nan, float(np.max(miss)))


@dataclass(frozen=True)
class SynthesisStudy:
    """A linkage synthesised from its scene, and checked by analysing what it produced."""

    spec: SynthesisSpec
    design: LinkageDesign
    check: RoundTrip

    @property
    def language(self) -> str:
        """The scene's language."""
        return self.spec.language

    def title(self, lang: str) -> str:
        """The scene's title (or the problem's name)."""
        return self.spec.title or message(f"synth.problem.{self.spec.problem}", lang)

    def protocol_lines(self, lang: str) -> list[str]:
        """The construction protocol, numbered."""
        return [f"{i}. {say(s, lang)}" for i, s in enumerate(self.design.protocol, start=1)]

    def family_lines(self, lang: str) -> list[str]:
        """A few members of the family along the construction circle with their γmin."""
        fam = self.design.family
        if not fam:
            return []
        lines = [message(f"synth.family.head_{self.design.problem}", lang)]
        for m in fam[:: max(1, len(fam) // 10)]:
            n = {k: number(v * 1e3, 2, lang) for k, v in m.lengths.items()}
            g = number(math.degrees(m.gamma_min), 2, lang) if m.valid else "—"
            lines.append("  " + message(f"synth.family.row_{self.design.problem}", lang,
                                        gamma=g, **n))
        return lines

    def result_lines(self, lang: str) -> list[str]:
        """The chosen dimensions, the conditions and the round trip, one sentence each."""
        d, c, rt = self.design, self.design.conditions, self.check
        deg = math.degrees
        mm = {k: number(v * 1e3, 3, lang) for k, v in d.lengths.items()}
        lines = [message(f"synth.result.{d.problem}", lang, **mm)]
        if d.problem == "function":
            return lines + self.function_lines(lang)
        if d.problem == "guidance":
            return lines + self.guidance_lines(lang)
        if d.problem == "path":
            return lines + self.guidance_lines(lang)[:-1] + self.path_lines(lang)
        if "grashof" in c:
            lines.append(message("synth.result.grashof", lang,
                                 margin=number(c["grashof_margin"] * 1e3, 3, lang)))
        elif d.problem == "coulisse":
            lines.append(message("synth.result.coulisse_angle", lang))
        if "gamma_min_at_phi" in c:
            lines.append(message("synth.result.gamma", lang,
                                 gamma=number(deg(c["gamma_min"]), 3, lang),
                                 phi=number(deg(c["gamma_min_at_phi"]), 1, lang)))
        elif "pressure_max" in c:
            kind = "slider" if d.problem == "slider_crank" else "shaper"
            values = {"phi": number(deg(c["pressure_max_at_phi"]), 1, lang)} \
                if kind == "slider" else {}
            lines.append(message(f"synth.result.gamma_{kind}", lang,
                                 gamma=number(deg(c["gamma_min"]), 3, lang),
                                 alpha=number(deg(c["pressure_max"]), 3, lang), **values))
        lines.append(message("synth.result.dead", lang,
                             p1=number(deg(c["dead_centres_phi"][0]), 3, lang),
                             p2=number(deg(c["dead_centres_phi"][1]), 3, lang)))
        lines.append(message("synth.result.working", lang,
                             frm=c["working_from"],
                             phi=number(deg(c["working_stroke_phi"]), 3, lang),
                             sense=message("synth.sense." + ("ccw" if self.spec.sense > 0
                                                             else "cw"), lang)))
        asked = (number(deg(d.asked_output), 4, lang) + "°" if d.output_kind == "angle"
                 else number(d.asked_output * 1e3, 4, lang))
        got = (number(deg(rt.output), 4, lang) + "°" if d.output_kind == "angle"
               else number(rt.output * 1e3, 4, lang))
        lines.append(message(f"synth.result.round_trip_{d.output_kind}", lang,
                             k=number(rt.k, 9, lang), k_asked=number(d.k, 9, lang),
                             got=got, asked=asked,
                             dk=number(abs(rt.k - d.k) * 1e12, 3, lang)))
        if rt.gamma_min == rt.gamma_min:
            lines.append(message("synth.result.gamma_sampled", lang,
                                 gamma=number(deg(rt.gamma_min), 3, lang),
                                 phi=number(deg(rt.gamma_phi), 1, lang),
                                 n=CYCLE_SAMPLES))
        return lines

    def guidance_lines(self, lang: str) -> list[str]:
        """A guided linkage's type, defects, sense and round trip."""
        c, rt = self.design.conditions, self.check
        lines = [message("synth.gd.crank_" + ("yes" if c["crank"] else "no"), lang)]
        for defect in ("branch_defect", "order_defect", "circuit_defect"):
            lines.append(message(f"synth.gd.{defect}_{'yes' if c[defect] else 'no'}", lang))
        lines.append(message("synth.gd.sense", lang,
                             sense=message("synth.sense." + ("ccw" if c["sense"] > 0 else "cw"),
                                           lang),
                             phis=", ".join(number(math.degrees(p), 3, lang) + "°"
                                            for p in c["precision_phi"])))
        lines.append(message("synth.gd.round_trip", lang,
                             miss=significant(rt.output * 1e3, 3, lang)))
        return lines

    def path_lines(self, lang: str) -> list[str]:
        """A path generator's miss (its own and the engine's round trip)."""
        c, rt = self.design.conditions, self.check
        own = "synth.pg.miss" if c["exact"] else "synth.pg.miss_lsq"
        return [message(own, lang, miss=significant(c["path_miss"] * 1e3, 3, lang)),
                message("synth.pg.round_trip", lang, miss=significant(rt.output * 1e3, 3, lang))]

    def function_lines(self, lang: str) -> list[str]:
        """A function generator's linkage type, defects, structural error and round trip."""
        d, c, rt = self.design, self.design.conditions, self.check
        n = d.lengths
        if not c["grashof"]:
            kind = "non_grashof"
        elif min(n.values()) == n["a"]:
            kind = "crank_rocker"
        elif min(n.values()) == n["d"]:
            kind = "double_crank"
        else:
            kind = "double_rocker"
        lines = [message(f"synth.fg.kind_{kind}", lang)]
        for defect in ("branch_defect", "circuit_defect"):
            lines.append(message(f"synth.fg.{defect}_{'yes' if c[defect] else 'no'}", lang))
        exact = len(c["precision_x"]) == 3
        lines.append(message("synth.fg.error" if exact else "synth.fg.error_lsq", lang,
                             e=significant(c["structural_error_max"], 4, lang),
                             x=number(c["structural_error_at_x"], 4, lang)))
        lines.append(message("synth.fg.round_trip", lang,
                             miss=significant(math.degrees(rt.output), 3, lang),
                             e=significant(rt.structural_max, 4, lang)))
        return lines

    def report(self, language: str | None = None) -> str:
        """Return the text report."""
        lang = language or self.language
        lines = [message("synth.title", lang, title=self.title(lang)), "",
                 message("synth.report.protocol", lang), *self.protocol_lines(lang), ""]
        fam = self.family_lines(lang)
        if fam:
            lines += [*fam, "", say(self.design.choice, lang), ""]
        lines += [message("synth.report.results", lang), *self.result_lines(lang)]
        return "\n".join(lines) + "\n"

    def to_json(self) -> dict[str, Any]:
        """Return the JSON document (SI units: m, rad)."""
        d, rt = self.design, self.check
        return {
            "kind": "synthesis", "problem": d.problem, "title": self.spec.title,
            "K": d.k, "theta": d.theta, "lengths": dict(d.lengths),
            "conditions": dict(d.conditions),
            "protocol": [{"id": s.msgid, "values": dict(s.values),
                          "text": say(s, self.language)} for s in d.protocol],
            "choice": {"id": d.choice.msgid, "values": dict(d.choice.values)},
            "family": [{"t": m.t, "lengths": m.lengths,
                        "gamma_min": m.gamma_min if m.valid else None} for m in d.family],
            "round_trip": {"K": rt.k, "output": rt.output, "output_kind": d.output_kind,
                           "asked_output": d.asked_output,
                           "gamma_min_sampled": rt.gamma_min if rt.gamma_min == rt.gamma_min
                           else None, "extremes_phi": list(rt.extremes_phi)},
            "scene": d.scene,
        }

    def scene_text(self) -> str:
        """The produced mechanism scene as TOML (what ``mechplan solve``/``draw`` take)."""
        head = "# " + message("synth.scene.comment", self.language,
                              problem=message(f"synth.problem.{self.spec.problem}",
                                              self.language),
                              k=number(self.spec.k, 4, self.language)) + "\n"
        return head + to_toml(self.design.scene)

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        """The synthesis sheet(s)."""
        from ..sheet.synthesis import synthesis_sheets

        lang = language or self.language
        results = self.result_lines(lang)
        if self.design.family:
            results = [say(self.design.choice, lang), *results]
        from .synthesis_table import condition_rows

        return synthesis_sheets(self.design, self.protocol_lines(lang), results,
                                self.title(lang), size or self.spec.sheet,
                                standard or self.spec.standard, lang, name,
                                dict(self.spec.title_block), condition_rows(self, lang))

    def write_files(self, out_dir: str | Path, name: str) -> list[Path]:
        """Write the produced mechanism scene, ``<name>-mechanism.toml``."""
        path = Path(out_dir) / f"{name}-mechanism.toml"
        path.write_text(self.scene_text(), encoding="utf-8")
        return [path]

    def answers(self) -> Keys:
        """The synthesised lengths, θ and γmin (SI) by name."""
        d = self.design
        scalars = {**d.lengths, "theta": d.theta, "K": d.k}
        if "gamma_min" in d.conditions:
            scalars["gamma_min"] = d.conditions["gamma_min"]
        return Keys("synthesis", scalars=scalars, study=self.to_json())


def solve_synthesis_text(text: str, file: str) -> SynthesisStudy:
    """Parse a synthesis scene, synthesise it and analyse what it produced."""
    from ..scene.synthesis import parse_synthesis

    spec = parse_synthesis(text, file)
    design = synthesise(spec)
    return SynthesisStudy(spec, design, round_trip(design))


__all__ = ["RoundTrip", "SynthesisStudy", "k_of_theta", "round_trip", "solve_synthesis_text"]
