"""``mechplan doctor``: what this installation finds — fonts, viewers, optional extras."""

from __future__ import annotations

import importlib.util
import platform
import shutil
import sys

from . import __version__

#: optional packages and what they add
EXTRAS = (("pdfplumber", "test: reading PDF sheets"), ("hypothesis", "test: fuzzing scenes"),
          ("mpmath", "test, bench: 40-digit references"), ("scipy", "bench"),
          ("numba", "bench: pylinkage compiled"), ("pylinkage", "bench: peer package"),
          ("mechanism", "bench: peer package"), ("fontTools", "sheets: font metrics"))
#: external programs the user may open the sheets with
VIEWERS = (("librecad", "DXF viewer (LibreCAD)"), ("chromium", "SVG/PDF viewer (Chromium)"),
           ("chromium-browser", "SVG/PDF viewer (Chromium)"), ("pdftoppm", "poppler tools"))


def report() -> str:
    """Return the report as text, one finding a line."""
    from .drafting.fonts import BUNDLED_DIR, SheetFont, font_path

    head = (f"mechplan {__version__} (Python {platform.python_version()}, {sys.platform}, "
            f"{sys.executable})")
    lines = [head, "fonts:"]
    for font in SheetFont:
        path = font_path(font)
        where = "not found: text metrics are estimated" if path is None else (
            f"bundled {path}" if path.parent == BUNDLED_DIR else f"system {path}")
        lines.append(f"  {font.family}: {where}")
    lines.append("viewers:")
    seen = set()
    for program, what in VIEWERS:
        found = shutil.which(program)
        if what in seen and not found:
            continue
        if found:
            seen.add(what)
        lines.append(f"  {program}: {found or 'not found'} ({what})")
    lines.append("optional packages:")
    for name, what in EXTRAS:
        present = importlib.util.find_spec(name) is not None
        lines.append(f"  {name}: {'found' if present else 'not installed'} ({what})")
    return "\n".join(lines)
