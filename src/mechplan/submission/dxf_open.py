"""Open a DXF submission: its bytes as an ezdxf document (a binary DXF, a sound file, or one
ezdxf's recovery repairs), what damage ezdxf raises, and the limits on what a sheet may expand to
(INSERT bombs, blocks inside themselves) checked before anything is expanded."""

from __future__ import annotations

import io
import logging
import re
import struct
from collections.abc import Iterable
from typing import Any

from ezdxf import DXFError

from ..errors import CheckError
from ..i18n import Text
from ..limits import DXF_MAX_ENTITIES, DXF_MAX_INSERT_DEPTH

#: what ezdxf raises on damaged values besides its own DXFError family
DAMAGE = (OSError, UnicodeDecodeError, ValueError, TypeError, EOFError, IndexError,
          ArithmeticError, struct.error)      # struct.error: a truncated binary DXF


#: what ezdxf's recovery raises on some damaged files (its own asserts and half-built objects)
RECOVER_DAMAGE = (AttributeError, AssertionError, LookupError, RecursionError)
#: … and what one damaged entity may raise while it is read
ENTITY_DAMAGE = (AttributeError, AssertionError, LookupError)
_BINARY_SENTINEL = b"AutoCAD Binary DXF\r\n\x1a\x00"


#: a graphical entity of an ASCII DXF: group code 0 on its line, then the entity's name
_ENTITY_START = re.compile(
    rb"\n[ \t]*0[ \t]*\r?\n(?:LINE|LWPOLYLINE|POLYLINE|VERTEX|TEXT|MTEXT|ATTRIB|ATTDEF|INSERT|"
    rb"SOLID|TRACE|3DFACE|CIRCLE|ARC|ELLIPSE|SPLINE|POINT|DIMENSION|LEADER|HATCH|RAY|XLINE)"
    rb"[ \t]*\r?\n")


def refuse_before_loading(raw: bytes, file: str) -> None:
    """Refuse an ASCII DXF whose entities (in model space, paper space and block definitions,
    counted in its bytes) exceed :data:`~mechplan.limits.DXF_MAX_ENTITIES`, before ezdxf builds
    a document of them (a second a million; building them takes minutes and gigabytes)."""
    if raw.startswith(_BINARY_SENTINEL):
        return                  # a binary DXF is bounded by the file size limit alone
    count = 0
    for count, _ in enumerate(_ENTITY_START.finditer(raw), start=1):
        if count > DXF_MAX_ENTITIES:
            raise CheckError(Text("readers.error.dxf_entities", {"limit": DXF_MAX_ENTITIES}),
                             file=file)


def load_document(raw: bytes, repairs: Repairs | None = None) -> tuple[Any, Any]:
    """The document and its auditor from a DXF's bytes: a binary DXF as ezdxf reads it; an ASCII
    one as ezdxf reads a sound file (twice as fast on a large sheet), and when that fails through
    ezdxf's recovery, which repairs what it can (``repairs`` then keeps only its messages)."""
    from ezdxf import recover

    if raw.startswith(_BINARY_SENTINEL):
        from ezdxf.document import Drawing
        from ezdxf.lldxf.tagger import binary_tags_loader

        doc = Drawing.load(binary_tags_loader(raw, errors="surrogateescape"))
        return doc, doc.audit()
    if raw.rstrip()[-3:].upper() == b"EOF":        # a truncated file goes to the recovery
        import ezdxf
        from ezdxf.filemanagement import dxf_stream_info

        try:
            info = dxf_stream_info(io.StringIO(raw[:1 << 20].decode("utf-8", errors="ignore")))
            doc = ezdxf.read(io.StringIO(raw.decode(info.encoding, errors="surrogateescape")))
            return doc, doc.audit()
        except (DXFError, *DAMAGE, *RECOVER_DAMAGE):
            if repairs is not None:
                repairs.messages.clear()
    return recover.read(io.BytesIO(raw))


def brief(exc: BaseException, limit: int = 160) -> str:
    """An exception's message cut short: it may quote a piece of the file."""
    text = " ".join(str(exc).split())
    return text if len(text) <= limit else text[:limit] + "…"


class Repairs(logging.Handler):
    """Keep the log messages of a DXF read (repairs of damaged values)."""

    def __init__(self) -> None:
        super().__init__(logging.WARNING)
        self.messages: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.messages.append(record.getMessage())


def refuse_bombs(doc: Any, file: str) -> None:
    """Count the entities of model space with every block INSERT expanded, from the block
    definitions alone (each block counted once), and refuse a sheet over the limits before
    anything is expanded: blocks of blocks of copies, a block inside itself."""
    counts: dict[str, int] = {}

    def block(name: str, chain: tuple[str, ...]) -> int:
        if name in counts:
            return counts[name]
        if name in chain:
            raise CheckError(Text("readers.error.dxf_cycle", {"name": name[:60]}), file=file)
        if len(chain) >= DXF_MAX_INSERT_DEPTH:
            raise CheckError(Text("readers.error.dxf_depth", {"name": name[:60],
                                                              "limit": DXF_MAX_INSERT_DEPTH}),
                             file=file)
        layout = doc.blocks.get(name) if name in doc.blocks else None
        counts[name] = n = 0 if layout is None else entities(layout, (*chain, name))
        return n

    def entities(space: Iterable[Any], chain: tuple[str, ...]) -> int:
        total = 0
        for e in space:
            total += 1
            if e.dxftype() == "INSERT":
                copies = max(1, int(e.dxf.get("row_count", 1) or 1)) * max(
                    1, int(e.dxf.get("column_count", 1) or 1))
                total += copies * (block(str(e.dxf.name), chain) + len(e.attribs))
            if total > DXF_MAX_ENTITIES:
                raise CheckError(Text("readers.error.dxf_entities",
                                      {"limit": DXF_MAX_ENTITIES}), file=file)
        return total

    entities(doc.modelspace(), ())


class Budget:
    """Entities read so far, every block INSERT expanded: a sheet over
    :data:`~mechplan.limits.DXF_MAX_ENTITIES` (an INSERT bomb: blocks of blocks of copies) is
    refused as soon as the count passes it, before the rest is expanded."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.count = 0
        self.skipped: dict[tuple[str, str], bool] = {}     # see dxf._skipped

    def take(self) -> None:
        self.count += 1
        if self.count > DXF_MAX_ENTITIES:
            raise CheckError(Text("readers.error.dxf_entities", {"limit": DXF_MAX_ENTITIES}),
                             file=self.file)
