"""Typed access to a TOML table with key paths in every error message."""

from __future__ import annotations

import difflib
from typing import Any

from ..errors import SceneError, shown
from ..i18n import Text
from ..units import parse_quantity

#: largest magnitude (SI) a scene may give per dimension: beyond, squares overflow or lose all
#: digits
LIMITS = {"length": 1e6, "angle": 1e6, "angular_velocity": 1e9}
DEFAULT_LIMIT = 1e15


def _limit(dimension: str) -> str:
    from ..units import DIMENSIONS

    unit = DIMENSIONS.get(dimension, ("", ""))[1]
    return f"{LIMITS.get(dimension, DEFAULT_LIMIT):g} {unit}".strip()


class Table:
    """A TOML table that remembers its key path and which keys were used."""

    def __init__(self, data: Any, path: str, file: str) -> None:
        if not isinstance(data, dict):
            raise SceneError(Text("errors.table.expected",
                                  {"value": f"{type(data).__name__} {shown(data)}"}),
                             file=file, key=path or None)
        self.data = data
        self.path = path
        self.file = file

    def key(self, name: str) -> str:
        """Return the full key path of a child key."""
        return f"{self.path}.{name}" if self.path else name

    def error(self, name: str | None, message: str | Text) -> SceneError:
        """Return a SceneError located at a child key (or at this table)."""
        return SceneError(
            message, file=self.file, key=self.key(name) if name else (self.path or None)
        )

    def has(self, name: str) -> bool:
        """Tell whether a key is present."""
        return name in self.data

    def raw(self, name: str, default: Any = None, required: bool = False) -> Any:
        """Return a raw value."""
        if name not in self.data:
            if required:
                raise self.error(name, Text("errors.key.missing"))
            return default
        return self.data[name]

    def table(self, name: str, required: bool = False) -> Table | None:
        """Return a child table."""
        if name not in self.data:
            if required:
                raise self.error(name, Text("errors.key.table_missing"))
            return None
        return Table(self.data[name], self.key(name), self.file)

    def string(self, name: str, default: str | None = None, required: bool = False,
               choices: tuple[str, ...] | None = None) -> str | None:
        """Return a string value, optionally from a closed set."""
        value = self.raw(name, default, required)
        if value is None:
            return None
        if not isinstance(value, (str, int)) or isinstance(value, bool):
            raise self.error(name, Text("errors.key.expected_text", {"value": shown(value)}))
        value = str(value)
        if choices and value not in choices:
            raise self.error(name, Text("errors.key.one_of", {"choices": ", ".join(choices),
                                                               "value": shown(value)}))
        return value

    def quantity(self, name: str, dimension: str, default: float | None = None,
                 required: bool = False, positive: bool = False,
                 nonnegative: bool = False) -> float | None:
        """Return a quantity in SI units."""
        if name not in self.data:
            if required:
                raise self.error(name, Text("errors.key.missing_quantity",
                                            {"noun": Text(f"errors.noun.{dimension}")}))
            return default
        value = parse_quantity(self.data[name], dimension, file=self.file, key=self.key(name))
        limit = LIMITS.get(dimension, DEFAULT_LIMIT)
        if abs(value) > limit:
            raise self.error(name, Text("errors.key.too_large", {
                "limit": _limit(dimension), "value": shown(self.data[name])}))
        if positive and not value > 0:
            raise self.error(name, Text("errors.key.positive", {"value": shown(self.data[name])}))
        if nonnegative and value < 0:
            raise self.error(name, Text("errors.key.not_negative",
                                        {"value": shown(self.data[name])}))
        return value

    def value_quantity(self, value: Any, name: str, dimension: str) -> float:
        """Parse a value that sits at a child key."""
        out = parse_quantity(value, dimension, file=self.file, key=self.key(name))
        limit = LIMITS.get(dimension, DEFAULT_LIMIT)
        if abs(out) > limit:
            raise self.error(name, Text("errors.key.too_large", {"limit": _limit(dimension),
                                                                  "value": shown(value)}))
        return out

    def check_keys(self, allowed: tuple[str, ...]) -> None:
        """Reject unknown keys, suggesting the closest allowed one."""
        for name in self.data:
            if name not in allowed:
                close = difflib.get_close_matches(name, allowed, n=1)
                raise self.error(name, Text("errors.key.unknown_close", {"close": close[0]})
                                 if close else
                                 Text("errors.key.unknown", {"allowed": ", ".join(allowed)}))
