"""Output folders of batch, sweep and class checks: created or checked up front, written into
only, never through a symbolic link, and locked against a second run."""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from ..errors import MechplanError, os_reason
from .texts import say


def prepare_output(path: str | os.PathLike[str]) -> Path:
    """Create the output folder if needed; refuse a file, a folder that cannot be written."""
    out = Path(path)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise MechplanError(say("output_not_folder"), file=str(out)) from None
    except OSError as exc:
        raise MechplanError(say("output_unwritable", reason=os_reason(exc)),
                            file=str(out)) from None
    if not out.is_dir():
        raise MechplanError(say("output_not_folder"), file=str(out))
    try:                           # mkdir succeeds on a read-only folder that exists
        fd, probe = tempfile.mkstemp(prefix=".mechplan-probe-", dir=out)
    except OSError as exc:
        raise MechplanError(say("output_unwritable", reason=os_reason(exc)),
                            file=str(out)) from None
    os.close(fd)
    os.unlink(probe)
    return out


def subfolder(out: Path, name: str) -> Path:
    """Create (or find) the folder ``out/name``; refuse a symbolic link or a file there."""
    folder = out / name
    if folder.is_symlink():
        raise MechplanError(say("symlink"), file=str(folder))
    try:
        folder.mkdir(exist_ok=True)
    except FileExistsError:
        raise MechplanError(say("output_not_folder"), file=str(folder)) from None
    except OSError as exc:
        raise MechplanError(say("output_unwritable", reason=os_reason(exc)),
                            file=str(folder)) from None
    if folder.is_symlink() or not folder.is_dir():
        raise MechplanError(say("output_not_folder"), file=str(folder))
    return folder


@contextlib.contextmanager
def locked(out: Path, name: str = ".mechplan.lock") -> Iterator[None]:
    """Hold an exclusive lock on ``out`` for this run (released by the system when the process
    dies, even by SIGKILL); refuse when another run holds it."""
    try:
        import fcntl
    except ImportError:            # not on POSIX: no lock, as before
        yield
        return
    path = out / name
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0), 0o644)
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            raise MechplanError(say("symlink"), file=str(path)) from None
        raise MechplanError(say("output_unwritable", reason=os_reason(exc)),
                            file=str(out)) from None
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise MechplanError(say("busy"), file=str(out)) from None
        except OSError:             # a file system without locks (some network ones): go on
            pass
        yield
    finally:
        os.close(fd)


def remove_stale(folder: Path, prefixes: tuple[str, ...]) -> int:
    """Remove the temporary files an interrupted atomic write left in ``folder``
    (``.<prefix>….tmp``; only while holding the folder's lock). Return how many."""
    removed = 0
    for entry in folder.iterdir():
        n = entry.name
        if n.endswith(".tmp") and any(n.startswith(f".{p}") for p in prefixes):
            with contextlib.suppress(FileNotFoundError):
                entry.unlink()
                removed += 1
    return removed
