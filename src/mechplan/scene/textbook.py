"""Read the ``[answers]`` section of a mechanism scene into a :class:`TextbookSpec`.

```toml
[answers]
ask = ["relative", "rubbing", "transmission", "stroke", "least_velocity"]   # or ["all"]
pin_radius = "10 mm"                 # every pin's radius (rubbing velocity)
pins = { O = "25 mm", "A(1,2)" = "30 mm" }  # a pin's own radius: by its point, or point(links)
outputs = ["B", "3"]                 # stroke/swing of these; default every slider and rocker
```
"""

from __future__ import annotations

from typing import Any

from ..i18n import Text
from ..model.mechanism import GROUND, Mechanism, PairKind
from ..model.textbook import Answer, TextbookSpec
from .reader import Table

KEYS = ("ask", "pin_radius", "pins", "outputs")
NAMES = tuple(a.value for a in Answer)


def parse_textbook(data: dict[str, Any], file: str, mech: Mechanism) -> TextbookSpec | None:
    """Return what the ``[answers]`` section asks for, or None when the scene has none."""
    if "answers" not in data:
        return None
    t = Table(data["answers"], "answers", file)
    t.check_keys(KEYS)
    ask = t.raw("ask", ["all"])
    if isinstance(ask, str):
        ask = [ask]
    if not isinstance(ask, list) or not ask or any(
            not isinstance(a, str) or a not in (*NAMES, "all") for a in ask):
        raise t.error("ask", Text(
            "errmsg2.scene_textbook.ask_list",
            {"names": ', '.join(NAMES), "value": repr(ask)}))
    asked = frozenset(Answer) if "all" in ask else frozenset(Answer(a) for a in ask)
    radius = t.quantity("pin_radius", "length", positive=True)
    pins: dict[str, float] = {}
    pt = t.table("pins")
    if pt is not None:
        revolute = [p for p in mech.pairs if p.kind is PairKind.REVOLUTE]
        at_pins = {p.point for p in revolute} | {f"{p.point}({x},{y})" for p in revolute
                                                 for x, y in ((p.a, p.b), (p.b, p.a))}
        for name in pt.data:
            if name not in at_pins:
                raise pt.error(name, Text(
                    "errmsg2.scene_textbook.not_pin",
                    {"pins": ', '.join(sorted(p.point for p in revolute))}))
            value = pt.quantity(name, "length", positive=True)
            assert value is not None
            pins[name] = value
    outputs = t.raw("outputs", [])
    if isinstance(outputs, str):
        outputs = [outputs]
    if not isinstance(outputs, list) or any(not isinstance(o, (str, int)) for o in outputs):
        raise t.error("outputs", Text(
            "errmsg2.scene_textbook.outputs_list",
            {"value": repr(outputs)}))
    points = {p for lk in mech.links.values() for p in lk.points}
    for o in map(str, outputs):
        if o == GROUND or (o not in mech.links and o not in points):
            raise t.error("outputs", Text(
                "errmsg2.scene_textbook.not_link_or_point",
                {"value": repr(o)}))
    if Answer.RUBBING in asked and radius is None and not pins and "all" not in ask:
        raise t.error("pin_radius", Text("errmsg2.scene_textbook.pin_radius"))
    return TextbookSpec(asked=asked, pin_radius=radius, pins=pins,
                        outputs=tuple(map(str, outputs)))
