"""Imports flow one way: geometry never imports a renderer, renderers never compute mechanics,
strings from files stop in scene/ and submission/. What each package may import, and that drafting
knows no mechanics, are import-linter contracts in pyproject.toml (tests/test_import_contracts.py);
checked here on the source, with ast: no module-level import cycles, who reads TOML, what renderers
name, the operation registry, module sizes."""

from __future__ import annotations

import ast
import graphlib
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "mechplan"

def test_only_scene_reads_toml_and_renderers_compute_no_mechanics():
    for path in SRC.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(SRC)
        if "tomllib" in text:
            assert rel.parts[0] in ("scene", "submission"), rel
        if rel.parts[0] == "render":
            assert "construct" not in text and "solve" not in text, rel


# -- modules ------------------------------------------------------------------------------------
def _module(path: Path) -> str:
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module(p): p for p in SRC.rglob("*.py")}


def _module_level_imports(path: Path) -> set[str]:
    """mechplan modules a module imports when it is imported (not inside functions, not for
    type checking only); importing ``a.b.c`` also imports the packages ``a.b`` and ``a``."""
    name = _module(path)
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    found: set[str] = set()

    def visit(body: list[ast.stmt]) -> None:
        for node in body:
            if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
                continue
            if isinstance(node, (ast.If, ast.Try)):
                visit(node.body)
                visit(node.orelse)
                for handler in getattr(node, "handlers", []):
                    visit(handler.body)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[: len(package.split(".")) - node.level + 1]
                    mod = ".".join(base + ([node.module] if node.module else []))
                else:
                    mod = node.module or ""
                for alias in node.names:
                    full = f"{mod}.{alias.name}"
                    found.add(full if full in MODULES else mod)
            elif isinstance(node, ast.Import):
                found.update(alias.name for alias in node.names)

    visit(ast.parse(path.read_text(encoding="utf-8")).body)
    out = set()
    for mod in found:
        parts = mod.split(".")
        for i in range(2, len(parts) + 1):
            parent = ".".join(parts[:i])
            # a submodule importing its own package is how packages work, not a cycle
            if parent in MODULES and parent != name and not name.startswith(parent + "."):
                out.add(parent)
    return out


def test_no_module_level_import_cycles():
    """Not an import-linter contract: its acyclic_siblings squashes packages and counts imports
    inside functions, which break some cycles on purpose. graphlib (the standard library) finds a
    cycle in what modules import when they are imported."""
    graph = {m: _module_level_imports(p) for m, p in MODULES.items()}
    try:
        graphlib.TopologicalSorter(graph).prepare()
    except graphlib.CycleError as error:
        pytest.fail("module-level import cycle: " + " imports ".join(reversed(error.args[1])))


def test_operations_live_in_one_registry():
    """Nothing outside construct/ops/ evaluates an operation, and no module fills a registry."""
    for path in SRC.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(SRC)
        assert "EVALUATORS.update" not in text and "EVALUATORS[" not in text, rel


@pytest.mark.parametrize("package", ["construct", "geom", "model", "drafting", "sheet", "render",
                                     "dynamics", "scene", "submission", "check", "studies",
                                     "batch", "synthesis"])
def test_modules_are_small(package):
    for path in sorted((SRC / package).rglob("*.py")):
        lines = path.read_text(encoding="utf-8").count("\n")
        assert lines <= 500, f"{path.relative_to(SRC)} has {lines} lines"
