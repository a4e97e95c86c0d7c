"""A machine's cycle diagram (``kind = "cycle"``): the members' scenes solved, their phases on
the main shaft, report, JSON and the rectangular and circular diagrams."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import SceneError
from ..i18n import Text, message, number, unit
from .answers import Keys

if TYPE_CHECKING:
    from ..construct.cycle import MemberCycle
    from ..drafting.primitives import Sheet
    from ..dynamics.cam_linkage import CamLinkage
    from ..model.cycle import MachineSpec


@dataclass(frozen=True)
class CycleStudy:
    """The members' phases on one shaft; ``speeds``: each member's shaft speed (rad/s)."""

    spec: MachineSpec
    members: tuple[MemberCycle, ...]
    origin: float
    speeds: tuple[float, ...]
    shafts: tuple[ShaftResult, ...] = ()
    #: the linkages turned by a cam's follower, by member name
    driven: dict[str, CamLinkage] = field(default_factory=dict)
    member_shafts: tuple[str | None, ...] = ()
    cycle_shaft: str | None = None

    @property
    def language(self) -> str:
        """The machine file's language."""
        return self.spec.language

    def spans_deg(self, m: MemberCycle) -> list[tuple[str, float, float]]:
        """(kind, ψ start, ψ end) in degrees from the diagram's origin, in order."""
        return [(s.kind, math.degrees(a), math.degrees(b)) for s, a, b in m.on_shaft(self.origin)]

    def report(self, language: str | None = None) -> str:
        lang = language or self.language
        def n(x: float, d: int = 2) -> str:
            return number(x, d, lang)
        out = [message("machine_cycle.report.title", lang, title=self.spec.title,
                       start=n(math.degrees(self.origin)))]
        for m in self.members:
            out.append(message(f"machine_cycle.report.member.{m.kind}", lang, name=m.name,
                               phase=_signed(math.degrees(m.phase), lang), output=m.subject))
            for s in m.spans:
                out.append(message("machine_cycle.report.span", lang,
                                   kind=message(f"machine_cycle.kind.{s.kind}", lang),
                                   angle=n(math.degrees(s.angle)),
                                   start=n(math.degrees(s.start) % 360.0 + 0.0)))
            out.append(message("machine_cycle.report.on_shaft", lang, spans="; ".join(
                f"{message(f'machine_cycle.kind.{k}', lang)} {n(a)}…{n(b)}°"
                for k, a, b in self.spans_deg(m))))
        out.extend(machine_lines(self, lang))
        if self.speed_mismatch and not self.shafts:
            out.append(message("machine_cycle.warning.speeds", lang, speeds=", ".join(
                n(abs(w), 4) for w in self.speeds)))
        return "\n".join(out)

    @property
    def speed_mismatch(self) -> bool:
        """True when the members turn at different speeds."""
        w = [abs(x) / m.turns for x, m in zip(self.speeds, self.members)]
        return max(w) - min(w) > 1e-9 * max(w)

    def to_json(self) -> dict[str, Any]:
        return {"kind": "cycle", "title": self.spec.title,
                "start_deg": math.degrees(self.origin),
                "members": [{
                    "name": m.name, "kind": m.kind, "scene": spec.scene, "output": m.subject,
                    "phase_deg": math.degrees(m.phase), "stroke": m.stroke,
                    "speed_rad_s": w,
                    "phases": [{"kind": s.kind, "start_own_deg": math.degrees(s.start) % 360.0,
                                "angle_deg": math.degrees(s.angle)} for s in m.spans],
                    "on_shaft": [{"kind": k, "from_deg": a, "to_deg": b}
                                 for k, a, b in self.spans_deg(m)],
                    "turns": m.turns, "shaft": sh, "driven_by": spec.driven_by,
                    "cam_linkage": (self.driven[m.name].to_json() if m.name in self.driven
                                    else None)}
                    for m, spec, w, sh in zip(self.members, self.spec.members, self.speeds,
                                              self.member_shafts or (None,) * len(self.members))],
                "motor": ({"omega_rad_s": self.spec.motor.omega} if self.spec.motor else None),
                "cycle_shaft": self.cycle_shaft,
                "shafts": [sh.to_json() for sh in self.shafts]}

    def answers(self) -> Keys:
        """Each member's phase angles in degrees by name ("<member>.<kind>")."""
        scalars: dict[str, float] = {}
        for m in self.members:
            for s in m.spans:
                key = f"{m.name}.{s.kind}"
                scalars[key] = scalars.get(key, 0.0) + s.angle
        for sh in self.shafts:
            scalars[f"{sh.name}.ratio"] = float(sh.from_motor)
            scalars[f"{sh.name}.omega"] = sh.omega
        for name, d in self.driven.items():
            ex = d.extremes()
            for k in ("contact", "torque", "moment"):
                if k in ex:
                    scalars[f"{name}.{k}_max"] = ex[k]["max"]
                    scalars[f"{name}.{k}_min"] = ex[k]["min"]
        return Keys("cycle", scalars=scalars, study=self.to_json())

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.cycle import CycleView, cycle_sheets

        lang = language or self.language
        return cycle_sheets(CycleView(self.members, self.origin, tuple(machine_lines(self, lang)),
                                      tuple(self.driven.values())),
                            self.spec.title, size, standard, lang, name)


def _signed(deg: float, lang: str) -> str:
    """"+ 30,00" or "− 120,00": the offset written after ψ."""
    return ("− " if deg < 0 else "+ ") + number(abs(deg), 2, lang)


def solve_cycle_text(text: str, file: str, data_dir: str | Path | None = None) -> CycleStudy:
    """Parse a machine file, solve each member's scene (paths relative to ``data_dir``, default
    the machine file's folder), its train of shafts, and lay out the phases on the shaft."""
    from ..construct.cycle import cam_cycle, diagram_origin, driven_cycle, linkage_cycle
    from ..scene.cycle import parse_machine

    spec = parse_machine(text, file)
    folder = Path(data_dir) if data_dir is not None else Path(file).parent
    shafts = _shafts(spec, folder, file)
    by_name = {sh.name: sh for sh in shafts}
    member_shafts = tuple((m.shaft or (shafts[0].name if shafts else None))
                          for m in spec.members)
    cycle = spec.cycle_shaft or (min((by_name[s] for s in member_shafts if s is not None),
                                     key=lambda sh: abs(sh.omega)).name if shafts else None)
    members: list[MemberCycle | None] = [None] * len(spec.members)
    speeds: list[float] = [0.0] * len(spec.members)
    cams: dict[str, tuple[int, Any]] = {}
    scenes: dict[int, Any] = {}
    for i, m in enumerate(spec.members):
        kind, parsed = _member_scene(m.name, m.scene, folder, file, f"members[{i}].scene")
        turns, shaft_speed = 1, None
        sh_name = member_shafts[i]
        if sh_name is not None and cycle is not None:
            turns = _turns(by_name[cycle].from_motor, by_name[sh_name].from_motor, m.name, file,
                           f"members[{i}].shaft")
            shaft_speed = abs(by_name[sh_name].omega)
        try:
            if m.driven_by is not None:
                if kind != "mechanism":
                    raise SceneError(Text("machine_cycle.error.kind", {"name": m.name,
                                                                       "kind": kind}),
                                     key=f"members[{i}].scene")
                scenes[i] = parsed
                continue
            if kind == "mechanism":
                from ..solve import solve

                sol = solve(parsed, count=4)
                members[i] = replace(linkage_cycle(sol.construction, parsed.mechanism, m.name,
                                                   m.phase, m.subject, m.working,
                                                   f"members[{i}].output"), turns=turns)
                speeds[i] = shaft_speed or float(parsed.mechanism.drive.omega)
            else:
                members[i] = replace(cam_cycle(parsed.phases, parsed.stroke, m.name, m.phase),
                                     turns=turns)
                speeds[i] = shaft_speed or float(parsed.omega)
                cams[m.name] = (i, parsed)
        except SceneError as exc:
            if exc.file:
                raise
            raise SceneError(exc.detail, file=file, key=exc.key or f"members[{i}].scene") from None
    driven: dict[str, CamLinkage] = {}
    for i, sc in scenes.items():
        m = spec.members[i]
        key = f"members[{i}]"
        if m.driven_by not in cams:
            raise SceneError(Text("machine.error.driven_by", {
                "name": m.name, "cam": m.driven_by or "",
                "cams": ", ".join(cams) or "-"}), file=file, key=key + ".driven_by")
        j, cam = cams[m.driven_by]
        from ..model.mechanism import DriverKind
        from .cam_linkage import cam_linkage

        if (sc.mechanism.drive.kind is DriverKind.SLIDER) != m.near_length and m.near_given:
            raise SceneError(Text("machine.error.near_unit", {"name": m.name}), file=file,
                             key=key + ".near")
        try:
            d = cam_linkage(cam, sc, m.near, speeds[j], m.name, m.driven_by, m.subject, key)
        except SceneError as exc:
            if exc.file:
                raise
            raise SceneError(exc.detail, file=file, key=exc.key or key) from None
        driven[m.name] = d
        cam_member = members[j]
        assert cam_member is not None
        stroke_ = float(np.max(d.out) - np.min(d.out))
        members[i] = driven_cycle(cam_member, m.name, d.output, stroke_)
        speeds[i] = speeds[j]
    done = [mc for mc in members if mc is not None]
    origin = diagram_origin(done, spec.start)
    return CycleStudy(spec, tuple(done), origin, tuple(speeds), shafts, driven, member_shafts,
                      cycle)


def _member_scene(name: str, scene: str, folder: Path, file: str, key: str) -> tuple[str, Any]:
    """The member's scene kind and its parsed scene (a mechanism or a cam)."""
    from ..scene.document import parse_toml, read_text, scene_kind

    path = folder / scene
    if not path.is_file():
        raise SceneError(Text("machine_cycle.error.missing", {"name": name, "scene": scene,
                                                              "folder": str(folder)}),
                         file=file, key=key)
    sub = read_text(path)
    kind = scene_kind(parse_toml(sub, str(path)), str(path))
    if kind == "mechanism":
        from ..scene import parse_scene

        return kind, parse_scene(sub, str(path))
    if kind == "cam":
        from ..scene.cam import parse_cam

        return kind, parse_cam(sub, str(path))
    raise SceneError(Text("machine_cycle.error.kind", {"name": name, "kind": kind}), file=file,
                     key=key)


@dataclass(frozen=True)
class ShaftResult:
    """A shaft of the machine: its train's stages (exact ratios), the ratio from the motor and
    its speed (rad/s, signed)."""

    name: str
    source: str
    train: str
    stages: tuple[tuple[str, Fraction], ...]
    ratio: Fraction          # u = ω_source/ω_shaft
    from_motor: Fraction     # u = ω_motor/ω_shaft
    omega: float

    def to_json(self) -> dict[str, Any]:
        return {"name": self.name, "from": self.source, "train": self.train,
                "stages": [{"kind": k, "ratio": str(u), "value": float(u)}
                           for k, u in self.stages],
                "ratio": str(self.ratio), "ratio_value": float(self.ratio),
                "ratio_from_motor": str(self.from_motor),
                "ratio_from_motor_value": float(self.from_motor), "omega_rad_s": self.omega}


def _shafts(spec: MachineSpec, folder: Path, file: str) -> tuple[ShaftResult, ...]:
    """Each shaft's train solved from its gear scene; speeds from the motor down."""
    from ..scene.document import parse_toml, read_text, scene_kind
    from ..scene.gears import parse_gears
    from ..synthesis.gears.ratio import train_fraction
    from ..synthesis.gears.solve import solve_gears

    out: list[ShaftResult] = []
    known: dict[str, tuple[Fraction, float]] = {}
    if spec.motor is not None:
        known["motor"] = (Fraction(1), spec.motor.omega)
    for i, sh in enumerate(spec.shafts):
        key = f"shafts[{i}].train"
        path = folder / sh.train
        if not path.is_file():
            raise SceneError(Text("machine_cycle.error.missing", {
                "name": sh.name, "scene": sh.train, "folder": str(folder)}), file=file, key=key)
        sub = read_text(path)
        kind = scene_kind(parse_toml(sub, str(path)), str(path))
        if kind != "gears":
            raise SceneError(Text("machine.error.train_kind", {"name": sh.name, "kind": kind}),
                             file=file, key=key)
        try:
            stages = train_fraction(solve_gears(parse_gears(sub, str(path))))
        except SceneError as exc:
            if exc.file:
                raise
            raise SceneError(exc.detail, file=str(path), key=exc.key) from None
        u = Fraction(1)
        for _, x in stages:
            u *= x
        base, w0 = known[sh.source]
        total = base * u
        omega = w0 / float(u)
        known[sh.name] = (total, omega)
        out.append(ShaftResult(sh.name, sh.source, sh.train, tuple(stages), u, total, omega))
    return tuple(out)


def _turns(cycle: Fraction, member: Fraction, name: str, file: str, key: str) -> int:
    """Turns of a member's shaft per turn of the diagram's shaft: a whole number."""
    r = abs(cycle / member)
    if r.denominator != 1:
        raise SceneError(Text("machine.error.turns", {"name": name, "turns": str(r)}),
                         file=file, key=key)
    return int(r)


def machine_lines(st: CycleStudy, lang: str) -> list[str]:
    """The machine's table in words: the motor, each shaft's train and speed, each member's
    shaft and turns, and what each cam-driven linkage asks of its cam."""
    def n(x: float, d: int = 2) -> str:
        return number(x, d, lang)

    def rpm(w: float) -> str:
        return n(abs(w) * 30.0 / math.pi, 1)
    out: list[str] = []
    if st.spec.motor is not None:
        out.append(message("machine.report.motor", lang, omega=n(st.spec.motor.omega, 3),
                           rpm=rpm(st.spec.motor.omega)))
    for sh in st.shafts:
        stages = " · ".join(f"{message(f'machine.stage.{k}', lang)} {_fraction(u, lang)}"
                            for k, u in sh.stages)
        out.append(message("machine.report.shaft", lang, name=sh.name, source=sh.source,
                           train=sh.train, stages=stages, ratio=_fraction(sh.ratio, lang),
                           total=_fraction(sh.from_motor, lang), omega=n(sh.omega, 4),
                           rpm=rpm(sh.omega)))
    if st.shafts:
        for m, on, w in zip(st.members, st.member_shafts, st.speeds):
            out.append(message("machine.report.member_shaft", lang, name=m.name,
                               shaft=on or "-", turns=str(m.turns), omega=n(w, 4)))
    for name, d in st.driven.items():
        ex = d.extremes()
        unit_ = unit("rad" if d.rocker else "m", lang)
        out.append(message("machine.report.driven", lang, name=name, cam=d.cam, output=d.output,
                           low=n(ex["output"]["min"], 5), high=n(ex["output"]["max"], 5),
                           unit=unit_, w_low=n(ex["output_rate"]["min"], 4),
                           w_high=n(ex["output_rate"]["max"], 4)))
        if "contact" in ex:
            out.append(message("machine.report.driven_forces", lang, name=name,
                               m_low=n(ex["moment"]["min"], 3) if "moment" in ex else "-",
                               m_high=n(ex["moment"]["max"], 3) if "moment" in ex else "-",
                               n_low=n(ex["contact"]["min"], 2),
                               n_low_phi=n(ex["contact"]["min_phi_deg"], 0),
                               n_high=n(ex["contact"]["max"], 2),
                               t_low=n(ex["torque"]["min"], 3), t_high=n(ex["torque"]["max"], 3),
                               t_mean=n(ex["torque_mean"], 3)))
        if d.separates:
            out.append(message("machine.warning.separates", lang, name=name,
                               n=n(ex["contact"]["min"], 2),
                               phi=n(ex["contact"]["min_phi_deg"], 0)))
    return out


def _fraction(u: Fraction, lang: str) -> str:
    """"−4573/750 (≈ −6.0973)" or "−2" for a whole ratio."""
    sign = "−" if u < 0 else ""
    if u.denominator == 1:
        return f"{sign}{abs(u.numerator)}"
    return f"{sign}{abs(u.numerator)}/{u.denominator} (≈ {number(float(u), 4, lang)})"
