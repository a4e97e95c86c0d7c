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


DIESEL_2600 = """
kind = "engine"
[engine]
speed = "2600 rpm"
bore = "120 mm"
crank_radius = "60 mm"
rod_length = "225 mm"
{engine_extra}
[masses]
piston = "2 kg"
rod = "3 kg"
rod_small_end = "1 kg"
[thermal]
fuel = "diesel"
alpha = {alpha}
epsilon = {epsilon}
p_a = "88 kPa"
p_r = "110 kPa"
T_r = 750
n1 = 1.37
n2 = 1.26
xi_z = 0.82
{thermal_extra}
"""


def diesel_2600(engine_extra: str = "", alpha: object = 1.4, epsilon: object = 17,
                thermal_extra: str = "") -> str:
    """The thermal tests' diesel (2600 rpm, 120 × 120 mm) with extra [engine] and [thermal] lines;
    a value given as "{name}" stays a placeholder for the test's own ``format``."""
    return DIESEL_2600.format(engine_extra=engine_extra, alpha=alpha, epsilon=epsilon,
                              thermal_extra=thermal_extra)
