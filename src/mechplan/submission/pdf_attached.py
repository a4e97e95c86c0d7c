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
from .contained import MAX_MEMBER, mb, refuse_member

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


def is_dxf(att: Attachment) -> bool:
    """True for an attached DXF (by its name, or by its first bytes)."""
    head = att.data[:256]
    return att.name.lower().endswith(".dxf") or bool(_DXF_HEAD.match(head)) \
        or head.startswith(b"AutoCAD Binary DXF")


def attachments(path: Path) -> list[Attachment]:
    """Every file attached to a PDF, in the order the document lists them (name tree first, then
    page annotations); refuse one over the limits."""
    data = read_bytes(path, PDF, error=CheckError)
    if not data.lstrip()[:5] == b"%PDF-":
        raise CheckError(Text("lms2.pdf_not_pdf"), file=str(path))
    from pypdf import PdfReader
    from pypdf.errors import PyPdfError

    try:
        with _decompression_limit():
            return _attachments(PdfReader(io.BytesIO(data), strict=False), path)
    except CheckError:
        raise
    # pypdf's failures on a damaged or hostile PDF (its own family — a stream inflating past the
    # limit among them — and what a malformed object raises while it is read)
    except (PyPdfError, ValueError, TypeError, KeyError, IndexError, AttributeError,
            RecursionError, OSError, EOFError, ArithmeticError) as exc:
        raise CheckError(Text("lms2.pdf_bad", {"reason": " ".join(str(exc).split())[:160]}),
                         file=str(path)) from None


def _decompression_limit() -> Any:
    """No stream inflated past one member's limit (pypdf's ``apply_configuration``, for this
    read only; an older pypdf stops at its own 75 MB and the size is refused afterwards)."""
    import contextlib

    try:
        from pypdf import apply_configuration
    except ImportError:
        return contextlib.nullcontext()
    return apply_configuration(zlib_maximum_output_length=MAX_MEMBER + 1)


def _attachments(reader: Any, path: Path) -> list[Attachment]:
    found: list[Attachment] = []
    for entry in reader.attachment_list:
        stream = entry._embedded_file        # the stream object: its declared sizes
        _refuse(entry.name, _int(entry.size), _int(stream.get("/Length")), path)
        found.append(_checked(entry.name, lambda e=entry: e.content,
                              _int(stream.get("/Length")), path))
    for k, page in enumerate(reader.pages):
        if k >= MAX_PAGES:
            break
        for annot in _annotations(page):
            got = _annotated(annot, path)
            if got is not None:
                found.append(got)
    return found


def attached_dxf(path: Path) -> tuple[Attachment, list[str]]:
    """The DXF attached to a PDF, and the names of the other attachments (not checked)."""
    found = attachments(path)
    drawings = [a for a in found if is_dxf(a)]
    if not drawings:
        names = ", ".join(a.name for a in found) or "—"
        raise CheckError(Text("lms2.pdf_no_dxf", {"attached": names}), file=str(path))
    return drawings[0], [a.name for a in found if a is not drawings[0]]


def _int(value: Any) -> int | None:
    try:
        return int(value) if value is not None else None
    except (TypeError, ValueError):
        return None


def _refuse(name: str, size: int | None, packed: int | None, path: Path) -> None:
    if size is not None:
        refuse_member(size, packed or size, name, str(path))


def _checked(name: str, read: Any, packed: int | None, path: Path) -> Attachment:
    """The attachment read by ``read()``: refused when it inflates past the limit (pypdf stops
    there) or its size and compression ratio are over the limits."""
    from pypdf.errors import LimitReachedError

    try:
        body = read()
    except LimitReachedError:
        raise CheckError(Text("lms2.member_too_big", {"entry": name, "limit": mb(MAX_MEMBER)}),
                         file=str(path)) from None
    refuse_member(len(body), packed or len(body), name, str(path))
    return Attachment(str(name), body)


def _annotations(page: Any) -> list[Any]:
    annots = page.get("/Annots")
    if annots is None:
        return []
    annots = annots.get_object()
    return [a.get_object() for a in annots] if isinstance(annots, list) else []


def _annotated(annot: Any, path: Path) -> Attachment | None:
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
    packed = _int(stream.get("/Length"))
    _refuse(name, size, packed, path)
    return _checked(name, stream.get_data, packed, path)
