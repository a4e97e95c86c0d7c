"""A disk that fills during a write ends in one clean error and leaves nothing (issue 38)."""

from __future__ import annotations

import errno
import io
import os

import pytest

from mechplan.errors import DrawingError
from mechplan.render import atomic


class FullDisk(io.RawIOBase):
    """A file on a disk with ``room`` bytes left: then every write fails with ENOSPC."""

    def __init__(self, fd: int, room: int) -> None:
        self.fd, self.room = fd, room

    def writable(self) -> bool:
        return True

    def write(self, b) -> int:  # type: ignore[override]
        if self.room <= 0:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        n = min(len(b), self.room)
        os.write(self.fd, bytes(b[:n]))
        self.room -= n
        return n

    def fileno(self) -> int:
        return self.fd

    def close(self) -> None:
        if not self.closed:
            os.close(self.fd)
        super().close()


@pytest.mark.parametrize("room", [0, 100, 20_000])
@pytest.mark.parametrize("size", [10, 5_000, 100_000])
def test_full_disk_is_one_clean_error(room: int, size: int, tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(atomic.os, "fdopen",
                        lambda fd, mode="r": io.BufferedWriter(FullDisk(fd, room), 8192))
    target = tmp_path / "sheet.svg"
    target.write_bytes(b"old")
    if size <= room:
        atomic.write_atomic(target, b"x" * size)
        assert target.read_bytes() == b"x" * size
        return
    with pytest.raises(DrawingError, match="the disk is full") as info:
        atomic.write_atomic(target, b"x" * size)
    assert info.value.file == str(target)
    assert target.read_bytes() == b"old"                   # the old file is kept
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sheet.svg"]   # no .tmp left


def test_dev_full_through_a_writer_function(tmp_path, monkeypatch) -> None:
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full on this system")

    def fdopen(fd: int, mode: str = "r"):
        os.close(fd)
        return open("/dev/full", "wb")                   # closed by atomic_open

    monkeypatch.setattr(atomic.os, "fdopen", fdopen)
    with pytest.raises(DrawingError, match="the disk is full"):
        atomic.write_atomic(tmp_path / "a.csv", lambda fh: fh.write(b"a,b\n1,2\n"))
    assert list(tmp_path.iterdir()) == []
