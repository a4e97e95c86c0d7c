"""Output folders: create them or say, in one sentence, why they cannot be written."""

from __future__ import annotations

import os
from pathlib import Path

from .errors import DrawingError, os_reason


def prepare_dir(path: str | os.PathLike[str]) -> Path:
    """Create the output folder ``path`` if needed and make sure files can be written in it."""
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise DrawingError("the output folder must be a folder, not a file (got "
                           f"{str(out)!r}); choose another -o", file=str(out))
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise DrawingError(f"the output folder cannot be created ({os_reason(exc)}); "
                           "choose another -o", file=str(out)) from None
    if not os.access(out, os.W_OK | os.X_OK):
        raise DrawingError("the output folder must be writable (permission denied or read-only); "
                           "choose another -o", file=str(out))
    return out
