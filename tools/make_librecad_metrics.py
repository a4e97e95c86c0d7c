#!/usr/bin/env python
"""Build src/mechplan/fonts/librecad/metrics.json: glyph widths of the LibreCAD fonts of our styles.

LibreCAD 2.2 draws a DXF TEXT in the stroke font named like its style (render/dxf.py names the
styles kst32b, azomix, unicode), advancing each letter by its right-most stroke plus the font's
letter spacing and a space by the word spacing, at 9 font units per text height. The DXF writer
measures our texts in these fonts (render/librecad.py) without LibreCAD installed, from this file:
per font its spacings and, per character it has, the right-most x of the glyph (font units).
Only the non-CJK characters are kept (sheets write Chinese in a separate font). Run::

    python tools/make_librecad_metrics.py [/usr/share/librecad/fonts]
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

SRC = Path(sys.argv[1] if len(sys.argv) > 1 else "/usr/share/librecad/fonts")
OUT = Path(__file__).resolve().parents[1] / "src/mechplan/fonts/librecad/metrics.json"
FONTS = ("kst32b", "azomix", "unicode")
MAX_CODE = 0x2E80          # the CJK blocks start here


def read_lff(path: Path) -> tuple[dict[str, float], dict[int, list[str]]]:
    """(header numbers, glyph code → stroke lines) of a LibreCAD font."""
    header: dict[str, float] = {}
    glyphs: dict[int, list[str]] = {}
    code = None
    for line in path.read_text(encoding="utf-8").splitlines():
        m = re.match(r"^#\s*(LetterSpacing|WordSpacing):\s*([\d.]+)", line)
        if m:
            header[m.group(1)] = float(m.group(2))
            continue
        m = re.match(r"^\[([0-9a-fA-F]{4,6})\]", line)
        if m:
            code = int(m.group(1), 16)
            glyphs[code] = []
        elif code is not None and line.strip() and not line.startswith("#"):
            glyphs[code].append(line.strip())
    return header, glyphs


def right_edge(glyphs: dict[int, list[str]], code: int, depth: int = 0) -> float | None:
    """The right-most x of a glyph's strokes (references resolved), None for an empty glyph."""
    xs: list[float] = []
    for line in glyphs.get(code, []):
        if line.startswith("C") and depth < 8:
            x = right_edge(glyphs, int(line[1:], 16), depth + 1)
            if x is not None:
                xs.append(x)
            continue
        for pt in line.split(";"):
            parts = pt.split(",")
            if len(parts) >= 2:
                xs.append(float(parts[0]))
    return max(xs) if xs else None


def main() -> int:
    out = {}
    for name in FONTS:
        header, glyphs = read_lff(SRC / f"{name}.lff")
        edges = {}
        for code in sorted(glyphs):
            if code < MAX_CODE and code != 0x20:
                x = right_edge(glyphs, code)
                edges[f"{code:04x}"] = round(x, 3) if x is not None else 0.0
        out[name] = {"letter_spacing": header.get("LetterSpacing", 3.0),
                     "word_spacing": header.get("WordSpacing", 6.75), "right_edge": edges}
    OUT.write_text(json.dumps(out, separators=(",", ":"), sort_keys=True) + "\n", encoding="utf-8")
    counts = ", ".join(f"{k} {len(v['right_edge'])}" for k, v in out.items())
    print(f"{OUT}: {counts} glyphs, {OUT.stat().st_size / 1e3:.0f} kB")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
