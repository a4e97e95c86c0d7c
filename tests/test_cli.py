"""The command line: solve prints reports and JSON; user errors exit 2 without a traceback."""

import itertools
import json
import math
import subprocess
import sys

import pytest
from scenes import ROOT, TEMPLATES

from mechplan.cli import main


def run(args, capsys):
    code = main(args)
    out, err = capsys.readouterr()
    return code, out, err


def test_solve_v_engine_text_in_vietnamese(capsys):
    code, out, _ = run(["solve", str(ROOT / "templates" / "v_engine.toml")], capsys)
    assert code == 0
    assert "I(0,1) → II(2,3) → II(4,5)" in out
    assert "W = 3·5 − 2·7 = 1" in out
    assert "pb = 67,0 mm → v_B = 6,702 m/s" in out          # decimal comma in Vietnamese
    assert "Họa đồ vận tốc" in out and "Theo định lý đồng dạng" in out


@pytest.mark.parametrize("lang,words", [("en", "Through b draw a line ⊥ BC"),
                                        ("ru", "Через точку b проводим прямую ⊥ BC"),
                                        ("zh", "过 b 作 BC 的垂线")])
def test_solve_languages(capsys, lang, words):
    code, out, _ = run(["solve", str(ROOT / "templates" / "v_engine.toml"), "--lang", lang], capsys)
    assert code == 0 and words in out


def test_solve_json_document(capsys):
    _code, out, _ = run(["solve", str(ROOT / "templates" / "v_engine.toml"), "--json"], capsys)
    doc = json.loads(out)
    assert doc["dof"] == 1 and doc["structure"] == "I(0,1) → II(2,3) → II(4,5)"
    assert doc["groups"] == [{"class": 2, "kind": "RRP", "links": ["2", "3"]},
                             {"class": 2, "kind": "RRP", "links": ["4", "5"]}]
    pos = doc["positions"][0]
    assert (pos["phi_deg"] == pytest.approx(180.0)
            and pos["crank_angle_deg"] == pytest.approx(-120.0))
    w1 = 800 * 2 * math.pi / 60
    assert pos["links"]["2"]["omega"] == pytest.approx(-w1 * 0.08 / 0.248, rel=1e-12)
    assert pos["links"]["2"]["angle_deg"] == pytest.approx(60.0, abs=1e-9)
    b = pos["points"]["B"]
    assert math.hypot(*b["v"]) == pytest.approx(w1 * 0.08, rel=1e-14)
    assert set(b) == {"r", "v", "a"}


def test_solve_at_and_positions(capsys):
    path = str(ROOT / "templates" / "four_bar.toml")
    doc = json.loads(run(["solve", path, "--json", "--at", "0", "90"], capsys)[1])
    assert [p["phi_deg"] for p in doc["positions"]] == [0.0, 90.0]
    doc = json.loads(run(["solve", path, "--json", "--positions", "8"], capsys)[1])
    phis = [p["phi_deg"] for p in doc["positions"]]
    assert len(phis) == 8 and all(math.isclose((b - a) % 360, 45.0)
                                  for a, b in itertools.pairwise(phis))


def test_scene_error_exits_2_with_one_message(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text((ROOT / "templates" / "slider_crank.toml").read_text().replace(
        'OA = "100 mm"', 'OA = "100 kg"'))
    proc = subprocess.run([sys.executable, "-m", "mechplan.cli", "solve", str(bad)],
                          check=False, capture_output=True, text=True)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert 1 <= len(lines) <= 2
    assert ("bad.toml" in lines[0] and "links.1.lengths.OA" in lines[0]
            and "not a length" in lines[0])


def test_missing_file_exits_2(capsys):
    code, _, err = run(["solve", "/nonexistent/scene.toml"], capsys)
    assert code == 2 and "scene.toml: the scene file does not exist" in err


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_every_template_solves(path, capsys):
    code, out, _ = run(["solve", str(path), "--json"], capsys)
    assert code == 0
    doc = json.loads(out)
    # W = 1, or 2 with a second driving crank (docs/two_inputs.md)
    assert doc["dof"] == (2 if "second_driver" in doc else 1) and doc["positions"]
    for pos in doc["positions"]:
        for entry in pos["points"].values():
            assert all(math.isfinite(x)
                       for x in entry["r"] + entry.get("v", []) + entry.get("a", []))


def test_new_copies_a_template(tmp_path, capsys):
    dest = tmp_path / "mine.toml"
    assert run(["new", "shaper", "-o", str(dest)], capsys)[0] == 0
    assert dest.read_text() == (ROOT / "templates" / "shaper.toml").read_text()
    assert run(["new", "shaper", "-o", str(dest)], capsys)[0] == 2


def test_new_into_a_folder_named_with_a_trailing_slash(tmp_path, capsys, monkeypatch):
    """Issue 35: `new X -o sub/` writes sub/X.toml (the folder made), never a file named sub."""
    monkeypatch.chdir(tmp_path)
    code, _out, _ = run(["new", "four_bar", "-o", "sub/"], capsys)
    assert code == 0 and (tmp_path / "sub").is_dir()
    assert (tmp_path / "sub" / "four_bar.toml").read_text() == \
        (ROOT / "templates" / "four_bar.toml").read_text()
    (tmp_path / "afile").write_text("x")
    code, _, err = run(["new", "four_bar", "-o", "afile/"], capsys)
    assert code == 2 and "is a file" in err and (tmp_path / "afile").read_text() == "x"


@pytest.mark.parametrize("command", ["batch", "sweep", "check"])
def test_jobs_and_workers_are_one_option(command):
    """Issue 35: --jobs (as the README writes it), -j and --workers mean the same everywhere."""
    from mechplan.cli import parser

    extra = {"batch": ["t.toml", "v.csv", "-o", "o"],
             "sweep": ["t.toml", "--vary", "a=1..2:2", "-o", "o"],
             "check": ["t.toml", "s.dxf"]}[command]
    dest = "jobs" if command == "check" else "workers"
    for spelling in ("--jobs", "-j", "--workers"):
        args = parser().parse_args([command, *extra, spelling, "3"])
        assert getattr(args, dest) == 3, spelling


def test_solve_json_carries_forces_and_reduced_values(capsys):
    _code, out, _ = run(["solve", str(ROOT / "templates" / "v_engine.toml"), "--json"], capsys)
    pos = json.loads(out)["positions"][0]
    forces = pos["forces"]
    assert set(forces) == {"inertia", "reactions", "guide_reactions", "balancing_moment",
                           "zhukovsky_balancing_moment"}
    assert set(forces["reactions"]) == {"01", "12", "23", "24", "45"}
    assert set(forces["guide_reactions"]) == {"03", "05"}
    assert forces["balancing_moment"] == pytest.approx(forces["zhukovsky_balancing_moment"],
                                                       rel=1e-9)
    # gas force p·πd²/4 on piston E, along Ay towards A: the guide reaction is ⊥ Ay
    r05 = forces["guide_reactions"]["05"]["force"]
    assert (r05[0] * math.cos(math.radians(120)) + r05[1] * math.sin(math.radians(120))
            == pytest.approx(0, abs=1e-9))
    assert set(pos["reduced"]) == {"moment", "inertia"} and pos["reduced"]["inertia"] > 0


def test_help_and_version_import_nothing_heavy():
    """Issue 35: `mechplan --help` / `--version` answer at once — building the parser imports no
    numerical or drawing library and no part of the checker, the LMS round trip or the solver."""
    import subprocess
    import sys

    heavy = ("numpy", "pint", "scipy", "matplotlib", "ezdxf", "shapely", "mechplan.check.grade",
             "mechplan.lms.run", "mechplan.solve", "mechplan.scene.loader")
    code = ("import sys\nfrom mechplan.cli import parser\nparser()\n"
            f"print([m for m in {heavy!r} if m in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=120).stdout.strip()
    assert out == "[]", out
