"""A machine's cycle diagram (``kind = "cycle"``): the members' scenes solved, their phases on
the main shaft, report, JSON and the rectangular and circular diagrams."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..errors import SceneError
from ..i18n import Text, message, number
from .answers import Keys

if TYPE_CHECKING:
    from ..construct.cycle import MemberCycle
    from ..drafting.primitives import Sheet
    from ..model.cycle import MachineSpec


@dataclass(frozen=True)
class CycleStudy:
    """The members' phases on one shaft; ``speeds``: each member's shaft speed (rad/s)."""

    spec: MachineSpec
    members: tuple[MemberCycle, ...]
    origin: float
    speeds: tuple[float, ...]

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
        if self.speed_mismatch:
            out.append(message("machine_cycle.warning.speeds", lang, speeds=", ".join(
                n(abs(w), 4) for w in self.speeds)))
        return "\n".join(out)

    @property
    def speed_mismatch(self) -> bool:
        """True when the members' scenes give their shafts different speeds."""
        w = [abs(x) for x in self.speeds]
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
                                 for k, a, b in self.spans_deg(m)]}
                    for m, spec, w in zip(self.members, self.spec.members, self.speeds)]}

    def answers(self) -> Keys:
        """Each member's phase angles in degrees by name ("<member>.<kind>")."""
        scalars: dict[str, float] = {}
        for m in self.members:
            for s in m.spans:
                key = f"{m.name}.{s.kind}"
                scalars[key] = scalars.get(key, 0.0) + s.angle
        return Keys("cycle", scalars=scalars, study=self.to_json())

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.cycle import CycleView, cycle_sheets

        return cycle_sheets(CycleView(self.members, self.origin), self.spec.title, size,
                            standard, language or self.language, name)


def _signed(deg: float, lang: str) -> str:
    """"+ 30,00" or "− 120,00": the offset written after ψ."""
    return ("− " if deg < 0 else "+ ") + number(abs(deg), 2, lang)


def solve_cycle_text(text: str, file: str, data_dir: str | Path | None = None) -> CycleStudy:
    """Parse a machine file, solve each member's scene (paths relative to ``data_dir``, default
    the machine file's folder) and lay out their phases on the shaft."""
    from ..construct.cycle import cam_cycle, diagram_origin, linkage_cycle
    from ..scene.cycle import parse_machine
    from ..scene.document import parse_toml, read_text, scene_kind

    spec = parse_machine(text, file)
    folder = Path(data_dir) if data_dir is not None else Path(file).parent
    members: list[MemberCycle] = []
    speeds: list[float] = []
    for i, m in enumerate(spec.members):
        key = f"members[{i}].scene"
        path = folder / m.scene
        if not path.is_file():
            raise SceneError(Text("machine_cycle.error.missing", {"name": m.name, "scene": m.scene,
                                                          "folder": str(folder)}),
                             file=file, key=key)
        sub = read_text(path)
        kind = scene_kind(parse_toml(sub, str(path)), str(path))
        try:
            if kind == "mechanism":
                from ..scene import parse_scene
                from ..solve import solve

                scene = parse_scene(sub, str(path))
                sol = solve(scene, count=4)
                members.append(linkage_cycle(sol.construction, scene.mechanism, m.name, m.phase,
                                             m.subject, m.working, f"members[{i}].output"))
                speeds.append(float(scene.mechanism.drive.omega))
            elif kind == "cam":
                from ..scene.cam import parse_cam

                cam = parse_cam(sub, str(path))
                members.append(cam_cycle(cam.phases, cam.stroke, m.name, m.phase))
                speeds.append(float(cam.omega))
            else:
                raise SceneError(Text("machine_cycle.error.kind", {"name": m.name, "kind": kind}),
                                 key=key)
        except SceneError as exc:
            if exc.file:
                raise
            raise SceneError(exc.detail, file=file, key=exc.key or key) from None
    origin = diagram_origin(members, spec.start)
    return CycleStudy(spec, tuple(members), origin, tuple(speeds))
