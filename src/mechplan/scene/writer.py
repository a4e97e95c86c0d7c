"""Scene dicts written back as TOML text (inline tables), read back unchanged by the loader."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..errors import SceneError, shown_key
from ..i18n import Text
from .toml import MAX_NESTING


def _toml_value(value: Any, key: str, depth: int = 1) -> str:
    if depth > MAX_NESTING:  # also a table that contains itself
        raise SceneError(
            Text("errmsg.scene_writer.tables_lists_are", {"max_nesting": str(MAX_NESTING)}),
            file="<dict>",
            key=shown_key(key),
        )
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        x = float(value)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, os.PathLike):
        return json.dumps(os.fspath(value), ensure_ascii=False)
    if isinstance(value, Mapping):
        items = ", ".join(f"{json.dumps(str(k), ensure_ascii=False)} = "
                          f"{_toml_value(v, f'{key}.{k}', depth + 1)}" for k, v in value.items())
        return "{" + items + "}"
    if isinstance(value, (list, tuple)):
        items = ", ".join(_toml_value(v, f"{key}[{i}]", depth + 1) for i, v in enumerate(value))
        return "[" + items + "]"
    raise SceneError(
        Text("errmsg.scene_writer.text_number_list", {"name": str(type(value).__name__)}),
        file="<dict>",
        key=key,
    )


def to_toml(data: Mapping[str, Any]) -> str:
    """Return TOML text for a scene given as a dict (inline tables, read back unchanged)."""
    if not isinstance(data, Mapping):
        raise SceneError(
            Text("errmsg.scene_writer.scene_table_name", {"name": str(type(data).__name__)}),
            file="<dict>",
        )
    return "".join(f"{json.dumps(str(k), ensure_ascii=False)} = {_toml_value(v, str(k))}\n"
                   for k, v in data.items())
