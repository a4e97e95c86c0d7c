"""The machine file's train: each shaft's exact ratio against the train's velocity plan (a linear
system written independently of Willis) and the textbook closed forms; shafts in series with
signs; members on a faster shaft turning a whole number of times per cycle; the course machine
template; the machine file's errors."""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path

import pytest

from mechplan.errors import SceneError
from mechplan.scene.gears import parse_gears
from mechplan.studies import solve_file
from mechplan.synthesis.gears.ratio import train_fraction
from mechplan.synthesis.gears.solve import solve_gears

ROOT = Path(__file__).resolve().parents[2] / "templates"


@pytest.mark.parametrize("stem", ["planetary_single_row", "planetary_two_row",
                                  "planetary_shifted"])
def test_exact_ratio_against_the_velocity_plan_and_the_closed_form(stem: str) -> None:
    path = ROOT / f"{stem}.toml"
    sol = solve_gears(parse_gears(path.read_text(encoding="utf-8"), str(path)))
    stages = dict(train_fraction(sol))
    res = sol.planetary
    assert res is not None and res.plan is not None
    u = stages["planetary"]
    assert float(u) == pytest.approx(res.plan.ratio, rel=1e-12)
    z = res.chosen.z
    s = res.spec
    if s.scheme.value == "single_row" and (s.fixed, s.input, s.output) == ("3", "1", "h"):
        assert u == 1 + Fraction(z[2], z[0])                 # u_1h = 1 + z3/z1
    if s.scheme.value == "two_row_ext_int" and (s.fixed, s.input, s.output) == ("4", "1", "h"):
        assert u == 1 + Fraction(z[1] * z[3], z[0] * z[2])   # u_1h = 1 + z2·z4/(z1·z3)
    if sol.ordinary is not None:
        assert stages["ordinary"] == Fraction(-sol.ordinary.z6, sol.ordinary.z5)


PAIR = """kind = "gears"
title = "pair"
[pair]
module = "3 mm"
teeth = [{z1}, {z2}]
"""

CAM = """kind = "cam"
title = "cam"
[follower]
motion = "translating"
contact = "roller"
roller_radius = "10 mm"
[motion]
stroke = "20 mm"
speed = "100 rpm"
phases = [
  { kind = "rise", angle = "100 deg", law = "cycloidal" },
  { kind = "far_dwell", angle = "40 deg" },
  { kind = "return", angle = "90 deg", law = "cosine" },
  { kind = "near_dwell", angle = "130 deg" },
]
"""

SLIDER = """title = "slider-crank"
[ground]
O = ["0 mm", "0 mm"]
guides.g = { through = "O", angle = "0 deg" }
[links.1]
lengths = { OA = "80 mm" }
[links.2]
lengths = { AB = "300 mm" }
[links.3]
slides = { point = "B", on = "g" }
[drive]
link = "1"
speed = "100 rpm"
"""


def _machine(tmp_path: Path, z: tuple[int, int], extra: str = "") -> Path:
    (tmp_path / "reducer.toml").write_text(
        (ROOT / "planetary_single_row.toml").read_text(encoding="utf-8"), encoding="utf-8")
    (tmp_path / "pair.toml").write_text(PAIR.format(z1=z[0], z2=z[1]), encoding="utf-8")
    (tmp_path / "cam.toml").write_text(CAM, encoding="utf-8")
    (tmp_path / "slider.toml").write_text(SLIDER, encoding="utf-8")
    path = tmp_path / "machine.toml"
    path.write_text(f"""kind = "cycle"
title = "m"
[motor]
speed = "1440 rpm"
sense = "cw"
[[shafts]]
name = "fast"
train = "reducer.toml"
[[shafts]]
name = "slow"
train = "pair.toml"
from = "fast"
[[members]]
name = "cam"
scene = "cam.toml"
shaft = "fast"
[[members]]
name = "slider"
scene = "slider.toml"
shaft = "slow"
{extra}""", encoding="utf-8")
    return path


def test_shafts_in_series_and_a_member_turning_twice_per_cycle(tmp_path: Path) -> None:
    st = solve_file(_machine(tmp_path, (20, 40)))
    doc = st.to_json()
    w_motor = -1440 * math.pi / 30
    fast, slow = doc["shafts"]
    assert fast["ratio"] == "5" and slow["ratio"] == "-2" and slow["ratio_from_motor"] == "-10"
    assert fast["omega_rad_s"] == pytest.approx(w_motor / 5, rel=1e-15)
    assert slow["omega_rad_s"] == pytest.approx(-w_motor / 10, rel=1e-15)
    assert doc["cycle_shaft"] == "slow"                       # the slowest by default
    cam, slider = doc["members"]
    assert cam["turns"] == 2 and slider["turns"] == 1
    spans = cam["on_shaft"]
    assert sum(s["to_deg"] - s["from_deg"] for s in spans) == pytest.approx(360.0)
    rises = [s["to_deg"] - s["from_deg"] for s in spans if s["kind"] == "rise"]
    assert sum(rises) == pytest.approx(100.0)                 # twice 50° of the slow shaft
    # the same phase on the two turns: the rises start 180° of the slow shaft apart
    starts = sorted(s["from_deg"] for s in spans if s["kind"] == "rise")
    assert len(starts) == 2 and starts[1] - starts[0] == pytest.approx(180.0)
    assert st.answers().scalars["slow.ratio"] == -10.0
    assert "−10" in st.report("en") and st.sheets(None, None, None, "machine")


def test_a_member_on_a_shaft_with_a_fractional_ratio_is_refused(tmp_path: Path) -> None:
    with pytest.raises(SceneError) as e:
        solve_file(_machine(tmp_path, (20, 30)))
    assert e.value.key == "members[0].shaft" and "3/2" in str(e.value)


def test_the_course_machine_template() -> None:
    st = solve_file(ROOT / "machine_course.toml")
    doc = st.to_json()
    sh = doc["shafts"][0]
    sol = solve_gears(parse_gears((ROOT / "planetary_single_row.toml").read_text("utf-8"),
                                  "planetary_single_row.toml"))
    assert sol.planetary is not None
    z = sol.planetary.chosen.z
    u = 1 + Fraction(z[2], z[0])
    assert sh["ratio"] == str(u)
    assert sh["omega_rad_s"] == pytest.approx(1440 * math.pi / 30 / float(u), rel=1e-15)
    kinds = [m["kind"] for m in doc["members"]]
    assert kinds == ["linkage", "cam", "driven"]
    lever = doc["members"][2]
    assert lever["driven_by"] == "cam" and lever["on_shaft"] == doc["members"][1]["on_shaft"]
    cl = lever["cam_linkage"]
    assert cl["omega_cam_rad_s"] == pytest.approx(abs(sh["omega_rad_s"]))
    assert min(cl["contact"]) > 0 and not cl["separates"]
    assert abs(cl["extremes"]["torque_mean"]) < 1e-6        # a conservative load: no net work


@pytest.mark.parametrize("extra, key", [
    ('[[members]]\nname = "x"\nscene = "slider.toml"\ndriven_by = "nobody"\nshaft = "slow"\n',
     "members[2].driven_by"),
    ('[[members]]\nname = "x"\nscene = "slider.toml"\ndriven_by = "cam"\nshaft = "fast"\n',
     "members[2].driven_by"),                                # a translating follower
    ('[[members]]\nname = "x"\nscene = "slider.toml"\nnear = "10 deg"\n', "members[2].near"),
    ('[[members]]\nname = "x"\nscene = "slider.toml"\ndriven_by = "cam"\nphase = "5 deg"\n',
     "members[2].phase"),
    ('[[members]]\nname = "x"\nscene = "slider.toml"\nshaft = "nowhere"\n', "members[2].shaft"),
])
def test_errors_name_their_key(tmp_path: Path, extra: str, key: str) -> None:
    with pytest.raises(SceneError) as e:
        solve_file(_machine(tmp_path, (20, 40), extra))
    assert e.value.key == key


def test_shafts_need_a_motor(tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text('kind = "cycle"\n[[shafts]]\nname = "s"\ntrain = "x.toml"\n'
                    '[[members]]\nname = "a"\nscene = "a.toml"\n', encoding="utf-8")
    with pytest.raises(SceneError) as e:
        solve_file(path)
    assert e.value.key == "shafts"
