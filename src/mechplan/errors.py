"""The one exception family users can cause; every message names where and why."""

from __future__ import annotations

import errno
import reprlib

_OS_REASONS = {errno.EACCES: "permission", errno.EPERM: "permission",
               errno.EROFS: "read_only", errno.ENOSPC: "disk_full", errno.EDQUOT: "quota",
               errno.ENOTDIR: "part_is_file", errno.EEXIST: "exists", errno.EISDIR: "is_folder",
               errno.ENAMETOOLONG: "name_too_long"}


def os_reason(exc: OSError) -> str:
    """Return a short reason for an operating-system error (for a user message): a catalogue
    text said in the message's language where the reason is a known one."""
    name = _OS_REASONS.get(exc.errno or 0)
    if name is None:
        return exc.strerror or exc.__class__.__name__
    from .i18n import Text

    return Text(f"errors.os.{name}")


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
    """Base of every error a user can cause (bad scene, impossible geometry, unreadable file).

    The reason (``detail``) is a catalogue message (:class:`mechplan.i18n.Text`: its English
    sentence, its message id and arguments) wherever the raise site says one: :meth:`text` says
    the whole error in another language and :attr:`code` is its stable id for programs.
    """

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

    @property
    def code(self) -> str:
        """A stable machine-readable code: the message id of the reason (``scene.unknown_key``),
        or the error's class name where the reason is not from the catalogues yet."""
        key = getattr(self.detail, "key", None)
        return key if isinstance(key, str) else type(self).__name__

    def text(self, language: str = "en") -> str:
        """The whole message (file, key and reason) in a language: en, ru, vi or zh."""
        from .i18n import LANGUAGES, Text, message

        language = language if language in LANGUAGES else "en"
        where = []
        if self.file:
            where.append(elide(str(self.file), MAX_KEY_CHARS))
        if self.key:
            where.append(message("errors.where.key", language, key=shown_key(self.key)))
        detail = self.detail
        said = elide(detail.tr(language) if isinstance(detail, Text) else str(detail),
                     MAX_MESSAGE_CHARS)
        return ": ".join([*where, said])

    def to_json(self, language: str = "en") -> dict[str, object]:
        """The error as a JSON object: its code, message (in ``language``), file and key."""
        return {"error": {"code": self.code, "kind": type(self).__name__,
                          "message": self.text(language), "file": self.file, "key": self.key}}


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
