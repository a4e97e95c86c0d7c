"""Simpson and Ravigneaux sets: every gear's exact ratio (Willis in fractions) against direct
kinematics — the gears laid out in the plane, every pinion a rigid body on the carrier, rolling
without slip at each pitch point, the velocities solved numerically — and the textbook closed
forms (second gear 1 + z_S/z_R1, reverse −z_R2/z_S; Ravigneaux first z_R/z_S1, reverse
−z_R/z_S2)."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from mechplan.errors import SceneError
from mechplan.model.gears import CompoundGear, CompoundSpec
from mechplan.studies import solve_text
from mechplan.synthesis.gears.compound import MEMBERS, solve_shift

M = 1.0


def _cross(w: float, r: np.ndarray) -> np.ndarray:
    return w * np.array([-r[1], r[0]])


def _direct(kind: str, teeth: dict[str, int], inp: str, held: tuple[str, ...],
            locked: tuple[str, ...]) -> dict[str, float]:
    """Member speeds from rolling at the pitch points (ω_in = 1)."""
    if kind == "simpson":
        zs, zr1, zr2 = teeth["sun"], teeth["ring1"], teeth["ring2"]
        rs = M * zs / 2
        # gears: (name, centre, radius, carrier it rides on or None); meshes: (a, b, internal)
        bodies = {"S": (np.zeros(2), rs, None), "R1": (np.zeros(2), M * zr1 / 2, None),
                  "C1R2": (np.zeros(2), M * zr2 / 2, None)}
        p1, p2 = M * (zr1 - zs) / 4, M * (zr2 - zs) / 4
        bodies["P1"] = (np.array([rs + p1, 0.0]), p1, "C1R2")
        angle = 0.7
        bodies["P2"] = ((rs + p2) * np.array([math.cos(angle), math.sin(angle)]), p2, "C2")
        meshes = [("S", "P1", False), ("P1", "R1", True), ("S", "P2", False),
                  ("P2", "C1R2", True)]
        unknown = ["S", "R1", "C1R2", "C2", "P1", "P2"]
    else:
        zs1, zs2, zr = teeth["sun_small"], teeth["sun_large"], teeth["ring"]
        r1, r2, rr = M * zs1 / 2, M * zs2 / 2, M * zr / 2
        rl = (rr - r2) / 2
        rsh = 0.3 * rr
        cl = np.array([r2 + rl, 0.0])
        a_s = r1 + rsh
        cos_b = (a_s ** 2 + (r2 + rl) ** 2 - (rsh + rl) ** 2) / (2 * a_s * (r2 + rl))
        b = math.acos(cos_b)
        cs = a_s * np.array([math.cos(b), math.sin(b)])
        bodies = {"S1": (np.zeros(2), r1, None), "S2": (np.zeros(2), r2, None),
                  "R": (np.zeros(2), rr, None), "SP": (cs, rsh, "C"), "LP": (cl, rl, "C")}
        meshes = [("S1", "SP", False), ("SP", "LP", False), ("S2", "LP", False),
                  ("LP", "R", True)]
        unknown = ["S1", "S2", "R", "C", "SP", "LP"]
    idx = {k: i for i, k in enumerate(unknown)}
    rows, rhs = [], []
    for a, b_, internal in meshes:
        ca, ra, _ = bodies[a]
        cb = bodies[b_][0]
        if internal:            # a: the pinion inside ring b
            q = ca + ra * ca / np.linalg.norm(ca)
        else:
            u = (cb - ca) / np.linalg.norm(cb - ca)
            q = ca + ra * u
        n = (q - ca) / np.linalg.norm(q - ca)
        t = np.array([-n[1], n[0]])                     # the common tangent at q
        row = np.zeros(len(unknown))
        # velocity of q on a minus on b, along t: rotation about its own centre plus its
        # carrier's rotation carrying the centre
        for name, sign, (c, _, carrier) in ((a, 1.0, bodies[a]), (b_, -1.0, bodies[b_])):
            row[idx[name]] += sign * float(_cross(1.0, q - c) @ t)
            if carrier is not None:
                row[idx[carrier]] += sign * float(_cross(1.0, c) @ t)
        rows.append(row)
        rhs.append(0.0)
    row = np.zeros(len(unknown))
    row[idx[inp]] = 1.0
    rows.append(row)
    rhs.append(1.0)
    for h in held:
        row = np.zeros(len(unknown))
        row[idx[h]] = 1.0
        rows.append(row)
        rhs.append(0.0)
    if locked:
        row = np.zeros(len(unknown))
        row[idx[locked[0]]], row[idx[locked[1]]] = 1.0, -1.0
        rows.append(row)
        rhs.append(0.0)
    w = np.linalg.solve(np.array(rows), np.array(rhs))
    return {k: float(w[idx[k]]) for k in MEMBERS[kind]}


SIMPSON = {"sun": 30, "ring1": 72, "ring2": 72}
RAVIGNEAUX = {"sun_small": 30, "sun_large": 36, "ring": 72}


@pytest.mark.parametrize("kind, teeth, inp, held, locked, out", [
    ("simpson", SIMPSON, "R1", ("C2",), (), "C1R2"),
    ("simpson", SIMPSON, "R1", ("S",), (), "C1R2"),
    ("simpson", SIMPSON, "R1", (), ("R1", "S"), "C1R2"),
    ("simpson", SIMPSON, "S", ("C2",), (), "C1R2"),
    ("simpson", {"sun": 28, "ring1": 70, "ring2": 76}, "R1", ("C2",), (), "C1R2"),
    ("ravigneaux", RAVIGNEAUX, "S1", ("C",), (), "R"),
    ("ravigneaux", RAVIGNEAUX, "S1", ("S2",), (), "R"),
    ("ravigneaux", RAVIGNEAUX, "S2", ("C",), (), "R"),
    ("ravigneaux", RAVIGNEAUX, "S2", ("S1",), (), "C"),
    ("ravigneaux", {"sun_small": 26, "sun_large": 34, "ring": 78}, "S1", ("S2",), (), "R"),
])
def test_every_gear_against_direct_kinematics(kind, teeth, inp, held, locked, out) -> None:
    spec = CompoundSpec(kind, teeth, ())
    s = solve_shift(spec, "g", inp, held, locked, out, "k")
    direct = _direct(kind, teeth, inp, held, locked)
    for m, w in s.speeds.items():
        assert float(w) == pytest.approx(direct[m], abs=1e-12)
    assert float(s.ratio) == pytest.approx(1 / direct[out], rel=1e-12)


def test_closed_forms() -> None:
    simpson = CompoundSpec("simpson", SIMPSON, ())
    assert solve_shift(simpson, "2", "R1", ("S",), (), "C1R2", "k").ratio == 1 + Fraction(30, 72)
    assert solve_shift(simpson, "R", "S", ("C2",), (), "C1R2", "k").ratio == -Fraction(72, 30)
    assert solve_shift(simpson, "3", "R1", (), ("R1", "S"), "C1R2", "k").ratio == 1
    rav = CompoundSpec("ravigneaux", RAVIGNEAUX, ())
    assert solve_shift(rav, "1", "S1", ("C",), (), "R", "k").ratio == Fraction(72, 30)
    assert solve_shift(rav, "R", "S2", ("C",), (), "R", "k").ratio == -Fraction(72, 36)


def test_the_scene_and_its_errors() -> None:
    text = """kind = "gears"
title = "r"
[compound]
type = "ravigneaux"
teeth = { sun_small = 30, sun_large = 36, ring = 72 }
[[compound.gears]]
name = "1st"
input = "S1"
held = ["C"]
output = "R"
"""
    doc = solve_text(text, "r.toml").to_json()["compound"]
    assert doc["gears"][0]["ratio"] == "12/5"
    for bad, key in ((text.replace('held = ["C"]', 'held = ["X"]'), "compound.gears[0].held"),
                     (text.replace('held = ["C"]\n', ""), "compound.gears[0]"),
                     (text.replace('held = ["C"]', 'held = ["S1"]'), "compound.gears[0]"),
                     (text.replace("ring = 72", "ring = 30"), "compound.teeth.ring")):
        with pytest.raises(SceneError) as e:
            solve_text(bad, "r.toml")
        assert e.value.key == key
    assert CompoundGear("g", "S1", "R").held == ()
