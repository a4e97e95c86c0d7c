"""Text as LibreCAD 2.2 draws it: which of its stroke fonts has a string's glyphs, how wide it is.

LibreCAD ignores a DXF text style's font file and draws the stroke font (.lff) named like the style.
Each letter advances by its right-most stroke plus the font's letter spacing, a space by the word
spacing, at 9 font units per text height; a letter the font lacks is drawn as ◊. The widths come
from ``fonts/librecad/metrics.json`` (tools/make_librecad_metrics.py, from LibreCAD's kst32b,
azomix and unicode fonts) and from the font mechplan ships (``fonts/librecad/mechplan-vi.lff``).
"""

from __future__ import annotations

import functools
import json
import re
from dataclasses import dataclass

from mechplan.drafting.fonts import BUNDLED_DIR

FOLDER = BUNDLED_DIR / "librecad"
#: LibreCAD's units: a letter's capital height
CAP_UNITS = 9.0


@dataclass(frozen=True, slots=True)
class StrokeFont:
    """A LibreCAD font's spacing and the right edge of each glyph it has (font units)."""

    name: str
    letter_spacing: float
    word_spacing: float
    right_edge: dict[int, float]

    def has(self, text: str) -> bool:
        """Return True if the font has every non-space character of `text`."""
        return all(ord(c) in self.right_edge for c in text if c != " ")

    def width_mm(self, text: str, height_mm: float, width_factor: float = 1.0) -> float:
        """Return the width LibreCAD draws `text` with at `height_mm` (first to last stroke)."""
        units = 0.0
        last_gap = 0.0
        for c in text:
            if c == " ":
                units += self.word_spacing
                last_gap = 0.0
                continue
            # a missing letter is drawn as a ◊ about as wide as a capital
            edge = self.right_edge.get(ord(c), 6.0)
            units += max(edge, 0.0) + self.letter_spacing
            last_gap = self.letter_spacing
        return max(units - last_gap, 0.0) * height_mm / CAP_UNITS * width_factor


def _read_lff(name: str) -> StrokeFont:
    spacing = {"LetterSpacing": 3.0, "WordSpacing": 6.75}
    glyphs: dict[int, list[str]] = {}
    code = None
    for line in (FOLDER / f"{name}.lff").read_text(encoding="utf-8").splitlines():
        m = re.match(r"^#\s*(LetterSpacing|WordSpacing):\s*([\d.]+)", line)
        if m:
            spacing[m.group(1)] = float(m.group(2))
        elif m := re.match(r"^\[([0-9a-fA-F]{4,6})\]", line):
            code = int(m.group(1), 16)
            glyphs[code] = []
        elif code is not None and line.strip() and not line.startswith("#"):
            glyphs[code].append(line.strip())

    def edge(c: int, depth: int = 0) -> float:
        xs = [0.0]
        for line in glyphs.get(c, []):
            if line.startswith("C"):
                if depth < 8:
                    xs.append(edge(int(line[1:], 16), depth + 1))
                continue
            xs += [float(p.split(",")[0]) for p in line.split(";") if "," in p]
        return max(xs)

    return StrokeFont(name, spacing["LetterSpacing"], spacing["WordSpacing"],
                      {c: edge(c) for c in glyphs if c != 0x20})


@functools.cache
def stroke_fonts() -> dict[str, StrokeFont]:
    """Return the LibreCAD fonts the DXF styles are named after, by name."""
    data = json.loads((FOLDER / "metrics.json").read_text(encoding="utf-8"))
    fonts = {name: StrokeFont(name, d["letter_spacing"], d["word_spacing"],
                              {int(k, 16): v for k, v in d["right_edge"].items()})
             for name, d in data.items()}
    fonts["mechplan-vi"] = _read_lff("mechplan-vi")
    return fonts
