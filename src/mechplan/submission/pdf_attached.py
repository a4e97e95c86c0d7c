"""Drawings handed in as a PDF with the DXF attached: the PDF's embedded files (the document's
``/EmbeddedFiles`` name tree, as "Attach file" writes it, and ``/FileAttachment`` annotations, as
the paper-clip comment writes it) read in memory, each within the limits of every file read inside
another (:mod:`.contained`). The PDF's own drawing is not read: only the attached DXF is checked."""

from __future__ import annotations

import io
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import CheckError
from ..i18n import Text
from ..limits import DXF_MAX_BYTES
from ..userfiles import FileKind, read_bytes
from .contained import MAX_ENTRIES, MAX_MEMBER, MAX_TOTAL, mb, refuse_member

#: a PDF may hold a drawing as large as a DXF may be
PDF = FileKind("dxf", DXF_MAX_BYTES)
#: pages whose annotations are looked at for attachments
MAX_PAGES = 500
_DXF_HEAD = re.compile(rb"\s*0\s*\r?\n\s*SECTION")


@dataclass(frozen=True, slots=True)
class Attachment:
    """One file attached to a PDF: its name and bytes."""

    name: str
    data: bytes


@dataclass(frozen=True, slots=True)
class _Listed:
    """An attachment found, not yet read: its name, its sizes as declared, how to read it."""

    name: str
    read: Any
    packed: int | None
    size: int | None


def is_dxf(att: Attachment) -> bool:
    """True for an attached DXF (by its name, or by its first bytes)."""
    head = att.data[:256]
    return att.name.lower().endswith(".dxf") or bool(_DXF_HEAD.match(head)) \
        or head.startswith(b"AutoCAD Binary DXF")


def attached_dxf(path: Path) -> tuple[Attachment, list[str]]:
    """The DXF attached to a PDF, and the names of the other attachments (not checked).

    Only what is needed is inflated: the first attachment named ``.dxf``; when none is, the
    others one by one until one starts as a DXF — each within one member's limit, all together
    within an archive's."""
    data = read_bytes(path, PDF, error=CheckError)
    if not data.lstrip()[:5] == b"%PDF-":
        raise CheckError(Text("lms2.pdf_not_pdf"), file=str(path))
    from pypdf import PdfReader
    from pypdf.errors import PyPdfError

    try:
        with _decompression_limit():
            listed = _listed(PdfReader(io.BytesIO(data), strict=False))
            named = [a for a in listed if a.name.lower().endswith(".dxf")]
            total = 0
            for entry in named[:1] or listed:
                got = _checked(entry, path)
                total += len(got.data)
                if total > MAX_TOTAL:
                    raise CheckError(Text("lms.too_big", {"entry": entry.name,
                                                          "limit": mb(MAX_TOTAL),
                                                          "member": mb(MAX_MEMBER)}),
                                     file=str(path))
                if is_dxf(got):
                    return got, [a.name for a in listed if a is not entry]
    except CheckError:
        raise
    # pypdf's failures on a damaged or hostile PDF (its own family — a stream inflating past the
    # limit among them — and what a malformed object raises while it is read)
    except (PyPdfError, ValueError, TypeError, KeyError, IndexError, AttributeError,
            RecursionError, OSError, EOFError, ArithmeticError) as exc:
        raise CheckError(Text("lms2.pdf_bad", {"reason": " ".join(str(exc).split())[:160]}),
                         file=str(path)) from None
    names = ", ".join(a.name for a in listed) or "—"
    raise CheckError(Text("lms2.pdf_no_dxf", {"attached": names}), file=str(path))


def _decompression_limit() -> Any:
    """No stream inflated past one member's limit (pypdf's ``apply_configuration``, for this
    read only; an older pypdf stops at its own 75 MB and the size is refused afterwards)."""
    import contextlib

    try:
        from pypdf import apply_configuration
    except ImportError:
        return contextlib.nullcontext()
    return apply_configuration(zlib_maximum_output_length=MAX_MEMBER + 1)


def _listed(reader: Any) -> list[_Listed]:
    """The attachments of a PDF in the order it lists them (name tree, then page annotations),
    at most :data:`MAX_ENTRIES`; nothing inflated yet."""
    found: list[_Listed] = []
    for entry in reader.attachment_list:
        stream = entry._embedded_file        # the stream object: its declared sizes
        found.append(_Listed(str(entry.name), lambda e=entry: e.content,
                             _int(stream.get("/Length")), _int(entry.size)))
        if len(found) >= MAX_ENTRIES:
            return found
    for k, page in enumerate(reader.pages):
        if k >= MAX_PAGES:
            break
        for annot in _annotations(page):
            got = _annotated(annot)
            if got is not None:
                found.append(got)
                if len(found) >= MAX_ENTRIES:
                    return found
    return found


def _int(value: Any) -> int | None:
    try:
        return int(value) if value is not None else None
    except (TypeError, ValueError):
        return None


def _checked(entry: _Listed, path: Path) -> Attachment:
    """The attachment's bytes: refused when its declared size is over the limit, when it
    inflates past the limit (pypdf stops there), or its size and ratio are over the limits."""
    from pypdf.errors import LimitReachedError

    if entry.size is not None:
        refuse_member(entry.size, entry.packed or entry.size, entry.name, str(path))
    try:
        body = entry.read()
    except LimitReachedError:
        raise CheckError(Text("lms2.member_too_big", {"entry": entry.name,
                                                      "limit": mb(MAX_MEMBER)}),
                         file=str(path)) from None
    refuse_member(len(body), entry.packed or len(body), entry.name, str(path))
    return Attachment(entry.name, body)


def _annotations(page: Any) -> list[Any]:
    annots = page.get("/Annots")
    if annots is None:
        return []
    annots = annots.get_object()
    return [a.get_object() for a in annots] if isinstance(annots, list) else []


def _annotated(annot: Any) -> _Listed | None:
    """The file of a ``/FileAttachment`` annotation (its file specification's ``/EF /F``)."""
    if not hasattr(annot, "get") or annot.get("/Subtype") != "/FileAttachment":
        return None
    spec = annot.get("/FS")
    spec = spec.get_object() if spec is not None else None
    if spec is None or not hasattr(spec, "get"):
        return None
    ef = spec.get("/EF")
    ef = ef.get_object() if ef is not None else None
    stream = (ef.get("/F") or ef.get("/UF")) if ef is not None and hasattr(ef, "get") else None
    if stream is None:
        return None
    stream = stream.get_object()
    name = str(spec.get("/UF") or spec.get("/F") or "attachment")
    params = stream.get("/Params")
    size = _int(params.get_object().get("/Size")) if params is not None else None
    return _Listed(name, stream.get_data, _int(stream.get("/Length")), size)
