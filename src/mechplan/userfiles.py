"""The one way mechplan opens a file a user gave it: a scene, a variants file, a submission, a
data file a scene names.

Only a regular file is read — a FIFO, a device (``/dev/zero``), a socket or a folder is refused
without blocking (it is opened with ``O_NONBLOCK`` and looked at with ``fstat`` before a byte is
read) — and no more than the size limit of its kind (:mod:`mechplan.limits`). Errors name the file
and the reason, never what the file holds.
"""

from __future__ import annotations

import os
import stat
from dataclasses import dataclass
from pathlib import Path

from . import limits
from .errors import MechplanError, os_reason
from .i18n import Text


@dataclass(frozen=True, slots=True)
class FileKind:
    """What a file is to mechplan: its name in messages (``readers.kind.<id>``) and its limit."""

    id: str
    max_bytes: int

    @property
    def noun(self) -> Text:
        """The kind of file as a message says it ("the scene file")."""
        return Text(f"readers.kind.{self.id}")


SCENE = FileKind("scene", limits.SCENE_MAX_BYTES)
VARIANTS = FileKind("variants", limits.VARIANTS_MAX_BYTES)
TABLE = FileKind("table", limits.TABLE_MAX_BYTES)
DXF = FileKind("dxf", limits.DXF_MAX_BYTES)
DATA = FileKind("data", limits.DATA_MAX_BYTES)

_CHUNK = 1 << 20


def _what(mode: int) -> str:
    """The message id of what a non-regular file is."""
    if stat.S_ISDIR(mode):
        return "readers.error.folder"
    if stat.S_ISFIFO(mode):
        return "readers.error.fifo"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "readers.error.device"
    if stat.S_ISSOCK(mode):
        return "readers.error.socket"
    return "readers.error.special"


def read_bytes(path: str | os.PathLike[str], kind: FileKind, *,
               error: type[MechplanError] = MechplanError, key: str | None = None,
               shown: str | None = None) -> bytes:
    """Return the bytes of a regular file of ``kind``.

    Raise ``error`` (naming ``shown`` or the path, and ``key`` when a scene key named the file)
    when it is missing, unreadable, not a regular file, or larger than ``kind.max_bytes``.
    """
    name = shown or os.fspath(path)

    def fail(msgid: str, **args: object) -> MechplanError:
        return error(Text(msgid, {"kind": kind.noun, **args}), file=name, key=key)

    # O_NONBLOCK: opening a FIFO must not wait for a writer (POSIX); O_BINARY: no newline
    # translation (Windows); O_NOCTTY: a terminal device never becomes ours
    flags = os.O_RDONLY | sum(getattr(os, f, 0) for f in ("O_NONBLOCK", "O_NOCTTY", "O_CLOEXEC",
                                                          "O_BINARY"))
    try:
        fd = os.open(path, flags)
    except FileNotFoundError:
        raise fail("readers.error.missing") from None
    except OSError as exc:
        raise fail("readers.error.cannot_open", reason=os_reason(exc)) from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise fail(_what(info.st_mode))
        if info.st_size > kind.max_bytes:
            raise fail("readers.error.too_big", size=_size(info.st_size),
                       limit=_size(kind.max_bytes))
        chunks: list[bytes] = []
        total = 0
        while True:                # the file may grow while it is read: read at most the limit
            try:
                chunk = os.read(fd, min(_CHUNK, kind.max_bytes + 1 - total))
            except OSError as exc:
                raise fail("readers.error.cannot_read", reason=os_reason(exc)) from None
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
            if total > kind.max_bytes:
                raise fail("readers.error.too_big", size=_size(total), limit=_size(kind.max_bytes))
        return b"".join(chunks)
    finally:
        os.close(fd)


def read_text(path: str | os.PathLike[str], kind: FileKind, *,
              error: type[MechplanError] = MechplanError, key: str | None = None,
              shown: str | None = None) -> str:
    """Return a regular file of ``kind`` as UTF-8 text (a byte-order mark is dropped); see
    :func:`read_bytes`. Text that is not UTF-8 is an error naming the file, not its content."""
    data = read_bytes(path, kind, error=error, key=key, shown=shown)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise error(Text("readers.error.not_utf8", {"kind": kind.noun, "offset": exc.start}),
                    file=shown or os.fspath(path), key=key) from None


def _size(n: int) -> str:
    for unit, factor in (("GB", 1024**3), ("MB", 1024**2), ("kB", 1024)):
        if n >= factor:
            return f"{n / factor:.1f} {unit}"
    return f"{n} B"


def data_file(name: str, scene_file: str | os.PathLike[str], *, key: str,
              data_dir: str | os.PathLike[str] | None = None,
              error: type[MechplanError] = MechplanError) -> Path:
    """Resolve a data file a scene names (``key = "name"``) inside the scene's folder, or inside
    ``data_dir`` when the user named one.

    An absolute path, a path that leaves that folder (``../``, or a symbolic link pointing out of
    it) is refused with a message naming the key; whether the file exists is :func:`read_bytes`'s
    to say.
    """
    base = Path(data_dir) if data_dir is not None else Path(scene_file).parent
    scene = os.fspath(scene_file)
    if not name or "\x00" in name:
        raise error(Text("readers.error.data_name"), file=scene, key=key)
    rel = Path(name)
    if rel.is_absolute() or rel.drive or name.startswith(("/", "\\")):
        raise error(Text("readers.error.data_absolute", {"folder": str(base)}), file=scene,
                    key=key)
    root = base.resolve()
    target = (root / rel).resolve()
    if target != root and root not in target.parents:
        raise error(Text("readers.error.data_outside", {"folder": str(base)}), file=scene,
                    key=key)
    return target
