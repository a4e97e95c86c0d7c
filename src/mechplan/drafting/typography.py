"""Sub- and superscripts written in a label ("a^n_CB", "v_B", "ω^2") for every backend.

A ``^`` raises and a ``_`` lowers the run of letters, digits and primes that follows it; the
renderers draw the runs at 70 % size above or below the baseline: DXF as MTEXT stacks
(``a\\Sn^CB;``), SVG as shifted ``tspan``s, PDF/PNG as separately placed strings.
"""

from __future__ import annotations

import re

SCRIPT_SIZE = 0.7      # of the text height
SUP_SHIFT = 0.45       # raise of a superscript, of the text height
SUB_SHIFT = -0.25      # drop of a subscript

_SCRIPT = re.compile(r"([\^_])([0-9A-Za-zА-Яа-яЁё′″'*]+)")


def has_scripts(text: str) -> bool:
    """Whether a label holds sub- or superscript marks."""
    return bool(_SCRIPT.search(text))


def runs(text: str) -> list[tuple[str, int]]:
    """The label as (text, shift) runs: shift +1 superscript, −1 subscript, 0 on the baseline."""
    out: list[tuple[str, int]] = []
    pos = 0
    for m in _SCRIPT.finditer(text):
        if m.start() > pos:
            out.append((text[pos:m.start()], 0))
        out.append((m.group(2), 1 if m.group(1) == "^" else -1))
        pos = m.end()
    if pos < len(text):
        out.append((text[pos:], 0))
    return out


#: Unicode super- and subscript characters (the ×10ⁿ exponents of the number writers, M_b⁰, S₄)
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻", "0123456789+-")
_SUBSCRIPTS = str.maketrans("₀₁₂₃₄₅₆₇₈₉₊₋", "0123456789+-")
_UNICODE_SCRIPT = re.compile("([⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻]+)|([₀₁₂₃₄₅₆₇₈₉₊₋]+)")


#: the Latin-1 superscripts every sheet font has (LibreCAD's too): "m/s²" keeps its glyph
_LATIN1 = frozenset("¹²³")


def _shifted(m: re.Match[str]) -> bool:
    """Whether a run of script characters must be drawn as a shifted run (not only ¹²³)."""
    return not set(m.group(0)) <= _LATIN1


def has_unicode_scripts(text: str) -> bool:
    """Whether a label holds Unicode super- or subscript characters a stroke font lacks
    ("1,1×10⁻¹⁶"; not the "²" of "m/s²")."""
    return any(_shifted(m) for m in _UNICODE_SCRIPT.finditer(text))


def glyph_runs(text: str) -> list[tuple[str, int]]:
    """:func:`runs`, with the Unicode super- and subscript characters also as shifted runs of
    ordinary ones ("1,1×10⁻¹⁶" → "1,1×10" then "-16" raised): for a backend whose fonts lack
    those glyphs (LibreCAD's stroke fonts, DXF)."""
    out: list[tuple[str, int]] = []
    pos = 0
    for m in _UNICODE_SCRIPT.finditer(text):
        if not _shifted(m):
            continue
        out.extend(runs(text[pos:m.start()]))
        if m.group(1):
            out.append((m.group(1).translate(_SUPERSCRIPTS), 1))
        else:
            out.append((m.group(2).translate(_SUBSCRIPTS), -1))
        pos = m.end()
    out.extend(runs(text[pos:]))
    return out


def plain(text: str) -> str:
    """The label without its marks ("a^n_CB" → "anCB")."""
    return "".join(t for t, _ in runs(text))


def _escape(text: str) -> str:
    return text.replace("\\", "\\\\").replace("{", "\\{").replace("}", "\\}").replace("^", "^ ")


def mtext(text: str) -> str:
    """MTEXT content with stacks: a superscript followed by a subscript is one stack (n over CB,
    ``a\\Sn^CB;``), a lone one has an empty other half (``v\\S^B;``, ``ω\\S2^;``). AutoCAD and
    LibreCAD both draw these stacks (LibreCAD prints the ``\\A`` alignment code as text).
    Unicode super- and subscript characters, which LibreCAD's fonts lack, are stacks too
    ("1,1×10⁻¹⁶" → ``1,1×10\\S-16^;``), see :func:`glyph_runs`."""
    parts = glyph_runs(text)
    out: list[str] = []
    i = 0
    while i < len(parts):
        t, shift = parts[i]
        if shift == 0:
            out.append(_escape(t))
        elif shift > 0 and i + 1 < len(parts) and parts[i + 1][1] < 0:
            out.append(f"\\S{_escape(t)}^{_escape(parts[i + 1][0])};")
            i += 1
        elif shift > 0:
            out.append(f"\\S{_escape(t)}^;")
        else:
            out.append(f"\\S^{_escape(t)};")
        i += 1
    return "".join(out)
