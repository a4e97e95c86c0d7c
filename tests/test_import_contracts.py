"""Imports flow one way: the import-linter contracts in pyproject.toml ([tool.importlinter]) hold,
and each kind of them breaks when the code breaks it (checked on a copy of the package)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = ROOT / "pyproject.toml"
CONTRACTS = {contract["id"]: contract["name"] for contract in
             tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["tool"]["importlinter"]["contracts"]}
LINT_IMPORTS = "from importlinter.cli import lint_imports_command; lint_imports_command()"


def lint_imports(src: Path) -> subprocess.CompletedProcess[str]:
    """``lint-imports`` with the contracts of pyproject.toml, on the mechplan package in ``src``
    (the working directory comes first on the path; nothing is cached)."""
    return subprocess.run(
        [sys.executable, "-c", LINT_IMPORTS, str(PYPROJECT), "--no-cache", "--no-logo"],
        cwd=src, env={**os.environ, "COLUMNS": "1000"}, capture_output=True, text=True,
        timeout=300, check=False)


def test_the_import_contracts_hold():
    run = lint_imports(ROOT / "src")
    assert run.returncode == 0, run.stdout + run.stderr


#: a copy of the package where each kind of contract is broken: imports inside a function and
#: under TYPE_CHECKING count, a grant of one module (drafting.fields) is not the whole package,
#: and drafting reaches mechanics through another module (i18n) while importing only the base
BREAKS = {
    "geom/__init__.py": "\n\ndef _broken():\n    import mechplan.construct\n",
    "model/__init__.py": "\nfrom typing import TYPE_CHECKING\n\nif TYPE_CHECKING:\n"
                         "    import mechplan.dynamics\n",
    "scene/__init__.py": "\nimport mechplan.drafting.frame\n",
    "i18n.py": "\n\ndef _broken():\n    import mechplan.geom\n",
}
BROKEN = {"geom", "model", "scene", "drafting-knows-no-mechanics"}


def test_each_kind_of_contract_breaks(tmp_path):
    def not_python(folder: str, names: list[str]) -> list[str]:
        return [name for name in names if name == "__pycache__"
                or not (name.endswith(".py") or (Path(folder) / name).is_dir())]

    copy = tmp_path / "mechplan"
    shutil.copytree(ROOT / "src" / "mechplan", copy, ignore=not_python)
    for name, code in BREAKS.items():
        with open(copy / name, "a", encoding="utf-8") as module:
            module.write(code)
    run = lint_imports(tmp_path)
    report = run.stdout + run.stderr
    assert run.returncode == 1, report
    broken = {key for key, name in CONTRACTS.items() if f"{name} BROKEN" in run.stdout}
    kept = {key for key, name in CONTRACTS.items() if f"{name} KEPT" in run.stdout}
    assert broken == BROKEN, report
    assert kept == set(CONTRACTS) - BROKEN, report
