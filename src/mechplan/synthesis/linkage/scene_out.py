"""The mechanism scene a synthesis hands to the analysis (a dict the loader takes as it is)."""

from __future__ import annotations

from typing import Any

from ...i18n import message
from ...model.synthesis import SynthesisSpec


def mm(x: float) -> str:
    """A length in millimetres written with every digit (the round trip keeps 1e-12)."""
    return repr(float(x) * 1e3) + " mm"


def deg(x: float) -> str:
    """An angle in degrees written with every digit."""
    import math

    return repr(math.degrees(float(x))) + " deg"


def link_name(role: str, spec: SynthesisSpec) -> str:
    """The link's name in the scene's language."""
    return message(f"synth.link.{role}", spec.language)


def base(spec: SynthesisSpec, ground: dict[str, Any], links: dict[str, Any],
         start: dict[str, str], assembly: dict[str, Any] | None = None) -> dict[str, Any]:
    """A whole scene: title, language, ground, links, drive (link 1), assembly, positions."""
    scene: dict[str, Any] = {
        "title": spec.title or message(f"synth.problem.{spec.problem}", spec.language),
        "language": spec.language,
        "ground": ground,
        "links": links,
        "drive": {"link": "1", "speed": repr(float(spec.speed)) + " rad/s",
                  "sense": "ccw" if spec.sense > 0 else "cw"},
    }
    if assembly:
        scene["assembly"] = assembly
    scene["positions"] = {"count": spec.positions, "start": start}
    return scene
