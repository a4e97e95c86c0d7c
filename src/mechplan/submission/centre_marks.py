"""Instant centres as students write them: names (``I13``, ``P₁₃``, ``П 1 3``) read through the
notation catalogue's ``[centres]`` section, and the centres labelled on a drawn sheet — each
name given the point mark, line end or crossing it stands beside, or the arrow it is written at
(a centre far away or at infinity)."""

from __future__ import annotations

import math
import re
import statistics
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .notation import SUBSCRIPTS, catalogue
from .read import Entry, Point, SheetText, Submission
from .sketch import drawn_graph, place_labels

#: between the letter and the digits; no parenthesis: "I(0,1)" is a structural formula (the
#: class I mechanism of links 0 and 1), not a centre
_SEP = r"[\s_,.\-–{}]*"


@dataclass(frozen=True, slots=True)
class CentreName:
    """A written centre name: the two links (in the written order) and what follows them
    (``""``, ``"x"``, ``"y"`` or a point's name for a distance)."""

    i: str
    j: str
    rest: str = ""


@dataclass(frozen=True, slots=True)
class CentreMark:
    """A centre labelled on a sheet: its point (mm of paper) or, for one written at an arrow,
    the arrow's direction; ``infinite`` when the text says ∞."""

    name: CentreName
    written: str
    where: str
    at: Point | None
    direction: Point | None = None     # unit vector of an arrow written beside the name
    infinite: bool = False
    distance: float = 0.0


def _letters() -> str:
    letters = catalogue().get("centres", {}).get("letters", ["I", "P"])
    return "".join(re.escape(x) for x in letters)


def _infinity() -> tuple[str, ...]:
    return tuple(catalogue().get("centres", {}).get("infinity", ["∞"]))


#: a link's absolute centre when a name says no link: resolved by the checker (the coupler)
COUPLER = ""
#: the ``i`` of a :class:`CentreName` naming the acceleration pole of link ``j`` ("Q2")
POLE = "Q"


def read_pole(text: str, links: Sequence[str]) -> CentreName | None:
    """The acceleration pole a label names ("Q2", "Q₂", "полюс ускорений 2"), or None."""
    words = sorted(catalogue().get("centres", {}).get("pole", ["Q"]), key=len, reverse=True)
    t = text.strip().translate(SUBSCRIPTS)
    m = re.fullmatch(rf"(?:{'|'.join(re.escape(w) for w in words)}){_SEP}(\d+)", t,
                     re.IGNORECASE)
    if not m or m.group(1) not in links or m.group(1) == "0":
        return None
    return CentreName(POLE, m.group(1))


def _absolute_pattern() -> str:
    cat = catalogue().get("centres", {})
    words = sorted(cat.get("absolute", ["МЦС"]), key=len, reverse=True)
    link_words = sorted(cat.get("link_words", []), key=len, reverse=True)
    lw = "|".join(re.escape(w) for w in link_words)
    return (rf"(?<![\w])(?:{'|'.join(re.escape(w) for w in words)})"
            rf"(?:{_SEP}(?:(?:{lw}){_SEP})?(\d+)(?!\d))?") if lw else \
        rf"(?<![\w])(?:{'|'.join(re.escape(w) for w in words)})(?:{_SEP}(\d+)(?!\d))?"


def _read_absolute(t: str, links: Sequence[str], whole: bool) -> CentreName | None:
    """МЦС / tâm vận tốc tức thời / 速度瞬心 [of link j]: the centre of the frame and link j
    (:data:`COUPLER` for j when no link is written)."""
    pat = _absolute_pattern() + (r"(.*)$" if whole else "")
    m = re.match(pat, t, re.IGNORECASE) if whole else re.search(pat, t, re.IGNORECASE)
    if not m:
        return None
    link = m.group(1) or COUPLER
    rest = (m.group(2) or "").strip() if whole else ""
    if link == COUPLER:                 # "МЦС P02": the centre's own name follows
        after = t[m.end():] if not whole else rest.strip("()[]{} =—-–:")
        named = read_centre(after, links, whole) if after.strip() else None
        if named is not None or (whole and rest):
            return named
    if link != COUPLER and (link not in links or link == "0"):
        return None
    if whole and rest and not re.fullmatch(r"[A-Za-z]\w{0,3}", rest):
        return None
    return CentreName("0", link, rest)


def read_centre(text: str, links: Sequence[str], whole: bool = True,
                single: bool = False) -> CentreName | None:
    """The centre a name means (``whole``: the text is the name alone, perhaps with a suffix
    ``x``/``y`` or a point name), or None. Link ids longer than a character need a separator
    unless only one split of the digits names two links. The tradition's name of a link's
    absolute centre (МЦС, tâm vận tốc tức thời, 绝对瞬心, with or without its link) is the centre
    of the frame and that link; ``single``: a letter with one link ("P2") is too (on drawings)."""
    t = text.strip().translate(SUBSCRIPTS)
    absolute = _read_absolute(t, links, whole)
    if absolute is not None:
        return absolute
    pat = rf"(?<![\w])[{_letters()}]{_SEP}(\d[\d\s,.\-–_]*)" + (r"(.*)$" if whole else "")
    m = re.match(pat, t) if whole else re.search(pat, t)
    if not m:
        return None
    digits, rest = m.group(1), (m.group(2) if whole else "")
    parts = [p for p in re.split(r"[\s,.\-–_]+", digits.strip()) if p]
    pair = _split(parts, set(links))
    if pair is None and single and len(parts) == 1 and parts[0] in links and parts[0] != "0":
        pair = ("0", parts[0])
    if pair is None:
        return None
    rest = re.sub(r"^[\s_{}()\[\],]+|[\s_{}()\[\]]+$", "", rest)
    if whole and rest and not re.fullmatch(r"[A-Za-z]\w{0,3}", rest):
        return None
    return CentreName(pair[0], pair[1], rest)


def _split(parts: list[str], links: set[str]) -> tuple[str, str] | None:
    if len(parts) == 2:
        return (parts[0], parts[1]) if set(parts) <= links and parts[0] != parts[1] else None
    if len(parts) != 1 or len(parts[0]) < 2:
        if len(parts) > 2 and all(len(p) == 1 for p in parts):
            return _split(["".join(parts)], links)
        return None
    s = parts[0]
    splits = [(s[:k], s[k:]) for k in range(1, len(s))
              if s[:k] in links and s[k:] in links and s[:k] != s[k:]]
    return splits[0] if len(splits) == 1 else None


def says_infinity(text: str) -> bool:
    """Whether a text marks a centre at infinity."""
    low = text.lower()
    return any(w.lower() in low for w in _infinity())


def centre_entries(entries: Sequence[Entry],
                   links: Sequence[str]) -> tuple[list[tuple[CentreName, Entry]], list[Entry]]:
    """The entries of a table that name centres, and the others."""
    found, rest = [], []
    anyone = {*links, *"0123456789"}        # a centre of links the mechanism has not is reported
    for e in entries:
        name = read_centre(e.name, links) or read_centre(e.name, sorted(anyone))
        (rest.append(e) if name is None else found.append((name, e)))
    return found, rest


#: a table row's cells stand on one line to the right of its name, within this many mm
ROW_REACH_MM = 80.0
#: ... its first cell within this many mm (a label of a drawing with numbers of another panel
#: far to its right — a circle diagram's order — is no row)
FIRST_CELL_MM = 40.0
_NUMBER = re.compile(r"^[+\-−]?\d+(?:[.,]\d+)?$")
_ANGLE = re.compile(r"([+\-−]?\d+(?:[.,]\d+)?)\s*°")


def table_rows(sub: Submission, links: Sequence[str]) -> list[tuple[CentreName, Entry]]:
    """The rows of a table of centres drawn on a sheet (mechplan's own: name, x, y in mm of
    the scene's frame, or name, ∞, direction °): a name whose row holds numbers to its right."""
    out = []
    for t, name, cells in _rows(sub, links):
        if says_infinity(cells[0].text):
            angle = next((m.group(1) for c in cells[1:] if (m := _ANGLE.search(c.text))), None)
            text = "∞" + (f" {angle}°" if angle is not None else "")
        else:
            text = f"({cells[0].text.strip()}; {cells[1].text.strip()}) mm"
        out.append((name, Entry(t.text.strip(), t.where, text=text, at=t.centre)))
    return out


def _rows(sub: Submission, links: Sequence[str]) -> list[tuple[SheetText, CentreName,
                                                                list[SheetText]]]:
    out: list[tuple[SheetText, CentreName, list[SheetText]]] = []
    names = [(i, t, n) for i, t in enumerate(sub.texts) if len(t.text) <= MAX_TEXT
             and (n := read_centre(t.text, links)) is not None and not n.rest]
    if not names:
        return out
    at = np.array([t.centre for t in sub.texts], dtype=float).reshape(-1, 2)
    for i, t, name in names:
        dx, dy = at[:, 0] - t.centre[0], np.abs(at[:, 1] - t.centre[1])
        near = np.flatnonzero((dy < 0.6 * max(t.height, 1e-9)) & (dx > 0.0) &
                              (dx < ROW_REACH_MM))
        row = sorted((sub.texts[j] for j in near if j != i), key=lambda c: c.centre[0])
        first = row[0].centre[0] - t.centre[0] if row else math.inf
        if len(row) >= 2 and first <= FIRST_CELL_MM and (says_infinity(row[0].text) or
                              all(_NUMBER.match(c.text.strip()) for c in row[:2])):
            out.append((t, name, row))
    return out


#: texts longer than this are no centre names (a paragraph of notes)
MAX_TEXT = 60


def find_centre_marks(sub: Submission, links: Sequence[str], tol: float | None = None,
                      snap: float = 0.2) -> list[CentreMark]:
    """Every centre labelled on a drawn sheet: a text naming one centre (texts listing several —
    a circle diagram's order, a table row of numbers — are not marks) given the point it stands
    beside (within ``tol`` mm; by default twice the texts' height, 3 … 10 mm, as for the labels of
    plans), or the arrowhead it is written at."""
    texts: list[tuple[SheetText, CentreName]] = []
    in_tables = {id(t) for t, _, _ in _rows(sub, links)}
    poles = []
    for t in sub.texts:
        if len(t.text) > MAX_TEXT or ":" in t.text or "=" in t.text or id(t) in in_tables:
            continue
        pole = read_pole(t.text, links)
        if pole is not None:
            poles.append((t, pole))
            continue
        name = read_centre(t.text, links, whole=False, single=True)
        if name is None or _count_names(t.text, links) != 1:
            continue
        words = t.text.strip()
        if read_centre(words, links, single=True) is None and not _arrow_words(words):
            continue
        texts.append((t, name))
    # "P2" (a letter and one link) and the poles "Q2" name centres only on a drawing of the
    # centres: one with at least one centre written with its two links (elsewhere "P2" or "Q2"
    # may be a force)
    if not any(read_centre(t.text, links, whole=False) is not None
               and read_centre(t.text, links, whole=False) == n for t, n in texts):
        texts = [(t, n) for t, n in texts if read_centre(t.text, links, whole=False) == n]
        poles = []
    if not texts and not poles:
        return []
    if tol is None:
        heights = [t.height for t, _ in texts + poles if t.height > 0]
        tol = min(10.0, max(3.0, 2.0 * statistics.median(heights))) if heights else 5.0
    marks: list[CentreMark] = []
    heads = list(sub.heads)
    plain = [(t, n) for t, n in texts if read_centre(t.text.strip(), links, single=True) is not None
             and not says_infinity(t.text)] + poles
    at_arrows = [(t, n) for t, n in texts if (t, n) not in plain]
    if plain:
        graph = drawn_graph(sub.lines, sub.markers, snap, sub.heads)
        spots = place_labels([t for t, _ in plain], graph, sub.lines, tol)
        for (t, n), spot in zip(plain, spots):
            marks.append(CentreMark(n, t.text.strip(), t.where, spot.at, None, False,
                                    spot.distance))
    for t, n in at_arrows:
        head = _nearest_head(t, heads, 3.0 * tol)
        direction = None
        if head is not None:
            (tx, ty), (bx, by) = head
            d = math.hypot(tx - bx, ty - by)
            direction = ((tx - bx) / d, (ty - by) / d) if d > 0 else None
        marks.append(CentreMark(n, t.text.strip(), t.where, head[0] if head else None,
                                direction, says_infinity(t.text)))
    return marks


def _count_names(text: str, links: Sequence[str]) -> int:
    n, rest = 0, text
    while read_centre(rest, links, whole=False, single=True) is not None:
        n += 1
        cut = re.search(rf"[{_letters()}]", rest)
        rest = rest[cut.end():] if cut else ""
        if n > 3:
            break
    return n


def _arrow_words(text: str) -> bool:
    """A name written with a few words at an arrow ("to I02", "I23 at ∞", "к P02")."""
    return says_infinity(text) or len(text.split()) <= 3


def _nearest_head(t: SheetText, heads: list[tuple[Point, Point]],
                  reach: float) -> tuple[Point, Point] | None:
    best, best_d = None, reach
    for tip, base in heads:
        d = t.distance(tip)
        if d <= best_d:
            best, best_d = (tip, base), d
    return best
