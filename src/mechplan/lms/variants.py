"""The variants a class is checked against: one scene, a folder of scenes (``v07.toml``), or the
output folder of ``mechplan batch`` (``<id>/scene.toml`` with its ``answer_key.json``)."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..check.texts import T
from ..errors import CheckError


@dataclass(frozen=True)
class VariantFile:
    """One variant: its id, its scene and (from a batch class) its answer key."""

    id: str
    scene: Path
    key: Path | None = None

    def answer_key(self) -> dict[str, Any] | None:
        """The variant's answer key document, when the class has one."""
        if self.key is None or not self.key.is_file():
            return None
        with self.key.open(encoding="utf-8") as fh:
            doc: dict[str, Any] = json.load(fh)
        return doc


def load_variants(path: Path) -> dict[str, VariantFile]:
    """The variants by id."""
    if path.is_file():
        return {path.stem: VariantFile(path.stem, path)}
    found = {d.name: VariantFile(d.name, d / "scene.toml", d / "answer_key.json")
             for d in sorted(path.iterdir()) if d.is_dir() and not d.is_symlink()
             and (d / "scene.toml").is_file()}
    found |= {s.stem: VariantFile(s.stem, s) for s in sorted(path.glob("*.toml"))
              if s.stem not in found}
    if not found:
        raise CheckError(T("error.no_variants"), file=str(path))
    return found


def variant_in(text: str, variants: dict[str, VariantFile]) -> str | None:
    """The variant whose id is a word of ``text`` (the longest wins)."""
    named = [v for v in variants if re.search(rf"(?:^|[\W_]){re.escape(v)}(?:$|[\W_])", text,
                                              re.IGNORECASE)]
    return max(named, key=len) if named else None
