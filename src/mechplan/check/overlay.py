"""Overlay sheet of a check: the submission in blue, the exact plans (placed by the poles) in
green, each wrong segment marked in red with its error — a :class:`Sheet` written by the
``render`` backends (DXF, SVG, PDF)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..drafting.fonts import text_width_mm
from ..drafting.primitives import Line, Role, Sheet, Text
from ..errors import CheckError, DrawingError
from ..i18n import num
from ..render import write, write_atomic
from .report import SLIP, WRONG, CheckReport, SegmentRow
from .texts import T, tr, word

Point = tuple[float, float]

#: the role of each layer of marks
ROLES = {"SUBMISSION": Role.SUBMISSION, "EXACT": Role.EXACT, "ERRORS": Role.ERRORS,
         "NOTES": Role.TEXT}
#: blank paper around the overlay's drawing (mm)
MARGIN_MM = 10.0


@dataclass(frozen=True, slots=True)
class Mark:
    """One primitive of the overlay (mm of the submission's sheet, y up)."""

    layer: str                 # SUBMISSION, EXACT, ERRORS, NOTES
    start: Point
    end: Point | None = None   # None: a text at ``start``
    text: str = ""
    height: float = 2.5         # ISO 3098 height (mm)


def marks(report: CheckReport, lang: str = "en") -> list[Mark]:
    """The overlay's primitives, their texts in a language (en, ru, vi, zh)."""
    out: list[Mark] = []
    for plan in report.plans:
        if not plan.drawn_lines and not plan.exact_segments:
            continue
        start = len(out)
        out += [Mark("SUBMISSION", a, b) for a, b in plan.drawn_lines]
        out += [Mark("EXACT", a, b) for _, a, b in plan.exact_segments]
        out += [Mark("EXACT", (at[0] - 3.0, at[1] - 3.5), None, label, 1.8)
                for label, at in plan.exact_mm.items()]
        points = {p.step: p.at_mm for p in plan.points}
        for row in plan.segments:
            a, b = points.get(row.start), points.get(row.end)
            if row.verdict not in (WRONG, SLIP) or a is None or b is None:
                continue
            mid = ((a[0] + b[0]) / 2 + 1.0, (a[1] + b[1]) / 2 + 1.0)
            out += [Mark("ERRORS", a, b), Mark("ERRORS", mid, None, _error_text(row, lang), 1.8)]
        title = (T("overlay.title", plan=plan.name, mu=plan.mu, unit=plan.mu_unit).tr(lang)
                 if plan.mu else tr(plan.name, lang))
        lo, hi = _extent(out[start:])
        out.append(Mark("NOTES", (lo[0], hi[1] + 6.0), None, title, 3.5))
    out += _centre_marks(report, lang)
    if not out:
        raise CheckError(T("error.overlay_table"), file=report.submission)
    lo, _ = _extent(out)
    out.append(Mark("NOTES", (lo[0], lo[1] - 8.0), None, T("overlay.legend").tr(lang), 3.5))
    return out


def _centre_marks(report: CheckReport, lang: str) -> list[Mark]:
    """The exact instant centres (a small cross and the name) and, for a wrong one, a line from
    the drawn place to the exact one with its error."""
    out: list[Mark] = []
    for c in report.centres:
        if c.exact_mm is None:
            continue
        x, y = c.exact_mm
        out += [Mark("EXACT", (x - 1.5, y), (x + 1.5, y)),
                Mark("EXACT", (x, y - 1.5), (x, y + 1.5)),
                Mark("EXACT", (x + 1.5, y - 3.5), None, c.label, 1.8)]
        if c.verdict == WRONG and c.at_mm is not None and c.found == "point":
            out += [Mark("ERRORS", c.at_mm, c.exact_mm),
                    Mark("ERRORS", (c.at_mm[0] + 1.0, c.at_mm[1] + 1.0), None,
                         T("mm", v=num(c.error or 0.0, ".1f", lang)).tr(lang), 1.8)]
    return out


def _extent(ms: list[Mark], texts: bool = False) -> tuple[Point, Point]:
    """The lowest and highest x and y the marks reach (with ``texts``: their texts' far corners
    too)."""
    pts = [p for m in ms for p in (m.start, m.end) if p is not None] + [
        (m.start[0] + text_width_mm(m.text, m.height), m.start[1] + m.height)
        for m in ms if texts and m.end is None]
    xs, ys = zip(*pts)
    return (min(xs), min(ys)), (max(xs), max(ys))


def _error_text(row: SegmentRow, lang: str = "en") -> str:
    parts = [row.name]
    if row.error_mm is not None:
        parts.append(T("overlay.err_mm", v=row.error_mm).tr(lang))
    if row.error_pct is not None:
        parts.append(T("overlay.err_pct", v=row.error_pct).tr(lang))
    if row.direction_deg is not None and row.tolerance_deg is not None and \
            abs(row.direction_deg) > row.tolerance_deg:
        parts.append(T("overlay.err_deg", v=row.direction_deg).tr(lang))
    if row.cause:
        parts.append(word("cause", row.cause, lang))
    return " ".join(parts)


def overlay_sheet(report: CheckReport, lang: str = "en", name: str = "overlay") -> Sheet:
    """The overlay as a :class:`Sheet` (roles SUBMISSION, EXACT, ERRORS, TEXT), drawn by any
    ``render`` backend; its size is the drawing's extent plus a margin."""
    ms = marks(report, lang)
    lo, hi = _extent(ms, texts=True)
    x0, y0 = lo[0] - MARGIN_MM, lo[1] - MARGIN_MM

    def q(p: Point) -> Point:
        return (p[0] - x0, p[1] - y0)

    # a mark with an end is a line, one without is a text
    prims = tuple(Line(q(m.start), q(m.end), ROLES[m.layer]) if m.end is not None
                  else Text(q(m.start), m.text, m.height, role=ROLES[m.layer]) for m in ms)
    return Sheet(hi[0] - x0 + MARGIN_MM, hi[1] - y0 + MARGIN_MM, prims, language=lang, name=name)


def write_overlay(report: CheckReport, path: str | Path, lang: str = "en") -> Path:
    """Write the overlay as SVG, DXF or PDF (by the file's suffix), its texts in a language."""
    p = Path(path)
    suffix = p.suffix.lower().lstrip(".")
    if suffix not in ("svg", "dxf", "pdf"):
        raise CheckError(T("error.overlay_kind", suffix=suffix or "—"), file=str(p))
    sheet = overlay_sheet(report, lang, p.stem or "overlay")
    return _written(p, lambda: write(sheet, p, (suffix,))[0])


def write_bytes(path: Path, data: bytes) -> Path:
    """Write a report file atomically (a failed write leaves the old file)."""
    return _written(path, lambda: write_atomic(path, data))


def _written(path: Path, write_it: Callable[[], Path]) -> Path:
    """Write a file; a failure is a :class:`CheckError` naming it."""
    try:
        return write_it()
    except DrawingError as exc:
        raise CheckError(exc.detail, file=str(path)) from None
    except OSError as exc:
        raise CheckError(T("error.write", reason=exc.strerror or str(exc)),
                         file=str(path)) from None
