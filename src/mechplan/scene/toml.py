"""Parse TOML text that nobody checked: within limits of size, nesting, numbers and text length.

Every TOML document mechplan reads — scenes, variants files, submitted answer tables — goes through
:func:`loads`. ``tomllib`` recurses once per level of nested arrays and inline tables, so a file
nested a thousand levels deep would end in a ``RecursionError``; a 400-digit integer overflows the
float it becomes; a 50 MB string is slow to parse and to echo. These are refused here, with the
key path of the offending value (see docs/security.md).
"""

from __future__ import annotations

import math
import tomllib
from typing import Any

from ..i18n import Text

#: characters of TOML text parsed at most (a scene is a few kilobytes)
MAX_TEXT_CHARS = 4 * 1024 * 1024
#: tables and arrays inside each other (a scene needs 6, a submitted table 3)
MAX_NESTING = 32
#: characters of one string value or key (a title, a name, a quantity such as "80 mm")
MAX_STRING_CHARS = 10_000
#: magnitude of an integer or a float: beyond 2**53 integers are not exact as floats
MAX_NUMBER = 2**53


class TomlLimitError(ValueError):
    """A TOML document exceeds one of the limits; ``kind`` says which, ``key`` where."""

    def __init__(self, kind: str, message: str, key: str | None = None, **args: Any) -> None:
        super().__init__(message)
        self.kind = kind
        self.key = key
        self.args_ = args


def loads(text: str) -> dict[str, Any]:
    """Parse TOML text and check it against the limits.

    Raise :class:`tomllib.TOMLDecodeError` for bad syntax and :class:`TomlLimitError` for a
    document beyond a limit (too long, too deep, a number too large, a string too long).
    """
    if len(text) > MAX_TEXT_CHARS:
        raise TomlLimitError(
            "size",
            Text(
                "errmsg.scene_toml.text_text_characters",
                {"text": f"{len(text):,}", "max_text_chars": f"{MAX_TEXT_CHARS:,}"},
            ),
            size=len(text),
            limit=MAX_TEXT_CHARS,
        )
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        raise
    except RecursionError:  # tomllib recurses per level: far past MAX_NESTING
        raise _too_deep(None) from None
    except ValueError as exc:  # an integer of more than 4300 digits
        if "digits" not in str(exc):
            raise
        raise TomlLimitError(
            "number",
            Text("errmsg.scene_toml.number_beyond_max", {"max_number": str(MAX_NUMBER)}),
            value="…",
            limit=MAX_NUMBER,
        ) from None
    check(data)
    return data


def check(data: dict[str, Any]) -> None:
    """Check parsed TOML (or a dict given through the API) against the limits, without recursion."""
    stack: list[tuple[Any, str, int]] = [(data, "", 0)]
    while stack:
        value, path, depth = stack.pop()
        if isinstance(value, dict):
            if depth >= MAX_NESTING:
                raise _too_deep(path)
            for name, item in value.items():
                if not isinstance(name, str):
                    continue
                child = f"{path}.{name}" if path else name
                if len(name) > MAX_STRING_CHARS:
                    raise _too_long(path or None, len(name))
                stack.append((item, child, depth + 1))
        elif isinstance(value, list):
            if depth >= MAX_NESTING:
                raise _too_deep(path)
            stack.extend((item, f"{path}[{i}]", depth + 1) for i, item in enumerate(value))
        elif isinstance(value, str):
            if len(value) > MAX_STRING_CHARS:
                raise _too_long(path, len(value))
        elif isinstance(value, bool):
            continue
        elif isinstance(value, int):
            if abs(value) > MAX_NUMBER:
                digits = (f"{len(str(abs(value)))}" if value.bit_length() < 14_000   # str() stops
                          else f"about {int(value.bit_length() * math.log10(2)) + 1}")  # at 4300
                raise TomlLimitError(
                    "number",
                    Text(
                        "errmsg.scene_toml.within_max_number",
                        {"max_number": str(MAX_NUMBER), "digits": str(digits)},
                    ),
                    path,
                    value=f"{digits} digits",
                    limit=MAX_NUMBER,
                )
        elif isinstance(value, float) and not (math.isfinite(value) and abs(value) <= MAX_NUMBER):
            raise TomlLimitError(
                "number",
                Text(
                    "errmsg.scene_toml.finite_number_within",
                    {"max_number": f"{MAX_NUMBER:.3g}", "value": repr(value)},
                ),
                path,
                value=repr(value),
                limit=MAX_NUMBER,
            )


def _too_deep(path: str | None) -> TomlLimitError:
    return TomlLimitError(
        "nesting",
        Text("errmsg.scene_toml.tables_lists_are", {"max_nesting": str(MAX_NESTING)}),
        path or None,
        limit=MAX_NESTING,
    )


def _too_long(path: str | None, length: int) -> TomlLimitError:
    return TomlLimitError(
        "string",
        Text(
            "errmsg.scene_toml.text_length_characters",
            {"length": f"{length:,}", "max_string_chars": f"{MAX_STRING_CHARS:,}"},
        ),
        path,
        length=length,
        limit=MAX_STRING_CHARS,
    )
