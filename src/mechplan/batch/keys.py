"""Scene key paths (``links.2.lengths.BC``): read and set values in a scene's TOML document."""

from __future__ import annotations

import copy
import re
from typing import Any

from ..errors import SceneError

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def split_key(key: str) -> list[str]:
    """Split a key path into its parts; a user error names the key."""
    parts = key.strip().split(".")
    if not key.strip() or any(not p for p in parts):
        raise SceneError(f"a key path must be names joined by dots, e.g. links.2.lengths.BC "
                         f"(got {key!r})")
    return parts


def get_value(doc: dict[str, Any], key: str, file: str | None = None) -> Any:
    """Return the value at a key path of a TOML document."""
    node: Any = doc
    for part in split_key(key):
        if not isinstance(node, dict) or part not in node:
            raise SceneError(f"the template has no value at {key}; set keys the template already "
                             "has", file=file, key=key)
        node = node[part]
    return node


def with_values(doc: dict[str, Any], values: dict[str, Any],
                file: str | None = None) -> dict[str, Any]:
    """Return a copy of a TOML document with values set at key paths (existing tables only)."""
    out = copy.deepcopy(doc)
    for key, value in values.items():
        parts = split_key(key)
        node: Any = out
        for part in parts[:-1]:
            if not isinstance(node, dict) or not isinstance(node.get(part), dict):
                raise SceneError(f"the template has no table at {'.'.join(parts[:-1])}; set keys "
                                 "inside the template's tables", file=file, key=key)
            node = node[part]
        node[parts[-1]] = value
    return out


def split_quantity(text: str, key: str) -> tuple[float, str]:
    """Split ``"80 mm"`` / ``"80mm"`` / ``"0,3"`` into (80.0, "mm")."""
    m = _NUMBER.match(text)
    if not m:
        raise SceneError(f"a value must be a number with an optional unit, e.g. '80 mm' "
                         f"(got {text!r})", key=key)
    return float(m.group(1).replace(",", ".")), m.group(2)


def quantity_text(value: float, unit: str) -> Any:
    """Write a number back as a scene value: ``"80 mm"``, or a bare float without a unit."""
    return f"{value:.12g} {unit}" if unit else float(f"{value:.12g}")
