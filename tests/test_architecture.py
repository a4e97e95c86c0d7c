"""Imports flow one way: geometry never imports a renderer, renderers never compute mechanics,
strings from files stop in scene/ (checked on the source, with ast)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "mechplan"

#: package → the mechplan packages it may import (errors and units are open to all)
ALLOWED = {
    "geom": set(),
    "model": set(),
    "scene": {"model"},
    "construct": {"geom", "model"},
    "dynamics": {"geom", "model", "scene", "construct"},
    "synthesis": {"geom", "model"},
    "sheet": {"geom", "model", "scene", "construct", "dynamics", "synthesis", "solve",
              "render.atomic"},
    "render": {"sheet"},
    "check": {"geom", "model", "scene", "construct", "dynamics", "synthesis", "solve", "sheet",
              "render", "studies"},
}
BASE = {"errors", "units", "i18n", "__init__", "__version__"}


def _imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = path.relative_to(SRC).parts[:-1]
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = list(package[: len(package) - node.level + 1])
                mod = ".".join(base + ([node.module] if node.module else []))
            elif node.module and node.module.startswith("mechplan"):
                mod = node.module.removeprefix("mechplan").lstrip(".")
            else:
                continue
            names = [mod] if node.module else [f"{mod}.{a.name}".strip(".") for a in node.names]
            out.update(n for n in names if n)
        elif isinstance(node, ast.Import):
            out.update(a.name.removeprefix("mechplan.") for a in node.names
                       if a.name.startswith("mechplan."))
    return out


@pytest.mark.parametrize("package", sorted(ALLOWED))
def test_package_imports_only_what_it_may(package):
    allowed = ALLOWED[package] | {package} | BASE
    for path in sorted((SRC / package).rglob("*.py")):
        for mod in _imports(path):
            top = mod.split(".")[0]
            ok = top in allowed or mod in allowed or any(mod.startswith(a + ".") or mod == a
                                                         for a in allowed)
            assert ok, f"{path.relative_to(SRC)} imports mechplan.{mod}"


def test_only_scene_reads_toml_and_renderers_compute_no_mechanics():
    for path in SRC.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(SRC)
        if "tomllib" in text:
            assert rel.parts[0] in ("scene", "check"), rel     # check reads TOML submissions
        if rel.parts[0] == "render":
            assert "construct" not in text and "solve" not in text, rel
