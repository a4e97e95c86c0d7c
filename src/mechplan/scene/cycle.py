"""Read a machine file (``kind = "cycle"``): the members on one main shaft and their phases."""

from __future__ import annotations

from typing import Any

from ..i18n import LANGUAGES, Text
from ..model.cycle import MachineSpec, MemberSpec, Working
from .document import parse_toml
from .reader import Table

WORKING = tuple(w.value for w in Working)


def parse_machine(text: str, file: str = "<scene>") -> MachineSpec:
    """Parse the text of a machine file."""
    data: dict[str, Any] = parse_toml(text, file)
    top = Table(data, "", file)
    top.check_keys(("kind", "title", "language", "start", "members"))
    raw = top.raw("members", required=True)
    if not isinstance(raw, list) or not raw or not all(isinstance(m, dict) for m in raw):
        raise top.error("members", Text("machine_cycle.error.members"))
    members = []
    for i, m in enumerate(raw):
        t = Table(m, f"members[{i}]", file)
        t.check_keys(("name", "scene", "phase", "output", "working"))
        scene = t.string("scene", required=True)
        assert scene is not None
        phase = t.quantity("phase", "angle", 0.0)
        members.append(MemberSpec(
            name=t.string("name", str(i + 1)) or str(i + 1), scene=scene,
            phase=phase if phase is not None else 0.0, subject=t.string("output"),
            working=Working(t.string("working", "longer", choices=WORKING))))
    names = [m.name for m in members]
    if len(set(names)) != len(names):
        raise top.error("members", Text("machine_cycle.error.names", {"names": ", ".join(names)}))
    return MachineSpec(title=top.string("title", "") or "",
                       language=top.string("language", "en", choices=LANGUAGES) or "en",
                       members=tuple(members), start=top.quantity("start", "angle"), file=file)
