"""Atomic file output: a failed render never leaves a partial file nor clobbers the old one."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import BinaryIO

from mechplan.errors import DrawingError, os_reason
from mechplan.i18n import Text


@contextlib.contextmanager
def atomic_open(path: str | os.PathLike[str]) -> Iterator[BinaryIO]:
    """Open a temporary file next to `path` for binary writing; replace `path` on success.

    The temporary file is flushed and fsynced before `os.replace`, and removed if the body raises.
    """
    target = Path(path)
    directory = target.parent if str(target.parent) else Path(".")
    if not directory.is_dir():
        raise DrawingError(Text("errors.atomic.no_folder", {"path": repr(str(directory))}),
                           file=str(path))
    if target.is_dir():
        raise DrawingError(Text("errors.atomic.is_folder", {"path": repr(str(target))}),
                           file=str(path))
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        raise DrawingError(Text("errors.atomic.cannot_write_in", {
            "path": repr(str(directory)), "reason": os_reason(exc)}), file=str(path)) from None
    try:
        fh = os.fdopen(fd, "wb")
        try:
            yield fh
            fh.flush()
            os.fsync(fh.fileno())
            fh.close()
        except OSError as exc:
            if exc.errno is None:        # not from the operating system
                raise
            raise DrawingError(Text("errors.atomic.cannot_write", {"reason": os_reason(exc)}),
                               file=str(path)) from None
        finally:
            # after a failed flush the data is still in the buffer: closing flushes it again and
            # would replace the error above with a raw OSError (the descriptor is closed anyway)
            with contextlib.suppress(OSError):
                fh.close()
        if target.exists():
            # keep the permissions of the file being replaced
            with contextlib.suppress(OSError):
                os.chmod(tmp, target.stat().st_mode & 0o7777)
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
        try:
            os.replace(tmp, target)
        except OSError as exc:
            raise DrawingError(Text("errors.atomic.cannot_replace", {"reason": os_reason(exc)}),
                               file=str(path)) from None
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise
    _fsync_dir(directory)


def _fsync_dir(directory: Path) -> None:
    # make the rename itself durable; not possible on every platform
    with contextlib.suppress(OSError, AttributeError):
        fd = os.open(directory, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def write_atomic(path: str | os.PathLike[str], data: bytes | Callable[[BinaryIO], None]) -> Path:
    """Write `data` (bytes, or a function writing to a binary stream) to `path` atomically."""
    with atomic_open(path) as fh:
        if callable(data):
            data(fh)
        else:
            fh.write(data)
    return Path(path)
