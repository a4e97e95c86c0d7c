"""Differentials (W = 2): two basic links turn as given, the third follows. Checked against direct
kinematics written here (rolling without slip at the pitch points, planet axle on the carrier), and
the superposition of the two inputs, each alone with the other held."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from mechplan.errors import SceneError
from mechplan.studies.gears import solve_gear_text

SETS = {"single_row": [20, 31, 82], "two_row_ext_int": [17, 17, 17, 51],
        "two_row_ext_ext": [40, 20, 21, 39], "two_row_int_int": [80, 20, 19, 79]}
INTERNAL = {"single_row": (False, True), "two_row_ext_int": (False, True),
            "two_row_ext_ext": (False, False), "two_row_int_int": (True, True)}


def direct(scheme: str, z: list[int], known: dict[str, float]) -> dict[str, float]:
    """ω of a, planet, b, h from the velocities of the pitch points (m = 2 mm)."""
    r = [0.001 * v for v in z]
    names = ["1", "2", "3"] if scheme == "single_row" else ["1", "2", "3", "4"]
    ra, rb = r[0], r[-1]
    pa, pb = (r[1], r[1]) if scheme == "single_row" else (r[1], r[2])
    ia, ib = INTERNAL[scheme]
    e = ra - pa if ia else ra + pa
    yb = e + pb if ib else e - pb
    assert yb == pytest.approx(rb)
    cols = {names[0]: 0, names[-1]: 2, "h": 3}
    rows = [[ra, -(ra - e), 0.0, -e], [0.0, -(yb - e), yb, -e]]
    rhs = [0.0, 0.0]
    for link, w in known.items():
        row = [0.0] * 4
        row[cols[link]] = 1.0
        rows.append(row)
        rhs.append(w)
    wa, wp, wb, wh = np.linalg.solve(np.array(rows), np.array(rhs))
    out = {names[0]: wa, names[-1]: wb, "h": wh}
    for n in names[1:-1]:
        out[n] = wp
    return out


def scene(scheme: str, z: list[int], speeds: dict[str, float], extra: str = "") -> str:
    table = ", ".join(f'"{k}" = "{v} rad/s"' for k, v in speeds.items())
    return (f'kind = "gears"\n[planetary]\nscheme = "{scheme}"\nspeeds = {{ {table} }}\n'
            f'planets = 1\nmodule = "2 mm"\ngiven = {z}\n{extra}')


@pytest.mark.parametrize("scheme", list(SETS))
def test_every_pair_of_inputs_agrees_with_direct_kinematics(scheme):
    z = SETS[scheme]
    links = ("1", "3" if scheme == "single_row" else "4", "h")
    for l1, l2 in itertools.permutations(links, 2):
        speeds = {l1: 1.0, l2: -0.5}
        st = solve_gear_text(scene(scheme, z, speeds), "d.toml")
        res = st.solution.planetary
        truth = direct(scheme, z, speeds)
        for n, w in truth.items():
            assert res.plan.omega[n] == pytest.approx(w, rel=1e-12, abs=1e-14)
        # superposition: each input alone, the other held, adds up to the plan of both
        p1, p2 = res.partials
        for n in truth:
            assert p1.omega[n] + p2.omega[n] == pytest.approx(res.plan.omega[n], abs=1e-14)
        assert p1.omega[l2] == 0 and p2.omega[l1] == 0


def test_the_books_question_a_plus_one_d_minus_half():
    """'A turns +1, D turns −½ → arm?' for the course's 17/17/17/51 train (i^h = −3): Willis
    gives ω_h = (ω_1 − i·ω_4)/(1 − i) = (1 − 1.5)/4 = −1/8."""
    st = solve_gear_text(scene("two_row_ext_int", [17, 17, 17, 51], {"1": 1, "4": -0.5}),
                         "d.toml")
    assert st.solution.planetary.plan.omega["h"] == pytest.approx(-0.125, rel=1e-14)
    doc = st.to_json()["planetary"]
    assert doc["differential"]["omega_each_input_alone_rad_s"][0]["h"] == pytest.approx(0.25)
    assert doc["differential"]["omega_each_input_alone_rad_s"][1]["h"] == pytest.approx(-0.375)
    text = st.report("ru")
    assert "-0,125" in text or "−0,125" in text


@pytest.mark.parametrize("extra, key", [
    ('fixed = "4"\n', "planetary.fixed"),
    ('ratio = 4\n', "planetary.ratio"),
])
def test_differential_keys_that_do_not_belong(extra, key):
    with pytest.raises(SceneError) as err:
        solve_gear_text(scene("two_row_ext_int", [17, 17, 17, 51], {"1": 1, "4": -0.5}, extra),
                        "d.toml")
    assert err.value.key == key


def test_differential_needs_two_links_and_teeth():
    text = scene("two_row_ext_int", [17, 17, 17, 51], {"1": 1, "4": -0.5})
    with pytest.raises(SceneError) as err:
        solve_gear_text(text.replace('"4" = "-0.5 rad/s"', '"9" = "1 rad/s"'), "d.toml")
    assert "speeds" in err.value.key
    with pytest.raises(SceneError) as err:
        solve_gear_text(text.replace("given = [17, 17, 17, 51]\n", ""), "d.toml")
    assert err.value.key == "planetary.given"
