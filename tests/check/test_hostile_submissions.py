"""Submissions written to break the checker end in a clean message (issue 38): nesting in a TOML
answer table, huge numbers, a name with a subscript thousands of characters long."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from mechplan.cli import main
from mechplan.scene import load_scene
from mechplan.submission.notation import points, read

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = str(ROOT / "templates" / "four_bar.toml")


def check_table(text: str, tmp_path: Path, capsys, *args: str) -> tuple[int, str]:
    table = tmp_path / "ivanov.toml"
    table.write_text(text, encoding="utf-8")
    code = main(["check", FOUR_BAR, str(table), "--at", "60", *args])
    err = capsys.readouterr().err
    assert "Traceback" not in err and len(err) < 2500, err
    return code, err


@pytest.mark.parametrize("nested", ["x = " + "[" * 1000 + "]" * 1000,
                                    "[values]\n" + "a." * 600 + "b = 1"])
def test_deep_answer_table(nested: str, tmp_path, capsys) -> None:
    code, err = check_table('"φ" = "60°"\n' + nested + "\n", tmp_path, capsys)
    assert code == 2 and "ivanov.toml" in err and "nested more than 32 levels" in err


def test_deep_answer_table_in_russian(tmp_path, capsys) -> None:
    code, err = check_table("x = " + "[" * 1000 + "]" * 1000 + "\n", tmp_path, capsys,
                            "--lang", "ru")
    assert code == 2 and "вложены глубже 32" in err


def test_huge_number_in_an_answer_table(tmp_path, capsys) -> None:
    code, err = check_table("[velocity]\npb = " + "9" * 400 + "\n", tmp_path, capsys)
    assert code == 2 and "key 'velocity.pb'" in err and "400 digits" in err


def test_long_subscript_is_not_understood(tmp_path, capsys) -> None:
    code, err = check_table('[values]\n"V' + "C" * 3000 + '" = "6.78 m/s"\n', tmp_path, capsys)
    assert code == 2 and "not understood" in err


def test_points_of_a_long_subscript_without_recursion() -> None:
    mech = load_scene(FOUR_BAR).mechanism
    start = time.perf_counter()
    assert points("b2" * 5000, mech) == ["B"] * 5000
    assert points("b2" * 5000 + "x", mech) is None
    assert read("V" + "C" * 5000, mech) is None
    assert time.perf_counter() - start < 15


def test_points_split_as_before() -> None:
    mech = load_scene(FOUR_BAR).mechanism
    assert points("cb", mech) == ["C", "B"]
    assert points("c2b2", mech) == ["C", "B"]
    assert points("e2", mech) == ["E"]
    assert points("", mech) == []
    assert points("z", mech) is None
    assert read("VC2B2", mech) is not None and read("VC2B2", mech).canonical == "v_CB"


def test_long_word_is_read_in_linear_time() -> None:
    # the a_CB^n pattern took quadratic time: 20,000 letters were minutes over a table
    from mechplan.submission.notation import compact, dimension

    start = time.perf_counter()
    for _ in range(20):
        assert read("x" * 20_000, None) is None and dimension("x" * 20_000) is None
        compact("x" * 20_000)
    assert time.perf_counter() - start < 15


def test_csv_with_a_long_name(tmp_path, capsys) -> None:
    table = tmp_path / "ivanov.csv"
    table.write_text("name,value\npb,67.0\n" + "x" * 20_000 + ",1\n", encoding="utf-8")
    start = time.perf_counter()
    code = main(["check", FOUR_BAR, str(table), "--at", "60"])
    assert code in (1, 2) and time.perf_counter() - start < 20
    assert "Traceback" not in capsys.readouterr().err
