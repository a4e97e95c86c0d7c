"""The code is clean by the project's own static checks: ruff (line length 100 enforced), mypy
over the package, and mypy --strict on geom/, model/ and construct/."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", *args], cwd=ROOT, capture_output=True, text=True,
                          check=False)


def test_ruff_is_clean():
    proc = _run("ruff", "check", "src", "tests", "benchmarks", "tools")
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_mypy_is_clean_and_strict_below_the_sheets():
    pkg = ROOT / "src" / "mechplan"
    proc = _run("mypy", "--no-error-summary", str(pkg))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    strict = _run("mypy", "--strict", "--no-error-summary",
                  *(str(pkg / p) for p in ("geom", "model", "construct")))
    assert strict.returncode == 0, strict.stdout + strict.stderr
