"""CLI quirks of issue 21: each fixed, each with a test."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from mechplan import __version__
from mechplan.cli import main, template_names

ROOT = Path(__file__).resolve().parents[2]
TEMPLATES = ROOT / "templates"


def run(args: list[str], capsys) -> tuple[int, str, str]:
    try:
        code = main(args)
    except SystemExit as exc:           # argparse refuses the command line
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    return code, out, err


def test_version(capsys) -> None:
    code, out, _ = run(["--version"], capsys)
    assert code == 0 and out.strip() == f"mechplan {__version__}"


def test_positions_zero_is_refused(capsys) -> None:
    code, _, err = run(["solve", str(TEMPLATES / "four_bar.toml"), "--positions", "0"], capsys)
    assert code == 2 and "--positions" in err and "≥ 1" in err


def test_at_with_positions_is_refused(capsys) -> None:
    code, _, err = run(["solve", str(TEMPLATES / "four_bar.toml"), "--at", "30",
                        "--positions", "4"], capsys)
    assert code == 2 and "not allowed with" in err


def test_new_list_and_help_name_every_template(capsys) -> None:
    files = sorted(p.stem for p in TEMPLATES.glob("*.toml"))
    assert template_names() == files
    code, out, _ = run(["new", "--list"], capsys)
    assert code == 0 and out.split() == files
    code, out, _ = run(["new", "--help"], capsys)
    assert code == 0 and all(name in out.replace("\n", " ") for name in files)


@pytest.mark.parametrize("name", ["quick_return", "quick_return.toml"])
def test_new_with_or_without_suffix(tmp_path: Path, capsys, name: str, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, _ = run(["new", name], capsys)
    assert code == 0 and out.strip() == "quick_return.toml"
    assert (tmp_path / "quick_return.toml").read_text(encoding="utf-8") == \
        (TEMPLATES / "quick_return.toml").read_text(encoding="utf-8")
    code, _, err = run(["new", name], capsys)
    assert code == 2 and "exists already" in err


def test_new_into_a_folder_and_unknown_template(tmp_path: Path, capsys) -> None:
    code, out, _ = run(["new", "four_bar", "-o", str(tmp_path)], capsys)
    assert code == 0 and Path(out.strip()) == tmp_path / "four_bar.toml"
    code, _, err = run(["new", "five_bar"], capsys)
    assert code == 2 and "five_bar" in err and "four_bar" in err


def test_draw_reports_each_failure_and_draws_the_rest(tmp_path: Path, capsys) -> None:
    bad1 = tmp_path / "bad1.toml"
    bad1.write_text("title = 'x'\n[links.1]\n", encoding="utf-8")
    bad2 = tmp_path / "bad2.toml"
    bad2.write_text("not toml = = =", encoding="utf-8")
    out_dir = tmp_path / "out"
    code, out, err = run(["draw", str(bad1), str(TEMPLATES / "slider_crank.toml"), str(bad2),
                          "-o", str(out_dir), "--format", "svg"], capsys)
    assert code == 2
    assert "bad1.toml" in err and "bad2.toml" in err and "2 of 3 scenes failed" in err
    assert "Traceback" not in err
    assert (out_dir / "slider_crank.svg").is_file() and "slider_crank.svg" in out


def test_draw_unknown_format(tmp_path: Path, capsys) -> None:
    code, _, err = run(["draw", str(TEMPLATES / "four_bar.toml"), "-o", str(tmp_path),
                        "--format", "svg,jpg"], capsys)
    assert code == 2 and "--format" in err and "jpg" in err


def test_doctor_reports_fonts_viewers_and_extras(capsys) -> None:
    code, out, _ = run(["doctor"], capsys)
    assert code == 0
    assert "osifont: " in out and "Noto Sans CJK SC: " in out and "not found: text" not in out
    assert "librecad" in out and "chromium" in out and "pdfplumber" in out


@pytest.mark.skipif(shutil.which("bash") is None, reason="needs bash")
def test_bash_completion_completes_commands_and_templates(capsys) -> None:
    code, script, _ = run(["completion", "bash"], capsys)
    assert code == 0

    def complete(*words: str) -> list[str]:
        line = " ".join(["mechplan", *words])
        probe = (f"{script}\nCOMP_WORDS=(mechplan {' '.join(words)}); "
                 f"COMP_CWORD={len(words)}; COMP_LINE='{line}'; _mechplan; "
                 'printf "%s\\n" "${COMPREPLY[@]}"')
        proc = subprocess.run(["bash", "-c", probe], capture_output=True, text=True, timeout=20,
                              check=True)
        return proc.stdout.split()

    assert complete("d") == ["draw", "doctor"]
    assert complete("dr") == ["draw"]
    assert complete("new", "quick") == ["quick_return"]
    assert complete("draw", "x.toml", "--sheet", "A") == ["A0", "A1", "A2", "A3", "A4"]
