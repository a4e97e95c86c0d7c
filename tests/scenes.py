"""Small scene texts used across tests (parametrised, so tests can move, rotate and scale them)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from mechplan.construct.builder import build_construction
from mechplan.model.structure import analyse
from mechplan.scene import load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[1]
ALL_TEMPLATES = sorted((ROOT / "templates").glob("*.toml"))


def _kind(path: Path) -> str:
    import tomllib

    return str(tomllib.loads(path.read_text(encoding="utf-8")).get("kind", "mechanism"))


def _driver(path: Path) -> str:
    import tomllib

    drive = tomllib.loads(path.read_text(encoding="utf-8")).get("drive", {})
    return str(drive.get("kind", "crank")) if isinstance(drive, dict) else "crank"


#: templates of crank-driven linkages (the kind every plan, force and sheet test of the linkage
#: half runs on: their positions are crank angles over a turn)
TEMPLATES = [p for p in ALL_TEMPLATES if _kind(p) == "mechanism" and _driver(p) == "crank"]
#: templates of linkages driven by a cylinder or a slider (positions are lengths; no force plan
#: yet): tests/construct/test_linear_drivers.py and the own-sheets grid run on them
DRIVER_TEMPLATES = [p for p in ALL_TEMPLATES if _kind(p) == "mechanism" and _driver(p) != "crank"]


def _two_inputs(path: Path) -> bool:
    import tomllib

    return "drive2" in tomllib.loads(path.read_text(encoding="utf-8"))


#: crank templates with a second driving crank (W = 2, ``[drive2]``): every plan, force and
#: sheet test runs on them; Kennedy's theorem cannot find all their instant centres (a five-bar
#: has only its pairs' centres from it), so the instant-centre tests leave them out
TWO_INPUT_TEMPLATES = [p for p in TEMPLATES if _two_inputs(p)]


def construction_of(scene, plans=("position", "velocity", "acceleration")):
    """Build a scene's construction."""
    return build_construction(scene.mechanism, analyse(scene.mechanism), plans, scene.assembly_phi)


def template(name: str):
    """Load a bundled template and build its construction."""
    scene = load_scene(ROOT / "templates" / f"{name}.toml")
    return scene, construction_of(scene)


def slider_crank_text(r_mm=100.0, l_mm=400.0, e_mm=0.0, speed="1500 rpm", sense="ccw",
                      origin=(0.0, 0.0), rot_deg=0.0, unit="mm", side="+") -> str:
    """A slider-crank whose frame is moved by ``origin`` and turned by ``rot_deg``."""
    c, s = math.cos(math.radians(rot_deg)), math.sin(math.radians(rot_deg))
    gx, gy = -s * e_mm + origin[0], c * e_mm + origin[1]
    return f"""
title = "slider-crank"
[ground]
O = ["{origin[0]!r} {unit}", "{origin[1]!r} {unit}"]
G = ["{gx!r} {unit}", "{gy!r} {unit}"]
guides.g = {{ through = "G", angle = "{rot_deg!r} deg" }}
[links.1]
lengths = {{ OA = "{r_mm!r} {unit}" }}
[links.2]
lengths = {{ AB = "{l_mm!r} {unit}" }}
points = {{ S2 = "0.3 of A B" }}
[links.3]
slides = {{ point = "B", on = "g" }}
[drive]
link = "1"
speed = "{speed}"
sense = "{sense}"
from = "{rot_deg!r} deg"
[assembly]
B = "{side}"
"""


def four_bar_text(a=(0.0, 0.0), d=(250.0, 0.0), ab=80.0, bc=260.0, cd=180.0, be=150.0, ce=180.0,
                  speed="10 rad/s", sense="ccw", side_c="left", side_e="left", ref_deg=0.0,
                  unit="mm") -> str:
    """A four-bar with a coupler point E."""
    return f"""
title = "four-bar"
[ground]
A = ["{a[0]!r} {unit}", "{a[1]!r} {unit}"]
D = ["{d[0]!r} {unit}", "{d[1]!r} {unit}"]
[links.1]
lengths = {{ AB = "{ab!r} {unit}" }}
[links.2]
lengths = {{ BC = "{bc!r} {unit}", BE = "{be!r} {unit}", CE = "{ce!r} {unit}" }}
side = {{ E = "{side_e} of B->C" }}
[links.3]
lengths = {{ DC = "{cd!r} {unit}" }}
[drive]
link = "1"
speed = "{speed}"
sense = "{sense}"
from = "{ref_deg!r} deg"
[assembly]
C = "{side_c} of B->D"
"""


def build_text(text: str, plans=("position", "velocity", "acceleration")):
    """Parse a scene text and build its construction."""
    scene = parse_scene(text)
    return scene, construction_of(scene, plans)


#: Scotch yoke: the yoke slides on the frame, the block on the crank pin slides in its slot (RPP)
SCOTCH_YOKE = """
[ground]
O = ["0 mm", "0 mm"]
guides.h = { through = "O", angle = "0 deg" }
[links.1]
lengths = { OA = "50 mm" }
[links.2]
slides = { point = "A", on = "slot" }
[links.3]
slides = { point = "Y", on = "h" }
points = { K = ["0 mm", "30 mm"] }
guides.slot = { through = "Y", angle = "90 deg" }
[drive]
link = "1"
speed = "20 rad/s"
"""

#: a slider in a slot along the crank pinned to a slider on a frame guide (PRP)
SLOTTED_CRANK_PRP = """
[ground]
O = ["0 mm", "0 mm"]
H = ["0 mm", "50 mm"]
guides.h = { through = "H", angle = "0 deg" }
[links.1]
lengths = { OA = "100 mm" }
guides.slot = { through = "O", toward = "A" }
[links.2]
slides = { point = "K", on = "slot" }
[links.3]
slides = { point = "K", on = "h" }
[drive]
link = "1"
speed = "5 rad/s"
"""

PHI = np.radians(np.array([0.0, 17.0, 60.0, 91.0, 135.0, 180.0, 222.0, 270.0, 300.0, 341.0]))
