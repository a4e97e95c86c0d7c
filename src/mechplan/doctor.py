"""``mechplan doctor``: what this installation finds — fonts, viewers, optional extras."""

from __future__ import annotations

import importlib.util
import os
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
    from .drafting.fonts import (
        ENV_FONT_DIRS,
        ENV_SYSTEM_FONTS,
        SheetFont,
        font_path,
        font_source,
        system_fonts_enabled,
    )

    head = (f"mechplan {__version__} (Python {platform.python_version()}, {sys.platform}, "
            f"{sys.executable})")
    choice = ("the system's fonts first (--system-fonts / " + ENV_SYSTEM_FONTS + "=1)"
              if system_fonts_enabled() else "the bundled fonts (the same on every machine; "
              "--system-fonts or " + ENV_SYSTEM_FONTS + "=1 to prefer the system's)")
    lines = [head, f"fonts: {choice}"]
    if os.environ.get(ENV_FONT_DIRS):
        lines.append(f"  {ENV_FONT_DIRS}={os.environ[ENV_FONT_DIRS]} (searched first)")
    for font in SheetFont:
        path = font_path(font)
        where = ("not found: text metrics are estimated" if path is None
                 else f"{font_source(font)} {path}")
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
