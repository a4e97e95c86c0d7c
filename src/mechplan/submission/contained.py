"""Files inside files, read in memory within one set of limits: the members of a zip (an LMS
download, an XLSX workbook) and the attachments of a PDF. A member over the size limits or
compressed more than any real drawing or table is (a bomb) is refused naming the member; nothing
is ever written by its own name."""

from __future__ import annotations

import io
import zipfile
from collections.abc import Iterator

from ..archive_limits import MAX_ENTRIES, MAX_MEMBER, MAX_RATIO, MAX_TOTAL, RATIO_FLOOR
from ..errors import CheckError
from ..i18n import Text


def mb(n: int) -> str:
    """A limit in megabytes as messages say it."""
    return f"{n // 1024**2} MB"


def refuse_member(size: int, packed: int, entry: str, file: str,
                  error: type[CheckError] = CheckError) -> None:
    """Refuse one member of ``size`` bytes unpacked from ``packed`` bytes: over
    :data:`MAX_MEMBER`, or over :data:`RATIO_FLOOR` and compressed more than :data:`MAX_RATIO`."""
    if size > MAX_MEMBER:
        raise error(Text("lms2.member_too_big", {"entry": entry, "limit": mb(MAX_MEMBER)}),
                    file=file)
    if size > RATIO_FLOOR and size > MAX_RATIO * max(packed, 1):
        raise error(Text("lms.ratio", {"entry": entry, "ratio": size // max(packed, 1),
                                       "limit": MAX_RATIO}), file=file)


def read_member(zf: zipfile.ZipFile, info: zipfile.ZipInfo, entry: str, file: str,
                error: type[CheckError] = CheckError) -> bytes:
    """One member's bytes, read no further than its declared size (a header that lies about the
    size is refused as a bomb); zipfile's own failures on a damaged or hostile member — bad CRC or
    header (BadZipFile), encryption (RuntimeError), an unknown method (NotImplementedError),
    truncation (EOFError, ValueError, OSError) — refuse it naming ``entry``."""
    try:
        with zf.open(info) as fh:
            body = fh.read(info.file_size + 1)
    except (zipfile.BadZipFile, OSError, ValueError, RuntimeError, NotImplementedError,
            EOFError) as exc:
        raise error(Text("lms.bad_member", {"entry": entry, "reason": str(exc)[:160]}),
                    file=file) from None
    if len(body) > info.file_size:
        raise error(Text("lms.ratio", {"entry": entry, "ratio": "?", "limit": MAX_RATIO}),
                    file=file)
    return body


def zip_members(data: bytes, file: str, error: type[CheckError] = CheckError
                ) -> Iterator[tuple[str, bytes]]:
    """The (name, bytes) of every file of a zip held in memory (an XLSX workbook), each checked
    against the limits before it is read, none read past its declared size."""
    try:
        zf = zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, OSError, ValueError) as exc:
        raise error(Text("lms.bad_zip", {"entry": file, "reason": str(exc)[:160]}),
                    file=file) from None
    total = 0
    with zf:
        infos = zf.infolist()
        if len(infos) > MAX_ENTRIES:
            raise error(Text("lms.too_many", {"entry": infos[MAX_ENTRIES].filename,
                                              "limit": MAX_ENTRIES}), file=file)
        for info in infos:
            if info.is_dir():
                continue
            refuse_member(info.file_size, info.compress_size, info.filename, file, error)
            total += info.file_size
            if total > MAX_TOTAL:
                raise error(Text("lms.too_big", {"entry": info.filename,
                                                 "limit": mb(MAX_TOTAL),
                                                 "member": mb(MAX_MEMBER)}), file=file)
            yield info.filename, read_member(zf, info, info.filename, file, error)
