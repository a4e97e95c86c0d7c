"""Output folders: create them or say, in one sentence, why they cannot be written."""

from __future__ import annotations

import os
from pathlib import Path

from .errors import DrawingError, os_reason
from .i18n import Text


def prepare_dir(path: str | os.PathLike[str]) -> Path:
    """Create the output folder ``path`` if needed and make sure files can be written in it."""
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise DrawingError(Text("errors.output.is_file", {"path": repr(str(out))}),
                           file=str(out))
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise DrawingError(Text("errors.output.cannot_create", {"reason": os_reason(exc)}),
                           file=str(out)) from None
    if not os.access(out, os.W_OK | os.X_OK):
        raise DrawingError(Text("errors.output.not_writable"), file=str(out))
    return out
