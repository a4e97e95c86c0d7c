"""Sub- and superscripts written in a label ("a^n_CB", "v_B", "ω^2") for every backend.

A ``^`` raises and a ``_`` lowers the run of letters, digits and primes that follows it; the
renderers draw the runs at 70 % size above or below the baseline: DXF as MTEXT groups with
height and alignment codes (``a{\\H0.7x;\\A2;n}{\\H0.7x;\\A0;CB}``), SVG as shifted
``tspan``s, PDF/PNG as separately placed strings.
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


def plain(text: str) -> str:
    """The label without its marks ("a^n_CB" → "anCB")."""
    return "".join(t for t, _ in runs(text))


def _escape(text: str) -> str:
    return text.replace("\\", "\\\\").replace("{", "\\{").replace("}", "\\}").replace("^", "^ ")


def mtext(text: str) -> str:
    """MTEXT content: each script run in a group at 70 % height aligned to the top (\\A2) or the
    bottom (\\A0) of the line ("a{\\H0.7x;\\A2;n}{\\H0.7x;\\A0;CB}")."""
    out: list[str] = []
    for t, shift in runs(text):
        if shift == 0:
            out.append(_escape(t))
        else:
            out.append(f"{{\\H{SCRIPT_SIZE:g}x;\\A{2 if shift > 0 else 0};{_escape(t)}}}")
    return "".join(out)
