"""Read a machine file (``kind = "cycle"``): the members on one main shaft and their phases."""

from __future__ import annotations

from typing import Any

from ..errors import SceneError
from ..i18n import LANGUAGES, Text
from ..model.cycle import MachineSpec, MemberSpec, Motor, ShaftSpec, Working
from .document import parse_toml
from .reader import Table

WORKING = tuple(w.value for w in Working)


def parse_machine(text: str, file: str = "<scene>") -> MachineSpec:
    """Parse the text of a machine file."""
    data: dict[str, Any] = parse_toml(text, file)
    top = Table(data, "", file)
    top.check_keys(("kind", "title", "language", "start", "members", "motor", "shafts",
                    "cycle_shaft"))
    motor, shafts = _motor(top), _shafts(top)
    raw = top.raw("members", required=True)
    if not isinstance(raw, list) or not raw or not all(isinstance(m, dict) for m in raw):
        raise top.error("members", Text("machine_cycle.error.members"))
    members = []
    for i, m in enumerate(raw):
        t = Table(m, f"members[{i}]", file)
        t.check_keys(("name", "scene", "phase", "output", "working", "driven_by", "near",
                      "shaft"))
        scene = t.string("scene", required=True)
        assert scene is not None
        phase = t.quantity("phase", "angle", 0.0)
        near, near_length = 0.0, False
        if t.has("near"):                # a crank's angle, or a driving slider's coordinate
            try:
                near = t.quantity("near", "angle") or 0.0
            except SceneError:
                near, near_length = t.quantity("near", "length") or 0.0, True
        members.append(MemberSpec(
            name=t.string("name", str(i + 1)) or str(i + 1), scene=scene,
            phase=phase if phase is not None else 0.0, subject=t.string("output"),
            working=Working(t.string("working", "longer", choices=WORKING)),
            driven_by=t.string("driven_by"), near=near, near_length=near_length,
            near_given=t.has("near"),
            shaft=t.string("shaft", choices=tuple(sh.name for sh in shafts) or None)))
        if t.has("phase") and t.has("driven_by"):
            raise t.error("phase", Text("machine.error.driven_phase"))
        if t.has("near") and not t.has("driven_by"):
            raise t.error("near", Text("machine.error.near_alone"))
        if t.has("shaft") and not shafts:
            raise t.error("shaft", Text("machine.error.no_shafts"))
    names = [m.name for m in members]
    if len(set(names)) != len(names):
        raise top.error("members", Text("machine_cycle.error.names", {"names": ", ".join(names)}))
    return MachineSpec(title=top.string("title", "") or "",
                       language=top.string("language", "en", choices=LANGUAGES) or "en",
                       members=tuple(members), start=top.quantity("start", "angle"), file=file,
                       motor=motor, shafts=shafts,
                       cycle_shaft=top.string("cycle_shaft",
                                              choices=tuple(sh.name for sh in shafts) or None))


def _motor(top: Table) -> Motor | None:
    """``[motor]``: its speed and sense."""
    t = top.table("motor")
    if t is None:
        return None
    t.check_keys(("speed", "sense"))
    speed = t.quantity("speed", "angular_velocity", required=True) or 0.0
    if not speed > 0:
        raise t.error("speed", Text("machine.error.motor_speed", {"value": repr(t.raw("speed"))}))
    sense = 1 if t.string("sense", "ccw", choices=("ccw", "cw")) == "ccw" else -1
    return Motor(sense * speed)


def _shafts(top: Table) -> tuple[ShaftSpec, ...]:
    """``[[shafts]]``: each turned through a gear scene from the motor or an earlier shaft."""
    raw = top.raw("shafts")
    if raw is None:
        return ()
    if not isinstance(raw, list) or not raw or not all(isinstance(m, dict) for m in raw):
        raise top.error("shafts", Text("machine.error.shafts"))
    if top.table("motor") is None:
        raise top.error("shafts", Text("machine.error.no_motor"))
    out: list[ShaftSpec] = []
    for i, m in enumerate(raw):
        t = Table(m, f"shafts[{i}]", top.file)
        t.check_keys(("name", "train", "from"))
        name = t.string("name", required=True) or ""
        seen = ("motor", *(s.name for s in out))
        if name in seen:
            raise t.error("name", Text("machine.error.shaft_name", {"name": name}))
        out.append(ShaftSpec(name=name, train=t.string("train", required=True) or "",
                             source=t.string("from", "motor", choices=seen) or "motor"))
    return tuple(out)
