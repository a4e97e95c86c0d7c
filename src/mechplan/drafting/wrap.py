"""Word wrap with the sheet fonts' real metrics: a text split into lines no wider than a measure.

Lines break at spaces, never inside "φ = 30°" (not before "=", "%", "°", "±", ")" …, not after
"=", "±", "→", "(" or after a bare number, so a value keeps its unit), and between any two CJK
characters (Chinese has no spaces) except before closing punctuation (，。：；）、…). A word
longer than the measure stays whole on a line of its own.
"""

from __future__ import annotations

import re

from .fonts import SheetFont, _is_cjk, text_width_mm

#: no line starts with these (closing punctuation, units and operators glued to what precedes)
_NO_START = set("=%°±·→)]}’”′″:;,.!?/×−–，。：；）】」』、！？…")
#: no line ends with these (operators and opening brackets glued to what follows)
_NO_END = ("=", "±", "→", "(", "[", "{", "·", "×", "/", "（", "【", "「", "『")
_NUMBER = re.compile(r"^[−\-+]?\d[\d.,]*$")


def _tokens(text: str) -> list[tuple[str, bool]]:
    """(token, preceded by a space) of ``text``: its words, with every CJK character a token of
    its own (closing punctuation stays with the character before it)."""
    out: list[tuple[str, bool]] = []
    for word in text.split():
        spaced = bool(out)
        run = ""
        for ch in word:
            if run and ch not in _NO_START and (_is_cjk(ord(ch)) or _is_cjk(ord(run[-1]))):
                out.append((run, spaced))
                run, spaced = "", False
            run += ch
        out.append((run, spaced))
    return out


def _may_break(prev: str, nxt: str) -> bool:
    """Whether a line may end after token ``prev`` and the next start with ``nxt``."""
    if nxt[0] in _NO_START or prev.endswith(_NO_END):
        return False
    return not _NUMBER.match(prev)


def wrap(text: str, height_mm: float, width_mm: float,
         font: SheetFont | None = None) -> list[str]:
    """Lines of ``text`` at capital height ``height_mm``, each at most ``width_mm`` wide when it
    can be (a single unbreakable word may be wider); measured in ``font`` (default: the font
    each line needs)."""
    if not text.strip():
        return []
    if text_width_mm(text, height_mm, font) <= width_mm:
        return [text]                      # as it is, spacing included
    tokens = _tokens(text)
    # glue tokens that must not be separated into units
    units: list[tuple[str, bool]] = []
    last = ""
    for tok, spaced in tokens:
        if units and not _may_break(last, tok):
            prev, prev_spaced = units[-1]
            units[-1] = (prev + (" " if spaced else "") + tok, prev_spaced)
        else:
            units.append((tok, spaced))
        last = tok
    lines: list[str] = []
    line = ""
    for unit, spaced in units:
        candidate = line + (" " if spaced and line else "") + unit
        if line and text_width_mm(candidate, height_mm, font) > width_mm:
            lines.append(line)
            line = unit
        else:
            line = candidate
    if line:
        lines.append(line)
    return lines
