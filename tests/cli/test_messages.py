"""Messages that say what is actually wrong (issue 21), limits, and output paths — exit code 2."""

from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest

import mechplan
from mechplan.cli import main

ROOT = Path(__file__).resolve().parents[2]
SLIDER = (ROOT / "templates" / "slider_crank.toml").read_text(encoding="utf-8")
PARALLELOGRAM = """
title = "parallelogram"
[ground]
O = ["0 mm", "0 mm"]
D = ["200 mm", "0 mm"]
[links.1]
lengths = { OA = "100 mm" }
[links.2]
lengths = { AB = "200 mm" }
[links.3]
lengths = { DB = "100 mm" }
[drive]
link = "1"
speed = "100 rpm"
[assembly]
B = "left of O->D"
[positions]
at = ["30 deg"]
"""


def error_of(text: str, tmp_path: Path, capsys) -> str:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    code = main(["solve", str(scene)])
    _, err = capsys.readouterr()
    assert code == 2, err
    assert err.count("\n") == 1 and "Traceback" not in err and "scene.toml" in err
    return err


def test_unknown_slider_point(tmp_path, capsys) -> None:
    err = error_of(SLIDER.replace('point = "B", on = "x"', 'point = "Q", on = "x"'), tmp_path,
                   capsys)
    assert "links.3.slides.point" in err and "unknown point 'Q'" in err
    assert "degrees of freedom" not in err


def test_link_point_named_like_a_frame_point(tmp_path, capsys) -> None:
    err = error_of(SLIDER.replace('points = { S2 = "0.3 of A B" }',
                                  'points = { S2 = "0.3 of A B", O = ["10 mm", "0 mm"] }'),
                   tmp_path, capsys)
    assert "links.2.points.O has the name of a frame point" in err


def test_two_decimal_marks(tmp_path, capsys) -> None:
    err = error_of(SLIDER.replace('OA = "100 mm"', 'OA = "1,0,0 mm"'), tmp_path, capsys)
    assert "links.1.lengths.OA" in err and "one decimal mark" in err
    assert "positive" not in err


def test_missing_speed_names_speed(tmp_path, capsys) -> None:
    err = error_of(SLIDER.replace('speed = "1500 rpm"', ""), tmp_path, capsys)
    assert "drive.speed" in err and "omega" not in err and "800 rpm" in err


def test_parallelogram_at_its_change_point(tmp_path, capsys) -> None:
    err = error_of(PARALLELOGRAM, tmp_path, capsys)
    assert "assembly.B" in err and "collinear" in err and "ill-conditioned" in err
    assert "neither assembly" not in err
    # the hint works: assembled away from the change point, the scene solves
    fixed = PARALLELOGRAM.replace("[assembly]", '[assembly]\nat = "30 deg"')
    m = mechplan.loads(fixed)
    sol = m.solve(phi_deg=[30.0])
    # a parallelogram: the coupler stays parallel to the frame, ω2 = 0, ω3 = ω1
    assert abs(sol.omega["2"][0]) < 1e-12
    assert sol.omega["3"][0] == pytest.approx(sol.omega["1"][0], rel=1e-12)


def test_force_key_of_a_force_load(tmp_path, capsys) -> None:
    text = SLIDER + '\n[[loads]]\ntype = "force"\npoint = "B"\nforce = "800 N"\n'
    err = error_of(text, tmp_path, capsys)
    assert "loads[0].force" in err
    assert "did you mean 'bore'" not in err and "magnitude" in err and "vector" in err


def test_numeric_overflow_is_a_user_error(tmp_path, capsys) -> None:
    err = error_of(SLIDER.replace('OA = "100 mm"', 'OA = "1e300 mm"'), tmp_path, capsys)
    assert "links.1.lengths.OA" in err and "at most 1e+06 m" in err


def test_a_million_positions_are_refused_up_front_with_the_estimate(tmp_path, capsys) -> None:
    err = error_of(SLIDER.replace("count = 12", "count = 1000000"), tmp_path, capsys)
    assert "positions.count" in err and "1000000 positions" in err and "GB" in err
    assert "MECHPLAN_MEMORY_BUDGET" in err


def test_the_budget_is_configurable(monkeypatch) -> None:
    m = mechplan.loads(SLIDER)
    monkeypatch.setenv("MECHPLAN_MEMORY_BUDGET", "1 MB")
    with pytest.raises(mechplan.MechplanError, match="budget of 1.0 MB"):
        m.solve(positions=100_000)
    monkeypatch.setenv("MECHPLAN_MEMORY_BUDGET", "lots")
    with pytest.raises(mechplan.MechplanError, match="MECHPLAN_MEMORY_BUDGET must be a size"):
        m.solve(positions=10)
    monkeypatch.delenv("MECHPLAN_MEMORY_BUDGET")
    assert m.solve(positions=100_000).positions == 100_000


# -- output paths --------------------------------------------------------------------------------

def draw_error(args: list[str], capsys) -> str:
    code = main(["draw", str(ROOT / "templates" / "four_bar.toml"), "--format", "svg", *args])
    _, err = capsys.readouterr()
    assert code == 2 and "Traceback" not in err
    return err


def test_output_is_an_existing_file(tmp_path, capsys) -> None:
    blocker = tmp_path / "out"
    blocker.write_text("keep me", encoding="utf-8")
    err = draw_error(["-o", str(blocker)], capsys)
    assert str(blocker) in err and "must be a folder, not a file" in err
    assert blocker.read_text(encoding="utf-8") == "keep me"


def test_output_below_a_file(tmp_path, capsys) -> None:
    (tmp_path / "f").write_text("x", encoding="utf-8")
    err = draw_error(["-o", str(tmp_path / "f" / "sub")], capsys)
    assert "cannot be created" in err and "a part of it is a file" in err


def test_read_only_output_folder(tmp_path, capsys, monkeypatch) -> None:
    # root may write anywhere, so the refusal of the file system is simulated
    real = os.access
    monkeypatch.setattr(os, "access", lambda p, mode, **k: False if Path(p) == tmp_path
                        else real(p, mode, **k))
    err = draw_error(["-o", str(tmp_path)], capsys)
    assert str(tmp_path) in err and "must be writable" in err


def test_disk_full_leaves_no_partial_file(tmp_path, capsys, monkeypatch) -> None:
    from mechplan.render import atomic

    def full(fd: int) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(atomic.os, "fsync", full)
    err = draw_error(["-o", str(tmp_path)], capsys)
    assert "four_bar.svg" in err and "the disk is full" in err
    assert list(tmp_path.iterdir()) == []


def test_read_only_file_system(tmp_path, capsys, monkeypatch) -> None:
    import tempfile

    def erofs(*a, **k):
        raise OSError(errno.EROFS, "Read-only file system")

    monkeypatch.setattr(tempfile, "mkstemp", erofs)
    err = draw_error(["-o", str(tmp_path)], capsys)
    assert "read-only" in err and str(tmp_path) in err
