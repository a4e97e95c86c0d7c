"""Scene texts shared by the engine tests."""

from __future__ import annotations

MOTO = """
kind = "engine"
title = "moto"
[engine]
strokes = 4
speed = "8500 rpm"
bore = "56.5 mm"
crank_radius = "23.5 mm"
rod_length = "106 mm"
p0 = "100 kPa"
{engine_extra}
[masses]
piston = "170 g"
rod = "215 g"
{rod_split}
rotating_extra = "20 g"
[indicator]
epsilon = 9
p_a = "85 kPa"
p_r = "110 kPa"
n1 = 1.32
n2 = 1.23
p_z = "6.98 MPa"
{indicator_extra}
"""


def moto(engine_extra: str = "", rod_split: str = 'rod_small_end = "40 g"',
         indicator_extra: str = "") -> str:
    """The §3 motorcycle engine with optional extra keys."""
    return MOTO.format(engine_extra=engine_extra, rod_split=rod_split,
                       indicator_extra=indicator_extra)
