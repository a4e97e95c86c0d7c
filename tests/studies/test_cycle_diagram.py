"""The cycle diagram: a slider-crank's working stroke and return against the closed form, a cam's
phases as given, both on one shaft with their offsets; the machine file's errors."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import pytest

from mechplan.errors import SceneError
from mechplan.studies import solve_file, solve_text

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


def _slider(r: float, l: float, e: float, sense: str = "ccw") -> str:
    return f"""title = "slider-crank"
[ground]
O = ["0 mm", "0 mm"]
G = ["0 mm", "{e} mm"]
guides.g = {{ through = "G", angle = "0 deg" }}
[links.1]
lengths = {{ OA = "{r} mm" }}
[links.2]
lengths = {{ AB = "{l} mm" }}
[links.3]
slides = {{ point = "B", on = "g" }}
[drive]
link = "1"
speed = "100 rpm"
sense = "{sense}"
"""


def _machine(tmp_path: Path, members: str, files: dict[str, str]) -> Path:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    path = tmp_path / "machine.toml"
    path.write_text('kind = "cycle"\ntitle = "m"\n' + members, encoding="utf-8")
    return path


@pytest.mark.parametrize("r, l, e, sense", [(80, 300, 30, "ccw"), (100, 350, -60, "cw"),
                                            (50, 200, 0, "ccw")])
def test_slider_crank_strokes_closed_form(tmp_path: Path, r: float, l: float, e: float,
                                          sense: str) -> None:
    path = _machine(tmp_path, '[[members]]\nname = "ram"\nscene = "s.toml"\n',
                    {"s.toml": _slider(r, l, e, sense)})
    doc = solve_file(path).to_json()
    theta = math.degrees(math.asin(abs(e) / (l - r)) - math.asin(abs(e) / (l + r)))
    phases = {p["kind"]: p["angle_deg"] for p in doc["members"][0]["phases"]}
    assert phases["work"] == pytest.approx(180 + theta, abs=1e-9)
    assert phases["return"] == pytest.approx(180 - theta, abs=1e-9)
    # the diagram starts with the working stroke of the first member
    on = doc["members"][0]["on_shaft"]
    assert on[0]["kind"] == "work" and on[0]["from_deg"] == pytest.approx(0, abs=1e-9)
    assert on[0]["to_deg"] == pytest.approx(180 + theta, abs=1e-9)


def test_working_stroke_choice(tmp_path: Path) -> None:
    files = {"s.toml": _slider(80, 300, 30)}
    longer = solve_file(_machine(tmp_path, '[[members]]\nname = "a"\nscene = "s.toml"\n', files))
    flipped = solve_file(_machine(tmp_path, '[[members]]\nname = "a"\nscene = "s.toml"\n'
                                  'working = "to_max"\n', files))
    flipped2 = solve_file(_machine(tmp_path, '[[members]]\nname = "a"\nscene = "s.toml"\n'
                                   'working = "to_min"\n', files))
    w = {d.to_json()["members"][0]["phases"][0]["angle_deg"] for d in (flipped, flipped2)}
    assert len(w) == 2 and longer.to_json()["members"][0]["phases"][0]["angle_deg"] == max(w)


def test_cam_phases_and_offset_on_one_shaft(tmp_path: Path) -> None:
    members = ('[[members]]\nname = "ram"\nscene = "s.toml"\n'
               '[[members]]\nname = "feeder"\nscene = "c.toml"\nphase = "-75 deg"\n')
    st = solve_file(_machine(tmp_path, members, {"s.toml": _slider(80, 300, 30),
                                                 "c.toml": CAM}))
    doc = st.to_json()
    ram, cam = doc["members"]
    assert [(p["kind"], p["angle_deg"]) for p in cam["phases"]] == [
        ("rise", pytest.approx(100)), ("far_dwell", pytest.approx(40)),
        ("return", pytest.approx(90)), ("near_dwell", pytest.approx(130))]
    # ψ of the rise's start: cam angle 0 = ψ + phase → ψ = 75°, from the diagram's origin
    rise = next(s for s in cam["on_shaft"] if s["kind"] == "rise")
    assert rise["from_deg"] == pytest.approx((75 - doc["start_deg"]) % 360, abs=1e-9)
    for m in (ram, cam):
        total = sum(s["to_deg"] - s["from_deg"] for s in m["on_shaft"])
        assert total == pytest.approx(360, abs=1e-9)
        edges = [(s["from_deg"], s["to_deg"]) for s in m["on_shaft"]]
        assert all(b[0] == pytest.approx(a[1], abs=1e-9) for a, b in itertools.pairwise(edges))
    assert st.speeds[0] == pytest.approx(st.speeds[1]) and "rad/s" not in st.report("en")
    report = st.report("ru")
    assert "рабочий ход" in report and "дальнее стояние" in report


def test_speed_mismatch_is_warned(tmp_path: Path) -> None:
    members = ('[[members]]\nname = "ram"\nscene = "s.toml"\n'
               '[[members]]\nname = "f"\nscene = "c.toml"\n')
    st = solve_file(_machine(tmp_path, members, {"s.toml": _slider(80, 300, 30),
                                                 "c.toml": CAM.replace("100 rpm", "50 rpm")}))
    assert "different speeds" in st.report("en") and st.to_json()["members"][1]["speed_rad_s"] \
        == pytest.approx(50 * math.pi / 30)


@pytest.mark.parametrize("members, key", [
    ('[[members]]\nname = "a"\nscene = "missing.toml"\n', "members[0].scene"),
    ('[[members]]\nname = "a"\nscene = "s.toml"\n[[members]]\nname = "a"\nscene = "s.toml"\n',
     "members"),
    ('[[members]]\nname = "a"\nscene = "s.toml"\nworking = "fast"\n', "members[0].working"),
    ('[[members]]\nname = "a"\nscene = "s.toml"\noutput = "Q"\n', "members[0].output"),
])
def test_errors_name_the_key(tmp_path: Path, members: str, key: str) -> None:
    path = _machine(tmp_path, members, {"s.toml": _slider(80, 300, 30)})
    with pytest.raises(SceneError) as err:
        solve_file(path)
    assert err.value.key == key


def test_a_cylinder_driven_linkage_is_refused() -> None:
    root = Path(__file__).resolve().parents[2] / "templates"
    text = '[[members]]\nname = "boom"\nscene = "excavator_boom.toml"\n'
    with pytest.raises(SceneError) as err:
        solve_text('kind = "cycle"\n' + text, str(root / "m.toml"))
    assert err.value.key == "members[0].scene" and "crank" in str(err.value)


def test_rocker_output_of_a_crank_rocker(tmp_path: Path) -> None:
    """A four-bar's rocker: θ_w + θ_r = 360°, the working stroke the longer (K ≥ 1)."""
    root = Path(__file__).resolve().parents[2] / "templates"
    st = solve_text('kind = "cycle"\n[[members]]\nname = "r"\nscene = "four_bar.toml"\n',
                    str(root / "m.toml"))
    work, ret = st.members[0].spans
    assert work.kind == "work" and work.angle >= ret.angle
    assert work.angle + ret.angle == pytest.approx(2 * math.pi, abs=1e-12)
    # closed form: crank and coupler collinear, a = 80, b = 260, c = 180, d = 250 (mm)
    a, b, c, d = 80.0, 260.0, 180.0, 250.0
    ext = math.acos(((b + a) ** 2 + d ** 2 - c ** 2) / (2 * (b + a) * d))
    fold = math.acos(((b - a) ** 2 + d ** 2 - c ** 2) / (2 * (b - a) * d))
    theta = abs(fold - ext)
    assert work.angle == pytest.approx(math.pi + theta, abs=1e-9)


def test_template_draws_both_diagrams() -> None:
    root = Path(__file__).resolve().parents[2] / "templates"
    st = solve_file(root / "machine_cycle.toml")
    texts = " ".join(getattr(p, "string", "") for sh in st.sheets(None, None, "zh", "m")
                     for p in sh.primitives)
    assert "矩形运动循环图" in texts and "圆形运动循环图" in texts
    assert solve_text((root / "machine_cycle.toml").read_text(encoding="utf-8"),
                      str(root / "machine_cycle.toml")).to_json()["members"][1]["kind"] == "cam"
