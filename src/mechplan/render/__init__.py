"""Backends that draw a `Sheet` of primitives: DXF (ezdxf), SVG (svgwrite), PDF and PNG
(matplotlib).

Every file is written atomically: a failing render leaves any existing file untouched.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable, Sequence
from pathlib import Path

from mechplan.drafting.fonts import missing_glyphs
from mechplan.drafting.primitives import Sheet, Text
from mechplan.errors import DrawingError
from mechplan.render.atomic import atomic_open, write_atomic

from ..i18n import Text as Msg

FORMATS: tuple[str, ...] = ("dxf", "svg", "pdf", "png")

log = logging.getLogger(__name__)


def warn_missing_glyphs(sheet: Sheet) -> str:
    """Log a warning naming the characters of `sheet` no font has; return them."""
    chars = missing_glyphs(p.string for p in sheet.flat() if isinstance(p, Text))
    if chars:
        from mechplan.i18n import message

        log.warning(message("fonts.missing_glyphs", sheet.language, sheet=sheet.name,
                            chars=" ".join(chars)))
    return chars


def _renderer(fmt: str, png_dpi: float) -> Callable[[Sheet], bytes]:
    if fmt == "dxf":
        from mechplan.render import dxf

        return dxf.to_bytes
    if fmt == "svg":
        from mechplan.render import svg

        return lambda s: ('<?xml version="1.0" encoding="utf-8" ?>\n' + svg.to_svg(s)).encode()
    from mechplan.render import mpl

    return lambda s: mpl.to_bytes(s, fmt, dpi=png_dpi)


def write(
    sheet: Sheet,
    path_or_dir: str | os.PathLike[str],
    formats: Sequence[str] | None = None,
    *,
    png_dpi: float = 150.0,
) -> list[Path]:
    """Write `sheet` in each of `formats`; return the written paths.

    A directory (existing, or given with a trailing separator) receives `<sheet.name>.<format>`
    files, all of `FORMATS` by default. A file path with a known suffix writes that format only by
    default; with `formats` given, each format goes to the path with its own suffix. Every sheet is
    rendered completely before the first file is replaced.
    """
    target = Path(path_or_dir)
    is_dir = target.is_dir() or str(path_or_dir).endswith((os.sep, "/"))
    suffix = target.suffix.lower().lstrip(".")
    if formats is None:
        formats = FORMATS if is_dir or suffix not in FORMATS else (suffix,)
    fmts = [str(f).lower().lstrip(".") for f in formats]
    unknown = [f for f in fmts if f not in FORMATS]
    if unknown or not fmts:
        raise DrawingError(
            Msg(
                "errmsg.render.formats_among_formats",
                {"formats": ", ".join(FORMATS), "formats2": repr(list(formats))},
            )
        )
    if is_dir:
        target.mkdir(parents=True, exist_ok=True)
        paths = [target / f"{sheet.name}.{f}" for f in fmts]
    else:
        paths = [target if suffix == f else target.with_suffix(f".{f}") for f in fmts]
    if set(fmts) - {"dxf"}:            # the formats that embed the fonts
        warn_missing_glyphs(sheet)
    data = [_renderer(f, png_dpi)(sheet) for f in fmts]
    return [write_atomic(p, d) for p, d in zip(paths, data, strict=True)]


__all__ = ["FORMATS", "atomic_open", "warn_missing_glyphs", "write", "write_atomic"]
