"""A drawn plan's title: the text that stands above a drawing and names it.

Sheets title each plan ("Force plan I(0,1) — position 1, φ = 30.0°", "План скоростей, φ = 30°").
The title tells what vertex letters cannot: which group's force polygon a drawing is (the
polygons of two cranks carry the same letters a, b, c …) and at which position it was drawn (a
polygon of one position beside the plans of another). The title of a drawing is the nearest such
text that stands above it.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

from .labels import mu_plan
from .read import Point, SheetText

#: a title ends with its position: "φ = 30.0°", "phi1 = 30 deg", "l4 = 1562,5 mm", "s1 = -100,0 мм"
#: (a unit of up to three letters in any language; not a scale factor's "N/mm")
_ENDS_WITH_POSITION = re.compile(
    r"(?<![\w/])(?P<name>[^\W\d_]\w*)\s*=\s*(?P<value>-?\d+(?:[.,]\d+)?)\s*(?P<unit>°|[^\W\d_]{1,3})?\s*$",
    re.IGNORECASE)


#: a title stands over its drawing, or ends at most this far left of it (mm); a text that begins
#: right of the drawing titles another
ASIDE_MM = 200.0


def _group_pattern(group: str) -> re.Pattern[str]:
    """A group's name as a whole word of a text: "I(0,1)" not inside "II(0,1)"."""
    body = r"\s*".join(re.escape(ch) for ch in group if not ch.isspace())
    return re.compile(rf"(?<![\w(]){body}(?![\w)])")


def names_group(text: str, group: str) -> bool:
    """Whether ``text`` names the force group ``group`` ("Force plan I(0,1) — …")."""
    return bool(group) and _group_pattern(group).search(text) is not None


def position_written(title: str) -> tuple[str, float, str] | None:
    """The position a title ends with: (name, value, unit) of "φ = 30.0°" or "l4 = 1562.5 mm"."""
    m = _ENDS_WITH_POSITION.search(title.strip())
    if m is None:
        return None
    return m["name"], float(m["value"].replace(",", ".")), (m["unit"] or "").lower()


def written_step(title: str) -> float:
    """Half the last written digit of the position a title ends with ("30.0°" → 0.05)."""
    m = _ENDS_WITH_POSITION.search(title.strip())
    if m is None:
        return 0.0
    _, dot, decimals = m["value"].replace(",", ".").partition(".")
    return 0.5 * 10.0 ** -len(decimals if dot else "")


def _is_title(t: SheetText, groups: Sequence[str]) -> bool:
    text = t.text.strip()
    if len(text.split()) < 2 or mu_plan(text.split("=")[0].strip()) is not None:
        return False
    return position_written(text) is not None or any(names_group(text, g) for g in groups)


Box = tuple[float, float, float, float]          # left, right, bottom, top (mm)


def box_of(points: Iterable[Point]) -> Box | None:
    """The box of a drawing's labelled points."""
    pts = list(points)
    if not pts:
        return None
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return min(xs), max(xs), min(ys), max(ys)


def title_above(points: Iterable[Point], texts: Sequence[SheetText],
                groups: Sequence[str] = (), others: Sequence[Box] = (),
                figures: Sequence[Box] = ()) -> SheetText | None:
    """The title of the drawing whose labelled points are ``points``: among the texts that end
    with a position or name one of ``groups`` and stand above the drawing's box (their bottom no
    lower than its top less 1 mm, not beginning right of it, ending at most ``ASIDE_MM`` left of
    it) with no other drawing (``others``) between it and the drawing, and no unlabelled figure
    (``figures``: a table's rules, a frame of lines) standing wholly between them — a text over a
    table is the table's heading —, the nearest one (vertical plus horizontal gap)."""
    box = box_of(points)
    if box is None:
        return None
    left, right, _, top = box
    best: tuple[float, SheetText] | None = None
    for t in texts:
        if t.rotation % 360.0 != 0.0 or not _is_title(t, groups):
            continue
        bottom = t.centre[1] - t.half[1]
        if bottom < top - 1.0:
            continue
        lo, hi = t.centre[0] - t.half[0], t.centre[0] + t.half[0]
        aside = max(left - hi, 0.0)           # a title begins at its panel's left edge
        if aside > ASIDE_MM or lo > right:
            continue
        gap = (bottom - top if bottom > top else 0.0) + aside
        span = (min(lo, left), right, top, bottom)
        if any(_between(o, span) for o in others) or any(_inside_gap(f, span) for f in figures):
            continue
        if best is None or gap < best[0]:
            best = (gap, t)
    return None if best is None else best[1]


def _inside_gap(figure: Box, span: Box) -> bool:
    """Whether a figure at least 2 mm each way (not an underline) stands wholly in the vertical
    gap between a title and its drawing (1 mm of slack each way) and overlaps them across."""
    return (figure[1] - figure[0] >= 2.0 and figure[3] - figure[2] >= 2.0
            and figure[0] < span[1] and figure[1] > span[0]
            and figure[2] >= span[2] - 1.0 and figure[3] <= span[3] + 1.0)


def _between(other: Box, span: Box) -> bool:
    """Whether a drawing's box reaches into the span between a title and its drawing."""
    return (other[0] < span[1] and other[1] > span[0]
            and other[2] < span[3] and other[3] > span[2])
