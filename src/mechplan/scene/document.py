"""A scene file's text and its kind (the top-level ``kind`` key)."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from ..errors import SceneError
from ..i18n import Text
from ..userfiles import SCENE, FileKind
from ..userfiles import read_text as read_user_text
from . import toml

SCENE_KINDS: tuple[str, ...] = ("mechanism", "cam", "gears", "engine", "synthesis", "cycle")


def read_text(path: str | Path, kind: FileKind = SCENE) -> str:
    """Read a scene (or a variants file: ``kind``) as UTF-8 text: a regular file under its size
    limit (:mod:`mechplan.userfiles`); a user error names the file, never its content."""
    return read_user_text(path, kind, error=SceneError)


def study_kind(path: str | Path) -> tuple[str, dict[str, Any]] | None:
    """The study a scene file asks for — its kind (``"dynamics"`` for a mechanism with
    ``[dynamics]``, ``"linkage"`` for one with textbook ``[answers]``) and its parsed data — or
    None for a plain linkage."""
    data = parse_toml(read_text(path), str(path))
    kind = scene_kind(data, str(path))
    if kind == "mechanism":
        if "dynamics" in data:
            return "dynamics", data
        return ("linkage", data) if "answers" in data else None
    return kind, data


def parse_toml(text: str, file: str) -> dict[str, Any]:
    """Parse TOML text within the limits of :mod:`.toml`; a syntax error names the file, a
    value beyond a limit its key."""
    try:
        return toml.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(Text("errors.toml.invalid", {"reason": str(exc)}), file=file) from None
    except toml.TomlLimitError as exc:
        raise SceneError(exc.args[0], file=file, key=exc.key) from None


def scene_kind(data: dict[str, Any], file: str) -> str:
    """Return the ``kind`` of a parsed scene (default ``"mechanism"``)."""
    kind = data.get("kind", "mechanism")
    if kind not in SCENE_KINDS:
        raise SceneError(Text("errors.scene.kind", {"kinds": ", ".join(SCENE_KINDS),
                                                    "value": repr(kind)}), file=file, key="kind")
    return str(kind)
