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


# -- named inputs ---------------------------------------------------------------------------------
def _iterates_inputs(node: ast.expr) -> bool:
    """A comprehension or generator over ``….inputs`` (``(g.pt(i) for i in s.inputs)``)."""
    return isinstance(node, ast.GeneratorExp | ast.ListComp) and any(
        isinstance(gen.iter, ast.Attribute) and gen.iter.attr == "inputs"
        for gen in node.generators)


def _positional_inputs(tree: ast.AST) -> list[int]:
    """Lines that read a step's inputs by position: ``x.inputs[0]``, ``x.inputs[2:]``, or
    ``a, b = x.inputs`` (also from a generator over them)."""
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute) \
                and node.value.attr == "inputs":
            index = node.slice
            if isinstance(index, ast.UnaryOp):  # inputs[-1]
                index = index.operand
            if isinstance(index, ast.Constant | ast.Slice):
                lines.append(node.lineno)
        elif isinstance(node, ast.Assign) and any(isinstance(t, ast.Tuple) for t in node.targets):
            value = node.value
            if isinstance(value, ast.Attribute) and value.attr == "inputs" \
                    or _iterates_inputs(value):
                lines.append(node.lineno)
    return sorted(lines)


def test_the_positional_input_finder_finds_them():
    source = ("a, b = step.inputs\n*_, x = s.inputs\ny = s.inputs[0]\nz = s.inputs[-1]\n"
              "w = s.inputs[2:]\n(p, q), r = (g.pt(i) for i in s.inputs)\n"
              "ok = [v[i] for i in step.inputs]\nfirst, *rest = dict.fromkeys(step.inputs)\n")
    assert _positional_inputs(ast.parse(source)) == [1, 2, 3, 4, 5, 6]


def test_inputs_are_read_by_name():
    """An operation's inputs are read by name (``step.input("start")``, ``step.rest()``), never by
    position; construct/step.py defines those two by the positions the spec gives."""
    allowed = SRC / "construct" / "step.py"
    found = [f"{path.relative_to(SRC)}:{line}" for path in sorted(SRC.rglob("*.py"))
             if path != allowed
             for line in _positional_inputs(ast.parse(path.read_text(encoding="utf-8")))]
    assert not found, "inputs read by position: " + ", ".join(found)
