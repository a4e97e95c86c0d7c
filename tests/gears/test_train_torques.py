"""Torques and efficiency of a planetary train, Willis with losses per mesh, against the closed
forms printed in the course books (Kudryavtsev, «Теория механизмов и машин»; Artobolevsky §
on the efficiency of planetary trains):

- gear a drives the carrier, b held, i = i_ab^h < 0 (a drives in the relative motion):
  η_ah = (1 − η^h·i)/(1 − i);
- the carrier drives gear a, b held, 0 < i < 1 (a still drives in the relative motion):
  η_ha = (1 − i)/(1 − η^h·i) — 0.5 % for Artobolevsky's ratio-10⁴ train at η^h = 0.99²;
- with the carrier held it is an ordinary train: η = η^h.
Forces on the planet: M_a/(k·r_wa) at the pitch point A, by statics of the gear."""

from __future__ import annotations

import pytest

from mechplan.studies.gears import solve_gear_text

SCENE = """kind = "gears"
[planetary]
scheme = "{scheme}"
fixed = "{fixed}"
input = "{inp}"
output = "{out}"
ratio = {ratio}
planets = {k}
module = "1 mm"
teeth = [10, 200]
given = {given}
mesh_efficiency = [{e1}, {e2}]
output_torque = "{load} N*m"
{extra}
"""


def solve(**kw):
    kw.setdefault("extra", "")
    kw.setdefault("k", 3)
    return solve_gear_text(SCENE.format(**kw), "t.toml")


def test_sun_drives_carrier_ring_held():
    z = (17, 17, 17, 51)
    i = -z[1] * z[3] / (z[0] * z[2])
    st = solve(scheme="two_row_ext_int", fixed="4", inp="1", out="h", ratio=4, given=list(z),
               e1=0.98, e2=0.99, load=100.0, k=3)
    doc = st.to_json()["planetary"]["torques"]
    eta_h = 0.98 * 0.99
    assert doc["efficiency"] == pytest.approx((1 - eta_h * i) / (1 - i), rel=1e-12)
    m = doc["torque_N_m"]
    assert m["h"] == pytest.approx(-100.0, rel=1e-12)            # resisting, ω_h > 0
    assert m["1"] + m["4"] + m["h"] == pytest.approx(0.0, abs=1e-9)
    # the input torque: P_in = −P_out/η
    assert m["1"] * 1.0 == pytest.approx(100.0 * (1 / 4) / doc["efficiency"], rel=1e-12)
    # force on one planet at A: M_1/(k·r_w1), r_w1 = m·z1/2
    assert doc["planet_force_N"]["A"] == pytest.approx(m["1"] / (3 * 0.0085), rel=1e-12)


def test_carrier_drives_the_ratio_10000_train():
    z = (100, 101, 100, 99)
    i = z[1] * z[3] / (z[0] * z[2])
    st = solve(scheme="two_row_ext_ext", fixed="4", inp="h", out="1", ratio=10000, given=list(z),
               e1=0.99, e2=0.99, load=1.0, k=1, extra='centre_distance = "auto"')
    doc = st.to_json()["planetary"]["torques"]
    eta_h = 0.99 ** 2
    assert doc["efficiency"] == pytest.approx((1 - i) / (1 - eta_h * i), rel=1e-9)
    assert doc["efficiency"] == pytest.approx(0.0050005, rel=1e-4)
    assert doc["driver_in_relative_motion"] == "1"


def test_carrier_held_is_an_ordinary_train():
    st = solve(scheme="two_row_ext_int", fixed="h", inp="1", out="4", ratio=-3,
               given=[17, 17, 17, 51], e1=0.97, e2=0.99, load=30.0)
    assert st.to_json()["planetary"]["torques"]["efficiency"] == pytest.approx(0.97 * 0.99,
                                                                                rel=1e-12)


def test_lossless_train_balances_power():
    st = solve(scheme="single_row", fixed="3", inp="1", out="h", ratio=5.1, given=[20, 31, 82],
               e1=1, e2=1, load=10.0)
    doc = st.to_json()["planetary"]
    m, w = doc["torques"]["torque_N_m"], doc["omega_rad_s"]
    assert sum(m[n] * w[n] for n in m) == pytest.approx(0.0, abs=1e-12)
    assert doc["torques"]["efficiency"] == pytest.approx(1.0, rel=1e-12)
    assert "η = 1" in st.report("en").replace("1.0000", "1")
