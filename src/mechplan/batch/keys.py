"""Scene key paths (``links.2.lengths.BC``): read and set values in a scene's TOML document."""

from __future__ import annotations

import copy
import re
from typing import Any

from ..errors import SceneError
from ..i18n import Text
from .texts import say

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def split_key(key: str) -> list[str]:
    """Split a key path into its parts; a user error names the key."""
    parts = key.strip().split(".")
    if not key.strip() or any(not p for p in parts):
        raise SceneError(Text("batchvars.key_path", {"value": repr(key)}))
    return parts


def get_value(doc: dict[str, Any], key: str, file: str | None = None) -> Any:
    """Return the value at a key path of a TOML document."""
    node: Any = doc
    for part in split_key(key):
        if not isinstance(node, dict) or part not in node:
            raise SceneError(Text("batchvars.no_value", {"key": key}), file=file, key=key)
        node = node[part]
    return node


def with_values(doc: dict[str, Any], values: dict[str, Any],
                file: str | None = None) -> dict[str, Any]:
    """Return a copy of a TOML document with values set at key paths.

    Only values the template has can be set, never a whole table (``[output]``) or an array of
    tables; the new value is a number, a text, a boolean or a list of them; a value naming a
    file is a plain file name (inside the folder the scene is written to).
    """
    out = copy.deepcopy(doc)
    for key, value in values.items():
        node = out
        parts = split_key(key)
        for part in parts[:-1]:
            if not isinstance(node, dict) or not isinstance(node.get(part), dict):
                raise SceneError(say("key_missing", key=key), file=file, key=key)
            node = node[part]
        if not isinstance(node, dict) or parts[-1] not in node:
            raise SceneError(say("key_missing", key=key), file=file, key=key)
        if _is_table(node[parts[-1]]):
            raise SceneError(say("key_table", key=key), file=file, key=key)
        check_value(key, value, file)
        node[parts[-1]] = value
    return out


def _is_table(value: Any) -> bool:
    return isinstance(value, dict) or (isinstance(value, list)
                                       and any(isinstance(v, dict) for v in value))


def check_value(key: str, value: Any, file: str | None = None) -> None:
    """Refuse a value a variant may not set at ``key``: a table, a date, a path out of the
    scene's folder."""
    kind = _kind(value)
    if kind:
        raise SceneError(say("value_kind", kind=kind), file=file, key=key)
    parts = split_key(key)
    if parts[-1] in PATH_KEYS or "output" in parts[:-1]:
        for text in _texts(value):
            if text in ("", ".", "..") or any(c in text for c in "/\\\0:") or text[0] == "~":
                raise SceneError(say("path_outside", value=repr(text)), file=file, key=key)


#: keys whose value names a file (read or written relative to the scene's folder)
PATH_KEYS = frozenset({"file", "csv", "path", "dir", "folder", "dxf", "svg", "pdf", "png"})


def _kind(value: Any) -> str:
    if isinstance(value, bool | int | float | str):
        return ""
    if isinstance(value, list):
        return next((k for k in map(_kind, value) if k), "")
    return "table" if isinstance(value, dict) else type(value).__name__


def _texts(value: Any) -> list[str]:
    if isinstance(value, list):
        return [t for v in value for t in _texts(v)]
    return [value] if isinstance(value, str) else []


def split_quantity(text: str, key: str) -> tuple[float, str]:
    """Split ``"80 mm"`` / ``"80mm"`` / ``"0,3"`` into (80.0, "mm")."""
    m = _NUMBER.match(text)
    if not m:
        raise SceneError(Text("batchvars.number", {"value": repr(text)}), key=key)
    return float(m.group(1).replace(",", ".")), m.group(2)


def quantity_text(value: float, unit: str) -> Any:
    """Write a number back as a scene value: ``"80 mm"``, or a bare float without a unit."""
    return f"{value:.12g} {unit}" if unit else float(f"{value:.12g}")


def edited_text(text: str, values: dict[str, Any], file: str | None = None) -> str:
    """Return the template's TOML text with values set at key paths, as the template wrote it.

    The checks are :func:`with_values`'s (the text must already have passed the scene's own TOML
    reader, which limits its size and nesting); the edit is made on the template's document with
    tomlkit, so its comments, table order, ``[[loads]]`` and line breaks are kept and only the
    changed numbers differ.
    """
    import tomlkit

    from ..scene.document import parse_toml

    with_values(parse_toml(text, file or "<template>"), values, file)   # raises what it refuses
    doc = tomlkit.parse(text)
    for key, value in values.items():
        *path, last = split_key(key)
        node: Any = doc
        for part in path:
            node = node[part]
        node[last] = list(value) if isinstance(value, tuple) else value
    return tomlkit.dumps(doc)

