"""Scene texts with the dyads no template has: PRP (two pinned sliders) and RPP (Scotch yoke)."""

from __future__ import annotations

import numpy as np

#: Scotch yoke with a tilted frame guide and a slot not ⊥ to it: I(0,1) → II(2,3) [RPP]
SCOTCH_YOKE = """
title = "Scotch yoke (RPP)"
[ground]
O = ["0 mm", "0 mm"]
G = ["0 mm", "40 mm"]
guides.x = { through = "G", angle = "10 deg" }
[links.1]
lengths = { OA = "100 mm" }
mass = "1.2 kg"
centre = { S1 = [\"30 mm\", \"5 mm\"] }
J = "0.004 kg*m^2"
[links.2]
name = "block"
slides = { point = "A", on = "slot" }
points = { S2 = ["10 mm", "15 mm"] }
mass = "0.4 kg"
centre = "S2"
J = "0.001 kg*m^2"
[links.3]
name = "yoke"
slides = { point = "K", on = "x" }
points = { P = ["60 mm", "-20 mm"], S3 = ["30 mm", "50 mm"] }
guides.slot = { through = "P", angle = "80 deg" }
mass = "2.5 kg"
centre = "S3"
J = "0.02 kg*m^2"
[drive]
link = "1"
speed = "20 rad/s"
sense = "ccw"
epsilon = "15 rad/s^2"
[gravity]
direction = "-y"
[[loads]]
type = "force"
point = "P"
vector = ["-150 N", "40 N"]
[[loads]]
type = "pressure"
point = "K"
pressure = "0.2 MPa"
bore = "40 mm"
towards = "G"
[[loads]]
type = "moment"
link = "2"
moment = "-3 N*m"
"""

#: two sliders pinned at K: slider 2 in a slot along the crank, slider 3 on a frame guide (PRP)
PINNED_SLIDERS = """
title = "pinned sliders (PRP)"
[ground]
O = ["0 mm", "0 mm"]
G = ["0 mm", "150 mm"]
guides.x = { through = "G", angle = "-15 deg" }
[links.1]
lengths = { OA = "100 mm" }
guides.g1 = { through = "O", toward = "A" }
mass = "1 kg"
centre = "A"
[links.2]
slides = { point = "K", on = "g1" }
points = { S2 = ["20 mm", "10 mm"] }
mass = "0.5 kg"
centre = "S2"
J = "0.002 kg*m^2"
[links.3]
slides = { point = "K", on = "x" }
points = { S3 = ["-30 mm", "25 mm"] }
mass = "1.5 kg"
centre = "S3"
J = "0.01 kg*m^2"
[drive]
link = "1"
speed = "10 rad/s"
sense = "cw"
[gravity]
direction = "-y"
[[loads]]
type = "force"
point = "S3"
magnitude = "80 N"
angle = "30 deg"
[[loads]]
type = "table"
point = "K"
link = "3"
towards = "G"
against = "displacement"
table = [["-400 mm", "50 N"], ["0 mm", "-20 N"], ["400 mm", "120 N"]]
[[loads]]
type = "moment"
link = "3"
moment = "5 N*m"
"""

#: crank angles (rad) of the cycle kept away from the PRP scene's parallel guides (φ = 15°, 195°)
CYCLE = np.linspace(0.0, 2.0 * np.pi, 36, endpoint=False) + 0.05
