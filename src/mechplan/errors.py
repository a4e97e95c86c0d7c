"""The one exception family users can cause; every message names where and why."""

from __future__ import annotations

import errno
import reprlib

_OS_REASONS = {errno.EACCES: "permission denied", errno.EPERM: "permission denied",
               errno.EROFS: "the file system is read-only", errno.ENOSPC: "the disk is full",
               errno.EDQUOT: "the disk quota is exceeded", errno.ENOTDIR: "a part of it is a file",
               errno.EEXIST: "a file of that name exists", errno.EISDIR: "it is a folder",
               errno.ENAMETOOLONG: "the name is too long"}


def os_reason(exc: OSError) -> str:
    """Return a short reason for an operating-system error (for a user message)."""
    return _OS_REASONS.get(exc.errno or 0, exc.strerror or exc.__class__.__name__)


#: characters of a message, of a key path and of a file name said in an error; the middle of a
#: longer one is left out (a 5 MB title is never echoed whole)
MAX_MESSAGE_CHARS = 2000
MAX_KEY_CHARS = 200
_REPR = reprlib.Repr()
_REPR.maxstring = _REPR.maxother = 80
_REPR.maxlist = _REPR.maxtuple = _REPR.maxdict = _REPR.maxset = 6
_REPR.maxlevel = 3


def shown(value: object) -> str:
    """Return ``repr(value)`` short enough for a message: long texts and lists are elided, deep
    ones cut (never builds the whole repr of a huge value)."""
    try:
        return _REPR.repr(value)
    except ValueError:          # an int of more than 4300 digits has no repr
        return "<a number of thousands of digits>"


def elide(text: str, limit: int) -> str:
    """Return ``text``, or its beginning and end around "…" when longer than ``limit``."""
    if len(text) <= limit:
        return text
    keep = (limit - 30) // 2
    return f"{text[:keep]}… ({len(text) - 2 * keep:,} characters left out) …{text[-keep:]}"


def shown_key(key: str) -> str:
    """Return a key path short enough for a message."""
    return elide(key, MAX_KEY_CHARS)


class MechplanError(Exception):
    """Base of every error a user can cause (bad scene, impossible geometry, unreadable file)."""

    def __init__(self, message: str, *, file: str | None = None, key: str | None = None) -> None:
        if type(message) is str:        # a catalogue text (a str subclass) keeps its arguments
            message = elide(message, MAX_MESSAGE_CHARS)
        self.file = file
        self.key = key
        self.detail = message
        where = []
        if file:
            where.append(elide(str(file), MAX_KEY_CHARS))
        if key:
            where.append(f"key '{shown_key(key)}'")
        prefix = ": ".join(where)
        said = elide(str(message), MAX_MESSAGE_CHARS)
        super().__init__(f"{prefix}: {said}" if prefix else said)


class SceneError(MechplanError):
    """The scene file is malformed, incomplete or inconsistent."""


class TopologyError(SceneError):
    """The mechanism's structure cannot be analysed (W ≠ drives, unsupported group class)."""


class UnreachableError(MechplanError):
    """A group cannot be assembled at some crank positions."""

    def __init__(
        self,
        message: str,
        *,
        group: str | None = None,
        intervals_deg: list[tuple[float, float]] | None = None,
        gap: float | None = None,
        file: str | None = None,
    ) -> None:
        self.group = group
        self.intervals_deg = intervals_deg or []
        self.gap = gap
        super().__init__(message, file=file)


class SingularError(MechplanError):
    """A construction meets nearly parallel lines (toggle, change point): the result is refused."""

    def __init__(
        self,
        message: str,
        *,
        step: str | None = None,
        phi_deg: float | None = None,
        condition: float | None = None,
        file: str | None = None,
    ) -> None:
        self.step = step
        self.phi_deg = phi_deg
        self.condition = condition
        super().__init__(message, file=file)


class DrawingError(MechplanError):
    """A sheet cannot be laid out or written."""


class CheckError(MechplanError):
    """A submission (hand-drawn DXF or table of values) cannot be read or matched."""
