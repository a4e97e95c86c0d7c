"""Options beyond what can be computed are refused at once with the estimate (issue 38):
``--positions 100000000000`` before its angles are allocated, ``--at 1e300``, ``--label-distance
inf``."""

from __future__ import annotations

import resource
import subprocess
import sys
import time
from pathlib import Path

import pytest

from mechplan.cli import main

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = str(ROOT / "templates" / "four_bar.toml")


def test_positions_beyond_the_budget_are_refused_before_allocating() -> None:
    # 1 GB of address space: allocating 10^11 angles (745 GiB) first would fail with MemoryError
    code = ("import resource, sys\n"
            "resource.setrlimit(resource.RLIMIT_AS, (2 * 1024**3, 2 * 1024**3))\n"
            "from mechplan.cli import main\n"
            f"sys.exit(main(['solve', {FOUR_BAR!r}, '--positions', '100000000000']))\n")
    start = time.perf_counter()
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120, check=False)
    assert run.returncode == 2, run.stderr
    assert "Traceback" not in run.stderr and "100000000000 positions" in run.stderr
    assert "TB of memory" in run.stderr and "MECHPLAN_MEMORY_BUDGET" in run.stderr
    assert time.perf_counter() - start < 30


def test_scene_count_beyond_the_budget_names_its_key(tmp_path, capsys) -> None:
    scene = tmp_path / "s.toml"
    scene.write_text(Path(FOUR_BAR).read_text(encoding="utf-8").replace(
        "count = 12", "count = 1000000000"), encoding="utf-8")
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err
    assert "key 'positions.count'" in err and "1000000000 positions" in err
    # nothing near the 8 GB of 10^9 angles was allocated (ru_maxrss is in kB)
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 500_000


@pytest.mark.parametrize("value", ["1e300", "inf", "nan", "2e6"])
def test_solve_at_far_angles_is_refused(value: str, capsys) -> None:
    with pytest.raises(SystemExit) as info:
        main(["solve", FOUR_BAR, "--at", "30", value])
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert "--at" in err and "within ±1e+06" in err and "Traceback" not in err


def test_at_1e300_says_how_far_apart_floats_are(capsys) -> None:
    with pytest.raises(SystemExit):
        main(["solve", FOUR_BAR, "--at", "1e300"])
    assert "1.5e+284° apart" in capsys.readouterr().err


def test_check_at_far_angle_is_refused(tmp_path, capsys) -> None:
    table = tmp_path / "t.toml"
    table.write_text("[velocity]\npb = 67.0\n", encoding="utf-8")
    with pytest.raises(SystemExit) as info:
        main(["check", FOUR_BAR, str(table), "--at", "1e300"])
    assert info.value.code == 2 and "--at" in capsys.readouterr().err


@pytest.mark.parametrize(("option", "value"), [("--label-distance", "inf"),
                                               ("--label-distance", "5000"),
                                               ("--snap", "inf"), ("--snap", "1e308")])
def test_check_distances_are_finite_and_on_a_sheet(option: str, value: str, tmp_path,
                                                   capsys) -> None:
    table = tmp_path / "t.toml"
    table.write_text("[velocity]\npb = 67.0\n", encoding="utf-8")
    assert main(["check", FOUR_BAR, str(table), option, value, "--lang", "ru"]) == 2
    err = capsys.readouterr().err
    assert option in err and "Traceback" not in err and "1189" in err
    assert "конечным числом" in err                  # said in the report's language


@pytest.mark.parametrize("spec", ["9" * 400 + "mm", "99999mm", "velocity=500%", "1000deg"])
def test_check_tolerance_that_would_pass_anything(spec: str, tmp_path, capsys) -> None:
    table = tmp_path / "t.toml"
    table.write_text("[velocity]\npb = 67.0\n", encoding="utf-8")
    assert main(["check", FOUR_BAR, str(table), "--tolerance", spec]) == 2
    err = capsys.readouterr().err
    assert "--tolerance" in err and "Traceback" not in err and len(err) < 600


@pytest.mark.parametrize("jobs", ["0", "1000000000"])
def test_check_class_jobs(jobs: str, tmp_path, capsys) -> None:
    folder = tmp_path / "class"
    folder.mkdir()
    (folder / "ivanov.toml").write_text("[velocity]\npb = 67.0\n", encoding="utf-8")
    assert main(["check", FOUR_BAR, str(folder), "-o", str(tmp_path / "out"), "--jobs",
                 jobs]) == 2
    assert "--jobs" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_api_and_solver_refuse_far_angles() -> None:
    import mechplan
    from mechplan.limits import LimitError
    from mechplan.scene import load_scene
    from mechplan.solve import solve

    m = mechplan.load(FOUR_BAR)
    with pytest.raises(LimitError, match="phi_deg must be .* within ±1e\\+06"):
        m.solve(phi_deg=[30.0, 1e300])
    with pytest.raises(LimitError, match="1.5e\\+284° apart"):
        solve(load_scene(FOUR_BAR), at_deg=[1e300])
    assert m.solve(phi_deg=[30.0, 999_999.0]).phi_deg.shape == (2,)


def test_a_report_beyond_the_budget_is_refused_at_once_with_its_estimate(capsys, monkeypatch):
    """Issue 35: `solve --positions 1000000 --json` is refused in about a second (it used to run
    for over ten minutes to 5.4 GB); the estimate comes from one position's JSON."""
    start = time.perf_counter()
    code = main(["solve", FOUR_BAR, "--positions", "1000000", "--json"])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert "a report of 1000000 positions needs about" in err and "at most about" in err
    assert time.perf_counter() - start < 20
    # the same report under a budget it fits in is written: 3000 positions need about 100 MB
    monkeypatch.setenv("MECHPLAN_MEMORY_BUDGET", "10 MB")
    assert main(["solve", FOUR_BAR, "--positions", "3000", "--json"]) == 2
    assert "more than the budget of 10.0 MB" in capsys.readouterr().err
    monkeypatch.setenv("MECHPLAN_MEMORY_BUDGET", "1 GB")
    assert main(["solve", FOUR_BAR, "--positions", "3000", "--json"]) == 0
    assert capsys.readouterr().out.count('"phi_deg"') >= 3000
