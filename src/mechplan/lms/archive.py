"""Submission archives read safely: every member read into memory within limits, never extracted
by its own name. A name that climbs out (``../``, an absolute or drive path), a zip bomb (too many
entries, too much uncompressed data, a compression ratio no real drawing has, zips nested too
deep) refuses the archive with a message naming the entry."""

from __future__ import annotations

import io
import os
import re
import stat
import unicodedata
import zipfile
from dataclasses import dataclass
from pathlib import Path

# one set of limits for every file read inside another (zips, workbooks, PDF attachments)
from ..archive_limits import MAX_ENTRIES, MAX_MEMBER, MAX_RATIO, MAX_TOTAL, RATIO_FLOOR
from ..errors import CheckError
from .texts import say

__all__ = ["MAX_DEPTH", "MAX_ENTRIES", "MAX_MEMBER", "MAX_RATIO", "MAX_TOTAL", "RATIO_FLOOR",
           "ArchiveError", "Member", "read_download", "read_folder", "read_zip", "safe_name"]

#: deepest nesting of zips in zips (the download itself is depth 0)
MAX_DEPTH = 3


class ArchiveError(CheckError):
    """An archive mechplan refuses to read."""


@dataclass(frozen=True, slots=True)
class Member:
    """One file of a submissions download: its path inside (``/``-separated parts) and bytes."""

    parts: tuple[str, ...]
    data: bytes

    @property
    def name(self) -> str:
        """The file's own name."""
        return self.parts[-1]


@dataclass
class _Budget:
    entries: int = 0
    total: int = 0


def clean_parts(name: str, archive: str) -> tuple[str, ...]:
    """The parts of a member's name; refuse one that is absolute, has a drive, ``..`` or NUL."""
    text = name.replace("\\", "/")
    if (text.startswith("/") or re.match(r"^[A-Za-z]:", text) or "\0" in text
            or any(p == ".." for p in text.split("/"))):
        raise ArchiveError(say("unsafe_name", entry=repr(name)), file=archive)
    return tuple(unicodedata.normalize("NFC", p) for p in text.split("/") if p not in ("", "."))


def read_zip(data: bytes, archive: str, depth: int = 0,
             budget: _Budget | None = None, prefix: tuple[str, ...] = ()) -> list[Member]:
    """Every file of a zip (zips inside expanded in place, to ``MAX_DEPTH``)."""
    budget = budget or _Budget()
    if depth > MAX_DEPTH:
        raise ArchiveError(say("too_deep", entry="/".join(prefix), limit=MAX_DEPTH), file=archive)
    try:
        zf = zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, OSError, ValueError) as exc:
        raise ArchiveError(say("bad_zip", entry="/".join(prefix) or archive, reason=str(exc)[:160]),
                           file=archive) from None
    out: list[Member] = []
    with zf:
        infos = zf.infolist()
        for info in infos:
            budget.entries += 1
            entry = "/".join((*prefix, info.filename))
            if budget.entries > MAX_ENTRIES:
                raise ArchiveError(say("too_many", entry=entry, limit=MAX_ENTRIES), file=archive)
            parts = clean_parts(_decoded(info), archive)
            if info.is_dir() or not parts or stat.S_ISLNK(info.external_attr >> 16):
                continue
            _refuse_size(info.file_size, info.compress_size, entry, budget, archive)
            from ..submission.contained import read_member  # the package loads the readers
            body = read_member(zf, info, entry, archive, ArchiveError)
            budget.total += len(body) - info.file_size   # the real size, not the header's
            full = (*prefix, *parts)
            if parts[-1].lower().endswith(".zip"):
                out += read_zip(body, archive, depth + 1, budget, full[:-1] + (_stem(parts[-1]),))
            else:
                out.append(Member(full, body))
    return out


def _decoded(info: zipfile.ZipInfo) -> str:
    """The member's name: zips written without the UTF-8 flag (Info-ZIP, PHP's ZipArchive, which
    Moodle uses) mostly hold UTF-8 all the same, read by Python as cp437."""
    if info.flag_bits & 0x800:
        return info.filename
    try:
        return info.filename.encode("cp437").decode("utf-8")
    except (UnicodeEncodeError, UnicodeDecodeError):
        return info.filename


def _stem(name: str) -> str:
    return name[:-4] if name.lower().endswith(".zip") else name


def _refuse_size(size: int, packed: int, entry: str, budget: _Budget, archive: str) -> None:
    if size > MAX_MEMBER or budget.total + size > MAX_TOTAL:
        raise ArchiveError(say("too_big", entry=entry, limit=f"{MAX_TOTAL // 1024**2} MB",
                               member=f"{MAX_MEMBER // 1024**2} MB"), file=archive)
    if size > RATIO_FLOOR and size > MAX_RATIO * max(packed, 1):
        raise ArchiveError(say("ratio", entry=entry, ratio=size // max(packed, 1),
                               limit=MAX_RATIO), file=archive)
    budget.total += size


def read_folder(folder: Path, skip: Path | None = None) -> list[Member]:
    """Every regular file under a folder (links are not followed; zips inside expanded; the
    folder ``skip`` — the output, when it is inside — left out)."""
    budget = _Budget()
    out: list[Member] = []
    root = str(folder)
    skipped = skip.resolve() if skip is not None else None
    for here, dirs, files in os.walk(folder, followlinks=False):
        dirs[:] = sorted(d for d in dirs if (Path(here) / d).resolve() != skipped)
        rel = Path(here).relative_to(folder).parts
        for name in sorted(files):
            path = Path(here) / name
            budget.entries += 1
            entry = "/".join((*rel, name))
            if budget.entries > MAX_ENTRIES:
                raise ArchiveError(say("too_many", entry=entry, limit=MAX_ENTRIES), file=root)
            st = path.lstat()
            if not stat.S_ISREG(st.st_mode):
                out.append(Member((*rel, name), b""))   # listed as unreadable, never followed
                continue
            _refuse_size(st.st_size, st.st_size, entry, budget, root)
            data = path.read_bytes()
            if name.lower().endswith(".zip"):
                out += read_zip(data, root, 1, budget, (*rel, _stem(name)))
            else:
                out.append(Member(tuple(unicodedata.normalize("NFC", p) for p in (*rel, name)),
                                  data))
    return out


def read_download(path: Path, out: Path | None = None) -> list[Member]:
    """The files of a submissions download: a zip, or a folder it was unpacked into (without
    the output folder ``out`` if it is inside)."""
    if path.is_dir():
        return read_folder(path, out)
    from ..userfiles import FileKind, read_bytes

    data = read_bytes(path, FileKind("lms_archive", MAX_TOTAL), error=ArchiveError)
    return read_zip(data, str(path))


def safe_name(text: str, limit: int = 80) -> str:
    """A file or folder name made of the text's letters and digits (any script), ``_ - .``
    elsewhere ``_``; never empty, never ``.``/``..``, at most ``limit`` characters."""
    out = "".join(c if (c.isalnum() or c in "-_. ") else "_" for c in text).strip(" .")
    return (out or "_")[:limit]
